// The displacement-controlled path, its jumps and the hysteresis energy,
// derived from an arc-length curve with a known loop.
#include <gtest/gtest.h>

#include "cgcm/solver/PathAnalysis.hpp"

namespace cgcm {
namespace {

solver::LoadPoint row(double u, double P, bool stable, bool fold = false) {
  solver::LoadPoint p;
  p.u = u;
  p.P = P;
  p.stable = stable;
  p.fold = fold;
  return p;
}

// Approach and retraction of an S-shaped path: apart P = 0 up to the jump-in
// fold at u = 1, the unstable branch back to the pull-off fold at u = 0.5,
// in contact P = -1 from u = 0.5 to 2; then the same backwards.
std::vector<solver::LoadPoint> loop() {
  return {row(0.0, 0.0, true),   row(0.5, 0.0, true),    row(1.0, 0.0, true, true),  row(0.75, -0.5, false),
          row(0.5, -1.0, true, true), row(1.0, -1.0, true), row(2.0, -1.0, true),      row(1.0, -1.0, true),
          row(0.5, -1.0, true, true), row(0.75, -0.5, false), row(1.0, 0.0, true, true), row(0.5, 0.0, true),
          row(0.0, 0.0, true)};
}

TEST(PathAnalysis, JumpsOfALoopAndTheEnergyItDissipates) {
  const auto path = solver::displacementControlPath(loop());
  const auto jumps = solver::jumpsOf(path);
  ASSERT_EQ(jumps.size(), 2u);
  EXPECT_DOUBLE_EQ(jumps[0].from.u, 1.0);  // jump-in: from the fold apart ...
  EXPECT_DOUBLE_EQ(jumps[0].from.P, 0.0);
  EXPECT_DOUBLE_EQ(jumps[0].to.u, 1.0);    // ... to the contact branch at the same u
  EXPECT_DOUBLE_EQ(jumps[0].to.P, -1.0);
  EXPECT_DOUBLE_EQ(jumps[1].from.u, 0.5);  // pull-off
  EXPECT_DOUBLE_EQ(jumps[1].to.P, 0.0);
  for (const auto& p : path) EXPECT_TRUE(p.stable);
  // The loop between the branches over 0.5 <= u <= 1, height 1.
  EXPECT_NEAR(solver::hysteresisEnergy(path), 0.5, 1e-14);
}

TEST(PathAnalysis, AStablePathHasNoJumpsAndNoHysteresis) {
  std::vector<solver::LoadPoint> curve;
  for (int k = 0; k <= 10; ++k) curve.push_back(row(0.1 * k, -0.3 * k, true));
  for (int k = 9; k >= 0; --k) curve.push_back(row(0.1 * k, -0.3 * k, true));
  const auto path = solver::displacementControlPath(curve);
  EXPECT_TRUE(solver::jumpsOf(path).empty());
  EXPECT_NEAR(solver::hysteresisEnergy(path), 0.0, 1e-14);
}

}  // namespace
}  // namespace cgcm
