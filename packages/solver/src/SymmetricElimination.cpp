#include "SymmetricElimination.hpp"

#include <Kokkos_Core.hpp>
#include <Thyra_DefaultLinearOpSource.hpp>
#include <Thyra_LinearOpWithSolveBase.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "cgcm/assembly/TpetraTypes.hpp"

namespace cgcm::solver {

namespace {

using assembly::CrsMatrix;
using assembly::Map;
using assembly::MultiVector;
using assembly::Vector;
using Converter = Thyra::TpetraOperatorVectorExtraction<Real, LocalIndex, GlobalIndex, assembly::Node>;

class SymmetricEliminationSolve : public OperatorSolveBase {
 public:
  explicit SymmetricEliminationSolve(Teuchos::RCP<Thyra::LinearOpWithSolveBase<Real>> inner)
      : inner_(std::move(inner)) {}

  void initialize(const Teuchos::RCP<const Thyra::LinearOpSourceBase<Real>>& src,
                  const Thyra::LinearOpWithSolveFactoryBase<Real>& innerFactory, Thyra::ESupportSolveUse use) {
    setSource(src);
    A_ = Teuchos::rcp_dynamic_cast<const CrsMatrix>(Converter::getConstTpetraOperator(fwdOp_), true);
    const bool newGraph = As_.is_null() || As_->getCrsGraph() != A_->getCrsGraph();
    if (newGraph) {
      if (!A_->getRowMap()->isSameAs(*A_->getDomainMap()))
        throw std::logic_error("symmetric elimination: the matrix's row and domain maps differ");
      As_ = Teuchos::rcp(new CrsMatrix(A_->getCrsGraph()));
      As_->fillComplete(A_->getDomainMap(), A_->getRangeMap());
      AsOp_ = Thyra::tpetraLinearOp<Real, LocalIndex, GlobalIndex, assembly::Node>(
          fwdOp_->range(), fwdOp_->domain(), Teuchos::rcp_implicit_cast<assembly::Operator>(As_));
    }
    eliminate(newGraph);
    innerFactory.initializeOp(Thyra::defaultLinearOpSource(AsOp_), inner_.get(), use);
  }

 protected:
  // The forward operator (OperatorSolveBase's apply) is A itself, unit rows and all.
  bool solveSupportsSolveMeasureTypeImpl(Thyra::EOpTransp t, const Thyra::SolveMeasureType& m) const override {
    return inner_->solveSupportsSolveMeasureType(t, m);
  }
  Thyra::SolveStatus<Real> solveImpl(const Thyra::EOpTransp, const Thyra::MultiVectorBase<Real>& B,
                                     const Teuchos::Ptr<Thyra::MultiVectorBase<Real>>& X,
                                     const Teuchos::Ptr<const Thyra::SolveCriteria<Real>> criteria) const override {
    auto b = Converter::getConstTpetraMultiVector(Teuchos::rcpFromRef(B));
    const std::size_t nv = b->getNumVectors();
    // z = b on the unit rows; b_s = b - A z + z
    MultiVector z(b->getMap(), nv);
    z.elementWiseMultiply(1.0, *mask_, *b, 0.0);
    auto bs = Teuchos::rcp(new MultiVector(*b, Teuchos::Copy));
    A_->apply(z, *bs, Teuchos::NO_TRANS, -1.0, 1.0);
    bs->update(1.0, z, 1.0);

    // The inner solver's relative tolerance refers to |b_s|; asked for one relative to |b|, tighten it by
    // |b| / |b_s| where lifting made the right-hand side larger.
    std::vector<Real> nb(nv), nbs(nv);
    b->norm2(nb);
    bs->norm2(nbs);
    Real tighten = 1.0, widen = 1.0;
    for (std::size_t k = 0; k < nv; ++k)
      if (nbs[k] > 0.0 && nb[k] > 0.0) {
        tighten = std::min(tighten, nb[k] / nbs[k]);
        widen = std::max(widen, nbs[k] / nb[k]);
      }
    Thyra::SolveCriteria<Real> scaled;
    Teuchos::Ptr<const Thyra::SolveCriteria<Real>> innerCriteria = criteria;
    if (!criteria.is_null() && criteria->requestedTol != Thyra::SolveCriteria<Real>::unspecifiedTolerance() &&
        criteria->solveMeasureType(Thyra::SOLVE_MEASURE_NORM_RESIDUAL, Thyra::SOLVE_MEASURE_NORM_RHS) &&
        tighten < 1.0) {
      scaled = *criteria;
      scaled.requestedTol *= tighten;
      innerCriteria = Teuchos::ptrFromRef(scaled);
    }
    auto bsT = Thyra::createConstMultiVector<Real, LocalIndex, GlobalIndex, assembly::Node>(
        Teuchos::rcp_implicit_cast<const MultiVector>(bs), fwdOp_->range());
    Thyra::SolveStatus<Real> status = inner_->solve(Thyra::NOTRANS, *bsT, X, innerCriteria);

    // x = b on the unit rows exactly, whatever the Krylov method left there
    auto x = Converter::getTpetraMultiVector(Teuchos::rcpFromPtr(X));
    MultiVector onUnitRows(x->getMap(), nv);
    onUnitRows.elementWiseMultiply(1.0, *mask_, *x, 0.0);
    x->update(-1.0, onUnitRows, 1.0, z, 1.0);
    if (status.achievedTol != Thyra::SolveStatus<Real>::unknownTolerance()) status.achievedTol *= widen;
    return status;
  }

