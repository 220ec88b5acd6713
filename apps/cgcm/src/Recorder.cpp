#include "cgcm/app/Recorder.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include <Teuchos_CommHelpers.hpp>

#include "cgcm/interaction/ClosestPointSearch.hpp"

namespace cgcm::app {

using assembly::Vector;

namespace {

// The surface as straight segments (2D) or triangles (3D) through all its facets' nodes, for the
// closest-point search of the contact radius: a quadratic facet (Exodus order: corners, mid-edge
// nodes from edge 0-1 on, centre) becomes its pieces between its nodes, the polygon through them
// (a chord error of the curved facet, small beside the cells' size).
mesh::Surface straightPieces(const mesh::Surface& s, int dim) {
  const int npf = s.nodesPerFacet;
  if (dim == 2 ? npf == 2 : npf == 3 || npf == 4) return mesh::triangulated(s);
  static const int line3[2][2] = {{0, 2}, {2, 1}};
  static const int tri6[4][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}};
  static const int quad8[6][3] = {{0, 4, 7}, {4, 1, 5}, {5, 2, 6}, {6, 3, 7}, {4, 5, 6}, {4, 6, 7}};
  static const int quad9[8][3] = {{0, 4, 8}, {0, 8, 7}, {4, 1, 5}, {4, 5, 8}, {8, 5, 2}, {8, 2, 6}, {7, 8, 6}, {7, 6, 3}};
  mesh::Surface out;
  out.body = s.body;
  out.nodesPerFacet = dim;
  auto add = [&](const LocalIndex* n, const auto& pieces, LocalIndex f) {
    for (const auto& piece : pieces) {
      for (int k = 0; k < dim; ++k) out.facets.push_back(n[piece[k]]);
      if (!s.facetCells.empty()) out.facetCells.push_back(s.facetCells[f]);
    }
  };
  for (LocalIndex f = 0; f < s.numFacets(); ++f) {
    const LocalIndex* n = &s.facets[std::size_t(f) * npf];
    if (dim == 2)
      add(n, line3, f);
    else if (npf == 6)
      add(n, tri6, f);
    else if (npf == 8)
      add(n, quad8, f);
    else
      add(n, quad9, f);
  }
  return out;
}

}  // namespace

ContactProbe::ContactProbe(const mesh::ContactGeometry& c, const mesh::Mesh& m, assembly::Problem& problem)
    : c_(c), mesh_(m), problem_(problem), upper_(m.nodeSet(c.upperApex).at(0)), lower_(m.nodeSet(c.lowerApex).at(0)) {}

Real ContactProbe::gap(const Vector& u) const {
  const int y = mesh_.dim - 1;
  return (mesh_.coord(upper_, y) + problem_.nodeValue(u, upper_, y)) -
         (mesh_.coord(lower_, y) + problem_.nodeValue(u, lower_, y));
}

