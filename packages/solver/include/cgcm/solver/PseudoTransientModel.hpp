#pragma once
// The model with a pseudo-time derivative, for NOX's pseudo-transient solver:
//   f_t(x, x_dot) = M x_dot + f(x),   W = alpha M + beta df/dx,
// with M a fixed positive diagonal (zero on constrained rows). Driven by NOX's
// "Pseudo-Transient" solver it is an implicit, overdamped relaxation
// M x_dot = -f(x) whose pseudo-time step grows as |f| falls (switched
// evolution relaxation) until the iteration is plain Newton: from a state
// that lost its equilibrium (past a fold) it descends to a stable state,
// which is where a quasi-static jump lands. M = |diag df/dx| at the start
// makes the pseudo-time step dimensionless.
#include "cgcm/solver/ModelEvaluator.hpp"

namespace cgcm::solver {

class PseudoTransientModel : public Thyra::StateFuncModelEvaluatorBase<Real> {
 public:
  explicit PseudoTransientModel(Teuchos::RCP<cgcm::solver::ModelEvaluator> model);

  /// M = |diag df/dx| at x (current parameters), zero on constrained rows;
  /// entries below 1e-12 of the largest are raised to it. Collective.
  void setMassFromJacobian(const Vector& x);
  const Vector& mass() const { return *mass_; }

  // Thyra::ModelEvaluator
  Teuchos::RCP<const Thyra::VectorSpaceBase<Real>> get_x_space() const override { return model_->get_x_space(); }
  Teuchos::RCP<const Thyra::VectorSpaceBase<Real>> get_f_space() const override { return model_->get_f_space(); }
  Teuchos::RCP<const Thyra::VectorSpaceBase<Real>> get_p_space(int l) const override {
    return model_->get_p_space(l);
  }
  Teuchos::RCP<const Teuchos::Array<std::string>> get_p_names(int l) const override {
    return model_->get_p_names(l);
  }
  Thyra::ModelEvaluatorBase::InArgs<Real> getNominalValues() const override;
  Thyra::ModelEvaluatorBase::InArgs<Real> createInArgs() const override;
  Teuchos::RCP<Thyra::LinearOpBase<Real>> create_W_op() const override { return model_->create_W_op(); }
  Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<Real>> get_W_factory() const override {
    return model_->get_W_factory();
  }

 protected:
  void evalModelImpl(const Thyra::ModelEvaluatorBase::InArgs<Real>& in,
                     const Thyra::ModelEvaluatorBase::OutArgs<Real>& out) const override;

 private:
  Thyra::ModelEvaluatorBase::OutArgs<Real> createOutArgsImpl() const override;

  Teuchos::RCP<cgcm::solver::ModelEvaluator> model_;
  Teuchos::RCP<Vector> mass_;
};

}  // namespace cgcm::solver
