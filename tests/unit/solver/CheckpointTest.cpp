// checkpoint.bin: written and read back field by field; a truncated,
// changed (any byte), foreign or format-1 file is refused with a message
// naming it; a missing one too.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "cgcm/solver/Checkpoint.hpp"
#include "cgcm/core/Error.hpp"

namespace cgcm::solver {
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
  c.stepper.displacement = 0.0315;
  c.stepper.increment = 0.0015;
  c.stepper.step = 41;
  c.stepper.havePrevious = true;
  c.stepper.previousDisplacement = 0.0302;
  c.lastDisplacement = 0.0315;
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
  EXPECT_EQ(r.stepper.displacement, c.stepper.displacement);
  EXPECT_EQ(r.stepper.increment, c.stepper.increment);
  EXPECT_EQ(r.stepper.step, c.stepper.step);
  EXPECT_EQ(r.stepper.havePrevious, c.stepper.havePrevious);
  EXPECT_EQ(r.stepper.previousDisplacement, c.stepper.previousDisplacement);
  EXPECT_EQ(r.lastDisplacement, c.lastDisplacement);
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

// The message of readCheckpoint(dir), or "" if it accepted the file.
std::string refusal(const std::string& dir) {
  try {
    readCheckpoint(dir);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void changeByte(const std::string& path, std::uintmax_t at) {
  std::fstream f(path, std::ios::binary | std::ios::in | std::ios::out);
  f.seekg(std::streamoff(at));
  const char c = char(f.get());
  f.seekp(std::streamoff(at));
  f.put(char(c ^ 0x10));
  ASSERT_TRUE(f.good());
}

TEST(Checkpoint, RefusesAMissingFile) {
  const std::string dir = freshDir("missing");
  EXPECT_NE(refusal(dir).find("no checkpoint"), std::string::npos);
}

TEST(Checkpoint, RefusesTruncatedFiles) {
  const std::string dir = freshDir("truncated");
  ASSERT_TRUE(writeCheckpoint(dir, sample()));
  const auto size = std::filesystem::file_size(checkpointPath(dir));
  for (std::uintmax_t keep : {std::uintmax_t(0), std::uintmax_t(5), std::uintmax_t(8), size / 2, size - 4, size - 1}) {
    ASSERT_TRUE(writeCheckpoint(dir, sample()));
    std::filesystem::resize_file(checkpointPath(dir), keep);
    const std::string why = refusal(dir);
    EXPECT_NE(why.find("is damaged"), std::string::npos) << "cut to " << keep << " of " << size << ": " << why;
    EXPECT_NE(why.find(checkpointPath(dir)), std::string::npos) << why;
  }
}

// Every byte, one at a time: the magic, the stepper's state, the curve, the
// vectors, the end mark and the checksum itself.
TEST(Checkpoint, RefusesAnyChangedByte) {
  const std::string dir = freshDir("changed");
  ASSERT_TRUE(writeCheckpoint(dir, sample()));
  const auto size = std::filesystem::file_size(checkpointPath(dir));
  for (std::uintmax_t at = 0; at < size; ++at) {
    ASSERT_TRUE(writeCheckpoint(dir, sample()));
    changeByte(checkpointPath(dir), at);
    const std::string why = refusal(dir);
    EXPECT_NE(why.find("is damaged: its checksum (CRC-32) does not match"), std::string::npos)
        << "byte " << at << " of " << size << ": " << why;
    EXPECT_NE(why.find(checkpointPath(dir)), std::string::npos) << why;
  }
  // the middle and the last byte, named as such
  for (std::uintmax_t at : {size / 2, size - 1}) {
    ASSERT_TRUE(writeCheckpoint(dir, sample()));
    changeByte(checkpointPath(dir), at);
    EXPECT_NE(refusal(dir).find("checksum"), std::string::npos) << "byte " << at;
  }
  ASSERT_TRUE(writeCheckpoint(dir, sample()));
  EXPECT_EQ(refusal(dir), "");
}

TEST(Checkpoint, RefusesAForeignFile) {
  const std::string dir = freshDir("foreign");
  std::ofstream(checkpointPath(dir)) << "P,u\n0,1\n";
  const std::string why = refusal(dir);
  EXPECT_NE(why.find("is damaged"), std::string::npos) << why;
  EXPECT_NE(why.find(checkpointPath(dir)), std::string::npos) << why;
}

// Another format version: format 1 (no checksum, the end mark last) is named
// with what to do; a version byte changed in a format-2 file is damage.
TEST(Checkpoint, RefusesTheOlderFormat) {
  const std::string dir = freshDir("format1");
  ASSERT_TRUE(writeCheckpoint(dir, sample()));
  const auto size = std::filesystem::file_size(checkpointPath(dir));
  std::filesystem::resize_file(checkpointPath(dir), size - 4);  // format 1 had no checksum
  {
    std::fstream f(checkpointPath(dir), std::ios::binary | std::ios::in | std::ios::out);
    f.seekp(7);
    f.put('1');
  }
  std::string why = refusal(dir);
  EXPECT_NE(why.find(checkpointPath(dir) + " is a checkpoint of format 1, written by an older cgcm; this cgcm reads "
                                           "format 2: run the deck again from the start"),
            std::string::npos)
      << why;
  for (char version : {'1', '3'}) {
    ASSERT_TRUE(writeCheckpoint(dir, sample()));
    {
      std::fstream f(checkpointPath(dir), std::ios::binary | std::ios::in | std::ios::out);
      f.seekp(7);
      f.put(version);
    }
    why = refusal(dir);
    EXPECT_NE(why.find("is damaged: its checksum"), std::string::npos) << version << ": " << why;
  }
}

}  // namespace
}  // namespace cgcm::solver
