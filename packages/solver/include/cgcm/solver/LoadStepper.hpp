#pragma once
// Displacement control along a piecewise-linear path of the load u, with
// adaptive increments. A step that fails (no convergence, an evaluation
// error, a state that left its branch) is cut back and redone from the last
// converged state; it is never accepted. A step that still fails after
// `cutbacksBeforeJump` cut-backs is taken through by the jump method:
// - relaxation (default): pseudo-transient relaxation from the last state to
//   the step's u lands on the stable state a damped motion reaches; if that
//   state left the branch (jump-in, pull-off), continuation from the last
//   state locates the fold where the branch ends;
// - continuation: arc-length continuation from the last state locates the
//   fold, follows the unstable branch and lands on the far stable branch at
//   the step's u.
#include <Teuchos_ParameterList.hpp>

#include <functional>
#include <vector>

#include "cgcm/solver/Continuation.hpp"
#include "cgcm/solver/NewtonSolver.hpp"

namespace cgcm::solver {

struct LoadPathSettings {
  std::vector<Real> path{0.0, 1.0};   ///< waypoints of u; the run starts at path[0]
  Real initialIncrement = 0.005;
  Real minIncrement = 1e-7;
  Real maxIncrement = 0.01;
  int easyIterations = 4;             ///< grow the increment after steps this easy
  Real growth = 1.5;
  Real cutback = 0.5;
  /// A step that still fails after this many cut-backs is taken through by the jump method.
  int cutbacksBeforeJump = 0;
  /// How a jump from a fold finds the far stable branch.
  enum class JumpMethod {
    Relaxation,   ///< pseudo-transient relaxation just past the fold
    Continuation  ///< arc-length along the unstable branch back to the fold's u
  };
  JumpMethod jumpMethod = JumpMethod::Relaxation;
  RelaxationSettings relaxation;

  /// Valid parameters of the displacement-control part of the "Loading" sublist.
  static Teuchos::RCP<const Teuchos::ParameterList> validParameters();
  /// Reads and checks a validated "Loading" sublist (increments consistent, path of >= 2 distinct points).
  static LoadPathSettings fromParameters(const Teuchos::ParameterList& p);
};

struct StepInfo {
  int step = 0;         ///< accepted states so far (0 = initial state)
  Real displacement = 0.0;  ///< the prescribed displacement u of the state
  NewtonResult newton;
  int cutbacks = 0;     ///< failed attempts before this step converged
  bool jump = false;    ///< reached by a jump from a fold to another stable branch
  bool fold = false;    ///< a fold of the load path (located by continuation), where a jump starts
};

/// Where the stepper stands after an accepted state: enough, with that state
/// and the one before it, to go on exactly as an uninterrupted run would
/// (a checkpoint, see run()).
struct StepperState {
  std::size_t segment = 1;  ///< the waypoint being approached (index into the path)
  Real displacement = 0.0;  ///< u of the accepted state
  Real increment = 0.0;     ///< the next step's increment
  int step = 0;             ///< accepted states so far
  bool havePrevious = false;  ///< the secant predictor has a state before this one
  Real previousDisplacement = 0.0;    ///< u of that state
};

class LoadStepper {
 public:
  using Observer = std::function<void(const StepInfo&, const Vector& u)>;
  /// Called after the observer with the stepper's state, the accepted state
  /// and the state before it (meaningful when state.havePrevious).
  using CheckpointSink = std::function<void(const StepperState&, const Vector& u, const Vector& previous)>;
  /// Tells whether a converged step stayed on the branch it started from
  /// (true) or jumped to another one (false). Default: always continuous.
  using ContinuityCheck = std::function<bool(const Vector& before, const Vector& after)>;

  /// `continuation` (may be null: no jumps) carries the path through folds.
  LoadStepper(Teuchos::RCP<ModelEvaluator> model, NewtonSolver& newton, const LoadPathSettings& settings,
              Continuation* continuation = nullptr)
      : model_(std::move(model)), newton_(newton), settings_(settings), continuation_(continuation) {}

  /// Runs the whole path from u (initial guess at path[0]); calls `observer`
  /// after every accepted state. Throws NumericalError, naming the step, u and
  /// the reason, if a step fails below the minimum increment or the jump
  /// fails (everything observed so far stays valid).
  void run(Vector& u, const Observer& observer) { run(u, observer, {}, nullptr, nullptr); }
  /// The same, calling `checkpoint` after every accepted state of the path
  /// (not the folds reported on the way of a jump); with `resume`, u is the
  /// accepted state of `resume` (and `previous` the one before it) and the
  /// path goes on from there without solving the initial state again.
  void run(Vector& u, const Observer& observer, const CheckpointSink& checkpoint, const StepperState* resume,
           const Vector* previous);

  void setContinuityCheck(ContinuityCheck check) { continuous_ = std::move(check); }

  /// Continuation runs (jumps) so far and their cost.
  const std::vector<ContinuationResult>& jumps() const { return jumps_; }

 private:
  /// From the converged state u at p towards pNew: continuation until u
  /// reaches pNew again moving the same way. Fills trial and info, reports
  /// folds to the observer. False if the continuation failed.
  /// `landing`: the jump's end, found by relaxation; the continuation then
  /// only locates the fold.
  bool continueThrough(Real p, Real pNew, Vector& u, Vector& trial, StepInfo& info, int& step,
                       const Observer& observer, const Vector* landing = nullptr);
  /// The relaxation jump (Jump Method "relaxation") from the converged state
  /// u at p to pNew; falls back to continueThrough for jumps that leave the
  /// branch. Fills trial and info.
  bool relaxThrough(Real p, Real pNew, Vector& u, Vector& trial, StepInfo& info, int& step, const Observer& observer);
  /// The jump from a located fold towards pNew by relaxation at u just past
  /// the fold (further out if that fails, at most pNew). Fills trial and info.
  bool relaxFromFold(const PathPoint& fold, Real direction, Real pNew, Vector& trial, StepInfo& info);

  ContinuityCheck continuous_;
  Teuchos::RCP<ModelEvaluator> model_;
  NewtonSolver& newton_;
  LoadPathSettings settings_;
  Continuation* continuation_;
  std::vector<ContinuationResult> jumps_;
};

}  // namespace cgcm::solver
