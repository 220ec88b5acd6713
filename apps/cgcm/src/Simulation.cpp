#include "cgcm/app/Simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>

#include "cgcm/app/PathAnalysis.hpp"
#include "cgcm/app/Results.hpp"
#include "cgcm/app/Setup.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/interaction/ClosestPointSearch.hpp"
#include "cgcm/io/CsvWriter.hpp"
#include "cgcm/io/Deck.hpp"
#include "cgcm/solver/Continuation.hpp"
#include "cgcm/solver/LinearSolver.hpp"
#include "cgcm/solver/LoadStepper.hpp"

namespace cgcm::app {

using assembly::Vector;

namespace {

// Gap on the axis and contact radius of a two-body contact state.
class ContactProbe {
 public:
  ContactProbe(const ContactGeometry& c, const mesh::Mesh& m, assembly::Problem& a)
      : c_(c), mesh_(m), problem_(a), upper_(m.nodeSet(c.upperApex).at(0)), lower_(m.nodeSet(c.lowerApex).at(0)) {}

  /// Distance along the axis between the apex nodes. Collective.
  Real gap(const Vector& u) const {
    const int y = mesh_.dim - 1;
    return (mesh_.coord(upper_, y) + problem_.nodeValue(u, upper_, y)) -
           (mesh_.coord(lower_, y) + problem_.nodeValue(u, lower_, y));
  }

