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

/// Lennard-Jones with r0 = 0.5, 2 x 2 points per facet, cutoff 2.5.
SurfaceInteraction sceneInteraction(const Scene& sc, std::vector<Real> densities, SearchMethod search,
                                    Real smoothing = -1.0) {
  SurfaceInteractionOptions o;
  o.formulation = Formulation::ThreeD;
  o.quadraturePoints = 2;
  o.cutoff = 2.5;
  o.search = search;
  o.projectionSmoothing = smoothing;
  return SurfaceInteraction(sc.surfaces, std::move(densities), makePotential("lennard-jones", 1.0, 0.5), o);
}

SurfaceInteraction makeInteraction(const Scene& sc, SearchMethod search = SearchMethod::Tree) {
  return sceneInteraction(sc, {1.0, 1.3}, search);
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
    // fourth-order central differences: the blend weights vary on the scale
    // delta = 1e-3 r0, where the second-order stencil's truncation and
    // round-off leave no step below 7e-7; this one's round-off is about
    // 1e-13/h (measured: 1.3e-7 at h = 1e-6, 5.7e-8 at 3e-6, where a
    // projection-region kink enters the tri3 case)
    const Real h = 1e-6;
    for (std::size_t j = 0; j < sc.coords.size(); ++j) {
      std::vector<Real> c1 = sc.coords, c2 = sc.coords, c3 = sc.coords, c4 = sc.coords;
      c1[j] += 2 * h, c2[j] += h, c3[j] -= h, c4[j] -= 2 * h;
      const auto f1 = residual(si, c1), f2 = residual(si, c2), f3 = residual(si, c3), f4 = residual(si, c4);
      for (std::size_t i = 0; i < f1.size(); ++i) {
        const Real fd = (-f1[i] + 8 * f2[i] - 8 * f3[i] + f4[i]) / (12 * h);
        const auto it = K.find({int(i), int(j)});
        const Real k = it == K.end() ? 0.0 : it->second;
        worst = std::max(worst, std::abs(k - fd) / kmax);
      }
    }
    std::printf("[si3d] flat %s: %zu pairs (face %d, vertex %d, edge %d), max|K - K_fd|/max|K| = %.2e\n",
                flatTriangles ? "tri3" : "quad4", si.pairs().size(), regions[0], regions[1] + regions[2] + regions[3],
                regions[4] + regions[5] + regions[6], worst);
    EXPECT_LT(worst, 3e-7);
    // the flat grid's outer points see the cap's rim from outside: edges and vertices
    EXPECT_GT(regions[0], 0);
    EXPECT_GT(regions[1] + regions[2] + regions[3] + regions[4] + regions[5] + regions[6], 0);
  }
}

// A valley: two flat strips of triangles meeting at the concave edge x = 0
// (z = slope |x|), and a small quad patch above it. A point above the edge
// has its feet inside both strips; its closest triangle switches sides where
// it crosses the bisector x = 0, and so does the direction of x - x_P.
Scene patchOverValley(Real slope, Real x0) {
  Scene sc;
  sc.surfaces.push_back(flatGrid(sc.coords, 8, 1.0, true, 0));
  for (std::size_t n = 0; n < sc.coords.size(); n += 3) sc.coords[n + 2] = slope * std::abs(sc.coords[n]);
  const LocalIndex first = LocalIndex(sc.coords.size() / 3);
  const Real h = 0.3, w = 0.1;  // the patch: 2 x 2 quads of width w at height h, centred at x0, normal down
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= 2; ++i) sc.coords.insert(sc.coords.end(), {x0 + w * (i - 1), 0.03 + w * (j - 1), h});
  mesh::Surface q;
  q.body = 1;
  q.nodesPerFacet = 4;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      const LocalIndex a = first + LocalIndex(j * 3 + i);
      q.facets.insert(q.facets.end(), {a, LocalIndex(a + 3), LocalIndex(a + 4), LocalIndex(a + 1)});
    }
  sc.surfaces.push_back(q);
  return sc;
}

SurfaceInteraction valleyInteraction(const Scene& sc, Real smoothing) {
  return sceneInteraction(sc, {1.0, 1.0}, SearchMethod::Tree, smoothing);
}

