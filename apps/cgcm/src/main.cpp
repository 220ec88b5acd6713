// cgcm: solves the deck given on the command line.
//   cgcm DECK.xml [Path/To/Parameter=value ...]
//   cgcm --help | --version | --kokkos-help
#include <Tpetra_Core.hpp>

#include <cstring>
#include <iostream>

#include "cgcm/app/Setup.hpp"
#include "cgcm/app/Simulation.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/io/Deck.hpp"

namespace {

void usage(std::ostream& out) {
  out << "usage: cgcm DECK.xml [Path/To/Parameter=value ...]\n"
         "       cgcm --help     (every parameter with its default and meaning)\n"
         "       cgcm --version\n"
         "       cgcm --kokkos-help (Kokkos' run-time options)\n"
         "exit codes: 0 the whole path was followed; 1 the solver stopped (the reason is printed, the outputs\n"
         "            written so far are valid); 2 bad input (nothing was run)\n";
}

}  // namespace

int main(int argc, char** argv) {
  // Before Kokkos starts: it answers --help with its own option block.
  if (argc == 2 && (!std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h"))) {
    usage(std::cout);
    std::cout << "\nParameters (XML deck sublists; defaults in brackets):\n";
    cgcm::io::printHelp(std::cout, *cgcm::app::validParameters());
    return 0;
  }
  if (argc == 2 && !std::strcmp(argv[1], "--version")) {
    std::cout << "cgcm " << CGCM_VERSION << "\n";
    return 0;
  }
  if (argc == 2 && !std::strcmp(argv[1], "--kokkos-help")) {
    char help[] = "--kokkos-help";
    char* kokkosArgs[] = {argv[0], help, nullptr};
    int kokkosArgc = 2;
    char** kokkosArgv = kokkosArgs;
    Tpetra::ScopeGuard scope(&kokkosArgc, &kokkosArgv);
    return 0;
  }
  Tpetra::ScopeGuard scope(&argc, &argv);
  auto comm = Tpetra::getDefaultComm();
  const bool root = comm->getRank() == 0;
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0].rfind("--", 0) == 0) {
    if (root) usage(std::cerr);
    return 2;
  }
  try {
    auto deck = cgcm::io::readDeck(args[0]);
    cgcm::io::applyOverrides(*deck, *cgcm::app::validParameters(),
                             std::vector<std::string>(args.begin() + 1, args.end()));
    cgcm::app::resolveMeshFile(*deck, args[0]);
    cgcm::io::validateDeck(*deck, *cgcm::app::validParameters());
    const auto result = cgcm::app::runSimulation(comm, *deck, std::cout);
    return result.completed ? 0 : 1;
  } catch (const cgcm::InputError& e) {
    if (root) std::cerr << "cgcm: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    // The solver stops cleanly on its own; anything else still ends with a message, not an abort.
    if (root) std::cerr << "cgcm: stopped: " << e.what() << "\n";
    return 1;
  } catch (...) {
    if (root) std::cerr << "cgcm: stopped: unknown error\n";
    return 1;
  }
}
