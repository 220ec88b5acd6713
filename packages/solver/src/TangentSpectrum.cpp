#include "cgcm/solver/TangentSpectrum.hpp"

#include <AnasaziBasicEigenproblem.hpp>
#include <AnasaziBlockKrylovSchurSolMgr.hpp>
#include <AnasaziTpetraAdapter.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_LAPACK.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Thyra_VectorStdOps.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "MumpsFactorization.hpp"
#include "cgcm/core/Error.hpp"

namespace cgcm::solver {

namespace {

using assembly::CrsMatrix;
using assembly::Map;
using assembly::MultiVector;
using Extract = Thyra::TpetraOperatorVectorExtraction<Real, LocalIndex, GlobalIndex, assembly::Node>;
using Operator = assembly::Operator;

// y = alpha S^-1 x + beta y with S's factorisation: Anasazi's shift-invert operator.
class InverseOperator : public Operator {
 public:
  InverseOperator(const MumpsFactorization& mumps, Teuchos::RCP<const Map> map) : mumps_(mumps), map_(std::move(map)) {}
  Teuchos::RCP<const Map> getDomainMap() const override { return map_; }
  Teuchos::RCP<const Map> getRangeMap() const override { return map_; }
  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp, Real alpha, Real beta) const override {
    MultiVector Z(map_, X.getNumVectors());
    mumps_.solve(X, Z);  // S is symmetric: the transpose is the same solve
    Y.update(alpha, Z, beta);
  }

 private:
  const MumpsFactorization& mumps_;
  Teuchos::RCP<const Map> map_;
};

// A start vector that does not depend on the number of ranks and has a part along every mode (a
// symmetric start would miss every antisymmetric mode): a hash of the global index in [-1, 1].
void startVector(MultiVector& v) {
  auto data = v.getLocalViewHost(Tpetra::Access::OverwriteAll);
  const auto& map = *v.getMap();
  for (std::size_t l = 0; l < v.getLocalLength(); ++l) {
    auto h = static_cast<std::uint64_t>(map.getGlobalElement(LocalIndex(l))) * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull;
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ull;
    h ^= h >> 32;
    data(l, 0) = double(h % 2000001) / 1000000.0 - 1.0;
  }
}

// Scales v to a largest entry of +1 (the entry of largest magnitude, the lowest global index among ties).
void normalizeMode(Vector& v) {
  const auto data = v.getLocalViewHost(Tpetra::Access::ReadOnly);
  Real big = 0.0, value = 0.0;
  GlobalIndex where = std::numeric_limits<GlobalIndex>::max();
  for (std::size_t l = 0; l < v.getLocalLength(); ++l)
    if (std::abs(data(l, 0)) > big * (1.0 + 1e-12)) {
      big = std::abs(data(l, 0));
      value = data(l, 0);
      where = v.getMap()->getGlobalElement(LocalIndex(l));
    }
  const auto& comm = *v.getMap()->getComm();
  Real globalBig = 0.0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, big, Teuchos::outArg(globalBig));
  if (globalBig == 0.0) return;
  // the sign of the largest entry on the lowest-index rank holding one within rounding of the maximum
  GlobalIndex mine = big >= globalBig * (1.0 - 1e-12) ? where : std::numeric_limits<GlobalIndex>::max(), first = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, mine, Teuchos::outArg(first));
  Real sign = mine == first ? (value < 0.0 ? -1.0 : 1.0) : 0.0, globalSign = 0.0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, sign, Teuchos::outArg(globalSign));
  v.scale((globalSign < 0.0 ? -1.0 : 1.0) / globalBig);
}

// The `count` entries of `values` nearest 0 (indices), ascending by value.
std::vector<int> nearestZero(const std::vector<Real>& values, int count) {
  std::vector<int> index(values.size());
  std::iota(index.begin(), index.end(), 0);
  std::stable_sort(index.begin(), index.end(), [&](int a, int b) { return std::abs(values[a]) < std::abs(values[b]); });
  index.resize(std::min<std::size_t>(index.size(), std::size_t(count)));
  std::sort(index.begin(), index.end(), [&](int a, int b) { return values[a] < values[b]; });
  return index;
}

}  // namespace

Real Spectrum::ordered(int k) const {
  int computedNegative = 0;
  for (Real v : eigenvalues) computedNegative += v < 0.0 ? 1 : 0;
  // the computed negatives are the largest ones, eigenvalues negative - computedNegative .. negative - 1
  const int index = k - (negative - computedNegative);
  return index >= 0 && index < int(eigenvalues.size()) ? eigenvalues[std::size_t(index)]
                                                        : std::numeric_limits<Real>::quiet_NaN();
}

