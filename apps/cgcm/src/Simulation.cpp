#include "cgcm/app/Simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>

#include <sys/resource.h>

#include <Teuchos_CommHelpers.hpp>

#include "cgcm/app/Recorder.hpp"
#include "cgcm/app/Setup.hpp"
#include "cgcm/app/Summary.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/io/Deck.hpp"
#include "cgcm/solver/Checkpoint.hpp"
#include "cgcm/solver/Continuation.hpp"
#include "cgcm/solver/LinearSolver.hpp"
#include "cgcm/solver/LoadStepper.hpp"
#include "cgcm/solver/PathFollower.hpp"

namespace cgcm::app {

using assembly::Vector;
using solver::Checkpoint;

namespace {

// The output folder: created, with the run's parameters.xml (a restart keeps
// its own); --check only tells whether it could be.
void prepareOutput(const Teuchos::Comm<int>& comm, const Teuchos::ParameterList& deck, const std::string& dir,
                   RunMode mode) {
  solver::runOnRoot(comm, [&] {
    if (mode == RunMode::Restart) return;
    // the error_code forms: a name the file system refuses is bad input, not an exception
    std::error_code ec;
    if (mode == RunMode::Check) {
      const bool exists = std::filesystem::exists(dir, ec);
      if (ec || (exists && !std::filesystem::is_directory(dir, ec)))
        throw InputError("Output/Directory = \"" + dir + "\": cannot create it (" +
                         (ec ? ec.message() : "a file of that name exists") + ")");
      return;
    }
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir, ec))
      throw InputError("Output/Directory = \"" + dir + "\": cannot create it (" +
                       (ec ? ec.message() : "a file of that name exists") + ")");
    io::writeDeck(deck, dir + "/parameters.xml");
  });
}

// checkpoint.bin after every accepted state of a displacement-controlled path
// (collective: the ranks stream the vectors to rank 0 as it writes).
solver::LoadStepper::CheckpointSink checkpointSink(const Teuchos::RCP<const Teuchos::Comm<int>>& comm,
                                                  const std::string& dir, const Recorder& recorder,
                                                  const Real& lastDisplacement, bool root) {
  auto failed = std::make_shared<bool>(false);
  return [comm, &recorder, &lastDisplacement, dir, root, failed](const solver::StepperState& s, const Vector& state,
                                                                 const Vector& before) {
    Checkpoint c;
    c.stepper = s;
    c.lastDisplacement = lastDisplacement;
    c.exodusSteps = recorder.exodusSteps();
    c.curve = recorder.curve;
    if (!solver::writeCheckpoint(*comm, dir, c, state, s.havePrevious ? &before : nullptr) && !*failed) {
      *failed = true;
      if (root)
        std::cerr << "cgcm: warning: cannot write " << solver::checkpointPath(dir) << "; the run goes on without\n";
    }
  };
}

