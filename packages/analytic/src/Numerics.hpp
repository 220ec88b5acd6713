#pragma once
// Scalar root finding and minimisation used by the analytic package (private
// header). Both take an explicit bracket and never return an unconverged
// value: they throw NumericalError instead.
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <utility>

#include "cgcm/core/Error.hpp"
#include "cgcm/core/Types.hpp"

namespace cgcm::analytic::detail {

/// Brent's root finder (inverse quadratic interpolation, secant and
/// bisection) on [a, b] with f(a) f(b) < 0; converges to |Δx| ≤ tol + 2 eps|x|.
template <class F>
Real brentRoot(F&& f, Real a, Real b, Real fa, Real fb, Real tol, const std::string& what) {
  constexpr Real eps = std::numeric_limits<Real>::epsilon();
  if (fa == 0) return a;
  if (fb == 0) return b;
  if ((fa > 0) == (fb > 0)) {
    std::ostringstream msg;
    msg << what << ": root not bracketed in [" << a << ", " << b << "]";
    throw NumericalError(msg.str());
  }
  Real c = a, fc = fa, d = b - a, e = d;
  for (int it = 0; it < 200; ++it) {
    if ((fb > 0) == (fc > 0)) {
      c = a;
      fc = fa;
      d = e = b - a;
    }
    if (std::fabs(fc) < std::fabs(fb)) {
      a = b;
      b = c;
      c = a;
      fa = fb;
      fb = fc;
      fc = fa;
    }
    const Real tol1 = 2 * eps * std::fabs(b) + 0.5 * tol;
    const Real xm = 0.5 * (c - b);
    if (std::fabs(xm) <= tol1 || fb == 0) return b;
    if (std::fabs(e) >= tol1 && std::fabs(fa) > std::fabs(fb)) {
      const Real s = fb / fa;
      Real p, q;
      if (a == c) {
        p = 2 * xm * s;
        q = 1 - s;
      } else {
        const Real qq = fa / fc;
        const Real r = fb / fc;
        p = s * (2 * xm * qq * (qq - r) - (b - a) * (r - 1));
        q = (qq - 1) * (r - 1) * (s - 1);
      }
      if (p > 0) q = -q;
      p = std::fabs(p);
      if (2 * p < std::fmin(3 * xm * q - std::fabs(tol1 * q), std::fabs(e * q))) {
        e = d;
        d = p / q;
      } else {
        d = xm;
        e = d;
      }
    } else {
      d = xm;
      e = d;
    }
    a = b;
    fa = fb;
    b += (std::fabs(d) > tol1) ? d : std::copysign(tol1, xm);
    fb = f(b);
    if (!std::isfinite(fb)) throw NumericalError(what + ": non-finite function value");
  }
  throw NumericalError(what + ": Brent root finder did not converge in 200 iterations");
}

/// Brent's minimiser (golden section with parabolic steps) on [a, b];
/// returns (x, f(x)) with x located to relTol |x| + absTol.
template <class F>
std::pair<Real, Real> brentMinimise(F&& f, Real a, Real b, Real relTol, Real absTol,
                                    const std::string& what) {
  constexpr Real cgold = 0.3819660112501051;  // (3 − √5)/2
  Real x = a + cgold * (b - a), w = x, v = x;
  Real fx = f(x), fw = fx, fv = fx;
  Real d = 0, e = 0;
  for (int it = 0; it < 500; ++it) {
    const Real xm = 0.5 * (a + b);
    const Real tol1 = relTol * std::fabs(x) + absTol;
    const Real tol2 = 2 * tol1;
    if (std::fabs(x - xm) <= tol2 - 0.5 * (b - a)) return {x, fx};
    bool golden = true;
    if (std::fabs(e) > tol1) {
      Real r = (x - w) * (fx - fv);
      Real q = (x - v) * (fx - fw);
      Real p = (x - v) * q - (x - w) * r;
      q = 2 * (q - r);
      if (q > 0) p = -p;
      q = std::fabs(q);
      const Real etemp = e;
      e = d;
      if (!(std::fabs(p) >= std::fabs(0.5 * q * etemp) || p <= q * (a - x) || p >= q * (b - x))) {
        d = p / q;
        const Real u = x + d;
        if (u - a < tol2 || b - u < tol2) d = std::copysign(tol1, xm - x);
        golden = false;
      }
    }
    if (golden) {
      e = (x >= xm) ? a - x : b - x;
      d = cgold * e;
    }
    const Real u = (std::fabs(d) >= tol1) ? x + d : x + std::copysign(tol1, d);
    const Real fu = f(u);
    if (!std::isfinite(fu)) throw NumericalError(what + ": non-finite objective");
    if (fu <= fx) {
      if (u >= x) {
        a = x;
      } else {
        b = x;
      }
      v = w;
      fv = fw;
      w = x;
      fw = fx;
      x = u;
      fx = fu;
    } else {
      if (u < x) {
        a = u;
      } else {
        b = u;
      }
      if (fu <= fw || w == x) {
        v = w;
        fv = fw;
        w = u;
        fw = fu;
      } else if (fu <= fv || v == x || v == w) {
        v = u;
        fv = fu;
      }
    }
  }
  throw NumericalError(what + ": Brent minimiser did not converge in 500 iterations");
}

}  // namespace cgcm::analytic::detail
