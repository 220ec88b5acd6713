// Closest-point search: CGAL's AABB tree against brute force.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>

#include "InteractionTestUtil.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/interaction/ClosestPointSearch.hpp"

using namespace cgcm;
using namespace cgcm::interaction;
using namespace cgcm::interaction::testing;

namespace {

// A wavy, non-uniformly sampled open curve with convex and concave corners.
std::vector<Real> wavyCurve(int n) {
  return samplePolyline(
      [](Real s, Real& x, Real& y) {
        const Real u = s * s * (3.0 - 2.0 * s);  // graded: finer at both ends
        x = 4.0 * u;
        y = 0.3 * std::sin(3.0 * x) + 0.1 * x * x;
      },
      n);
}

std::vector<Real> circle(int n, Real R) {
  std::vector<Real> p;
  for (int i = 0; i <= n; ++i) {
    const Real t = 2.0 * kPi * i / n;
    p.push_back(R * std::cos(t));
    p.push_back(R * std::sin(t));
  }
  return p;
}

// Same facet, or an exact tie; same distance and point (tolerance 1e-13 absolute, O(1) geometry).
void expectSameProjection(const Projection& a, const Projection& b, const Real* x) {
  ASSERT_EQ(a.found(), b.found()) << "x = (" << x[0] << ", " << x[1] << ")";
  if (!a.found()) return;
  EXPECT_EQ(a.facet, b.facet) << "x = (" << x[0] << ", " << x[1] << ")";
  EXPECT_NEAR(a.distance, b.distance, 1e-13);
  EXPECT_NEAR(a.point[0], b.point[0], 1e-13);
  EXPECT_NEAR(a.point[1], b.point[1], 1e-13);
  EXPECT_NEAR(a.xi[0], b.xi[0], 1e-13);
}

// The accelerated implementations under test.
std::vector<std::unique_ptr<ClosestPointSearch>> accelerated() {
  std::vector<std::unique_ptr<ClosestPointSearch>> v;
  v.push_back(std::make_unique<AabbTreeSearch2D>());
  return v;
}

}  // namespace

TEST(SegmentProjection, ClampsToVertices) {
  const Real a[2] = {0.0, 0.0}, b[2] = {2.0, 0.0};
  Real xi, p[2];
  int region;
  const Real x1[2] = {0.5, 1.0};
  EXPECT_DOUBLE_EQ(projectOntoSegment(x1, a, b, xi, p, region), 1.0);
  EXPECT_EQ(region, 0);
  EXPECT_DOUBLE_EQ(xi, 0.25);
  const Real x2[2] = {-3.0, 4.0};
  EXPECT_DOUBLE_EQ(projectOntoSegment(x2, a, b, xi, p, region), 25.0);
  EXPECT_EQ(region, 1);
  EXPECT_EQ(xi, 0.0);
  const Real x3[2] = {5.0, -4.0};
  EXPECT_DOUBLE_EQ(projectOntoSegment(x3, a, b, xi, p, region), 25.0);
  EXPECT_EQ(region, 2);
  EXPECT_EQ(p[0], 2.0);
  // degenerate segment: the vertex
  EXPECT_DOUBLE_EQ(projectOntoSegment(x1, a, a, xi, p, region), 1.25);
  EXPECT_EQ(region, 1);
}

TEST(ClosestPointSearch, MatchesBruteForceOnCurvedPolyline) {
  std::vector<Real> coords;
  const mesh::Surface surf = addPolyline(coords, wavyCurve(300), 1);
  BruteForceSegmentSearch2D brute;
  brute.build(coords, surf);
  for (auto& search : accelerated()) {
    ClosestPointSearch& grid = *search;
    grid.build(coords, surf);
    ASSERT_EQ(grid.numFacets(), 300);

    std::mt19937 rng(7);
    std::uniform_real_distribution<Real> ux(-1.5, 5.5), uy(-1.5, 3.5);
    int vertexCases = 0, interiorCases = 0;
    const Real inf = std::numeric_limits<Real>::infinity();
    for (int i = 0; i < 20000; ++i) {
      const Real x[2] = {ux(rng), uy(rng)};
      const Projection pb = brute.project(x, inf);
      expectSameProjection(grid.project(x, inf), pb, x);
      ASSERT_TRUE(pb.found());
      if (pb.xi[0] == 0.0 || pb.xi[0] == 1.0)
        ++vertexCases;
      else
        ++interiorCases;
    }
    // both kinds of projection are exercised (end vertices and convex corners)
    EXPECT_GT(vertexCases, 500);
    EXPECT_GT(interiorCases, 5000);
  }
}