  /// Radial position where the upper surface is first farther than the
  /// contact distance from the lower surface (0 if the apex already is). Collective.
  Real contactRadius(const Vector& u) const {
    const std::vector<Real>& x = problem_.surfaceCoordinates(u);
    const int dim = mesh_.dim;
    auto search = interaction::makeClosestPointSearch(dim);
    search->build(x.data(), problem_.interaction()->targetSurface(c_.lowerBody));
    // radius: x (the axis is x = 0) in 2D; in 3D the distance from the vertical line through the upper apex
    const Real apex[2] = {dim == 3 ? mesh_.coord(upper_, 0) + problem_.nodeValue(u, upper_, 0) : 0.0,
                          dim == 3 ? mesh_.coord(upper_, 1) + problem_.nodeValue(u, upper_, 1) : 0.0};
    std::vector<std::pair<Real, Real>> profile;  // (radius, distance) of upper surface nodes
    const auto& s = mesh_.surfaces[c_.upperBody];
    std::vector<LocalIndex> nodes(s.facets);
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    const Real reach = 20.0 * c_.contactDistance;
    for (LocalIndex n : nodes) {
      const Real* p = &x[std::size_t(n) * dim];
      const auto proj = search->project(p, reach);
      const Real radius = dim == 3 ? std::hypot(p[0] - apex[0], p[1] - apex[1]) : p[0];
      profile.push_back({radius, proj.found() ? proj.distance : std::numeric_limits<Real>::infinity()});
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
  assembly::Problem& problem_;
  LocalIndex upper_, lower_;
};

// Turns converged states into load-curve rows: the force responses, the CSV
// row (flushed, so a run that stops leaves a valid file), the Exodus step and
// a progress line.
class Recorder {
 public:
  Recorder(const ProblemSetup& setup, const Discretization& disc, const ContactProbe* probe, const std::string& dir,
           bool exodus, int parameterIndex, bool print, std::ostream& log)
      : setup_(setup), model_(*disc.model), probe_(probe), parameterIndex_(parameterIndex),
        root_(disc.dofs->comm()->getRank() == 0), print_(print), log_(log), f_(disc.model->map()) {
    columns_ = {"step", "u"};
    if (parameterIndex_ > 0) columns_.push_back(model_.parameterNames()[parameterIndex_]);
    columns_.push_back("P");
    if (probe_) columns_.insert(columns_.end(), {"gap", "contact_radius"});
    if (setup_.balance) columns_.push_back("P_lower");
    columns_.insert(columns_.end(), {"newton_iterations", "stable", "fold", "jump", "residual", "cutbacks"});
    createOnRoot(*disc.dofs->comm(), [&] { csv_ = std::make_unique<io::CsvWriter>(dir + "/load_curve.csv", columns_); });
    if (disc.interaction)
      createOnRoot(*disc.dofs->comm(), [&] {
        bodyCsv_ = std::make_unique<io::CsvWriter>(dir + "/body_forces.csv",
                                                   std::vector<std::string>{"step", "u", "body", "Fx", "Fy", "Fz"});
      });
    if (exodus) results_ = std::make_unique<ResultsWriter>(dir + "/results.e", disc, columns_);
  }

  /// Records the state x at parameters p; `row` carries step, flags and solver figures. Collective.
  void record(const Vector& x, const std::vector<Real>& p, LoadPoint row) {
    model_.evaluateUnconstrained(x, p, f_);
    const auto& loadNodes = setup_.mesh->nodeSet(setup_.load.nodeSet);
    row.u = p[0];
    row.parameter = p[std::size_t(std::max(parameterIndex_, 0))];
    row.P = setup_.load.sign * setup_.load.scale *
            model_.problem().sumOverNodes(f_, loadNodes, setup_.load.component);
    if (probe_) {
      row.gap = probe_->gap(x);
      row.contactRadius = probe_->contactRadius(x);
    }
    if (setup_.balance)
      row.Plower = setup_.balance->sign * setup_.balance->scale * model_.problem().sumOverNodes(
                                              f_, setup_.mesh->nodeSet(setup_.balance->nodeSet),
                                              setup_.balance->component);
    curve.push_back(row);
    std::vector<double> values{double(row.step), row.u};
    if (parameterIndex_ > 0) values.push_back(row.parameter);
    values.push_back(row.P);
    if (probe_) values.insert(values.end(), {row.gap, row.contactRadius});
    if (setup_.balance) values.push_back(row.Plower);
    values.insert(values.end(), {double(row.newtonIterations), row.stable ? 1.0 : 0.0, row.fold ? 1.0 : 0.0,
                                 row.jump ? 1.0 : 0.0, row.residual, double(row.cutbacks)});
    if (results_) results_->write(x, values);
    // the interaction force on each body at this state (the evaluation above)
    const auto forces = model_.problem().interactionForces();  // collective; empty without interaction
    if (!root_) return;
    csv_->row(values);
    for (std::size_t b = 0; bodyCsv_ && b < forces.size(); ++b)
      bodyCsv_->row({double(row.step), row.u, double(b), forces[b][0], forces[b][1], forces[b][2]});
    if (!print_) return;
    char line[300];
    std::string extra;
    if (parameterIndex_ > 0) extra = "  " + columns_[2] + " = " + std::to_string(row.parameter);
    if (probe_) extra += "  gap = " + std::to_string(row.gap);
    std::snprintf(line, sizeof line, "step %4d  u = %+.6e%s  P = %+.6e  newton %2d  |f| = %.2e%s%s%s%s\n", row.step,
                  row.u, extra.c_str(), row.P, row.newtonIterations, row.residual, row.stable ? "" : "  unstable",
                  row.fold ? "  FOLD" : "", row.jump ? "  JUMP" : "",
                  row.cutbacks ? ("  (" + std::to_string(row.cutbacks) + " cut-backs)").c_str() : "");
    log_ << line << std::flush;
  }

  std::vector<LoadPoint> curve;

 private:
  const ProblemSetup& setup_;
  solver::ModelEvaluator& model_;
  const ContactProbe* probe_;
  int parameterIndex_;
  bool root_, print_;
  std::ostream& log_;
  Vector f_;
  std::vector<std::string> columns_;
  std::unique_ptr<io::CsvWriter> csv_, bodyCsv_;
  std::unique_ptr<ResultsWriter> results_;
};

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
                        std::ostream& log) {
  const bool root = comm->getRank() == 0;
  const auto& out = deck.sublist("Output");
  const std::string dir = out.get<std::string>("Directory");
  const bool printSteps = out.get<bool>("Print Steps");

  // Everything that can be rejected is checked before any work starts.
  ProblemSetup setup = buildProblem(deck);
  const PathPlan plan = planPath(deck.sublist("Loading"), setup);
  auto newtonSettings = solver::NewtonSettings::fromParameters(deck.sublist("Solver").sublist("Newton"));
  newtonSettings.forceScale = setup.forceScale;
  const int dim = assembly::formulationDim(setup.formulation);
  auto linearSolver =
      solver::buildLinearSolver(deck.sublist("Solver").sublist("Linear Solver"), comm->getSize(), dim);
  for (const auto& c : setup.conditions) setup.mesh->nodeSet(c.nodeSet);
  Teuchos::ParameterList loca = deck.isSublist("LOCA") ? deck.sublist("LOCA") : Teuchos::ParameterList("LOCA");
  {
    // Step sizes in the problem's units unless the deck gives LOCA's own.
    auto& step = loca.sublist("Step Size");
    if (!step.isParameter("Min Step Size")) step.set("Min Step Size", plan.path.minIncrement);
    if (!step.isParameter("Max Step Size") && plan.parameter == "u") step.set("Max Step Size", plan.path.maxIncrement);
  }

  createOnRoot(*comm, [&] {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::filesystem::is_directory(dir))
      throw InputError("Output/Directory = \"" + dir + "\": cannot create it (" +
                       (ec ? ec.message() : "a file of that name exists") + ")");
    io::writeDeck(deck, dir + "/parameters.xml");
  });

  const Discretization disc = discretize(comm, setup, linearSolver);
  const auto& problem = disc.problem;
  const auto& model = disc.model;
  solver::NewtonSolver newton(model, newtonSettings);
  solver::Continuation continuation(model, newtonSettings, loca, printSteps && newtonSettings.printIterations);
  std::unique_ptr<ContactProbe> probe;
  if (setup.contact) probe = std::make_unique<ContactProbe>(*setup.contact, *setup.mesh, *problem);
  const int parameterIndex = model->parameterIndex(plan.parameter);

