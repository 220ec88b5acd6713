#pragma once
// Pseudo-arclength continuation with LOCA (a LOCA::Stepper on a
// LOCA::Thyra::Group over the ModelEvaluator) in one entry of p(0): the prescribed
// displacement u, or any other parameter the model exposes (e.g. gammaW).
//
// On top of LOCA's stepper:
// - folds: the parameter component dp/ds of LOCA's unit tangent changes
//   sign across a fold; the fold is then located to solver tolerance as the
//   root of dp/ds along the arc-length step (Boost.Math TOMS 748), each trial
//   being an arc-length corrector solve;
// - stability under control of the continuation parameter: the determinant
//   of the Jacobian has the sign of dp/ds times that of the (regular)
//   bordered matrix, so it changes sign exactly at folds; a path that starts
//   stable is unstable after an odd number of folds;
// - with a TangentSpectrum (monitorStability), stability from the tangent's
//   eigenvalues instead: the count of negative eigenvalues at every point; a
//   count that changes without a fold is a branch point (a simple eigenvalue
//   crossing 0 where the path does not turn, e.g. the pitchfork of a symmetric
//   state losing stability to an asymmetric mode), located to solver
//   tolerance as the root of that eigenvalue along the step (TOMS 748, as for
//   folds); switchBranch() then finds a point of the other branch;
// - the matrix graph: when the interaction couplings of a converged point are
//   no longer covered by the graph (or an evaluation met missing entries), the
//   stepper stops, the graph is rebuilt and a new stepper continues from the
//   last converged point in the same direction.
#include <Teuchos_ParameterList.hpp>

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "cgcm/solver/NewtonSolver.hpp"
#include "cgcm/solver/ParameterizedModel.hpp"
#include "cgcm/solver/TangentSpectrum.hpp"

namespace cgcm::solver {

/// A converged point of a path.
struct PathPoint {
  Teuchos::RCP<Vector> x;     ///< state
  std::vector<Real> p;        ///< all entries of p(0)
  Real dpds = 0.0;            ///< parameter component of the unit tangent (LOCA's scaled arclength)
  bool stable = true;         ///< under control of the continuation parameter (from the eigenvalues when monitored)
  bool stableByFolds = true;  ///< the same from the parity of the folds passed since the start
  bool fold = false;          ///< a located fold (dp/ds = 0 to solver tolerance)
  bool branchPoint = false;   ///< a located branch point (an eigenvalue 0 to solver tolerance, no fold)
  int iterations = 0;         ///< Newton iterations of its corrector
  Real residual = 0.0;        ///< |f|_2 at the point (force units)
  /// With a monitored spectrum: the tangent's eigenvalues nearest 0 and the count of negative ones (-1: not
  /// computed); at a branch point `critical` is the mode whose eigenvalue is 0, otherwise the smallest one's;
  /// on a fold curve (ContinuationSegment::foldParameter) the fold's null vector.
  std::vector<Real> eigenvalues;
  int negativeEigenvalues = -1;
  Teuchos::RCP<Vector> critical;
};

/// One continuation run: from a converged point, in one parameter, until the
/// parameter reaches `target` while moving away from the start in `direction`
/// (after any number of folds), or fails.
struct ContinuationSegment {
  int parameter = 0;        ///< index in p(0)
  Real target = 0.0;
  Real direction = 1.0;     ///< +1 or -1: the way the parameter moves first (towards target)
  Real bound = 0.0;         ///< the other side: the run stops as failed if the parameter gets beyond it
  Real initialStep = 1e-3;  ///< size of the first parameter increment (> 0)
  bool stableStart = true;  ///< stability of the start point
  /// Only the end matters (a jump under displacement control): the first fold
  /// is located, later ones only counted; a monitored spectrum is not computed.
  bool landOnly = false;
  /// Stop at the first fold, once located (the run is then not `reached`).
  bool stopAtFold = false;
  /// With a monitored spectrum, at each located branch point: a point of the
  /// other branch (ContinuationResult::otherBranches), the solution whose
  /// displacement from the branch point has the component `switchAmplitude`
  /// times the critical mode (largest entry 1) along that mode, found by
  /// LOCA's arc-length corrector from branch point + switchAmplitude * mode
  /// in that direction with the parameter free. Its sign picks one half of a
  /// pitchfork. 0: no switching.
  Real switchAmplitude = 0.0;
  /// If set: the run stops after the first point for which it is true (ContinuationResult::stoppedWhen).
  std::function<bool(const PathPoint&)> stopWhen;
  /// >= 0: the start is a fold in p[foldParameter], and the run follows the fold
  /// itself as `parameter` changes, p[foldParameter] solved for (LOCA's
  /// Moore-Spence turning-point continuation, LOCA/Bifurcation). Its points
  /// carry the null vector in PathPoint::critical; a "fold" of this run is
  /// an extreme of the fold curve in `parameter` (a cusp, where the fold ends).
  int foldParameter = -1;
  /// The fold's null vector (initial guess and length normalisation), e.g. the critical mode at the fold.
  Teuchos::RCP<const Vector> nullVector;
};

struct ContinuationResult {
  bool reached = false;           ///< the parameter reached the target
  bool stoppedAtFold = false;     ///< stopped at the first fold (ContinuationSegment::stopAtFold)
  bool stoppedWhen = false;       ///< stopped by ContinuationSegment::stopWhen
  std::string failure;            ///< why not
  int steps = 0;                  ///< converged continuation steps (fold trials excluded)
  int failedSteps = 0;            ///< corrector failures (cut back by LOCA)
  int restarts = 0;               ///< stepper restarts after graph rebuilds
  int newtonIterations = 0;       ///< all corrector iterations, fold location included
  std::vector<PathPoint> folds;   ///< the folds located on the way
  std::vector<PathPoint> branchPoints;  ///< the branch points located on the way (with a monitored spectrum)
  /// ContinuationSegment::switchAmplitude: a point of the other branch at each branch point, in the same order
  /// (a failed switch: no point, and `switchFailures` says why).
  std::vector<PathPoint> otherBranches;
  std::vector<std::string> switchFailures;
  PathPoint last;                 ///< the last converged point
};

/// Continuation settings: the LOCA parameter list (sublists "Stepper",
/// "Predictor", "Step Size", "Bifurcation", ... as LOCA documents them) with
/// cgcm's defaults filled in. cgcm sets "Stepper/Continuation Parameter",
/// "Initial Value", "Max Value", "Min Value" and "Step Size/Initial Step Size"
/// for every run itself.
class Continuation {
 public:
  using Observer = std::function<void(const PathPoint&)>;

