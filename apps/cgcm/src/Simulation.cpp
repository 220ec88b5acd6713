#include "cgcm/app/Simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>

#include "cgcm/app/Setup.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/interaction/ClosestPointSearch.hpp"
#include "cgcm/io/CsvWriter.hpp"
#include "cgcm/io/Deck.hpp"
#include "cgcm/solver/LinearSolver.hpp"
#include "cgcm/solver/LoadStepper.hpp"

namespace cgcm::app {

using assembly::Vector;

namespace {

// Gap on the axis and contact radius of a two-body contact state.
class ContactProbe {
 public:
  ContactProbe(const ContactGeometry& c, const mesh::Mesh& m, assembly::Assembler& a)
      : c_(c), mesh_(m), assembler_(a), upper_(m.nodeSet(c.upperApex).at(0)), lower_(m.nodeSet(c.lowerApex).at(0)) {}

  /// Distance along the axis between the apex nodes. Collective.
  Real gap(const Vector& u) const {
    const int y = mesh_.dim - 1;
    return (mesh_.coord(upper_, y) + assembler_.nodeValue(u, upper_, y)) -
           (mesh_.coord(lower_, y) + assembler_.nodeValue(u, lower_, y));
  }

  /// Radial position where the upper surface is first farther than the
  /// contact distance from the lower surface (0 if the apex already is). Collective.
  Real contactRadius(const Vector& u) const {
    const std::vector<Real>& x = assembler_.surfaceCoordinates(u);
    auto search = interaction::makeClosestPointSearch(2);
    search->build(x.data(), mesh_.surfaces[c_.lowerBody]);
    std::vector<std::pair<Real, Real>> profile;  // (radius, distance) of upper surface nodes
    const auto& s = mesh_.surfaces[c_.upperBody];
    std::vector<LocalIndex> nodes(s.facets);
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    const Real reach = 20.0 * c_.contactDistance;
    for (LocalIndex n : nodes) {
      const Real* p = &x[std::size_t(n) * 2];
      const auto proj = search->project(p, reach);
      profile.push_back({p[0], proj.found() ? proj.distance : std::numeric_limits<Real>::infinity()});
    }
    std::sort(profile.begin(), profile.end());
    if (profile.empty() || profile[0].second >= c_.contactDistance) return 0.0;
    for (std::size_t k = 1; k < profile.size(); ++k)
      if (profile[k].second >= c_.contactDistance) {
        const auto& [r0, d0] = profile[k - 1];
        const auto& [r1, d1] = profile[k];
        if (!std::isfinite(d1)) return r1;
        return r0 + (c_.contactDistance - d0) / (d1 - d0) * (r1 - r0);
      }
    return profile.back().first;
  }

