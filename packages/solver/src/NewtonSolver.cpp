#include "cgcm/solver/NewtonSolver.hpp"

#include <NOX_Observer.hpp>
#include <NOX_Solver_Factory.H>
#include <NOX_Solver_Generic.H>
#include <NOX_StatusTest_Combo.H>
#include <NOX_StatusTest_FiniteValue.H>
#include <NOX_StatusTest_MaxIters.H>
#include <NOX_StatusTest_NormF.H>
#include <NOX_Thyra.H>
#include <Teuchos_StandardParameterEntryValidators.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>

#include <Thyra_LinearOpWithSolveFactoryHelpers.hpp>
#include <Thyra_TpetraLinearOp.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "cgcm/core/Error.hpp"

namespace cgcm::solver {

namespace {

using Extract = Thyra::TpetraOperatorVectorExtraction<Real, LocalIndex, GlobalIndex, assembly::Node>;

// Records ||f|| after every Newton iteration.
class ResidualRecorder : public NOX::Observer {
 public:
  explicit ResidualRecorder(std::vector<Real>& norms, bool print, int rank)
      : norms_(norms), print_(print), rank_(rank) {}
  void runPreSolve(const NOX::Solver::Generic& s) override { record(s); }
  void runPostIterate(const NOX::Solver::Generic& s) override { record(s); }

 private:
  void record(const NOX::Solver::Generic& s) {
    const Real n = s.getSolutionGroup().getNormF();
    norms_.push_back(n);
    if (print_ && rank_ == 0) std::printf("    newton %2d  |f| = %.6e\n", int(norms_.size()) - 1, n);
  }
  std::vector<Real>& norms_;
  bool print_;
  int rank_;
};

double evaluationSeconds(const assembly::Assembler& a) {
  return a.timings().residual + a.timings().jacobian + a.timings().interaction;
}

// Converged when Newton is caught in a cycle below `tolerance`: the last
// four norms alternate between two values (equal to 1 %) and the last update
// is small (below `updateTolerance` in every dof). Method 3 on piecewise-
// linear surfaces has a residual that jumps where a closest point crosses a
// concave corner of the other surface (its direction turns by the corner
// angle); a state next to such a switch sends Newton back and forth between
// its two sides. Near a fold, where no equilibrium is close, the norms wander
// instead and the state is not accepted.
class StallTest : public NOX::StatusTest::Generic {
 public:
  StallTest(Real tolerance, Real updateTolerance) : tolerance_(tolerance), updateTolerance_(updateTolerance) {}
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic& s, NOX::StatusTest::CheckType) override {
    status_ = NOX::StatusTest::Unconverged;
    if (s.getNumIterations() == 0) history_.clear();
    const Real now = s.getSolutionGroup().getNormF();
    history_.push_back(now);
    const std::size_t n = history_.size();
    if (n >= 4 && now <= tolerance_) {
      auto same = [](Real a, Real b) { return std::abs(a - b) <= 0.01 * std::max(a, b); };
      if (same(now, history_[n - 3]) && same(history_[n - 2], history_[n - 4])) {
        auto dx = s.getSolutionGroup().getX().clone(NOX::ShapeCopy);
        dx->update(1.0, s.getSolutionGroup().getX(), -1.0, s.getPreviousSolutionGroup().getX(), 0.0);
        if (dx->norm(NOX::Abstract::Vector::MaxNorm) <= updateTolerance_) status_ = NOX::StatusTest::Converged;
      }
    }
    return status_;
  }
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream& print(std::ostream& o, int indent) const override {
    for (int i = 0; i < indent; ++i) o << ' ';
    return o << status_ << "Cycle below " << tolerance_ << "\n";
  }

 private:
  Real tolerance_, updateTolerance_;
  std::vector<Real> history_;
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unconverged;
};

}  // namespace

Teuchos::RCP<const Teuchos::ParameterList> NewtonSettings::validParameters() {
  static Teuchos::RCP<Teuchos::ParameterList> valid;
  if (!valid.is_null()) return valid;
  valid = Teuchos::rcp(new Teuchos::ParameterList("Newton"));
  valid->set("Line Search", "full step", "full step: plain Newton; backtrack: halve the step until |f| decreases",
             Teuchos::rcp(new Teuchos::StringValidator(Teuchos::tuple<std::string>("full step", "backtrack"))));
  auto positive = Teuchos::rcp(new Teuchos::EnhancedNumberValidator<double>());
  positive->setMin(0.0);
  valid->set("Relative Tolerance", 1e-10, "converged when |f| <= this * |f| at the start of the load step",
             positive);
  valid->set("Absolute Tolerance", 1e-12, "or when |f| <= this (force units)", positive);
  auto iters = Teuchos::rcp(new Teuchos::EnhancedNumberValidator<int>());
  iters->setMin(1);
  valid->set("Max Iterations", 25, "Newton iterations before the load step is cut back", iters);
  valid->set("Print Iterations", false, "print |f| after every Newton iteration");
  valid->set("Stall Tolerance", 2e-3,
             "contact problems: accept a state where Newton cycles between two values of |f| (equal to 1 % over "
             "four iterations, last update below r0/10) below this fraction of the adhesion force scale 2 pi w R. "
             "The residual of Method 3 jumps where closest points cross concave corners of the discretised "
             "surface, and Newton can alternate across such a switch. Such states are marked in the load curve's "
             "stalled column, with their |f| in the residual column; 0 disables",
             positive);
  return valid;
}

