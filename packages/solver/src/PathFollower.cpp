#include "cgcm/solver/PathFollower.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "cgcm/core/Error.hpp"
#include "cgcm/core/ParameterValidators.hpp"

namespace cgcm::solver {

namespace {

// An accepted state of the path from a converged continuation point, as row `step`.
PathState stateOf(const PathPoint& pt, int step) {
  PathState s;
  s.x = pt.x.get();
  s.p = pt.p;
  s.step = step;
  s.iterations = pt.iterations;
  s.residual = pt.residual;
  s.stable = pt.stable;
  s.stableByFolds = pt.stableByFolds;
  s.fold = pt.fold;
  s.branchPoint = pt.branchPoint;
  s.eigenvalues = pt.eigenvalues;
  s.negativeEigenvalues = pt.negativeEigenvalues;
  s.critical = pt.critical;
  return s;
}

// Steps in u; at a fold the state jumps to the far stable branch at the same
// u, as under a rigid loading device (LoadStepper).
class DisplacementControl final : public PathFollower {
 public:
  DisplacementControl() : PathFollower({"displacement", false, true, false}) {}

  PathCost follow(Vector& u, const PathPlan& plan, PathContext& c, const Observer& observer) const override {
    LoadStepper stepper(c.model, *c.newton, plan.path(), c.continuation);
    if (c.continuity) stepper.setContinuityCheck(c.continuity);
    stepper.run(u, [&](const StepInfo& info, const Vector& state) {
      PathState s;
      s.x = &state;
      s.p = c.model->parameters();
      s.p[0] = info.displacement;
      s.step = info.step;
      s.iterations = info.newton.iterations;
      s.residual = info.newton.residualNorms.empty() ? 0.0 : info.newton.residualNorms.back();
      s.cutbacks = info.cutbacks;
      s.fold = info.fold;
      s.jump = info.jump;
      observer(s);
    }, c.checkpoint, c.resume, c.resumePrevious);
    PathCost cost;
    for (const auto& j : stepper.jumps()) cost.continuationSteps += j.steps, cost.graphRestarts += j.restarts;
    return cost;
  }
};

// LOCA pseudo-arclength continuation in u through the folds, the unstable
// branches included.
class ArcLengthControl final : public PathFollower {
 public:
  ArcLengthControl() : PathFollower({"arc-length", true, false, true}) {}

