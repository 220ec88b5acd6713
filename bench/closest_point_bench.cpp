// Closest-point search on CGAL's AABB tree: build and query times for
// surfaces of about 10^4 and 10^5 facets, the work of one Newton iteration
// (the tree is rebuilt once per iteration over the moved surface, and every
// surface quadrature point of the other body is projected, starting from the
// facet of its previous projection).
//
//   bench_closest_point
//
// 3D: a triangulated sphere of radius 1 (latitude-longitude), queried from 4
// points per facet of a sphere 0.05 larger (the other body's quadrature
// points), with the cutoff 0.1. 2D: a circle of segments, 4 points per
// segment. Prints; never fails.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "cgcm/interaction/ClosestPointSearch.hpp"

using namespace cgcm;
using Clock = std::chrono::steady_clock;

namespace {

double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

// nl x nt latitude-longitude triangulation of the unit sphere (2 nl nt triangles, poles included).
mesh::Surface sphere(int nl, int nt, std::vector<Real>& coords) {
  const Real pi = kPi;
  mesh::Surface s;
  s.nodesPerFacet = 3;
  coords = {0.0, 0.0, 1.0, 0.0, 0.0, -1.0};
  for (int l = 1; l < nl; ++l)
    for (int t = 0; t < nt; ++t) {
      const Real th = pi * l / nl, ph = 2 * pi * t / nt;
      coords.insert(coords.end(), {std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)});
    }
  auto at = [&](int l, int t) { return LocalIndex(2 + (l - 1) * nt + (t % nt)); };
  for (int t = 0; t < nt; ++t) {
    s.facets.insert(s.facets.end(), {0, at(1, t), at(1, t + 1)});
    s.facets.insert(s.facets.end(), {1, at(nl - 1, t + 1), at(nl - 1, t)});
    for (int l = 1; l < nl - 1; ++l) {
      s.facets.insert(s.facets.end(), {at(l, t), at(l + 1, t), at(l + 1, t + 1)});
      s.facets.insert(s.facets.end(), {at(l, t), at(l + 1, t + 1), at(l, t + 1)});
    }
  }
  return s;
}

void run(const char* what, interaction::ClosestPointSearch& search, const std::vector<Real>& coords,
         const mesh::Surface& surface, const std::vector<Real>& queries, Real cutoff) {
  const int dim = search.dim();
  const std::size_t n = queries.size() / dim;
  const auto t0 = Clock::now();
  search.build(coords, surface);
  const auto t1 = Clock::now();
  std::size_t found = 0;
  std::vector<LocalIndex> previous(n);
  for (std::size_t i = 0; i < n; ++i) {
    previous[i] = search.project(&queries[dim * i], cutoff).facet;
    found += previous[i] >= 0 ? 1 : 0;
  }
  const auto t2 = Clock::now();
  // the next iteration: each query starts from its previous projection
  for (std::size_t i = 0; i < n; ++i) previous[i] = search.project(&queries[dim * i], cutoff, previous[i]).facet;
  const auto t3 = Clock::now();
  std::printf("%-30s %7d facets  build %7.2f ms  %7zu queries %6.3f us each, %6.3f us with hints (%5.1f %% found)"
              "  iteration %7.2f ms\n",
              what, int(search.numFacets()), 1e3 * seconds(t0, t1), n, 1e6 * seconds(t1, t2) / double(n),
              1e6 * seconds(t2, t3) / double(n), 100.0 * double(found) / double(n),
              1e3 * (seconds(t0, t1) + seconds(t2, t3)));
}

}  // namespace

int main() {
  const Real cutoff = 0.1, lift = 1.05;
  for (auto [nl, nt] : {std::pair{50, 100}, std::pair{158, 316}}) {
    std::vector<Real> coords;
    const mesh::Surface s = sphere(nl, nt, coords);
    std::vector<Real> q;
    for (LocalIndex e = 0; e < s.numFacets(); ++e) {
      const Real* a = &coords[3 * std::size_t(s.facets[3 * e])];
      const Real* b = &coords[3 * std::size_t(s.facets[3 * e + 1])];
      const Real* c = &coords[3 * std::size_t(s.facets[3 * e + 2])];
      for (auto [wa, wb] : {std::pair{0.6, 0.2}, std::pair{0.2, 0.6}, std::pair{0.2, 0.2}, std::pair{1.0 / 3, 1.0 / 3}})
        for (int k = 0; k < 3; ++k) q.push_back(lift * (wa * a[k] + wb * b[k] + (1 - wa - wb) * c[k]));
    }
    auto tree = interaction::makeClosestPointSearch(3);
    run("3D triangles, CGAL AABB tree", *tree, coords, s, q, cutoff);
  }
  for (int n : {10000, 100000}) {
    const Real pi = kPi;
    std::vector<Real> coords, q;
    mesh::Surface s;
    s.nodesPerFacet = 2;
    for (int i = 0; i < n; ++i) {
      coords.insert(coords.end(), {std::cos(2 * pi * i / n), std::sin(2 * pi * i / n)});
      s.facets.insert(s.facets.end(), {LocalIndex(i), LocalIndex((i + 1) % n)});
      for (int g = 0; g < 4; ++g) {
        const Real t = 2 * pi * (i + (g + 0.5) / 4) / n;
        q.insert(q.end(), {lift * std::cos(t), lift * std::sin(t)});
      }
    }
    auto tree = interaction::makeClosestPointSearch(2);
    run("2D segments, CGAL AABB tree", *tree, coords, s, q, cutoff);
  }
  return 0;
}
