#include "MumpsSolver.hpp"
#include "MumpsFactorization.hpp"

#include <dmumps_c.h>
#include <mpi.h>

#include <sstream>
#include <stdexcept>
#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>

#include "cgcm/assembly/TpetraTypes.hpp"

namespace cgcm::solver {

namespace {

using assembly::CrsMatrix;
using assembly::Import;
using assembly::Map;
using assembly::MultiVector;
using Converter = Thyra::TpetraOperatorVectorExtraction<Real, LocalIndex, GlobalIndex, assembly::Node>;

/// One factorised matrix: its MUMPS factorisation (general: Dirichlet rows make the matrix unsymmetric).
class MumpsLinearOpWithSolve : public OperatorSolveBase {
 public:
  explicit MumpsLinearOpWithSolve(int ordering) : mumps_(MumpsFactorization::Symmetry::General, ordering) {}

  /// Factorises the matrix of `src`: each rank hands over its owned rows. Collective.
  void initialize(const Teuchos::RCP<const Thyra::LinearOpSourceBase<Real>>& src) {
    setSource(src);
    auto A = Teuchos::rcp_dynamic_cast<const CrsMatrix>(Converter::getConstTpetraOperator(fwdOp_), true);
    const auto rowMap = A->getRowMap();
    const auto colMap = A->getColMap();
    const GlobalIndex base = rowMap->getMinAllGlobalIndex();
    const GlobalIndex n = GlobalIndex(rowMap->getGlobalNumElements());
    if (rowMap->getMaxAllGlobalIndex() - base + 1 != n)
      throw std::runtime_error("MUMPS: the matrix rows are not numbered contiguously");
    std::vector<int> irn, jcn;
    std::vector<Real> val;
    irn.reserve(A->getNodeNumEntries());
    jcn.reserve(A->getNodeNumEntries());
    val.reserve(A->getNodeNumEntries());
    typename CrsMatrix::local_inds_host_view_type cols;
    typename CrsMatrix::values_host_view_type vals;
    for (LocalIndex r = 0; r < LocalIndex(A->getNodeNumRows()); ++r) {
      A->getLocalRowView(r, cols, vals);
      const int row = int(rowMap->getGlobalElement(r) - base + 1);
      for (std::size_t k = 0; k < cols.extent(0); ++k) {
        irn.push_back(row);
        jcn.push_back(int(colMap->getGlobalElement(cols(k)) - base + 1));
        val.push_back(vals(k));
      }
    }
    mumps_.factorize(A->getRangeMap(), A->getDomainMap(), n, base, std::move(irn), std::move(jcn), std::move(val));
  }

 protected:
  bool solveSupportsSolveMeasureTypeImpl(Thyra::EOpTransp, const Thyra::SolveMeasureType&) const override {
    return true;  // a direct solve meets any tolerance
  }
  Thyra::SolveStatus<Real> solveImpl(const Thyra::EOpTransp, const Thyra::MultiVectorBase<Real>& B,
                                     const Teuchos::Ptr<Thyra::MultiVectorBase<Real>>& X,
                                     const Teuchos::Ptr<const Thyra::SolveCriteria<Real>>) const override {
    auto b = Converter::getConstTpetraMultiVector(Teuchos::rcpFromRef(B));
    auto x = Converter::getTpetraMultiVector(Teuchos::rcpFromPtr(X));
    mumps_.solve(*b, *x);
    Thyra::SolveStatus<Real> status;
    status.solveStatus = Thyra::SOLVE_STATUS_CONVERGED;
    return status;
  }

