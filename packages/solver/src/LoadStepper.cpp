#include "cgcm/solver/LoadStepper.hpp"

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cgcm/core/Error.hpp"
#include "cgcm/core/ParameterValidators.hpp"

namespace cgcm::solver {

Teuchos::RCP<const Teuchos::ParameterList> LoadPathSettings::validParameters() {
  static Teuchos::RCP<Teuchos::ParameterList> valid;
  if (!valid.is_null()) return valid;
  valid = Teuchos::rcp(new Teuchos::ParameterList("Loading"));
  valid->set("Approach Path", Teuchos::Array<double>(Teuchos::tuple<double>(0.0, 0.1)),
             "waypoints of the prescribed displacement u; the run starts at the first and moves linearly "
             "through the others, e.g. {-0.02, 0.06, -0.03}: approach, then retract");
  using namespace validators;
  const auto positive = atLeast(1e-300);
  valid->set("Initial Increment", 0.005, "first increment of u (arc-length control: the first step's change of "
             "the continuation parameter)", positive);
  valid->set("Min Increment", 1e-7, "the run stops with an error if a step fails at this increment "
             "(arc-length control: the smallest arclength step)", positive);
  valid->set("Max Increment", 0.01,
             "largest increment of u (arc-length control: the largest arclength step, LOCA's Max Step Size)", positive);
  valid->set("Easy Step Iterations", 4, "the increment grows after a step that needed at most this many "
             "Newton iterations", intAtLeast(1));
  valid->set("Growth Factor", 1.5, "increment growth after an easy step (>= 1)", atLeast(1.0));
  valid->set("Cutback Factor", 0.5, "increment reduction after a failed step (0.01 .. 0.99)", between(0.01, 0.99));
  valid->set("Cutbacks Before Jump", 0,
             "displacement control: a step that still fails after this many cut-backs is taken through by the "
             "Jump Method, which also passes a fold (jump-to-contact, jump-off-contact, a ring of the contact "
             "zone snapping on or off); 0: at the first failure (0 .. 50)",
             intBetween(0, 50));
  valid->set("Jump Method", "relaxation",
             "displacement control, a step that failed: \"relaxation\" relaxes the last state at the step's u "
             "(pseudo-transient continuation: an overdamped motion ending in Newton steps) to where a damped "
             "motion lands, and locates the fold by continuation if the state left its branch; \"continuation\" "
             "follows the unstable branch by arc-length until u is back at the step's value (the connected "
             "stable branch; slow where the unstable branch has many small loops, as when the contact zone "
             "grows ring by ring)",
             choices({"relaxation", "continuation"}));
  valid->set("Relaxation Iterations", 400,
             "Jump Method = relaxation: iterations (linear solves) a jump may take before the step counts as "
             "failed (1 .. 100000)",
             intBetween(1, 100000));
  return valid;
}

LoadPathSettings LoadPathSettings::fromParameters(const Teuchos::ParameterList& p) {
  LoadPathSettings s;
  const auto& path = p.get<Teuchos::Array<double>>("Approach Path");
  s.path.assign(path.begin(), path.end());
  s.initialIncrement = p.get<double>("Initial Increment");
  s.minIncrement = p.get<double>("Min Increment");
  s.maxIncrement = p.get<double>("Max Increment");
  s.easyIterations = p.get<int>("Easy Step Iterations");
  s.growth = p.get<double>("Growth Factor");
  s.cutback = p.get<double>("Cutback Factor");
  s.cutbacksBeforeJump = p.get<int>("Cutbacks Before Jump");
  s.relaxation.maxIterations = p.get<int>("Relaxation Iterations");
  s.jumpMethod = p.get<std::string>("Jump Method") == "continuation" ? JumpMethod::Continuation : JumpMethod::Relaxation;
  if (s.path.size() < 2)
    throw InputError("Loading/Approach Path: needs at least two values (start and target), got " +
                     std::to_string(s.path.size()));
  for (std::size_t i = 0; i < s.path.size(); ++i)
    if (!std::isfinite(s.path[i]))
      throw InputError("Loading/Approach Path: waypoint " + std::to_string(i) + " is not a finite number");
  for (std::size_t i = 1; i < s.path.size(); ++i) {
    if (s.path[i] == s.path[i - 1])
      throw InputError("Loading/Approach Path: repeats the value " + std::to_string(s.path[i]) + " at positions " +
                       std::to_string(i - 1) + " and " + std::to_string(i) + "; consecutive waypoints must differ");
    if (i >= 2 && (s.path[i] - s.path[i - 1]) * (s.path[i - 1] - s.path[i - 2]) > 0)
      throw InputError("Loading/Approach Path: keeps moving the same way through waypoint " +
                       std::to_string(s.path[i - 1]) + "; list only the turning points (e.g. {-0.02, 0.06, -0.03})");
  }
  if (s.minIncrement > s.initialIncrement || s.initialIncrement > s.maxIncrement)
    throw InputError("Loading/Initial Increment: need Min Increment <= Initial Increment <= Max Increment, got " +
                     std::to_string(s.minIncrement) + ", " + std::to_string(s.initialIncrement) + ", " +
                     std::to_string(s.maxIncrement));
  return s;
}

bool LoadStepper::continueThrough(Real p, Real pNew, Vector& u, Vector& trial, StepInfo& info, int& step,
                                  const Observer& observer, const Vector* landing) {
  const auto [lo, hi] = std::minmax_element(settings_.path.begin(), settings_.path.end());
  const Real range = 2.0 * (*hi - *lo) + std::abs(pNew - p);
  ContinuationSegment segment;
  segment.parameter = 0;
  segment.target = pNew;
  segment.direction = pNew > p ? 1.0 : -1.0;
  segment.bound = p - segment.direction * range;
  segment.initialStep = std::abs(pNew - p);
  segment.stableStart = true;
  segment.landOnly = true;
  segment.stopAtFold = settings_.jumpMethod == LoadPathSettings::JumpMethod::Relaxation;
  model_->setDisplacement(p);
  bool first = true;
  const auto result = continuation_->run(u, segment, [&](const PathPoint& pt) {
    // Under displacement control only the fold where the branch ends is a
    // physical state; the rest of the continuation (unstable branches, further
    // folds on the way) is the path of the jump.
    if (!pt.fold || !first) return;
    first = false;
    StepInfo fold;
    fold.step = ++step;
    fold.displacement = pt.p[0];
    fold.fold = true;
    fold.newton.converged = true;
    fold.newton.iterations = pt.iterations;
    fold.newton.residualNorms = {pt.residual};
    observer(fold, *pt.x);
  });
  jumps_.push_back(result);
  model_->setDisplacement(pNew);
  if (landing != nullptr && !result.reached) {
    // The jump's end is known; the continuation only located its fold (or
    // could not). The landing moves back along its branch (which exists
    // there: it is stable at the step's u and ends only at its own fold) to
    // the fold's u, so that the jump is vertical in the load curve and the
    // loop's hysteresis that of a jump at the fold.
    trial.assign(*landing);
    info.jump = true;
    info.newton.converged = true;
    info.newton.iterations += result.newtonIterations;
    info.newton.failure.clear();
    if (result.stoppedAtFold) {
      const Real uJump = result.folds.front().p[0];
      Vector near(*landing, Teuchos::Copy);
      model_->setDisplacement(uJump);
      model_->dirichlet().impose(uJump, near);
      const NewtonResult back = newton_.solve(near);
      info.newton.iterations += back.iterations;
      if (back.converged && (!continuous_ || continuous_(*landing, near))) {
        trial.assign(near);
        info.displacement = uJump;
        info.newton.residualNorms = back.residualNorms;
      }
      model_->setDisplacement(info.displacement);
    }
    return true;
  }
  if (result.stoppedAtFold) {
    const bool landed = relaxFromFold(result.folds.front(), segment.direction, pNew, trial, info);
    info.newton.iterations += result.newtonIterations;
    if (!landed) info.newton.failure = "jump from the fold at u = " + std::to_string(result.folds.front().p[0]) +
                                       ": pseudo-transient relaxation failed: " + info.newton.failure;
    return landed;
  }
  if (!result.reached) {
    info.newton.failure = "continuation from u = " + std::to_string(p) + ": " + result.failure;
    return false;
  }
  trial.assign(*result.last.x);
  info.jump = !result.folds.empty();
  info.newton.converged = true;
  info.newton.iterations += result.newtonIterations;
  info.newton.residualNorms = {result.last.residual};
  info.newton.failure.clear();
  return true;
}

bool LoadStepper::relaxThrough(Real p, Real pNew, Vector& u, Vector& trial, StepInfo& info, int& step,
                               const Observer& observer) {
  // Relax from the last state straight to pNew. A state on the same branch
  // by the continuity check is taken as it is: a plain step if the
  // relaxation settled onto it, a small snap (a ring of the contact zone
  // snapping on or off, which the check lets pass) if it fell. For a jump
  // that leaves the branch (jump-in, pull-off) continuation from the last
  // state locates the fold, so that the curve shows where the branch ends.
  model_->setDisplacement(pNew);
  trial.assign(u);
  model_->dirichlet().impose(pNew, trial);
  info.newton = newton_.relax(trial, settings_.relaxation);
  if (!info.newton.converged) {
    const int spent = info.newton.iterations;
    const bool passed = continueThrough(p, pNew, u, trial, info, step, observer);
    info.newton.iterations += spent;
    return passed;
  }
  info.displacement = pNew;
  info.jump = info.newton.fell;
  if (!continuous_ || continuous_(u, trial)) return true;
  info.jump = true;
  const Vector landing(trial, Teuchos::Copy);
  return continueThrough(p, pNew, u, trial, info, step, observer, &landing);
}

bool LoadStepper::relaxFromFold(const PathPoint& fold, Real direction, Real pNew, Vector& trial, StepInfo& info) {
  // Just past the fold the state has no equilibrium nearby and relaxes to
  // the far branch; if the relaxation fails there, further out.
  const Real uFold = fold.p[0];
  const Real room = std::max(0.0, direction * (pNew - uFold));
  Real offset = std::min(room, 0.01 * settings_.initialIncrement);
  int iterations = 0;
  for (;;) {
    const Real uJump = offset >= room ? pNew : uFold + direction * offset;
    model_->setDisplacement(uJump);
    trial.assign(*fold.x);
    model_->dirichlet().impose(uJump, trial);
    info.newton = newton_.relax(trial, settings_.relaxation);
    iterations += info.newton.iterations;
    info.newton.iterations = iterations;
    if (info.newton.converged) {
      info.displacement = uJump;
      info.jump = true;
      return true;
    }
    if (offset >= room) return false;
    offset = std::min(room, 10.0 * offset);
  }
}

void LoadStepper::run(Vector& u, const Observer& observer, const CheckpointSink& checkpoint,
                      const StepperState* resume, const Vector* previous) {
  const auto& path = settings_.path;
  Vector trial(u.getMap());
  Vector uPrevious(u.getMap());  // the converged state before u, for the secant predictor
  Real pPrevious = 0.0;
  bool havePrevious = false;
  int step = 0;
  Real pCurrent = path[0];
  if (resume != nullptr && (resume->segment < 1 || resume->segment >= path.size()))
    throw InputError("restart: the checkpoint's path segment " + std::to_string(resume->segment) +
                     " is not one of this path's (1 .. " + std::to_string(path.size() - 1) + ")");

  // Predictor: extrapolate along the secant of the last two states (exact in
  // the rigid phase, close elsewhere), then impose the new boundary values.
  auto attempt = [&](Real p, StepInfo& info) {
    model_->setDisplacement(p);
    trial.assign(u);
    if (havePrevious && pCurrent != pPrevious)
      trial.update((p - pCurrent) / (pCurrent - pPrevious), u, -(p - pCurrent) / (pCurrent - pPrevious), uPrevious,
                   1.0);
    model_->dirichlet().impose(p, trial);
    info.newton = newton_.solve(trial);
    if (!info.newton.converged && havePrevious) {  // the predictor may have overshot: retry from u
      trial.assign(u);
      model_->dirichlet().impose(p, trial);
      const auto first = info.newton;
      info.newton = newton_.solve(trial);
      info.newton.iterations += first.iterations;
      if (!info.newton.converged) info.newton.failure = first.failure;
    }
    return info.newton.converged;
  };

  Real p = path[0];
  Real increment = settings_.initialIncrement;
  std::size_t firstSegment = 1;
  auto state = [&](std::size_t seg) {
    StepperState s;
    s.segment = seg;
    s.displacement = p;
    s.increment = increment;
    s.step = step;
    s.havePrevious = havePrevious;
    s.previousDisplacement = pPrevious;
    return s;
  };
  if (resume != nullptr) {
    p = pCurrent = resume->displacement;
    increment = resume->increment;
    step = resume->step;
    havePrevious = resume->havePrevious && previous != nullptr;
    pPrevious = resume->previousDisplacement;
    if (havePrevious) uPrevious.assign(*previous);
    firstSegment = resume->segment;
    model_->setDisplacement(p);
  } else {
    StepInfo info;
    info.displacement = path[0];
    if (!attempt(path[0], info))
      throw NumericalError("no equilibrium at the start of the load path, u = " + std::to_string(path[0]) + ": " +
                           info.newton.failure);
    u.assign(trial);
    observer(info, u);
    if (checkpoint) checkpoint(state(1), u, uPrevious);
  }

  for (std::size_t seg = firstSegment; seg < path.size(); ++seg) {
    const Real target = path[seg];
    const Real dir = target > p ? 1.0 : -1.0;
    while (dir * (target - p) > 1e-14 * (1.0 + std::abs(target))) {
      StepInfo info;
      for (;;) {
        const Real dp = std::min(increment, dir * (target - p));
        // Land exactly on the waypoint when the remainder is a small fraction of a step.
        const Real pNew = (dir * (target - p) - dp < 0.05 * dp) ? target : p + dir * dp;
        info.displacement = pNew;
        const bool converged = attempt(pNew, info);
        if (converged && (!continuous_ || continuous_(u, trial))) break;
        if (converged) info.newton.failure = "the state left its branch";
        ++info.cutbacks;
        const bool exhausted = increment * settings_.cutback < settings_.minIncrement;
        if (continuation_ != nullptr && (info.cutbacks > settings_.cutbacksBeforeJump || exhausted)) {
          const bool passed = settings_.jumpMethod == LoadPathSettings::JumpMethod::Relaxation
                                  ? relaxThrough(p, pNew, u, trial, info, step, observer)
                                  : continueThrough(p, pNew, u, trial, info, step, observer);
          if (passed) {
            increment = settings_.initialIncrement;
            break;
          }
          std::ostringstream msg;
          msg << "step " << step + 1 << " from u = " << p << " to " << pNew << " failed: " << info.newton.failure;
          model_->setDisplacement(p);
          throw NumericalError(msg.str());
        }
        if (exhausted) {
          std::ostringstream msg;
          msg << "step " << step + 1 << " from u = " << p << " failed below Loading/Min Increment = "
              << settings_.minIncrement << " (" << info.newton.failure << ")";
          model_->setDisplacement(p);
          throw NumericalError(msg.str());
        }
        increment *= settings_.cutback;
      }
      uPrevious.assign(u);
      pPrevious = p;
      havePrevious = !info.jump;  // no secant across a jump
      p = info.displacement;
      pCurrent = p;
      u.assign(trial);
      info.step = ++step;
      observer(info, u);
      if (info.cutbacks == 0 && info.newton.iterations <= settings_.easyIterations)
        increment = std::min(settings_.maxIncrement, increment * settings_.growth);
      if (checkpoint) checkpoint(state(seg), u, uPrevious);
    }
  }
}

}  // namespace cgcm::solver
