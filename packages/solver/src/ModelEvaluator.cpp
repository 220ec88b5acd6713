#include "cgcm/solver/ModelEvaluator.hpp"

#include <NOX_Thyra_Vector.H>
#include <Thyra_DefaultSpmdVectorSpace.hpp>
#include <Thyra_DetachedVectorView.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>

#include <cmath>

#include "cgcm/core/Error.hpp"

namespace cgcm::solver {

using MEB = Thyra::ModelEvaluatorBase;
using Extract = Thyra::TpetraOperatorVectorExtraction<Real, LocalIndex, GlobalIndex, assembly::Node>;

ModelEvaluator::ModelEvaluator(std::shared_ptr<assembly::Problem> problem,
                               std::shared_ptr<assembly::DirichletConditions> dirichlet,
                               Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> linearSolver,
                               std::vector<ScalarParameter> parameters)
    : problem_(std::move(problem)),
      dirichlet_(std::move(dirichlet)),
      linearSolver_(std::move(linearSolver)),
      extra_(std::move(parameters)) {
  const auto& comm = problem_->dofs().comm();
  const int np = 1 + int(extra_.size());
  xSpace_ = Thyra::createVectorSpace<Real>(map());
  pMap_ = Teuchos::rcp(new assembly::Map(np, 0, comm, Tpetra::LocallyReplicated));
  pSpace_ = Thyra::createVectorSpace<Real>(pMap_);
  auto names = Teuchos::rcp(new Teuchos::Array<std::string>(1, kDisplacementParameterName));
  for (const auto& e : extra_) names->push_back(e.name);
  pNames_ = names;

  nominal_ = createInArgs();
  auto x0 = Thyra::createMember(xSpace_);
  Thyra::assign(x0.ptr(), 0.0);
  nominal_.set_x(x0);
  pNominal_ = Thyra::createMember(pSpace_);
  Thyra::set_ele(0, 0.0, pNominal_.ptr());
  for (int k = 1; k < np; ++k) Thyra::set_ele(k, extra_[k - 1].nominal, pNominal_.ptr());
  nominal_.set_p(0, pNominal_);
  applied_.assign(extra_.size(), std::nan(""));
}

void ParameterizedModel::setResidualWeights(const Teuchos::RCP<Vector>& weights) {
  residualWeights_ = weights.is_null()
                         ? Teuchos::null
                         : Teuchos::rcp(new NOX::Thyra::Vector(Thyra::createVector(
                               Teuchos::rcp_implicit_cast<Tpetra::Vector<Real, LocalIndex, GlobalIndex, assembly::Node>>(
                                   weights))));
}

int ParameterizedModel::parameterIndex(const std::string& name) const {
  const auto& names = parameterNames();
  for (int k = 0; k < int(names.size()); ++k)
    if (names[k] == name) return k;
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "\"" : ", \"") + n + "\"";
  throw InputError("unknown model parameter \"" + name + "\"; this problem has " + list);
}

bool ModelEvaluator::graphCovers(const Vector& x) {
  auto& a = *problem_;
  if (!a.hasInteraction()) return true;
  return a.interactionGraphCovers(x, 0.5 * (a.interactionCutoff() + a.searchRadius()));
}

Teuchos::RCP<const Thyra::VectorSpaceBase<Real>> ModelEvaluator::get_p_space(int l) const {
  TEUCHOS_TEST_FOR_EXCEPTION(l != 0, std::invalid_argument, "cgcm model has one parameter vector");
  return pSpace_;
}

Teuchos::RCP<const Teuchos::Array<std::string>> ModelEvaluator::get_p_names(int l) const {
  TEUCHOS_TEST_FOR_EXCEPTION(l != 0, std::invalid_argument, "cgcm model has one parameter vector");
  return pNames_;
}

void ModelEvaluator::setParameter(int index, Real value) {
  // A solver that copied the nominal p(0) holds this very vector: keep it current.
  Thyra::set_ele(index, value, pNominal_.ptr());
}