Real ContactProbe::contactRadius(const Vector& u) const {
  // Each rank measures the nodes of its own facets of the upper body against the lower body's facets it
  // holds (all within the interaction's reach of them); the profile's crossing of the contact distance is
  // then found by reductions: the first node, in order of (radius, distance), at or beyond the contact
  // distance, and the last before it.
  const auto held = problem_.heldSurfaces(u);
  const std::vector<Real>& x = *held.coords;
  const int dim = mesh_.dim;
  const mesh::Surface& upper = (*held.surfaces)[std::size_t(c_.upperBody)];
  const mesh::Surface lower = straightPieces((*held.surfaces)[std::size_t(c_.lowerBody)], dim);
  auto search = interaction::makeClosestPointSearch(dim);
  search->build(x.data(), lower);
  std::vector<LocalIndex> upperNodes(upper.facets.begin(),
                                     upper.facets.begin() + std::ptrdiff_t(held.ownFacets[std::size_t(c_.upperBody)]) *
                                                                upper.nodesPerFacet);
  std::sort(upperNodes.begin(), upperNodes.end());
  upperNodes.erase(std::unique(upperNodes.begin(), upperNodes.end()), upperNodes.end());
  // radius: x (the axis is x = 0) in 2D; in 3D the distance from the vertical line through the upper apex
  const Real apex[2] = {dim == 3 ? mesh_.coord(upper_, 0) + problem_.nodeValue(u, upper_, 0) : 0.0,
                        dim == 3 ? mesh_.coord(upper_, 1) + problem_.nodeValue(u, upper_, 1) : 0.0};
  constexpr Real inf = std::numeric_limits<Real>::infinity();
  std::vector<std::pair<Real, Real>> profile;  // (radius, distance) of this rank's upper surface nodes
  const Real reach = 20.0 * c_.contactDistance;
  for (LocalIndex n : upperNodes) {
    const Real* p = &x[std::size_t(n) * dim];
    const auto proj = search->project(p, reach);
    const Real radius = dim == 3 ? std::hypot(p[0] - apex[0], p[1] - apex[1]) : p[0];
    profile.push_back({radius, proj.found() ? proj.distance : inf});
  }
  const auto& comm = *problem_.dofs().comm();
  auto reduce = [&](Real mine, Teuchos::EReductionType type) {
    Real all = 0.0;
    Teuchos::reduceAll(comm, type, mine, Teuchos::outArg(all));
    return all;
  };
  const Real cd = c_.contactDistance;
  Real r1 = inf, rMost = -inf;  // the first radius at or beyond the contact distance; the largest radius
  for (const auto& [r, d] : profile) {
    if (d >= cd) r1 = std::min(r1, r);
    rMost = std::max(rMost, r);
  }
  r1 = reduce(r1, Teuchos::REDUCE_MIN);
  if (r1 == inf) return std::max(0.0, reduce(rMost, Teuchos::REDUCE_MAX));  // every node within: the last radius
  Real d1 = inf, r0 = -inf;  // the distance at r1; the last radius before it (within the contact distance)
  for (const auto& [r, d] : profile) {
    if (r == r1 && d >= cd) d1 = std::min(d1, d);
    if (d < cd && r <= r1) r0 = std::max(r0, r);
  }
  d1 = reduce(d1, Teuchos::REDUCE_MIN);
  r0 = reduce(r0, Teuchos::REDUCE_MAX);
  if (r0 == -inf) return 0.0;  // the innermost node is already beyond the contact distance
  Real d0 = -inf;
  for (const auto& [r, d] : profile)
    if (r == r0 && d < cd) d0 = std::max(d0, d);
  d0 = reduce(d0, Teuchos::REDUCE_MAX);
  if (!std::isfinite(d1)) return r1;
  return r0 + (cd - d0) / (d1 - d0) * (r1 - r0);
}

Recorder::Recorder(const solver::ProblemSetup& setup, const solver::Discretization& disc, const ContactProbe* probe,
                   const std::string& dir, bool exodus, int parameterIndex, bool print, std::ostream& log,
                   const solver::Checkpoint* resume, int eigenvalues, bool foldCurve)
    : setup_(setup), mesh_(*disc.mesh), model_(*disc.model), probe_(probe), parameterIndex_(parameterIndex),
      eigenvalues_(eigenvalues), foldCurve_(foldCurve), root_(disc.dofs->comm()->getRank() == 0), print_(print),
      log_(log),
      f_(disc.model->map()) {
  columns_ = {"step", "u"};
  if (parameterIndex_ > 0) columns_.push_back(model_.parameterNames()[parameterIndex_]);
  columns_.push_back("P");
  if (probe_) columns_.insert(columns_.end(), {"gap", "contact_radius"});
  if (setup_.model.balance) columns_.push_back("P_lower");
  columns_.insert(columns_.end(), {"newton_iterations", "stable", "fold", "jump", "residual", "cutbacks"});
  if (eigenvalues_ > 0) {
    columns_.push_back("negative_eigenvalues");
    for (int k = 1; k <= eigenvalues_; ++k) columns_.push_back("eigenvalue_" + std::to_string(k));
    columns_.insert(columns_.end(), {"stable_by_folds", "branch_point", "branch"});
  }
  if (foldCurve_) columns_.push_back("fold_curve");
  // a new file, or (restart) the file kept up to the checkpoint's last row
  auto open = [&](const std::string& path, const std::vector<std::string>& columns) {
    return resume ? std::make_unique<io::CsvWriter>(path, columns, double(resume->curve.back().step))
                  : std::make_unique<io::CsvWriter>(path, columns);
  };
  if (resume) curve = resume->curve;
  solver::runOnRoot(*disc.dofs->comm(), [&] { csv_ = open(dir + "/load_curve.csv", columns_); });
  if (disc.problem->hasInteraction())
    solver::runOnRoot(*disc.dofs->comm(), [&] {
      bodyCsv_ = open(dir + "/body_forces.csv", std::vector<std::string>{"step", "u", "body", "Fx", "Fy", "Fz"});
    });
  if (exodus)
    results_ = std::make_unique<ResultsWriter>(dir + "/results.e", disc, columns_,
                                               resume ? resume->exodusSteps : -1, eigenvalues_ > 0);
}