// What the run cost: solves, the Jacobian's size, memory and mesh per rank,
// the assembly timings since `before`, Method 1's pair statistics.
void measureCost(RunResult& result, const solver::Discretization& disc, const solver::NewtonSolver& newton,
                 const assembly::AssemblyTimings& timingsBefore) {
  const auto& problem = disc.problem;
  // LOCA does not report its solves (its groups do not log them to NOX's statistics).
  result.linearSolves = newton.linearSolves().solves;
  result.krylovIterations = newton.linearSolves().iterations;
  const auto graph = problem->graph();  // collective only when it has to be built
  result.numDofs = disc.dofs->ownedMap()->getGlobalNumElements();
  result.matrixRows = graph->getGlobalNumRows();
  result.matrixEntries = graph->getGlobalNumEntries();
  {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);  // ru_maxrss in KiB on Linux
    const Teuchos::Comm<int>& comm = *disc.dofs->comm();
    const double mine = double(usage.ru_maxrss) / 1024.0;
    result.peakMemoryMB.assign(comm.getSize(), 0.0);
    Teuchos::gatherAll(comm, 1, &mine, comm.getSize(), result.peakMemoryMB.data());
    // the interacting surfaces a rank holds: its own facets and (Method 3) the ghosts near them
    long own = 0, ghosts = 0;
    for (const auto& s : disc.mesh->surfaces) own += long(s.numFacets());
    if (const auto* part = problem->surfaceInteractionPart()) {
      ghosts = part->held().numGhostFacets();
      result.surfaceGathers = part->held().numGathers();
    }
    const long held[4] = {long(disc.mesh->numCells()), long(disc.mesh->numNodes()), own, ghosts};
    std::vector<long> all(4 * std::size_t(comm.getSize()));
    Teuchos::gatherAll(comm, 4, held, int(all.size()), all.data());
    for (int r = 0; r < comm.getSize(); ++r)
      result.meshHeld.push_back({all[4 * r], all[4 * r + 1], all[4 * r + 2], all[4 * r + 3]});
  }
  const auto& t = problem->timings();
  result.assemblySeconds = (t.residual + t.jacobian) - (timingsBefore.residual + timingsBefore.jacobian);
  result.interactionSeconds = t.interaction - timingsBefore.interaction;
  result.searchSeconds = t.search - timingsBefore.search;
  result.graphSeconds = t.graph - timingsBefore.graph;
  if (const auto* volume = problem->volumeInteraction()) {
    const auto& vs = volume->summary();
    // each rank lists the pairs of its own cells: sums over the ranks
    LocalIndex numPairs = 0, atMax = 0, above = 0;
    int maxOrder = 0;
    Real maxEstimate = 0.0;
    Teuchos::reduceAll(*disc.dofs->comm(), Teuchos::REDUCE_SUM, vs.numAboveTolerance, Teuchos::outArg(above));
    Teuchos::reduceAll(*disc.dofs->comm(), Teuchos::REDUCE_MAX, vs.maxErrorEstimate, Teuchos::outArg(maxEstimate));
    Teuchos::reduceAll(*disc.dofs->comm(), Teuchos::REDUCE_MAX, vs.maxOrderUsed, Teuchos::outArg(maxOrder));
    Teuchos::reduceAll(*disc.dofs->comm(), Teuchos::REDUCE_SUM, vs.numPairs, Teuchos::outArg(numPairs));
    Teuchos::reduceAll(*disc.dofs->comm(), Teuchos::REDUCE_SUM, vs.numAtMaxOrder, Teuchos::outArg(atMax));
    long pointPairs = 0, totalPairs = 0;  // of the last evaluation and of all
    double kernelSeconds = 0.0;           // the slowest rank's
    Teuchos::reduceAll(*disc.dofs->comm(), Teuchos::REDUCE_SUM, vs.numPointPairs, Teuchos::outArg(pointPairs));
    Teuchos::reduceAll(*disc.dofs->comm(), Teuchos::REDUCE_SUM, vs.totalPointPairs, Teuchos::outArg(totalPairs));
    Teuchos::reduceAll(*disc.dofs->comm(), Teuchos::REDUCE_MAX, vs.kernelSeconds, Teuchos::outArg(kernelSeconds));
    std::ostringstream o;
    o << "volume pairs (Method 1): " << numPairs << " directed cell pairs within cutoff + skin = "
      << vs.cutoff + vs.skin << ", " << pointPairs << " quadrature-point pairs per evaluation, quadrature orders up to "
      << maxOrder << " (" << atMax << " pairs at the maximum " << volume->maxQuadratureOrder() << ", " << above
      << " above the tolerance " << volume->options().quadratureTolerance << "; estimated pair error up to "
      << maxEstimate << " of a pair's force), " << vs.numListBuilds << " pair lists built; kernel "
      << kernelSeconds << " s for " << totalPairs
      << " point pairs (" << 1e-6 * double(totalPairs) / std::max(kernelSeconds, 1e-300) << " M/s)";
    result.volumePairs = o.str();
  }

}

