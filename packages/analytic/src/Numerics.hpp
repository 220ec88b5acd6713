#pragma once
// Scalar root finding and minimisation used by the analytic package (private
// header): thin wrappers over Boost.Math's TOMS 748 root finder and Brent
// minimiser that take an explicit bracket, report failures through
// NumericalError naming `what`, and never return an unconverged value.
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <utility>

#include "cgcm/core/Error.hpp"
#include "cgcm/core/Types.hpp"

namespace cgcm::analytic::detail {

/// Root of f on [a, b] with f(a) = fa, f(b) = fb of opposite signs, to
/// |Δx| ≤ tol + 4 eps|x| (TOMS 748: bracketing, superlinear).
template <class F>
Real bracketedRoot(F&& f, Real a, Real b, Real fa, Real fb, Real tol, const std::string& what) {
  if (fa == 0) return a;
  if (fb == 0) return b;
  if ((fa > 0) == (fb > 0)) {
    std::ostringstream msg;
    msg << what << ": root not bracketed in [" << a << ", " << b << "]";
    throw NumericalError(msg.str());
  }
  constexpr Real eps = std::numeric_limits<Real>::epsilon();
  auto checked = [&](Real x) {
    const Real v = f(x);
    if (!std::isfinite(v)) throw NumericalError(what + ": non-finite function value");
    return v;
  };
  auto done = [&](Real lo, Real hi) { return std::fabs(hi - lo) <= tol + 4 * eps * std::fmax(std::fabs(lo), std::fabs(hi)); };
  constexpr std::uintmax_t budget = 200;
  std::uintmax_t iterations = budget;
  std::pair<Real, Real> bracket;
  try {
    bracket = boost::math::tools::toms748_solve(checked, a, b, fa, fb, done, iterations);
  } catch (const NumericalError&) {
    throw;
  } catch (const std::exception& e) {
    throw NumericalError(what + ": " + e.what());
  }
  if (iterations >= budget && !done(bracket.first, bracket.second))
    throw NumericalError(what + ": root finder did not converge in 200 iterations");
  return 0.5 * (bracket.first + bracket.second);
}

/// Minimum of f on [a, b] (Brent: golden section with parabolic steps);
/// returns (x, f(x)) with x located to about relTol |x| + absTol, but not
/// below 2^-26 |x|: Boost caps the precision at half the digits (√eps, the
/// limit for a minimum whose value carries round-off).
template <class F>
std::pair<Real, Real> bracketedMinimum(F&& f, Real a, Real b, Real relTol, Real absTol, const std::string& what) {
  // Boost's tolerance is relative (2^(1-bits) |x|); an absolute one becomes
  // relative to the bracket's largest |x|, which is never looser.
  const Real scale = std::fmax(std::fabs(a), std::fabs(b));
  Real tol = relTol;
  if (absTol > 0 && scale > 0) tol = tol > 0 ? std::fmin(tol, absTol / scale) : absTol / scale;
  const int maxBits = std::numeric_limits<Real>::digits / 2;
  const int bits = tol > 0 ? std::min(maxBits, std::max(2, 1 + static_cast<int>(std::ceil(-std::log2(tol))))) : maxBits;
  constexpr std::uintmax_t budget = 500;
  std::uintmax_t iterations = budget;
  auto checked = [&](Real x) {
    const Real v = f(x);
    if (!std::isfinite(v)) throw NumericalError(what + ": non-finite function value");
    return v;
  };
  const auto best = boost::math::tools::brent_find_minima(checked, std::fmin(a, b), std::fmax(a, b), bits, iterations);
  if (iterations >= budget) throw NumericalError(what + ": Brent minimiser did not converge in 500 iterations");
  return best;
}

}  // namespace cgcm::analytic::detail
