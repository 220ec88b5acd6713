// solver::streamToRoot: every entry of every rank reaches rank 0 once, in ascending index, a window at
// a time; an index given twice and a failing window stop every rank. Runs on one rank and on two
// (mpi_solver_tests_np2).
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>
#include <string>

#include "cgcm/solver/RootStream.hpp"

namespace cgcm::solver {
namespace {

// Rank r holds the indices i of [0, n) with i % p == r whose `keep(i)` holds, with values (i, -i).
struct Spread {
  std::vector<GlobalIndex> index;
  std::vector<Real> values;
};
Spread spread(GlobalIndex n, int rank, int p, const std::function<bool(GlobalIndex)>& keep) {
  Spread s;
  for (GlobalIndex i = rank; i < n; i += p)
    if (keep(i)) s.index.push_back(i), s.values.insert(s.values.end(), {Real(i), -Real(i)});
  return s;
}

TEST(RootStream, EveryEntryReachesRankZeroOnceInOrderAWindowAtATime) {
  const auto comm = Tpetra::getDefaultComm();
  const int rank = comm->getRank(), p = comm->getSize();
  // windows of 5 entries (5 x (8 + 16) bytes), 10 entries (one window), the default; dense and sparse
  for (const std::size_t bytes : {std::size_t(120), std::size_t(240), kRootStreamWindowBytes}) {
    for (const bool sparse : {false, true}) {
      const GlobalIndex n = 103;
      auto keep = [&](GlobalIndex i) { return !sparse || i % 7 == 3 || i > 90; };
      const Spread mine = spread(n, rank, p, keep);
      std::vector<GlobalIndex> received;
      int windows = 0;
      streamToRoot<Real>(
          *comm, mine.index, mine.values, 2,
          [&](const std::vector<GlobalIndex>& at, const std::vector<Real>& v) {
            ++windows;
            ASSERT_FALSE(at.empty());
            ASSERT_EQ(v.size(), 2 * at.size());
            EXPECT_LT(at.back() - at.front(), GlobalIndex(std::max<std::size_t>(1, bytes / 24)));  // one window
            for (std::size_t k = 0; k < at.size(); ++k) {
              EXPECT_EQ(v[2 * k], Real(at[k]));
              EXPECT_EQ(v[2 * k + 1], -Real(at[k]));
            }
            received.insert(received.end(), at.begin(), at.end());
          },
          bytes);
      if (rank != 0) {
        EXPECT_EQ(windows, 0);  // only rank 0 is called
        continue;
      }
      std::vector<GlobalIndex> expected;
      for (GlobalIndex i = 0; i < n; ++i)
        if (keep(i)) expected.push_back(i);
      EXPECT_EQ(received, expected) << "window bytes " << bytes << (sparse ? ", sparse" : ", dense");
      if (bytes == 120 && !sparse) EXPECT_EQ(windows, 21);  // 103 entries, 5 per window
      if (bytes == 240 && sparse) EXPECT_LE(windows, int(expected.size()));  // empty index ranges skipped
    }
  }
}

TEST(RootStream, AnIndexTwiceOrAFailingWindowStopsEveryRank) {
  const auto comm = Tpetra::getDefaultComm();
  const int rank = comm->getRank();
  // index 4 on every rank: on one rank only if p = 1, so there it is given twice in one list
  const std::vector<GlobalIndex> twice = comm->getSize() > 1 ? std::vector<GlobalIndex>{4} : std::vector<GlobalIndex>{4, 4};
  const std::vector<int> ones(twice.size(), 1);
  EXPECT_THROW(streamToRoot<int>(*comm, twice, ones, 1, [](const auto&, const auto&) {}), std::logic_error);
  // rank 0 fails at the first window; every rank throws after the last, with rank 0's message
  const std::vector<GlobalIndex> index = {GlobalIndex(rank), GlobalIndex(rank + 10)};
  const std::vector<int> values = {1, 2};
  int calls = 0;
  try {
    streamToRoot<int>(
        *comm, index, values, 1,
        [&](const auto&, const auto&) {
          ++calls;
          throw std::runtime_error("the disk is full");
        },
        12);  // one entry per window
    ADD_FAILURE() << "no exception on rank " << rank;
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("the disk is full"), std::string::npos) << e.what();
  }
  EXPECT_EQ(calls, rank == 0 ? 1 : 0);  // not called after the throw
  // a wrong number of values, or indices out of order, on rank 0 alone: every rank refuses
  const std::vector<int> short_ = rank == 0 ? std::vector<int>{1} : values;
  EXPECT_THROW(streamToRoot<int>(*comm, index, short_, 1, [](const auto&, const auto&) {}), std::logic_error);
  const std::vector<GlobalIndex> backwards = rank == 0 ? std::vector<GlobalIndex>{10, 0} : index;
  EXPECT_THROW(streamToRoot<int>(*comm, backwards, values, 1, [](const auto&, const auto&) {}), std::logic_error);
}

}  // namespace
}  // namespace cgcm::solver
