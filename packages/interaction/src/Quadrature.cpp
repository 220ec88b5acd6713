#include "cgcm/interaction/Quadrature.hpp"

#include <cmath>
#include <string>

#include "cgcm/core/Error.hpp"

namespace cgcm::interaction {

GaussRule gaussLegendreUnit(int n) {
  if (n < 1) throw InputError("Gauss-Legendre rule: number of points must be >= 1, got " + std::to_string(n));
  GaussRule rule;
  rule.points.resize(n);
  rule.weights.resize(n);
  const Real pi = std::acos(-1.0);
  // P_n(x) and P_n'(x) by the three-term recurrence.
  auto legendre = [n](Real x, Real& p, Real& dp) {
    Real p0 = 1.0, p1 = x;
    for (int k = 2; k <= n; ++k) {
      const Real p2 = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
      p0 = p1;
      p1 = p2;
    }
    p = p1;
    dp = n * (x * p1 - p0) / (x * x - 1.0);
  };
  // Newton iteration on the Legendre polynomial P_n over [-1, 1].
  for (int i = 0; i < (n + 1) / 2; ++i) {
    Real x = std::cos(pi * (i + 0.75) / (n + 0.5));
    Real p = 0.0, dp = 0.0;
    for (int it = 0; it < 100; ++it) {
      legendre(x, p, dp);
      const Real dx = p / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    legendre(x, p, dp);  // the derivative at the converged root
    const Real w = 2.0 / ((1.0 - x * x) * dp * dp);
    // x is the i-th largest root; map [-1, 1] -> [0, 1]
    rule.points[n - 1 - i] = 0.5 * (1.0 + x);
    rule.points[i] = 0.5 * (1.0 - x);
    rule.weights[n - 1 - i] = 0.5 * w;
    rule.weights[i] = 0.5 * w;
  }
  if (n % 2 == 1) rule.points[n / 2] = 0.5;
  return rule;
}

std::vector<FacetPoint> facetQuadrature(int nodes, int n) {
  if (nodes != 3 && nodes != 4)
    throw InputError("facet quadrature: facets have 3 or 4 nodes, got " + std::to_string(nodes));
  const GaussRule g = gaussLegendreUnit(n);
  std::vector<FacetPoint> out;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      FacetPoint q;
      if (nodes == 3) {
        // collapsed square: (u, v) in [0, 1]^2 -> (s, t) = (u, v (1 - u)), Jacobian 1 - u
        const Real u = g.points[i], s = u, t = g.points[j] * (1.0 - u);
        q.N[0] = 1.0 - s - t, q.N[1] = s, q.N[2] = t;
        q.dN[0][0] = -1.0, q.dN[0][1] = 1.0, q.dN[0][2] = 0.0;
        q.dN[1][0] = -1.0, q.dN[1][1] = 0.0, q.dN[1][2] = 1.0;
        q.weight = g.weights[i] * g.weights[j] * (1.0 - u);
      } else {
        const Real xi = 2.0 * g.points[i] - 1.0, eta = 2.0 * g.points[j] - 1.0;
        const Real sx[4] = {-1.0, 1.0, 1.0, -1.0}, sy[4] = {-1.0, -1.0, 1.0, 1.0};
        for (int a = 0; a < 4; ++a) {
          q.N[a] = 0.25 * (1.0 + sx[a] * xi) * (1.0 + sy[a] * eta);
          q.dN[0][a] = 0.25 * sx[a] * (1.0 + sy[a] * eta);
          q.dN[1][a] = 0.25 * sy[a] * (1.0 + sx[a] * xi);
        }
        q.weight = 4.0 * g.weights[i] * g.weights[j];
      }
      out.push_back(q);
    }
  return out;
}

}  // namespace cgcm::interaction
