#include "cgcm/solver/PseudoTransientModel.hpp"

#include <Thyra_TpetraThyraWrappers.hpp>

#include <algorithm>
#include <cmath>

#include "cgcm/core/Error.hpp"

namespace cgcm::solver {

using MEB = Thyra::ModelEvaluatorBase;
using Extract = Thyra::TpetraOperatorVectorExtraction<Real, LocalIndex, GlobalIndex, assembly::Node>;

PseudoTransientModel::PseudoTransientModel(Teuchos::RCP<cgcm::solver::ModelEvaluator> model)
    : model_(std::move(model)), mass_(Teuchos::rcp(new Vector(model_->map()))) {}

void PseudoTransientModel::setMassFromJacobian(const Vector& x) {
  const auto W = model_->create_W_op();
  auto in = model_->getNominalValues();
  const auto xCopy = Teuchos::rcp(new Vector(x, Teuchos::Copy));
  in.set_x(Thyra::createConstVector(
      Teuchos::rcp_implicit_cast<const Tpetra::Vector<Real, LocalIndex, GlobalIndex, assembly::Node>>(xCopy)));
  auto out = model_->createOutArgs();
  out.set_W_op(W);
  model_->evalModel(in, out);
  const auto J = Teuchos::rcp_dynamic_cast<Matrix>(Extract::getTpetraOperator(W), true);
  J->getLocalDiagCopy(*mass_);
  mass_->abs(*mass_);
  model_->dirichlet().zeroConstrained(*mass_);
  const Real largest = mass_->normInf();
  if (!(largest > 0.0) || !std::isfinite(largest))
    throw NumericalError("pseudo-transient relaxation: the diagonal of the Jacobian is zero or not finite");
  auto m = mass_->getLocalViewHost(Tpetra::Access::ReadWrite);
  Vector mask(model_->map());
  mask.putScalar(1.0);
  model_->dirichlet().zeroConstrained(mask);
  auto free = mask.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (std::size_t i = 0; i < m.extent(0); ++i)
    if (free(i, 0) != 0.0) m(i, 0) = std::max(m(i, 0), 1e-12 * largest);
}

MEB::InArgs<Real> PseudoTransientModel::createInArgs() const {
  MEB::InArgsSetup<Real> in;
  in.setModelEvalDescription("cgcm mechanics, pseudo-transient");
  in.set_Np(1);
  in.setSupports(MEB::IN_ARG_x);
  in.setSupports(MEB::IN_ARG_x_dot);
  in.setSupports(MEB::IN_ARG_alpha);
  in.setSupports(MEB::IN_ARG_beta);
  in.setSupports(MEB::IN_ARG_t);
  return in;
}

MEB::InArgs<Real> PseudoTransientModel::getNominalValues() const {
  auto in = createInArgs();
  const auto nominal = model_->getNominalValues();
  in.set_x(nominal.get_x());
  in.set_p(0, nominal.get_p(0));
  in.set_alpha(0.0);
  in.set_beta(1.0);
  return in;
}

MEB::OutArgs<Real> PseudoTransientModel::createOutArgsImpl() const {
  MEB::OutArgsSetup<Real> out;
  out.setModelEvalDescription("cgcm mechanics, pseudo-transient");
  out.set_Np_Ng(1, 0);
  out.setSupports(MEB::OUT_ARG_f);
  out.setSupports(MEB::OUT_ARG_W_op);
  return out;
}

void PseudoTransientModel::evalModelImpl(const MEB::InArgs<Real>& in, const MEB::OutArgs<Real>& out) const {
  auto steadyIn = model_->createInArgs();
  steadyIn.set_x(in.get_x());
  steadyIn.set_p(0, in.get_p(0));
  auto steadyOut = model_->createOutArgs();
  steadyOut.set_f(out.get_f());
  steadyOut.set_W_op(out.get_W_op());
  model_->evalModel(steadyIn, steadyOut);

  const auto xDot = in.get_x_dot();
  if (!out.get_f().is_null() && !xDot.is_null()) {
    auto f = Extract::getTpetraVector(out.get_f());
    f->elementWiseMultiply(1.0, *mass_, *Extract::getConstTpetraVector(xDot), 1.0);
  }
  const Real alpha = in.get_alpha(), beta = in.get_beta();
  if (!out.get_W_op().is_null() && (alpha != 0.0 || beta != 1.0)) {
    auto J = Teuchos::rcp_dynamic_cast<Matrix>(Extract::getTpetraOperator(out.get_W_op()), true);
    J->beginModify();
    {
      auto lcl = J->getLocalMatrixHost();
      const auto& rowMap = *J->getRowMap();
      const auto& colMap = *J->getColMap();
      auto m = mass_->getLocalViewHost(Tpetra::Access::ReadOnly);
      for (LocalIndex i = 0; i < LocalIndex(lcl.numRows()); ++i) {
        const LocalIndex diag = colMap.getLocalElement(rowMap.getGlobalElement(i));
        auto row = lcl.row(i);
        for (LocalIndex j = 0; j < row.length; ++j) {
          row.value(j) *= beta;
          if (row.colidx(j) == diag) row.value(j) += alpha * m(i, 0);
        }
      }
    }
    J->endModify();
  }
}

}  // namespace cgcm::solver
