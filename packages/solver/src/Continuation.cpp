#include "cgcm/solver/Continuation.hpp"

#include <LOCA.H>
#include <LOCA_MultiContinuation_AbstractStrategy.H>
#include <LOCA_MultiContinuation_ExtendedMultiVector.H>
#include <LOCA_MultiContinuation_ExtendedVector.H>
#include <LOCA_Parameter_SublistParser.H>
#include <LOCA_Thyra.H>
#include <LOCA_TurningPoint_MooreSpence_ExtendedGroup.H>
#include <LOCA_TurningPoint_MooreSpence_ExtendedVector.H>
#include <NOX_Solver_Factory.H>
#include <NOX_Thyra.H>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <Teuchos_oblackholestream.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <sstream>

#include "cgcm/core/Error.hpp"
#include "cgcm/solver/Convergence.hpp"

namespace cgcm::solver {

namespace {

using Extract = Thyra::TpetraOperatorVectorExtraction<Real, LocalIndex, GlobalIndex, assembly::Node>;
using Iterator = LOCA::Abstract::Iterator;

Teuchos::RCP<Vector> tpetraCopy(const NOX::Abstract::Vector& x) {
  const auto& tx = dynamic_cast<const NOX::Thyra::Vector&>(x);
  return Teuchos::rcp(new Vector(*Extract::getConstTpetraVector(tx.getThyraRCPVector()), Teuchos::Copy));
}

NOX::Thyra::Vector thyraCopy(const Vector& x) {
  auto copy = Teuchos::rcp(new Vector(x, Teuchos::Copy));
  return NOX::Thyra::Vector(
      Thyra::createVector(Teuchos::rcp_implicit_cast<Tpetra::Vector<Real, LocalIndex, GlobalIndex, assembly::Node>>(copy)));
}

// The names cgcm sets for every run.
const char* const kOwnedStepperKeys[] = {"Continuation Parameter", "Initial Value", "Max Value", "Min Value"};
// Names LOCA reads only late in a run (at its last step), so a dry start does not mark them.
const char* const kLateStepperKeys[] = {"Hit Continuation Bound", "Relative Stopping Threshold",
                                        "Compute Eigenvalues On Target Step"};

}  // namespace

struct Continuation::RunState {
  const ContinuationSegment* segment = nullptr;
  const Observer* observer = nullptr;
  ContinuationResult* result = nullptr;
  bool stable = true;         ///< stability of the last converged point
  bool restart = false;       ///< the graph must be rebuilt
  bool widen = false;         ///< ... wider than the search radius (an evaluation met missing entries)
  Real lastDpds = 0.0;        ///< dp/ds at the last converged point
  Real lastStepSize = 0.0;    ///< arclength of the last step (signed)
  bool atFold = false;        ///< a fold was located and the segment stops there
  bool stopWhen = false;      ///< ContinuationSegment::stopWhen held at the last point reported
  bool haveLast = false;
  Spectrum lastSpectrum = notYet();  ///< at the last converged point (a monitored spectrum; negative = -1: none yet)
  static Spectrum notYet() {
    Spectrum s;
    s.negative = -1;
    return s;
  }
};

// LOCA's stepper with cgcm's bookkeeping: every converged point goes to the
// observer with its tangent, stability and folds; graph coverage is checked.
class PathStepper : public LOCA::Stepper {
 public:
  PathStepper(const Teuchos::RCP<LOCA::GlobalData>& data,
              const Teuchos::RCP<LOCA::MultiContinuation::AbstractGroup>& group,
              const Teuchos::RCP<NOX::StatusTest::Generic>& tests, const Teuchos::RCP<Teuchos::ParameterList>& params,
              Continuation& owner, Continuation::RunState& state)
      : LOCA::Stepper(data, group, tests, params), owner_(owner), state_(state) {}

  /// Only the initial solve and the first tangent (to see which parameters LOCA reads).
  Iterator::IteratorStatus dryStart() { return start(); }

 protected:
  Iterator::IteratorStatus start() override {
    const auto status = LOCA::Stepper::start();
    if (status != Iterator::Failed) {
      state_.lastDpds = curPredictorPtr->getScalar(0);
      tangent_ = Teuchos::rcp_dynamic_cast<LOCA::MultiContinuation::ExtendedVector>(curPredictorPtr->clone());
    }
    return status;
  }

  Iterator::StepStatus preprocess(Iterator::StepStatus stepStatus) override {
    // LOCA 13.2 keeps the tangent of a point its tangent-factor test rejected
    // as the predictor of the retry; the retry must start along the tangent
    // of the last converged point.
    if (stepStatus == Iterator::Unsuccessful && !tangent_.is_null()) *curPredictorPtr = *tangent_;
    return LOCA::Stepper::preprocess(stepStatus);
  }

