// cgcm: solves the deck given on the command line.
//   cgcm DECK.xml [Path/To/Parameter=value ...]
//   cgcm --help | --version | --kokkos-help
#include <Tpetra_Core.hpp>

#include <cstring>
#include <filesystem>
#include <iostream>

#include "cgcm/app/Setup.hpp"
#include "cgcm/app/Simulation.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/io/Deck.hpp"

namespace {

void usage(std::ostream& out) {
  out << "usage: cgcm DECK.xml [Path/To/Parameter=value ...]\n"
         "       cgcm --restart OUTPUT_DIR [Path/To/Parameter=value ...]\n"
         "                       (continues a killed run from OUTPUT_DIR/checkpoint.bin with its parameters.xml)\n"
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
  const bool restart = !args.empty() && args[0] == "--restart";
  if (restart) args.erase(args.begin());
  if (args.empty() || args[0].rfind("--", 0) == 0) {
    if (root) usage(std::cerr);
    return 2;
  }
  try {
    // a restart reads the parameters the run echoed into its folder, and writes there
    const std::string deckPath = restart ? args[0] + "/parameters.xml" : args[0];
    if (restart && !std::filesystem::is_regular_file(deckPath))
      throw cgcm::InputError("--restart " + args[0] + ": not the output folder of a run (no parameters.xml)");
    auto deck = cgcm::io::readDeck(deckPath);
    cgcm::io::applyOverrides(*deck, *cgcm::app::validParameters(),
                             std::vector<std::string>(args.begin() + 1, args.end()));
    if (restart) deck->sublist("Output").set("Directory", args[0]);
    cgcm::app::resolveMeshFile(*deck, deckPath);
    cgcm::io::validateDeck(*deck, *cgcm::app::validParameters());
    const auto result = cgcm::app::runSimulation(comm, *deck, std::cout, restart);
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