TEST(ClosestPointSearch, PointsNearTheCurveIncludingCornerRegions) {
  // points at distance < 0.05 from the nodes: vertex regions of convex corners
  std::vector<Real> coords;
  const std::vector<Real> pts = wavyCurve(120);
  const mesh::Surface surf = addPolyline(coords, pts, 0);
  for (auto& search : accelerated()) {
    ClosestPointSearch& grid = *search;
    BruteForceSegmentSearch2D brute;
    grid.build(coords, surf);
    brute.build(coords, surf);
    std::mt19937 rng(11);
    std::uniform_real_distribution<Real> u(-0.05, 0.05);
    const Real inf = std::numeric_limits<Real>::infinity();
    int vertexCases = 0;
    for (int node = 0; node <= 120; ++node)
      for (int k = 0; k < 40; ++k) {
        const Real x[2] = {pts[2 * node] + u(rng), pts[2 * node + 1] + u(rng)};
        const Projection pb = brute.project(x, inf);
        expectSameProjection(grid.project(x, inf), pb, x);
        if (pb.xi[0] == 0.0 || pb.xi[0] == 1.0) ++vertexCases;
      }
    EXPECT_GT(vertexCases, 100);
  }
}

TEST(ClosestPointSearch, CutoffPrunesOnlyFartherPoints) {
  std::vector<Real> coords;
  const mesh::Surface surf = addPolyline(coords, circle(1000, 2.0), 0);
  for (auto& search : accelerated()) {
    ClosestPointSearch& grid = *search;
    BruteForceSegmentSearch2D brute;
    grid.build(coords, surf);
    brute.build(coords, surf);
    std::mt19937 rng(3);
    std::uniform_real_distribution<Real> u(-12.0, 12.0);
    const Real inf = std::numeric_limits<Real>::infinity();
    int pruned = 0, kept = 0;
    for (Real cutoff : {0.05, 0.5, 3.0}) {
      for (int i = 0; i < 5000; ++i) {
        const Real x[2] = {u(rng), u(rng)};
        const Projection full = brute.project(x, inf);
        const Projection pg = grid.project(x, cutoff);
        expectSameProjection(pg, brute.project(x, cutoff), x);
        // found exactly when the true distance is within the cutoff
        EXPECT_EQ(pg.found(), full.distance <= cutoff);
        if (pg.found()) {
          EXPECT_EQ(pg.facet, full.facet);
          ++kept;
        } else {
          ++pruned;
        }
      }
    }
    EXPECT_GT(pruned, 1000);
    EXPECT_GT(kept, 500);
    // far outside the grid box
    const Real far[2] = {100.0, -50.0};
    EXPECT_FALSE(grid.project(far, 10.0).found());
    expectSameProjection(grid.project(far, inf), brute.project(far, inf), far);
  }
}

TEST(ClosestPointSearch, FacetsNearPointListsEveryFacetWithinTheRadius) {
  // exactly the facets within the radius (the tree prunes by distance)
  std::vector<Real> coords;
  const mesh::Surface surf = addPolyline(coords, wavyCurve(200), 0);
  for (auto& search : accelerated()) {
    ClosestPointSearch& s = *search;
    s.build(coords, surf);
    std::mt19937 rng(7);
    std::uniform_real_distribution<Real> u(-1.0, 5.0), w(0.0, 0.5);
    for (int i = 0; i < 500; ++i) {
      const Real x[2] = {u(rng), u(rng) - 1.0};
      const Real radius = w(rng);
      std::vector<LocalIndex> near;
      s.facetsNearPoint(x, radius, near);
      std::sort(near.begin(), near.end());
      for (LocalIndex e = 0; e < s.numFacets(); ++e) {
        Real xi, p[2];
        int region;
        const bool within = projectOntoSegment(x, &coords[2 * e], &coords[2 * e + 2], xi, p, region) <=
                            radius * radius;
        const bool listed = std::binary_search(near.begin(), near.end(), e);
        EXPECT_EQ(listed, within) << e;
      }
    }
  }
}

TEST(ClosestPointSearch, EmptySurfaceAndInvalidInput) {
  std::vector<Real> coords = {0.0, 0.0};
  mesh::Surface empty;
  mesh::Surface tri;
  tri.nodesPerFacet = 3;
  tri.facets = {0, 0, 0};
  const Real x[2] = {1.0, 1.0};
  for (auto& search : accelerated()) {
    search->build(coords, empty);
    EXPECT_EQ(search->numFacets(), 0);
    EXPECT_FALSE(search->project(x, std::numeric_limits<Real>::infinity()).found());
    std::vector<LocalIndex> near;
    search->facetsNearPoint(x, 1.0, near);
    EXPECT_TRUE(near.empty());
    EXPECT_THROW(search->build(coords, tri), InputError);
  }
  EXPECT_THROW(makeClosestPointSearch(4), InputError);
  EXPECT_NE(makeClosestPointSearch(2), nullptr);
  EXPECT_EQ(makeClosestPointSearch(3)->dim(), 3);
}