 private:
  ContactGeometry c_;
  const mesh::Mesh& mesh_;
  assembly::Assembler& assembler_;
  LocalIndex upper_, lower_;
};

// Grows the interaction strength from `from` to 1 with the Dirichlet data
// held, in adaptive steps; throws NumericalError if a step fails below 1e-4
// of the range.
void rampInteractionStrength(interaction::SurfaceInteraction& interaction, solver::NewtonSolver& newton, Vector& u,
                             Real from, bool print, std::ostream& log) {
  Vector trial(u.getMap());
  Real s = from, ds = (1.0 - from) / 8.0;
  const Real dsMin = 1e-4 * (1.0 - from);
  std::string failure;
  while (s < 1.0) {
    const Real next = (1.0 - s) < 1.05 * ds ? 1.0 : s + ds;
    interaction.setStrength(next);
    trial.assign(u);
    const auto r = newton.solve(trial);
    if (!r.converged || r.stalled) {
      failure = r.stalled ? "Newton cycle" : r.failure;
      ds *= 0.5;
      if (ds < dsMin) {
        interaction.setStrength(s);
        throw NumericalError("adhesion ramp failed between scales " + std::to_string(s) + " and " +
                             std::to_string(next) + " (" + failure + ")");
      }
      continue;
    }
    u.assign(trial);
    s = next;
    if (print) {
      char line[160];
      std::snprintf(line, sizeof line, "ramp      adhesion scale = %.6f  newton %2d\n", s, r.iterations);
      log << line << std::flush;
    }
    if (r.iterations <= 4) ds *= 1.5;
  }
}

}  // namespace

RunResult runSimulation(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const Teuchos::ParameterList& deck,
                        std::ostream& log) {
  const bool root = comm->getRank() == 0;
  const auto& out = deck.sublist("Output");
  const std::string dir = out.get<std::string>("Directory");
  const bool printSteps = out.get<bool>("Print Steps");

  // Everything that can be rejected is checked before any work starts.
  ProblemSetup setup = buildProblem(deck);
  const auto loading = solver::LoadPathSettings::fromParameters(deck.sublist("Loading"));
  const Real approachScale = deck.sublist("Loading").get<double>("Approach Adhesion Scale");
  if (approachScale < 1.0 && !setup.interaction)
    throw InputError("Loading/Approach Adhesion Scale < 1 needs an interaction between bodies (Geometry/Type = "
                     "\"sphere on half-space\" or \"sphere on sphere\")");
  if (approachScale < 1.0 && loading.path.size() < 3)
    throw InputError("Loading/Approach Adhesion Scale < 1 needs an Approach Path of at least three waypoints: the "
                     "approach at reduced adhesion ends at the second, the recorded path starts there");
  auto newtonSettings = solver::NewtonSettings::fromParameters(deck.sublist("Solver").sublist("Newton"));
  newtonSettings.stallTolerance = newtonSettings.relativeStallTolerance * setup.forceScale;
  if (setup.interaction) newtonSettings.stallUpdateTolerance = 0.1 * setup.interaction->potential->r0();
  const int dim = assembly::formulationDim(setup.formulation);
  auto linearSolver =
      solver::buildLinearSolver(deck.sublist("Solver").sublist("Linear Solver"), comm->getSize(), dim);
  for (const auto& c : setup.conditions) setup.mesh->nodeSet(c.nodeSet);

  if (root) {
    std::filesystem::create_directories(dir);
    io::writeDeck(deck, dir + "/parameters.xml");
  }
  comm->barrier();

  const Discretization disc = discretize(comm, setup, linearSolver);
  const auto& dofs = disc.dofs;
  const auto& assembler = disc.assembler;
  const auto& model = disc.model;
  solver::NewtonSolver newton(model, newtonSettings);
  std::unique_ptr<ContactProbe> probe;
  if (setup.contact) probe = std::make_unique<ContactProbe>(*setup.contact, *setup.mesh, *assembler);

  if (root && printSteps) {
    log << "cgcm: " << assembly::formulationName(setup.formulation) << ", " << setup.mesh->numNodes() << " nodes, "
        << setup.mesh->numCells() << " cells, " << dofs->ownedMap()->getGlobalNumElements() << " dofs, "
        << comm->getSize() << " rank(s)\n";
    for (const auto& line : setup.report) log << "cgcm: " << line << "\n";
  }

  std::vector<std::string> columns{"step", "u", "P"};
  if (probe) columns.insert(columns.end(), {"gap", "contact_radius", "P_lower"});
  columns.insert(columns.end(), {"newton_iterations", "jump", "residual", "stalled", "cutbacks"});
  // Both files exist from the start, so a run that stops early never leaves an older run's curve behind.
  std::unique_ptr<io::CsvWriter> curveCsv, preparationCsv;
  if (root) curveCsv = std::make_unique<io::CsvWriter>(dir + "/load_curve.csv", columns);
  if (root && approachScale < 1.0)
    preparationCsv = std::make_unique<io::CsvWriter>(dir + "/preparation.csv", columns);
  bool preparing = approachScale < 1.0;  // states of the reduced-adhesion approach are not part of the result

  RunResult result;
  Vector u(model->map());
  if (!setup.initialMotion.empty()) {
    assembly::DirichletConditions motion(dofs);
    for (const auto& c : setup.initialMotion)
      motion.add(setup.mesh->nodeSet(c.nodeSet), c.component, c.offset, c.scale);
    motion.impose(loading.path.front(), u);
  }
  Vector f(model->map());
  const auto& loadNodes = setup.mesh->nodeSet(setup.load.nodeSet);
  auto observe = [&](const solver::StepInfo& info, const Vector& uSolved) {
    model->evaluateUnconstrained(uSolved, f);
    const Real P = setup.load.sign * assembler->sumOverNodes(f, loadNodes, setup.load.component);
    const Real res = info.newton.residualNorms.empty() ? 0.0 : info.newton.residualNorms.back();
    LoadPoint pt{info.step, info.load, P, 0.0, 0.0, info.newton.iterations, info.jump, res};
    Real Plower = 0.0;
    if (probe) {
      pt.gap = probe->gap(uSolved);
      pt.contactRadius = probe->contactRadius(uSolved);
      Plower = setup.balance->sign * assembler->sumOverNodes(f, setup.mesh->nodeSet(setup.balance->nodeSet),
                                                             setup.balance->component);
    }
    if (!preparing) {
      result.curve.push_back(pt);
      result.stalledSteps += info.newton.stalled ? 1 : 0;
    }
    if (!root) return;
    std::vector<double> row{double(info.step), info.load, P};
    if (probe) row.insert(row.end(), {pt.gap, pt.contactRadius, Plower});
    row.insert(row.end(), {double(info.newton.iterations), info.jump ? 1.0 : 0.0, res,
                           info.newton.stalled ? 1.0 : 0.0, double(info.cutbacks)});
    (preparing ? preparationCsv : curveCsv)->row(row);
    if (printSteps) {
      char line[240];
      std::snprintf(line, sizeof line, "%s %4d  u = %+.6e  P = %+.6e%s  newton %2d  |f| = %.2e%s%s%s\n",
                    preparing ? "approach" : "step", info.step, info.load, P, probe ? ("  gap = " + std::to_string(pt.gap)).c_str() : "",
                    info.newton.iterations, res, info.newton.stalled ? " (stalled)" : "",
                    info.cutbacks ? ("  (" + std::to_string(info.cutbacks) + " cut-backs)").c_str() : "",
                    info.jump ? "  JUMP" : "");
      log << line << std::flush;
    }
  };

  Real lastLoad = loading.path.front();
  auto runPath = [&](const solver::LoadPathSettings& settings) {
    solver::LoadStepper stepper(model, newton, settings);
    if (probe) {
      // A state that moved much more than the prescribed displacement left its branch.
      const Real floor = 0.05 * setup.interaction->potential->r0();
      stepper.setContinuityCheck([&](const Vector& before, const Vector& after) {
        const Real du = std::abs(model->load() - lastLoad);
        return std::abs(probe->gap(after) - probe->gap(before)) <= std::max(5.0 * du, floor);
      });
      stepper.setJumpStepLimit(0.1 * setup.interaction->potential->r0());
    }
    stepper.run(u, [&](const solver::StepInfo& info, const Vector& uSolved) {
      observe(info, uSolved);
      lastLoad = info.load;
    });
  };
  auto runStart = std::chrono::steady_clock::now();
  assembly::AssemblyTimings timingsBefore = assembler->timings();
  try {
    if (preparing) {
      solver::LoadPathSettings approach = loading;
      approach.path.resize(2);
      disc.interaction->setStrength(approachScale);
      newton.setStallTolerance(approachScale * newtonSettings.stallTolerance);  // the adhesion force scales too
      runPath(approach);
      const Real gapBefore = probe ? probe->gap(u) : 0.0;
      rampInteractionStrength(*disc.interaction, newton, u, approachScale, root && printSteps, log);
      const Real gapChange = probe ? std::abs(probe->gap(u) - gapBefore) : 0.0;
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - runStart).count();
      if (root && printSteps) {
        char line[200];
        std::snprintf(line, sizeof line, "cgcm: preparation (approach and ramp) %.3f s; the ramp moved the gap by %.3g r0\n",
                      seconds, gapChange / setup.interaction->potential->r0());
        log << line;
      }
      preparing = false;
      newton.setStallTolerance(newtonSettings.stallTolerance);
      // the summary's time split is that of the recorded path
      runStart = std::chrono::steady_clock::now();
      timingsBefore = assembler->timings();
    }
    solver::LoadPathSettings recorded = loading;
    if (approachScale < 1.0) recorded.path.erase(recorded.path.begin());
    runPath(recorded);
    result.completed = true;
  } catch (const NumericalError& e) {
    result.failure = e.what();
    if (root) log << "cgcm: stopped: " << e.what() << "\n";
  }
  result.newtonSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - runStart).count();
  const auto& t = assembler->timings();
  result.assemblySeconds = (t.residual + t.jacobian) - (timingsBefore.residual + timingsBefore.jacobian);
  result.interactionSeconds = t.interaction - timingsBefore.interaction;

  // Summary: minimum force, jumps, time split (also when the run stopped before the recorded path).
  if (root) {
    std::ofstream sum(dir + "/summary.txt");
    char buf[256];
    if (!result.curve.empty()) {
      const auto minIt = std::min_element(result.curve.begin(), result.curve.end(),
                                          [](const LoadPoint& a, const LoadPoint& b) { return a.P < b.P; });
      std::snprintf(buf, sizeof buf, "P_min = %.10g at u = %.10g (step %d)\n", minIt->P, minIt->u, minIt->step);
      sum << buf;
      if (printSteps) log << "cgcm: " << buf;
    }
    for (const auto& pt : result.curve)
      if (pt.jump) {
        std::snprintf(buf, sizeof buf, "jump at step %d: u = %.10g, P = %.10g\n", pt.step, pt.u, pt.P);
        sum << buf;
        if (printSteps) log << "cgcm: " << buf;
      }
    int iterations = 0;
    for (const auto& pt : result.curve) iterations += pt.newtonIterations;
    std::snprintf(buf, sizeof buf,
                  "steps = %zu (%d accepted at a stall), Newton iterations = %d (%.2f per step); wall time of the "
                  "load path %.3f s = bulk assembly %.3f s + interaction %.3f s + linear solves and NOX %.3f s\n",
                  result.curve.size(), result.stalledSteps, iterations,
                  double(iterations) / std::max<std::size_t>(1, result.curve.size()),
                  result.newtonSeconds, result.assemblySeconds, result.interactionSeconds,
                  result.newtonSeconds - result.assemblySeconds - result.interactionSeconds);
    sum << buf << (result.completed ? "completed\n" : "stopped: " + result.failure + "\n");
    if (printSteps) log << "cgcm: " << buf << "cgcm: outputs in " << dir << "/\n";
  }
  return result;
}

}  // namespace cgcm::app
