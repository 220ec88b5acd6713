#include "cgcm/solver/ModelEvaluator.hpp"

#include <Thyra_DefaultSpmdVectorSpace.hpp>
#include <Thyra_DetachedVectorView.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>

#include "cgcm/core/Error.hpp"

namespace cgcm::solver {

using MEB = Thyra::ModelEvaluatorBase;
using Extract = Thyra::TpetraOperatorVectorExtraction<Real, LocalIndex, GlobalIndex, assembly::Node>;

ModelEvaluator::ModelEvaluator(std::shared_ptr<assembly::Assembler> assembler,
                               std::shared_ptr<assembly::DirichletConditions> dirichlet,
                               Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> linearSolver)
    : assembler_(std::move(assembler)), dirichlet_(std::move(dirichlet)), linearSolver_(std::move(linearSolver)) {
  const auto& comm = assembler_->dofs().comm();
  xSpace_ = Thyra::createVectorSpace<Real>(map());
  pMap_ = Teuchos::rcp(new assembly::Map(1, 0, comm, Tpetra::LocallyReplicated));
  pSpace_ = Thyra::createVectorSpace<Real>(pMap_);
  pNames_ = Teuchos::rcp(new Teuchos::Array<std::string>(1, kLoadParameterName));

  MEB::InArgsSetup<Real> in;
  in.setModelEvalDescription("cgcm mechanics");
  in.set_Np(1);
  in.setSupports(MEB::IN_ARG_x);
  nominal_ = in;
  auto x0 = Thyra::createMember(xSpace_);
  Thyra::assign(x0.ptr(), 0.0);
  nominal_.set_x(x0);
  pNominal_ = Thyra::createMember(pSpace_);
  Thyra::assign(pNominal_.ptr(), 0.0);
  nominal_.set_p(0, pNominal_);
}

Teuchos::RCP<const Thyra::VectorSpaceBase<Real>> ModelEvaluator::get_p_space(int l) const {
  TEUCHOS_TEST_FOR_EXCEPTION(l != 0, std::invalid_argument, "cgcm model has one parameter vector");
  return pSpace_;
}

Teuchos::RCP<const Teuchos::Array<std::string>> ModelEvaluator::get_p_names(int l) const {
  TEUCHOS_TEST_FOR_EXCEPTION(l != 0, std::invalid_argument, "cgcm model has one parameter vector");
  return pNames_;
}

void ModelEvaluator::setLoad(Real p) {
  load_ = p;
  // A solver that copied the nominal p(0) holds this very vector: keep it current.
  Thyra::set_ele(0, p, pNominal_.ptr());
}

MEB::InArgs<Real> ModelEvaluator::getNominalValues() const { return nominal_; }

MEB::InArgs<Real> ModelEvaluator::createInArgs() const {
  MEB::InArgsSetup<Real> in;
  in.setModelEvalDescription("cgcm mechanics");
  in.set_Np(1);
  in.setSupports(MEB::IN_ARG_x);
  return in;
}

MEB::OutArgs<Real> ModelEvaluator::createOutArgsImpl() const {
  MEB::OutArgsSetup<Real> out;
  out.setModelEvalDescription("cgcm mechanics");
  out.set_Np_Ng(1, 0);
  out.setSupports(MEB::OUT_ARG_f);
  out.setSupports(MEB::OUT_ARG_W_op);
  out.setSupports(MEB::OUT_ARG_DfDp, 0, MEB::DerivativeSupport(MEB::DERIV_MV_BY_COL));
  return out;
}

Teuchos::RCP<Thyra::LinearOpBase<Real>> ModelEvaluator::create_W_op() const {
  Teuchos::RCP<assembly::Operator> W = assembler_->createMatrix();
  return Thyra::tpetraLinearOp<Real, LocalIndex, GlobalIndex, assembly::Node>(xSpace_, xSpace_, W);
}

void ModelEvaluator::evaluateUnconstrained(const Vector& u, Vector& f) { assembler_->evaluate(u, f, nullptr); }

void ModelEvaluator::evalModelImpl(const MEB::InArgs<Real>& in, const MEB::OutArgs<Real>& out) const {
  const auto u = Extract::getConstTpetraVector(in.get_x());
  Real p = load_;
  if (!in.get_p(0).is_null()) p = Thyra::get_ele(*in.get_p(0), 0);

  const auto fOut = out.get_f();
  const auto WOut = out.get_W_op();
  const auto dfdp = out.get_DfDp(0).getMultiVector();

  Teuchos::RCP<Vector> f;
  if (!fOut.is_null()) f = Extract::getTpetraVector(fOut);
  Teuchos::RCP<Matrix> J;
  if (!WOut.is_null()) {
    J = Teuchos::rcp_dynamic_cast<Matrix>(Extract::getTpetraOperator(WOut), true);
  }

  if (!f.is_null() || !J.is_null()) {
    Teuchos::RCP<Vector> fWork = f.is_null() ? Teuchos::rcp(new Vector(map())) : f;
    lastInverted_ = false;
    try {
      assembler_->evaluate(*u, *fWork, J.get());
    } catch (const InvertedElementError&) {
      if (!J.is_null()) throw;  // no tangent exists: the caller cuts the step back
      // A huge residual makes a line search back off instead of accepting the state.
      lastInverted_ = true;
      fWork->putScalar(1.0e100);
      return;
    }
    if (!f.is_null()) dirichlet_->applyToResidual(*u, p, *f);
    if (!J.is_null()) dirichlet_->applyToJacobian(*J);
  }
  if (!dfdp.is_null()) {
    auto d = Extract::getTpetraMultiVector(dfdp);
    dirichlet_->residualParameterDerivative(*d->getVectorNonConst(0));
  }
}

}  // namespace cgcm::solver