TEST(ClosestPointSearch, TimingAgainstBruteForce) {
  // Not a timed test: prints the cost per query for 10^4 segments, for
  // points near the surface and for points up to 10 cutoffs away.
  std::vector<Real> coords;
  const mesh::Surface surf = addPolyline(coords, circle(10000, 1.0), 0);
  AabbTreeSearch2D tree;
  BruteForceSegmentSearch2D brute;
  auto us = [](auto a, auto b) { return std::chrono::duration<double, std::micro>(b - a).count(); };
  auto t0 = std::chrono::steady_clock::now();
  tree.build(coords, surf);
  auto t1 = std::chrono::steady_clock::now();
  brute.build(coords, surf);
  std::printf("[search] 1e4 segments: build CGAL AABB tree %.0f us\n", us(t0, t1));
  const Real cutoff = 0.05;
  for (Real spread : {0.02, 0.5}) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<Real> u(0.0, 2.0 * kPi), d(1.0 - spread, 1.0 + spread);
    std::vector<Real> q;
    for (int i = 0; i < 4000; ++i) {
      const Real t = u(rng), r = d(rng);
      q.push_back(r * std::cos(t));
      q.push_back(r * std::sin(t));
    }
    const ClosestPointSearch* impl[2] = {&tree, &brute};
    double cost[2];
    LocalIndex sum[2] = {0, 0};
    for (int k = 0; k < 2; ++k) {
      auto a = std::chrono::steady_clock::now();
      for (int i = 0; i < 4000; ++i) sum[k] += impl[k]->project(&q[2 * i], cutoff).facet;
      cost[k] = us(a, std::chrono::steady_clock::now()) / 4000;
    }
    EXPECT_EQ(sum[0], sum[1]);
    std::printf("[search] points within %.2f of the circle, cutoff %.2f: CGAL AABB tree %.3f us, brute force %.2f us "
                "per query\n",
                spread, cutoff, cost[0], cost[1]);
  }
}

// ---------------------------------------------------------------------------
// 3D: triangles

namespace {

// A wavy sheet over [0, 2] x [0, 2] (n x n cells, each split into two
// triangles, the diagonal alternating) closed by a sphere of radius 0.5
// above it (latitude-longitude triangles): convex and concave edges and
// vertices, and vertices shared by many triangles.
mesh::Surface wavySheetAndBall(std::vector<Real>& coords, int n) {
  mesh::Surface s;
  s.nodesPerFacet = 3;
  auto node = [&](Real x, Real y, Real z) {
    coords.insert(coords.end(), {x, y, z});
    return LocalIndex(coords.size() / 3 - 1);
  };
  std::vector<LocalIndex> grid;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const Real x = 2.0 * i / n, y = 2.0 * j / n;
      grid.push_back(node(x, y, 0.15 * std::sin(3.0 * x) * std::cos(2.0 * y)));
    }
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const LocalIndex a = grid[j * (n + 1) + i], b = a + 1, c = a + (n + 1), d = c + 1;
      if ((i + j) % 2 == 0)
        s.facets.insert(s.facets.end(), {a, b, d, a, d, c});
      else
        s.facets.insert(s.facets.end(), {a, b, c, b, d, c});
    }
  const int nl = 8, nt = 12;
  const Real cx = 1.0, cy = 1.0, cz = 0.9, R = 0.5;
  const LocalIndex top = node(cx, cy, cz + R), bottom = node(cx, cy, cz - R);
  std::vector<LocalIndex> ring;
  for (int l = 1; l < nl; ++l)
    for (int t = 0; t < nt; ++t) {
      const Real th = kPi * l / nl, ph = 2.0 * kPi * t / nt;
      ring.push_back(node(cx + R * std::sin(th) * std::cos(ph), cy + R * std::sin(th) * std::sin(ph),
                          cz + R * std::cos(th)));
    }
  auto at = [&](int l, int t) { return ring[(l - 1) * nt + (t % nt)]; };
  for (int t = 0; t < nt; ++t) {
    s.facets.insert(s.facets.end(), {top, at(1, t), at(1, t + 1)});
    s.facets.insert(s.facets.end(), {bottom, at(nl - 1, t + 1), at(nl - 1, t)});
    for (int l = 1; l < nl - 1; ++l) {
      s.facets.insert(s.facets.end(), {at(l, t), at(l + 1, t), at(l + 1, t + 1)});
      s.facets.insert(s.facets.end(), {at(l, t), at(l + 1, t + 1), at(l, t + 1)});
    }
  }
  return s;
}