  Iterator::StepStatus postprocess(Iterator::StepStatus stepStatus) override {
    if (stepStatus == Iterator::Unsuccessful) {
      ++state_.result->failedSteps;
      return LOCA::Stepper::postprocess(stepStatus);
    }
    const int iterations = solverPtr->getNumIterations();
    const Real residual = residualNorm(solverPtr->getSolutionGroup(), owner_.model_->residualWeights());
    // (a fold curve's extended state holds the null vector, whose corrections the guards would misread)
    const bool guard = !atCorner() && state_.segment->foldParameter < 0;
    if (guard && correctorWentFar()) {
      ++state_.result->failedSteps;
      return LOCA::Stepper::postprocess(Iterator::Unsuccessful);
    }
    const auto status = LOCA::Stepper::postprocess(stepStatus);
    if (status == Iterator::Unsuccessful) return status;
    if (guard && turnCosine() < kMinTurnCosine) {
      ++state_.result->failedSteps;  // the retry starts from the last point's tangent (preprocess)
      return Iterator::Unsuccessful;
    }
    state_.result->newtonIterations += iterations;
    ++state_.result->steps;
    const Real dA = prevPredictorPtr->getScalar(0), dB = curPredictorPtr->getScalar(0);
    PathPoint pt = point(*curGroupPtr);
    pt.dpds = dB;
    pt.iterations = iterations;
    pt.residual = residual;
    const bool locate = !state_.segment->landOnly || state_.result->folds.empty();
    const bool foldBetween = dA * dB < 0.0;
    if (foldBetween && (!locate || !locateFold(dA, dB))) {
      // The fold was not located (or could not be) between A and B: B stands for it.
      pt.fold = true;
      state_.result->folds.push_back(pt);
      state_.stable = !state_.stable;
    }
    pt.stable = pt.stableByFolds = pt.fold || state_.stable;
    if (monitored()) {
      const Spectrum sB = assess(pt);
      // an eigenvalue crossed 0 where the path did not turn: a branch point between A and B
      const Spectrum& sA = state_.lastSpectrum;
      if (!foldBetween && sA.negative >= 0 && sB.negative != sA.negative) locateBranchPoint(sA, sB, pt);
      state_.lastSpectrum = sB;
    }
    if (state_.segment->stopAtFold && !state_.result->folds.empty()) {
      if (pt.fold) report(pt);  // B stands for a fold that was not located
      state_.atFold = true;
      return status;
    }
    if (state_.stopWhen) return status;  // a located fold or branch point before B ended the segment
    report(pt);
    state_.lastDpds = dB;
    state_.lastStepSize = stepSize;
    *tangent_ = *curPredictorPtr;
    // Restart on a wider graph before the couplings of the path outgrow it.
    if (!owner_.model_->graphCovers(*pt.x)) state_.restart = true;
    return status;
  }

  Iterator::IteratorStatus stop(Iterator::StepStatus stepStatus) override {
    if (owner_.model_->graphOutdated()) {
      state_.restart = state_.widen = true;
      owner_.model_->clearGraphOutdated();
    }
    if (state_.restart) return Iterator::Failed;
    if (state_.atFold || state_.stopWhen) return Iterator::Finished;
    // The target: reached when the parameter gets to it moving away from the
    // start (after any folds). LOCA's own bound logic assumes a monotonic
    // parameter and declares the bound reached next to a fold that lies just
    // short of it, so the target is not one of LOCA's bounds; LOCA's final
    // natural step then lands on it from the point just beyond.
    const auto& seg = *state_.segment;
    if (stepStatus == Iterator::Successful) {
      const Real value = curGroupPtr->getContinuationParameter();
      const Real previous = prevGroupPtr->getContinuationParameter();
      if (seg.direction * (value - seg.target) >= 0.0 && seg.direction * (value - previous) > 0.0) {
        targetValue = seg.target;
        return Iterator::Finished;
      }
    }
    return LOCA::Stepper::stop(stepStatus);
  }

  Iterator::IteratorStatus finish(Iterator::IteratorStatus status) override {
    if (state_.atFold || state_.stopWhen) return Iterator::Finished;  // no step to a bound: the fold is the end
    const auto result = LOCA::Stepper::finish(status);
    if (result == Iterator::Finished && isTargetStep) {
      // The natural step that lands on the bound: same branch as the last point.
      PathPoint pt = point(*curGroupPtr);
      pt.dpds = state_.lastDpds;
      pt.stable = pt.stableByFolds = state_.stable;
      if (monitored()) assess(pt);
      pt.iterations = solverPtr->getNumIterations();
      pt.residual = residualNorm(solverPtr->getSolutionGroup(), owner_.model_->residualWeights());
      state_.result->newtonIterations += pt.iterations;
      report(pt);
    }
    return result;
  }

