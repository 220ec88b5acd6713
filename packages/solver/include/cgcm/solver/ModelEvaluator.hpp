#pragma once
// The discrete problem as a Thyra ModelEvaluator: state x = nodal
// displacements (owned dofs), parameter vector p(0) = the named scalar
// parameters (first the prescribed displacement u; then any others
// the problem exposes, e.g. gammaW), residual f(x, p) = f_int(x) + f_C(x; p)
// with Dirichlet rows x_i - (offset_i + scale_i u), and W = df/dx on the
// assembled Tpetra matrix. NOX (Newton) and LOCA (continuation) drive it.
//
// A failed evaluation (an inverted cell, touching surfaces, a non-finite
// value, interaction entries outside the matrix graph) throws a
// cgcm::NumericalError: NOX, run with "Catch Throws During Solve", turns it
// into a failed solve, and the caller cuts the step back.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "cgcm/assembly/Problem.hpp"
#include "cgcm/assembly/Dirichlet.hpp"
#include "cgcm/core/ScalarParameter.hpp"
#include "cgcm/solver/ParameterizedModel.hpp"

namespace cgcm::solver {

using assembly::Matrix;

class ModelEvaluator : public ParameterizedModel {
 public:
  /// Name of p(0)[0], the prescribed displacement.
  static constexpr const char* kDisplacementParameterName = "u";

  ModelEvaluator(std::shared_ptr<assembly::Problem> problem,
                 std::shared_ptr<assembly::DirichletConditions> dirichlet,
                 Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> linearSolver,
                 std::vector<ScalarParameter> parameters = {});

  /// Names of the entries of p(0): "u" first, then the extra parameters.
  const Teuchos::Array<std::string>& parameterNames() const override { return *pNames_; }
  /// The parameter values used when the caller passes no p(0) (NOX Newton);
  /// LOCA passes its own.
  void setParameter(int index, Real value) override;
  Real parameter(int index) const;
  std::vector<Real> parameters() const override;

  /// The interaction couplings within the middle of the cutoff and the search radius.
  bool graphCovers(const Vector& x) override;
  void growGraph(const Vector& x, bool widen) override { problem_->updateInteractionGraph(x, true, widen ? 2.0 : 1.0); }
  bool graphOutdated() const override { return problem_->graphOutdated(); }
  void clearGraphOutdated() override { problem_->clearGraphOutdated(); }
  /// The prescribed displacement u, p(0)[0].
  void setDisplacement(Real u) { setParameter(0, u); }
  Real displacement() const { return parameter(0); }

  /// Residual before boundary conditions (the internal force, whose
  /// constrained entries are the reactions) at (x, p). Collective.
  void evaluateUnconstrained(const Vector& x, const std::vector<Real>& p, Vector& f);

  assembly::Problem& problem() { return *problem_; }
  const assembly::DirichletConditions& dirichlet() const { return *dirichlet_; }
  const Teuchos::RCP<const assembly::Map>& map() const { return problem_->dofs().ownedMap(); }

  // Thyra::ModelEvaluator
  Teuchos::RCP<const Thyra::VectorSpaceBase<Real>> get_x_space() const override { return xSpace_; }
  Teuchos::RCP<const Thyra::VectorSpaceBase<Real>> get_f_space() const override { return xSpace_; }
  Teuchos::RCP<const Thyra::VectorSpaceBase<Real>> get_p_space(int l) const override;
  Teuchos::RCP<const Teuchos::Array<std::string>> get_p_names(int l) const override;
  Thyra::ModelEvaluatorBase::InArgs<Real> getNominalValues() const override;
  Thyra::ModelEvaluatorBase::InArgs<Real> createInArgs() const override;
  Teuchos::RCP<Thyra::LinearOpBase<Real>> create_W_op() const override;
  Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<Real>> get_W_factory() const override {
    return linearSolver_;
  }

 protected:
  void evalModelImpl(const Thyra::ModelEvaluatorBase::InArgs<Real>& in,
                     const Thyra::ModelEvaluatorBase::OutArgs<Real>& out) const override;

 private:
  Thyra::ModelEvaluatorBase::OutArgs<Real> createOutArgsImpl() const override;
  /// The parameter values of `in` (or the nominal ones), applied to the physics.
  std::vector<Real> applyParameters(const Thyra::ModelEvaluatorBase::InArgs<Real>& in) const;
  void applyParameters(const std::vector<Real>& p) const;
  /// f(x, p) with boundary conditions (residual only).
  void residual(const Vector& x, const std::vector<Real>& p, Vector& f) const;

  std::shared_ptr<assembly::Problem> problem_;
  std::shared_ptr<assembly::DirichletConditions> dirichlet_;
  Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> linearSolver_;
  std::vector<ScalarParameter> extra_;
  mutable std::vector<Real> applied_;  ///< values of the extra parameters the physics holds now
  Teuchos::RCP<const Thyra::VectorSpaceBase<Real>> xSpace_, pSpace_;
  Teuchos::RCP<const assembly::Map> pMap_;
  Teuchos::RCP<const Teuchos::Array<std::string>> pNames_;
  Thyra::ModelEvaluatorBase::InArgs<Real> nominal_;
  Teuchos::RCP<Thyra::VectorBase<Real>> pNominal_;  ///< the p(0) held by nominal_
};

}  // namespace cgcm::solver