void expectSameProjection3D(const Projection& a, const Projection& b, const Real* x) {
  ASSERT_EQ(a.found(), b.found()) << "x = (" << x[0] << ", " << x[1] << ", " << x[2] << ")";
  if (!a.found()) return;
  EXPECT_EQ(a.facet, b.facet) << "x = (" << x[0] << ", " << x[1] << ", " << x[2] << ")";
  EXPECT_NEAR(a.distance, b.distance, 1e-13);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(a.point[k], b.point[k], 1e-13);
  EXPECT_NEAR(a.xi[0], b.xi[0], 1e-13);
  EXPECT_NEAR(a.xi[1], b.xi[1], 1e-13);
}

}  // namespace

TEST(TriangleProjection, IsTheClosestPointOfTheTriangle) {
  // Against a dense sampling of the triangle: never farther than the closest
  // sample, and the point lies in the triangle (s, t >= 0, s + t <= 1).
  std::mt19937 rng(13);
  std::uniform_real_distribution<Real> u(-1.5, 1.5);
  int regions[7] = {0, 0, 0, 0, 0, 0, 0};
  for (int trial = 0; trial < 300; ++trial) {
    Real a[3], b[3], c[3], x[3];
    for (int k = 0; k < 3; ++k) {
      a[k] = u(rng);
      b[k] = u(rng);
      c[k] = u(rng);
      x[k] = u(rng);
    }
    Real xi[2], p[3];
    int region;
    const Real d2 = projectOntoTriangle(x, a, b, c, xi, p, region);
    ++regions[region];
    EXPECT_GE(xi[0], -1e-14);
    EXPECT_GE(xi[1], -1e-14);
    EXPECT_LE(xi[0] + xi[1], 1.0 + 1e-14);
    Real best = std::numeric_limits<Real>::infinity();
    const int m = 60;
    for (int i = 0; i <= m; ++i)
      for (int j = 0; i + j <= m; ++j) {
        Real q2 = 0.0;
        for (int k = 0; k < 3; ++k) {
          const Real q = a[k] + (b[k] - a[k]) * i / m + (c[k] - a[k]) * j / m;
          q2 += (x[k] - q) * (x[k] - q);
        }
        best = std::min(best, q2);
      }
    EXPECT_LE(d2, best + 1e-12);
  }
  for (int r = 0; r < 7; ++r) EXPECT_GT(regions[r], 0) << "region " << r << " never met";
}

// The wavy sheet and ball with n cells per side, in both searches.
struct BothSearches3D {
  std::vector<Real> coords;
  mesh::Surface surf;
  BruteForceTriangleSearch3D brute;
  AabbTreeSearch3D tree;
  explicit BothSearches3D(int n) : surf(wavySheetAndBall(coords, n)) {
    brute.build(coords, surf);
    tree.build(coords, surf);
  }
};

TEST(ClosestPointSearch3D, MatchesBruteForceOnFacesEdgesAndVertices) {
  BothSearches3D s(24);
  auto& [coords, surf, brute, tree] = s;
  ASSERT_EQ(tree.numFacets(), brute.numFacets());
  std::mt19937 rng(17);
  std::uniform_real_distribution<Real> ux(-0.3, 2.3), uz(-0.6, 1.8);
  const Real inf = std::numeric_limits<Real>::infinity();
  int regions[7] = {0, 0, 0, 0, 0, 0, 0};
  for (int i = 0; i < 20000; ++i) {
    const Real x[3] = {ux(rng), ux(rng), uz(rng)};
    const Projection pb = brute.project(x, inf);
    expectSameProjection3D(tree.project(x, inf), pb, x);
    Real xi[2], p[3], t[9];
    int region;
    for (int v = 0; v < 3; ++v)
      for (int k = 0; k < 3; ++k) t[3 * v + k] = coords[3 * std::size_t(surf.facets[3 * pb.facet + v]) + k];
    projectOntoTriangle(x, t, t + 3, t + 6, xi, p, region);
    ++regions[region];
  }
  // faces, edges and vertices are all exercised
  EXPECT_GT(regions[0], 2000);
  EXPECT_GT(regions[4] + regions[5] + regions[6], 500);
  EXPECT_GT(regions[1] + regions[2] + regions[3], 50);
  // with cutoffs: found exactly when within, the same projection
  for (Real cutoff : {0.05, 0.3}) {
    int kept = 0, pruned = 0;
    for (int i = 0; i < 5000; ++i) {
      const Real x[3] = {ux(rng), ux(rng), uz(rng)};
      const Projection full = brute.project(x, inf);
      const Projection pt = tree.project(x, cutoff);
      expectSameProjection3D(pt, brute.project(x, cutoff), x);
      EXPECT_EQ(pt.found(), full.distance <= cutoff);
      (pt.found() ? kept : pruned)++;
    }
    EXPECT_GT(kept, 100);
    EXPECT_GT(pruned, 100);
  }
}