 private:
  // True if the corrector moved some dof farther from the predicted point
  // than half the largest change the predictor made: it left the part of the
  // path the step was aimed at (e.g. the apex snapped onto the other surface
  // or off it, skipping a loop), and the step is redone shorter. The largest
  // dof change, not LOCA's RMS arclength: a snap moves only the nodes near the
  // contact, which an RMS over the whole mesh hides.
  bool correctorWentFar() const {
    auto predicted = prevGroupPtr->getX().clone(NOX::DeepCopy);
    predicted->update(stepSize, *curPredictorPtr, 1.0);
    auto d = curGroupPtr->getX().clone(NOX::DeepCopy);
    d->update(-1.0, *predicted, 1.0);
    using LOCA::MultiContinuation::ExtendedVector;
    const Real correction = dynamic_cast<const ExtendedVector&>(*d).getXVec()->norm(NOX::Abstract::Vector::MaxNorm);
    const Real change = std::abs(stepSize) *
                        dynamic_cast<const ExtendedVector&>(*curPredictorPtr).getXVec()->norm(NOX::Abstract::Vector::MaxNorm);
    return correction > kMaxCorrection * change;
  }
  static constexpr Real kMaxCorrection = 0.5;

  // Cosine of the angle between the tangents at the new and the last point.
  // A step whose tangent turns by more than 37 degrees is redone shorter: at
  // the sharp turns of adhesive contact (the snap of the apex onto the other
  // surface) a long step can land on another part of the path, even behind
  // the last point.
  Real turnCosine() const {
    const Real ab = curGroupPtr->computeScaledDotProduct(*curPredictorPtr, *prevPredictorPtr);
    const Real aa = curGroupPtr->computeScaledDotProduct(*curPredictorPtr, *curPredictorPtr);
    const Real bb = curGroupPtr->computeScaledDotProduct(*prevPredictorPtr, *prevPredictorPtr);
    return ab / std::sqrt(aa * bb);
  }
  static constexpr Real kMinTurnCosine = 0.8;

  // The two tests above hold back long steps only. The residual is C1 but
  // not C2 (a closest point entering a vertex region), so the path has
  // points where it turns by a finite angle; steps this short pass them.
  bool atCorner() {
    return std::abs(stepSize) <= kCornerSteps * getStepSizeParams().get<double>("Min Step Size");
  }
  static constexpr Real kCornerSteps = 16.0;

  PathPoint point(const LOCA::MultiContinuation::AbstractStrategy& group) const {
    const LOCA::MultiContinuation::AbstractGroup* g = group.getUnderlyingGroup().get();
    PathPoint pt;
    // a fold curve's group: (x, null vector, the fold's parameter) over the model's group
    if (const auto* fold = dynamic_cast<const LOCA::TurningPoint::MooreSpence::ExtendedGroup*>(g)) {
      pt.critical = tpetraCopy(*dynamic_cast<const LOCA::TurningPoint::MooreSpence::ExtendedVector&>(fold->getX()).getNullVec());
      g = fold->getUnderlyingGroup().get();
    }
    pt.x = tpetraCopy(g->getX());
    const auto& pv = g->getParams();
    for (int k = 0; k < pv.length(); ++k) pt.p.push_back(pv[k]);
    return pt;
  }

  void report(const PathPoint& pt) {
    state_.result->last = pt;
    state_.haveLast = true;
    (*state_.observer)(pt);
    if (state_.segment->stopWhen && state_.segment->stopWhen(pt)) state_.stopWhen = true;
  }

  // A fold lies between the previous point A (dp/ds = dA) and the current
  // one B (dB): find the arclength t h from A (h the step A -> B) where dp/ds
  // vanishes, each trial an arc-length corrector solve from A along A's
  // tangent. Reports the fold and flips the stability; false if no trial converged.
  bool locateFold(Real dA, Real dB) {
    auto trial = Teuchos::rcp_dynamic_cast<LOCA::MultiContinuation::AbstractStrategy>(prevGroupPtr->clone());
    Real bestAbs = std::abs(dA) < std::abs(dB) ? std::abs(dA) : std::abs(dB);
    PathPoint best;
    bool haveBest = false;
    auto g = [&](Real t) -> Real {
      const auto [iterations, residual] = correctorAt(*trial, t, "fold location");
      trial->postProcessContinuationStep(Iterator::Successful);  // the tangent of this point, oriented by the secant
      trial->computePredictor();
      const Real d =
          dynamic_cast<const LOCA::MultiContinuation::ExtendedVector&>(trial->getPredictorTangent()[0]).getScalar(0);
      if (std::abs(d) < bestAbs || !haveBest) {
        bestAbs = std::abs(d);
        best = point(*trial);
        best.dpds = d;
        best.iterations = iterations;
        best.residual = residual;
        haveBest = true;
      }
      return d;
    };
    try {
      std::uintmax_t maxIterations = 30;
      boost::math::tools::toms748_solve(
          g, 0.0, 1.0, dA, dB, [](Real a, Real b) { return std::abs(b - a) <= 1e-9; }, maxIterations);
    } catch (const std::exception&) {
      // A trial did not converge: the best point found so far, if any, stands for the fold.
    }
    if (!haveBest) return false;
    best.fold = true;
    best.stable = best.stableByFolds = true;  // marginal: the end of a stable branch or the start of one
    if (monitored()) assess(best);
    state_.result->folds.push_back(best);
    report(best);
    state_.stable = !state_.stable;
    return true;
  }

