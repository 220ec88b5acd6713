#include "cgcm/solver/RootStream.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <algorithm>
#include <exception>
#include <limits>

#include "cgcm/assembly/GhostedSurfaces.hpp"
#include "cgcm/solver/Discretization.hpp"

namespace cgcm::solver {

void streamBytesToRoot(const assembly::Comm& comm, const std::vector<GlobalIndex>& index,
                       const std::vector<char>& values, std::size_t entryBytes, std::size_t windowBytes,
                       const std::function<void(const std::vector<GlobalIndex>&, const std::vector<char>&)>& onWindow) {
  // the caller's lists, checked on every rank together (a rank alone would leave the others waiting)
  std::string bad;
  if (entryBytes == 0 || values.size() != index.size() * entryBytes)
    bad = "streamToRoot: " + std::to_string(values.size()) + " bytes for " + std::to_string(index.size()) +
          " entries of " + std::to_string(entryBytes);
  for (std::size_t k = 0; k < index.size() && bad.empty(); ++k)
    if (index[k] < 0 || (k > 0 && index[k] <= index[k - 1]))
      bad = "streamToRoot: index " + std::to_string(index[k]) + " at entry " + std::to_string(k) +
            " (ascending and >= 0 expected)";
  int anyBad = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, bad.empty() ? 0 : 1, Teuchos::outArg(anyBad));
  if (anyBad) throw std::logic_error(bad.empty() ? "streamToRoot: another rank's entries are refused" : bad);
  const int p = comm.getSize();
  const bool root = comm.getRank() == 0;
  const GlobalIndex window = GlobalIndex(std::max<std::size_t>(1, windowBytes / (sizeof(GlobalIndex) + entryBytes)));
  const GlobalIndex none = std::numeric_limits<GlobalIndex>::max();
  std::exception_ptr failure;  // of onWindow
  std::string twice;          // an index given twice
  std::size_t next = 0;  // this rank's first entry not sent
  for (;;) {
    // the window starts at the smallest index not yet sent by any rank
    const GlobalIndex mine = next < index.size() ? index[next] : none;
    GlobalIndex start = mine;
    Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, mine, Teuchos::outArg(start));
    if (start == none) break;
    const std::size_t end = std::size_t(std::lower_bound(index.begin() + std::ptrdiff_t(next), index.end(),
                                                         start + window) - index.begin());
    std::vector<std::vector<char>> toRank(static_cast<std::size_t>(p));
    std::vector<char>& out = toRank[0];  // (index, values) per entry
    out.reserve((end - next) * (sizeof(GlobalIndex) + entryBytes));
    for (std::size_t k = next; k < end; ++k) {
      const char* i = reinterpret_cast<const char*>(&index[k]);
      out.insert(out.end(), i, i + sizeof(GlobalIndex));
      out.insert(out.end(), values.begin() + std::ptrdiff_t(k * entryBytes),
                 values.begin() + std::ptrdiff_t((k + 1) * entryBytes));
    }
    next = end;
    const auto fromRank = assembly::exchangeBytes(comm, toRank);
    if (!root || failure || !twice.empty()) continue;
    try {
      std::vector<std::pair<GlobalIndex, const char*>> entries;  // (index, its values) of every rank
      for (const auto& bytes : fromRank)
        for (std::size_t at = 0; at < bytes.size(); at += sizeof(GlobalIndex) + entryBytes) {
          GlobalIndex i;
          std::memcpy(&i, bytes.data() + at, sizeof i);
          entries.emplace_back(i, bytes.data() + at + sizeof i);
        }
      std::sort(entries.begin(), entries.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
      std::vector<GlobalIndex> at(entries.size());
      std::vector<char> v(entries.size() * entryBytes);
      for (std::size_t k = 0; k < entries.size(); ++k) {
        if (k > 0 && entries[k].first == entries[k - 1].first) {
          twice = "streamToRoot: index " + std::to_string(entries[k].first) + " given by two ranks";
          break;
        }
        at[k] = entries[k].first;
        std::copy(entries[k].second, entries[k].second + entryBytes, v.begin() + std::ptrdiff_t(k * entryBytes));
      }
      if (twice.empty()) onWindow(at, v);
    } catch (...) {
      failure = std::current_exception();
    }
  }
  std::vector<char> message(twice.begin(), twice.end());  // a bug of the caller: std::logic_error everywhere
  broadcastBytes(comm, message);
  if (!message.empty()) throw std::logic_error(std::string(message.begin(), message.end()));
  runOnRoot(comm, [&] {
    if (failure) std::rethrow_exception(failure);
  });
}

}  // namespace cgcm::solver