// A hint (any facet: the right one, a neighbour, a far one, one beyond the
// cutoff, an invalid index) changes the work, never the answer.
TEST(ClosestPointSearch3D, HintsDoNotChangeTheProjection) {
  BothSearches3D s(24);
  auto& [coords, surf, brute, tree] = s;
  std::mt19937 rng(23);
  std::uniform_real_distribution<Real> ux(-0.3, 2.3), uz(-0.6, 1.8);
  std::uniform_int_distribution<LocalIndex> anyFacet(0, tree.numFacets() - 1);
  const Real inf = std::numeric_limits<Real>::infinity();
  for (Real cutoff : {inf, 0.3, 0.05}) {
    for (int i = 0; i < 4000; ++i) {
      const Real x[3] = {ux(rng), ux(rng), uz(rng)};
      const Projection pb = brute.project(x, cutoff);
      const LocalIndex exact = brute.project(x, inf).facet;
      for (LocalIndex hint : {exact, LocalIndex(exact ^ 1), anyFacet(rng), LocalIndex(-1), tree.numFacets()})
        expectSameProjection3D(tree.project(x, cutoff, hint), pb, x);
    }
  }
}

TEST(ClosestPointSearch, HintsDoNotChangeTheProjection) {
  std::vector<Real> coords;
  const mesh::Surface surf = addPolyline(coords, wavyCurve(300), 1);
  BruteForceSegmentSearch2D brute;
  brute.build(coords, surf);
  AabbTreeSearch2D tree;
  tree.build(coords, surf);
  std::mt19937 rng(29);
  std::uniform_real_distribution<Real> ux(-1.5, 5.5), uy(-1.5, 3.5);
  std::uniform_int_distribution<LocalIndex> anyFacet(0, 299);
  const Real inf = std::numeric_limits<Real>::infinity();
  for (Real cutoff : {inf, 0.5}) {
    for (int i = 0; i < 4000; ++i) {
      const Real x[2] = {ux(rng), uy(rng)};
      const Projection pb = brute.project(x, cutoff);
      const LocalIndex exact = brute.project(x, inf).facet;
      for (LocalIndex hint : {exact, LocalIndex(exact + 1), anyFacet(rng), LocalIndex(-1), LocalIndex(300)})
        expectSameProjection(tree.project(x, cutoff, hint), pb, x);
    }
  }
}

TEST(ClosestPointSearch3D, FacetsNearCoverEveryFacetWithinTheRadius) {
  BothSearches3D s(16);
  auto& [coords, surf, brute, tree] = s;
  std::mt19937 rng(19);
  std::uniform_real_distribution<Real> u(-0.2, 2.2), w(0.0, 0.3);
  for (int i = 0; i < 300; ++i) {
    const Real x[3] = {u(rng), u(rng), u(rng) - 0.6};
    const Real radius = w(rng);
    std::vector<LocalIndex> a, b;
    tree.facetsNearPoint(x, radius, a);
    brute.facetsNearPoint(x, radius, b);
    EXPECT_TRUE(std::includes(b.begin(), b.end(), a.begin(), a.end()));
    for (LocalIndex e = 0; e < tree.numFacets(); ++e) {
      Real xi[2], p[3];
      int region;
      const Real* t = &coords[0];
      Real tri[9];
      for (int v = 0; v < 3; ++v)
        for (int k = 0; k < 3; ++k) tri[3 * v + k] = t[3 * std::size_t(surf.facets[3 * e + v]) + k];
      if (projectOntoTriangle(x, tri, tri + 3, tri + 6, xi, p, region) <= radius * radius) {
        EXPECT_TRUE(std::binary_search(a.begin(), a.end(), e)) << e;
      }
    }
  }
  mesh::Surface quads;
  quads.nodesPerFacet = 4;
  quads.facets = {0, 1, 2, 3};
  EXPECT_THROW(tree.build(coords, quads), InputError);
}