 private:
  MumpsFactorization mumps_;
};

}  // namespace

bool MumpsLinearOpWithSolveFactory::isCompatible(const Thyra::LinearOpSourceBase<Real>& fwdOpSrc) const {
  try {
    return !Teuchos::rcp_dynamic_cast<const CrsMatrix>(Converter::getConstTpetraOperator(fwdOpSrc.getOp())).is_null();
  } catch (const std::exception&) {
    return false;
  }
}

Teuchos::RCP<Thyra::LinearOpWithSolveBase<Real>> MumpsLinearOpWithSolveFactory::createOp() const {
  const auto params = params_.is_null() ? getValidParameters() : params_.getConst();
  const std::string ordering = params->get<std::string>("Ordering");
  return Teuchos::rcp(new MumpsLinearOpWithSolve(ordering == "AMD" ? 0 : 4));  // ICNTL(7): 0 AMD, 4 PORD
}

void MumpsLinearOpWithSolveFactory::initializeOp(const Teuchos::RCP<const Thyra::LinearOpSourceBase<Real>>& fwdOpSrc,
                                                 Thyra::LinearOpWithSolveBase<Real>* Op,
                                                 const Thyra::ESupportSolveUse) const {
  TEUCHOS_TEST_FOR_EXCEPT(Op == nullptr || fwdOpSrc.is_null());
  Teuchos::dyn_cast<MumpsLinearOpWithSolve>(*Op).initialize(fwdOpSrc);
}

void MumpsLinearOpWithSolveFactory::setParameterList(const Teuchos::RCP<Teuchos::ParameterList>& paramList) {
  paramList->validateParametersAndSetDefaults(*getValidParameters());
  params_ = paramList;
}

Teuchos::RCP<Teuchos::ParameterList> MumpsLinearOpWithSolveFactory::unsetParameterList() {
  auto old = params_;
  params_ = Teuchos::null;
  return old;
}

Teuchos::RCP<const Teuchos::ParameterList> MumpsLinearOpWithSolveFactory::getValidParameters() const {
  static const auto valid = [] {
    auto list = Teuchos::rcp(new Teuchos::ParameterList("MUMPS"));
    list->set("Ordering", "PORD",
              "fill-reducing ordering of the analysis: PORD (nested dissection; MUMPS' own choice in Debian's "
              "build, which links neither METIS nor SCOTCH) or AMD (approximate minimum degree: an "
              "analysis several times cheaper, somewhat more fill)",
              Teuchos::rcp(new Teuchos::StringValidator(Teuchos::tuple<std::string>("PORD", "AMD"))));
    return list;
  }();
  return valid;
}

namespace {
// MUMPS' 1-based ICNTL / INFOG (the manual's numbering).
int& icntl(DMUMPS_STRUC_C& id, int i) { return id.icntl[i - 1]; }
int infog(const DMUMPS_STRUC_C& id, int i) { return id.infog[i - 1]; }

// What a failed MUMPS phase means, in words where the code is common.
std::string failure(const char* phase, const DMUMPS_STRUC_C& id) {
  std::ostringstream os;
  os << "MUMPS " << phase << " failed (INFOG(1) = " << infog(id, 1) << ", INFOG(2) = " << infog(id, 2) << ")";
  if (infog(id, 1) == -10) os << ": the matrix is numerically singular";
  if (infog(id, 1) == -9 || infog(id, 1) == -8 || infog(id, 1) == -13) os << ": out of memory";
  return os.str();
}
}  // namespace

void MumpsFactorization::factorize(const Teuchos::RCP<const Map>& rangeMap, const Teuchos::RCP<const Map>& domainMap,
                                   GlobalIndex n, GlobalIndex base, std::vector<int> irn, std::vector<int> jcn,
                                   std::vector<Real> val) {
  const auto comm = Teuchos::rcp_dynamic_cast<const Teuchos::MpiComm<int>>(rangeMap->getComm(), true);
  // every rank must take the same branch: the MUMPS phases are collective
  const int sameHere = initialized_ && n == n_ && irn == irn_ && jcn == jcn_ ? 1 : 0;
  int sameEverywhere = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MIN, sameHere, Teuchos::outArg(sameEverywhere));
  if (sameEverywhere != 1) {
    release();
    id_ = DMUMPS_STRUC_C();
    id_.comm_fortran = MPI_Comm_c2f(*comm->getRawMpiComm());
    id_.par = 1;  // rank 0 works too
    id_.sym = symmetry_ == Symmetry::General ? 0 : 2;  // 2: symmetric, not necessarily definite (LDL^T)
    id_.job = -1;
    dmumps_c(&id_);
    if (infog(id_, 1) < 0) throw std::runtime_error(failure("initialisation", id_));
    initialized_ = true;
    icntl(id_, 1) = -1;  // no messages
    icntl(id_, 2) = -1;
    icntl(id_, 3) = -1;
    icntl(id_, 4) = 0;
    icntl(id_, 5) = 0;   // assembled matrix
    icntl(id_, 18) = 3;  // distributed coordinates
    icntl(id_, 20) = 0;  // dense right-hand sides on rank 0
    icntl(id_, 21) = 0;  // solution on rank 0
    icntl(id_, 7) = ordering_;
    // the root front factorised by MUMPS itself, not ScaLAPACK: only then is INFOG(12) the count of negative pivots
    if (symmetry_ == Symmetry::Symmetric) icntl(id_, 13) = 1;
    if (determinant_) icntl(id_, 33) = 1;  // RINFOG(12) * 2^INFOG(34)
    n_ = n;
    irn_ = std::move(irn);
    jcn_ = std::move(jcn);
    id_.n = int(n);
    id_.nnz_loc = MUMPS_INT8(irn_.size());
    id_.irn_loc = irn_.data();
    id_.jcn_loc = jcn_.data();
    id_.job = 1;
    dmumps_c(&id_);
    if (infog(id_, 1) < 0) throw std::runtime_error(failure("analysis", id_));

    // rank 0 holds every row of the gathered vectors
    std::vector<GlobalIndex> all;
    if (comm->getRank() == 0)
      for (GlobalIndex g = 0; g < n; ++g) all.push_back(base + g);
    rootMap_ = Teuchos::rcp(new Map(Tpetra::global_size_t(n), all.data(), all.size(), rangeMap->getIndexBase(), comm));
    gather_ = Teuchos::rcp(new Import(rangeMap, rootMap_));
    scatter_ = Teuchos::rcp(new Import(rootMap_, domainMap));
  }
  val_ = std::move(val);
  id_.a_loc = val_.data();
  // numerical factorisation; out of memory: more workspace, twice
  for (int attempt = 0;; ++attempt) {
    id_.job = 2;
    dmumps_c(&id_);
    if (infog(id_, 1) >= 0) break;
    if (infog(id_, 1) != -9 || attempt == 2) throw std::runtime_error(failure("factorisation", id_));
    icntl(id_, 14) *= 2;
  }
}

