#include "cgcm/app/Simulation.hpp"

#include <cstdio>
#include <filesystem>

#include "cgcm/app/Setup.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/io/CsvWriter.hpp"
#include "cgcm/io/Deck.hpp"
#include "cgcm/solver/LinearSolver.hpp"
#include "cgcm/solver/LoadStepper.hpp"

namespace cgcm::app {

using assembly::Vector;

RunResult runSimulation(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const Teuchos::ParameterList& deck,
                        std::ostream& log) {
  const bool root = comm->getRank() == 0;
  const auto& out = deck.sublist("Output");
  const std::string dir = out.get<std::string>("Directory");
  const bool printSteps = out.get<bool>("Print Steps");

  // Everything that can be rejected is checked before any work starts.
  ProblemSetup setup = buildProblem(deck);
  const auto loading = solver::LoadPathSettings::fromParameters(deck.sublist("Loading"));
  const auto newtonSettings = solver::NewtonSettings::fromParameters(deck.sublist("Solver").sublist("Newton"));
  auto linearSolver = solver::buildLinearSolver(deck.sublist("Solver").sublist("Linear Solver"), comm->getSize(),
                                                assembly::formulationDim(setup.formulation));
  for (const auto& c : setup.conditions) setup.mesh->nodeSet(c.nodeSet);

  if (root) {
    std::filesystem::create_directories(dir);
    io::writeDeck(deck, dir + "/parameters.xml");
  }
  comm->barrier();

  const int dim = assembly::formulationDim(setup.formulation);
  auto dofs = Teuchos::rcp(new assembly::DofMap(comm, *setup.mesh, dim));
  auto assembler = std::make_shared<assembly::Assembler>(dofs, setup.mesh, setup.formulation, setup.material);
  auto dirichlet = std::make_shared<assembly::DirichletConditions>(dofs);
  for (const auto& c : setup.conditions)
    dirichlet->add(setup.mesh->nodeSet(c.nodeSet), c.component, c.offset, c.scale);
  auto model = Teuchos::rcp(new solver::ModelEvaluator(assembler, dirichlet, linearSolver));
  solver::NewtonSolver newton(model, newtonSettings);

  if (root && printSteps)
    log << "cgcm: " << assembly::formulationName(setup.formulation) << ", " << setup.mesh->numNodes() << " nodes, "
        << setup.mesh->numCells() << " cells, " << dofs->ownedMap()->getGlobalNumElements() << " dofs, "
        << comm->getSize() << " rank(s)\n";

  std::unique_ptr<io::CsvWriter> csv;
  if (root) csv = std::make_unique<io::CsvWriter>(dir + "/load_curve.csv",
                                                  std::vector<std::string>{"step", "u", "P", "newton_iterations",
                                                                           "residual", "cutbacks"});
  RunResult result;
  Vector u(model->map());
  Vector f(model->map());
  const auto& loadNodes = setup.mesh->nodeSet(setup.load.nodeSet);
  auto observe = [&](const solver::StepInfo& info, const Vector& uSolved) {
    model->evaluateUnconstrained(uSolved, f);
    const Real P = setup.load.sign * assembler->sumOverNodes(f, loadNodes, setup.load.component);
    const Real res = info.newton.residualNorms.empty() ? 0.0 : info.newton.residualNorms.back();
    result.curve.push_back({info.step, info.load, P, info.newton.iterations, res});
    result.newtonSeconds += info.newton.seconds;
    if (!root) return;
    csv->row({double(info.step), info.load, P, double(info.newton.iterations), res, double(info.cutbacks)});
    if (printSteps) {
      char line[200];
      std::snprintf(line, sizeof line, "step %4d  u = %+.6e  P = %+.6e  newton %2d  |f| = %.2e%s\n", info.step,
                    info.load, P, info.newton.iterations, res,
                    info.cutbacks ? ("  (" + std::to_string(info.cutbacks) + " cut-backs)").c_str() : "");
      log << line << std::flush;
    }
  };

  solver::LoadStepper stepper(model, newton, loading);
  try {
    stepper.run(u, observe);
    result.completed = true;
  } catch (const NumericalError& e) {
    result.failure = e.what();
    if (root) log << "cgcm: stopped: " << e.what() << "\n";
  }
  result.assemblySeconds = assembler->timings().residual + assembler->timings().jacobian;
  if (root && printSteps)
    log << "cgcm: " << result.curve.size() << " states written to " << dir << "/load_curve.csv\n";
  return result;
}

}  // namespace cgcm::app
