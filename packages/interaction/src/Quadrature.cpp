#include "cgcm/interaction/Quadrature.hpp"

#include <algorithm>
#include <boost/math/special_functions/legendre.hpp>
#include <cmath>
#include <string>

#include "cgcm/core/Error.hpp"
#include "cgcm/interaction/FacetShape.hpp"

namespace cgcm::interaction {

GaussRule gaussLegendreUnit(int n) {
  if (n < 1) throw InputError("Gauss-Legendre rule: number of points must be >= 1, got " + std::to_string(n));
  GaussRule rule;
  rule.points.resize(n);
  rule.weights.resize(n);
  // The non-negative roots x_k of P_n, ascending (Boost.Math), weights
  // 2 / ((1 − x²) P_n'(x)²); mapped from [−1, 1] to [0, 1] in ± pairs (an
  // odd n's root 0 maps onto itself).
  const std::vector<Real> roots = boost::math::legendre_p_zeros<Real>(n);
  const int m = static_cast<int>(roots.size());
  for (int k = 0; k < m; ++k) {
    const Real x = roots[k];
    const Real dp = boost::math::legendre_p_prime<Real>(n, x);
    const Real w = 1.0 / ((1.0 - x * x) * dp * dp);  // half of 2/(...) for [0, 1]
    rule.points[n - m + k] = 0.5 * (1.0 + x);
    rule.points[m - 1 - k] = 0.5 * (1.0 - x);
    rule.weights[n - m + k] = w;
    rule.weights[m - 1 - k] = w;
  }
  return rule;
}

namespace {

// Fully symmetric rules on the reference triangle (invariant under every
// permutation of the vertices, so a facet and its mirror image, whose node
// order is permuted, get the same points): (barycentric orbit, weight) with
// weights summing to 1. Degree 1: centroid; 3: Strang-Fix 6 points;
// 5: Radon 7 points. All weights positive.
struct Orbit {
  Real a, b, c;  ///< barycentric coordinates of one point; the orbit is their distinct permutations
  Real weight;   ///< of each point of the orbit
};

std::vector<Orbit> symmetricTriangleRule(int degree) {
  if (degree <= 1) return {{1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0, 1.0}};
  if (degree <= 3) return {{0.659027622374092, 0.231933368553031, 0.109039009072877, 1.0 / 6.0}};
  return {{1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0, 0.225},
          {0.470142064105115, 0.470142064105115, 0.059715871789770, 0.132394152788506},
          {0.101286507323456, 0.101286507323456, 0.797426985353087, 0.125939180544827}};
}

/// The point (s, t) of weight w on a facet with N nodes: its shape functions.
template <int N>
FacetPoint facetPointOf(Real s, Real t, Real weight) {
  FacetPoint q;
  Real Nv[N], dN[2][N];
  facetShape<N>(s, t, Nv, dN);
  for (int a = 0; a < N; ++a) q.N[a] = Nv[a], q.dN[0][a] = dN[0][a], q.dN[1][a] = dN[1][a];
  q.xi[0] = s, q.xi[1] = t;
  q.weight = weight;
  return q;
}

FacetPoint facetPoint(int nodes, Real s, Real t, Real weight) {
  switch (nodes) {
    case 3: return facetPointOf<3>(s, t, weight);
    case 4: return facetPointOf<4>(s, t, weight);
    case 6: return facetPointOf<6>(s, t, weight);
    case 8: return facetPointOf<8>(s, t, weight);
    default: return facetPointOf<9>(s, t, weight);
  }
}

}  // namespace

std::vector<FacetPoint> facetQuadrature(int nodes, int n) {
  if (nodes != 3 && nodes != 4 && nodes != 6 && nodes != 8 && nodes != 9)
    throw InputError("facet quadrature: facets have 3, 4, 6, 8 or 9 nodes, got " + std::to_string(nodes));
  const GaussRule g = gaussLegendreUnit(n);
  std::vector<FacetPoint> out;
  if (nodes == 3 || nodes == 6) {
    // n points per direction ask for degree 2n - 1, as the n x n rule on a quadrilateral
    if (n <= 3) {
      for (const Orbit& o : symmetricTriangleRule(2 * n - 1)) {
        const Real bary[3] = {o.a, o.b, o.c};
        int perm[3] = {0, 1, 2};
        std::vector<std::pair<Real, Real>> seen;
        do {
          const Real s = bary[perm[1]], t = bary[perm[2]];
          bool known = false;
          for (const auto& [s0, t0] : seen) known = known || (s0 == s && t0 == t);
          if (known) continue;
          seen.emplace_back(s, t);
          out.push_back(facetPoint(nodes, s, t, 0.5 * o.weight));  // reference area 1/2
        } while (std::next_permutation(perm, perm + 3));
      }
      return out;
    }
    // higher orders: the collapsed (n + 1) x n Gauss rule (one more point along u for the Jacobian
    // 1 - u), averaged over the six vertex permutations
    const GaussRule gu = gaussLegendreUnit(n + 1);
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j < n; ++j) {
        const Real u = gu.points[i], s = u, t = g.points[j] * (1.0 - u);  // (u, v) -> (u, v (1 - u))
        const Real bary[3] = {1.0 - s - t, s, t}, w = gu.weights[i] * g.weights[j] * (1.0 - u) / 6.0;
        int perm[3] = {0, 1, 2};
        do out.push_back(facetPoint(nodes, bary[perm[1]], bary[perm[2]], w));
        while (std::next_permutation(perm, perm + 3));
      }
    return out;
  }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      out.push_back(facetPoint(nodes, 2.0 * g.points[i] - 1.0, 2.0 * g.points[j] - 1.0,
                               4.0 * g.weights[i] * g.weights[j]));
  return out;
}

}  // namespace cgcm::interaction