// The deck's Loading sublist for this problem: gammaW and gammaL can be continued in when the bodies interact.
solver::PathPlan planOf(const Teuchos::ParameterList& deck, const solver::ProblemSetup& setup) {
  if (!setup.interaction) return solver::PathPlan(deck.sublist("Loading"), {}, 0.0);
  return solver::PathPlan(deck.sublist("Loading"), {"gammaW", "gammaL"}, setup.interaction->potential->r0());
}

// Solver/Newton with the problem's force scale.
solver::NewtonSettings newtonSettingsOf(const Teuchos::ParameterList& deck, const solver::ProblemSetup& setup) {
  auto settings = solver::NewtonSettings::fromParameters(deck.sublist("Solver").sublist("Newton"),
                                                         deck.sublist("Solver").sublist("Linear Solver"));
  settings.forceScale = setup.forceScale;
  return settings;
}

// --restart: the checkpoint of a run the plan can continue.
std::optional<Checkpoint> resumeOf(RunMode mode, const solver::PathPlan& plan, const std::string& dir) {
  if (mode != RunMode::Restart) return std::nullopt;
  if (!plan.follower().restartable() || plan.parameter() != "u")
    throw InputError("--restart " + dir + ": only runs under displacement control can be continued "
                     "(Loading/Control = \"displacement\" and Continuation Parameter = \"u\")");
  try {
    return solver::readCheckpointHeader(dir);  // the vectors later, into the ranks' parts (initialGuess)
  } catch (const solver::MissingCheckpoint& e) {
    throw InputError("--restart " + dir + ": " + e.what() +
                     ": the run recorded no state, or Output/Checkpoint was false");
  } catch (const InputError& e) {
    throw InputError("--restart " + dir + ": " + e.what());
  }
}

// The solvers the path needs, and where a restart resumes.
solver::PathContext pathContext(const solver::Discretization& disc, solver::NewtonSolver& newton,
                                solver::Continuation& continuation, const std::optional<Checkpoint>& resume,
                                const Vector& previous) {
  solver::PathContext context;
  context.model = disc.model;
  context.newton = &newton;
  context.continuation = &continuation;
  if (resume) context.resume = &resume->stepper;
  if (resume && resume->stepper.havePrevious) context.resumePrevious = &previous;
  return context;
}

// A converged step whose gap moved much more than the prescribed displacement
// (since `lastDisplacement`, the last state that was no fold) left its branch.
solver::LoadStepper::ContinuityCheck continuityCheck(const ContactProbe& probe, const solver::ModelEvaluator& model,
                                                     const Real& lastDisplacement, Real floor) {
  return [&probe, &model, &lastDisplacement, floor](const Vector& before, const Vector& after) {
    const Real du = std::abs(model.displacement() - lastDisplacement);
    return std::abs(probe.gap(after) - probe.gap(before)) <= std::max(5.0 * du, floor);
  };
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The run's first lines: the problem's size, the control, the set-up's report, the convergence test.
void logStart(std::ostream& log, const solver::ProblemSetup& setup, const solver::PathPlan& plan, long numDofs,
              int ranks, const solver::NewtonSettings& newton) {
  log << "cgcm: " << formulationName(setup.formulation) << ", " << setup.numNodes << " nodes, " << setup.numCells
      << " cells, " << numDofs << " dofs, " << ranks << " rank(s); " << plan.follower().name() << " control\n";
  for (const auto& line : setup.report) log << "cgcm: " << line << "\n";
  log << "cgcm: a state is accepted when |f|_2 <= " << newton.tolerance() << " (Residual Tolerance "
      << newton.residualTolerance << " x F_ref " << setup.forceScale << ")";
  const Real Y = setup.material.youngsModulus();
  if (std::any_of(setup.bodyMaterials.begin(), setup.bodyMaterials.end(),
                  [&](const material::NeoHookean& m) { return m.youngsModulus() > Y; }))
    log << "; the residual of a body stiffer than Material's Young's modulus Y counts divided by Y_body/Y";
  log << "\n";
}

// The initial guess: the prescribed motion of whole bodies at the first u (a
// restart: the checkpoint's state of `dir`, and the one before it in `previous`).
void initialGuess(const solver::ProblemSetup& setup, const solver::Discretization& disc, const solver::PathPlan& plan,
                  const Checkpoint* resume, const std::string& dir, Vector& u, Vector& previous) {
  if (resume) {
    solver::readCheckpointVectors(dir, u, resume->stepper.havePrevious ? &previous : nullptr);
  } else if (!setup.model.initialMotion.empty()) {
    assembly::DirichletConditions motion(disc.dofs);
    for (const auto& c : setup.model.initialMotion)
      motion.add(disc.mesh->nodeSet(c.nodeSet), c.component, c.offset, c.scale);
    motion.impose(plan.path().path.front(), u);
  }
  disc.model->setDisplacement(resume ? resume->stepper.displacement : plan.path().path.front());
}

}  // namespace

