// cgcm: solves the deck given on the command line.
//   cgcm DECK.xml [Path/To/Parameter=value ...]
//   cgcm --restart OUTPUT_DIR [Path/To/Parameter=value ...]
//   cgcm --check DECK.xml [Path/To/Parameter=value ...]
//   cgcm --check-list FILE
//   cgcm --help | --version | --kokkos-help
#include <Tpetra_Core.hpp>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cgcm/app/Setup.hpp"
#include "cgcm/app/SizeEstimate.hpp"
#include "cgcm/app/Simulation.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/core/MallocTunables.hpp"
#include "cgcm/io/Deck.hpp"

namespace {

void usage(std::ostream& out) {
  out << "usage: cgcm DECK.xml [Path/To/Parameter=value ...]\n"
         "       cgcm --restart OUTPUT_DIR [Path/To/Parameter=value ...]\n"
         "                       (continues a killed run from OUTPUT_DIR/checkpoint.bin with its parameters.xml)\n"
         "       cgcm --check DECK.xml [Path/To/Parameter=value ...]\n"
         "                       (every check and the set-up of the problem, its size and memory; nothing solved)\n"
         "       cgcm --check-list FILE  (--check for each deck named on a line of FILE, one result line each)\n"
         "       cgcm --help     (every parameter with its default and meaning)\n"
         "       cgcm --version\n"
         "       cgcm --kokkos-help (Kokkos' run-time options)\n"
         "exit codes: 0 the whole path was followed (--check: the input is valid); 1 the solver stopped (the\n"
         "            reason is printed, the outputs written so far are valid); 2 bad input (nothing was run)\n";
}

enum class Outcome { Done = 0, Stopped = 1, BadInput = 2 };

/// One deck through the whole pipeline: read (a restart: the run's
/// parameters.xml), overrides, validation, then the run or the check. The
/// message of a failure goes to `err` (rank 0).
Outcome runDeck(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const std::vector<std::string>& args,
                cgcm::app::RunMode mode, std::ostream& out, std::ostream& err) {
  const bool root = comm->getRank() == 0;
  const bool restart = mode == cgcm::app::RunMode::Restart;
  try {
    const std::string deckPath = restart ? args[0] + "/parameters.xml" : args[0];
    std::error_code ec;
    if (restart && !std::filesystem::is_regular_file(deckPath, ec))
      throw cgcm::InputError("--restart " + args[0] + ": not the output folder of a run (no parameters.xml)");
    auto deck = cgcm::io::readDeck(deckPath);
    cgcm::io::applyOverrides(*deck, *cgcm::app::validParameters(),
                             std::vector<std::string>(args.begin() + 1, args.end()));
    if (restart) deck->sublist("Output").set("Directory", args[0]);
    cgcm::app::resolveMeshFile(*deck, deckPath);
    cgcm::io::validateDeck(*deck, *cgcm::app::validParameters());
    const auto result = cgcm::app::runSimulation(comm, *deck, out, mode);
    if (mode == cgcm::app::RunMode::Check && root) {
      const auto formulation = cgcm::parseFormulation(deck->sublist("Problem").get<std::string>("Formulation"));
      const auto size = cgcm::app::estimateSize(double(result.numNodes), double(result.numCells), formulation);
      out << "cgcm: " << args[0] << ": valid; " << result.numNodes << " nodes, " << result.numCells << " cells, "
          << result.numDofs << " unknowns, about " << int(size.megabytes) << " MB\n";
    }
    return result.completed ? Outcome::Done : Outcome::Stopped;
  } catch (const cgcm::InputError& e) {
    if (root) err << "cgcm: error: " << e.what() << "\n";
    return Outcome::BadInput;
  } catch (const std::exception& e) {
    // The solver stops cleanly on its own; anything else still ends with a message, not an abort.
    if (root) err << "cgcm: stopped: " << e.what() << "\n";
    return Outcome::Stopped;
  } catch (...) {
    if (root) err << "cgcm: stopped: unknown error\n";
    return Outcome::Stopped;
  }
}

}  // namespace

int main(int argc, char** argv) {
  cgcm::core::tuneMalloc(argv);
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
  auto mode = cgcm::app::RunMode::Run;
  if (!args.empty() && (args[0] == "--restart" || args[0] == "--check")) {
    mode = args[0] == "--restart" ? cgcm::app::RunMode::Restart : cgcm::app::RunMode::Check;
    args.erase(args.begin());
  } else if (args.size() == 2 && args[0] == "--check-list") {
    // one line per deck: the deck, then its outcome and message (a fuzzing and CI aid)
    std::ifstream list(args[1]);
    if (!list) {
      if (root) std::cerr << "cgcm: error: --check-list " << args[1] << ": cannot read it\n";
      return 2;
    }
    for (std::string deck; std::getline(list, deck);) {
      if (deck.empty()) continue;
      std::ostringstream out, err;
      const Outcome o = runDeck(comm, {deck}, cgcm::app::RunMode::Check, out, err);
      // the refusal, or the check's last line (size and memory)
      std::string message = err.str();
      if (message.empty()) {
        std::string line;
        for (std::istringstream lines(out.str()); std::getline(lines, line);)
          if (!line.empty()) message = line;
      }
      for (char& c : message)
        if (c == '\n') c = ' ';
      if (root) std::cout << deck << "\t" << int(o) << "\t" << message << std::endl;
    }
    return 0;
  }
  if (args.empty() || args[0].rfind("--", 0) == 0) {
    if (root) usage(std::cerr);
    return 2;
  }
  return int(runDeck(comm, args, mode, std::cout, std::cerr));
}
