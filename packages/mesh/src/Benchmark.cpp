#include "cgcm/mesh/Benchmark.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <set>
#include <stdexcept>

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

int scaled(int n, int level) { return cellsAtLevel(n, level); }

}  // namespace

std::vector<Real> geometric(Real length, Real first, int cells) {
  if (cells < 1 || !(first > 0.0) || !(length > 0.0)) throw InputError("geometric grading: invalid arguments");
  std::vector<Real> x(cells + 1, 0.0);
  if (cells * first >= length) {  // no room to grow (see fineThenGeometric): even cells, shorter than `first`
    for (int k = 1; k <= cells; ++k) x[k] = length * k / cells;
    x[cells] = length;
    return x;
  }
  const Real q = solveRatio(
      [&](Real r) {
        Real s = 0.0, t = first;
        for (int k = 0; k < cells; ++k, t *= r) s += t;
        return s;
      },
      length);
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
  if (coarseCells * h >= rest) {
    // no room to grow: cells of the fine size would run past `length` (and the last one, cut back
    // to it, would fold the mesh), so the rest is split evenly into cells no longer than the fine ones
    for (int k = 1; k <= coarseCells; ++k) x.push_back(fineLength + rest * k / coarseCells);
    x.back() = length;
    return x;
  }
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

Mesh quarterDisk(const QuarterDiskSpec& s, MeridianRows* rows) {
  if (!(s.radius > 0.0)) throw InputError("sphere radius must be > 0");
  if (s.refinement < kCoarsestLevel || s.refinement > kFinestLevel)
    throw InputError("Geometry/Mesh Refinement must be -1 .. 6");
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
  if (rows) {
    if (s.element.order != 1) throw std::logic_error("quarterDisk: rows of a linear mesh only");
    rows->clear();
    for (int j = nC; j >= 0; --j) {
      rows->emplace_back();
      for (int i = 0; i <= nB; ++i) rows->back().push_back(coreId[i][j]);
    }
    for (int k = 1; k <= nR; ++k) {
      rows->emplace_back();
      for (int i = 0; i <= nB; ++i) rows->back().push_back(bId[i][k]);
    }
  }
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

Mesh halfSpaceBlock(const HalfSpaceSpec& s, MeridianRows* rows) {
  if (!(s.width > s.fineLength) || !(s.depth > 0.0)) throw InputError("half-space block: invalid size");
  if (s.refinement < kCoarsestLevel || s.refinement > kFinestLevel)
    throw InputError("Geometry/Mesh Refinement must be -1 .. 6");
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
  if (rows) {
    if (s.element.order != 1) throw std::logic_error("halfSpaceBlock: rows of a linear mesh only");
    rows->assign(std::size_t(r.ny) + 1, {});
    for (int j = 0; j <= r.ny; ++j)
      for (int i = 0; i <= r.nx; ++i) (*rows)[j].push_back(LocalIndex(j * (r.nx + 1) + i));
  }
  return m;
}

namespace {

// The butterfly core's outer side runs from (r, 0) through the kite's corner (kKite r, kKite r)
// to (0, r): its cells there are about as long as the circle's of the same radius, and the core
// cell at the corner has an angle of 127 degrees. Outside, the rings turn into circles linearly
// in the radius between r and kBlendEnd r: slowly enough that the rings keep their order along
// the diagonal (their radius there grows at least 0.8 times as fast as r).
constexpr Real kKite = 0.75;
constexpr Real kBlendEnd = 2.0;

// The sign of a Hex8's volume: 512 times its Jacobian determinant at the centre.
Real hexOrientation(const Mesh& m, const LocalIndex* h) {
  Real e[3][3] = {};
  static const int sign[3][8] = {
      {-1, 1, 1, -1, -1, 1, 1, -1}, {-1, -1, 1, 1, -1, -1, 1, 1}, {-1, -1, -1, -1, 1, 1, 1, 1}};
  for (int d = 0; d < 3; ++d)
    for (int a = 0; a < 8; ++a)
      for (int i = 0; i < 3; ++i) e[d][i] += sign[d][a] * m.coord(h[a], i);
  return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
         e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
}

void addHex(const Mesh& m, ElementBlock& b, std::array<LocalIndex, 8> h) {
  if (hexOrientation(m, h.data()) < 0.0)
    for (int a = 0; a < 4; ++a) std::swap(h[a], h[a + 4]);
  b.connectivity.insert(b.connectivity.end(), h.begin(), h.end());
}

}  // namespace

int largestSweepCore(const Mesh& m, const MeridianRows& rows) {
  if (rows.empty()) return 0;
  std::size_t shortest = rows[0].size();
  for (const auto& row : rows) shortest = std::min(shortest, row.size());
  int best = 0;
  for (int k = 1; k + 1 < int(shortest); ++k) {
    bool fits = true;
    for (const auto& row : rows) {
      const Real rk = m.coord(row[std::size_t(k)], 0);
      fits = fits && rk > 0.0 && m.coord(row.back(), 0) >= kBlendEnd * rk;
    }
    if (!fits) break;
    best = k;
  }
  return best;
}

Mesh sweepQuarter(const Mesh& mer, const MeridianRows& rows, int k) {
  if (mer.dim != 2) throw std::logic_error("sweepQuarter: the meridian mesh is 2D");
  for (const auto& b : mer.blocks)
    if (b.type != CellType::Quad4) throw std::logic_error("sweepQuarter: the meridian mesh is of QUAD4 cells");
  const int limit = largestSweepCore(mer, rows);
  if (k < 1 || k > limit)
    throw InputError("sweep about the axis: a core of " + std::to_string(k) + " cells does not fit (1 .. " +
                     std::to_string(limit) + " do: each row must reach twice the core's radius)");
  const LocalIndex N = mer.numNodes();
  auto x = [&](LocalIndex n) { return mer.coord(n, 0); };
  auto y = [&](LocalIndex n) { return mer.coord(n, 1); };
  std::vector<int> rowOf(std::size_t(N), -1), colOf(std::size_t(N), -1);
  for (std::size_t j = 0; j < rows.size(); ++j)
    for (std::size_t i = 0; i < rows[j].size(); ++i) {
      const LocalIndex n = rows[j][i];
      if (rowOf[n] >= 0) throw std::logic_error("sweepQuarter: a node in two rows");
      if (i == 0 ? x(n) != 0.0 : !(x(n) > x(rows[j][i - 1])))
        throw std::logic_error("sweepQuarter: a row starts on the axis and moves away from it");
      rowOf[n] = int(j), colOf[n] = int(i);
    }
  auto inCore = [&](LocalIndex n) { return rowOf[n] >= 0 && colOf[n] < k; };
  for (LocalIndex n = 0; n < N; ++n)
    if (!(x(n) > 0.0) && !inCore(n)) throw std::logic_error("sweepQuarter: a node on the axis outside the rows");

  // the fractions along the kite's side (and of the quarter circle's half) of its nodes: the first row's spacing
  std::vector<Real> tau(std::size_t(k) + 1);
  for (int a = 0; a <= k; ++a) tau[a] = x(rows[0][a]) / x(rows[0][k]);
  // the height of row j at radius rho (the core and the kite leave the meridian rows' radii)
  auto profile = [&](int j, Real rho) {
    const auto& row = rows[std::size_t(j)];
    std::size_t i = 1;
    while (i + 1 < row.size() && x(row[i]) < rho) ++i;
    const Real t = std::clamp((rho - x(row[i - 1])) / (x(row[i]) - x(row[i - 1])), 0.0, 1.0);
    return y(row[i - 1]) + t * (y(row[i]) - y(row[i - 1]));
  };

  Mesh m;
  m.dim = 3;
  m.numBodies = mer.numBodies;
  std::vector<char> onX0, onY0;
  auto add = [&](Real px, Real py, Real pz) {
    m.coords.insert(m.coords.end(), {px, py, pz});
    onX0.push_back(px == 0.0);
    onY0.push_back(py == 0.0);
    return LocalIndex(m.numNodes() - 1);
  };
  const int na = 2 * k + 1;  // nodes of a ring, azimuth 0 (y = 0) .. 2k (x = 0)
  std::vector<std::vector<LocalIndex>> images(static_cast<std::size_t>(N));
  for (LocalIndex n = 0; n < N; ++n) {
    if (inCore(n)) continue;
    const Real r = x(n);
    const int j = rowOf[n];
    const Real w = j < 0 ? 1.0 : std::clamp((r / x(rows[j][k]) - 1.0) / (kBlendEnd - 1.0), 0.0, 1.0);
    for (int a = 0; a < na; ++a) {
      const int b = a <= k ? a : 2 * k - a;  // the half x >= y, mirrored in the diagonal
      const Real t = tau[b], phi = 0.25 * kPi * t;
      Real u = r * ((1.0 - w) * (1.0 - t + kKite * t) + w * std::cos(phi));
      Real v = r * ((1.0 - w) * kKite * t + w * std::sin(phi));
      if (b == 0) u = r, v = 0.0;
      if (b == k) v = u;
      if (a > k) std::swap(u, v);
      images[n].push_back(add(u, v, w < 1.0 ? profile(j, std::hypot(u, v)) : y(n)));
    }
  }
  // each row's core: grid (p, q), p, q = 0 .. k; its sides q = 0 and p = 0 are the row on the
  // planes y = 0 and x = 0, its sides p = k and q = k the ring of the row's node k
  std::vector<std::vector<LocalIndex>> core(rows.size(), std::vector<LocalIndex>(std::size_t(k + 1) * (k + 1)));
  for (std::size_t j = 0; j < rows.size(); ++j) {
    const auto& row = rows[j];
    const auto& edge = images[row[k]];
    auto at = [&](int p, int q) -> LocalIndex& { return core[j][std::size_t(p) * (k + 1) + q]; };
    for (int p = 0; p <= k; ++p) at(p, k) = edge[2 * k - p], at(k, p) = edge[p];
    at(0, 0) = add(0.0, 0.0, y(row[0]));
    images[row[0]] = {at(0, 0)};
    for (int p = 1; p < k; ++p) {
      at(p, 0) = add(x(row[p]), 0.0, y(row[p]));
      at(0, p) = add(0.0, x(row[p]), y(row[p]));
      images[row[p]] = {at(p, 0), at(0, p)};
    }
    // the inside: transfinite (Coons) blend of the four sides, parameters along the row
    const Real rk = x(row[k]);
    auto X = [&](LocalIndex n, int i) { return m.coord(n, i); };
    for (int p = 1; p < k; ++p)
      for (int q = 1; q < k; ++q) {
        const Real u = x(row[p]) / rk, v = x(row[q]) / rk;
        const LocalIndex right = edge[q], top = edge[2 * k - p], corner = edge[k];
        const Real px =
            u * X(right, 0) + (1.0 - v) * x(row[p]) + v * X(top, 0) - (u * (1.0 - v) * rk + u * v * X(corner, 0));
        const Real py =
            (1.0 - u) * x(row[q]) + u * X(right, 1) + v * X(top, 1) - ((1.0 - u) * v * rk + u * v * X(corner, 1));
        at(p, q) = add(px, py, profile(int(j), std::hypot(px, py)));
      }
  }

  // cells: a meridian cell off the core columns sweeps into 2k hexahedra; the core ones are replaced by the
  // cores' grids between consecutive rows
  std::vector<int> coreCells(rows.size(), 0), pairBlock(rows.size(), -1);
  for (std::size_t bi = 0; bi < mer.blocks.size(); ++bi) {
    const auto& b2 = mer.blocks[bi];
    ElementBlock b;
    b.name = b2.name;
    b.body = b2.body;
    b.type = CellType::Hex8;
    for (LocalIndex c = 0; c < b2.numCells(); ++c) {
      const LocalIndex* q = &b2.connectivity[std::size_t(c) * 4];
      if (std::any_of(q, q + 4, inCore)) {
        int jmin = 1 << 30, jmax = -1, imax = -1, imin = 1 << 30;
        for (int a = 0; a < 4; ++a) {
          if (rowOf[q[a]] < 0) throw std::logic_error("sweepQuarter: a cell next to the axis off the rows");
          jmin = std::min(jmin, rowOf[q[a]]), jmax = std::max(jmax, rowOf[q[a]]);
          imin = std::min(imin, colOf[q[a]]), imax = std::max(imax, colOf[q[a]]);
        }
        if (jmax != jmin + 1 || imax != imin + 1 || imax > k)
          throw std::logic_error("sweepQuarter: a cell next to the axis is not between consecutive rows");
        ++coreCells[jmin];
        pairBlock[jmin] = int(bi);
        continue;
      }
      for (int a = 0; a + 1 < na; ++a)
        addHex(m, b,
               {images[q[0]][a], images[q[1]][a], images[q[2]][a], images[q[3]][a], images[q[0]][a + 1],
                images[q[1]][a + 1], images[q[2]][a + 1], images[q[3]][a + 1]});
    }
    m.blocks.push_back(std::move(b));
  }
  for (std::size_t j = 0; j + 1 < rows.size(); ++j) {
    if (coreCells[j] != k) throw std::logic_error("sweepQuarter: consecutive rows are not joined by cells");
    auto& b = m.blocks[std::size_t(pairBlock[j])];
    const auto& lo = core[j];
    const auto& hi = core[j + 1];
    auto id = [k](int p, int q) { return std::size_t(p) * (k + 1) + q; };
    for (int p = 0; p < k; ++p)
      for (int q = 0; q < k; ++q)
        addHex(m, b,
               {lo[id(p, q)], lo[id(p + 1, q)], lo[id(p + 1, q + 1)], lo[id(p, q + 1)], hi[id(p, q)], hi[id(p + 1, q)],
                hi[id(p + 1, q + 1)], hi[id(p, q + 1)]});
  }

  // node sets: the images of their nodes, and the core's inside of the rows they hold whole
  for (const auto& [name, nodes] : mer.nodeSets) {
    std::vector<char> in(std::size_t(N), 0);
    for (LocalIndex n : nodes) in[n] = 1;
    std::vector<LocalIndex> out;
    for (LocalIndex n : nodes) out.insert(out.end(), images[n].begin(), images[n].end());
    for (std::size_t j = 0; j < rows.size(); ++j)
      if (std::all_of(rows[j].begin(), rows[j].begin() + k + 1, [&](LocalIndex n) { return in[n] != 0; }))
        for (int p = 1; p < k; ++p)
          for (int q = 1; q < k; ++q) out.push_back(core[j][std::size_t(p) * (k + 1) + q]);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    m.nodeSets[name] = std::move(out);
  }
  for (auto [name, flags] : {std::pair{"symmetry x", &onX0}, std::pair{"symmetry y", &onY0}}) {
    auto& set = m.nodeSets[name];
    for (LocalIndex n = 0; n < m.numNodes(); ++n)
      if ((*flags)[n]) set.push_back(n);
  }
  buildSurfaces(m);
  return m;
}

MeshSize sphereOnHalfSpaceQuarterSize(int refinement, int quarterCells) {
  // the meridian meshes' cell counts (quarterDisk, halfSpaceBlock) and sweepQuarter's: the rows' first k
  // columns make a k x k core per row, every other node a ring of 2k + 1 nodes
  const double s = std::ldexp(1.0, refinement), k = quarterCells / 2;
  auto swept = [k](double nodes, double cells, double rows) {
    return MeshSize{(nodes - rows * k) * (2 * k + 1) + rows * k * k,
                    (cells - (rows - 1) * k) * 2 * k + (rows - 1) * k * k};
  };
  const double nB = 24 * s, nC = 8 * s, nR = 14 * s, nx = 30 * s, ny = 20 * s;
  const MeshSize sphere =
      swept((nB + 1) * (nC + 1) + (nB + 1) * nR + nC * nR, nB * nC + nB * nR + nC * nR, nC + nR + 1);
  const MeshSize block = swept((nx + 1) * (ny + 1), nx * ny, ny + 1);
  return {sphere.nodes + block.nodes, sphere.cells + block.cells};
}

int largestQuarterCells(const QuarterDiskSpec& sphere, const HalfSpaceSpec& halfSpace) {
  QuarterDiskSpec s = sphere;
  HalfSpaceSpec h = halfSpace;
  s.element = h.element = ElementOrder{};
  MeridianRows sphereRows, blockRows;
  const Mesh disk = quarterDisk(s, &sphereRows);
  const Mesh block = halfSpaceBlock(h, &blockRows);
  return 2 * std::min(largestSweepCore(disk, sphereRows), largestSweepCore(block, blockRows));
}

Mesh sphereOnHalfSpaceQuarter(const QuarterDiskSpec& sphereSpec, const HalfSpaceSpec& halfSpaceSpec, int quarterCells) {
  if (quarterCells < 2 || quarterCells % 2 != 0)
    throw InputError("the quarter model needs an even number (>= 2) of cells over its 90 degrees, got " +
                     std::to_string(quarterCells));
  const int k = quarterCells / 2;
  const ElementOrder element = sphereSpec.element;
  QuarterDiskSpec s = sphereSpec;
  HalfSpaceSpec h = halfSpaceSpec;
  s.element = h.element = ElementOrder{};  // swept linear, elevated in 3D
  s.body = 0, h.body = 0;
  MeridianRows sphereRows, blockRows;
  Mesh disk = quarterDisk(s, &sphereRows);
  Mesh block = halfSpaceBlock(h, &blockRows);
  // the arc's nodes: their images go onto the sphere
  const Real R = s.radius;
  std::vector<Real> centre = {0.0, 0.0, s.centerY};
  auto onSphere = [&](const Mesh& m, LocalIndex n) {
    Real d2 = 0.0;
    for (int i = 0; i < m.dim; ++i) {
      const Real d = m.coord(n, i) - centre[std::size_t(3 - m.dim + i)];
      d2 += d * d;
    }
    return std::abs(std::sqrt(d2) - R) <= 1e-9 * R;
  };
  auto& arc = disk.nodeSets["sphere surface"];
  for (LocalIndex n = 0; n < disk.numNodes(); ++n)
    if (onSphere(disk, n)) arc.push_back(n);
  Mesh sphere = sweepQuarter(disk, sphereRows, k);
  Mesh half = sweepQuarter(block, blockRows, k);
  auto project = [&](Real* x) {
    const Real r = std::sqrt(x[0] * x[0] + x[1] * x[1] + (x[2] - centre[2]) * (x[2] - centre[2]));
    for (int i = 0; i < 3; ++i) x[i] = centre[std::size_t(i)] + (x[i] - centre[std::size_t(i)]) * (R / r);
  };
  for (LocalIndex n : sphere.nodeSet("sphere surface")) project(&sphere.coords[std::size_t(n) * 3]);
  if (element.order == 2) {
    // the new nodes of edges and faces whose corners are on the sphere go onto it; the cell nodes follow
    const std::vector<LocalIndex> corners = sphere.nodeSet("sphere surface");
    auto isCorner = [&](LocalIndex n) { return std::binary_search(corners.begin(), corners.end(), n); };
    elevate(
        sphere, element.serendipity,
        [&](LocalIndex a, LocalIndex b, Real* x) {
          if (isCorner(a) && isCorner(b)) project(x);
        },
        [&](const std::vector<LocalIndex>& face, Real* x) {
          if (std::all_of(face.begin(), face.end(), isCorner)) project(x);
        });
    elevate(half, element.serendipity);
  }
  sphere.nodeSets["driven"] = sphere.nodeSet("equator");
  auto& all = sphere.nodeSets["driven body"];
  for (LocalIndex n = 0; n < sphere.numNodes(); ++n) all.push_back(n);
  append(sphere, half, "lower ");
  Mesh& m = sphere;
  m.nodeSets["fixed"] = m.nodeSet("lower bottom");
  for (const char* plane : {"symmetry x", "symmetry y"}) {
    auto& set = m.nodeSets[plane];
    const auto& lower = m.nodeSet(std::string("lower ") + plane);
    set.insert(set.end(), lower.begin(), lower.end());
    std::sort(set.begin(), set.end());
  }
  // the interacting surfaces: the sphere's curved face and the half-space's top
  for (const char* set : {"symmetry x", "symmetry y", "driven"}) removeFacetsOn(m, 0, m.nodeSet(set));
  for (const char* set : {"symmetry x", "symmetry y", "fixed", "lower side"}) removeFacetsOn(m, 1, m.nodeSet(set));
  // the node sets of a gmsh mesh of the benchmark, no others
  for (int body : {0, 1}) {
    const Surface& surface = m.surfaces[std::size_t(body)];
    std::vector<LocalIndex> nodes(surface.facets);
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    m.nodeSets[body == 0 ? "contact:sphere" : "contact:half-space"] = std::move(nodes);
  }
  static const std::set<std::string> keep = {"apex",        "lower apex",     "driven",
                                             "fixed",       "symmetry x",     "symmetry y",
                                             "driven body", "contact:sphere", "contact:half-space"};
  for (auto it = m.nodeSets.begin(); it != m.nodeSets.end();)
    it = keep.count(it->first) ? std::next(it) : m.nodeSets.erase(it);
  return m;
}

}  // namespace cgcm::mesh
