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
  /// Accept an iterate where |f| cycles between two values below this force
  /// (0: never). Method 3 on piecewise-linear surfaces has a residual that
  /// jumps where a closest point moves across a concave corner of the other
  /// surface, so Newton can alternate across such a switch (the stall test in
  /// NewtonSolver.cpp). The problem sets this from its force scale times
  /// "Stall Tolerance".
  Real stallTolerance = 0.0;
  Real relativeStallTolerance = 2e-3;  ///< "Stall Tolerance", relative to the problem's force scale
  Real stallUpdateTolerance = 0.0;     ///< and the last update below this (problem length scale, e.g. r0/10)

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
  bool stalled = false;             ///< accepted in a cycle below the stall tolerance
  bool graphOutdated = false;       ///< the last attempt met interaction entries outside the graph
  int graphRebuilds = 0;            ///< graph rebuilds during this solve
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

  /// The force below which a Newton cycle is accepted (NewtonSettings::stallTolerance),
  /// e.g. scaled with a weakened interaction.
  void setStallTolerance(Real tolerance) { settings_.stallTolerance = tolerance; }

  /// Pseudo-transient continuation from u (whose constrained dofs already hold
  /// their values): x <- x - (J + D/dt)^-1 f with D = |diag J| and dt growing
  /// as |f| falls (switched evolution relaxation), then Newton. Small dt moves
  /// the state downhill like a damped dynamic relaxation, so after a fold of
  /// the displacement-controlled path it settles on a stable branch. Collective.
  /// No dof moves more than `maxMove` in one pseudo-time step (the update is
  /// scaled down), so a snapping state cannot jump through the other body.
  NewtonResult solvePseudoTransient(Vector& u, Real maxMove = 1e300, Real initialTimeStep = 1e-2,
                                    int maxSteps = 300);

 private:
  NewtonResult solveOnCurrentGraph(Vector& u);

  Teuchos::RCP<ModelEvaluator> model_;
  NewtonSettings settings_;
  Teuchos::RCP<NOX::Thyra::Group> group_;
  Teuchos::RCP<Teuchos::ParameterList> noxParams_;
  Teuchos::RCP<Vector> lastIterate_;  ///< iterate at which the graph was found outdated
};

}  // namespace cgcm::solver