 private:
  // As_ = A with the columns of A's unit rows zeroed outside them; mask_ = 1 on the unit rows. The entries
  // to zero are found again only when the graph or the set of unit rows changed.
  void eliminate(bool newGraph) {
    const auto lclA = A_->getLocalMatrixHost();
    const Map& rowMap = *A_->getRowMap();
    const Map& colMap = *A_->getColMap();
    // A unit row: diagonal 1, every other entry 0. Most rows fail at their first entry.
    std::vector<char> unitRows(lclA.numRows(), 0);
    for (LocalIndex i = 0; i < LocalIndex(lclA.numRows()); ++i) {
      const LocalIndex diag = colMap.getLocalElement(rowMap.getGlobalElement(i));
      const auto row = lclA.row(i);
      bool unit = true, diagonalOne = false;
      for (LocalIndex j = 0; j < row.length && unit; ++j) {
        if (row.colidx(j) == diag) unit = diagonalOne = row.value(j) == 1.0;
        else unit = row.value(j) == 0.0;
      }
      unitRows[i] = unit && diagonalOne;
    }
    int changed = newGraph || unitRows != unitRows_, anyChanged = 0;
    Teuchos::reduceAll(*rowMap.getComm(), Teuchos::REDUCE_MAX, changed, Teuchos::outArg(anyChanged));
    if (anyChanged) {
      unitRows_ = std::move(unitRows);
      mask_ = Teuchos::rcp(new Vector(A_->getRowMap()));
      {
        auto m = mask_->getLocalViewHost(Tpetra::Access::OverwriteAll);
        for (std::size_t i = 0; i < unitRows_.size(); ++i) m(i, 0) = unitRows_[i] ? 1.0 : 0.0;
      }
      // The mask on the column map; Tpetra leaves the importer null when that is the domain map itself.
      const auto importer = A_->getCrsGraph()->getImporter();
      Vector colMask(A_->getColMap());
      if (!importer.is_null()) colMask.doImport(*mask_, *importer, Tpetra::INSERT);
      const auto c = (importer.is_null() ? *mask_ : colMask).getLocalViewHost(Tpetra::Access::ReadOnly);
      zeroed_.clear();
      for (LocalIndex i = 0; i < LocalIndex(lclA.numRows()); ++i) {
        if (unitRows_[i]) continue;
        const std::size_t begin = lclA.graph.row_map(i), end = lclA.graph.row_map(i + 1);
        for (std::size_t k = begin; k < end; ++k)
          if (c(lclA.graph.entries(k), 0) != 0.0) zeroed_.push_back(k);
      }
    }
    As_->resumeFill();
    {
      const auto lclS = As_->getLocalMatrixHost();
      Kokkos::deep_copy(lclS.values, lclA.values);
      for (const std::size_t k : zeroed_) lclS.values(k) = 0.0;
    }
    As_->fillComplete(A_->getDomainMap(), A_->getRangeMap());
  }

  Teuchos::RCP<Thyra::LinearOpWithSolveBase<Real>> inner_;
  Teuchos::RCP<const CrsMatrix> A_;
  Teuchos::RCP<CrsMatrix> As_;
  Teuchos::RCP<const Thyra::LinearOpBase<Real>> AsOp_;
  Teuchos::RCP<Vector> mask_;
  std::vector<char> unitRows_;     ///< per owned row
  std::vector<std::size_t> zeroed_;  ///< the entries of As_ set to 0 (CSR positions)
};

}  // namespace

bool SymmetricEliminationFactory::isCompatible(const Thyra::LinearOpSourceBase<Real>& fwdOpSrc) const {
  try {
    return !Teuchos::rcp_dynamic_cast<const CrsMatrix>(Converter::getConstTpetraOperator(fwdOpSrc.getOp()))
                .is_null() &&
           inner_->isCompatible(fwdOpSrc);
  } catch (const std::exception&) {
    return false;
  }
}

Teuchos::RCP<Thyra::LinearOpWithSolveBase<Real>> SymmetricEliminationFactory::createOp() const {
  return Teuchos::rcp(new SymmetricEliminationSolve(inner_->createOp()));
}

void SymmetricEliminationFactory::initializeOp(const Teuchos::RCP<const Thyra::LinearOpSourceBase<Real>>& fwdOpSrc,
                                               Thyra::LinearOpWithSolveBase<Real>* Op,
                                               const Thyra::ESupportSolveUse supportSolveUse) const {
  TEUCHOS_TEST_FOR_EXCEPT(Op == nullptr || fwdOpSrc.is_null());
  Teuchos::dyn_cast<SymmetricEliminationSolve>(*Op).initialize(fwdOpSrc, *inner_, supportSolveUse);
}

}  // namespace cgcm::solver
