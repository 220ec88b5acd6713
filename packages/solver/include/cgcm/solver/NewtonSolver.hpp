#pragma once
// Newton's method (NOX, line-search based) on the ModelEvaluator at a fixed load.
#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

#include "cgcm/solver/ModelEvaluator.hpp"

namespace NOX::Thyra {
class Group;
}

namespace cgcm::solver {

struct NewtonSettings {
  enum class LineSearch { FullStep, Backtrack };
  LineSearch lineSearch = LineSearch::FullStep;
  Real relativeTolerance = 1e-10;  ///< on ||f|| relative to ||f|| at the start of the step
  Real absoluteTolerance = 1e-12;  ///< on ||f|| (force units)
  int maxIterations = 25;
  bool printIterations = false;

  /// Valid parameters of the "Newton" sublist, with defaults and documentation.
  static Teuchos::RCP<const Teuchos::ParameterList> validParameters();
  /// Reads a validated "Newton" sublist.
  static NewtonSettings fromParameters(const Teuchos::ParameterList& p);
};

struct NewtonResult {
  bool converged = false;
  int iterations = 0;
  std::vector<Real> residualNorms;  ///< ||f|| at the start and after each iteration
  std::string failure;              ///< why it did not converge
  double seconds = 0.0;             ///< wall time of the whole solve
  double evaluationSeconds = 0.0;   ///< part of it spent in residual/tangent evaluations
};

class NewtonSolver {
 public:
  NewtonSolver(Teuchos::RCP<ModelEvaluator> model, const NewtonSettings& settings);
  ~NewtonSolver();

  /// Solves f(u, p) = 0 at the model's current load, starting from u; on
  /// convergence u holds the solution, otherwise it is left unchanged. Collective.
  NewtonResult solve(Vector& u);

  /// Rebuilds the Jacobian operator (after the matrix graph changed).
  void resetJacobian();

 private:
  Teuchos::RCP<ModelEvaluator> model_;
  NewtonSettings settings_;
  Teuchos::RCP<NOX::Thyra::Group> group_;
  Teuchos::RCP<Teuchos::ParameterList> noxParams_;
};

}  // namespace cgcm::solver