  /// `loca`: the deck's LOCA sublist (may be empty). Throws InputError for
  /// entries cgcm sets itself. `print`: LOCA's own step output.
  Continuation(Teuchos::RCP<ParameterizedModel> model, const NewtonSettings& newton, const Teuchos::ParameterList& loca,
               bool print = false);
  ~Continuation();

  /// cgcm's default LOCA list (documented in the user guide).
  static Teuchos::RCP<Teuchos::ParameterList> defaultLocaParameters();

  /// Builds (without solving) a stepper on the model at x with the complete
  /// parameter list, then reports every entry of the user's Stepper,
  /// Predictor and Step Size sublists that LOCA did not read: a misspelt or
  /// unknown name. Throws InputError naming them. Collective.
  void validate(const Vector& x);

  /// Decides stability by the tangent's eigenvalues (`spectrum`, on the same
  /// model) at every converged point, and locates branch points; null: by
  /// the parity of the folds (the default).
  void monitorStability(std::shared_ptr<TangentSpectrum> spectrum) { spectrum_ = std::move(spectrum); }

  /// Runs one segment from the converged point (x0, the model's current
  /// parameters). `observer` sees every new converged point in path order,
  /// located folds included (the start point is not repeated). Collective.
  ContinuationResult run(const Vector& x0, const ContinuationSegment& segment, const Observer& observer);

  /// The deck's LOCA/Bifurcation/Type is "Turning Point": a parameter continuation follows a fold of the
  /// path in two parameters (PathPlan) instead of the path at fixed u.
  bool followsFolds() const;

  /// The full parameter list of the last run (LOCA's defaults filled in).
  const Teuchos::ParameterList& lastParameters() const { return *lastParams_; }

 private:
  friend class PathStepper;
  struct RunState;

  Teuchos::RCP<ParameterizedModel> model_;
  NewtonSettings newton_;
  Teuchos::RCP<Teuchos::ParameterList> loca_;  ///< the user's list over cgcm's defaults
  Teuchos::RCP<Teuchos::ParameterList> lastParams_;
  bool print_;
  std::shared_ptr<TangentSpectrum> spectrum_;
};

}  // namespace cgcm::solver
