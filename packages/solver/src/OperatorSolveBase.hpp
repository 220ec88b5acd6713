#pragma once
// What cgcm's solve strategies (MumpsSolver.hpp, SymmetricElimination.hpp,
// PreconditionerReuse.hpp) share: the object that solves with one forward
// operator takes its source, spaces and apply from that operator and solves without transposition; the
// strategy builds its own preconditioning (none is accepted from outside).
#include <Thyra_LinearOpSourceBase.hpp>
#include <Thyra_LinearOpWithSolveBase.hpp>
#include <Thyra_LinearOpWithSolveFactoryBase.hpp>

#include "cgcm/core/Types.hpp"

namespace cgcm::solver {

class OperatorSolveBase : public Thyra::LinearOpWithSolveBase<Real> {
 public:
  const Teuchos::RCP<const Thyra::LinearOpSourceBase<Real>>& source() const { return src_; }
  Teuchos::RCP<const Thyra::VectorSpaceBase<Real>> range() const override { return fwdOp_->range(); }
  Teuchos::RCP<const Thyra::VectorSpaceBase<Real>> domain() const override { return fwdOp_->domain(); }

 protected:
  void setSource(const Teuchos::RCP<const Thyra::LinearOpSourceBase<Real>>& src) {
    src_ = src;
    fwdOp_ = src->getOp();
  }
  bool opSupportedImpl(Thyra::EOpTransp t) const override { return Thyra::opSupported(*fwdOp_, t); }
  void applyImpl(const Thyra::EOpTransp t, const Thyra::MultiVectorBase<Real>& X,
                 const Teuchos::Ptr<Thyra::MultiVectorBase<Real>>& Y, const Real alpha,
                 const Real beta) const override {
    Thyra::apply(*fwdOp_, t, X, Y, alpha, beta);
  }
  bool solveSupportsImpl(Thyra::EOpTransp t) const override { return Thyra::real_trans(t) == Thyra::NOTRANS; }

  Teuchos::RCP<const Thyra::LinearOpSourceBase<Real>> src_;
  Teuchos::RCP<const Thyra::LinearOpBase<Real>> fwdOp_;
};

/// Creates and initialises OperatorSolveBase objects.
class OperatorSolveFactoryBase : public Thyra::LinearOpWithSolveFactoryBase<Real> {
 public:
  void uninitializeOp(Thyra::LinearOpWithSolveBase<Real>* Op,
                      Teuchos::RCP<const Thyra::LinearOpSourceBase<Real>>* fwdOpSrc,
                      Teuchos::RCP<const Thyra::PreconditionerBase<Real>>* prec,
                      Teuchos::RCP<const Thyra::LinearOpSourceBase<Real>>* approxFwdOpSrc,
                      Thyra::ESupportSolveUse*) const override {
    TEUCHOS_TEST_FOR_EXCEPT(Op == nullptr);
    if (fwdOpSrc) *fwdOpSrc = Teuchos::dyn_cast<OperatorSolveBase>(*Op).source();
    if (prec) *prec = Teuchos::null;
    if (approxFwdOpSrc) *approxFwdOpSrc = Teuchos::null;
  }
  bool supportsPreconditionerInputType(const Thyra::EPreconditionerInputType) const override { return false; }
  void initializePreconditionedOp(const Teuchos::RCP<const Thyra::LinearOpSourceBase<Real>>& fwdOpSrc,
                                  const Teuchos::RCP<const Thyra::PreconditionerBase<Real>>&,
                                  Thyra::LinearOpWithSolveBase<Real>* Op,
                                  const Thyra::ESupportSolveUse supportSolveUse) const override {
    initializeOp(fwdOpSrc, Op, supportSolveUse);
  }
};

/// A strategy that wraps another one (`inner_`), whose parameters are its own.
class DecoratingSolveFactory : public OperatorSolveFactoryBase {
 public:
  explicit DecoratingSolveFactory(Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> inner)
      : inner_(std::move(inner)) {}

  bool isCompatible(const Thyra::LinearOpSourceBase<Real>& fwdOpSrc) const override {
    return inner_->isCompatible(fwdOpSrc);
  }
  void setParameterList(const Teuchos::RCP<Teuchos::ParameterList>& p) override { inner_->setParameterList(p); }
  Teuchos::RCP<Teuchos::ParameterList> getNonconstParameterList() override {
    return inner_->getNonconstParameterList();
  }
  Teuchos::RCP<Teuchos::ParameterList> unsetParameterList() override { return inner_->unsetParameterList(); }
  Teuchos::RCP<const Teuchos::ParameterList> getParameterList() const override { return inner_->getParameterList(); }
  Teuchos::RCP<const Teuchos::ParameterList> getValidParameters() const override {
    return inner_->getValidParameters();
  }

 protected:
  Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> inner_;
};

}  // namespace cgcm::solver
