#include "cgcm/solver/NewtonSolver.hpp"

#include <NOX_Observer.hpp>
#include <NOX_Solver_Factory.H>
#include <NOX_Solver_Generic.H>
#include <NOX_SolverStats.hpp>
#include <NOX_Thyra.H>
#include <Teuchos_StandardParameterEntryValidators.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <string>

#include "cgcm/core/Error.hpp"
#include "cgcm/solver/Convergence.hpp"
#include "cgcm/solver/PseudoTransientModel.hpp"
#include "cgcm/core/ParameterValidators.hpp"

namespace cgcm::solver {

namespace {

using Extract = Thyra::TpetraOperatorVectorExtraction<Real, LocalIndex, GlobalIndex, assembly::Node>;

// Records |f|_2 (the convergence test's norm) after every Newton iteration.
class ResidualRecorder : public NOX::Observer {
 public:
  ResidualRecorder(std::vector<Real>& norms, bool print, int rank, Teuchos::RCP<const NOX::Abstract::Vector> weights)
      : norms_(norms), print_(print), rank_(rank), weights_(std::move(weights)) {}
  void runPreSolve(const NOX::Solver::Generic& s) override { record(s); }
  void runPostIterate(const NOX::Solver::Generic& s) override {
    record(s);
    // NOX goes on with an unconverged Newton direction ("Rescue Bad Newton
    // Solve"); the first such solve is kept for the failure message.
    const auto stats = s.getSolverStatistics();
    if (stats && linearFailure_.empty() && stats->linearSolve.lastNonlinearSolve_NumLinearSolves > 0 &&
        !stats->linearSolve.lastLinearSolve_Converged) {
      std::ostringstream msg;
      msg << "the linear solve of Newton iteration " << s.getNumIterations() << " did not converge ("
          << stats->linearSolve.lastLinearSolve_NumIterations << " iterations, relative residual "
          << stats->linearSolve.lastLinearSolve_AchievedTolerance << ")";
      linearFailure_ = msg.str();
    }
  }
  const std::string& linearFailure() const { return linearFailure_; }