  // The arc-length corrector from A (the last converged point) at t h along A's tangent, into `trial`
  // (h: the step A -> B). Returns its Newton iterations and residual; throws NumericalError naming `what`.
  std::pair<int, Real> correctorAt(LOCA::MultiContinuation::AbstractStrategy& trial, Real t, const char* what) {
    const Real h = stepSize;
    trial.copy(*prevGroupPtr);
    trial.setStepSize(t * h);
    trial.setPrevX(prevGroupPtr->getX());
    trial.computeX(*prevGroupPtr, *prevPredictorPtr, t * h);
    auto solver = NOX::Solver::buildSolver(Teuchos::rcpFromRef(trial), noxStatusTestPtr, parsedParams->getSublist("NOX"));
    if (solver->solve() != NOX::StatusTest::Converged)
      throw NumericalError(std::string(what) + ": the corrector did not converge at t = " + std::to_string(t));
    state_.result->newtonIterations += solver->getNumIterations();
    trial.copy(solver->getSolutionGroup());
    return {solver->getNumIterations(), residualNorm(solver->getSolutionGroup(), owner_.model_->residualWeights())};
  }

  // The tangent's spectrum at pt: its eigenvalues, and its stability from them (a located fold or branch point
  // stays marginal). Collective.
  Spectrum assess(PathPoint& pt) {
    Spectrum s = owner_.spectrum_->compute(*pt.x, pt.p);
    pt.eigenvalues = s.eigenvalues;
    pt.negativeEigenvalues = pt.fold || pt.branchPoint ? marginalCount(s) : s.negative;
    pt.critical = s.mode();
    if (!pt.fold && !pt.branchPoint) pt.stable = s.stable();
    return s;
  }

  // The spectrum is assessed at every point, except in a jump (only its end matters).
  bool monitored() const { return owner_.spectrum_ && !state_.segment->landOnly && state_.segment->foldParameter < 0; }

  // At a located fold or branch point one eigenvalue is 0 to solver tolerance and its sign is round-off: it is
  // not counted as negative.
  static int marginalCount(const Spectrum& s) {
    std::size_t k = 0;
    for (std::size_t i = 1; i < s.eigenvalues.size(); ++i)
      if (std::abs(s.eigenvalues[i]) < std::abs(s.eigenvalues[k])) k = i;
    return s.negative - (!s.eigenvalues.empty() && s.eigenvalues[k] < 0.0 ? 1 : 0);
  }

  // The mode of the eigenvalue nearest 0.
  static const Teuchos::RCP<Vector>& nearestZeroMode(const Spectrum& s) {
    std::size_t k = 0;
    for (std::size_t i = 1; i < s.eigenvalues.size(); ++i)
      if (std::abs(s.eigenvalues[i]) < std::abs(s.eigenvalues[k])) k = i;
    return s.modes[k];
  }

