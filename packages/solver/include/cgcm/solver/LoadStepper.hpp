#pragma once
// Displacement-controlled load stepping along a piecewise-linear path of the
// load parameter p, with adaptive increments: a step that fails (no Newton
// convergence, inverted element) is cut back and redone from the last
// converged state; it is never accepted.
#include <Teuchos_ParameterList.hpp>

#include <functional>
#include <vector>

#include "cgcm/solver/NewtonSolver.hpp"

namespace cgcm::solver {

struct LoadPathSettings {
  std::vector<Real> path{0.0, 1.0};   ///< waypoints of p; the run starts at path[0]
  Real initialIncrement = 0.01;
  Real minIncrement = 1e-8;
  Real maxIncrement = 0.05;
  int easyIterations = 4;             ///< grow the increment after steps this easy
  Real growth = 1.5;
  Real cutback = 0.5;
  /// Steps that still fail (or jump) below this increment mean the
  /// displacement-controlled branch has ended at a fold: the state jumps to
  /// the other stable branch (pseudo-transient solve) and the step is marked.
  Real foldIncrement = 1e-4;

  /// Valid parameters of the "Loading" sublist.
  static Teuchos::RCP<const Teuchos::ParameterList> validParameters();
  /// Reads and checks a validated "Loading" sublist (increments consistent, path of >= 2 distinct points).
  static LoadPathSettings fromParameters(const Teuchos::ParameterList& p);
};

struct StepInfo {
  int step = 0;       ///< accepted steps so far (0 = initial state)
  Real load = 0.0;
  NewtonResult newton;
  int cutbacks = 0;   ///< failed attempts before this step converged
  bool jump = false;  ///< the state jumped to another branch (fold of the load path)
};

class LoadStepper {
 public:
  using Observer = std::function<void(const StepInfo&, const Vector& u)>;
  /// Tells whether a converged step stayed on the branch it started from
  /// (true) or jumped to another one (false). Default: always continuous.
  using ContinuityCheck = std::function<bool(const Vector& before, const Vector& after)>;

  LoadStepper(Teuchos::RCP<ModelEvaluator> model, NewtonSolver& newton, const LoadPathSettings& settings)
      : model_(std::move(model)), newton_(newton), settings_(settings) {}

  /// Runs the whole path from u (initial guess at path[0]); calls `observer`
  /// after every accepted step. Throws NumericalError if a step fails below the
  /// minimum increment (everything observed so far stays valid).
  void run(Vector& u, const Observer& observer);

  void setContinuityCheck(ContinuityCheck check) { continuous_ = std::move(check); }

  /// Length scale of a jump: the largest move of a dof per pseudo-time step
  /// in a pseudo-transient relaxation and the first push along the branch's
  /// secant (unset: no pushes, the relaxation starts from the last state).
  void setJumpStepLimit(Real maxMove) { jumpStepLimit_ = maxMove; }

 private:
  /// At a fold at load p: finds an equilibrium on another branch from the
  /// last state u (uPrevious: the state before it, or null). Fills trial and
  /// info; false if none was found.
  bool jumpToOtherBranch(Real p, const Vector& u, const Vector* uPrevious, Vector& trial, StepInfo& info);

  ContinuityCheck continuous_;
  Real jumpStepLimit_ = 1e300;
  Teuchos::RCP<ModelEvaluator> model_;
  NewtonSolver& newton_;
  LoadPathSettings settings_;
};

}  // namespace cgcm::solver
