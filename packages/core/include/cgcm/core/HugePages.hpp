#pragma once
// Transparent huge pages for glibc's malloc.
//
// Tpetra, MueLu and MUMPS allocate and free large arrays in every Newton
// iteration (matrix products of the multigrid set-up, Kokkos views, MUMPS'
// fronts). glibc serves them with fresh 4 KiB pages, and on a virtual machine
// each first touch is a page fault of several microseconds: 23 % of the
// process time of the 108k peer block, 19 % of the 3D sphere deck. glibc 2.35+
// places its memory in transparent huge pages when its tunable
// glibc.malloc.hugetlb=1 is set, but reads tunables only at start-up, from the
// environment; so the program runs itself again with it (doc/performance.md).
#include <unistd.h>

#include <cstdlib>
#include <string>

namespace cgcm::core {

/// Call first in main, before any thread, MPI or Kokkos starts: unless the
/// environment already sets glibc.malloc.hugetlb or CGCM_HUGE_PAGES=0, sets the
/// tunable and executes this program again with the same arguments (same
/// process id). Does nothing where glibc or Linux lacks the tunable; if the
/// execution fails the program goes on with 4 KiB pages.
inline void useHugePageMalloc(char** argv) {
#if defined(__linux__) && defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 35))
  const char* choice = std::getenv("CGCM_HUGE_PAGES");
  if (choice && std::string(choice) == "0") return;
  const char* current = std::getenv("GLIBC_TUNABLES");
  std::string tunables = current ? current : "";
  if (tunables.find("glibc.malloc.hugetlb") != std::string::npos) return;
  tunables += (tunables.empty() ? "" : ":") + std::string("glibc.malloc.hugetlb=1");
  if (setenv("GLIBC_TUNABLES", tunables.c_str(), 1) != 0) return;
  execv("/proc/self/exe", argv);  // returns only if it failed
#else
  (void)argv;
#endif
}

/// Whether glibc's malloc was told to use huge pages in this process (the
/// tunable glibc.malloc.hugetlb set to 1 or 2, by useHugePageMalloc or by the
/// caller's environment).
inline bool hugePageMalloc() {
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (!tunables) return false;
  const std::string t = tunables, key = "glibc.malloc.hugetlb=";
  const auto at = t.find(key);
  return at != std::string::npos && at + key.size() < t.size() && t[at + key.size()] != '0';
}

}  // namespace cgcm::core
