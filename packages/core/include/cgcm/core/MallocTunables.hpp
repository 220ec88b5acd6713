#pragma once
// glibc malloc's tunables for a finite-element run (doc/performance.md, "Memory pages").
//
// Tpetra, MueLu and MUMPS allocate and free large arrays in every Newton
// iteration (matrix products of the multigrid set-up, Kokkos views, MUMPS'
// fronts). Two of glibc's defaults cost here:
//   - fresh 4 KiB pages: on a virtual machine each first touch is a page fault
//     of several microseconds (23 % of the process time of the 108k peer block,
//     19 % of the 3D sphere deck). glibc.malloc.hugetlb=1 puts the heap in
//     transparent huge pages.
//   - a moving mmap threshold: after a mapped block is freed glibc serves
//     blocks up to that size (up to 32 MiB) from the heap, where the holes they
//     leave stay resident. glibc.malloc.mmap_threshold=4194304 maps every block
//     of 4 MiB or more and returns it when freed (the 325k-unknown 3D deck on two
//     ranks: 848 and 797 MB per rank against 771 and 709; 4 MiB, twice a huge
//     page, so that mapped blocks are mostly huge pages too: 1 MiB made 13 times
//     the page faults of the default on the 2D deck).
// glibc reads tunables only at start-up, from the environment; so the program
// runs itself again with them.
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <string>

namespace cgcm::core {

namespace detail {
/// The value of glibc tunable `name` in `tunables` (GLIBC_TUNABLES' form, name=value:name=value), or empty.
inline std::string tunableValue(const std::string& tunables, const std::string& name) {
  const std::string key = name + "=";
  for (std::size_t at = 0; at < tunables.size();) {
    const std::size_t end = std::min(tunables.find(':', at), tunables.size());
    if (tunables.compare(at, key.size(), key) == 0) return tunables.substr(at + key.size(), end - at - key.size());
    at = end + 1;
  }
  return "";
}
/// The same in this process's GLIBC_TUNABLES.
inline std::string mallocTunable(const std::string& name) {
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  return tunables ? tunableValue(tunables, name) : "";
}
}  // namespace detail

/// The mmap threshold tuneMalloc sets, in bytes.
constexpr long kMallocMmapThreshold = 4L << 20;

/// Call first in main, before any thread, MPI or Kokkos starts: adds to
/// GLIBC_TUNABLES glibc.malloc.hugetlb=1 (unless CGCM_HUGE_PAGES=0) and
/// glibc.malloc.mmap_threshold (unless CGCM_MMAP_THRESHOLD=0), each unless the
/// environment already names it, and if it added one, executes this program
/// again with the same arguments (same process id). Does nothing where glibc
/// lacks the tunables; if the execution fails the program goes on with glibc's
/// defaults.
inline void tuneMalloc(char** argv) {
#if defined(__linux__) && defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 35))
  const auto off = [](const char* variable) {
    const char* value = std::getenv(variable);
    return value && std::string(value) == "0";
  };
  const char* current = std::getenv("GLIBC_TUNABLES");
  const std::string before = current ? current : "";
  std::string tunables = before;
  const auto add = [&](const std::string& name, const std::string& value) {
    if (!detail::tunableValue(tunables, name).empty()) return;
    tunables += (tunables.empty() ? "" : ":") + name + "=" + value;
  };
  if (!off("CGCM_HUGE_PAGES")) add("glibc.malloc.hugetlb", "1");
  if (!off("CGCM_MMAP_THRESHOLD")) add("glibc.malloc.mmap_threshold", std::to_string(kMallocMmapThreshold));
  if (tunables == before || setenv("GLIBC_TUNABLES", tunables.c_str(), 1) != 0) return;
  execv("/proc/self/exe", argv);  // returns only if it failed
#else
  (void)argv;
#endif
}

/// Whether glibc's malloc was told to use huge pages in this process (the
/// tunable glibc.malloc.hugetlb set to 1 or 2, by tuneMalloc or by the
/// caller's environment).
inline bool hugePageMalloc() {
  const std::string v = detail::mallocTunable("glibc.malloc.hugetlb");
  return !v.empty() && v != "0";
}

/// How this process's malloc was tuned, for the summary: "transparent huge pages" or "4 KiB pages", then
/// "blocks from 4 MiB mapped" when the mmap threshold is set (by tuneMalloc or the environment).
inline std::string mallocDescription() {
  std::string d = hugePageMalloc() ? "transparent huge pages" : "4 KiB pages";
  const std::string threshold = detail::mallocTunable("glibc.malloc.mmap_threshold");
  if (threshold.empty()) return d;
  const long bytes = std::strtol(threshold.c_str(), nullptr, 10);
  const bool mebibytes = bytes > 0 && bytes % (1L << 20) == 0;
  return d + ", blocks from " + (mebibytes ? std::to_string(bytes >> 20) + " MiB" : threshold + " bytes") +
         " mapped";
}

}  // namespace cgcm::core
