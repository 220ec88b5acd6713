#pragma once
// Globally adaptive Gauss-Kronrod (7/15) quadrature and complete elliptic
// integrals, the two numerical tools of the subsurface stress; the rule and
// the integrals are Boost.Math's.
#include <algorithm>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/special_functions/ellint_rd.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <cmath>
#include <limits>
#include <queue>
#include <sstream>
#include <string>
#include <vector>

#include "cgcm/core/Error.hpp"
#include "cgcm/core/Types.hpp"

namespace cgcm::analytic {

struct QuadratureResult {
  Real value = 0;
  Real error = 0;      ///< estimated absolute error
  int intervals = 0;   ///< number of intervals at the end
  int evaluations = 0; ///< integrand evaluations
};

namespace detail {

struct Interval {
  Real lo, hi, value, error;
  bool operator<(const Interval& o) const { return error < o.error; }
};

/// One 15-point Kronrod evaluation (Boost.Math's nodes and weights) with
/// QUADPACK's error estimate (qk15), which scales |K15 − G7| by the
/// integrand's variation so that smooth integrands are not over-refined.
/// Boost's own estimate is the bare |K15 − G7|: with it, the ring kernel's
/// log-singular φ integral of the tests needs more than 2000 intervals for a
/// relative 1e-13, against a few dozen here.
template <class F>
Interval gk15(F& f, Real lo, Real hi) {
  using K15 = boost::math::quadrature::gauss_kronrod<Real, 15>;
  using G7 = boost::math::quadrature::gauss<Real, 7>;
  const auto& x = K15::abscissa();  // 0 and the seven positive nodes, ascending; the even-indexed are G7's
  const auto& wk = K15::weights();
  const auto& wg = G7::weights();   // at 0 and at G7's positive nodes
  constexpr Real eps = std::numeric_limits<Real>::epsilon();
  const Real centre = 0.5 * (lo + hi);
  const Real half = 0.5 * (hi - lo);
  const Real fc = f(centre);
  Real resk = fc * wk[0];
  Real resg = fc * wg[0];
  Real resabs = std::fabs(resk);
  Real fv1[8], fv2[8];
  for (int j = 1; j < 8; ++j) {
    const Real dx = half * x[j];
    const Real f1 = f(centre - dx);
    const Real f2 = f(centre + dx);
    fv1[j] = f1;
    fv2[j] = f2;
    resk += wk[j] * (f1 + f2);
    resabs += wk[j] * (std::fabs(f1) + std::fabs(f2));
    if (j % 2 == 0) resg += wg[j / 2] * (f1 + f2);
  }
  const Real mean = 0.5 * resk;
  Real resasc = wk[0] * std::fabs(fc - mean);
  for (int j = 1; j < 8; ++j) resasc += wk[j] * (std::fabs(fv1[j] - mean) + std::fabs(fv2[j] - mean));
  const Real h = std::fabs(half);
  Real err = std::fabs((resk - resg) * half);
  resasc *= h;
  resabs *= h;
  if (resasc != 0 && err != 0) err = resasc * std::fmin(1.0, std::pow(200 * err / resasc, 1.5));
  if (resabs > std::numeric_limits<Real>::min() / (50 * eps)) err = std::fmax(50 * eps * resabs, err);
  return {lo, hi, resk * half, err};
}

}  // namespace detail

/// ∫ f over [points.front(), points.back()], split first at every given
/// point (sorted, duplicates removed), then by bisecting the interval with
/// the largest error estimate until the summed estimate is
/// ≤ max(absTol, relTol · |integral|) (global adaptivity, as QUADPACK's
/// qag; Boost.Math's adaptive driver is local, with a tolerance relative to
/// the first estimate only). The estimate never falls below 50 ε Σ|f| per
/// interval (QUADPACK), so relTol below ~1e-13 cannot be met where the
/// integrand changes sign.
/// Throws NumericalError (naming `what`) if that needs more than
/// maxIntervals intervals, if an interval can no longer be split, or if f
/// returns a non-finite value.
template <class F>
QuadratureResult integrateAdaptive(F&& f, std::vector<Real> points, Real absTol, Real relTol,
                                   int maxIntervals, const std::string& what) {
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  QuadratureResult result;
  if (points.size() < 2) return result;
  std::priority_queue<detail::Interval> heap;
  Real total = 0;
  Real error = 0;
  int evaluations = 0;
  auto fail = [&](const std::string& why) {
    std::ostringstream msg;
    msg << what << ": quadrature failed on [" << points.front() << ", " << points.back()
        << "]: " << why << " (estimate " << total << ", error " << error << ", tolerance "
        << std::fmax(absTol, relTol * std::fabs(total)) << ", " << heap.size() << " intervals)";
    throw NumericalError(msg.str());
  };
  auto eval = [&](Real lo, Real hi) {
    detail::Interval iv = detail::gk15(f, lo, hi);
    evaluations += 15;
    if (!std::isfinite(iv.value)) fail("non-finite integrand");
    return iv;
  };
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    detail::Interval iv = eval(points[i], points[i + 1]);
    total += iv.value;
    error += iv.error;
    heap.push(iv);
  }
  while (error > std::fmax(absTol, relTol * std::fabs(total))) {
    if (static_cast<int>(heap.size()) >= maxIntervals) fail("too many intervals");
    const detail::Interval worst = heap.top();
    const Real mid = 0.5 * (worst.lo + worst.hi);
    if (!(mid > worst.lo && mid < worst.hi)) fail("interval too small to split");
    heap.pop();
    const detail::Interval left = eval(worst.lo, mid);
    const detail::Interval right = eval(mid, worst.hi);
    total += left.value + right.value - worst.value;
    error += left.error + right.error - worst.error;
    heap.push(left);
    heap.push(right);
  }
  // Re-sum from the final intervals: the running sums collect rounding.
  result.intervals = static_cast<int>(heap.size());
  result.value = 0;
  result.error = 0;
  while (!heap.empty()) {
    result.value += heap.top().value;
    result.error += heap.top().error;
    heap.pop();
  }
  result.evaluations = evaluations;
  return result;
}

/// Complete elliptic integrals of the first and second kind, K(k) and E(k),
/// for the modulus k given through k² and the complementary k'² = 1 − k²
/// (both passed so that neither is obtained by cancellation).
struct EllipticKE {
  Real K = 0;
  Real E = 0;
};

/// Carlson's symmetric forms (Boost.Math): K = R_F(0, k'², 1),
/// E = K − k²/3 R_D(0, k'², 1), accurate up to k' → 0.
inline EllipticKE ellipticKE(Real k2, Real kp2) {
  EllipticKE r;
  r.K = boost::math::ellint_rf(Real(0), kp2, Real(1));
  r.E = r.K - k2 / 3 * boost::math::ellint_rd(Real(0), kp2, Real(1));
  return r;
}

}  // namespace cgcm::analytic
