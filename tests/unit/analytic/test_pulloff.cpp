// Pull-off points under load and displacement control.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "cgcm/analytic/MaugisDugdale.hpp"
#include "cgcm/analytic/PullOff.hpp"

namespace an = cgcm::analytic;
using cgcm::Real;

TEST(PullOff, Hertz) {
  const an::PullOff p = an::pullOff(an::ContactModel::hertz());
  EXPECT_FALSE(p.adhesive);
  EXPECT_EQ(p.loadControl.load, 0.0);
  EXPECT_EQ(p.loadControl.a, 0.0);
  EXPECT_EQ(p.displacementControl.load, 0.0);
}

TEST(PullOff, JkrClosedForm) {
  const an::ContactModel jkr = an::ContactModel::jkr();
  const an::PullOff p = an::pullOff(jkr);
  EXPECT_DOUBLE_EQ(p.loadControl.load, -1.5);
  EXPECT_DOUBLE_EQ(p.displacementControl.load, -5.0 / 6.0);
  // They are the curve's points, and the extrema: dP̄/dā = 0 resp. dδ̄/dā = 0.
  EXPECT_NEAR(jkr.at(p.loadControl.a).load, -1.5, 1e-14);
  EXPECT_NEAR(jkr.at(p.displacementControl.a).load, -5.0 / 6.0, 1e-14);
  EXPECT_NEAR(jkr.slopes(p.loadControl.a).dLoad, 0.0, 1e-14);
  EXPECT_NEAR(jkr.slopes(p.displacementControl.a).dApproach, 0.0, 1e-14);
  EXPECT_TRUE(p.displacementJump);
}

TEST(PullOff, Dmt) {
  const an::PullOff p = an::pullOff(an::ContactModel::dmt());
  EXPECT_EQ(p.loadControl.load, -2.0);
  EXPECT_EQ(p.displacementControl.load, -2.0);
  EXPECT_EQ(p.loadControl.a, 0.0);
  EXPECT_FALSE(p.displacementJump);
}

// λ → ∞: JKR's −3/2 (load) and −5/6 (displacement), to 1e-6 at λ = 1e3
// (measured gaps 1.6e-7 and 3.8e-8); radii to 1e-5.
TEST(PullOff, MaugisDugdaleTendsToJkr) {
  const an::PullOff p = an::pullOff(an::ContactModel::maugisDugdale(1e3));
  EXPECT_NEAR(p.loadControl.load, -1.5, 1e-6);
  EXPECT_NEAR(p.displacementControl.load, -5.0 / 6.0, 1e-6);
  EXPECT_NEAR(p.loadControl.a, std::cbrt(1.5), 1e-5);
  EXPECT_NEAR(p.displacementControl.a, std::cbrt(1.0 / 6.0), 1e-5);
  EXPECT_TRUE(p.displacementJump);
}

// λ → 0: DMT's −2 in both controls, to 1e-4 at λ = 1e-3 (measured
// −1.999946 and −1.999946).
TEST(PullOff, MaugisDugdaleTendsToDmt) {
  const an::PullOff p = an::pullOff(an::ContactModel::maugisDugdale(1e-3));
  EXPECT_NEAR(p.loadControl.load, -2.0, 1e-4);
  EXPECT_NEAR(p.displacementControl.load, -2.0, 1e-4);
  EXPECT_FALSE(p.displacementJump);
}

// The reference value of the theory sheet (about −1.60 at λ = 1), and that
// the points are extrema of the curve.
TEST(PullOff, MaugisDugdaleLambdaOne) {
  const an::ContactModel md = an::ContactModel::maugisDugdale(1.0);
  const an::PullOff p = an::pullOff(md);
  EXPECT_NEAR(p.loadControl.load, -1.6007, 5e-4);
  EXPECT_NEAR(md.slopes(p.loadControl.a).dLoad, 0.0, 1e-10);
  EXPECT_TRUE(p.displacementJump);
  EXPECT_NEAR(md.slopes(p.displacementControl.a).dApproach, 0.0, 1e-10);
  // The displacement-control point lies on the curve, at smaller ā and
  // with less tension than the load-control point.
  EXPECT_NEAR(md.at(p.displacementControl.a).load, p.displacementControl.load, 1e-13);
  EXPECT_LT(p.displacementControl.a, p.loadControl.a);
  EXPECT_GT(p.displacementControl.load, p.loadControl.load);
  // Nothing on the curve is more tensile than the load-control point.
  for (Real a = 0.01; a < 3; a += 0.01) EXPECT_GE(md.at(a).load, p.loadControl.load - 1e-12);
}

// The load-control pull-off force rises monotonically from −2 (DMT) to −3/2
// (JKR) with λ; so does the displacement-control one from −2 to −5/6.
TEST(PullOff, MonotoneInLambda) {
  Real previousLoad = -2.0;
  Real previousDisp = -2.0;
  for (int i = 0; i <= 60; ++i) {
    const Real lambda = 1e-3 * std::pow(1e6, i / 60.0);
    const an::PullOff p = an::pullOff(an::ContactModel::maugisDugdale(lambda));
    EXPECT_GT(p.loadControl.load, previousLoad) << "lambda " << lambda;
    EXPECT_LT(p.loadControl.load, -1.5) << "lambda " << lambda;
    EXPECT_GT(p.displacementControl.load, previousDisp) << "lambda " << lambda;
    EXPECT_LT(p.displacementControl.load, -5.0 / 6.0) << "lambda " << lambda;
    // Under displacement control the contact separates at less tension.
    EXPECT_GE(p.displacementControl.load, p.loadControl.load) << "lambda " << lambda;
    previousLoad = p.loadControl.load;
    previousDisp = p.displacementControl.load;
  }
}

// Below λ ≈ 0.938 (Maugis 1992; here 0.93795 from the sign of dδ̄/dā at
// ā = 1e-5) δ̄(ā) is monotone and the contact shrinks to ā = 0 without a jump
// under displacement control; above, it jumps off.
TEST(PullOff, DisplacementControlJumpAppearsNearLambda0938) {
  const an::PullOff below = an::pullOff(an::ContactModel::maugisDugdale(0.93));
  EXPECT_FALSE(below.displacementJump);
  EXPECT_EQ(below.displacementControl.a, 0.0);
  EXPECT_DOUBLE_EQ(below.displacementControl.load, an::mdZeroContactLimit(0.93).load);
  const an::PullOff above = an::pullOff(an::ContactModel::maugisDugdale(0.945));
  EXPECT_TRUE(above.displacementJump);
  EXPECT_GT(above.displacementControl.a, 0.0);
}