// Force on the patch as its centre crosses the valley's bisector: with the
// closest triangle alone it jumps; blended over the triangles within a few
// delta it does not, and its tangent matches finite differences.
TEST(SurfaceInteraction3D, BlendIsContinuousAcrossAConcaveEdge) {
  auto patchForce = [](Real smoothing, Real x0) {
    Scene sc = patchOverValley(0.3, x0);
    SurfaceInteraction si = valleyInteraction(sc, smoothing);
    si.updatePairs(sc.coords);
    std::vector<PairContribution> c;
    si.evaluate(sc.coords, c, false);
    return si.summary().resultant[1];
  };
  // the patch's Gauss points sit at x0 -+ w/2 -+ w/(2 sqrt 3): x0 = xc -+ e puts a row of them across x = 0
  const Real e = 1e-9, xc = 0.05 - 0.05 / std::sqrt(3.0);
  for (Real smoothing : {0.0, 5e-4}) {
    const auto fa = patchForce(smoothing, xc - e), fb = patchForce(smoothing, xc + e);
    const Real jump = std::abs(fa[0] - fb[0]) / std::abs(fa[2]);
    std::printf("[valley] smoothing %.0e: jump of Fx across the bisector = %.2e |Fz|\n", smoothing, jump);
    if (smoothing == 0.0) EXPECT_GT(jump, 1e-3);
    else EXPECT_LT(jump, 1e-7);
  }
  // the tangent of the blend, with delta large enough that weights vary on the FD scale
  for (Real x0 : {xc, xc + 0.01}) {
    Scene sc = patchOverValley(0.3, x0);
    SurfaceInteraction si = valleyInteraction(sc, 0.05);
    si.updatePairs(sc.coords);
    EXPECT_GT(si.summary().numBlended, 0);
    const auto K = tangent(si, sc.coords);
    Real kmax = 0.0, worst = 0.0;
    for (const auto& kv : K) kmax = std::max(kmax, std::abs(kv.second));
    const Real h = 1e-6;
    for (std::size_t j = 0; j < sc.coords.size(); ++j) {
      std::vector<Real> cp = sc.coords, cm = sc.coords;
      cp[j] += h, cm[j] -= h;
      const auto fp = residual(si, cp), fm = residual(si, cm);
      for (std::size_t i = 0; i < fp.size(); ++i) {
        const auto it = K.find({int(i), int(j)});
        worst = std::max(worst, std::abs((it == K.end() ? 0.0 : it->second) - (fp[i] - fm[i]) / (2 * h)) / kmax);
      }
    }
    std::printf("[valley] blended pairs %d, max|K - K_fd|/max|K| = %.2e\n", int(si.summary().numBlended), worst);
    EXPECT_LT(worst, 1e-7);
  }
}

