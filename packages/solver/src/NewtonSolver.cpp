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

#include <chrono>
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

double evaluationSeconds(const assembly::Assembler& a) { return a.timings().residual + a.timings().jacobian; }

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
  return valid;
}

NewtonSettings NewtonSettings::fromParameters(const Teuchos::ParameterList& p) {
  NewtonSettings s;
  s.lineSearch = p.get<std::string>("Line Search") == "backtrack" ? LineSearch::Backtrack : LineSearch::FullStep;
  s.relativeTolerance = p.get<double>("Relative Tolerance");
  s.absoluteTolerance = p.get<double>("Absolute Tolerance");
  s.maxIterations = p.get<int>("Max Iterations");
  s.printIterations = p.get<bool>("Print Iterations");
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
  NewtonResult result;
  const auto t0 = std::chrono::steady_clock::now();
  const double eval0 = evaluationSeconds(model_->assembler());

  auto uCopy = Teuchos::rcp(new Vector(u, Teuchos::Copy));
  auto uThyra = Thyra::createVector(Teuchos::rcp_implicit_cast<Tpetra::Vector<Real, LocalIndex, GlobalIndex, assembly::Node>>(uCopy));
  group_->setX(NOX::Thyra::Vector(uThyra));

  using namespace NOX::StatusTest;
  auto converged = Teuchos::rcp(new Combo(Combo::OR));
  converged->addStatusTest(Teuchos::rcp(new NormF(*group_, settings_.relativeTolerance)));
  converged->addStatusTest(Teuchos::rcp(new NormF(settings_.absoluteTolerance)));
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
  } catch (const NumericalError& e) {
    result.failure = e.what();
  } catch (const std::exception& e) {
    // Linear solver breakdowns and line-search failures end up here: a failed step, not a crash.
    result.failure = std::string("solver failure: ") + e.what();
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  result.evaluationSeconds = evaluationSeconds(model_->assembler()) - eval0;
  return result;
}

}  // namespace cgcm::solver
