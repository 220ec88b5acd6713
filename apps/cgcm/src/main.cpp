// cgcm: solves the deck given on the command line.
//   cgcm DECK.xml [Path/To/Parameter=value ...]
//   cgcm --help
#include <Tpetra_Core.hpp>

#include <iostream>

#include "cgcm/app/Setup.hpp"
#include "cgcm/app/Simulation.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/io/Deck.hpp"

namespace {

void usage(std::ostream& out) {
  out << "usage: cgcm DECK.xml [Path/To/Parameter=value ...]\n"
         "       cgcm --help     (every parameter with its default and meaning)\n"
         "exit codes: 0 the whole path was followed; 1 the solver stopped (the reason is printed, the outputs\n"
         "            written so far are valid); 2 bad input (nothing was run)\n";
}

}  // namespace

int main(int argc, char** argv) {
  Tpetra::ScopeGuard scope(&argc, &argv);
  auto comm = Tpetra::getDefaultComm();
  const bool root = comm->getRank() == 0;
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty()) {
    if (root) usage(std::cerr);
    return 2;
  }
  if (args[0] == "--help" || args[0] == "-h") {
    if (root) {
      usage(std::cout);
      std::cout << "\nParameters (XML deck sublists; defaults in brackets):\n";
      cgcm::io::printHelp(std::cout, *cgcm::app::validParameters());
    }
    return 0;
  }
  try {
    auto deck = cgcm::io::readDeck(args[0]);
    cgcm::io::applyOverrides(*deck, *cgcm::app::validParameters(),
                             std::vector<std::string>(args.begin() + 1, args.end()));
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