void Recorder::record(const solver::PathState& state) {
  const Vector& x = *state.x;
  const std::vector<Real>& p = state.p;
  solver::LoadPoint row;
  row.step = state.step;
  row.newtonIterations = state.iterations;
  row.stable = state.stable;
  row.fold = state.fold;
  row.branchPoint = state.branchPoint;
  row.jump = state.jump;
  row.residual = state.residual;
  row.cutbacks = state.cutbacks;
  model_.evaluateUnconstrained(x, p, f_);
  auto resultant = [&](const mesh::ForceResponse& r) {  // collective
    const auto& nodes = mesh_.nodeSet(r.nodeSet);
    if (r.direction.empty()) return r.sign * r.scale * model_.problem().sumOverNodes(f_, nodes, r.component);
    Real sum = 0.0;
    for (std::size_t i = 0; i < r.direction.size(); ++i)
      sum += r.direction[i] * model_.problem().sumOverNodes(f_, nodes, int(i));
    return r.scale * sum;
  };
  row.u = p[0];
  row.parameter = p[std::size_t(std::max(parameterIndex_, 0))];
  row.P = resultant(setup_.model.force);
  if (probe_) {
    row.gap = probe_->gap(x);
    row.contactRadius = probe_->contactRadius(x);
  }
  if (setup_.model.balance) row.Plower = resultant(*setup_.model.balance);
  if (state.branch == 0) curve.push_back(row);  // the summary's folds, jumps and hysteresis are the path's
  std::vector<double> values{double(row.step), row.u};
  if (parameterIndex_ > 0) values.push_back(row.parameter);
  values.push_back(row.P);
  if (probe_) values.insert(values.end(), {row.gap, row.contactRadius});
  if (setup_.model.balance) values.push_back(row.Plower);
  values.insert(values.end(), {double(row.newtonIterations), row.stable ? 1.0 : 0.0, row.fold ? 1.0 : 0.0,
                               row.jump ? 1.0 : 0.0, row.residual, double(row.cutbacks)});
  if (eigenvalues_ > 0) {
    const Real nan = std::numeric_limits<Real>::quiet_NaN();  // not computed (fewer converged)
    values.push_back(state.negativeEigenvalues >= 0 ? double(state.negativeEigenvalues) : nan);
    for (int k = 0; k < eigenvalues_; ++k)
      values.push_back(std::size_t(k) < state.eigenvalues.size() ? state.eigenvalues[std::size_t(k)] : nan);
    values.insert(values.end(), {state.stableByFolds ? 1.0 : 0.0, state.branchPoint ? 1.0 : 0.0, double(state.branch)});
  }
  if (foldCurve_) values.push_back(state.onFoldCurve ? 1.0 : 0.0);
  if (results_) results_->write(x, values, state.critical.get());
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
  if (state.branch > 0) extra += "  (branch " + std::to_string(state.branch) + ")";
  if (state.onFoldCurve) extra += "  (fold curve)";
  if (probe_) extra += "  gap = " + std::to_string(row.gap);
  std::snprintf(line, sizeof line, "step %4d  u = %+.6e%s  P = %+.6e  newton %2d  |f| = %.2e%s%s%s%s\n", row.step,
                row.u, extra.c_str(), row.P, row.newtonIterations, row.residual, row.stable ? "" : "  unstable",
                row.fold ? "  FOLD" : state.branchPoint ? "  BRANCH POINT" : "", row.jump ? "  JUMP" : "",
                row.cutbacks ? ("  (" + std::to_string(row.cutbacks) + " cut-backs)").c_str() : "");
  log_ << line << std::flush;
}

}  // namespace cgcm::app
