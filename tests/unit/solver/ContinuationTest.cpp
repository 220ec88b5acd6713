// Arc-length continuation (LOCA) with fold location and stability, on a
// spring chain against a Lennard-Jones wall whose folds are known in closed
// form (ChainModel.hpp), and the failure handling of continuation and load
// stepping.
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <cmath>

#include "ChainModel.hpp"
#include "TestSystem.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/io/Deck.hpp"
#include "cgcm/solver/Continuation.hpp"
#include "cgcm/solver/LinearSolver.hpp"
#include "cgcm/solver/LoadStepper.hpp"

namespace cgcm {
namespace {

using test::ChainModel;
using test::LennardJonesWall;

Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> autoSolver() {
  Teuchos::ParameterList settings("Linear Solver");
  settings.setParameters(*solver::linearSolverValidParameters());
  settings.set("Tolerance", 1e-13);
  return solver::buildLinearSolver(settings, Tpetra::getDefaultComm()->getSize(), 1);
}

struct Chain {
  LennardJonesWall wall;
  Teuchos::RCP<ChainModel> model;
  solver::NewtonSettings newton;
  Chain() {
    model = Teuchos::rcp(new ChainModel(Tpetra::getDefaultComm(), 10, 10.0, 1.0, wall, autoSolver()));
    newton.residualTolerance = 1e-11;
    newton.forceScale = 1.0;
    newton.maxIterations = 10;
  }
  // The tip gap of the equilibrium at lambda on the branch that starts at g from above.
  double gapAt(double lambda, double lo, double hi) const {
    std::uintmax_t it = 200;
    const auto r = boost::math::tools::toms748_solve([&](double g) { return model->lambdaOf(g) - lambda; }, lo, hi,
                                                     boost::math::tools::eps_tolerance<double>(50), it);
    return 0.5 * (r.first + r.second);
  }
  // The two folds: phi''(g) = -K, below and above the minimum of phi'' at g^6 = 3.25.
  std::pair<double, double> foldGaps() const {
    const double gm = std::pow(3.25, 1.0 / 6.0);
    auto h = [&](double g) { return wall.ddphi(g) + model->K(); };
    std::uintmax_t it = 200;
    const auto a = boost::math::tools::toms748_solve(h, 1.0, gm, boost::math::tools::eps_tolerance<double>(50), it);
    it = 200;
    const auto b = boost::math::tools::toms748_solve(h, gm, 3.0, boost::math::tools::eps_tolerance<double>(50), it);
    return {0.5 * (a.first + a.second), 0.5 * (b.first + b.second)};
  }
};

TEST(Continuation, LocatesTheFoldsOfASpringChainAgainstALennardJonesWall) {
  Chain c;
  const auto [g1, g2] = c.foldGaps();
  ASSERT_LT(c.model->lambdaOf(g2), c.model->lambdaOf(g1));  // a loop: jump-in at g2, pull-off at g1

  solver::Continuation continuation(c.model, c.newton, Teuchos::ParameterList("LOCA"));
  const double lambdaFar = 5.0, lambdaNear = 0.98;  // the loop spans lambda = 1.98 .. 3.80
  const double gFar = c.gapAt(lambdaFar, g2, 10.0);
  c.model->setParameter(0, lambdaFar);
  auto x = c.model->stateOf(gFar);

  for (int pass = 0; pass < 2; ++pass) {
    SCOPED_TRACE(pass == 0 ? "approach" : "retraction");
    solver::ContinuationSegment seg;
    seg.target = pass == 0 ? lambdaNear : lambdaFar;
    seg.direction = pass == 0 ? -1.0 : 1.0;
    seg.bound = pass == 0 ? 10.0 : -10.0;
    seg.initialStep = 0.05;
    int checked = 0, unstable = 0;
    const auto r = continuation.run(*x, seg, [&](const solver::PathPoint& pt) {
      if (pt.fold) return;
      // stability from the path against the sign of det J at the point
      const double g = c.model->tipGap(*pt.x);
      EXPECT_EQ(pt.stable, c.model->jacobianDeterminant(g) > 0.0) << "lambda = " << pt.p[0] << ", g = " << g;
      EXPECT_NEAR(pt.p[0], c.model->lambdaOf(g), 1e-9);  // an equilibrium
      unstable += pt.stable ? 0 : 1;
      ++checked;
    });
    ASSERT_TRUE(r.reached) << r.failure;
    EXPECT_GT(checked, 10);
    EXPECT_GT(unstable, 2);
    ASSERT_EQ(r.folds.size(), 2u);
    // approach: first the jump-in fold g2, then g1; retraction the other way round
    const double first = pass == 0 ? g2 : g1, second = pass == 0 ? g1 : g2;
    EXPECT_NEAR(c.model->tipGap(*r.folds[0].x), first, 1e-6);
    EXPECT_NEAR(c.model->tipGap(*r.folds[1].x), second, 1e-6);
    // the fold's lambda to solver tolerance (quadratic in the gap error)
    EXPECT_NEAR(r.folds[0].p[0], c.model->lambdaOf(first), 1e-10);
    EXPECT_NEAR(r.folds[1].p[0], c.model->lambdaOf(second), 1e-10);
    EXPECT_LT(std::abs(r.folds[0].dpds), 1e-4);
    EXPECT_TRUE(r.last.stable);
    EXPECT_DOUBLE_EQ(r.last.p[0], seg.target);
    x = r.last.x;
    c.model->setParameter(0, seg.target);
  }
  std::printf("chain folds: lambda = %.12f (g = %.9f), %.12f (g = %.9f); pull-off tension %.9f\n",
              c.model->lambdaOf(g2), g2, c.model->lambdaOf(g1), g1, c.wall.dphi(g1));
}

TEST(Continuation, AnEvaluationErrorInTheCorrectorCutsTheStepBack) {
  Chain c;
  int thrown = 0;
  c.model->beforeEvaluation = [&](double lambda) {
    if (lambda < 2.0 && thrown == 0) {
      ++thrown;
      throw NumericalError("injected evaluation failure");
    }
  };
  solver::Continuation continuation(c.model, c.newton, Teuchos::ParameterList("LOCA"));
  c.model->setParameter(0, 3.0);
  auto x = c.model->stateOf(c.gapAt(3.0, 1.5, 10.0));
  solver::ContinuationSegment seg;
  seg.target = 1.5;
  seg.direction = -1.0;
  seg.bound = 10.0;
  seg.initialStep = 0.2;
  const auto r = continuation.run(*x, seg, [](const solver::PathPoint&) {});
  ASSERT_TRUE(r.reached) << r.failure;
  EXPECT_EQ(thrown, 1);
  EXPECT_GE(r.failedSteps, 1);
}

TEST(Continuation, LocaParametersItDoesNotReadAreRejected) {
  Chain c;
  c.model->setParameter(0, 3.0);
  auto x = c.model->stateOf(c.gapAt(3.0, 1.5, 10.0));
  Teuchos::ParameterList loca("LOCA");
  loca.sublist("Stepper").set("Max Stepz", 10);
  loca.sublist("Step Size").set("Max Step Size", 0.5);  // a real one
  // read before, as the deck's echo to parameters.xml reads every entry: still told apart
  EXPECT_EQ(loca.sublist("Stepper").get<int>("Max Stepz"), 10);
  ASSERT_TRUE(loca.sublist("Stepper").getEntry("Max Stepz").isUsed());
  solver::Continuation continuation(c.model, c.newton, loca);
  try {
    continuation.validate(*x);
    ADD_FAILURE() << "no error for LOCA/Stepper/Max Stepz";
  } catch (const InputError& e) {
    const std::string listed = std::string(e.what()).substr(0, std::string(e.what()).find(": not a parameter"));
    EXPECT_EQ(listed, "LOCA/Stepper/Max Stepz") << e.what();
  }
  Teuchos::ParameterList owned("LOCA");
  owned.sublist("Stepper").set("Initial Value", 1.0);
  EXPECT_THROW(solver::Continuation(c.model, c.newton, owned), InputError);
}

// A block whose evaluation fails once inside a window of u.
class FaultyModel : public solver::ModelEvaluator {
 public:
  using ModelEvaluator::ModelEvaluator;
  mutable int thrown = 0;