RunResult runSimulation(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const Teuchos::ParameterList& deck,
                        std::ostream& log, RunMode mode) {
  const bool root = comm->getRank() == 0;
  const auto& out = deck.sublist("Output");
  const std::string dir = out.get<std::string>("Directory");
  const bool printSteps = out.get<bool>("Print Steps");

  // Build: everything that can be rejected is checked before any work starts.
  const auto setupStart = std::chrono::steady_clock::now();
  solver::ProblemSetup setup = buildProblem(*comm, deck);  // rank 0 builds the mesh
  const double meshSeconds = secondsSince(setupStart);
  const solver::PathPlan plan = planOf(deck, setup);
  if (plan.branchSwitching() && out.get<int>("Eigenvalues") == 0)
    throw InputError("Loading/Branch Switching = true: branch points are found from the tangent's eigenvalues; "
                     "set Output/Eigenvalues > 0 (e.g. 3)");
  if (plan.branchSwitching() && !plan.follower().tracesUnstableBranches() && plan.parameter() == "u")
    throw InputError("Loading/Branch Switching = true: branch points are located on arc-length paths only; set "
                     "Loading/Control = \"arc-length\" (or continue in a Continuation Parameter)");
  const solver::NewtonSettings newtonSettings = newtonSettingsOf(deck, setup);
  const auto& linearSolverSettings = deck.sublist("Solver").sublist("Linear Solver");
  const int dim = formulationDim(setup.formulation);
  solver::buildLinearSolver(linearSolverSettings, comm->getSize(), dim, Teuchos::null, !setup.interaction);
  const std::optional<Checkpoint> resume = resumeOf(mode, plan, dir);
  prepareOutput(*comm, deck, dir, mode);
  const auto distributionStart = std::chrono::steady_clock::now();
  const solver::Discretization disc = solver::discretize(comm, setup, linearSolverSettings);
  const double distributionSeconds = secondsSince(distributionStart);
  std::size_t numSurfaceFacets = 0;
  if (setup.model.mesh)
    for (const auto& s : setup.model.mesh->surfaces) numSurfaceFacets += std::size_t(s.numFacets());
  // Rank 0 lets the whole mesh go: from here on every rank holds its part alone (disc.mesh), results.e too.
  setup.model.mesh.reset();
  const long numDofs = long(disc.dofs->ownedMap()->getGlobalNumElements());
  if (resume && long(resume->unknowns) != numDofs)
    throw InputError("--restart " + dir + ": the checkpoint holds " + std::to_string(resume->unknowns) +
                     " unknowns, the deck's problem " + std::to_string(numDofs) +
                     " (parameters.xml or the mesh changed since)");
  const auto& model = disc.model;
  solver::NewtonSolver newton(model, newtonSettings);
  const auto loca = plan.locaParameters(deck.isSublist("LOCA") ? deck.sublist("LOCA") : Teuchos::ParameterList("LOCA"));
  solver::Continuation continuation(model, newtonSettings, loca, printSteps && newtonSettings.printIterations);
  if (continuation.followsFolds() && plan.parameter() == "u")
    throw InputError("LOCA/Bifurcation/Type = Turning Point follows the Approach Path's first fold in a second "
                     "parameter: set Loading/Continuation Parameter (gammaW or gammaL) and its Parameter Path");
  std::unique_ptr<ContactProbe> probe;
  if (setup.model.contact) probe = std::make_unique<ContactProbe>(*setup.model.contact, *disc.mesh, *disc.problem);
  if (root && printSteps) logStart(log, setup, plan, numDofs, comm->getSize(), newtonSettings);
  Vector u(model->map()), previous(model->map());
  initialGuess(setup, disc, plan, resume ? &*resume : nullptr, dir, u, previous);
  if (plan.usesContinuation()) continuation.validate(u);  // LOCA reads its list: typos stop here
  RunResult result;
  result.numNodes = setup.numNodes, result.numCells = setup.numCells, result.numDofs = std::size_t(numDofs);
  if (mode == RunMode::Check) return result.completed = true, result;
  if (root) std::ofstream(dir + "/summary.txt") << "running" << (resume ? " (restarted after step " +
                                                   std::to_string(resume->stepper.step) + ")" : "") << "\n";

  // Follow the path, recording every accepted state (a checkpoint after each, under displacement control).
  const int eigenvalues = out.get<int>("Eigenvalues");
  Recorder recorder(setup, disc, probe.get(), dir, out.get<bool>("Exodus"), model->parameterIndex(plan.parameter()),
                    printSteps, log, resume ? &*resume : nullptr, eigenvalues, continuation.followsFolds());
  Real lastDisplacement = resume ? resume->lastDisplacement : plan.path().path.front();  // of the last state that was no fold
  solver::PathContext context = pathContext(disc, newton, continuation, resume, previous);
  if (eigenvalues > 0) context.spectrum = std::make_shared<solver::TangentSpectrum>(model, eigenvalues);
  if (out.get<bool>("Checkpoint")) context.checkpoint = checkpointSink(comm, dir, recorder, lastDisplacement, root);
  if (probe) context.continuity = continuityCheck(*probe, *model, lastDisplacement, 0.05 * setup.interaction->potential->r0());
  const auto runStart = std::chrono::steady_clock::now();
  const assembly::AssemblyTimings timingsBefore = disc.problem->timings();
  try {
    const auto cost = plan.follow(u, context, [&](const solver::PathState& state) {
      recorder.record(state);
      if (!state.fold) lastDisplacement = state.p[0];
    });
    result.continuationSteps = cost.continuationSteps, result.graphRestarts = cost.graphRestarts;
    result.pathNotes = cost.notes;
    result.completed = true;
  } catch (const NumericalError& e) {
    result.failure = e.what();
    if (root)
      std::cerr << "cgcm: stopped after step " << (recorder.curve.empty() ? 0 : recorder.curve.back().step) << ": "
                << e.what() << "\n";
  }
  result.pathSeconds = secondsSince(runStart);

  // Summarise: minimum force, folds, jumps, hysteresis, cost (also when the run stopped).
  result.curve = recorder.curve;
  result.meshSeconds = meshSeconds, result.distributionSeconds = distributionSeconds;
  result.resultsMeshSeconds = recorder.resultsMeshSeconds(), result.resultsSeconds = recorder.resultsStepSeconds();
  result.meshSource = setup.model.meshSource;
  result.numSurfaceFacets = numSurfaceFacets;
  result.linearSolver = solver::resolvedLinearSolverType(linearSolverSettings, dim);
  measureCost(result, disc, newton, timingsBefore);
  if (root) writeSummary(dir + "/summary.txt", result, plan, printSteps ? &log : nullptr);
  if (root && printSteps) log << "cgcm: outputs in " << dir << "/\n";
  return result;
}

}  // namespace cgcm::app
