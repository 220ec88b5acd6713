#pragma once
// Sample grids shared by the analytic package's tests.
#include <cmath>
#include <vector>

#include "cgcm/core/Types.hpp"

namespace cgcm::analytic::test {

/// n values from lo to hi, evenly spaced in log (lo, hi > 0, n >= 2).
inline std::vector<Real> logspace(Real lo, Real hi, int n) {
  std::vector<Real> v(n);
  for (int i = 0; i < n; ++i) v[i] = lo * std::pow(hi / lo, static_cast<Real>(i) / (n - 1));
  return v;
}

}  // namespace cgcm::analytic::test
