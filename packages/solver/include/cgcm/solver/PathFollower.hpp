#pragma once
// Path control as a strategy: the deck's Loading sublist names how the load
// path is followed (Loading/Control: a registry of path followers, each one
// class), along the Approach Path in u, and then, optionally, by arc-length
// continuation in another parameter of the model (Continuation Parameter:
// gammaW, gammaL). The caller sees accepted states through one observer,
// whichever control reached them.
#include <Teuchos_ParameterList.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cgcm/solver/Continuation.hpp"
#include "cgcm/solver/LoadStepper.hpp"
#include "cgcm/solver/ModelEvaluator.hpp"
#include "cgcm/solver/NewtonSolver.hpp"

namespace cgcm::solver {

/// An accepted state of the path.
struct PathState {
  const Vector* x = nullptr;  ///< the state
  std::vector<Real> p;        ///< every entry of p(0) at the state (p[0] = u)
  int step = 0;               ///< its row: accepted states before it along the whole path
  int iterations = 0;         ///< Newton iterations of its solve (or corrector)
  Real residual = 0.0;        ///< |f|_2 of the accepted state (force units)
  int cutbacks = 0;           ///< failed attempts before it (displacement control)
  bool stable = true;         ///< under control of the continuation parameter (from the eigenvalues when computed)
  bool stableByFolds = true;  ///< the same from the parity of the folds passed (arc-length), or true (displacement control)
  bool fold = false;          ///< a located fold (turning point of the path)
  bool branchPoint = false;   ///< a located branch point (an eigenvalue crossing 0 without a fold)
  bool jump = false;          ///< reached by a jump from a fold (displacement control)
  int branch = 0;             ///< 0: the path; k > 0: the branch from the k-th branch point (Loading/Branch Switching)
  bool onFoldCurve = false;   ///< a fold of the path followed in two parameters (LOCA/Bifurcation/Type = Turning Point)
  /// PathContext::spectrum: the tangent's eigenvalues nearest 0, the count of negative ones (-1: not
  /// computed) and the critical mode (TangentSpectrum).
  std::vector<Real> eigenvalues;
  int negativeEigenvalues = -1;
  Teuchos::RCP<const Vector> critical;
};

/// What a path costs besides Newton's solves.
struct PathCost {
  int continuationSteps = 0;  ///< arc-length steps (arc-length control, jumps, parameter continuation)
  int graphRestarts = 0;      ///< continuation restarts after graph rebuilds
  std::vector<std::string> notes;  ///< what the path could not do and went on without (a branch switch that failed)
};

/// A branch point of the path and the first point of the other branch through it.
struct BranchSwitch {
  int parameter = 0;  ///< index in p(0) of the parameter continued in
  PathPoint branchPoint, other;
};

/// What followers share with the caller: the solvers, and hooks for a run that
/// is checkpointed (displacement control) or watches for a state that left its branch.
struct PathContext {
  Teuchos::RCP<ModelEvaluator> model;
  NewtonSolver* newton = nullptr;
  Continuation* continuation = nullptr;
  LoadStepper::ContinuityCheck continuity;  ///< may be empty
  LoadStepper::CheckpointSink checkpoint;   ///< may be empty
  const StepperState* resume = nullptr;     ///< a restart: where the interrupted run stood
  const Vector* resumePrevious = nullptr;   ///< and the state before it (resume->havePrevious)
  /// Stability from the tangent's eigenvalues at every accepted state, branch points located on
  /// arc-length paths (the continuation monitors the same spectrum); null: from the parity of folds.
  std::shared_ptr<TangentSpectrum> spectrum;
  /// Loading/Branch Switching: the switches made along the path (followed after it), and the branch followed now.
  std::vector<BranchSwitch> switches;
  int branch = 0;
};

class PathPlan;

/// One way of following the Approach Path in u.
class PathFollower {
 public:
  using Observer = std::function<void(const PathState&)>;
  /// What a control is, for the run's outputs and checks.
  struct Traits {
    const char* name;  ///< its Loading/Control value
    /// Its curve holds the unstable branches between folds (arc-length); the
    /// path of a rigid loading device is then derived from it. Otherwise the
    /// curve is that path already (stable branches joined by jumps).
    bool tracesUnstableBranches;
    bool restartable;       ///< a killed run can go on from its last accepted state (checkpoint.bin)
    bool usesContinuation;  ///< LOCA is used along the path in u (its parameters are checked before the run)
  };
  explicit PathFollower(const Traits& traits) : traits_(traits) {}
  virtual ~PathFollower() = default;
  std::string name() const { return traits_.name; }
  bool tracesUnstableBranches() const { return traits_.tracesUnstableBranches; }
  bool restartable() const { return traits_.restartable; }
  bool usesContinuation() const { return traits_.usesContinuation; }
  /// Follows the plan's Approach Path from u (the initial guess at its first
  /// value; a restart: the accepted state of context.resume), calling
  /// `observer` after every accepted state. Throws NumericalError, naming
  /// where and why, if the path cannot be followed (every state observed so far stays valid).
  virtual PathCost follow(Vector& u, const PathPlan& plan, PathContext& context, const Observer& observer) const = 0;

