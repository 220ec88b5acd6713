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

#include "cgcm/app/Checkpoint.hpp"
#include "cgcm/app/Recorder.hpp"
#include "cgcm/app/Setup.hpp"
#include "cgcm/app/Summary.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/io/Deck.hpp"
#include "cgcm/solver/Continuation.hpp"
#include "cgcm/solver/LinearSolver.hpp"
#include "cgcm/solver/LoadStepper.hpp"

namespace cgcm::app {

using assembly::Vector;

namespace {

// What the Loading sublist asks for, checked before any work.
struct PathPlan {
  bool arcLength = false;
  solver::LoadPathSettings path;
  std::string parameter = "u";
  std::vector<Real> parameterPath;  ///< waypoints of the parameter (not u)
  std::vector<Real> bounds;         ///< {lower, upper} or empty
};

PathPlan planPath(const Teuchos::ParameterList& loading, const ProblemSetup& setup) {
  PathPlan plan;
  plan.arcLength = loading.get<std::string>("Control") == "arc-length";
  plan.path = solver::LoadPathSettings::fromParameters(loading);
  // A jump relaxes in moves of at most a quarter of the interaction length, so that
  // no iterate skips the equilibrium spacing or pushes a surface through another.
  if (setup.interaction) plan.path.relaxation.maxIncrement = 0.25 * setup.interaction->potential->r0();
  plan.parameter = loading.get<std::string>("Continuation Parameter");
  const auto& pp = loading.get<Teuchos::Array<double>>("Parameter Path");
  plan.parameterPath.assign(pp.begin(), pp.end());
  const auto& b = loading.get<Teuchos::Array<double>>("Parameter Bounds");
  plan.bounds.assign(b.begin(), b.end());
  if (plan.parameter != "u" && !setup.interaction)
    throw InputError("Loading/Continuation Parameter = \"" + plan.parameter +
                     "\" needs an interaction between bodies (a sphere geometry); allowed here: \"u\"");
  if (plan.parameter == "u" && !plan.parameterPath.empty())
    throw InputError("Loading/Parameter Path: only with a Continuation Parameter other than \"u\"; the path in u "
                     "is Loading/Approach Path");
  if (plan.parameter != "u" && plan.parameterPath.empty())
    throw InputError("Loading/Parameter Path: give the waypoints of " + plan.parameter + " (e.g. {100, 20})");
  for (std::size_t i = 0; i < plan.parameterPath.size(); ++i)
    if (!std::isfinite(plan.parameterPath[i]) || !(plan.parameterPath[i] > 0.0))
      throw InputError("Loading/Parameter Path: waypoint " + std::to_string(i) + " = " +
                       std::to_string(plan.parameterPath[i]) + "; " + plan.parameter + " must be finite and > 0");
  if (!plan.bounds.empty()) {
    if (plan.bounds.size() != 2 || !(plan.bounds[0] < plan.bounds[1]) || !std::isfinite(plan.bounds[0]) ||
        !std::isfinite(plan.bounds[1]))
      throw InputError("Loading/Parameter Bounds: give {lower, upper} with lower < upper (finite), or leave it empty");
    const auto& wp = plan.parameter == "u" ? plan.path.path : plan.parameterPath;
    for (Real v : wp)
      if (v < plan.bounds[0] || v > plan.bounds[1])
        throw InputError("Loading/Parameter Bounds: the path value " + std::to_string(v) + " lies outside {" +
                         std::to_string(plan.bounds[0]) + ", " + std::to_string(plan.bounds[1]) + "}");
  }
  return plan;
}

// The bound beyond which a continuation segment from `start` towards
// `target` counts as run away: the deck's bounds, or the path's range widened
// by twice its span (positive parameters stay above a thousandth of the path's smallest value).
Real runawayBound(const PathPlan& plan, const std::vector<Real>& waypoints, Real direction, bool positive) {
  if (!plan.bounds.empty()) return direction > 0 ? plan.bounds[0] : plan.bounds[1];
  const auto [lo, hi] = std::minmax_element(waypoints.begin(), waypoints.end());
  const Real span = *hi - *lo;
  if (direction > 0) return positive ? std::max(*lo - 2.0 * span, 1e-3 * *lo) : *lo - 2.0 * span;
  return *hi + 2.0 * span;
}

}  // namespace

RunResult runSimulation(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const Teuchos::ParameterList& deck,
                        std::ostream& log, RunMode mode) {
  const bool restart = mode == RunMode::Restart, checkOnly = mode == RunMode::Check;
  const bool root = comm->getRank() == 0;
  const auto& out = deck.sublist("Output");
  const std::string dir = out.get<std::string>("Directory");
  const bool printSteps = out.get<bool>("Print Steps");

  // Everything that can be rejected is checked before any work starts.
  const auto setupStart = std::chrono::steady_clock::now();
  // rank 0 builds the mesh; the other ranks receive their parts in discretize()
  const ProblemSetup setup = buildProblem(*comm, deck);
  const double meshSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - setupStart).count();
  const PathPlan plan = planPath(deck.sublist("Loading"), setup);
  auto newtonSettings = solver::NewtonSettings::fromParameters(deck.sublist("Solver").sublist("Newton"),
                                                               deck.sublist("Solver").sublist("Linear Solver"));
  newtonSettings.forceScale = setup.forceScale;
  const int dim = formulationDim(setup.formulation);
  const auto& linearSolverSettings = deck.sublist("Solver").sublist("Linear Solver");
  // rejects bad settings now
  solver::buildLinearSolver(linearSolverSettings, comm->getSize(), dim, Teuchos::null, !setup.interaction.has_value());
  const std::string linearSolverType = solver::resolvedLinearSolverType(linearSolverSettings, dim);
  Teuchos::ParameterList loca = deck.isSublist("LOCA") ? deck.sublist("LOCA") : Teuchos::ParameterList("LOCA");
  {
    // Step sizes in the problem's units unless the deck gives LOCA's own.
    auto& step = loca.sublist("Step Size");
    if (!step.isParameter("Min Step Size")) step.set("Min Step Size", plan.path.minIncrement);
    if (!step.isParameter("Max Step Size") && plan.parameter == "u") step.set("Max Step Size", plan.path.maxIncrement);
  }

