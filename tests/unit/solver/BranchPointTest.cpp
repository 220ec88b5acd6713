// Branch points and fold curves: the pitchfork of a tilting bar between two
// Lennard-Jones contacts (TiltingBarModel.hpp), whose branch point and tilted
// branch are known in closed form, found by continuation with the tangent's
// spectrum, and the tilted branch followed after switching to it; the fold of
// a spring chain against a Lennard-Jones wall (ChainModel.hpp) followed in two
// parameters (LOCA's turning-point continuation) to the cusp where it ends.
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <cmath>
#include <cstdio>

#include "ChainModel.hpp"
#include "TiltingBarModel.hpp"
#include "cgcm/solver/Continuation.hpp"
#include "cgcm/solver/LinearSolver.hpp"

namespace cgcm {
namespace {

using test::LennardJonesWall;
using test::TiltingBarModel;

struct Bar {
  LennardJonesWall wall;
  double k = 10.0, kt = 4.0, l = 1.0;
  Teuchos::RCP<TiltingBarModel> model;
  solver::NewtonSettings newton;
  Bar() {
    Teuchos::ParameterList settings("Linear Solver");
    settings.setParameters(*solver::linearSolverValidParameters());
    model = Teuchos::rcp(new TiltingBarModel(Tpetra::getDefaultComm(), k, kt, l, wall,
                                             solver::buildLinearSolver(settings, Tpetra::getDefaultComm()->getSize(), 1)));
    newton.residualTolerance = 1e-12;
    newton.forceScale = 1.0;
    newton.maxIterations = 12;
  }
  // The root of h in [lo, hi] to round-off.
  template <class F>
  static double root(F h, double lo, double hi) {
    std::uintmax_t it = 200;
    const auto r = boost::math::tools::toms748_solve(h, lo, hi, boost::math::tools::eps_tolerance<double>(52), it);
    return 0.5 * (r.first + r.second);
  }
  // The branch point: the level branch's tilt stiffness kt + 2 l^2 phi''(z) vanishes (above the minimum of phi'').
  double branchHeight() const {
    return root([&](double z) { return kt + 2 * l * l * wall.ddphi(z); }, std::pow(3.25, 1.0 / 6.0), 3.0);
  }
  // The tilted branch at tilt theta: the height from the tilt equation, near z.
  double tiltedHeight(double theta, double z) const {
    return root([&](double h) { return model->tiltResidual(h, theta); }, z - 0.05, z + 0.05);
  }
};

TEST(BranchPoint, APitchforkOfATiltingBarIsLocatedAndItsTiltedBranchFollowed) {
  Bar bar;
  const double zb = bar.branchHeight(), lambdaB = bar.model->levelLambda(zb);
  ASSERT_GT(bar.kt / (bar.l * bar.l), 0.0);
  ASSERT_LT(bar.kt / (bar.l * bar.l), bar.k);  // the branch point comes before the level branch's fold

  solver::Continuation continuation(bar.model, bar.newton, Teuchos::ParameterList("LOCA"));
  continuation.monitorStability(std::make_shared<solver::TangentSpectrum>(bar.model, 2));
  const double zStart = 3.0;
  auto x = bar.model->stateOf(zStart, 0.0);
  bar.model->setParameter(0, bar.model->levelLambda(zStart));

  // the level branch, approached from far, to between the branch point and the fold
  solver::ContinuationSegment level;
  level.target = 1.62;
  level.direction = -1.0;
  level.bound = 10.0;
  level.initialStep = 0.05;
  level.switchAmplitude = 0.05;
  int levelPoints = 0, unstable = 0;
  const auto r = continuation.run(*x, level, [&](const solver::PathPoint& pt) {
    const auto [z, theta] = bar.model->unknowns(*pt.x);
    EXPECT_LT(std::abs(theta), 1e-12);  // the corrector keeps the symmetry
    EXPECT_NEAR(pt.p[0], bar.model->levelLambda(z), 1e-10);
    if (pt.branchPoint) return;
    // stable while the tilt stiffness is positive; the parity of folds (there are none) misses it
    const bool stable = bar.kt + 2 * bar.l * bar.l * bar.wall.ddphi(z) > 0.0;
    EXPECT_EQ(pt.stable, stable) << "z = " << z;
    EXPECT_EQ(pt.negativeEigenvalues, stable ? 0 : 1) << "z = " << z;
    EXPECT_TRUE(pt.stableByFolds);
    unstable += stable ? 0 : 1;
    ++levelPoints;
  });
  ASSERT_TRUE(r.reached) << r.failure;
  EXPECT_TRUE(r.folds.empty());
  EXPECT_GT(levelPoints, 5);
  EXPECT_GE(unstable, 2);
  ASSERT_EQ(r.branchPoints.size(), 1u);
  const auto& bp = r.branchPoints[0];
  EXPECT_NEAR(bp.p[0], lambdaB, 1e-8);
  EXPECT_NEAR(bar.model->unknowns(*bp.x).first, zb, 1e-6);
  EXPECT_LT(std::abs(bp.eigenvalues[0]), 1e-8 * bar.k);
  const auto [modeZ, modeTheta] = bar.model->unknowns(*bp.critical);
  EXPECT_LT(std::abs(modeZ), 1e-6);  // the tilt
  EXPECT_DOUBLE_EQ(modeTheta, 1.0);

  // the point of the tilted branch at tilt amplitude 0.05, on the closed form
  ASSERT_EQ(r.otherBranches.size(), 1u) << (r.switchFailures.empty() ? "" : r.switchFailures[0]);
  const auto& first = r.otherBranches[0];
  const auto [z1, theta1] = bar.model->unknowns(*first.x);
  EXPECT_NEAR(theta1, 0.05, 1e-12);  // the mode (0, 1) to round-off: its component is theta
  const double z1Closed = bar.tiltedHeight(theta1, z1);
  EXPECT_NEAR(z1, z1Closed, 1e-10);
  EXPECT_NEAR(first.p[0], bar.model->lambdaAt(z1Closed, theta1), 1e-10);

  // follow the tilted branch away from the branch point: the parameter moves the way the switch took it
  bar.model->setParameter(0, first.p[0]);
  solver::ContinuationSegment tilted;
  tilted.direction = first.p[0] > lambdaB ? 1.0 : -1.0;
  tilted.target = lambdaB + tilted.direction * 0.05;
  tilted.bound = lambdaB - tilted.direction * 1.0;
  tilted.initialStep = 1e-3;
  int tiltedPoints = 0;
  double largestTilt = 0.0;
  const auto t = continuation.run(*first.x, tilted, [&](const solver::PathPoint& pt) {
    const auto [z, theta] = bar.model->unknowns(*pt.x);
    const double zClosed = bar.tiltedHeight(theta, z);
    EXPECT_NEAR(z, zClosed, 1e-10) << "theta = " << theta;
    EXPECT_NEAR(pt.p[0], bar.model->lambdaAt(zClosed, theta), 1e-10) << "theta = " << theta;
    largestTilt = std::max(largestTilt, std::abs(theta));
    ++tiltedPoints;
  });
  EXPECT_TRUE(t.reached) << t.failure;
  EXPECT_GT(tiltedPoints, 5);
  EXPECT_GT(largestTilt, 0.1);
  std::printf("tilting bar: branch point lambda = %.12f (closed form %.12f, difference %.1e), z = %.9f; tilted branch to lambda = %.6f, "
              "tilt %.4f, %d points, last point %s (%d negative eigenvalues)\n",
              bp.p[0], lambdaB, bp.p[0] - lambdaB, zb, t.last.p[0], largestTilt, tiltedPoints, t.last.stable ? "stable" : "unstable",
              t.last.negativeEigenvalues);
}

// The chain's folds in (lambda, eps): eps phi1''(g) = -K with phi = eps phi1, lambda = g + eps phi1'(g) / K,
// i.e. eps(g) = -K / phi1''(g), lambda(g) = g - phi1'(g) / phi1''(g). The jump-in and pull-off folds meet
// where eps(g) is smallest, at the cusp where the third derivative of phi1 vanishes: g^6 = 3.25 (s = 1).
// Below that eps the approach has no fold.
TEST(FoldCurve, TheChainsJumpInFoldIsFollowedInTheWallStrengthToItsCusp) {
  LennardJonesWall unit;  // phi1: eps = 1
  Teuchos::ParameterList settings("Linear Solver");
  settings.setParameters(*solver::linearSolverValidParameters());
  settings.set("Tolerance", 1e-13);
  auto model = Teuchos::rcp(new test::ChainModel(Tpetra::getDefaultComm(), 10, 10.0, 1.0, unit,
                                                 solver::buildLinearSolver(settings, Tpetra::getDefaultComm()->getSize(), 1)));
  solver::NewtonSettings newton;
  newton.residualTolerance = 1e-11;
  newton.forceScale = 1.0;
  newton.maxIterations = 10;
  const double K = model->K();
  auto epsOf = [&](double g) { return -K / unit.ddphi(g); };
  auto lambdaOf = [&](double g) { return g - unit.dphi(g) / unit.ddphi(g); };
  const double gCusp = std::pow(3.25, 1.0 / 6.0), epsCusp = epsOf(gCusp), lambdaCusp = lambdaOf(gCusp);

  // the approach at eps = 1 to its jump-in fold, located, with its critical mode (the null vector)
  solver::Continuation continuation(model, newton, Teuchos::ParameterList("LOCA"));
  continuation.monitorStability(std::make_shared<solver::TangentSpectrum>(model, 1));
  const double lambdaFar = 5.0;
  const double gFar = Bar::root([&](double g) { return model->lambdaOf(g) - lambdaFar; }, 3.0, 10.0);
  model->setParameter(0, lambdaFar);
  solver::ContinuationSegment approach;
  approach.target = 0.98;
  approach.direction = -1.0;
  approach.bound = 10.0;
  approach.initialStep = 0.05;
  approach.stopAtFold = true;
  const auto a = continuation.run(*model->stateOf(gFar), approach, [](const solver::PathPoint&) {});
  ASSERT_TRUE(a.stoppedAtFold) << a.failure;
  const auto& fold = a.folds.front();
  ASSERT_FALSE(fold.critical.is_null());

  // the fold followed as eps falls, lambda solved for with the null vector, to the cusp
  continuation.monitorStability(nullptr);
  for (std::size_t k = 0; k < fold.p.size(); ++k) model->setParameter(int(k), fold.p[k]);
  solver::ContinuationSegment curve;
  curve.parameter = 1;
  curve.foldParameter = 0;
  curve.nullVector = fold.critical;
  curve.target = 0.01;
  curve.direction = -1.0;
  curve.bound = 10.0;
  curve.initialStep = 0.02;
  curve.stopAtFold = true;  // the fold curve's extreme in eps
  int points = 0;
  const auto c = continuation.run(*fold.x, curve, [&](const solver::PathPoint& pt) {
    const double g = model->tipGap(*pt.x), lambda = pt.p[0], eps = pt.p[1];
    // a fold of the chain at (lambda, eps): on the closed-form curve
    EXPECT_NEAR(eps, epsOf(g), 1e-9) << "g = " << g;
    EXPECT_NEAR(lambda, lambdaOf(g), 1e-9) << "g = " << g;
    EXPECT_FALSE(pt.critical.is_null());
    ++points;
  });
  ASSERT_TRUE(c.stoppedAtFold) << c.failure;
  EXPECT_GE(points, 3);  // LOCA's steps on the extended system are long (5 or 6 points here): every one is checked
  const auto& cusp = c.folds.front();
  EXPECT_NEAR(cusp.p[1], epsCusp, 1e-8);
  EXPECT_NEAR(cusp.p[0], lambdaCusp, 1e-6);
  EXPECT_NEAR(model->tipGap(*cusp.x), gCusp, 1e-3);  // eps is flat in g at the cusp: g to the root of its error
  std::printf("chain fold curve: cusp eps = %.10f (closed form %.10f), lambda = %.8f (%.8f), %d points, "
              "%d Newton iterations\n", cusp.p[1], epsCusp, cusp.p[0], lambdaCusp, points, c.newtonIterations);
}

}  // namespace
}  // namespace cgcm
