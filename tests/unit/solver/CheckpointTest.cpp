// checkpoint.bin: written and read back field by field; a truncated,
// changed (any byte), foreign or format-1 file is refused with a message
// naming it; a missing one too. The distributed forms (one rank and two:
// mpi_solver_tests_np2) write the file one process writes, and read it back
// into each rank's entries.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <fstream>
#include <iterator>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>

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

// A vector of n dofs spread over the ranks out of order (rank r owns the dofs d with 7d mod p = r, listed
// backwards), with the value value(d) at dof d.
assembly::Vector spreadVector(GlobalIndex n, const std::function<Real(GlobalIndex)>& value) {
  const auto comm = Tpetra::getDefaultComm();
  std::vector<GlobalIndex> mine;
  for (GlobalIndex d = n - 1; d >= 0; --d)
    if ((7 * d) % comm->getSize() == comm->getRank()) mine.push_back(d);
  const auto map = Teuchos::rcp(new assembly::Map(Tpetra::global_size_t(n), mine.data(), mine.size(), 0, comm));
  assembly::Vector v(map);
  auto h = v.getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (std::size_t k = 0; k < mine.size(); ++k) h(k, 0) = value(mine[k]);
  return v;
}

// Rank 0's folder, made fresh before every rank goes on.
std::string sharedDir(const std::string& name) {
  const auto comm = Tpetra::getDefaultComm();
  const std::string dir = std::string(CGCM_TEST_OUTPUT) + "/checkpoint/" + name + "-np" + std::to_string(comm->getSize());
  if (comm->getRank() == 0) freshDir(name + "-np" + std::to_string(comm->getSize()));
  comm->barrier();
  return dir;
}

std::string fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The ranks stream their entries to rank 0 in windows of 5 values: the file is, byte for byte, the one
// writeCheckpoint(dir, c) writes with the whole vectors; read back a window of 3 values at a time, each
// rank's entries are what it wrote; without a previous state the file holds none.
TEST(DistributedCheckpoint, RanksWriteTheFileOneProcessWritesAndReadTheirEntriesBack) {
  const auto comm = Tpetra::getDefaultComm();
  const GlobalIndex n = 37;
  auto uOf = [](GlobalIndex d) { return std::sin(double(d)) + double(d); };
  auto previousOf = [](GlobalIndex d) { return -1e-3 * double(d); };
  const assembly::Vector u = spreadVector(n, uOf), previous = spreadVector(n, previousOf);
  const std::string dir = sharedDir("ranks"), whole = sharedDir("ranks-whole");
  Checkpoint header = sample();
  header.u.clear(), header.previous.clear();
  ASSERT_TRUE(writeCheckpoint(*comm, dir, header, u, &previous, 40));
  if (comm->getRank() == 0) {
    Checkpoint c = sample();
    c.u.clear(), c.previous.clear();
    for (GlobalIndex d = 0; d < n; ++d) c.u.push_back(uOf(d)), c.previous.push_back(previousOf(d));
    ASSERT_TRUE(writeCheckpoint(whole, c));
    EXPECT_EQ(fileBytes(checkpointPath(dir)), fileBytes(checkpointPath(whole)));
    const Checkpoint r = readCheckpoint(dir);
    EXPECT_EQ(r.u, c.u);
    EXPECT_EQ(r.previous, c.previous);
    EXPECT_EQ(r.unknowns, std::uint64_t(n));
  }
  comm->barrier();
  const Checkpoint h = readCheckpointHeader(dir, 24);
  EXPECT_EQ(h.unknowns, std::uint64_t(n));
  EXPECT_TRUE(h.u.empty());
  ASSERT_EQ(h.curve.size(), sample().curve.size());
  EXPECT_EQ(h.curve[2].P, sample().curve[2].P);
  EXPECT_EQ(h.stepper.step, sample().stepper.step);
  assembly::Vector u2 = spreadVector(n, [](GlobalIndex) { return 0.0; });
  assembly::Vector p2 = spreadVector(n, [](GlobalIndex) { return 0.0; });  // (a copy would share u2's values)
  readCheckpointVectors(dir, u2, &p2, 24);
  {
    const auto a = u.getLocalViewHost(Tpetra::Access::ReadOnly), b = u2.getLocalViewHost(Tpetra::Access::ReadOnly);
    const auto pa = previous.getLocalViewHost(Tpetra::Access::ReadOnly), pb = p2.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (std::size_t k = 0; k < a.extent(0); ++k) {
      EXPECT_EQ(b(k, 0), a(k, 0)) << "entry " << k;
      EXPECT_EQ(pb(k, 0), pa(k, 0)) << "entry " << k;
    }
  }
  // no previous state: none in the file
  header.stepper.havePrevious = false;
  ASSERT_TRUE(writeCheckpoint(*comm, dir, header, u, nullptr));
  if (comm->getRank() == 0) {
    const Checkpoint r = readCheckpoint(dir);
    EXPECT_EQ(r.u.size(), std::size_t(n));
    EXPECT_TRUE(r.previous.empty());
  }
  comm->barrier();
}

// Every rank refuses what one process refuses, before it writes an entry: a vector of another length,
// a changed byte; a folder that cannot be written is false on every rank.
TEST(DistributedCheckpoint, RanksRefuseAnotherLengthOrADamagedFileTogether) {
  const auto comm = Tpetra::getDefaultComm();
  const std::string dir = sharedDir("ranks-refused");
  const assembly::Vector u = spreadVector(37, [](GlobalIndex d) { return double(d); });
  Checkpoint header = sample();
  header.u.clear(), header.previous.clear();
  header.stepper.havePrevious = false;
  ASSERT_TRUE(writeCheckpoint(*comm, dir, header, u, nullptr));
  assembly::Vector other = spreadVector(36, [](GlobalIndex) { return -1.0; });
  try {
    readCheckpointVectors(dir, other, nullptr);
    ADD_FAILURE() << "another length accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the checkpoint holds 37 unknowns, the problem 36"), std::string::npos)
        << e.what();
  }
  {
    const auto h = other.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (std::size_t k = 0; k < h.extent(0); ++k) EXPECT_EQ(h(k, 0), -1.0);  // untouched
  }
  comm->barrier();
  if (comm->getRank() == 0) changeByte(checkpointPath(dir), 100);
  comm->barrier();
  assembly::Vector same = spreadVector(37, [](GlobalIndex) { return -1.0; });
  try {
    readCheckpointVectors(dir, same, nullptr);
    ADD_FAILURE() << "a damaged file accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("is damaged: its checksum"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(writeCheckpoint(*comm, dir + "/missing/folder", header, u, nullptr));
  comm->barrier();
}

}  // namespace
}  // namespace cgcm::solver