 protected:
  void evalModelImpl(const Thyra::ModelEvaluatorBase::InArgs<Real>& in,
                     const Thyra::ModelEvaluatorBase::OutArgs<Real>& out) const override {
    const double u = in.get_p(0).is_null() ? displacement() : Thyra::get_ele(*in.get_p(0), 0);
    if (u < -0.09 && u > -0.2 && thrown == 0) {
      ++thrown;
      throw NumericalError("injected evaluation failure");
    }
    ModelEvaluator::evalModelImpl(in, out);
  }
};

TEST(LoadStepping, AnEvaluationErrorCutsTheStepBack) {
  auto d = Teuchos::rcp(new Teuchos::ParameterList("cgcm"));
  io::applyOverrides(*d, *test::deckParameters(),
                     {"Geometry/Type=block", "Problem/Formulation=plane strain", "Loading/Approach Path={0, -0.2}",
                      "Loading/Initial Increment=0.1", "Loading/Max Increment=0.1"});
  io::validateDeck(*d, *test::deckParameters());
  const auto setup = test::setupOf(*d);
  auto comm = Tpetra::getDefaultComm();
  auto disc = solver::discretize(comm, setup, autoSolver());
  auto model = Teuchos::rcp(new FaultyModel(disc.problem, disc.dirichlet, autoSolver()));
  solver::NewtonSettings settings;
  settings.forceScale = setup.forceScale;
  solver::NewtonSolver newton(model, settings);
  solver::LoadStepper stepper(model, newton, solver::LoadPathSettings::fromParameters(d->sublist("Loading")));
  assembly::Vector u(model->map());
  std::vector<solver::StepInfo> steps;
  stepper.run(u, [&](const solver::StepInfo& info, const assembly::Vector&) { steps.push_back(info); });
  EXPECT_EQ(model->thrown, 1);
  ASSERT_GE(steps.size(), 3u);
  int cutbacks = 0;
  for (const auto& s : steps) cutbacks += s.cutbacks;
  EXPECT_GE(cutbacks, 1);
  EXPECT_DOUBLE_EQ(steps.back().displacement, -0.2);
  for (const auto& s : steps) EXPECT_LE(s.newton.residualNorms.back(), settings.tolerance());
}

}  // namespace
}  // namespace cgcm
