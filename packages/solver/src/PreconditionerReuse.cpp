#include "PreconditionerReuse.hpp"

#include <Teuchos_ParameterList.hpp>
#include <Thyra_PreconditionerFactoryBase.hpp>

#include <stdexcept>

namespace cgcm::solver {

// Every rank decides alike (a preconditioner's set-up is collective): ages and Krylov counts are the same on
// every rank.
struct PreconditionerReuseFactory::Kept {
  Teuchos::RCP<Thyra::PreconditionerFactoryBase<Real>> factory;
  int maxReuse;
  Real growthLimit;
  Teuchos::RCP<Thyra::PreconditionerBase<Real>> preconditioner;  ///< null until the first Jacobian
  int age = 0;              ///< later Jacobians it has served
  int firstIterations = -1;  ///< Krylov iterations of the first solve with it (-1: none yet, or not known)
  bool rebuild = false;      ///< a solve with it needed too many: build anew for the next Jacobian

  void build(const Teuchos::RCP<const Thyra::LinearOpSourceBase<Real>>& src) {
    if (preconditioner.is_null()) preconditioner = factory->createPrec();
    factory->initializePrec(src, preconditioner.get());
    age = 0;
    firstIterations = -1;
    rebuild = false;
  }
};

namespace {

// Belos' Krylov iterations of a solve, or -1 where the status does not say.
int krylovIterations(const Thyra::SolveStatus<Real>& status) {
  const auto& extra = status.extraParameters;
  if (extra.is_null() || !extra->isType<int>("Belos/Iteration Count")) return -1;
  return extra->get<int>("Belos/Iteration Count");
}

}  // namespace

class ReusingSolve : public OperatorSolveBase {
 public:
  using Kept = PreconditionerReuseFactory::Kept;

  ReusingSolve(Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> innerFactory,
               Teuchos::RCP<Thyra::LinearOpWithSolveBase<Real>> inner, Teuchos::RCP<Kept> kept)
      : innerFactory_(std::move(innerFactory)), inner_(std::move(inner)), kept_(std::move(kept)) {}

  void initialize(const Teuchos::RCP<const Thyra::LinearOpSourceBase<Real>>& src, Thyra::ESupportSolveUse use) {
    setSource(src);
    use_ = use;
    Kept& k = *kept_;
    if (k.preconditioner.is_null() || k.rebuild || k.age >= k.maxReuse) {
      k.build(src);
    } else {
      ++k.age;
    }
    innerFactory_->initializePreconditionedOp(src, k.preconditioner, inner_.get(), use);
  }

 protected:
  bool solveSupportsSolveMeasureTypeImpl(Thyra::EOpTransp t, const Thyra::SolveMeasureType& m) const override {
    return inner_->solveSupportsSolveMeasureType(t, m);
  }

  Thyra::SolveStatus<Real> solveImpl(const Thyra::EOpTransp t, const Thyra::MultiVectorBase<Real>& B,
                                     const Teuchos::Ptr<Thyra::MultiVectorBase<Real>>& X,
                                     const Teuchos::Ptr<const Thyra::SolveCriteria<Real>> criteria) const override {
    Kept& k = *kept_;
    Thyra::SolveStatus<Real> status = inner_->solve(t, B, X, criteria);
    const int iterations = krylovIterations(status);
    if (k.age == 0) {  // the preconditioner of this Jacobian: its count is the reference
      if (k.firstIterations < 0) k.firstIterations = iterations;
      return status;
    }
    if (status.solveStatus != Thyra::SOLVE_STATUS_UNCONVERGED) {
      if (iterations >= 0 && k.firstIterations >= 0 && iterations > k.growthLimit * k.firstIterations)
        k.rebuild = true;
      return status;
    }
    // A kept preconditioner under which the solve failed: a fresh one, and the solve again from where it
    // stopped, counted as one solve of both attempts' iterations.
    k.build(src_);
    innerFactory_->initializePreconditionedOp(src_, k.preconditioner, inner_.get(), use_);
    Thyra::SolveStatus<Real> again = inner_->solve(t, B, X, criteria);
    const int more = krylovIterations(again);
    k.firstIterations = more;
    if (iterations >= 0 && more >= 0 && !again.extraParameters.is_null()) {
      again.extraParameters->set("Belos/Iteration Count", iterations + more);
      again.extraParameters->set("Iteration Count", iterations + more);
    }
    return again;
  }

 private:
  Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> innerFactory_;
  Teuchos::RCP<Thyra::LinearOpWithSolveBase<Real>> inner_;
  Teuchos::RCP<Kept> kept_;
  Thyra::ESupportSolveUse use_ = Thyra::SUPPORT_SOLVE_UNSPECIFIED;
};

PreconditionerReuseFactory::PreconditionerReuseFactory(Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> inner,
                                                       int maxReuse, Real growthLimit)
    : DecoratingSolveFactory(std::move(inner)), kept_(Teuchos::rcp(new Kept)) {
  if (maxReuse < 0 || !(growthLimit >= 1.0))
    throw std::logic_error("PreconditionerReuseFactory: maxReuse >= 0 and growthLimit >= 1");
  kept_->factory = inner_->getPreconditionerFactory();
  if (kept_->factory.is_null() ||
      !inner_->supportsPreconditionerInputType(Thyra::PRECONDITIONER_INPUT_TYPE_AS_OPERATOR))
    throw std::logic_error("PreconditionerReuseFactory: the inner strategy has no preconditioner factory");
  kept_->maxReuse = maxReuse;
  kept_->growthLimit = growthLimit;
}

Teuchos::RCP<Thyra::LinearOpWithSolveBase<Real>> PreconditionerReuseFactory::createOp() const {
  return Teuchos::rcp(new ReusingSolve(inner_, inner_->createOp(), kept_));
}

void PreconditionerReuseFactory::initializeOp(const Teuchos::RCP<const Thyra::LinearOpSourceBase<Real>>& fwdOpSrc,
                                              Thyra::LinearOpWithSolveBase<Real>* Op,
                                              const Thyra::ESupportSolveUse supportSolveUse) const {
  TEUCHOS_TEST_FOR_EXCEPT(Op == nullptr || fwdOpSrc.is_null());
  Teuchos::dyn_cast<ReusingSolve>(*Op).initialize(fwdOpSrc, supportSolveUse);
}

}  // namespace cgcm::solver
