#pragma once
// Globally adaptive Gauss-Kronrod (7/15) quadrature and complete elliptic
// integrals, the two numerical tools of the subsurface stress.
#include <algorithm>
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

// Kronrod nodes (positive half, descending) and weights of the 15-point rule;
// the odd-indexed nodes are those of the embedded 7-point Gauss rule
// (QUADPACK qk15).
inline constexpr Real kXgk[8] = {
    0.991455371120812639206854697526329, 0.949107912342758524526189684047851,
    0.864864423359769072789712788640926, 0.741531185599394439863864773280788,
    0.586087235467691130294144845693013, 0.405845151377397166906606412076961,
    0.207784955007898467600689403773245, 0.000000000000000000000000000000000};
inline constexpr Real kWgk[8] = {
    0.022935322010529224963732008058970, 0.063092092629978553290700663189204,
    0.104790010322250183839876322541518, 0.140653259715525918745189590510238,
    0.169004726639267902826583426598550, 0.190350578064785409913256402421014,
    0.204432940075298892414161999234649, 0.209482141084727828012999174891714};
inline constexpr Real kWg[4] = {
    0.129484966168869693270611432679082, 0.279705391489276667901467771423780,
    0.381830050505118944950369775488975, 0.417959183673469387755102040816327};

struct Interval {
  Real lo, hi, value, error;
  bool operator<(const Interval& o) const { return error < o.error; }
};

/// One 15-point Kronrod evaluation with the QUADPACK error estimate, which
/// scales |K15 − G7| by the integrand's variation (resasc) so that smooth
/// integrands are not over-refined.
template <class F>
Interval gk15(F& f, Real lo, Real hi) {
  constexpr Real eps = std::numeric_limits<Real>::epsilon();
  const Real centre = 0.5 * (lo + hi);
  const Real half = 0.5 * (hi - lo);
  const Real fc = f(centre);
  Real resk = fc * kWgk[7];
  Real resg = fc * kWg[3];
  Real resabs = std::fabs(resk);
  Real fv1[7], fv2[7];
  for (int j = 0; j < 7; ++j) {
    const Real dx = half * kXgk[j];
    const Real f1 = f(centre - dx);
    const Real f2 = f(centre + dx);
    fv1[j] = f1;
    fv2[j] = f2;
    resk += kWgk[j] * (f1 + f2);
    resabs += kWgk[j] * (std::fabs(f1) + std::fabs(f2));
    if (j % 2 == 1) resg += kWg[j / 2] * (f1 + f2);
  }
  const Real mean = 0.5 * resk;
  Real resasc = kWgk[7] * std::fabs(fc - mean);
  for (int j = 0; j < 7; ++j) resasc += kWgk[j] * (std::fabs(fv1[j] - mean) + std::fabs(fv2[j] - mean));
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
/// ≤ max(absTol, relTol · |integral|). The estimate never falls below
/// 50 ε Σ|f| per interval (QUADPACK), so relTol below ~1e-13 cannot be met
/// where the integrand changes sign.
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

/// Arithmetic-geometric mean: a₀ = 1, b₀ = k', c₀ = k; K = π/(2 a_∞) and
/// E = K (1 − Σ 2^(n−1) c_n²). c_{n+1} = c_n²/(4 a_{n+1}) avoids the
/// cancellation of (a_n − b_n)/2. Converges quadratically; k' → 0 (k → 1)
/// costs about log₂ log(1/k') extra steps.
inline EllipticKE ellipticKE(Real k2, Real kp2) {
  constexpr Real pi = kPi;
  Real a = 1;
  Real b = std::sqrt(kp2);
  Real c2 = k2;  // c_n²
  Real sum = 0.5 * c2;
  Real pow2 = 0.5;
  for (int n = 0; n < 60; ++n) {
    if (std::fabs(a - b) <= 1e-16 * a) break;
    const Real an = 0.5 * (a + b);
    const Real cn = c2 / (4 * an);  // c_{n+1}
    b = std::sqrt(a * b);
    a = an;
    c2 = cn * cn;
    pow2 *= 2;
    sum += pow2 * c2;
  }
  EllipticKE r;
  r.K = pi / (2 * a);
  r.E = r.K * (1 - sum);
  return r;
}

}  // namespace cgcm::analytic
