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

/// Shape functions of a surface facet at one quadrature point, and its weight
/// on the reference facet (triangles: s, t >= 0, s + t <= 1, area 1/2;
/// quadrilaterals: [-1, 1]^2, area 4; FacetShape.hpp).
struct FacetPoint {
  Real N[9] = {};
  Real dN[2][9] = {};  ///< dN_a/dxi_i
  Real xi[2] = {};     ///< the point's parameters (s, t) or (xi, eta)
  Real weight = 0.0;
};

/// Quadrature on a facet with `nodes` = 3, 6 (triangles), 4, 8 or 9
/// (quadrilaterals; node orders in FacetShape.hpp) and n points per direction,
/// exact for degree 2n - 1. Triangles: rules invariant under every
/// permutation of the vertices (a facet and its mirror image get mirrored
/// points): n = 1 the centroid, 2 Strang-Fix (6 points), 3 Radon (7 points),
/// n >= 4 the collapsed (n + 1) x n Gauss rule averaged over the six vertex
/// permutations; all weights positive. Quadrilaterals: the n x n tensor Gauss
/// rule. Node order: tri3 (0,0), (1,0), (0,1); quad4 (-1,-1), (1,-1), (1,1),
/// (-1,1), counter-clockwise seen from outside. A curved facet gets the
/// points and weights of its linear one and its own shape functions.
std::vector<FacetPoint> facetQuadrature(int nodes, int n);

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
