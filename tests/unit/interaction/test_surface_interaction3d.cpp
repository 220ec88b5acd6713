// Method 3 driver in 3D: a triangulated spherical cap above a flat surface of
// quadrilaterals (and of triangles). The assembled tangent against central
// differences of the assembled residual (curved neighbours, projections onto
// faces, edges and vertices), graph couplings covering every pair, the CGAL
// and brute-force searches agreeing, and the bounding-box test between bodies.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <vector>

#include "cgcm/core/Error.hpp"
#include "cgcm/interaction/SurfaceInteraction.hpp"

using namespace cgcm;
using namespace cgcm::interaction;

namespace {

struct Scene {
  std::vector<Real> coords;  // 3 per node
  std::vector<mesh::Surface> surfaces;
};

// Flat n x n grid on [-L, L]^2 at z = 0, outward normal +z (quads, or each quad split in two triangles).
mesh::Surface flatGrid(std::vector<Real>& coords, int n, Real L, bool triangles, int body) {
  const LocalIndex first = LocalIndex(coords.size() / 3);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) coords.insert(coords.end(), {-L + 2 * L * i / n, -L + 2 * L * j / n, 0.0});
  mesh::Surface s;
  s.body = body;
  s.nodesPerFacet = triangles ? 3 : 4;
  auto id = [&](int i, int j) { return first + LocalIndex(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const LocalIndex a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (triangles) s.facets.insert(s.facets.end(), {a, b, c, a, c, d});
      else s.facets.insert(s.facets.end(), {a, b, c, d});
    }
  return s;
}

// Lower cap of a sphere of radius R centred at height zc over a grid of
// [-L, L]^2, triangles with outward normal (down, away from the centre).
mesh::Surface sphereCap(std::vector<Real>& coords, int n, Real L, Real R, Real zc, int body) {
  const LocalIndex first = LocalIndex(coords.size() / 3);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const Real x = -L + 2 * L * i / n, y = -L + 2 * L * j / n + 0.013;  // off the grid's symmetry
      coords.insert(coords.end(), {x, y, zc - std::sqrt(R * R - x * x - y * y)});
    }
  mesh::Surface s;
  s.body = body;
  s.nodesPerFacet = 3;
  auto id = [&](int i, int j) { return first + LocalIndex(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const LocalIndex a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      s.facets.insert(s.facets.end(), {a, c, b, a, d, c});  // clockwise seen from above: normal down
    }
  return s;
}

Scene capOverFlat(bool flatTriangles) {
  Scene sc;
  sc.surfaces.push_back(flatGrid(sc.coords, 6, 1.5, flatTriangles, 0));
  sc.surfaces.push_back(sphereCap(sc.coords, 5, 0.8, 2.0, 2.0 + 0.6, 1));
  return sc;
}

SurfaceInteraction makeInteraction(const Scene& sc, SearchMethod search = SearchMethod::Tree) {
  SurfaceInteractionOptions o;
  o.formulation = Formulation::ThreeD;
  o.quadraturePoints = 2;
  o.cutoff = 2.5;
  o.search = search;
  return SurfaceInteraction(sc.surfaces, {1.0, 1.3}, makePotential("lennard-jones", 1.0, 0.5), o);
}

std::vector<Real> residual(SurfaceInteraction& si, const std::vector<Real>& coords) {
  std::vector<PairContribution> c;
  si.evaluate(coords, c, false);
  std::vector<Real> f(coords.size(), 0.0);
  for (const auto& p : c)
    for (int a = 0; a < p.numRowNodes; ++a)
      for (int i = 0; i < 3; ++i) f[3 * p.rowNodes[a] + i] += p.f[3 * a + i];
  return f;
}

std::map<std::pair<int, int>, Real> tangent(SurfaceInteraction& si, const std::vector<Real>& coords) {
  std::vector<PairContribution> c;
  si.evaluate(coords, c, true);
  std::map<std::pair<int, int>, Real> K;
  for (const auto& p : c)
    for (int a = 0; a < p.numRowNodes; ++a)
      for (int i = 0; i < 3; ++i)
        for (int b = 0; b < p.numColNodes; ++b)
          for (int j = 0; j < 3; ++j) K[{3 * p.rowNodes[a] + i, 3 * p.colNodes[b] + j}] += p.K[3 * a + i][3 * b + j];
  return K;
}

}  // namespace