 private:
  Traits traits_;
};

/// A Loading/Control value: its follower.
struct PathControlEntry {
  const char* deckName;
  const char* description;  ///< for the deck's help
  std::unique_ptr<PathFollower> (*make)();
};
const std::vector<PathControlEntry>& pathControlRegistry();

/// The deck's Loading sublist, read and checked: the follower, the path in u,
/// the parameter continuation after it.
class PathPlan {
 public:
  /// The Loading sublist: every parameter with its default and help.
  static Teuchos::RCP<const Teuchos::ParameterList> validParameters();
  /// The help of the LOCA sublist, with the defaults cgcm gives LOCA.
  static const char* locaHelp();

  /// From a validated Loading sublist; `parameters`: the names the model can
  /// continue in besides u, `lengthScale`: the interaction's r0 (a jump relaxes
  /// in moves of at most a quarter of it; 0: no interaction). Throws InputError
  /// naming the parameter for a path that cannot be followed.
  PathPlan(const Teuchos::ParameterList& loading, const std::vector<std::string>& parameters, Real lengthScale);

  const PathFollower& follower() const { return *follower_; }
  const LoadPathSettings& path() const { return path_; }
  /// Loading/Branch Switching (it needs the tangent's eigenvalues and an arc-length path).
  bool branchSwitching() const { return branchSwitching_; }
  /// Loading/Continuation Parameter: "u", or the parameter continued in after the Approach Path.
  const std::string& parameter() const { return parameter_; }
  /// The run needs LOCA (its list is then checked before any work).
  bool usesContinuation() const { return follower_->usesContinuation() || parameter_ != "u"; }

  /// The deck's LOCA sublist over the step sizes of this plan, the one home of
  /// these defaults: Step Size/Min Step Size = Loading/Min Increment, and
  /// Max Step Size = Loading/Max Increment when the parameter is u.
  Teuchos::ParameterList locaParameters(const Teuchos::ParameterList& deckLoca) const;

  /// The whole path: the follower along the Approach Path, then continuation
  /// in the Continuation Parameter through its Parameter Path. Throws
  /// NumericalError if it stops.
  PathCost follow(Vector& u, PathContext& context, const PathFollower::Observer& observer) const;

  /// One continuation segment from the converged state u (the model's current
  /// parameters) to `target` of parameter `index`, or to the first point for which
  /// `stopWhen` holds; u ends on the last point. Throws NumericalError if it stops otherwise.
  PathCost continueTo(Vector& u, int index, Real target, const std::vector<Real>& waypoints, Real initialStep,
                      bool stableStart, PathContext& context, const PathFollower::Observer& observer,
                      int& step, const std::function<bool(const PathPoint&)>& stopWhen = {}) const;

 private:
  Real runawayBound(const std::vector<Real>& waypoints, Real direction, bool positive) const;
  /// LOCA/Bifurcation/Type = Turning Point: the first fold of the path in u followed in (u, parameter
  /// `index`) through the Parameter Path, to its end or to the cusp where the fold ends (the fold
  /// curve's extreme in the parameter, a located `fold` row). Throws NumericalError without a fold.
  void followFold(const std::optional<PathPoint>& fold, int index, PathContext& context,
                  const PathFollower::Observer& observer, int& step, PathCost& cost) const;
  /// Follows the branches of context.switches, each from its first point to the end of its path.
  void followOtherBranches(Vector& u, PathContext& context, const PathFollower::Observer& observer, int& step,
                           PathCost& cost) const;

  std::shared_ptr<const PathFollower> follower_;
  LoadPathSettings path_;
  std::string parameter_ = "u";
  std::vector<Real> parameterPath_;  ///< waypoints of the parameter (not u)
  std::vector<Real> bounds_;         ///< {lower, upper} or empty
  bool branchSwitching_ = false;
  Real switchAmplitude_ = 0.0;       ///< Loading/Switch Amplitude, 0 resolved
};

}  // namespace cgcm::solver