NewtonSettings NewtonSettings::fromParameters(const Teuchos::ParameterList& p) {
  NewtonSettings s;
  s.lineSearch = p.get<std::string>("Line Search") == "backtrack" ? LineSearch::Backtrack : LineSearch::FullStep;
  s.relativeTolerance = p.get<double>("Relative Tolerance");
  s.absoluteTolerance = p.get<double>("Absolute Tolerance");
  s.maxIterations = p.get<int>("Max Iterations");
  s.printIterations = p.get<bool>("Print Iterations");
  s.relativeStallTolerance = p.get<double>("Stall Tolerance");
  return s;
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
  const auto t0 = std::chrono::steady_clock::now();
  const double eval0 = evaluationSeconds(model_->assembler());
  // The interaction couplings of the graph must cover the pairs near the start state.
  if (model_->assembler().updateInteractionGraph(u)) resetJacobian();
  NewtonResult result;
  int rebuilds = 0;
  for (int rebuild = 0;; ++rebuild) {
    result = solveOnCurrentGraph(u);
    result.graphRebuilds = rebuilds;
    if (!result.graphOutdated || rebuild == 2) break;
    // Pairs moved beyond the graph during the iteration: widen it around the
    // start and around the iterate where it happened, then redo the solve.
    Vector iterate(u.getMap());
    iterate.assign(*lastIterate_);
    model_->assembler().updateInteractionGraph(u, true, 1.0 + rebuild);
    model_->assembler().updateInteractionGraph(iterate, true, 1.0 + rebuild);
    resetJacobian();
    ++rebuilds;
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  result.evaluationSeconds = evaluationSeconds(model_->assembler()) - eval0;
  return result;
}

NewtonResult NewtonSolver::solveOnCurrentGraph(Vector& u) {
  NewtonResult result;

  auto uCopy = Teuchos::rcp(new Vector(u, Teuchos::Copy));
  auto uThyra = Thyra::createVector(Teuchos::rcp_implicit_cast<Tpetra::Vector<Real, LocalIndex, GlobalIndex, assembly::Node>>(uCopy));
  group_->setX(NOX::Thyra::Vector(uThyra));

  using namespace NOX::StatusTest;
  auto converged = Teuchos::rcp(new Combo(Combo::OR));
  converged->addStatusTest(Teuchos::rcp(new NormF(*group_, settings_.relativeTolerance)));
  converged->addStatusTest(Teuchos::rcp(new NormF(settings_.absoluteTolerance)));
  Teuchos::RCP<StallTest> stall;
  if (settings_.stallTolerance > 0.0) {
    stall = Teuchos::rcp(new StallTest(settings_.stallTolerance, settings_.stallUpdateTolerance));
    converged->addStatusTest(stall);
  }
  auto tests = Teuchos::rcp(new Combo(Combo::OR));
  tests->addStatusTest(Teuchos::rcp(new FiniteValue));
  tests->addStatusTest(converged);
  tests->addStatusTest(Teuchos::rcp(new MaxIters(settings_.maxIterations)));

  auto params = Teuchos::rcp(new Teuchos::ParameterList(*noxParams_));
  Teuchos::RCP<NOX::Observer> recorder = Teuchos::rcp(
      new ResidualRecorder(result.residualNorms, settings_.printIterations, model_->map()->getComm()->getRank()));
  params->sublist("Solver Options").set("Observer", recorder);

  try {
    auto solver = NOX::Solver::buildSolver(group_, tests, params);
    const auto status = solver->solve();
    result.iterations = solver->getNumIterations();
    if (status == Converged && !model_->lastEvaluationInverted()) {
      result.converged = true;
      result.stalled = !stall.is_null() && stall->getStatus() == Converged &&
                       solver->getSolutionGroup().getNormF() > settings_.absoluteTolerance;
      const auto& x = dynamic_cast<const NOX::Thyra::Vector&>(solver->getSolutionGroup().getX());
      u.assign(*Extract::getConstTpetraVector(x.getThyraRCPVector()));
    } else if (status == Converged) {
      result.failure = "inverted element at the last iterate";
    } else {
      const int n = result.iterations;
      result.failure = n >= settings_.maxIterations ? "no convergence in " + std::to_string(n) + " iterations"
                                                    : "non-finite or failed iterate";
    }
  } catch (const InvertedElementError& e) {
    result.failure = e.what();
  } catch (const assembly::GraphOutdatedError& e) {
    result.failure = e.what();
    result.graphOutdated = true;
    lastIterate_ = Teuchos::rcp(new Vector(u.getMap()));
    const auto& x = dynamic_cast<const NOX::Thyra::Vector&>(group_->getX());
    lastIterate_->assign(*Extract::getConstTpetraVector(x.getThyraRCPVector()));
  } catch (const NumericalError& e) {
    result.failure = e.what();
  } catch (const std::exception& e) {
    // Linear solver breakdowns and line-search failures end up here: a failed step, not a crash.
    result.failure = std::string("solver failure: ") + e.what();
  }
  return result;
}

NewtonResult NewtonSolver::solvePseudoTransient(Vector& u, Real maxMove, Real initialTimeStep, int maxSteps) {
  const auto t0 = std::chrono::steady_clock::now();
  const double eval0 = evaluationSeconds(model_->assembler());
  auto& assembler = model_->assembler();
  const auto& dirichlet = model_->dirichlet();
  const Real p = model_->load();
  const auto map = model_->map();
  Vector x(map), f(map), dx(map), minusF(map), diag(map), xPrevious(map);
  x.assign(u);
  xPrevious.assign(u);
  int rejected = 0;
  NewtonResult result;
  Real dt = initialTimeStep, fPrevious = -1.0, f0 = -1.0;
  auto space = Thyra::createVectorSpace<Real>(map);
  Teuchos::RCP<Matrix> J;
  for (int step = 0; step < maxSteps; ++step) {
    // a new matrix only when the interaction couplings outgrew the graph
    if (assembler.updateInteractionGraph(x, true) || J.is_null()) J = assembler.createMatrix();
    try {
      assembler.evaluate(x, f, J.get());
    } catch (const NumericalError& e) {
      // the last update went too far (inverted element, bodies touching): halve it
      if (++rejected > 20 || step == 0) {
        result.failure = std::string("pseudo-transient: ") + e.what();
        break;
      }
      dx.scale(-0.5);
      x.update(1.0, dx, 1.0);
      dt *= 0.25;
      continue;
    }
    dirichlet.applyToResidual(x, p, f);
    dirichlet.applyToJacobian(*J);
    const Real fn = f.norm2();
    if (f0 < 0.0) f0 = fn;
    result.residualNorms.push_back(fn);
    if (settings_.printIterations && map->getComm()->getRank() == 0)
      std::printf("    pseudo-transient %3d  dt = %.3e  |f| = %.6e\n", step, dt, fn);
    if (fn <= std::max(settings_.absoluteTolerance, 1e-6 * f0) && dt > 1e6) break;  // Newton finishes
    // switched evolution relaxation, with a steady growth so the state leaves a fold quickly
    if (fPrevious > 0.0) dt = std::min(1e12, 1.25 * dt * std::clamp(fPrevious / fn, 0.5, 4.0));
    fPrevious = fn;
    // J + D/dt with D = |diag J| (unit on constrained rows)
    J->getLocalDiagCopy(diag);
    J->beginModify();
    {
      auto lcl = J->getLocalMatrixHost();
      auto d = diag.getLocalViewHost(Tpetra::Access::ReadOnly);
      const auto& rowMap = *J->getRowMap();
      const auto& colMap = *J->getColMap();
      for (LocalIndex r = 0; r < LocalIndex(lcl.numRows()); ++r) {
        const LocalIndex dc = colMap.getLocalElement(rowMap.getGlobalElement(r));
        auto row = lcl.row(r);
        for (LocalIndex k = 0; k < row.length; ++k)
          if (row.colidx(k) == dc) row.value(k) += std::abs(d(r, 0)) / dt;
      }
    }
    J->endModify();
    Teuchos::RCP<const ::Thyra::LinearOpBase<Real>> op = ::Thyra::tpetraLinearOp<Real, LocalIndex, GlobalIndex, assembly::Node>(
        space, space, Teuchos::rcp_implicit_cast<assembly::Operator>(J));
    auto lows = ::Thyra::linearOpWithSolve(*model_->get_W_factory(), op);
    minusF.update(-1.0, f, 0.0);
    dx.putScalar(0.0);
    auto b = ::Thyra::createConstVector<Real, LocalIndex, GlobalIndex, assembly::Node>(Teuchos::rcpFromRef(minusF), space);
    auto s = ::Thyra::createVector<Real, LocalIndex, GlobalIndex, assembly::Node>(Teuchos::rcpFromRef(dx), space);
    lows->solve(::Thyra::NOTRANS, *b, s.ptr());
    const Real largest = dx.normInf();
    if (largest > maxMove) dx.scale(maxMove / largest);
    x.update(1.0, dx, 1.0);
    ++result.iterations;
  }
  if (result.failure.empty()) {
    const int pseudoSteps = result.iterations;
    NewtonResult newton = solve(x);
    newton.iterations += pseudoSteps;
    newton.residualNorms.insert(newton.residualNorms.begin(), result.residualNorms.begin(),
                                result.residualNorms.end());
    result = newton;
    if (result.converged) u.assign(x);
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  result.evaluationSeconds = evaluationSeconds(model_->assembler()) - eval0;
  return result;
}

}  // namespace cgcm::solver