  std::optional<Checkpoint> resume;
  if (restart) {
    if (plan.arcLength || plan.parameter != "u")
      throw InputError("--restart " + dir + ": only runs under displacement control can be continued "
                       "(Loading/Control = \"displacement\" and Continuation Parameter = \"u\")");
    resume = readCheckpoint(dir);
  }
  runOnRoot(*comm, [&] {
    if (restart) return;  // the folder and its parameters.xml are the run's own
    // the error_code forms: a name the file system refuses is bad input, not an exception
    std::error_code ec;
    if (checkOnly) {
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

  const auto distributionStart = std::chrono::steady_clock::now();
  const Discretization disc = discretize(comm, setup, linearSolverSettings);
  const double distributionSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - distributionStart).count();
  const std::size_t numNodes = setup.numNodes, numCells = setup.numCells;
  if (resume && resume->u.size() != disc.dofs->ownedMap()->getGlobalNumElements())
    throw InputError("--restart " + dir + ": the checkpoint holds " + std::to_string(resume->u.size()) +
                     " unknowns, the deck's problem " +
                     std::to_string(disc.dofs->ownedMap()->getGlobalNumElements()) +
                     " (parameters.xml or the mesh changed since)");
  const auto& problem = disc.problem;
  const auto& model = disc.model;
  solver::NewtonSolver newton(model, newtonSettings);
  solver::Continuation continuation(model, newtonSettings, loca, printSteps && newtonSettings.printIterations);
  std::unique_ptr<ContactProbe> probe;
  if (setup.model.contact) probe = std::make_unique<ContactProbe>(*setup.model.contact, *disc.mesh, *problem);
  const int parameterIndex = model->parameterIndex(plan.parameter);

  if (root && printSteps) {
    log << "cgcm: " << formulationName(setup.formulation) << ", " << numNodes << " nodes, " << numCells
        << " cells, " << disc.dofs->ownedMap()->getGlobalNumElements() << " dofs, "
        << comm->getSize() << " rank(s); " << (plan.arcLength ? "arc-length" : "displacement") << " control\n";
    for (const auto& line : setup.report) log << "cgcm: " << line << "\n";
    log << "cgcm: a state is accepted when |f|_2 <= " << newtonSettings.tolerance() << " (Residual Tolerance "
        << newtonSettings.residualTolerance << " x F_ref " << setup.forceScale << ")\n";
  }

  if (checkOnly) {
    Vector u(model->map());
    model->setLoad(plan.path.path.front());
    if (plan.arcLength || plan.parameter != "u") continuation.validate(u);
    RunResult checked;
    checked.completed = true;
    checked.numNodes = numNodes;
    checked.numCells = numCells;
    checked.numDofs = disc.dofs->ownedMap()->getGlobalNumElements();
    return checked;
  }

  // The summary says what the run is doing until it ends.
  if (root) {
    std::ofstream running(dir + "/summary.txt");
    running << "running" << (resume ? " (restarted after step " + std::to_string(resume->stepper.step) + ")" : "")
            << "\n";
  }

  // The initial guess: the prescribed motion of whole bodies at the first u
  // (a restart: the checkpoint's state).
  Vector u(model->map());
  RootGather gather(disc.dofs->ownedMap());
  Vector previous(model->map());
  if (resume) {
    gather.scatter(resume->u, u);
    if (resume->stepper.havePrevious) gather.scatter(resume->previous, previous);
  } else if (!setup.model.initialMotion.empty()) {
    assembly::DirichletConditions motion(disc.dofs);
    for (const auto& c : setup.model.initialMotion)
      motion.add(disc.mesh->nodeSet(c.nodeSet), c.component, c.offset, c.scale);
    motion.impose(plan.path.path.front(), u);
  }
  model->setLoad(resume ? resume->stepper.load : plan.path.path.front());
  if (plan.arcLength || plan.parameter != "u") continuation.validate(u);  // LOCA reads its list: typos stop here

  Recorder recorder(setup, disc, probe.get(), dir, out.get<bool>("Exodus"), parameterIndex, printSteps, log,
                    resume ? &*resume : nullptr);
  RunResult result;
  int step = resume ? resume->stepper.step : 0;
  bool stable = true;
  auto recordPoint = [&](const solver::PathPoint& pt) {
    LoadPoint row;
    row.step = ++step;
    row.newtonIterations = pt.iterations;
    row.stable = pt.stable;
    row.fold = pt.fold;
    row.residual = pt.residual;
    recorder.record(*pt.x, pt.p, row);
    stable = pt.stable;
  };
  // One continuation segment from the current state; throws NumericalError if it stops.
  auto continueTo = [&](int parameter, Real target, const std::vector<Real>& waypoints, Real initialStep) {
    const Real from = model->parameter(parameter);
    solver::ContinuationSegment segment;
    segment.parameter = parameter;
    segment.target = target;
    segment.direction = target > from ? 1.0 : -1.0;
    segment.bound = runawayBound(plan, waypoints, segment.direction, parameter > 0);
    segment.initialStep = std::min(initialStep, std::abs(target - from));
    segment.stableStart = stable;
    const auto r = continuation.run(u, segment, recordPoint);
    result.continuationSteps += r.steps;
    result.graphRestarts += r.restarts;
    if (!r.reached) throw NumericalError(r.failure);
    u.assign(*r.last.x);
    for (std::size_t k = 0; k < r.last.p.size(); ++k) model->setParameter(int(k), r.last.p[k]);
  };

  auto runStart = std::chrono::steady_clock::now();
  const assembly::AssemblyTimings timingsBefore = problem->timings();
  try {
    if (!plan.arcLength) {
      solver::LoadStepper stepper(model, newton, plan.path, &continuation);
      Real lastLoad = resume ? resume->lastLoad : plan.path.path.front();
      bool checkpointFailed = false;
      solver::LoadStepper::CheckpointSink checkpoint;
      if (out.get<bool>("Checkpoint"))
        checkpoint = [&](const solver::StepperState& s, const Vector& state, const Vector& before) {
          Checkpoint c;  // collective: the vectors are gathered on rank 0
          c.stepper = s;
          c.lastLoad = lastLoad;
          c.exodusSteps = recorder.exodusSteps();
          c.u = gather.gather(state);
          if (s.havePrevious) c.previous = gather.gather(before);
          if (!root) return;
          c.curve = recorder.curve;
          if (!writeCheckpoint(dir, c) && !checkpointFailed) {
            checkpointFailed = true;
            std::cerr << "cgcm: warning: cannot write " << checkpointPath(dir) << "; the run goes on without\n";
          }
        };
      const solver::StepperState* from = resume ? &resume->stepper : nullptr;
      const Vector* fromPrevious = resume && resume->stepper.havePrevious ? &previous : nullptr;
      if (probe) {
        // A converged step whose gap moved much more than the prescribed displacement left its branch.
        const Real floor = 0.05 * setup.interaction->potential->r0();
        stepper.setContinuityCheck([&](const Vector& before, const Vector& after) {
          const Real du = std::abs(model->load() - lastLoad);
          return std::abs(probe->gap(after) - probe->gap(before)) <= std::max(5.0 * du, floor);
        });
        stepper.run(u, [&](const solver::StepInfo& info, const Vector& state) {
          LoadPoint row;
          row.step = step = info.step;
          row.newtonIterations = info.newton.iterations;
          row.fold = info.fold;
          row.jump = info.jump;
          row.residual = info.newton.residualNorms.empty() ? 0.0 : info.newton.residualNorms.back();
          row.cutbacks = info.cutbacks;
          auto p = model->parameters();
          p[0] = info.load;
          recorder.record(state, p, row);
          if (!info.fold) lastLoad = info.load;
        }, checkpoint, from, fromPrevious);
      } else {
        stepper.run(u, [&](const solver::StepInfo& info, const Vector& state) {
          LoadPoint row;
          row.step = step = info.step;
          row.newtonIterations = info.newton.iterations;
          row.residual = info.newton.residualNorms.empty() ? 0.0 : info.newton.residualNorms.back();
          row.cutbacks = info.cutbacks;
          auto p = model->parameters();
          p[0] = info.load;
          recorder.record(state, p, row);
        }, checkpoint, from, fromPrevious);
      }
      for (const auto& j : stepper.jumps()) result.continuationSteps += j.steps, result.graphRestarts += j.restarts;
    } else {
      model->dirichlet().impose(plan.path.path.front(), u);
      const auto first = newton.solve(u);
      if (!first.converged)
        throw NumericalError("no equilibrium at the start of the load path, u = " +
                             std::to_string(plan.path.path.front()) + ": " + first.failure);
      LoadPoint row;
      row.newtonIterations = first.iterations;
      row.residual = first.residualNorms.back();
      recorder.record(u, model->parameters(), row);
      for (std::size_t k = 1; k < plan.path.path.size(); ++k)
        continueTo(0, plan.path.path[k], plan.path.path, plan.path.initialIncrement);
    }
    if (plan.parameter != "u") {
      std::vector<Real> waypoints{model->parameter(parameterIndex)};
      waypoints.insert(waypoints.end(), plan.parameterPath.begin(), plan.parameterPath.end());
      for (std::size_t k = 1; k < waypoints.size(); ++k) {
        if (waypoints[k] == model->parameter(parameterIndex)) continue;
        continueTo(parameterIndex, waypoints[k], waypoints,
                   0.01 * std::abs(waypoints[k] - model->parameter(parameterIndex)));
      }
    }
    result.completed = true;
  } catch (const NumericalError& e) {
    result.failure = e.what();
    if (root) std::cerr << "cgcm: stopped after step " << step << ": " << e.what() << "\n";
  }
  result.curve = recorder.curve;
  result.pathSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - runStart).count();
  result.meshSeconds = meshSeconds;
  result.distributionSeconds = distributionSeconds;
  {
    // LOCA does not report its solves (its groups do not log them to NOX's statistics).
    result.linearSolves = newton.linearSolves().solves;
    result.krylovIterations = newton.linearSolves().iterations;
    result.linearSolver = linearSolverType;
  }
  const auto graph = problem->graph();  // collective only when it has to be built
  result.numNodes = numNodes;
  result.numCells = numCells;
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
    const long held[2] = {long(disc.mesh->numCells()), long(disc.mesh->numNodes())};
    std::vector<long> all(2 * std::size_t(comm.getSize()));
    Teuchos::gatherAll(comm, 2, held, int(all.size()), all.data());
    for (int r = 0; r < comm.getSize(); ++r) result.meshHeld.push_back({all[2 * r], all[2 * r + 1]});
  }
  const auto& t = problem->timings();
  result.assemblySeconds = (t.residual + t.jacobian) - (timingsBefore.residual + timingsBefore.jacobian);
  result.interactionSeconds = t.interaction - timingsBefore.interaction;
  result.searchSeconds = t.search - timingsBefore.search;
  result.graphSeconds = t.graph - timingsBefore.graph;
  if (const auto* volume = problem->volumeInteraction()) {
    const auto& vs = volume->summary();
    // each rank lists the pairs of its own cells: sums over the ranks
    LocalIndex numPairs = 0, atMax = 0;
    int maxOrder = 0;
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
      << maxOrder << " (" << atMax << " pairs at the maximum " << volume->maxQuadratureOrder()
      << "), " << vs.numListBuilds << " pair lists built; kernel " << kernelSeconds << " s for " << totalPairs
      << " point pairs (" << 1e-6 * double(totalPairs) / std::max(kernelSeconds, 1e-300) << " M/s)";
    result.volumePairs = o.str();
  }

  // Summary: minimum force, folds, jumps, hysteresis, cost (also when the run stopped).
  if (root) {
    writeSummary(dir + "/summary.txt", result, plan.parameter, plan.arcLength, printSteps ? &log : nullptr);
    if (printSteps) log << "cgcm: outputs in " << dir << "/\n";
  }
  return result;
}

}  // namespace cgcm::app
