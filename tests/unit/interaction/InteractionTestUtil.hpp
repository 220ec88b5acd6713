#pragma once
// Helpers for the interaction tests: polylines as (coordinates, surface),
// global residual and tangent of a SurfaceInteraction.
#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <utility>
#include <vector>

#include "cgcm/core/Types.hpp"
#include "cgcm/interaction/SurfaceInteraction.hpp"
#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::interaction::testing {

using cgcm::kPi;

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

/// Appends the open chain of n curved segments (Line3: end, end, mid) on the
/// curve c(s), s in [0, 1], to `coords` (mid nodes at the parameter midpoints;
/// body on the left of increasing s) and returns its surface.
inline mesh::Surface addCurvedChain(std::vector<Real>& coords, const std::function<void(Real, Real&, Real&)>& curve,
                                    int n, int body) {
  mesh::Surface s;
  s.body = body;
  s.nodesPerFacet = 3;
  const LocalIndex first = LocalIndex(coords.size() / 2);
  for (int i = 0; i <= 2 * n; ++i) {  // node 2i: end i, node 2i + 1: the mid node of segment i
    Real x, y;
    curve(Real(i) / (2 * n), x, y);
    coords.push_back(x);
    coords.push_back(y);
  }
  for (int i = 0; i < n; ++i) s.facets.insert(s.facets.end(), {first + 2 * i, first + 2 * i + 2, first + 2 * i + 1});
  return s;
}

/// Points of a curve c(s), s in [0, 1], at n + 1 parameter values.
inline std::vector<Real> samplePolyline(const std::function<void(Real, Real&, Real&)>& curve, int n) {
  std::vector<Real> p(2 * std::size_t(n + 1));
  for (int i = 0; i <= n; ++i) curve(Real(i) / n, p[2 * i], p[2 * i + 1]);
  return p;
}

/// Global residual (2 dofs per node) of all pairs at coords, the pair list fixed.
inline std::vector<Real> assembleResidual(SurfaceInteraction& si, const std::vector<Real>& coords) {
  std::vector<PairContribution> c;
  si.evaluate(coords, c, false);
  std::vector<Real> f(coords.size(), 0.0);
  for (const PairContribution& p : c)
    for (int a = 0; a < p.numRowNodes; ++a)
      for (int i = 0; i < 2; ++i) f[2 * p.rowNodes[a] + i] += p.f[2 * a + i];
  return f;
}

/// Sparse global tangent from the pair contributions.
inline std::map<std::pair<int, int>, Real> assembleTangent(SurfaceInteraction& si,
                                                           const std::vector<Real>& coords) {
  std::vector<PairContribution> c;
  si.evaluate(coords, c, true);
  std::map<std::pair<int, int>, Real> K;
  for (const PairContribution& p : c)
    for (int a = 0; a < p.numRowNodes; ++a)
      for (int i = 0; i < 2; ++i)
        for (int b = 0; b < p.numColNodes; ++b)
          for (int j = 0; j < 2; ++j)
            K[{2 * p.rowNodes[a] + i, 2 * p.colNodes[b] + j}] += p.K[2 * a + i][2 * b + j];
  return K;
}

/// max |K - K_fd| / max |K| over all entries, K_fd by central differences of
/// the residual with step h (the pair list of the last updatePairs kept).
inline Real tangentError(SurfaceInteraction& si, const std::vector<Real>& coords, Real h) {
  const auto K = assembleTangent(si, coords);
  Real kmax = 0.0;
  for (const auto& kv : K) kmax = std::max(kmax, std::abs(kv.second));
  Real worst = 0.0;
  const std::size_t n = coords.size();
  for (std::size_t j = 0; j < n; ++j) {
    std::vector<Real> cp = coords, cm = coords;
    cp[j] += h;
    cm[j] -= h;
    const std::vector<Real> fp = assembleResidual(si, cp), fm = assembleResidual(si, cm);
    for (std::size_t i = 0; i < n; ++i) {
      const Real fd = (fp[i] - fm[i]) / (2 * h);
      const auto it = K.find({int(i), int(j)});
      const Real k = it == K.end() ? 0.0 : it->second;
      worst = std::max(worst, std::abs(k - fd) / kmax);
    }
  }
  return worst;
}

}  // namespace cgcm::interaction::testing