void MumpsFactorization::solve(const MultiVector& b, MultiVector& x) const {
  MultiVector root(rootMap_, b.getNumVectors());
  root.doImport(b, *gather_, Tpetra::INSERT);
  {
    auto data = root.getLocalViewHost(Tpetra::Access::ReadWrite);  // column-major, leading dimension n on rank 0
    id_.rhs = data.data();
    id_.nrhs = int(root.getNumVectors());
    id_.lrhs = root.getLocalLength() > 0 ? int(root.getStride()) : int(n_);
    id_.job = 3;
    dmumps_c(&id_);
  }
  if (infog(id_, 1) < 0) throw std::runtime_error(failure("solve", id_));
  x.doImport(root, *scatter_, Tpetra::INSERT);
}

int MumpsFactorization::negativePivots() const { return infog(id_, 12); }

int MumpsFactorization::determinantSign() const {
  const Real mantissa = id_.rinfog[11];  // RINFOG(12)
  return mantissa > 0.0 ? 1 : mantissa < 0.0 ? -1 : 0;
}

void MumpsFactorization::release() {
  if (!initialized_) return;
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (finalized) return;  // destroyed after MPI: the process is ending anyway
  id_.job = -2;
  dmumps_c(&id_);
  initialized_ = false;
}

}  // namespace cgcm::solver
