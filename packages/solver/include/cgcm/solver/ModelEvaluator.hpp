#pragma once
// The discrete problem as a Thyra ModelEvaluator: state x = nodal
// displacements (owned dofs), parameter p(0) = the load parameter (the
// prescribed displacement, named "Applied Displacement"), residual
// f(x, p) = f_int(x) + f_C(x) with Dirichlet rows x_i - (offset_i + scale_i p),
// and W = df/dx on the assembled Tpetra matrix. NOX and LOCA drive it.
#include <Thyra_StateFuncModelEvaluatorBase.hpp>

#include <memory>

#include "cgcm/assembly/Assembler.hpp"
#include "cgcm/assembly/Dirichlet.hpp"

namespace cgcm::solver {

using assembly::Matrix;
using assembly::Vector;

class ModelEvaluator : public Thyra::StateFuncModelEvaluatorBase<Real> {
 public:
  static constexpr const char* kLoadParameterName = "Applied Displacement";

  ModelEvaluator(std::shared_ptr<assembly::Assembler> assembler,
                 std::shared_ptr<assembly::DirichletConditions> dirichlet,
                 Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> linearSolver);

  /// Load parameter used when the caller passes no p(0) (NOX Newton); LOCA passes its own.
  void setLoad(Real p);
  Real load() const { return load_; }

  /// Residual before boundary conditions (the internal force, whose
  /// constrained entries are the reactions), at (u, p). Collective.
  void evaluateUnconstrained(const Vector& u, Vector& f);

  /// True if the last residual-only evaluation met an inverted element; that
  /// residual was then filled with a large value so line searches back off.
  bool lastEvaluationInverted() const { return lastInverted_; }

  assembly::Assembler& assembler() { return *assembler_; }
  const assembly::DirichletConditions& dirichlet() const { return *dirichlet_; }
  const Teuchos::RCP<const assembly::Map>& map() const { return assembler_->dofs().ownedMap(); }

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

 private:
  Thyra::ModelEvaluatorBase::OutArgs<Real> createOutArgsImpl() const override;
  void evalModelImpl(const Thyra::ModelEvaluatorBase::InArgs<Real>& in,
                     const Thyra::ModelEvaluatorBase::OutArgs<Real>& out) const override;

  std::shared_ptr<assembly::Assembler> assembler_;
  std::shared_ptr<assembly::DirichletConditions> dirichlet_;
  Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> linearSolver_;
  Teuchos::RCP<const Thyra::VectorSpaceBase<Real>> xSpace_, pSpace_;
  Teuchos::RCP<const assembly::Map> pMap_;
  Teuchos::RCP<const Teuchos::Array<std::string>> pNames_;
  Thyra::ModelEvaluatorBase::InArgs<Real> nominal_;
  Teuchos::RCP<Thyra::VectorBase<Real>> pNominal_;  ///< the p(0) held by nominal_
  Real load_ = 0.0;
  mutable bool lastInverted_ = false;
};

}  // namespace cgcm::solver