  // The number of negative eigenvalues changed from A (sA) to B (sB) without a fold: eigenvalue number
  // j = min(negative) crossed 0. Its root along the step, each trial an arc-length corrector solve from A and
  // a spectrum; the branch point found is reported (before B) with the mode of that eigenvalue; if it
  // cannot be located (the crossing eigenvalue not among those computed, or a trial did not converge), B
  // stands for it. Then, if asked, a point of the other branch.
  void locateBranchPoint(const Spectrum& sA, const Spectrum& sB, PathPoint& b) {
    const int j = std::min(sA.negative, sB.negative);
    const Real gA = sA.ordered(j), gB = sB.ordered(j);
    PathPoint best;
    Teuchos::RCP<LOCA::MultiContinuation::AbstractStrategy> at;
    if (std::isfinite(gA) && std::isfinite(gB) && gA * gB < 0.0) {
      auto trial = Teuchos::rcp_dynamic_cast<LOCA::MultiContinuation::AbstractStrategy>(prevGroupPtr->clone());
      Real bestAbs = std::numeric_limits<Real>::infinity();
      auto g = [&](Real t) -> Real {
        const auto [iterations, residual] = correctorAt(*trial, t, "branch point location");
        trial->postProcessContinuationStep(Iterator::Successful);  // the tangent of this point (its dp/ds)
        trial->computePredictor();
        PathPoint q = point(*trial);
        q.iterations = iterations;
        q.residual = residual;
        q.branchPoint = true;
        const Spectrum s = owner_.spectrum_->compute(*q.x, q.p);
        const Real value = s.ordered(j);
        if (!std::isfinite(value)) throw NumericalError("branch point location: the crossing eigenvalue was lost");
        if (std::abs(value) < bestAbs) {
          bestAbs = std::abs(value);
          q.eigenvalues = s.eigenvalues;
          q.negativeEigenvalues = marginalCount(s);
          q.critical = nearestZeroMode(s);
          q.dpds = dynamic_cast<const LOCA::MultiContinuation::ExtendedVector&>(trial->getPredictorTangent()[0])
                       .getScalar(0);
          best = q;
          at = Teuchos::rcp_dynamic_cast<LOCA::MultiContinuation::AbstractStrategy>(trial->clone());
        }
        return value;
      };
      try {
        std::uintmax_t maxIterations = 40;
        boost::math::tools::toms748_solve(
            g, 0.0, 1.0, gA, gB, [](Real a, Real c) { return std::abs(c - a) <= 1e-11; }, maxIterations);
      } catch (const std::exception&) {
        // a trial did not converge: the best point so far, if any, stands for the branch point
      }
    }
    if (at.is_null()) {
      b.branchPoint = true;  // B stands for it
      b.stable = true;
      state_.result->branchPoints.push_back(b);
      return;
    }
    best.stable = j == 0;  // marginal: the end of a stable branch or the start of one
    best.stableByFolds = state_.stable;
    state_.result->branchPoints.push_back(best);
    report(best);
    if (state_.segment->switchAmplitude != 0.0) switchBranch(*at, *best.critical, state_.segment->switchAmplitude);
  }

  // A point of the other branch through the branch point `at`: the corrector along (mode, 0) from
  // at + amplitude * mode, with the arc-length constraint mode . (x - x_at) = amplitude mode . mode.
  void switchBranch(const LOCA::MultiContinuation::AbstractStrategy& at, const Vector& mode, Real amplitude) {
    try {
      auto other = Teuchos::rcp_dynamic_cast<LOCA::MultiContinuation::AbstractStrategy>(at.clone());
      auto direction = Teuchos::rcp_dynamic_cast<LOCA::MultiContinuation::ExtendedVector>(
          at.getPredictorTangent()[0].clone(NOX::ShapeCopy), true);
      *direction->getXVec() = thyraCopy(mode);
      direction->getScalar(0) = 0.0;
      other->setPredictorTangentDirection(*direction, 0);
      other->scaleTangent();  // LOCA rescales the tangent to its arc-length norm: T = rho * direction
      const auto& tangent = other->getPredictorTangent()[0];
      const Real rho = tangent.innerProduct(*direction) / direction->innerProduct(*direction);
      // the constraint (scaled T) . (x - x_at) = step (scaled T) . T puts the mode's component at step * rho
      other->setPrevX(at.getX());
      other->setStepSize(amplitude / rho);
      other->computeX(at, tangent, amplitude / rho);
      auto solver = NOX::Solver::buildSolver(other, noxStatusTestPtr, parsedParams->getSublist("NOX"));
      if (solver->solve() != NOX::StatusTest::Converged)
        throw NumericalError("the corrector did not converge (try another Switch Amplitude)");
      state_.result->newtonIterations += solver->getNumIterations();
      const auto& solved = dynamic_cast<const LOCA::MultiContinuation::AbstractStrategy&>(solver->getSolutionGroup());
      PathPoint q = point(solved);
      q.iterations = solver->getNumIterations();
      q.residual = residualNorm(solved, owner_.model_->residualWeights());
      assess(q);
      q.stableByFolds = q.stable;
      state_.result->otherBranches.push_back(q);
    } catch (const std::exception& e) {
      state_.result->switchFailures.push_back("branch switching at " + owner_.model_->parameterNames()[state_.segment->parameter] +
                                              " = " + std::to_string(at.getContinuationParameter()) + ": " + e.what() +
                                              "; the other branch is not followed");
    }
  }