TangentSpectrum::TangentSpectrum(Teuchos::RCP<ParameterizedModel> model, int count, int denseSize)
    : model_(std::move(model)), count_(count), denseSize_(denseSize) {
  if (count_ < 1) throw InputError("TangentSpectrum: the number of eigenvalues must be at least 1");
}

TangentSpectrum::~TangentSpectrum() = default;

Spectrum TangentSpectrum::compute(const Vector& x, const std::vector<Real>& p) {
  // the tangent at (x, p)
  if (W_.is_null()) W_ = model_->create_W_op();
  auto in = model_->createInArgs();
  auto xCopy = Teuchos::rcp(new Vector(x, Teuchos::Copy));
  in.set_x(Thyra::createConstVector<Real, LocalIndex, GlobalIndex, assembly::Node>(
      Teuchos::rcp_implicit_cast<const Tpetra::Vector<Real, LocalIndex, GlobalIndex, assembly::Node>>(xCopy),
      model_->get_x_space()));
  auto pv = Thyra::createMember(model_->get_p_space(0));
  for (std::size_t k = 0; k < p.size(); ++k) Thyra::set_ele(Teuchos::Ordinal(k), p[k], pv.ptr());
  in.set_p(0, pv);
  auto out = model_->createOutArgs();
  out.set_W_op(W_);
  model_->evalModel(in, out);
  auto K = Teuchos::rcp_dynamic_cast<const CrsMatrix>(Extract::getConstTpetraOperator(W_), true);

  // the constrained dofs: unit rows (diagonal 1, every other entry 0), also as columns
  const auto rowMap = K->getRowMap(), colMap = K->getColMap();
  Vector unitRow(rowMap), unitColumn(colMap);
  {
    auto mask = unitRow.getLocalViewHost(Tpetra::Access::OverwriteAll);
    typename CrsMatrix::local_inds_host_view_type cols;
    typename CrsMatrix::values_host_view_type vals;
    for (LocalIndex r = 0; r < LocalIndex(K->getNodeNumRows()); ++r) {
      K->getLocalRowView(r, cols, vals);
      const GlobalIndex g = rowMap->getGlobalElement(r);
      bool unit = true, diagonal = false;
      for (std::size_t k = 0; k < cols.extent(0) && unit; ++k) {
        if (colMap->getGlobalElement(cols(k)) == g) diagonal = vals(k) == 1.0, unit = diagonal;
        else unit = vals(k) == 0.0;
      }
      mask(r, 0) = unit && diagonal ? 1.0 : 0.0;
    }
  }
  unitColumn.doImport(unitRow, assembly::Import(rowMap, colMap), Tpetra::INSERT);

  // S's coordinates: the free rows' lower triangle, each off-diagonal K_ij counted half at (max, min) (MUMPS sums
  // the two halves); a constrained dof gets a diagonal far from 0 that no eigenvalue asked for can reach
  const GlobalIndex base = rowMap->getMinAllGlobalIndex();
  const GlobalIndex n = GlobalIndex(rowMap->getGlobalNumElements());
  if (rowMap->getMaxAllGlobalIndex() - base + 1 != n)
    throw NumericalError("tangent spectrum: the matrix rows are not numbered contiguously");
  std::vector<int> irn, jcn;
  std::vector<Real> val;
  std::vector<GlobalIndex> constrained;
  Real maxDiagonal = 0.0;
  long free = 0;
  {
    const auto rowMask = unitRow.getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto colMask = unitColumn.getLocalViewHost(Tpetra::Access::ReadOnly);
    typename CrsMatrix::local_inds_host_view_type cols;
    typename CrsMatrix::values_host_view_type vals;
    for (LocalIndex r = 0; r < LocalIndex(K->getNodeNumRows()); ++r) {
      const GlobalIndex gi = rowMap->getGlobalElement(r);
      if (rowMask(r, 0) != 0.0) {
        constrained.push_back(gi);
        continue;
      }
      ++free;
      K->getLocalRowView(r, cols, vals);
      for (std::size_t k = 0; k < cols.extent(0); ++k) {
        if (colMask(cols(k), 0) != 0.0) continue;
        const GlobalIndex gj = colMap->getGlobalElement(cols(k));
        if (gi == gj) maxDiagonal = std::max(maxDiagonal, std::abs(vals(k)));
        irn.push_back(int(std::max(gi, gj) - base + 1));
        jcn.push_back(int(std::min(gi, gj) - base + 1));
        val.push_back(gi == gj ? vals(k) : 0.5 * vals(k));
      }
    }
  }
  const auto& comm = *rowMap->getComm();
  Real globalMaxDiagonal = 0.0;
  long globalFree = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, maxDiagonal, Teuchos::outArg(globalMaxDiagonal));
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, free, Teuchos::outArg(globalFree));
  if (globalFree == 0) throw NumericalError("tangent spectrum: every dof is constrained");
  const Real far = 1e3 * std::max(globalMaxDiagonal, 1e-300);
  for (GlobalIndex g : constrained) {
    irn.push_back(int(g - base + 1));
    jcn.push_back(int(g - base + 1));
    val.push_back(far);
  }
  const int wanted = int(std::min<long>(count_, globalFree));

  Spectrum result;
  if (n <= denseSize_) {
    // every rank sums the whole matrix and solves it (LAPACK), then keeps its rows of the mode
    const int N = int(n);
    std::vector<Real> local(std::size_t(N) * N, 0.0), A(local.size(), 0.0);
    for (std::size_t k = 0; k < irn.size(); ++k) {
      const int i = irn[k] - 1, j = jcn[k] - 1;
      local[std::size_t(i) * N + j] += val[k];
      if (i != j) local[std::size_t(j) * N + i] += val[k];
    }
    Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, int(local.size()), local.data(), A.data());
    std::vector<Real> w(N);
    int info = 0, lwork = -1;
    Real query = 0.0;
    Teuchos::LAPACK<int, Real> lapack;
    lapack.SYEV('V', 'U', N, A.data(), N, w.data(), &query, lwork, &info);
    lwork = int(query);
    std::vector<Real> work(std::size_t(std::max(lwork, 1)));
    lapack.SYEV('V', 'U', N, A.data(), N, w.data(), work.data(), lwork, &info);
    if (info != 0) throw NumericalError("tangent spectrum: LAPACK dsyev failed (info = " + std::to_string(info) + ")");
    // the constrained dofs' eigenvalues (far) are not the system's
    std::vector<Real> freeValues;
    std::vector<int> column;
    for (int k = 0; k < N; ++k)
      if (w[k] < 0.5 * far) freeValues.push_back(w[k]), column.push_back(k);
    for (Real v : freeValues) result.negative += v < 0.0 ? 1 : 0;
    for (int k : nearestZero(freeValues, wanted)) {
      result.eigenvalues.push_back(freeValues[k]);
      auto mode = Teuchos::rcp(new Vector(rowMap));
      auto m = mode->getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (std::size_t l = 0; l < mode->getLocalLength(); ++l)
        m(l, 0) = A[std::size_t(column[k]) * N + std::size_t(rowMap->getGlobalElement(LocalIndex(l)) - base)];
      result.modes.push_back(mode);
    }
  } else {
    if (!mumps_) mumps_ = std::make_unique<MumpsFactorization>(MumpsFactorization::Symmetry::Symmetric, 4);
    try {
      mumps_->factorize(rowMap, rowMap, n, base, std::move(irn), std::move(jcn), std::move(val));
    } catch (const std::runtime_error& e) {
      throw NumericalError(std::string("tangent spectrum: ") + e.what());
    }
    result.negative = mumps_->negativePivots();
    using MV = MultiVector;
    using OP = Operator;
    auto start = Teuchos::rcp(new MV(rowMap, 1));
    startVector(*start);
    auto problem = Teuchos::rcp(new Anasazi::BasicEigenproblem<Real, MV, OP>(
        Teuchos::rcp(new InverseOperator(*mumps_, rowMap)), start));
    problem->setHermitian(true);
    problem->setNEV(wanted);
    if (!problem->setProblem()) throw NumericalError("tangent spectrum: Anasazi refused the eigenproblem");
    Teuchos::ParameterList settings;
    settings.set("Which", "LM");  // of S^-1: the eigenvalues of S nearest 0
    settings.set("Block Size", 1);
    settings.set("Num Blocks", int(std::min<long>(std::max(3 * wanted, 20), globalFree)));
    settings.set("Maximum Restarts", 500);
    settings.set("Convergence Tolerance", 1e-10);
    settings.set("Verbosity", int(Anasazi::Errors));
    Anasazi::BlockKrylovSchurSolMgr<Real, MV, OP> solver(problem, settings);
    solver.solve();
    const auto& solution = problem->getSolution();
    if (solution.numVecs < 1)
      throw NumericalError("tangent spectrum: Anasazi's Krylov-Schur found no eigenvalue in 500 restarts");
    std::vector<Real> values;
    for (int k = 0; k < solution.numVecs; ++k) values.push_back(1.0 / solution.Evals[k].realpart);
    for (int k : nearestZero(values, wanted)) {
      result.eigenvalues.push_back(values[k]);
      auto mode = Teuchos::rcp(new Vector(rowMap));
      mode->update(1.0, *solution.Evecs->getVector(std::size_t(k)), 0.0);
      result.modes.push_back(mode);
    }
  }
  for (auto& mode : result.modes) normalizeMode(*mode);
  return result;
}

}  // namespace cgcm::solver