 private:
  void record(const NOX::Solver::Generic& s) {
    const auto& g = s.getSolutionGroup();
    if (!g.isF()) return;
    const Real n = residualNorm(g, weights_);
    norms_.push_back(n);
    if (print_ && rank_ == 0) std::printf("    newton %2d  |f| = %.6e\n", int(norms_.size()) - 1, n);
  }
  std::vector<Real>& norms_;
  bool print_;
  int rank_;
  Teuchos::RCP<const NOX::Abstract::Vector> weights_;
  std::string linearFailure_;
};

Teuchos::RCP<Vector> tpetraCopy(const NOX::Abstract::Vector& x) {
  const auto& tx = dynamic_cast<const NOX::Thyra::Vector&>(x);
  return Teuchos::rcp(new Vector(*Extract::getConstTpetraVector(tx.getThyraRCPVector()), Teuchos::Copy));
}

}  // namespace

double evaluationSeconds(const assembly::Problem& a) {
  return a.timings().residual + a.timings().jacobian + a.timings().interaction;
}

Teuchos::RCP<const Teuchos::ParameterList> NewtonSettings::validParameters() {
  static Teuchos::RCP<Teuchos::ParameterList> valid;
  if (!valid.is_null()) return valid;
  valid = Teuchos::rcp(new Teuchos::ParameterList("Newton"));
  valid->set("Line Search", "full step", "full step: plain Newton; backtrack: halve the step until |f| decreases",
             validators::choices({"full step", "backtrack"}));
  const auto tolerance = validators::between(1e-14, 1e-2);
  valid->set("Residual Tolerance", 1e-10,
             "a state is accepted when the 2-norm of the residual (internal plus interaction force over all free "
             "dofs) is at most this times the force unit F_ref: E0/R0 = Y R0^2 for contact (Y R0 per unit "
             "thickness in plane strain), Young's modulus times the loaded area for a block, with Y Material's "
             "Young's modulus; the rows of a body stiffer than that count divided by Y_body/Y. A state needs one "
             "Newton update unless its starting point already meets 1e-6 of the tolerance. The run prints the "
             "absolute value. Round-off leaves |f|_2 below 1e-14 F_ref on the benchmark meshes of level 0 to 3 "
             "(1e-14 .. 1e-2)",
             tolerance);
  valid->set("Max Iterations", 15, "Newton iterations before a step counts as failed and is cut back (1 .. 1000)",
             validators::intBetween(1, 1000));
  valid->set("Print Iterations", false, "print |f| after every Newton iteration");
  return valid;
}

NewtonSettings NewtonSettings::fromParameters(const Teuchos::ParameterList& newton,
                                              const Teuchos::ParameterList& linearSolver) {
  NewtonSettings s;
  s.lineSearch = newton.get<std::string>("Line Search") == "backtrack" ? LineSearch::Backtrack : LineSearch::FullStep;
  s.residualTolerance = newton.get<double>("Residual Tolerance");
  s.maxIterations = newton.get<int>("Max Iterations");
  s.printIterations = newton.get<bool>("Print Iterations");
  s.linearTolerance = linearSolver.get<double>("Tolerance");
  s.adaptiveLinearTolerance = linearSolver.get<std::string>("Forcing Term") == "Eisenstat-Walker";
  return s;
}

void setLinearSolveControls(const NewtonSettings& settings, bool adaptive, Teuchos::ParameterList& newtonDirection) {
  // NOX passes its own "Tolerance" (default 1e-10) to every solve, and Belos then uses it in place of the
  // Stratimikos list's "Convergence Tolerance".
  newtonDirection.sublist("Linear Solver").set("Tolerance", settings.linearTolerance);
  if (!adaptive) return;
  newtonDirection.set("Forcing Term Method", "Type 2");
  newtonDirection.set("Forcing Term Minimum Tolerance", settings.linearTolerance);
}

NewtonSolver::NewtonSolver(Teuchos::RCP<ModelEvaluator> model, const NewtonSettings& settings)
    : model_(std::move(model)), settings_(settings) {
  noxParams_ = Teuchos::rcp(new Teuchos::ParameterList("NOX"));
  noxParams_->set("Nonlinear Solver", "Line Search Based");
  auto& ls = noxParams_->sublist("Line Search");
  if (settings_.lineSearch == NewtonSettings::LineSearch::Backtrack) {
    ls.set("Method", "Backtrack");
    ls.sublist("Backtrack").set("Max Iters", 10);
    ls.sublist("Backtrack").set("Minimum Step", 1e-6);
  } else {
    ls.set("Method", "Full Step");
  }
  noxParams_->sublist("Direction").set("Method", "Newton");
  setLinearSolveControls(settings_, settings_.adaptiveLinearTolerance, noxParams_->sublist("Direction").sublist("Newton"));
  noxParams_->sublist("Printing").set("Output Information", 0);
  resetJacobian();
}

NewtonSolver::~NewtonSolver() = default;

void NewtonSolver::resetJacobian() {
  NOX::Thyra::Vector x0(*model_->getNominalValues().get_x());
  const Teuchos::RCP<::Thyra::PreconditionerBase<Real>> noPrecOp;
  const Teuchos::RCP<::Thyra::PreconditionerFactoryBase<Real>> noPrecFactory;
  group_ = Teuchos::rcp(new NOX::Thyra::Group(x0, model_, model_->create_W_op(), model_->get_W_factory(),
                                              noPrecOp, noPrecFactory));
}

NewtonResult NewtonSolver::solve(Vector& u) {
  return withGraphUpdates(u, [this](Vector& v) { return solveOnCurrentGraph(v); });
}

NewtonResult NewtonSolver::relax(Vector& u, const RelaxationSettings& settings) {
  return withGraphUpdates(u, [&](Vector& v) { return relaxOnCurrentGraph(v, settings); });
}

NewtonResult NewtonSolver::withGraphUpdates(Vector& u, const std::function<NewtonResult(Vector&)>& attempt) {
  const auto t0 = std::chrono::steady_clock::now();
  const double eval0 = evaluationSeconds(model_->problem());
  // The interaction couplings of the graph must cover the pairs near the start state.
  if (model_->problem().updateInteractionGraph(u)) resetJacobian();
  NewtonResult result;
  int rebuilds = 0;
  for (int rebuild = 0;; ++rebuild) {
    model_->problem().clearGraphOutdated();
    result = attempt(u);
    result.graphRebuilds = rebuilds;
    if (result.converged || !model_->problem().graphOutdated() || rebuild == 2) break;
    // Pairs moved beyond the graph during the iteration: widen it around the
    // start and around the iterate where it happened, then redo the solve.
    model_->problem().updateInteractionGraph(u, true, 1.0 + rebuild);
    model_->problem().updateInteractionGraph(*lastIterate_, true, 1.0 + rebuild);
    resetJacobian();
    ++rebuilds;
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  result.evaluationSeconds = evaluationSeconds(model_->problem()) - eval0;
  return result;
}

NewtonResult NewtonSolver::solveOnCurrentGraph(Vector& u) {
  return runNox(group_, *noxParams_, settings_.maxIterations, u);
}

NewtonResult NewtonSolver::relaxOnCurrentGraph(Vector& u, const RelaxationSettings& settings) {
  // Implicit Euler in pseudo-time on M x_dot = -f(x) (f is the gradient of
  // the potential energy): each iteration solves (M / delta + J) dx = -f.
  // A step is redone with a quarter of delta when
  //  - it is not a descent direction (f . dx >= 0): M / delta + J is then
  //    indefinite along the soft mode of the fold and the step would climb
  //    back towards the saddle;
  //  - its state cannot be evaluated (an inverted cell, touching surfaces);
  //  - |f| grows more than fourfold (the step went into the repulsive wall).
  // The largest dof change is capped at settings.maxIncrement. After an
  // accepted step delta grows by |f_old| / |f_new| times two (at most 10x,
  // at least 1x), so the relaxation ends in Newton steps. NOX's own
  // "Pseudo-Transient" solver has none of these safeguards: from the
  // jump-in fold of the benchmark its first Newton-like step inverts a cell.
  NewtonResult result;
  const int rank = model_->map()->getComm()->getRank();
  auto transient = Teuchos::rcp(new PseudoTransientModel(model_));
  auto uCopy = Teuchos::rcp(new Vector(u, Teuchos::Copy));
  const NOX::Thyra::Vector x0(Thyra::createVector(
      Teuchos::rcp_implicit_cast<Tpetra::Vector<Real, LocalIndex, GlobalIndex, assembly::Node>>(uCopy)));
  const Teuchos::RCP<::Thyra::PreconditionerBase<Real>> noPrecOp;
  const Teuchos::RCP<::Thyra::PreconditionerFactoryBase<Real>> noPrecFactory;
  Teuchos::RCP<NOX::Thyra::Group> group;
  Teuchos::ParameterList linearSolve("Linear Solver");
  linearSolve.set("Tolerance", settings_.linearTolerance);
  auto evaluateAt = [&](const NOX::Abstract::Vector& x) {
    group->setX(x);
    if (group->computeF() != NOX::Abstract::Group::Ok) throw NumericalError("residual evaluation failed");
    const Real n = residualNorm(*group, model_->residualWeights());
    if (!std::isfinite(n)) throw NumericalError("the residual is not finite");
    return n;
  };
  Real fNorm = 0.0;
  try {
    transient->setMassFromJacobian(u);
    group = Teuchos::rcp(new NOX::Thyra::Group(x0, transient, transient->create_W_op(), transient->get_W_factory(),
                                               noPrecOp, noPrecFactory));
    fNorm = evaluateAt(x0);
  } catch (const std::exception& e) {
    result.failure = std::string("pseudo-transient relaxation could not start: ") + e.what();
    return result;
  }
  Real delta = settings.initialStep;
  Real lowest = std::numeric_limits<Real>::infinity();
  auto record = [&](Real n) {
    if (n > 3.0 * lowest) result.fell = true;
    lowest = std::min(lowest, n);
    result.residualNorms.push_back(n);
    if (settings_.printIterations && rank == 0)
      std::printf("    relax %3d  |f| = %.6e  delta = %.3e\n", int(result.residualNorms.size()) - 1, n, delta);
  };
  record(fNorm);
  const Real tolerance = settings_.tolerance();
  while (fNorm > tolerance) {
    if (result.iterations >= settings.maxIterations) {
      result.failure = "no equilibrium after " + std::to_string(result.iterations) + " relaxation iterations (|f| = " +
                       std::to_string(fNorm) + ")";
      return result;
    }
    ++result.iterations;
    const auto xOld = group->getX().clone(NOX::DeepCopy);
    const auto fOld = group->getF().clone(NOX::DeepCopy);
    std::string rejection;
    try {
      auto& in = group->getNonconstInArgs();
      in.set_alpha(delta >= settings.newtonStep ? 0.0 : 1.0 / delta);
      in.set_beta(1.0);
      if (group->computeJacobian() != NOX::Abstract::Group::Ok ||
          group->computeNewton(linearSolve) != NOX::Abstract::Group::Ok)
        throw NumericalError("linear solve failed");
      NOX::SolverStats stats;
      group->logLastLinearSolveStats(stats);
      linearSolves_.solves += 1;
      linearSolves_.iterations += stats.linearSolve.lastLinearSolve_NumIterations;
      auto dx = group->getNewton().clone(NOX::DeepCopy);
      if (dx->innerProduct(*fOld) >= 0.0) {
        rejection = "no descent direction";
      } else {
        const Real largest = dx->norm(NOX::Abstract::Vector::MaxNorm);
        if (settings.maxIncrement > 0.0 && largest > settings.maxIncrement) dx->scale(settings.maxIncrement / largest);
        auto x = xOld->clone(NOX::DeepCopy);
        x->update(1.0, *dx, 1.0);
        const Real fNew = evaluateAt(*x);
        if (fNew > 4.0 * fNorm && fNew > tolerance) {
          rejection = "|f| grew from " + std::to_string(fNorm) + " to " + std::to_string(fNew);
        } else {
          delta *= std::clamp(2.0 * fNorm / fNew, 1.0, 10.0);
          fNorm = fNew;
          record(fNorm);
          continue;
        }
      }
    } catch (const std::exception& e) {
      if (model_->problem().graphOutdated()) {
        lastIterate_ = tpetraCopy(group->getX());
        result.failure = e.what();
        return result;
      }
      rejection = e.what();
    }
    delta *= 0.25;
    if (delta < settings.minStep) {
      result.failure = "pseudo-time step below its minimum: " + rejection;
      return result;
    }
    try {
      fNorm = evaluateAt(*xOld);
    } catch (const std::exception& e) {
      result.failure = e.what();
      return result;
    }
  }
  result.converged = true;
  u.assign(*tpetraCopy(group->getX()));
  return result;
}

NewtonResult NewtonSolver::runNox(const Teuchos::RCP<NOX::Thyra::Group>& group, const Teuchos::ParameterList& params,
                                  int maxIterations, Vector& u) {
  NewtonResult result;
  auto uCopy = Teuchos::rcp(new Vector(u, Teuchos::Copy));
  group->setX(NOX::Thyra::Vector(Thyra::createVector(
      Teuchos::rcp_implicit_cast<Tpetra::Vector<Real, LocalIndex, GlobalIndex, assembly::Node>>(uCopy))));

  auto solverParams = Teuchos::rcp(new Teuchos::ParameterList(params));
  auto recorder = Teuchos::rcp(
      new ResidualRecorder(result.residualNorms, settings_.printIterations, model_->map()->getComm()->getRank(),
                           model_->residualWeights()));
  solverParams->sublist("Solver Options").set("Observer", Teuchos::rcp_implicit_cast<NOX::Observer>(recorder));
  try {
    auto solver = NOX::Solver::buildSolver(group, convergenceTests(settings_.tolerance(), maxIterations, model_->residualWeights()), solverParams);
    const auto status = solver->solve();
    result.iterations = solver->getNumIterations();
    if (const auto stats = solver->getSolverStatistics()) {
      linearSolves_.solves += stats->linearSolve.lastNonlinearSolve_NumLinearSolves;
      linearSolves_.iterations += stats->linearSolve.lastNonlinearSolve_NumLinearIterations;
    }
    if (status == NOX::StatusTest::Converged) {
      result.converged = true;
      u.assign(*tpetraCopy(solver->getSolutionGroup().getX()));
    } else {
      const int n = result.iterations;
      const Real last = result.residualNorms.empty() ? 0.0 : result.residualNorms.back();
      result.failure = n >= maxIterations   ? "no convergence in " + std::to_string(n) + " iterations"
                       : std::isfinite(last) ? "no progress in " + std::to_string(n) + " iterations (|f| = " +
                                                   std::to_string(last) + ")"
                                             : "non-finite residual or failed iterate";
      if (!recorder->linearFailure().empty()) result.failure += "; " + recorder->linearFailure();
    }
  } catch (const std::exception& e) {
    // Inverted cells, touching surfaces, entries outside the graph, linear
    // solver breakdowns: a failed solve, not a crash.
    result.failure = e.what();
    if (model_->problem().graphOutdated()) lastIterate_ = tpetraCopy(group->getX());
  } catch (const char* e) {  // some NOX failures throw a bare string
    result.failure = std::string("NOX: ") + e;
  }
  return result;
}

}  // namespace cgcm::solver