  if (root && printSteps) {
    log << "cgcm: " << assembly::formulationName(setup.formulation) << ", " << setup.mesh->numNodes() << " nodes, "
        << setup.mesh->numCells() << " cells, " << disc.dofs->ownedMap()->getGlobalNumElements() << " dofs, "
        << comm->getSize() << " rank(s); " << (plan.arcLength ? "arc-length" : "displacement") << " control\n";
    for (const auto& line : setup.report) log << "cgcm: " << line << "\n";
    log << "cgcm: a state is accepted when |f|_2 <= " << newtonSettings.tolerance() << " (Residual Tolerance "
        << newtonSettings.residualTolerance << " x F_ref " << setup.forceScale << ")\n";
  }

  // The initial guess: the prescribed motion of whole bodies at the first u.
  Vector u(model->map());
  if (!setup.initialMotion.empty()) {
    assembly::DirichletConditions motion(disc.dofs);
    for (const auto& c : setup.initialMotion)
      motion.add(setup.mesh->nodeSet(c.nodeSet), c.component, c.offset, c.scale);
    motion.impose(plan.path.path.front(), u);
  }
  model->setLoad(plan.path.path.front());
  if (plan.arcLength || plan.parameter != "u") continuation.validate(u);  // LOCA reads its list: typos stop here

  Recorder recorder(setup, disc, probe.get(), dir, out.get<bool>("Exodus"), parameterIndex, printSteps, log);
  RunResult result;
  int step = 0;
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
      if (probe) {
        // A converged step whose gap moved much more than the prescribed displacement left its branch.
        const Real floor = 0.05 * setup.interaction->potential->r0();
        Real lastLoad = plan.path.path.front();
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
        });
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
        });
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
  const auto graph = problem->graph();  // collective only when it has to be built
  const auto matrixRows = graph->getGlobalNumRows(), matrixEntries = graph->getGlobalNumEntries();
  result.pathSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - runStart).count();
  const auto& t = problem->timings();
  result.assemblySeconds = (t.residual + t.jacobian) - (timingsBefore.residual + timingsBefore.jacobian);
  result.interactionSeconds = t.interaction - timingsBefore.interaction;

  // Summary: minimum force, folds, jumps, hysteresis, cost (also when the run stopped).
  if (root) {
    std::ofstream sum(dir + "/summary.txt");
    auto both = [&](const char* text) {
      sum << text;
      if (printSteps) log << "cgcm: " << text;
    };
    char buf[400];
    both(result.completed ? "completed\n" : ("stopped: " + result.failure + "\n").c_str());
    const auto& c = result.curve;
    if (!c.empty()) {
      const auto minIt =
          std::min_element(c.begin(), c.end(), [](const LoadPoint& a, const LoadPoint& b) { return a.P < b.P; });
      std::snprintf(buf, sizeof buf, "P_min = %.10g at u = %.10g (step %d)\n", minIt->P, minIt->u, minIt->step);
      both(buf);
    }
    for (const auto& pt : c)
      if (pt.fold) {
        const std::string other =
            plan.parameter == "u" ? "" : ", " + plan.parameter + " = " + std::to_string(pt.parameter);
        std::snprintf(buf, sizeof buf, "fold at step %d: u = %.10g%s, P = %.10g, gap = %.6g, contact radius = %.6g\n",
                      pt.step, pt.u, other.c_str(), pt.P, pt.gap, pt.contactRadius);
        both(buf);
      }
    if (plan.parameter == "u") {
      const auto path = plan.arcLength ? displacementControlPath(c) : c;
      for (const auto& j : jumpsOf(path)) {
        std::snprintf(buf, sizeof buf, "jump under displacement control at u = %.10g: P %.10g -> %.10g, gap %.6g -> %.6g\n",
                      j.from.u, j.from.P, j.to.P, j.from.gap, j.to.gap);
        both(buf);
      }
      std::snprintf(buf, sizeof buf, "hysteresis energy (loop of the displacement-controlled path) = %.10g\n",
                    hysteresisEnergy(path));
      both(buf);
    }
    int iterations = 0, unstable = 0;
    for (const auto& pt : c) iterations += pt.newtonIterations, unstable += pt.stable ? 0 : 1;
    std::snprintf(buf, sizeof buf,
                  "states = %zu (%d unstable), Newton iterations = %d (%.2f per state), continuation steps = %d, "
                  "graph restarts = %d\n",
                  c.size(), unstable, iterations, double(iterations) / std::max<std::size_t>(1, c.size()),
                  result.continuationSteps, result.graphRestarts);
    both(buf);
    std::snprintf(buf, sizeof buf, "Jacobian at the end: %zu rows, %zu entries (%.1f per row)\n",
                  std::size_t(matrixRows), std::size_t(matrixEntries),
                  double(matrixEntries) / std::max<std::size_t>(1, matrixRows));
    both(buf);
    std::snprintf(buf, sizeof buf,
                  "wall time of the path %.3f s = bulk assembly %.3f s + interaction %.3f s + linear solves, NOX "
                  "and LOCA %.3f s\n",
                  result.pathSeconds, result.assemblySeconds, result.interactionSeconds,
                  result.pathSeconds - result.assemblySeconds - result.interactionSeconds);
    both(buf);
    if (printSteps) log << "cgcm: outputs in " << dir << "/\n";
  }
  return result;
}

}  // namespace cgcm::app
