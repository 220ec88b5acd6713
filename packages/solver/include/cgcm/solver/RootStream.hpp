#pragma once
// An array spread over the ranks, delivered to rank 0 in pieces: each entry
// (a global index and its values) is on one rank; rank 0 receives the entries
// a window of consecutive indices at a time, in ascending index, and hands each
// window on (to a file). Rank 0 so holds one window of the array, never the
// whole of it: what writes results.e of a distributed mesh (app::ResultsWriter)
// without the whole mesh or a whole field on one rank.
#include <algorithm>
#include <cstring>
#include <functional>
#include <type_traits>
#include <vector>

#include "cgcm/assembly/TpetraTypes.hpp"

namespace cgcm::solver {

/// The bytes a window holds at most by default (its entries on rank 0).
constexpr std::size_t kRootStreamWindowBytes = std::size_t(8) << 20;

/// Byte-level streamToRoot: `entryBytes` bytes of values per index. Collective.
void streamBytesToRoot(const assembly::Comm& comm, const std::vector<GlobalIndex>& index,
                       const std::vector<char>& values, std::size_t entryBytes, std::size_t windowBytes,
                       const std::function<void(const std::vector<GlobalIndex>&, const std::vector<char>&)>& onWindow);

/// Sends this rank's entries to rank 0: `index` ascending and >= 0, `width` values of T per index in
/// `values`. Rank 0 calls onWindow(index, values) for each window of consecutive indices (as many as
/// fit in `windowBytes` with their values) that holds an entry of any rank, with the window's entries of
/// every rank in ascending index. The ranks go window by window together, so a rank without entries
/// takes part until the last. An index given twice (on one rank or two), out of order, or a wrong
/// number of values throws std::logic_error on every rank; what onWindow throws is thrown on every
/// rank after the last window (rank 0 calls it no more after a throw). Collective.
template <class T>
void streamToRoot(const assembly::Comm& comm, const std::vector<GlobalIndex>& index, const std::vector<T>& values,
                  int width, const std::function<void(const std::vector<GlobalIndex>&, const std::vector<T>&)>& onWindow,
                  std::size_t windowBytes = kRootStreamWindowBytes) {
  static_assert(std::is_trivially_copyable_v<T>, "streamToRoot: plain data only");
  std::vector<char> bytes(values.size() * sizeof(T));
  if (!bytes.empty()) std::memcpy(bytes.data(), values.data(), bytes.size());
  streamBytesToRoot(comm, index, bytes, std::size_t(std::max(width, 0)) * sizeof(T), windowBytes,
                    [&](const std::vector<GlobalIndex>& at, const std::vector<char>& raw) {
                      std::vector<T> v(raw.size() / sizeof(T));
                      if (!v.empty()) std::memcpy(v.data(), raw.data(), raw.size());
                      onWindow(at, v);
                    });
}

}  // namespace cgcm::solver