  Continuation& owner_;
  Continuation::RunState& state_;
  Teuchos::RCP<LOCA::MultiContinuation::ExtendedVector> tangent_;  ///< at the last converged point
};

namespace {

// `to` gets the entries of `from` (sublists merged) marked as not read (a new ParameterEntry starts
// unused): validate() tells the names LOCA reads by their use flags, which an earlier reader of the
// deck (its echo to parameters.xml) may have set.
void setUnread(Teuchos::ParameterList& to, const Teuchos::ParameterList& from) {
  for (auto it = from.begin(); it != from.end(); ++it) {
    const std::string& name = from.name(it);
    const Teuchos::ParameterEntry& e = from.entry(it);
    if (e.isList())
      setUnread(to.sublist(name), Teuchos::any_cast<Teuchos::ParameterList>(e.getAny(false)));
    else
      to.setEntry(name, Teuchos::ParameterEntry(e.getAny(false), e.isDefault(), false, e.docString(), e.validator()));
  }
}

}  // namespace

namespace {

// The deck's LOCA/Bifurcation list: what LOCA's Moore-Spence turning-point group reads (names and values),
// checked before the run (LOCA reads them only when a fold is followed, late in a run).
void checkBifurcation(const Teuchos::ParameterList& b) {
  const std::vector<std::string> owned = {"Bifurcation Parameter", "Length Normalization Vector", "Initial Null Vector"};
  const std::vector<std::string> known = {"Type", "Formulation", "Solver Method", "Perturb Initial Solution",
                                          "Relative Perturbation Size", "Null Vector Scaling",
                                          "Update Null Vectors Every Continuation Step",
                                          "Multiply Null Vectors by Mass Matrix"};
  auto listed = [](const std::vector<std::string>& names) {
    std::string out;
    for (const auto& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
  };
  for (auto it = b.begin(); it != b.end(); ++it) {
    const std::string& name = b.name(it);
    if (std::find(owned.begin(), owned.end(), name) != owned.end())
      throw InputError("LOCA/Bifurcation/" + name + ": set by cgcm (the fold's parameter u and its null vector); "
                       "remove it from the LOCA sublist");
    if (std::find(known.begin(), known.end(), name) == known.end())
      throw InputError("LOCA/Bifurcation/" + name + ": not a parameter of LOCA's turning-point continuation; "
                       "allowed: " + listed(known));
  }
  auto choice = [&](const std::string& name, const std::vector<std::string>& allowed, const std::string& why) {
    if (!b.isParameter(name)) return;
    if (!b.isType<std::string>(name) ||
        std::find(allowed.begin(), allowed.end(), b.get<std::string>(name)) == allowed.end())
      throw InputError("LOCA/Bifurcation/" + name + ": allowed values " + listed(allowed) + why);
  };
  choice("Type", {"None", "Turning Point"}, " (Turning Point: follow the approach's first fold in (u, the "
                                          "Continuation Parameter))");
  choice("Formulation", {"Moore-Spence"}, " (Minimally Augmented needs transposed solves, which cgcm's solvers "
                                          "do not offer)");
  choice("Solver Method", {"Phipps Bordering", "Salinger Bordering"}, "");
  choice("Null Vector Scaling", {"None", "Order 1", "Order N"}, "");
}

}  // namespace

Teuchos::RCP<Teuchos::ParameterList> Continuation::defaultLocaParameters() {
  auto p = Teuchos::rcp(new Teuchos::ParameterList("LOCA"));
  auto& stepper = p->sublist("Stepper");
  stepper.set("Continuation Method", "Arc Length");
  stepper.set("Max Steps", 2000);
  stepper.set("Compute Eigenvalues", false);
  stepper.set("Hit Continuation Bound", true);
  p->sublist("Predictor").set("Method", "Tangent");
  auto& step = p->sublist("Step Size");
  step.set("Method", "Adaptive");
  step.set("Aggressiveness", 0.5);
  step.set("Failed Step Reduction Factor", 0.5);
  return p;
}

Continuation::Continuation(Teuchos::RCP<ParameterizedModel> model, const NewtonSettings& newton,
                           const Teuchos::ParameterList& loca, bool print)
    : model_(std::move(model)), newton_(newton), print_(print) {
  for (const char* key : kOwnedStepperKeys)
    if (loca.isSublist("Stepper") && loca.sublist("Stepper").isParameter(key))
      throw InputError(std::string("LOCA/Stepper/") + key +
                       ": set by cgcm from the Loading sublist (Continuation Parameter, Approach Path, Parameter "
                       "Path, Parameter Bounds); remove it from the LOCA sublist");
  if (loca.isSublist("Stepper") && loca.sublist("Stepper").isParameter("Max Nonlinear Iterations"))
    throw InputError("LOCA/Stepper/Max Nonlinear Iterations: set by cgcm from Solver/Newton/Max Iterations");
  if (loca.isSublist("Bifurcation")) checkBifurcation(loca.sublist("Bifurcation"));
  loca_ = defaultLocaParameters();
  setUnread(*loca_, loca);
  loca_->sublist("Stepper").set("Max Nonlinear Iterations", newton_.maxIterations);
  lastParams_ = Teuchos::rcp(new Teuchos::ParameterList(*loca_));
}

Continuation::~Continuation() = default;

bool Continuation::followsFolds() const {
  return loca_->isSublist("Bifurcation") && loca_->sublist("Bifurcation").isType<std::string>("Type") &&
         loca_->sublist("Bifurcation").get<std::string>("Type") == "Turning Point";
}

namespace {

// The parameter list of one stepper: LOCA's and the corrector's (NOX).
Teuchos::RCP<Teuchos::ParameterList> runParameters(const Teuchos::ParameterList& loca, const NewtonSettings& newton,
                                                   const std::string& name,
                                                   Real start, Real lower, Real upper, Real initialStep,
                                                   int maxSteps, bool print) {
  auto params = Teuchos::rcp(new Teuchos::ParameterList("cgcm continuation"));
  auto& l = params->sublist("LOCA");
  l.setParameters(loca);
  auto& stepper = l.sublist("Stepper");
  stepper.set("Continuation Parameter", name);
  stepper.set("Initial Value", start);
  stepper.set("Min Value", lower);
  stepper.set("Max Value", upper);
  stepper.set("Max Steps", maxSteps);
  l.sublist("Step Size").set("Initial Step Size", initialStep);
  auto& nox = params->sublist("NOX");
  nox.set("Nonlinear Solver", "Line Search Based");
  nox.sublist("Line Search").set("Method", "Full Step");
  nox.sublist("Direction").set("Method", "Newton");
  // LOCA's predictor and bordering solves reuse this tolerance: always the constant one.
  setLinearSolveControls(newton, false, nox.sublist("Direction").sublist("Newton"));
  // Evaluation errors (an inverted cell, touching surfaces) fail the step, which LOCA then cuts back.
  nox.set("Catch Throws During Solve", true);
  auto& printing = nox.sublist("Printing");
  printing.set("Output Information", print ? (NOX::Utils::StepperIteration | NOX::Utils::Warning) : 0);
  if (!print) {
    // NOX reports a caught evaluation error on its output stream whatever the print level.
    Teuchos::RCP<std::ostream> quiet = Teuchos::rcp(new Teuchos::oblackholestream);
    printing.set("Output Stream", quiet);
    printing.set("Error Stream", quiet);
  }
  return params;
}

}  // namespace

void Continuation::validate(const Vector& x) {
  const auto p = model_->parameters();
  auto params = runParameters(*loca_, newton_, model_->parameterNames()[0], p[0], p[0] - 1.0, p[0] + 1.0, 1e-3,
                              loca_->sublist("Stepper").get<int>("Max Steps"), false);
  params->sublist("NOX").sublist("Printing").set("Output Information", 0);
  params->sublist("LOCA").sublist("Bifurcation").set("Type", "None");  // its list is checked by the constructor
  auto data = LOCA::createGlobalData(params);
  LOCA::ParameterVector pv;
  for (std::size_t k = 0; k < p.size(); ++k) pv.addParameter(model_->parameterNames()[k], p[k]);
  auto group = Teuchos::rcp(new LOCA::Thyra::Group(data, thyraCopy(x), model_, pv, 0));
  ContinuationResult result;
  RunState state;
  ContinuationSegment segment;
  segment.target = p[0] + 1.0;
  state.segment = &segment;
  result.last.x = Teuchos::rcp(new Vector(x, Teuchos::Copy));
  Observer ignore = [](const PathPoint&) {};
  state.observer = &ignore;
  state.result = &result;
  std::string unread;
  {
    PathStepper stepper(data, group, convergenceTests(newton_.tolerance(), newton_.maxIterations, model_->residualWeights()), params, *this,
                        state);
    stepper.dryStart();
    const auto& used = params->sublist("LOCA");
    for (const char* sub : {"Stepper", "Predictor", "Step Size"}) {
      if (!loca_->isSublist(sub)) continue;
      for (auto it = loca_->sublist(sub).begin(); it != loca_->sublist(sub).end(); ++it) {
        const std::string& key = it->first;
        if (loca_->sublist(sub).isSublist(key)) continue;
        bool late = false;
        for (const char* k : kLateStepperKeys) late = late || key == k;
        if (late || used.sublist(sub).getEntry(key).isUsed()) continue;
        unread += (unread.empty() ? "" : ", ") + std::string("LOCA/") + sub + "/" + key;
      }
    }
  }
  LOCA::destroyGlobalData(data);
  if (!unread.empty())
    throw InputError(unread + ": not a parameter of LOCA's " +
                     "stepper, predictor or step size (LOCA did not read it); see the LOCA documentation for the "
                     "names (e.g. LOCA/Stepper/Max Steps, LOCA/Step Size/Max Step Size, LOCA/Predictor/Method)");
}

ContinuationResult Continuation::run(const Vector& x0, const ContinuationSegment& segment, const Observer& observer) {
  ContinuationResult result;
  RunState state;
  state.segment = &segment;
  state.observer = &observer;
  state.result = &result;
  state.stable = segment.stableStart;
  const std::string name = model_->parameterNames()[segment.parameter];
  // LOCA's bounds: the runaway bound, and as far beyond the target on the other side.
  const Real beyond = segment.target + segment.direction * std::abs(segment.target - segment.bound);
  const Real lower = segment.direction > 0 ? segment.bound : beyond;
  const Real upper = segment.direction > 0 ? beyond : segment.bound;
  int maxSteps = loca_->sublist("Stepper").get<int>("Max Steps");

  auto x = Teuchos::rcp(new Vector(x0, Teuchos::Copy));
  std::vector<Real> p = model_->parameters();
  Real initialStep = segment.direction * segment.initialStep;
  result.last.x = x;
  result.last.p = p;
  result.last.stable = segment.stableStart;
  if (spectrum_ && !segment.landOnly && segment.foldParameter < 0) state.lastSpectrum = spectrum_->compute(*x, p);
  Teuchos::RCP<const Vector> nullVector = segment.nullVector;
  if (segment.foldParameter >= 0 && nullVector.is_null())
    throw InputError("continuation along a fold: the fold's null vector is needed (ContinuationSegment::nullVector)");
  for (;;) {
    model_->clearGraphOutdated();
    if (!model_->graphCovers(*x)) model_->growGraph(*x, false);
    auto params = runParameters(*loca_, newton_, name, p[segment.parameter], lower, upper, initialStep, maxSteps, print_);
    // the path itself is continued (the deck's Bifurcation list is for the fold curve's runs)
    if (segment.foldParameter < 0) params->sublist("LOCA").sublist("Bifurcation").set("Type", "None");
    if (segment.foldParameter >= 0) {
      auto& bifurcation = params->sublist("LOCA").sublist("Bifurcation");
      bifurcation.set("Type", "Turning Point");
      bifurcation.get("Formulation", "Moore-Spence");
      bifurcation.get("Solver Method", "Phipps Bordering");
      bifurcation.set("Bifurcation Parameter", model_->parameterNames()[segment.foldParameter]);
      Teuchos::RCP<NOX::Abstract::Vector> normalization = Teuchos::rcp(new NOX::Thyra::Vector(thyraCopy(*nullVector)));
      bifurcation.set("Length Normalization Vector", normalization);
      bifurcation.set("Initial Null Vector", normalization->clone(NOX::DeepCopy));
    }
    lastParams_ = params;
    auto data = LOCA::createGlobalData(params);
    LOCA::ParameterVector pv;
    for (std::size_t k = 0; k < p.size(); ++k) pv.addParameter(model_->parameterNames()[k], p[k]);
    auto group = Teuchos::rcp(new LOCA::Thyra::Group(data, thyraCopy(*x), model_, pv, 0));
    Iterator::IteratorStatus status;
    const int stepsBefore = result.steps + result.failedSteps;
    {
      PathStepper stepper(data, group, convergenceTests(newton_.tolerance(), newton_.maxIterations, model_->residualWeights()), params, *this,
                          state);
      try {
        status = stepper.run();
      } catch (const std::exception& e) {
        status = Iterator::Failed;
        result.failure = e.what();
      } catch (const char* e) {  // some NOX and LOCA failures throw a bare string
        status = Iterator::Failed;
        result.failure = std::string("LOCA: ") + e;
      }
    }
    LOCA::destroyGlobalData(data);
    maxSteps -= result.steps + result.failedSteps - stepsBefore;
    if (state.restart && maxSteps > 0 && result.restarts < 100) {
      // Continue from the last converged point on a graph that covers it.
      state.restart = false;
      x = result.last.x;
      p = result.last.p;
      if (segment.foldParameter >= 0 && !result.last.critical.is_null()) nullVector = result.last.critical;
      model_->growGraph(*x, state.widen);
      state.widen = false;
      // LOCA's first step moves the parameter by the initial step (signed).
      const Real dp = state.lastStepSize * state.lastDpds;
      initialStep = std::abs(dp) > 1e-3 * segment.initialStep
                        ? dp : std::copysign(1e-3 * segment.initialStep, dp == 0.0 ? segment.direction : dp);
      ++result.restarts;
      continue;
    }
    const Real reachedValue = result.last.p[segment.parameter];
    const Real scale = std::abs(segment.target) + std::abs(segment.bound) + 1e-300;
    if (state.stopWhen) {
      result.stoppedWhen = true;
    } else if (state.atFold) {
      result.stoppedAtFold = true;
    } else if (status == Iterator::Finished && std::abs(reachedValue - segment.target) <= 1e-12 * scale) {
      result.reached = true;
    } else if (result.failure.empty()) {
      std::ostringstream msg;
      msg << "continuation in " << name << " stopped at " << name << " = " << reachedValue << " after "
          << result.steps << " steps";
      if (status == Iterator::Finished)
        msg << ": it reached the bound " << segment.bound << " before the target " << segment.target;
      else if (maxSteps <= 0)
        msg << ": LOCA/Stepper/Max Steps reached";
      else
        msg << ": the step size fell below LOCA/Step Size/Min Step Size (the corrector did not converge)";
      result.failure = msg.str();
    }
    break;
  }
  return result;
}

}  // namespace cgcm::solver