TEST(SurfaceInteraction3D, TangentMatchesFiniteDifferences) {
  for (bool flatTriangles : {false, true}) {
    Scene sc = capOverFlat(flatTriangles);
    SurfaceInteraction si = makeInteraction(sc);
    si.updatePairs(sc.coords);
    ASSERT_GT(si.pairs().size(), 100u);
    std::vector<PairContribution> c;
    si.evaluate(sc.coords, c, false);
    int regions[7] = {};
    for (const auto& p : si.pairs()) {
      // the region of each pair's projection, from the kernel's state
      PairContribution pc;
      ++regions[si.evaluatePair(sc.coords.data(), p, pc, false).region];
    }
    const auto K = tangent(si, sc.coords);
    Real kmax = 0.0;
    for (const auto& kv : K) kmax = std::max(kmax, std::abs(kv.second));
    Real worst = 0.0;
    const Real h = 1e-7;
    for (std::size_t j = 0; j < sc.coords.size(); ++j) {
      std::vector<Real> cp = sc.coords, cm = sc.coords;
      cp[j] += h, cm[j] -= h;
      const auto fp = residual(si, cp), fm = residual(si, cm);
      for (std::size_t i = 0; i < fp.size(); ++i) {
        const Real fd = (fp[i] - fm[i]) / (2 * h);
        const auto it = K.find({int(i), int(j)});
        const Real k = it == K.end() ? 0.0 : it->second;
        worst = std::max(worst, std::abs(k - fd) / kmax);
      }
    }
    std::printf("[si3d] flat %s: %zu pairs (face %d, vertex %d, edge %d), max|K - K_fd|/max|K| = %.2e\n",
                flatTriangles ? "tri3" : "quad4", si.pairs().size(), regions[0], regions[1] + regions[2] + regions[3],
                regions[4] + regions[5] + regions[6], worst);
    EXPECT_LT(worst, 1e-6);
    // the flat grid's outer points see the cap's rim from outside: edges and vertices
    EXPECT_GT(regions[0], 0);
    EXPECT_GT(regions[1] + regions[2] + regions[3] + regions[4] + regions[5] + regions[6], 0);
  }
}

TEST(SurfaceInteraction3D, CouplingsCoverEveryPair) {
  Scene sc = capOverFlat(false);
  SurfaceInteraction si = makeInteraction(sc);
  si.updatePairs(sc.coords);
  std::vector<PairContribution> c;
  si.evaluate(sc.coords, c, true);
  const auto graph = si.couplings(sc.coords, 1.1 * si.cutoff());
  int missing = 0;
  for (const auto& p : c)
    for (int a = 0; a < p.numRowNodes; ++a)
      for (int b = 0; b < p.numColNodes; ++b)
        if (!std::binary_search(graph.begin(), graph.end(), std::make_pair(p.rowNodes[a], p.colNodes[b]))) ++missing;
  EXPECT_EQ(missing, 0);
}

TEST(SurfaceInteraction3D, TreeAndBruteForceAgree) {
  Scene sc = capOverFlat(false);
  SurfaceInteraction tree = makeInteraction(sc), brute = makeInteraction(sc, SearchMethod::BruteForce);
  tree.updatePairs(sc.coords);
  brute.updatePairs(sc.coords);
  ASSERT_EQ(tree.pairs().size(), brute.pairs().size());
  const auto ft = residual(tree, sc.coords), fb = residual(brute, sc.coords);
  Real fmax = 0.0, diff = 0.0;
  for (std::size_t i = 0; i < ft.size(); ++i) fmax = std::max(fmax, std::abs(ft[i])), diff = std::max(diff, std::abs(ft[i] - fb[i]));
  EXPECT_LE(diff, 1e-12 * fmax);
  // both bodies pull on each other: opposite vertical resultants of similar size
  const auto& R = tree.summary().resultant;
  EXPECT_LT(R[0][2] * R[1][2], 0.0);
}

TEST(SurfaceInteraction3D, FarBodiesAreNotSearched) {
  Scene sc = capOverFlat(false);
  for (std::size_t k = 3 * 49; k < sc.coords.size(); k += 3) sc.coords[k + 2] += 10.0;  // lift the cap (after 7 x 7 flat nodes)
  SurfaceInteraction si = makeInteraction(sc);
  si.updatePairs(sc.coords);
  EXPECT_EQ(si.pairs().size(), 0u);
  EXPECT_EQ(si.summary().numQuadraturePoints, 0);
}

TEST(SurfaceInteraction3D, RejectsSegmentsIn3D) {
  Scene sc = capOverFlat(false);
  sc.surfaces[0].nodesPerFacet = 2;
  EXPECT_THROW(makeInteraction(sc), InputError);
}
