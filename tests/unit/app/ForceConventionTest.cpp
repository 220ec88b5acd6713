// P means the force on the whole body in every formulation: a plane-strain
// half model (the built-in cylinder on a half-space, or the same mesh from
// gmsh with its "axis" line) reports twice its resultant, so that it equals
// the force of the full model (the gmsh mesh mirrored in x = 0).
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>

#include <cstdio>
#include <sstream>

#include "cgcm/app/Setup.hpp"
#include "cgcm/app/Simulation.hpp"
#include "cgcm/io/Deck.hpp"

namespace cgcm {
namespace {

// The attraction before contact (u from -0.02 to -0.008: gaps of 1.3 to 0.7 r0 above r_S0).
std::vector<solver::LoadPoint> planeStrainCurve(const std::string& name, const std::vector<std::string>& geometry,
                                             bool mirrored = false) {
  auto d = io::readDeck(CGCM_DECK);
  if (mirrored) d->sublist("Geometry").set("Mirror Planes", Teuchos::Array<std::string>(1, "x"));
  std::vector<std::string> overrides = {"Problem/Formulation=plane strain", "Loading/Approach Path={-0.02, -0.008}",
                                        "Loading/Initial Increment=0.004", "Loading/Max Increment=0.004",
                                        "Solver/Newton/Print Iterations=false", "Output/Exodus=false",
                                        "Output/Checkpoint=false", "Solver/Newton/Residual Tolerance=1e-11",
                                        "Output/Directory=" + std::string(CGCM_TEST_OUTPUT) + "/force-" + name};
  overrides.insert(overrides.end(), geometry.begin(), geometry.end());
  io::applyOverrides(*d, *app::validParameters(), overrides);
  io::validateDeck(*d, *app::validParameters());
  std::ostringstream log;
  const auto run = app::runSimulation(Tpetra::getDefaultComm(), *d, log);
  EXPECT_TRUE(run.completed) << name << ": " << run.failure;
  // the half models say that they double
  EXPECT_EQ(log.str().find("P = 2 x the resultant") != std::string::npos, !mirrored) << name << ": " << log.str();
  return run.curve;
}

TEST(ForceConvention, APlaneStrainHalfModelReportsTheWholeCylindersForce) {
  const std::string geo = "Geometry/File=" + std::string(CGCM_MESHES) + "/sphere-on-half-space.geo";
  const auto builtIn = planeStrainCurve("built-in", {});
  const auto half = planeStrainCurve("half", {"Geometry/Type=gmsh", geo});
  const auto full = planeStrainCurve("full", {"Geometry/Type=gmsh", geo}, true);
  ASSERT_EQ(builtIn.size(), half.size());
  ASSERT_EQ(full.size(), half.size());
  // F_ref = Y R0 = 1 per unit thickness: each state's |f|_2 <= 1e-11 (Residual Tolerance, a tenth of the
  // default: at 1e-10 the two differ by 6.8e-10, at 1e-11 by 6e-16, so the difference is the
  // solver's stopping point, not the convention)
  const Real tolerance = 1e-11;
  Real largest = 0.0, worst = 0.0;
  for (std::size_t k = 0; k < half.size(); ++k) {
    SCOPED_TRACE("row " + std::to_string(k));
    EXPECT_EQ(half[k].u, full[k].u);
    // the gmsh mesh is the built-in one node for node: the same solves
    EXPECT_NEAR(half[k].P, builtIn[k].P, 1e-8 * std::abs(builtIn[k].P) + 1e-14);
    // the full model's reactions sum both halves; each state is converged to the tolerance
    EXPECT_NEAR(full[k].P, half[k].P, 2.0 * tolerance);
    EXPECT_NEAR(full[k].Plower, half[k].Plower, 2.0 * tolerance);
    largest = std::max(largest, std::abs(half[k].P));
    worst = std::max(worst, std::abs(full[k].P - half[k].P));
  }
  std::printf("plane strain, P of the full model against 2 x the half's: largest difference %.3g (|P| up to %.3g)\n",
              worst, largest);
  EXPECT_GT(largest, 1e3 * tolerance) << "the path must load the cylinder";
}

}  // namespace
}  // namespace cgcm
