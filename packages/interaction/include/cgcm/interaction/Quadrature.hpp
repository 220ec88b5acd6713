#pragma once
// Gauss-Legendre rules on the unit interval [0, 1] (points and weights, the
// weights sum to 1), used for surface integrals and for the numerical
// defaults of the potentials.
#include <vector>

#include "cgcm/core/Types.hpp"

namespace cgcm::interaction {

struct GaussRule {
  std::vector<Real> points;   ///< in (0, 1), increasing
  std::vector<Real> weights;  ///< positive, sum 1
  int size() const { return int(points.size()); }
};

/// n-point Gauss-Legendre rule on [0, 1] (n >= 1; exact for degree 2n - 1).
/// Throws InputError for n < 1.
GaussRule gaussLegendreUnit(int n);

/// Composite Gauss-Legendre integral of f over [a, b]: `panels` equal
/// panels of an n-point rule.
template <class F>
Real integrate(F&& f, Real a, Real b, int panels, const GaussRule& rule) {
  const Real h = (b - a) / panels;
  Real sum = 0.0;
  for (int p = 0; p < panels; ++p) {
    const Real x0 = a + p * h;
    for (int i = 0; i < rule.size(); ++i) sum += rule.weights[i] * f(x0 + h * rule.points[i]);
  }
  return sum * h;
}

}  // namespace cgcm::interaction
