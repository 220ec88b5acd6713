#include "cgcm/solver/LoadStepper.hpp"

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include <cmath>
#include <sstream>

#include "cgcm/core/Error.hpp"

namespace cgcm::solver {

Teuchos::RCP<const Teuchos::ParameterList> LoadPathSettings::validParameters() {
  static Teuchos::RCP<Teuchos::ParameterList> valid;
  if (!valid.is_null()) return valid;
  valid = Teuchos::rcp(new Teuchos::ParameterList("Loading"));
  valid->set("Approach Path", Teuchos::Array<double>{0.0, 0.1},
             "waypoints of the prescribed displacement u (the load parameter); the run starts at the first "
             "and moves linearly through the others, e.g. {-0.02, 0.06, -0.03}: approach, then retract");
  auto positive = Teuchos::rcp(new Teuchos::EnhancedNumberValidator<double>());
  positive->setMin(1e-300);
  valid->set("Initial Increment", 0.005, "first increment of u", positive);
  valid->set("Min Increment", 1e-7, "the run stops with an error if a step fails at this increment", positive);
  valid->set("Max Increment", 0.01, "largest increment of u", positive);
  auto iters = Teuchos::rcp(new Teuchos::EnhancedNumberValidator<int>());
  iters->setMin(1);
  valid->set("Easy Step Iterations", 4, "the increment grows after a step that needed at most this many "
             "Newton iterations", iters);
  auto growth = Teuchos::rcp(new Teuchos::EnhancedNumberValidator<double>());
  growth->setMin(1.0);
  valid->set("Growth Factor", 1.5, "increment growth after an easy step (>= 1)", growth);
  auto cut = Teuchos::rcp(new Teuchos::EnhancedNumberValidator<double>(0.01, 0.99));
  valid->set("Cutback Factor", 0.5, "increment reduction after a failed step (0.01 .. 0.99)", cut);
  valid->set("Fold Increment", 1e-4,
             "a step that fails or jumps even below this increment marks a fold of the load path "
             "(jump-to-contact / jump-off-contact): the state then jumps to the other stable branch",
             positive);
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
  s.foldIncrement = p.get<double>("Fold Increment");
  if (s.path.size() < 2)
    throw InputError("Loading/Approach Path needs at least two values (start and target), got " +
                     std::to_string(s.path.size()));
  for (std::size_t i = 1; i < s.path.size(); ++i) {
    if (s.path[i] == s.path[i - 1])
      throw InputError("Loading/Approach Path repeats the value " + std::to_string(s.path[i]) +
                       " at positions " + std::to_string(i - 1) + " and " + std::to_string(i) +
                       "; consecutive waypoints must differ");
    if (i >= 2 && (s.path[i] - s.path[i - 1]) * (s.path[i - 1] - s.path[i - 2]) > 0)
      throw InputError("Loading/Approach Path keeps moving the same way through waypoint " +
                       std::to_string(s.path[i - 1]) + "; list only the turning points (e.g. {-0.02, 0.06, -0.03})");
  }
  if (s.minIncrement > s.foldIncrement)
    throw InputError("Loading: need Min Increment <= Fold Increment, got " + std::to_string(s.minIncrement) +
                     " and " + std::to_string(s.foldIncrement));
  if (s.minIncrement > s.initialIncrement || s.initialIncrement > s.maxIncrement)
    throw InputError("Loading: need Min Increment <= Initial Increment <= Max Increment, got " +
                     std::to_string(s.minIncrement) + ", " + std::to_string(s.initialIncrement) + ", " +
                     std::to_string(s.maxIncrement));
  return s;
}

bool LoadStepper::jumpToOtherBranch(Real p, const Vector& u, const Vector* uPrevious, Vector& trial,
                                    StepInfo& info) {
  model_->setLoad(p);
  int iterations = 0;
  auto relax = [&](Real push, const Vector* direction, Real largest) {
    trial.assign(u);
    if (push > 0.0) trial.update(push / largest, *direction, 1.0);
    model_->dirichlet().impose(p, trial);
    // a pushed state past the fold lands within a few dozen pseudo steps
    // (at gammaW = 20, 44 pseudo steps and Newton iterations together); the
    // unpushed one, the last resort, gets the default
    info.newton = newton_.solvePseudoTransient(trial, jumpStepLimit_, 1e-2, push > 0.0 ? 100 : 300);
    iterations += info.newton.iterations;
    info.newton.iterations = iterations;
    // a relaxation that only stalls has not found an equilibrium
    if (info.newton.converged && info.newton.stalled)
      info.newton.failure = "the relaxation ended in a Newton cycle, not at an equilibrium";
    if (!info.newton.converged || info.newton.stalled) return false;
    info.jump = !continuous_ || !continuous_(u, trial);
    return true;
  };
  // Right at a fold the residual is tiny and a relaxation from u hardly
  // moves. Near the fold the secant of the last two states is the mode that
  // loses stability, so the state is pushed along it first, by growing amounts.
  if (uPrevious != nullptr && jumpStepLimit_ < 1e300) {
    Vector direction(u.getMap());
    direction.update(1.0, u, -1.0, *uPrevious, 0.0);
    const Real largest = direction.normInf();
    if (largest > 0.0)
      for (Real push : {1.0, 4.0})
        if (relax(push * jumpStepLimit_, &direction, largest)) return true;  // on either branch
  }
  return relax(0.0, nullptr, 1.0);
}

void LoadStepper::run(Vector& u, const Observer& observer) {
  const auto& path = settings_.path;
  Vector trial(u.getMap());
  Vector uPrevious(u.getMap());  // the converged state before u, for the secant predictor
  Real pPrevious = 0.0;
  bool havePrevious = false;
  int step = 0;
  Real pCurrent = path[0];

  // Predictor: extrapolate along the secant of the last two states (exact in
  // the rigid phase, close elsewhere), then impose the new boundary values.
  auto attempt = [&](Real p, StepInfo& info) {
    model_->setLoad(p);
    trial.assign(u);
    if (havePrevious && pCurrent != pPrevious)
      trial.update((p - pCurrent) / (pCurrent - pPrevious), u, -(p - pCurrent) / (pCurrent - pPrevious), uPrevious,
                   1.0);
    model_->dirichlet().impose(p, trial);
    info.newton = newton_.solve(trial);
    if (!info.newton.converged && havePrevious &&
        info.newton.failure.find("inverted") != std::string::npos) {  // the predictor overshot: retry from u
      trial.assign(u);
      model_->dirichlet().impose(p, trial);
      const auto first = info.newton;
      info.newton = newton_.solve(trial);
      info.newton.iterations += first.iterations;
    }
    return info.newton.converged;
  };

  // Initial state.
  {
    StepInfo info;
    info.load = path[0];
    if (!attempt(path[0], info))
      throw NumericalError("no equilibrium at the start of the load path, u = " + std::to_string(path[0]) + ": " +
                           info.newton.failure);
    u.assign(trial);
    observer(info, u);
  }

  Real p = path[0];
  Real increment = settings_.initialIncrement;
  for (std::size_t seg = 1; seg < path.size(); ++seg) {
    const Real target = path[seg];
    const Real dir = target > p ? 1.0 : -1.0;
    while (dir * (target - p) > 1e-14 * (1.0 + std::abs(target))) {
      StepInfo info;
      info.step = step + 1;
      for (;;) {
        const Real dp = std::min(increment, dir * (target - p));
        // Land exactly on the waypoint when the remainder is a small fraction of a step.
        const Real pNew = (dir * (target - p) - dp < 0.05 * dp) ? target : p + dir * dp;
        info.load = pNew;
        const bool converged = attempt(pNew, info);
        if (converged && (!continuous_ || continuous_(u, trial))) break;
        if (converged) info.newton.failure = "the state left its branch";
        ++info.cutbacks;
        if (increment <= settings_.foldIncrement) {
          // The branch ends here: the state must settle on the other stable branch.
          // the secant is the direction of motion only if the last step went the same way
          const bool secant = havePrevious && (pNew - p) * (p - pPrevious) > 0.0;
          if (jumpToOtherBranch(pNew, u, secant ? &uPrevious : nullptr, trial, info)) {
            increment = settings_.initialIncrement;
            break;
          }
        }
        increment *= settings_.cutback;
        if (increment < settings_.minIncrement) {
          std::ostringstream msg;
          msg << "load step from u = " << p << " failed below Loading/Min Increment = " << settings_.minIncrement
              << " (" << info.newton.failure << ")";
          model_->setLoad(p);
          throw NumericalError(msg.str());
        }
      }
      uPrevious.assign(u);
      pPrevious = p;
      havePrevious = !info.jump;  // no secant across a jump
      p = info.load;
      pCurrent = p;
      u.assign(trial);
      ++step;
      observer(info, u);
      if (info.cutbacks == 0 && info.newton.iterations <= settings_.easyIterations)
        increment = std::min(settings_.maxIncrement, increment * settings_.growth);
    }
  }
}

}  // namespace cgcm::solver