Real ModelEvaluator::parameter(int index) const { return Thyra::get_ele(*pNominal_, index); }

std::vector<Real> ModelEvaluator::parameters() const {
  std::vector<Real> p(pNames_->size());
  for (std::size_t k = 0; k < p.size(); ++k) p[k] = parameter(int(k));
  return p;
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
  Teuchos::RCP<assembly::Operator> W = problem_->createMatrix();
  return Thyra::tpetraLinearOp<Real, LocalIndex, GlobalIndex, assembly::Node>(xSpace_, xSpace_, W);
}

void ModelEvaluator::applyParameters(const std::vector<Real>& p) const {
  for (std::size_t k = 0; k < extra_.size(); ++k) {
    const Real v = p[k + 1];
    if (!std::isfinite(v))
      throw NumericalError("model parameter " + extra_[k].name + " = " + std::to_string(v) + " is not finite");
    if (v == applied_[k]) continue;
    extra_[k].apply(v);
    applied_[k] = v;
  }
}

std::vector<Real> ModelEvaluator::applyParameters(const MEB::InArgs<Real>& in) const {
  const auto pv = in.get_p(0).is_null() ? pNominal_.getConst() : in.get_p(0);
  std::vector<Real> p(pNames_->size());
  for (std::size_t k = 0; k < p.size(); ++k) p[k] = Thyra::get_ele(*pv, int(k));
  applyParameters(p);
  return p;
}

void ModelEvaluator::evaluateUnconstrained(const Vector& x, const std::vector<Real>& p, Vector& f) {
  applyParameters(p);
  problem_->evaluate(x, f, nullptr);
}

void ModelEvaluator::residual(const Vector& x, const std::vector<Real>& p, Vector& f) const {
  applyParameters(p);
  problem_->evaluate(x, f, nullptr);
  dirichlet_->applyToResidual(x, p[0], f);
}

void ModelEvaluator::evalModelImpl(const MEB::InArgs<Real>& in, const MEB::OutArgs<Real>& out) const {
  const auto x = Extract::getConstTpetraVector(in.get_x());
  const std::vector<Real> p = applyParameters(in);
  const auto fOut = out.get_f();
  const auto WOut = out.get_W_op();
  const auto dfdp = out.get_DfDp(0).getMultiVector();

  Teuchos::RCP<Vector> f;
  if (!fOut.is_null()) f = Extract::getTpetraVector(fOut);
  Teuchos::RCP<Matrix> J;
  if (!WOut.is_null()) J = Teuchos::rcp_dynamic_cast<Matrix>(Extract::getTpetraOperator(WOut), true);

  if (!f.is_null() || !J.is_null()) {
    Teuchos::RCP<Vector> fWork = f.is_null() ? Teuchos::rcp(new Vector(map())) : f;
    problem_->evaluate(*x, *fWork, J.get());
    if (!f.is_null()) {
      dirichlet_->applyToResidual(*x, p[0], *f);
      const Real norm = f->norm2();
      if (!std::isfinite(norm)) throw NumericalError("the residual is not finite");
    }
    if (!J.is_null()) dirichlet_->applyToJacobian(*J);
  }
  if (!dfdp.is_null()) {
    auto d = Extract::getTpetraMultiVector(dfdp);
    // u enters through the Dirichlet rows only: exact.
    dirichlet_->residualParameterDerivative(*d->getVectorNonConst(0));
    // The other parameters: central differences of the residual.
    Vector fPlus(map()), fMinus(map());
    for (std::size_t k = 1; k < p.size(); ++k) {
      const Real h = 1e-6 * std::max(std::abs(p[k]), 1e-3);
      std::vector<Real> q = p;
      q[k] = p[k] + h;
      residual(*x, q, fPlus);
      q[k] = p[k] - h;
      residual(*x, q, fMinus);
      d->getVectorNonConst(k)->update(0.5 / h, fPlus, -0.5 / h, fMinus, 0.0);
    }
    applyParameters(p);
  }
}

}  // namespace cgcm::solver
