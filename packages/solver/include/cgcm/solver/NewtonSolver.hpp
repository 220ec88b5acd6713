#pragma once
// Newton's method (NOX, line-search based) on the ModelEvaluator at fixed
// parameters. A state is accepted only when the residual passes the force
// test of Convergence.hpp.
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
  /// "Residual Tolerance": converged when |f|_2 <= this * forceScale.
  Real residualTolerance = 1e-10;
  /// The problem's force unit (set by the problem, e.g. Y R0^2).
  Real forceScale = 1.0;
  int maxIterations = 15;
  bool printIterations = false;

  /// The tolerance on |f|_2 in force units.
  Real tolerance() const { return residualTolerance * forceScale; }

  /// Valid parameters of the "Newton" sublist, with defaults and documentation.
  static Teuchos::RCP<const Teuchos::ParameterList> validParameters();
  /// Reads a validated "Newton" sublist (forceScale stays 1).
  static NewtonSettings fromParameters(const Teuchos::ParameterList& p);
};

struct NewtonResult {
  bool converged = false;
  int iterations = 0;
  std::vector<Real> residualNorms;  ///< |f|_2 at the start and after each iteration
  std::string failure;              ///< why it did not converge
  double seconds = 0.0;             ///< wall time of the whole solve
  double evaluationSeconds = 0.0;   ///< part of it spent in residual/tangent evaluations
  int graphRebuilds = 0;            ///< graph rebuilds during this solve
};

class NewtonSolver {
 public:
  NewtonSolver(Teuchos::RCP<ModelEvaluator> model, const NewtonSettings& settings);
  ~NewtonSolver();

  /// Solves f(u, p) = 0 at the model's current parameters, starting from u; on
  /// convergence u holds the solution, otherwise it is left unchanged.
  /// Evaluation errors (inverted cells, touching surfaces, linear solver
  /// breakdowns) end the solve as a failure with their message. Collective.
  NewtonResult solve(Vector& u);

  /// Rebuilds the Jacobian operator (after the matrix graph changed).
  void resetJacobian();

  const NewtonSettings& settings() const { return settings_; }

 private:
  NewtonResult solveOnCurrentGraph(Vector& u);

  Teuchos::RCP<ModelEvaluator> model_;
  NewtonSettings settings_;
  Teuchos::RCP<NOX::Thyra::Group> group_;
  Teuchos::RCP<Teuchos::ParameterList> noxParams_;
  Teuchos::RCP<Vector> lastIterate_;  ///< iterate at which the graph was found outdated
};

/// Wall time the assembler has spent in evaluations so far.
double evaluationSeconds(const assembly::Assembler& a);

}  // namespace cgcm::solver
