#pragma once
// Helpers for the interaction tests: polylines as (coordinates, surface).
#include <cmath>
#include <functional>
#include <vector>

#include "cgcm/core/Types.hpp"
#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::interaction::testing {

constexpr Real kPi = 3.14159265358979323846;

/// Appends the open polyline through `points` (x, y pairs) to `coords` and
/// returns its surface (segments i -> i+1, body on the left of each).
inline mesh::Surface addPolyline(std::vector<Real>& coords, const std::vector<Real>& points, int body) {
  mesh::Surface s;
  s.body = body;
  s.nodesPerFacet = 2;
  const LocalIndex first = LocalIndex(coords.size() / 2);
  const LocalIndex n = LocalIndex(points.size() / 2);
  coords.insert(coords.end(), points.begin(), points.end());
  for (LocalIndex i = 0; i + 1 < n; ++i) {
    s.facets.push_back(first + i);
    s.facets.push_back(first + i + 1);
  }
  return s;
}

/// Points of a curve c(s), s in [0, 1], at n + 1 parameter values.
inline std::vector<Real> samplePolyline(const std::function<void(Real, Real&, Real&)>& curve, int n) {
  std::vector<Real> p(2 * std::size_t(n + 1));
  for (int i = 0; i <= n; ++i) curve(Real(i) / n, p[2 * i], p[2 * i + 1]);
  return p;
}

}  // namespace cgcm::interaction::testing
