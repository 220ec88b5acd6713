#pragma once
// Newton's method (NOX, line-search based) on the ModelEvaluator at fixed
// parameters. A state is accepted only when the residual passes the force
// test of Convergence.hpp.
#include <Teuchos_ParameterList.hpp>

#include <functional>
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
  /// Relative tolerance of iterative linear solves ("Linear Solver/Tolerance");
  /// NOX hands it to every solve, so it is set here, not only in Stratimikos.
  Real linearTolerance = 1e-10;
  /// "Linear Solver/Forcing Term" = Eisenstat-Walker: the linear tolerance
  /// follows the residual's decrease (never below linearTolerance).
  bool adaptiveLinearTolerance = false;

  /// The tolerance on |f|_2 in force units.
  Real tolerance() const { return residualTolerance * forceScale; }

  /// Valid parameters of the "Newton" sublist, with defaults and documentation.
  static Teuchos::RCP<const Teuchos::ParameterList> validParameters();
  /// Reads validated "Newton" and "Linear Solver" sublists (forceScale stays 1).
  static NewtonSettings fromParameters(const Teuchos::ParameterList& newton, const Teuchos::ParameterList& linearSolver);
};

/// Pseudo-transient relaxation (PseudoTransientModel): the pseudo-time step
/// delta is dimensionless (the "mass" is |diag df/dx| at the start), follows
/// delta |f_old| / |f|, and beyond `newtonStep` the iteration is plain Newton.
struct RelaxationSettings {
  Real initialStep = 1.0;
  Real minStep = 1e-8;
  Real newtonStep = 1e6;
  /// Cap on the largest dof change per iteration (length units; 0: none).
  Real maxIncrement = 0.0;
  int maxIterations = 400;
};

/// Linear solves and their Krylov iterations (0 for direct solvers), summed.
struct LinearSolveCount {
  long solves = 0;
  long iterations = 0;
  LinearSolveCount& operator+=(const LinearSolveCount& o) {
    solves += o.solves, iterations += o.iterations;
    return *this;
  }
};

struct NewtonResult {
  bool converged = false;
  int iterations = 0;
  std::vector<Real> residualNorms;  ///< |f|_2 at the start and after each iteration
  std::string failure;              ///< why it did not converge
  double seconds = 0.0;             ///< wall time of the whole solve
  double evaluationSeconds = 0.0;   ///< part of it spent in residual/tangent evaluations
  int graphRebuilds = 0;            ///< graph rebuilds during this solve
  /// relax(): |f| rose to more than 3x its lowest earlier value on the way,
  /// i.e. the state fell away from where it started (a snap), rather than
  /// settling onto a nearby equilibrium.
  bool fell = false;
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

  /// Linear solves of every solve() and relax() so far, failed ones included.
  const LinearSolveCount& linearSolves() const { return linearSolves_; }

  /// Relaxes u to an equilibrium at the model's current parameters by
  /// pseudo-transient continuation: an overdamped descent that ends with
  /// Newton steps, for a start that has no equilibrium nearby (just past a
  /// fold). Converged only when the residual passes the same test as solve().
  /// Collective.
  NewtonResult relax(Vector& u, const RelaxationSettings& settings);

  /// Rebuilds the Jacobian operator (after the matrix graph changed).
  void resetJacobian();

  const NewtonSettings& settings() const { return settings_; }

 private:
  /// Runs `attempt` on u, widening the interaction graph and retrying (at
  /// most twice) if the iteration met couplings outside it.
  NewtonResult withGraphUpdates(Vector& u, const std::function<NewtonResult(Vector&)>& attempt);
  NewtonResult solveOnCurrentGraph(Vector& u);
  NewtonResult relaxOnCurrentGraph(Vector& u, const RelaxationSettings& settings);
  /// Runs a NOX solver built from `params` on `group` from u; fills the result.
  NewtonResult runNox(const Teuchos::RCP<NOX::Thyra::Group>& group, const Teuchos::ParameterList& params,
                      int maxIterations, Vector& u);

  Teuchos::RCP<ModelEvaluator> model_;
  NewtonSettings settings_;
  Teuchos::RCP<NOX::Thyra::Group> group_;
  Teuchos::RCP<Teuchos::ParameterList> noxParams_;
  Teuchos::RCP<Vector> lastIterate_;  ///< iterate at which the graph was found outdated
  LinearSolveCount linearSolves_;
};

/// Puts the linear-solve tolerance of `settings` into NOX's "Direction/Newton"
/// sublist, with the Eisenstat-Walker forcing term when `adaptive`.
void setLinearSolveControls(const NewtonSettings& settings, bool adaptive, Teuchos::ParameterList& newtonDirection);

/// Wall time the problem has spent in evaluations so far.
double evaluationSeconds(const assembly::Problem& a);

}  // namespace cgcm::solver