// A quad grid of current size 2 x 2 at height h over a wide flat, stretched by (1.1, 1.05) from its
// reference: it carries T(h) times its current area 4 with the current area, times its reference
// area 4 / (1.1 x 1.05) with the reference area (the Gauss rule integrates both exactly; relative
// 1e-12 for the rounding of the sums).
TEST(SurfaceInteraction3D, ReferenceAreaCountsTheUndeformedLayer) {
  const Real h = 0.6, sx = 1.1, sy = 1.05;
  Scene sc;
  sc.surfaces.push_back(flatGrid(sc.coords, 6, 4.0, false, 0));
  mesh::Surface upper = flatGrid(sc.coords, 4, 1.0, false, 1);
  for (std::size_t f = 0; f < upper.facets.size(); f += 4) std::swap(upper.facets[f + 1], upper.facets[f + 3]);  // normal -z
  const std::size_t firstUpper = std::size_t(sc.surfaces[0].facets.back()) + 1;
  for (std::size_t n = firstUpper; n < sc.coords.size() / 3; ++n) sc.coords[3 * n + 2] = h;
  sc.surfaces.push_back(upper);
  std::vector<Real> reference = sc.coords;
  for (std::size_t n = firstUpper; n < sc.coords.size() / 3; ++n) reference[3 * n] /= sx, reference[3 * n + 1] /= sy;
  const auto lj = makePotential("lennard-jones", 1.0, 0.5);
  const Real T = lj->traction(h, 1.0, 1.0);
  for (SurfaceDensity density : {SurfaceDensity::CurrentArea, SurfaceDensity::ReferenceArea}) {
    SurfaceInteractionOptions o;
    o.formulation = Formulation::ThreeD;
    o.quadraturePoints = 2;
    o.cutoff = 10.0;
    o.surfaceDensity = density;
    SurfaceInteraction si(sc.surfaces, {1.0, 1.0}, lj, o);
    si.setReferenceConfiguration(reference);
    si.updatePairs(sc.coords);
    std::vector<PairContribution> c;
    si.evaluate(sc.coords, c, false);
    const Real area = density == SurfaceDensity::ReferenceArea ? 4.0 / (sx * sy) : 4.0;
    EXPECT_NEAR(si.summary().resultant[1][2], T * area, 1e-12 * std::abs(T * area))
        << (density == SurfaceDensity::ReferenceArea ? "reference area" : "current area");
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

// One search per state: a second call at the same coordinates reuses the
// pairs; after a move the search (started from the previous projections)
// finds what a fresh instance finds.
TEST(SurfaceInteraction3D, SearchesOncePerState) {
  Scene sc = capOverFlat(false);
  SurfaceInteraction si = makeInteraction(sc);
  si.updatePairs(sc.coords);
  si.updatePairs(sc.coords);
  EXPECT_EQ(si.summary().numSearches, 1);
  std::vector<Real> moved = sc.coords;
  for (std::size_t i = 0; i < moved.size(); ++i) moved[i] += 0.02 * std::sin(0.7 * i);
  si.updatePairs(moved);
  EXPECT_EQ(si.summary().numSearches, 2);
  SurfaceInteraction fresh = makeInteraction(sc);
  fresh.updatePairs(moved);
  ASSERT_EQ(si.pairs().size(), fresh.pairs().size());
  std::size_t sameTarget = 0;
  for (std::size_t i = 0; i < si.pairs().size(); ++i) {
    EXPECT_EQ(si.pairs()[i].facet, fresh.pairs()[i].facet);
    EXPECT_EQ(si.pairs()[i].otherBody, fresh.pairs()[i].otherBody);
    sameTarget += si.pairs()[i].target() == fresh.pairs()[i].target();
  }
  EXPECT_EQ(sameTarget, si.pairs().size());
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

// Two ranks' shares: the facets split in two complementary sets give, between
// them, exactly the pairs, the residual and the graph couplings of all facets.
TEST(SurfaceInteraction3D, ComplementaryFacetSharesAddUpToTheWhole) {
  Scene sc = capOverFlat(false);
  SurfaceInteraction whole = makeInteraction(sc);
  whole.updatePairs(sc.coords);
  const auto fWhole = residual(whole, sc.coords);
  const auto cWhole = whole.couplings(sc.coords, 1.1 * whole.cutoff());
  std::vector<Real> fSum(fWhole.size(), 0.0);
  std::vector<std::pair<LocalIndex, LocalIndex>> cUnion;
  std::size_t pairs = 0;
  for (int share = 0; share < 2; ++share) {
    SurfaceInteraction part = makeInteraction(sc);
    std::vector<std::vector<char>> evaluated;
    for (const auto& s : sc.surfaces) {
      evaluated.emplace_back(s.numFacets());
      for (LocalIndex f = 0; f < s.numFacets(); ++f) evaluated.back()[f] = char((f * 7 / 3) % 2 == share);
    }
    part.setEvaluatedFacets(evaluated);
    part.updatePairs(sc.coords);
    pairs += part.pairs().size();
    for (const auto& p : part.pairs()) EXPECT_TRUE(evaluated[p.body][p.facet]);
    const auto f = residual(part, sc.coords);
    for (std::size_t i = 0; i < f.size(); ++i) fSum[i] += f[i];
    const auto c = part.couplings(sc.coords, 1.1 * part.cutoff());
    cUnion.insert(cUnion.end(), c.begin(), c.end());
  }
  EXPECT_EQ(pairs, whole.pairs().size());
  Real fmax = 0.0, diff = 0.0;
  for (std::size_t i = 0; i < fWhole.size(); ++i)
    fmax = std::max(fmax, std::abs(fWhole[i])), diff = std::max(diff, std::abs(fWhole[i] - fSum[i]));
  EXPECT_GT(fmax, 0.0);
  EXPECT_LE(diff, 1e-13 * fmax);
  std::sort(cUnion.begin(), cUnion.end());
  cUnion.erase(std::unique(cUnion.begin(), cUnion.end()), cUnion.end());
  EXPECT_EQ(cUnion, cWhole);
}

TEST(SurfaceInteraction3D, EvaluatedFacetsNeedOneFlagPerFacet) {
  Scene sc = capOverFlat(false);
  SurfaceInteraction si = makeInteraction(sc);
  EXPECT_THROW(si.setEvaluatedFacets({std::vector<char>(sc.surfaces[0].numFacets(), 1)}), InputError);
  EXPECT_THROW(si.setEvaluatedFacets({std::vector<char>(3, 1), std::vector<char>(sc.surfaces[1].numFacets(), 1)}),
               InputError);
}
