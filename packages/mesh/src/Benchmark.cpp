#include "cgcm/mesh/Benchmark.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "cgcm/core/Error.hpp"
#include "cgcm/mesh/Generators.hpp"

namespace cgcm::mesh {

namespace {

// Smallest q >= 1 with total(q) >= length, for an increasing total(q) (bisection).
Real solveRatio(const std::function<Real(Real)>& total, Real length) {
  if (total(1.0) >= length) return 1.0;
  Real lo = 1.0, hi = 2.0;
  while (total(hi) < length) hi *= 2.0;
  for (int it = 0; it < 200; ++it) {
    const Real mid = 0.5 * (lo + hi);
    (total(mid) < length ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

// Signed area of a quad (positive: counter-clockwise).
Real quadArea(const Mesh& m, const LocalIndex* q) {
  Real a = 0.0;
  for (int k = 0; k < 4; ++k) {
    const LocalIndex p = q[k], n = q[(k + 1) % 4];
    a += m.coord(p, 0) * m.coord(n, 1) - m.coord(n, 0) * m.coord(p, 1);
  }
  return 0.5 * a;
}

void addQuad(const Mesh& m, ElementBlock& b, LocalIndex n0, LocalIndex n1, LocalIndex n2, LocalIndex n3) {
  LocalIndex q[4] = {n0, n1, n2, n3};
  if (quadArea(m, q) < 0.0) std::swap(q[1], q[3]);
  b.connectivity.insert(b.connectivity.end(), q, q + 4);
}

LocalIndex addNode(Mesh& m, Real x, Real y) {
  m.coords.push_back(x);
  m.coords.push_back(y);
  return m.numNodes() - 1;
}

int scaled(int n, int level) { return n << level; }

}  // namespace

std::vector<Real> geometric(Real length, Real first, int cells) {
  if (cells < 1 || !(first > 0.0) || !(length > 0.0)) throw InputError("geometric grading: invalid arguments");
  const Real q = solveRatio(
      [&](Real r) {
        Real s = 0.0, t = first;
        for (int k = 0; k < cells; ++k, t *= r) s += t;
        return s;
      },
      length);
  std::vector<Real> x(cells + 1, 0.0);
  Real h = first;
  for (int k = 1; k <= cells; ++k, h *= q) x[k] = x[k - 1] + h;
  x[cells] = length;
  return x;
}

std::vector<Real> fineThenGeometric(Real length, Real fineLength, int fineCells, int coarseCells) {
  if (fineCells < 1 || coarseCells < 0 || !(fineLength > 0.0) || !(fineLength < length))
    throw InputError("graded mesh: need 0 < fine length < length and at least one fine cell");
  const Real h = fineLength / fineCells;
  std::vector<Real> x;
  for (int k = 0; k <= fineCells; ++k) x.push_back(h * k);
  if (coarseCells == 0) {
    x.back() = length;
    return x;
  }
  const Real rest = length - fineLength;
  const Real q = solveRatio(
      [&](Real r) {
        Real s = 0.0, t = h;
        for (int k = 0; k < coarseCells; ++k) s += (t *= r);
        return s;
      },
      rest);
  Real t = h;
  for (int k = 0; k < coarseCells; ++k) x.push_back(x.back() + (t *= q));
  x.back() = length;
  return x;
}

Mesh quarterDisk(const QuarterDiskSpec& s) {
  if (!(s.radius > 0.0)) throw InputError("sphere radius must be > 0");
  if (s.refinement < 0 || s.refinement > 6) throw InputError("Geometry/Mesh Refinement must be 0 .. 6");
  if (!(s.fineAngle > 0.0 && s.fineAngle < 0.7)) throw InputError("quarter disk: fine angle must be in (0, 0.7)");
  const int L = s.refinement;
  // Polar angle from the apex: patch B spans [0, pi/4], patch C [pi/4, pi/2].
  const std::vector<Real> thetaB = fineThenGeometric(kPi / 4, s.fineAngle, scaled(16, L), scaled(8, L));
  const int nB = int(thetaB.size()) - 1, nC = scaled(8, L);
  std::vector<Real> thetaC(nC + 1);
  for (int j = 0; j <= nC; ++j) thetaC[j] = kPi / 4 + (kPi / 4) * j / nC;
  // Radial layers of the curved patches, finest at the surface: t in [0, 1] from core to surface.
  const Real core = 0.5;
  const int nR = scaled(14, L);
  // the first layer is as thick as the fine cells along the surface are long
  const Real fineCell = s.fineAngle / scaled(16, L);
  const std::vector<Real> depth = geometric(1.0, fineCell / (1.0 - core), nR);  // from the surface
  std::vector<Real> t(nR + 1);
  for (int k = 0; k <= nR; ++k) t[k] = 1.0 - depth[nR - k];

  Mesh m;
  m.dim = 2;
  m.numBodies = s.body + 1;
  const Real R = s.radius, c = core * R, sy = s.lowerHalf ? -1.0 : 1.0;
  // local frame: x radial, y' = distance from the centre towards the apex (>= 0)
  auto put = [&](Real x, Real yApex) { return addNode(m, x, s.centerY + sy * yApex); };

  // Core rectangle [0, c] x [0, c] in (x, y'): x_i from patch B's rays, y'_j from patch C's rays.
  std::vector<std::vector<LocalIndex>> coreId(nB + 1, std::vector<LocalIndex>(nC + 1));
  for (int i = 0; i <= nB; ++i)
    for (int j = 0; j <= nC; ++j) coreId[i][j] = put(c * std::tan(thetaB[i]), c / std::tan(thetaC[j]));
  // Patch B: rays at thetaB from the core's apex-side edge (y' = c) to the arc.
  std::vector<std::vector<LocalIndex>> bId(nB + 1, std::vector<LocalIndex>(nR + 1));
  for (int i = 0; i <= nB; ++i) {
    bId[i][0] = coreId[i][0];
    const Real x0 = c * std::tan(thetaB[i]), y0 = c;
    const Real x1 = R * std::sin(thetaB[i]), y1 = R * std::cos(thetaB[i]);
    for (int k = 1; k <= nR; ++k) bId[i][k] = put(x0 + t[k] * (x1 - x0), y0 + t[k] * (y1 - y0));
  }
  // Patch C: rays at thetaC from the core's outer edge (x = c) to the arc; the first ray is B's last.
  std::vector<std::vector<LocalIndex>> cId(nC + 1, std::vector<LocalIndex>(nR + 1));
  for (int j = 0; j <= nC; ++j) {
    if (j == 0) {
      cId[0] = bId[nB];
      continue;
    }
    cId[j][0] = coreId[nB][j];
    const Real x0 = c, y0 = c / std::tan(thetaC[j]);
    const Real x1 = R * std::sin(thetaC[j]), y1 = R * std::cos(thetaC[j]);
    for (int k = 1; k <= nR; ++k) cId[j][k] = put(x0 + t[k] * (x1 - x0), y0 + t[k] * (y1 - y0));
  }
  // coreId[i][0] is the apex-side edge (theta_C = pi/4 there gives y' = c) — shared with patch B.
  ElementBlock b;
  b.name = s.name;
  b.body = s.body;
  b.type = CellType::Quad4;
  for (int i = 0; i < nB; ++i)
    for (int j = 0; j < nC; ++j) addQuad(m, b, coreId[i][j], coreId[i + 1][j], coreId[i + 1][j + 1], coreId[i][j + 1]);
  for (int i = 0; i < nB; ++i)
    for (int k = 0; k < nR; ++k) addQuad(m, b, bId[i][k], bId[i + 1][k], bId[i + 1][k + 1], bId[i][k + 1]);
  for (int j = 0; j < nC; ++j)
    for (int k = 0; k < nR; ++k) addQuad(m, b, cId[j][k], cId[j + 1][k], cId[j + 1][k + 1], cId[j][k + 1]);
  m.blocks.push_back(std::move(b));

  std::vector<LocalIndex> axis, equator;
  for (int j = 0; j <= nC; ++j) axis.push_back(coreId[0][j]);
  for (int k = 0; k <= nR; ++k) axis.push_back(bId[0][k]);
  for (int i = 0; i <= nB; ++i) equator.push_back(coreId[i][nC]);
  for (int k = 0; k <= nR; ++k) equator.push_back(cId[nC][k]);
  // the patches share their first rays with the core: remove the repeated nodes
  for (auto* set : {&axis, &equator}) {
    std::sort(set->begin(), set->end());
    set->erase(std::unique(set->begin(), set->end()), set->end());
  }
  m.nodeSets["axis"] = axis;
  m.nodeSets["equator"] = equator;
  m.nodeSets["apex"] = {bId[0][nR]};
  if (s.element.order != 2) {
    buildSurfaces(m);
    return m;
  }
  // the node of an edge between two nodes of the arc goes onto the arc (the midpoint, pushed out radially)
  auto onArc = [&](LocalIndex n) { return std::abs(std::hypot(m.coord(n, 0), m.coord(n, 1) - s.centerY) - R) <= 1e-12 * R; };
  elevate(m, s.element.serendipity, [&](LocalIndex a, LocalIndex b, Real* x) {
    if (!onArc(a) || !onArc(b)) return;
    const Real r = std::hypot(x[0], x[1] - s.centerY);
    x[0] *= R / r;
    x[1] = s.centerY + (x[1] - s.centerY) * R / r;
  });
  return m;
}

Mesh halfSpaceBlock(const HalfSpaceSpec& s) {
  if (!(s.width > s.fineLength) || !(s.depth > 0.0)) throw InputError("half-space block: invalid size");
  if (s.refinement < 0 || s.refinement > 6) throw InputError("Geometry/Mesh Refinement must be 0 .. 6");
  const int L = s.refinement;
  const std::vector<Real> xs = fineThenGeometric(s.width, s.fineLength, scaled(20, L), scaled(10, L));
  const std::vector<Real> ds = geometric(s.depth, s.fineLength / scaled(20, L), scaled(20, L));
  RectangleSpec r;
  r.x0 = 0.0;
  r.y0 = s.topY - s.depth;
  r.lx = s.width;
  r.ly = s.depth;
  r.nx = int(xs.size()) - 1;
  r.ny = int(ds.size()) - 1;
  r.body = s.body;
  r.name = s.name;
  r.element = s.element;
  // Piecewise-linear interpolation of the node tables as gradings.
  auto table = [](std::vector<Real> pos, Real length) {
    return [pos, length](Real u) {
      const Real f = u * (pos.size() - 1);
      const std::size_t k = std::min<std::size_t>(std::size_t(f), pos.size() - 2);
      return (pos[k] + (f - k) * (pos[k + 1] - pos[k])) / length;
    };
  };
  r.gradeX = table(xs, s.width);
  std::vector<Real> ys(ds.size());  // from the bottom: fine at the top
  for (std::size_t k = 0; k < ds.size(); ++k) ys[k] = s.depth - ds[ds.size() - 1 - k];
  r.gradeY = table(ys, s.depth);
  Mesh m = rectangle(r);
  m.nodeSets["axis"] = m.nodeSets.at("left");
  m.nodeSets["side"] = m.nodeSets.at("right");
  m.nodeSets.erase("left");
  m.nodeSets.erase("right");
  m.nodeSets["apex"] = {LocalIndex(std::size_t(r.ny) * (r.nx + 1))};  // (0, topY): first node of the top row
  return m;
}

}  // namespace cgcm::mesh
