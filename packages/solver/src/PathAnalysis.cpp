#include "cgcm/solver/PathAnalysis.hpp"

#include <algorithm>
#include <cmath>

namespace cgcm::solver {

std::vector<LoadPoint> displacementControlPath(const std::vector<LoadPoint>& curve) {
  std::vector<LoadPoint> path;
  const std::size_t n = curve.size();
  std::size_t i = 0;
  while (i < n) {
    const LoadPoint& r = curve[i];
    path.push_back(r);
    const bool endsStableBranch = r.fold && i > 0 && curve[i - 1].stable && !curve[i - 1].fold;
    if (!endsStableBranch) {
      ++i;
      continue;
    }
    const Real dir = r.u > curve[i - 1].u ? 1.0 : -1.0;
    // The first later segment of stable, non-fold rows that passes the fold's u the same way.
    std::size_t j = i + 1;
    for (; j < n; ++j) {
      const LoadPoint &a = curve[j - 1], &b = curve[j];
      if (j - 1 <= i || !a.stable || !b.stable || a.fold || b.fold) continue;
      if (dir * (b.u - a.u) > 0.0 && dir * (r.u - a.u) >= 0.0 && dir * (b.u - r.u) >= 0.0) break;
    }
    if (j >= n) break;  // the curve never comes back: the path ends at the fold
    const LoadPoint &a = curve[j - 1], &b = curve[j];
    const Real t = (r.u - a.u) / (b.u - a.u);
    LoadPoint landing = b;
    landing.u = r.u;
    landing.parameter = r.parameter;
    landing.P = a.P + t * (b.P - a.P);
    landing.gap = a.gap + t * (b.gap - a.gap);
    landing.contactRadius = a.contactRadius + t * (b.contactRadius - a.contactRadius);
    landing.Plower = a.Plower + t * (b.Plower - a.Plower);
    landing.jump = true;
    landing.fold = false;
    path.push_back(landing);
    i = j;
  }
  return path;
}

std::vector<Jump> jumpsOf(const std::vector<LoadPoint>& path) {
  std::vector<Jump> jumps;
  for (std::size_t k = 1; k < path.size(); ++k)
    if (path[k].jump) jumps.push_back({path[k - 1], path[k]});
  return jumps;
}

namespace {

// Integral of P du along rows[first..last] (in order), counting only the parts with u >= uLow.
Real integralAbove(const std::vector<LoadPoint>& rows, std::size_t first, std::size_t last, Real uLow) {
  Real sum = 0.0;
  for (std::size_t k = first; k < last; ++k) {
    Real u0 = rows[k].u, u1 = rows[k + 1].u, P0 = rows[k].P, P1 = rows[k + 1].P;
    if (u0 == u1) continue;
    if (std::max(u0, u1) <= uLow) continue;
    auto at = [&](Real u) { return P0 + (P1 - P0) * (u - u0) / (u1 - u0); };
    if (u0 < uLow) P0 = at(uLow), u0 = uLow;
    if (u1 < uLow) P1 = at(uLow), u1 = uLow;
    sum += 0.5 * (P0 + P1) * (u1 - u0);
  }
  return sum;
}

}  // namespace

Real hysteresisEnergy(const std::vector<LoadPoint>& path) {
  if (path.size() < 3) return 0.0;
  const auto top = std::max_element(path.begin(), path.end(),
                                     [](const LoadPoint& a, const LoadPoint& b) { return a.u < b.u; });
  const std::size_t turn = std::size_t(top - path.begin());
  if (turn == 0 || turn + 1 >= path.size()) return 0.0;
  const Real uLow = std::max(path.front().u, path.back().u);
  // approach: +integral of P du; retraction (du < 0): -integral in increasing u
  return integralAbove(path, 0, turn, uLow) + integralAbove(path, turn, path.size() - 1, uLow);
}

}  // namespace cgcm::solver
