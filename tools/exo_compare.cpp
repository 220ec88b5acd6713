// exo_compare: compares two Exodus II files (time values, global, nodal and
// element variables by name), or prints what one holds. Debian has no SEACAS
// exodiff; this covers what cgcm's tests need.
//
//   exo_compare [--abs A] [--rel R] [--abs-for NAME=A ...] a.e b.e
//       exit 0 if |a-b| <= A + R max(|a|,|b|) everywhere (variable NAME: its own A), 1 if not
//   exo_compare --dump file.e                 blocks, sets, variable names, steps and the globals per step
//
// Exit code 2: bad usage or an unreadable file.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

#include "cgcm/io/ExodusReader.hpp"

namespace {

int usage() {
  std::cerr << "usage: exo_compare [--abs A] [--rel R] [--abs-for NAME=A ...] a.e b.e   (defaults: A = 1e-12, R = 1e-9)\n"
               "       exo_compare --dump file.e\n";
  return 2;
}

void list(const char* what, const std::vector<cgcm::io::ExodusReader::Entity>& entities) {
  std::cout << what << ":";
  for (const auto& e : entities)
    std::cout << " \"" << e.name << "\" (" << (e.type.empty() ? "" : e.type + ", ") << e.size << ")";
  std::cout << "\n";
}

void list(const char* what, const std::vector<std::string>& names) {
  std::cout << what << ":";
  for (const auto& n : names) std::cout << " " << n;
  std::cout << "\n";
}

void dump(const std::string& path) {
  const cgcm::io::ExodusReader r(path);
  std::cout << "file: " << path << "\ntitle: " << r.title() << "\ndimension: " << r.dim() << ", nodes: " << r.numNodes()
            << ", elements: " << r.numElements() << "\n";
  list("element blocks", r.blocks());
  list("node sets", r.nodeSets());
  list("side sets", r.sideSets());
  list("nodal variables", r.nodalNames());
  list("element variables", r.elementNames());
  list("global variables", r.globalNames());
  std::cout << "steps: " << r.numSteps() << "\nstep time";
  for (const auto& n : r.globalNames()) std::cout << " " << n;
  std::cout << "\n";
  char buf[32];
  for (int s = 1; s <= r.numSteps(); ++s) {
    std::snprintf(buf, sizeof buf, "%.12g", r.times()[s - 1]);
    std::cout << s << " " << buf;
    for (double g : r.globals(s)) std::snprintf(buf, sizeof buf, "%.12g", g), std::cout << " " << buf;
    std::cout << "\n";
  }
}

bool number(const char* text, double& value) {
  char* end = nullptr;
  value = std::strtod(text, &end);
  return end != text && *end == '\0' && value >= 0.0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    if (argc == 3 && std::string(argv[1]) == "--dump") {
      dump(argv[2]);
      return 0;
    }
    cgcm::io::ExodusTolerance tol;
    std::vector<std::string> files;
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if ((arg == "--abs" || arg == "--rel") && i + 1 < argc) {
        if (!number(argv[++i], arg == "--abs" ? tol.abs : tol.rel)) return usage();
      } else if (arg == "--abs-for" && i + 1 < argc) {
        const std::string spec = argv[++i];
        const auto eq = spec.rfind('=');
        double a = 0.0;
        if (eq == std::string::npos || eq == 0 || !number(spec.c_str() + eq + 1, a)) return usage();
        tol.absFor[spec.substr(0, eq)] = a;
      } else if (!arg.empty() && arg[0] == '-') {
        return usage();
      } else {
        files.push_back(arg);
      }
    }
    if (files.size() != 2) return usage();
    const auto differences = cgcm::io::compareExodus(files[0], files[1], tol);
    for (const auto& d : differences) std::cout << d << "\n";
    if (differences.empty()) std::cout << "same within abs " << tol.abs << ", rel " << tol.rel << "\n";
    return differences.empty() ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "exo_compare: " << e.what() << "\n";
    return 2;
  }
}
