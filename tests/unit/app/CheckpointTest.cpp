// checkpoint.bin: written and read back field by field; a truncated or
// foreign file is refused with a message naming it; a missing one too.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cgcm/app/Checkpoint.hpp"
#include "cgcm/core/Error.hpp"

namespace cgcm::app {
namespace {

std::string freshDir(const std::string& name) {
  const std::string dir = std::string(CGCM_TEST_OUTPUT) + "/checkpoint/" + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

Checkpoint sample() {
  Checkpoint c;
  c.stepper.segment = 2;
  c.stepper.load = 0.0315;
  c.stepper.increment = 0.0015;
  c.stepper.step = 41;
  c.stepper.havePrevious = true;
  c.stepper.previousLoad = 0.0302;
  c.lastLoad = 0.0315;
  c.exodusSteps = 42;
  for (int k = 0; k < 3; ++k) {
    LoadPoint p;
    p.step = k;
    p.u = 0.01 * k;
    p.P = -1e-4 * k;
    p.gap = 0.5 + k;
    p.newtonIterations = 3 + k;
    p.fold = k == 1;
    p.jump = k == 2;
    p.stable = k != 1;
    p.residual = 1e-11 * k;
    p.cutbacks = k;
    c.curve.push_back(p);
  }
  c.u = {1.0, -2.5, 3.25e-7};
  c.previous = {0.5, -2.0, 3.0e-7};
  return c;
}

TEST(Checkpoint, ReadsBackWhatWasWritten) {
  const std::string dir = freshDir("roundtrip");
  const Checkpoint c = sample();
  ASSERT_TRUE(writeCheckpoint(dir, c));
  EXPECT_FALSE(std::filesystem::exists(checkpointPath(dir) + ".tmp"));
  const Checkpoint r = readCheckpoint(dir);
  EXPECT_EQ(r.stepper.segment, c.stepper.segment);
  EXPECT_EQ(r.stepper.load, c.stepper.load);
  EXPECT_EQ(r.stepper.increment, c.stepper.increment);
  EXPECT_EQ(r.stepper.step, c.stepper.step);
  EXPECT_EQ(r.stepper.havePrevious, c.stepper.havePrevious);
  EXPECT_EQ(r.stepper.previousLoad, c.stepper.previousLoad);
  EXPECT_EQ(r.lastLoad, c.lastLoad);
  EXPECT_EQ(r.exodusSteps, c.exodusSteps);
  EXPECT_EQ(r.u, c.u);
  EXPECT_EQ(r.previous, c.previous);
  ASSERT_EQ(r.curve.size(), c.curve.size());
  for (std::size_t k = 0; k < c.curve.size(); ++k) {
    EXPECT_EQ(r.curve[k].step, c.curve[k].step);
    EXPECT_EQ(r.curve[k].u, c.curve[k].u);
    EXPECT_EQ(r.curve[k].P, c.curve[k].P);
    EXPECT_EQ(r.curve[k].gap, c.curve[k].gap);
    EXPECT_EQ(r.curve[k].newtonIterations, c.curve[k].newtonIterations);
    EXPECT_EQ(r.curve[k].stable, c.curve[k].stable);
    EXPECT_EQ(r.curve[k].fold, c.curve[k].fold);
    EXPECT_EQ(r.curve[k].jump, c.curve[k].jump);
    EXPECT_EQ(r.curve[k].residual, c.curve[k].residual);
    EXPECT_EQ(r.curve[k].cutbacks, c.curve[k].cutbacks);
  }
}

TEST(Checkpoint, RefusesMissingTruncatedAndForeignFiles) {
  const std::string dir = freshDir("bad");
  try {
    readCheckpoint(dir);
    FAIL() << "no checkpoint accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no checkpoint"), std::string::npos) << e.what();
  }
  ASSERT_TRUE(writeCheckpoint(dir, sample()));
  const auto size = std::filesystem::file_size(checkpointPath(dir));
  for (std::uintmax_t keep : {std::uintmax_t(0), std::uintmax_t(5), size / 2, size - 1}) {
    ASSERT_TRUE(writeCheckpoint(dir, sample()));
    std::filesystem::resize_file(checkpointPath(dir), keep);
    try {
      readCheckpoint(dir);
      FAIL() << "a checkpoint cut to " << keep << " of " << size << " bytes accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("truncated or not a cgcm checkpoint"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find(checkpointPath(dir)), std::string::npos) << e.what();
    }
  }
  std::ofstream(checkpointPath(dir)) << "P,u\n0,1\n";
  EXPECT_THROW(readCheckpoint(dir), InputError);
}

}  // namespace
}  // namespace cgcm::app
