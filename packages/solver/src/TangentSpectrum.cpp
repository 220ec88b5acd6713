#include "cgcm/solver/TangentSpectrum.hpp"

#include <AnasaziBasicEigenproblem.hpp>
#include <AnasaziBlockKrylovSchurSolMgr.hpp>
#include <AnasaziTpetraAdapter.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_LAPACK.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Tpetra_RowMatrixTransposer.hpp>
#include <Thyra_VectorStdOps.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
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

// The `count` eigenvalues (re + i im) nearest 0 (indices), ascending by real part.
std::vector<std::size_t> nearestZero(const std::vector<Real>& re, const std::vector<Real>& im, int count) {
  std::vector<std::size_t> index(re.size());
  std::iota(index.begin(), index.end(), 0);
  std::stable_sort(index.begin(), index.end(),
                   [&](std::size_t a, std::size_t b) { return std::hypot(re[a], im[a]) < std::hypot(re[b], im[b]); });
  index.resize(std::min<std::size_t>(index.size(), std::size_t(count)));
  std::stable_sort(index.begin(), index.end(), [&](std::size_t a, std::size_t b) { return re[a] < re[b]; });
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
  // the tangent at (x, p), on a matrix graph that holds the couplings of x (the path's solver last assembled one
  // at an earlier iterate)
  if (!model_->graphCovers(x)) model_->growGraph(x, false);
  auto W = model_->create_W_op();
  auto in = model_->createInArgs();
  auto xCopy = Teuchos::rcp(new Vector(x, Teuchos::Copy));
  in.set_x(Thyra::createConstVector<Real, LocalIndex, GlobalIndex, assembly::Node>(
      Teuchos::rcp_implicit_cast<const Tpetra::Vector<Real, LocalIndex, GlobalIndex, assembly::Node>>(xCopy),
      model_->get_x_space()));
  auto pv = Thyra::createMember(model_->get_p_space(0));
  std::vector<Real> all = model_->parameters();  // those p does not give keep the model's values
  for (std::size_t k = 0; k < p.size() && k < all.size(); ++k) all[k] = p[k];
  for (std::size_t k = 0; k < all.size(); ++k) Thyra::set_ele(Teuchos::Ordinal(k), all[k], pv.ptr());
  in.set_p(0, pv);
  auto out = model_->createOutArgs();
  out.set_W_op(W);
  try {
    model_->evalModel(in, out);
  } catch (const NumericalError&) {
    if (!model_->graphOutdated()) throw;
    model_->growGraph(x, true);  // couplings beyond the search radius: a wider graph, once
    W = model_->create_W_op();
    out.set_W_op(W);
    model_->evalModel(in, out);
  }
  auto K = Teuchos::rcp_dynamic_cast<const CrsMatrix>(Extract::getConstTpetraOperator(W), true);

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

  // K_FF's coordinates (a constrained dof gets a diagonal far from 0 that no eigenvalue asked for can reach), and
  // whether K_FF is symmetric: the largest |K_ij - K_ji| of the free entries against the largest |K_ij|
  const GlobalIndex base = rowMap->getMinAllGlobalIndex();
  const GlobalIndex n = GlobalIndex(rowMap->getGlobalNumElements());
  if (rowMap->getMaxAllGlobalIndex() - base + 1 != n)
    throw NumericalError("tangent spectrum: the matrix rows are not numbered contiguously");
  const auto KT = Tpetra::RowMatrixTransposer<Real, LocalIndex, GlobalIndex, assembly::Node>(K).createTranspose();
  std::vector<int> irn, jcn;
  std::vector<Real> val;
  std::vector<GlobalIndex> constrained;
  Real maxDiagonal = 0.0, maxEntry = 0.0, maxAsymmetry = 0.0;
  long free = 0;
  {
    const auto rowMask = unitRow.getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto colMask = unitColumn.getLocalViewHost(Tpetra::Access::ReadOnly);
    typename CrsMatrix::local_inds_host_view_type cols, colsT;
    typename CrsMatrix::values_host_view_type vals, valsT;
    std::vector<std::pair<GlobalIndex, Real>> transposed;
    for (LocalIndex r = 0; r < LocalIndex(K->getNodeNumRows()); ++r) {
      const GlobalIndex gi = rowMap->getGlobalElement(r);
      if (rowMask(r, 0) != 0.0) {
        constrained.push_back(gi);
        continue;
      }
      ++free;
      // row gi of K^T, by global column
      const LocalIndex rT = KT->getRowMap()->getLocalElement(gi);
      KT->getLocalRowView(rT, colsT, valsT);
      transposed.clear();
      for (std::size_t k = 0; k < colsT.extent(0); ++k)
        transposed.push_back({KT->getColMap()->getGlobalElement(colsT(k)), valsT(k)});
      std::sort(transposed.begin(), transposed.end());
      K->getLocalRowView(r, cols, vals);
      for (std::size_t k = 0; k < cols.extent(0); ++k) {
        if (colMask(cols(k), 0) != 0.0) continue;
        const GlobalIndex gj = colMap->getGlobalElement(cols(k));
        if (gi == gj) maxDiagonal = std::max(maxDiagonal, std::abs(vals(k)));
        maxEntry = std::max(maxEntry, std::abs(vals(k)));
        const auto t = std::lower_bound(transposed.begin(), transposed.end(), std::make_pair(gj, -HUGE_VAL));
        const Real kji = t != transposed.end() && t->first == gj ? t->second : 0.0;
        maxAsymmetry = std::max(maxAsymmetry, std::abs(vals(k) - kji));
        irn.push_back(int(gi - base + 1));
        jcn.push_back(int(gj - base + 1));
        val.push_back(vals(k));
      }
    }
  }
  const auto& comm = *rowMap->getComm();
  Real globalMax[3] = {0.0, 0.0, 0.0};
  const Real localMax[3] = {maxDiagonal, maxEntry, maxAsymmetry};
  long globalFree = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, 3, localMax, globalMax);
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, free, Teuchos::outArg(globalFree));
  if (globalFree == 0) throw NumericalError("tangent spectrum: every dof is constrained");
  Spectrum result;
  result.symmetric = globalMax[2] <= kSymmetryTolerance * globalMax[1];
  const Real far = 1e3 * std::max(globalMax[0], 1e-300);
  for (GlobalIndex g : constrained) {
    irn.push_back(int(g - base + 1));
    jcn.push_back(int(g - base + 1));
    val.push_back(far);
  }
  if (result.symmetric) {
    // the lower triangle: each off-diagonal pair counted half at (max, min) (MUMPS sums the two halves)
    for (std::size_t k = 0; k < irn.size(); ++k)
      if (irn[k] != jcn[k]) {
        if (irn[k] < jcn[k]) std::swap(irn[k], jcn[k]);
        val[k] *= 0.5;
      }
  }
  const int wanted = int(std::min<long>(count_, globalFree));

  std::vector<Real> re, im;                  // eigenvalues found
  std::vector<Teuchos::RCP<Vector>> vectors;  // their eigenvectors (real parts)
  if (n <= denseSize_) {
    // every rank sums the whole matrix and solves it (LAPACK)
    const int N = int(n);
    std::vector<Real> local(std::size_t(N) * N, 0.0), A(local.size(), 0.0);  // column-major
    for (std::size_t k = 0; k < irn.size(); ++k) {
      const int i = irn[k] - 1, j = jcn[k] - 1;
      local[std::size_t(j) * N + i] += val[k];
      if (result.symmetric && i != j) local[std::size_t(i) * N + j] += val[k];
    }
    Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, int(local.size()), local.data(), A.data());
    std::vector<Real> wr(N), wi(N, 0.0), V;
    int info = 0;
    Teuchos::LAPACK<int, Real> lapack;
    if (result.symmetric) {
      int lwork = 3 * N;
      std::vector<Real> work(static_cast<std::size_t>(lwork));
      lapack.SYEV('V', 'U', N, A.data(), N, wr.data(), work.data(), lwork, &info);
      V = A;
    } else {
      int lwork = 8 * N;
      std::vector<Real> work(static_cast<std::size_t>(lwork)), vl(1);
      V.resize(std::size_t(N) * N);
      lapack.GEEV('N', 'V', N, A.data(), N, wr.data(), wi.data(), vl.data(), 1, V.data(), N, work.data(), lwork, &info);
    }
    if (info != 0) throw NumericalError("tangent spectrum: LAPACK failed (info = " + std::to_string(info) + ")");
    for (int k = 0; k < N; ++k) {
      if (wi[k] == 0.0 && std::abs(wr[k] - far) <= 1e-8 * far) continue;  // a constrained dof's
      re.push_back(wr[k]);
      im.push_back(wi[k]);
      auto v = Teuchos::rcp(new Vector(rowMap));  // GEEV: a complex pair's real part is column k (the first of two)
      const int column = wi[k] < 0.0 ? k - 1 : k;
      auto m = v->getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (std::size_t l = 0; l < v->getLocalLength(); ++l)
        m(l, 0) = V[std::size_t(column) * N + std::size_t(rowMap->getGlobalElement(LocalIndex(l)) - base)];
      vectors.push_back(v);
    }
    for (std::size_t k = 0; k < re.size(); ++k) result.negative += re[k] < 0.0 ? 1 : 0;
  } else {
    const auto symmetry = result.symmetric ? MumpsFactorization::Symmetry::Symmetric : MumpsFactorization::Symmetry::General;
    if (!mumps_ || mumps_->symmetry() != symmetry) mumps_ = std::make_unique<MumpsFactorization>(symmetry, 4, true);
    try {
      mumps_->factorize(rowMap, rowMap, n, base, std::move(irn), std::move(jcn), std::move(val));
    } catch (const std::runtime_error& e) {
      throw NumericalError(std::string("tangent spectrum: ") + e.what());
    }
    using MV = MultiVector;
    using OP = Operator;
    auto start = Teuchos::rcp(new MV(rowMap, 1));
    startVector(*start);
    auto problem = Teuchos::rcp(new Anasazi::BasicEigenproblem<Real, MV, OP>(
        Teuchos::rcp(new InverseOperator(*mumps_, rowMap)), start));
    problem->setHermitian(result.symmetric);
    problem->setNEV(wanted);
    if (!problem->setProblem()) throw NumericalError("tangent spectrum: Anasazi refused the eigenproblem");
    Teuchos::ParameterList settings;
    settings.set("Which", "LM");  // of K_FF^-1: the eigenvalues of K_FF nearest 0
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
    for (int k = 0; k < solution.numVecs; ++k) {
      // theta = 1 / lambda; a complex pair's vectors are its real and imaginary parts (index +1, -1)
      const std::complex<Real> lambda = 1.0 / std::complex<Real>(solution.Evals[k].realpart, solution.Evals[k].imagpart);
      re.push_back(lambda.real());
      im.push_back(lambda.imag());
      const int column = !solution.index.empty() && solution.index[std::size_t(k)] < 0 ? k - 1 : k;
      auto v = Teuchos::rcp(new Vector(rowMap));
      v->update(1.0, *solution.Evecs->getVector(std::size_t(column)), 0.0);
      vectors.push_back(v);
    }
    if (result.symmetric) {
      result.negative = mumps_->negativePivots();  // exact: Sylvester's law of inertia
    } else {
      // the negative real parts found; det K_FF has the sign (-1)^(number of negative real eigenvalues): if the
      // parity differs, one more lies beyond those computed
      for (std::size_t k = 0; k < re.size(); ++k) result.negative += re[k] < 0.0 ? 1 : 0;
      int realNegative = 0;
      for (std::size_t k = 0; k < re.size(); ++k) realNegative += re[k] < 0.0 && im[k] == 0.0 ? 1 : 0;
      if ((mumps_->determinantSign() < 0) != (realNegative % 2 == 1)) ++result.negative, result.complete = false;
    }
  }
  for (std::size_t k : nearestZero(re, im, wanted)) {
    result.eigenvalues.push_back(re[k]);
    result.imaginaryParts.push_back(im[k]);
    result.modes.push_back(vectors[k]);
  }
  for (auto& mode : result.modes) normalizeMode(*mode);
  return result;
}

}  // namespace cgcm::solver