  PathCost follow(Vector& u, const PathPlan& plan, PathContext& c, const Observer& observer) const override {
    const auto& waypoints = plan.path().path;
    c.model->dirichlet().impose(waypoints.front(), u);
    const auto first = c.newton->solve(u);
    if (!first.converged)
      throw NumericalError("no equilibrium at the start of the load path, u = " + std::to_string(waypoints.front()) +
                           ": " + first.failure);
    PathState start;
    start.x = &u;
    start.p = c.model->parameters();
    start.iterations = first.iterations;
    start.residual = first.residualNorms.back();
    observer(start);
    PathCost cost;
    int step = 0;
    bool stable = true;
    const auto track = [&](const PathState& s) {
      stable = s.stableByFolds;
      observer(s);
    };
    for (std::size_t k = 1; k < waypoints.size(); ++k) {
      const auto segment = plan.continueTo(u, 0, waypoints[k], waypoints, plan.path().initialIncrement, stable, c,
                                           track, step);
      cost.continuationSteps += segment.continuationSteps;
      cost.graphRestarts += segment.graphRestarts;
      cost.notes.insert(cost.notes.end(), segment.notes.begin(), segment.notes.end());
    }
    return cost;
  }
};

}  // namespace

const std::vector<PathControlEntry>& pathControlRegistry() {
  static const std::vector<PathControlEntry> registry = {
      {"displacement",
       "steps in u along the Approach Path; at a fold (jump-to-contact, jump-off-contact) the state jumps to the "
       "far stable branch at the same u (found by continuation), as under a rigid loading device",
       [] { return std::unique_ptr<PathFollower>(new DisplacementControl); }},
      {"arc-length",
       "LOCA pseudo-arclength continuation through the folds, the unstable branch included (rows with stable = 0)",
       [] { return std::unique_ptr<PathFollower>(new ArcLengthControl); }},
  };
  return registry;
}

Teuchos::RCP<const Teuchos::ParameterList> PathPlan::validParameters() {
  static const Teuchos::RCP<const Teuchos::ParameterList> valid = [] {
    auto loading = Teuchos::rcp(new Teuchos::ParameterList("Loading"));
    std::vector<std::string> names;
    std::string help;
    for (const auto& e : pathControlRegistry()) {
      names.push_back(e.deckName);
      help += std::string(help.empty() ? "" : " ") + "\"" + e.deckName + "\": " + e.description + ".";
    }
    help.pop_back();  // the last description's full stop
    loading->set("Control", names.front(), help, validators::choices(names));
    loading->setParameters(*LoadPathSettings::validParameters());
    loading->set("Continuation Parameter", "u",
                 "\"u\": the path is the Approach Path. \"gammaW\" or \"gammaL\": after the Approach Path (at the "
                 "deck's gammas), arc-length continuation in that parameter along the Parameter Path at the last u",
                 validators::choices({"u", "gammaW", "gammaL"}));
    loading->set("Parameter Path", Teuchos::Array<double>{},
                 "waypoints of the Continuation Parameter when it is not u, e.g. {100, 20}: from the deck's value "
                 "through these; empty for u");
    loading->set("Parameter Bounds", Teuchos::Array<double>{},
                 "{lower, upper}: the continuation stops as failed if its parameter leaves this range (arc-length "
                 "control and jumps; default: the path's range widened by twice its span on each side)");
    loading->set("Branch Switching", false,
                 "at every branch point located on an arc-length path (Output/Eigenvalues > 0), follow the other "
                 "branch too: after the path, from the solution at Switch Amplitude along the critical mode, with "
                 "the parameter moving the way the switch moved it, to the end of its path (the largest or "
                 "smallest waypoint); its rows have branch = 1, 2, ... in load_curve.csv");
    loading->set("Switch Amplitude", 0.0,
                 "the component along the critical mode (largest entry 1) of the first point of the other branch, "
                 "in length units; its sign picks one half of a pitchfork. 0: a tenth of the interaction length "
                 "r0 (without an interaction 1e-3)",
                 validators::atLeast(-HUGE_VAL));
    return Teuchos::RCP<const Teuchos::ParameterList>(loading);
  }();
  return valid;
}

const char* PathPlan::locaHelp() {
  return "passed to LOCA's stepper (sublists Stepper, Predictor, Step Size, Bifurcation, ... with LOCA's own "
         "names), over cgcm's defaults: Stepper/Continuation Method = Arc Length, Max Steps = 2000; "
         "Predictor/Method = Tangent; Step Size/Method = Adaptive, Min Step Size = Loading/Min Increment, Max "
         "Step Size = Loading/Max Increment (continuation in u), the first step's change of the parameter "
         "Loading/Initial Increment (in u) or 1 % of the way to the first Parameter Path waypoint. cgcm sets "
         "Stepper/Continuation Parameter, Initial Value, Min and Max Value and Max Nonlinear Iterations itself; "
         "names LOCA does not read are rejected before the run";
}

PathPlan::PathPlan(const Teuchos::ParameterList& loading, const std::vector<std::string>& parameters,
                   Real lengthScale) {
  const std::string control = loading.get<std::string>("Control");
  for (const auto& e : pathControlRegistry())
    if (control == e.deckName) follower_ = e.make();
  if (!follower_) throw InputError("Loading/Control = \"" + control + "\": not a path control");
  path_ = LoadPathSettings::fromParameters(loading);
  // A jump relaxes in moves of at most a quarter of the interaction length, so that
  // no iterate skips the equilibrium spacing or pushes a surface through another.
  if (lengthScale > 0.0) path_.relaxation.maxIncrement = 0.25 * lengthScale;
  branchSwitching_ = loading.get<bool>("Branch Switching");
  switchAmplitude_ = loading.get<double>("Switch Amplitude");
  if (!std::isfinite(switchAmplitude_))
    throw InputError("Loading/Switch Amplitude: must be finite (0: a tenth of the interaction length)");
  if (switchAmplitude_ == 0.0) switchAmplitude_ = lengthScale > 0.0 ? 0.1 * lengthScale : 1e-3;
  parameter_ = loading.get<std::string>("Continuation Parameter");
  const auto& pp = loading.get<Teuchos::Array<double>>("Parameter Path");
  parameterPath_.assign(pp.begin(), pp.end());
  const auto& b = loading.get<Teuchos::Array<double>>("Parameter Bounds");
  bounds_.assign(b.begin(), b.end());
  if (parameter_ != "u" && std::find(parameters.begin(), parameters.end(), parameter_) == parameters.end())
    throw InputError("Loading/Continuation Parameter = \"" + parameter_ +
                     "\" needs an interaction between bodies (a sphere geometry); allowed here: \"u\"");
  if (parameter_ == "u" && !parameterPath_.empty())
    throw InputError("Loading/Parameter Path: only with a Continuation Parameter other than \"u\"; the path in u "
                     "is Loading/Approach Path");
  if (parameter_ != "u" && parameterPath_.empty())
    throw InputError("Loading/Parameter Path: give the waypoints of " + parameter_ + " (e.g. {100, 20})");
  for (std::size_t i = 0; i < parameterPath_.size(); ++i)
    if (!std::isfinite(parameterPath_[i]) || !(parameterPath_[i] > 0.0))
      throw InputError("Loading/Parameter Path: waypoint " + std::to_string(i) + " = " +
                       std::to_string(parameterPath_[i]) + "; " + parameter_ + " must be finite and > 0");
  if (!bounds_.empty()) {
    if (bounds_.size() != 2 || !(bounds_[0] < bounds_[1]) || !std::isfinite(bounds_[0]) || !std::isfinite(bounds_[1]))
      throw InputError("Loading/Parameter Bounds: give {lower, upper} with lower < upper (finite), or leave it empty");
    for (Real v : parameter_ == "u" ? path_.path : parameterPath_)
      if (v < bounds_[0] || v > bounds_[1])
        throw InputError("Loading/Parameter Bounds: the path value " + std::to_string(v) + " lies outside {" +
                         std::to_string(bounds_[0]) + ", " + std::to_string(bounds_[1]) + "}");
  }
}

Teuchos::ParameterList PathPlan::locaParameters(const Teuchos::ParameterList& deckLoca) const {
  Teuchos::ParameterList loca = deckLoca;
  auto& step = loca.sublist("Step Size");
  if (!step.isParameter("Min Step Size")) step.set("Min Step Size", path_.minIncrement);
  if (!step.isParameter("Max Step Size") && parameter_ == "u") step.set("Max Step Size", path_.maxIncrement);
  return loca;
}

// The bound beyond which a continuation segment counts as run away: the deck's
// bounds, or the path's range widened by twice its span (positive parameters
// stay above a thousandth of the path's smallest value).
Real PathPlan::runawayBound(const std::vector<Real>& waypoints, Real direction, bool positive) const {
  if (!bounds_.empty()) return direction > 0 ? bounds_[0] : bounds_[1];
  const auto [lo, hi] = std::minmax_element(waypoints.begin(), waypoints.end());
  const Real span = *hi - *lo;
  if (direction > 0) return positive ? std::max(*lo - 2.0 * span, 1e-3 * *lo) : *lo - 2.0 * span;
  return *hi + 2.0 * span;
}

PathCost PathPlan::continueTo(Vector& u, int index, Real target, const std::vector<Real>& waypoints,
                              Real initialStep, bool stableStart, PathContext& c,
                              const PathFollower::Observer& observer, int& step,
                              const std::function<bool(const PathPoint&)>& stopWhen) const {
  const Real from = c.model->parameter(index);
  ContinuationSegment segment;
  segment.parameter = index;
  segment.target = target;
  segment.direction = target > from ? 1.0 : -1.0;
  segment.bound = runawayBound(waypoints, segment.direction, index > 0);
  segment.initialStep = std::min(initialStep, std::abs(target - from));
  segment.stableStart = stableStart;
  if (branchSwitching_ && c.spectrum && c.branch == 0) segment.switchAmplitude = switchAmplitude_;
  segment.stopWhen = stopWhen;
  const auto r = c.continuation->run(u, segment, [&](const PathPoint& pt) {
    PathState s = stateOf(pt, ++step);
    s.branch = c.branch;
    observer(s);
  });
  PathCost cost{r.steps, r.restarts, {}};
  for (std::size_t k = 0; k < r.otherBranches.size(); ++k)
    c.switches.push_back({index, r.branchPoints.at(k), r.otherBranches[k]});
  cost.notes = r.switchFailures;
  if (!r.reached && !r.stoppedWhen) throw NumericalError(r.failure);
  u.assign(*r.last.x);
  for (std::size_t k = 0; k < r.last.p.size(); ++k) c.model->setParameter(int(k), r.last.p[k]);
  return cost;
}

PathCost PathPlan::follow(Vector& u, PathContext& c, const PathFollower::Observer& observer) const {
  int step = c.resume ? c.resume->step : 0;
  bool stable = true;
  if (c.continuation) c.continuation->monitorStability(c.spectrum);
  std::optional<PathPoint> firstFold;  // of the path in u (LOCA/Bifurcation/Type = Turning Point follows it)
  const auto track = [&](const PathState& s) {
    step = s.step;
    stable = s.stableByFolds;
    if (s.fold && !firstFold && s.branch == 0 && !s.onFoldCurve) {
      firstFold = PathPoint();
      firstFold->x = Teuchos::rcp(new Vector(*s.x, Teuchos::Copy));
      firstFold->p = s.p;
    }
    if (!c.spectrum || s.negativeEigenvalues >= 0) return observer(s);
    // a state the continuation did not assess (displacement control, the start of a path)
    PathState assessed = s;
    const Spectrum spectrum = c.spectrum->compute(*s.x, s.p);
    assessed.eigenvalues = spectrum.eigenvalues;
    assessed.negativeEigenvalues = spectrum.negative;
    assessed.critical = spectrum.mode();
    if (!s.fold) assessed.stable = spectrum.stable();
    observer(assessed);
  };
  PathCost cost = follower_->follow(u, *this, c, track);
  if (parameter_ == "u") {
    followOtherBranches(u, c, track, step, cost);
    return cost;
  }
  const int index = c.model->parameterIndex(parameter_);
  if (c.continuation->followsFolds()) {
    followFold(firstFold, index, c, track, step, cost);
    return cost;
  }
  std::vector<Real> waypoints{c.model->parameter(index)};
  waypoints.insert(waypoints.end(), parameterPath_.begin(), parameterPath_.end());
  for (std::size_t k = 1; k < waypoints.size(); ++k) {
    const Real now = c.model->parameter(index);
    if (waypoints[k] == now) continue;
    const auto segment =
        continueTo(u, index, waypoints[k], waypoints, 0.01 * std::abs(waypoints[k] - now), stable, c, track, step);
    cost.continuationSteps += segment.continuationSteps;
    cost.graphRestarts += segment.graphRestarts;
    cost.notes.insert(cost.notes.end(), segment.notes.begin(), segment.notes.end());
  }
  followOtherBranches(u, c, track, step, cost);
  return cost;
}

void PathPlan::followFold(const std::optional<PathPoint>& fold, int index, PathContext& c,
                          const PathFollower::Observer& observer, int& step, PathCost& cost) const {
  if (!fold)
    throw NumericalError("LOCA/Bifurcation/Type = Turning Point: the Approach Path has no fold to follow in " +
                         parameter_ + " (no jump-to-contact at the deck's " + parameter_ + ")");
  // the fold's null vector: the tangent's critical mode there (its eigenvalue is 0 to solver tolerance)
  TangentSpectrum spectrum(c.model, 1);
  const Spectrum atFold = spectrum.compute(*fold->x, fold->p);
  for (std::size_t k = 0; k < fold->p.size(); ++k) c.model->setParameter(int(k), fold->p[k]);
  const Real from = fold->p[std::size_t(index)], target = parameterPath_.back();
  std::vector<Real> waypoints{from};
  waypoints.insert(waypoints.end(), parameterPath_.begin(), parameterPath_.end());
  ContinuationSegment segment;
  segment.parameter = index;
  segment.foldParameter = 0;
  segment.nullVector = atFold.mode();
  segment.target = target;
  segment.direction = target > from ? 1.0 : -1.0;
  segment.bound = runawayBound(waypoints, segment.direction, true);
  segment.initialStep = 0.01 * std::abs(target - from);
  segment.stopAtFold = true;  // the fold curve's extreme in the parameter: the cusp where the fold ends
  const auto r = c.continuation->run(*fold->x, segment, [&](const PathPoint& pt) {
    PathState s = stateOf(pt, ++step);
    s.onFoldCurve = true;
    observer(s);
  });
  cost.continuationSteps += r.steps;
  cost.graphRestarts += r.restarts;
  if (!r.reached && !r.stoppedAtFold) throw NumericalError("following the fold in " + parameter_ + ": " + r.failure);
}

void PathPlan::followOtherBranches(Vector& u, PathContext& c, const PathFollower::Observer& observer, int& step,
                                   PathCost& cost) const {
  for (std::size_t k = 0; k < c.switches.size(); ++k) {
    const BranchSwitch sw = c.switches[k];
    const int index = sw.parameter;
    const std::string name = c.model->parameterNames()[index];
    std::vector<Real> waypoints = index == 0 ? path_.path : parameterPath_;
    waypoints.push_back(sw.branchPoint.p[std::size_t(index)]);
    const Real at = sw.other.p[std::size_t(index)];
    const Real direction = at >= sw.branchPoint.p[std::size_t(index)] ? 1.0 : -1.0;
    const Real target = direction > 0 ? *std::max_element(waypoints.begin(), waypoints.end())
                                      : *std::min_element(waypoints.begin(), waypoints.end());
    c.branch = int(k) + 1;
    // the first point of the branch, then the branch
    PathState first = stateOf(sw.other, ++step);
    first.branch = c.branch;
    observer(first);
    if (direction * (target - at) <= 0.0) continue;
    u.assign(*sw.other.x);
    for (std::size_t i = 0; i < sw.other.p.size(); ++i) c.model->setParameter(int(i), sw.other.p[i]);
    // a branch that rejoins the path does so at one of its branch points, where it turns (a fold of the
    // branch): it ends there
    const Real near = 0.01 * std::abs(switchAmplitude_);
    const auto rejoins = [&](const PathPoint& pt) {
      if (!pt.fold) return false;
      for (const auto& other : c.switches) {
        Vector d(*pt.x, Teuchos::Copy);
        d.update(-1.0, *other.branchPoint.x, 1.0);
        if (d.normInf() <= near) return true;
      }
      return false;
    };
    try {
      const Real initialStep = index == 0 ? path_.initialIncrement : 0.01 * std::abs(target - at);
      const auto segment =
          continueTo(u, index, target, waypoints, initialStep, sw.other.stable, c, observer, step, rejoins);
      cost.continuationSteps += segment.continuationSteps;
      cost.graphRestarts += segment.graphRestarts;
      cost.notes.insert(cost.notes.end(), segment.notes.begin(), segment.notes.end());
    } catch (const NumericalError& e) {
      throw NumericalError("the branch from the branch point at " + name + " = " +
                           std::to_string(sw.branchPoint.p[std::size_t(index)]) + ": " + e.what());
    }
  }
  c.branch = 0;
}

}  // namespace cgcm::solver
