#include "cgcm/analytic/MaugisDugdale.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "cgcm/core/Error.hpp"

namespace cgcm::analytic {
namespace {

constexpr Real kEps = std::numeric_limits<Real>::epsilon();

void requirePositive(const char* what, Real value) {
  if (!(std::isfinite(value) && value > 0)) {
    std::ostringstream msg;
    msg << "Maugis-Dugdale: " << what << " must be finite and > 0, got " << value;
    throw InputError(msg.str());
  }
}

/// s − atan s. For small s the difference cancels (both terms ≈ s while the
/// result is ≈ s³/3), so use the alternating series s³/3 − s⁵/5 + s⁷/7 − …;
/// for s < 0.1 consecutive terms fall by at least 100, and 9 terms reach
/// rounding.
Real sMinusAtan(Real s) {
  if (s < 0.1) {
    const Real s2 = s * s;
    Real term = s * s2;  // s^(2k+1)
    Real sum = 0;
    Real sign = 1;
    for (int k = 1; k <= 9; ++k) {
      sum += sign * term / static_cast<Real>(2 * k + 1);
      term *= s2;
      sign = -sign;
    }
    return sum;
  }
  return s - std::atan(s);
}

/// The two brackets of (42) written in s = √(m²−1), m = √(1+s²):
///   A = s + (m²−2) atan s = (s − atan s) + s² atan s,
///   B = s atan s − (m − 1) = s atan s − s²/(1+m),
/// both free of cancellation as s → 0 (A ≈ 4s³/3, B ≈ s²/2), and their
/// derivatives
///   A' = 2s²/m² + 2 s atan s,   B' = atan s + s/m² − s/m  (≈ s as s → 0).
struct Brackets {
  Real A, B, dA, dB;
};

Brackets brackets(Real s) {
  const Real at = std::atan(s);
  const Real m2 = 1 + s * s;
  const Real m = std::sqrt(m2);
  Brackets b;
  b.A = sMinusAtan(s) + s * s * at;
  b.B = s * at - s * s / (1 + m);
  b.dA = 2 * s * s / m2 + 2 * s * at;
  b.dB = at + s / m2 - s / m;
  return b;
}

}  // namespace

Real mdResidual(Real lambda, Real a, Real s) {
  const Brackets b = brackets(s);
  return 0.5 * lambda * a * a * b.A + (4.0 / 3.0) * lambda * lambda * a * b.B - 1;
}

Real solveMdS(Real lambda, Real a, Real sGuess) {
  requirePositive("lambda", lambda);
  requirePositive("contact radius a", a);
  const Real cA = 0.5 * lambda * a * a;
  const Real cB = (4.0 / 3.0) * lambda * lambda * a;
  auto residual = [&](Real s, Real& dF) {
    const Brackets b = brackets(s);
    dF = cA * b.dA + cB * b.dB;
    return cA * b.A + cB * b.B - 1;
  };
  auto fail = [&](const char* why) {
    std::ostringstream msg;
    msg.precision(17);
    msg << "Maugis-Dugdale: equation (42) not solved for lambda = " << lambda << ", a = " << a
        << ": " << why;
    throw NumericalError(msg.str());
  };

  // Starting point: for large s, A ≈ (π/2)s² and B ≈ (π/2 − 1)s, so (42)
  // reads (π/2)cA s² + (π/2 − 1)cB s = 1; its positive root, written without
  // cancellation. The bracketing below corrects it where s is not large.
  Real s = sGuess;
  if (!(std::isfinite(s) && s > 0)) {
    const Real q2 = 0.5 * kPi * cA;
    const Real q1 = (0.5 * kPi - 1) * cB;
    s = 2 / (q1 + std::sqrt(q1 * q1 + 4 * q2));
  }

  // Bracket [lo, hi] with F(lo) < 0 < F(hi). F(0) = −1 and F is strictly
  // increasing, so expanding geometrically from s always succeeds unless the
  // root leaves the floating-point range.
  Real dF = 0;
  Real f = residual(s, dF);
  if (f == 0) return s;
  Real lo = 0;
  Real hi = std::numeric_limits<Real>::infinity();
  if (f < 0) {
    lo = s;
    Real t = s;
    for (;;) {
      t *= 4;
      if (t > 1e150) fail("no sign change of the residual below s = 1e150");
      Real dt = 0;
      const Real ft = residual(t, dt);
      if (ft > 0) {
        hi = t;
        break;
      }
      if (ft == 0) return t;
      lo = t;
      s = t;
      f = ft;
      dF = dt;
    }
  } else {
    hi = s;
    Real t = s;
    for (;;) {
      t *= 0.25;
      if (t < 1e-150) fail("no sign change of the residual above s = 1e-150");
      Real dt = 0;
      const Real ft = residual(t, dt);
      if (ft < 0) {
        lo = t;
        break;
      }
      if (ft == 0) return t;
      hi = t;
      s = t;
      f = ft;
      dF = dt;
    }
  }

  // Safeguarded Newton: a Newton step that leaves the bracket is replaced by
  // bisection (geometric while the bracket spans orders of magnitude).
  for (int it = 0; it < 200; ++it) {
    Real next = (dF > 0) ? s - f / dF : std::numeric_limits<Real>::quiet_NaN();
    if (!(next > lo && next < hi)) {
      next = (lo > 0 && hi > 4 * lo) ? std::sqrt(lo * hi) : 0.5 * (lo + hi);
    }
    const Real step = std::fabs(next - s);
    s = next;
    if (step <= 4 * kEps * s || (hi - lo) <= 4 * kEps * hi) return s;
    f = residual(s, dF);
    if (!std::isfinite(f)) fail("non-finite residual");
    if (f == 0) return s;
    if (f < 0) {
      lo = s;
    } else {
      hi = s;
    }
  }
  fail("no convergence in 200 safeguarded Newton iterations");
  return s;  // unreachable
}

MdSolution solveMaugisDugdale(Real lambda, Real a, Real sGuess) {
  MdSolution sol;
  sol.lambda = lambda;
  sol.a = a;
  sol.s = solveMdS(lambda, a, sGuess);
  const Real s = sol.s;
  sol.m = std::sqrt(1 + s * s);
  // (43): the bracket s + m² atan s has only positive terms.
  sol.load = a * a * a - lambda * a * a * (s + sol.m * sol.m * std::atan(s));
  sol.approach = a * a - (4.0 / 3.0) * a * lambda * s;
  return sol;
}

MdSlopes mdSlopes(const MdSolution& sol) {
  const Real lambda = sol.lambda;
  const Real a = sol.a;
  const Real s = sol.s;
  const Brackets b = brackets(s);
  // F(s, ā) = (λā²/2) A(s) + (4λ²ā/3) B(s) − 1.
  const Real dFds = 0.5 * lambda * a * a * b.dA + (4.0 / 3.0) * lambda * lambda * a * b.dB;
  const Real dFda = lambda * a * b.A + (4.0 / 3.0) * lambda * lambda * b.B;
  MdSlopes d;
  d.ds = -dFda / dFds;
  // P̄ = ā³ − λā² C(s), C = s + (1+s²) atan s, C' = 2 + 2 s atan s.
  const Real at = std::atan(s);
  const Real C = s + (1 + s * s) * at;
  const Real dC = 2 + 2 * s * at;
  d.dLoad = 3 * a * a - 2 * lambda * a * C - lambda * a * a * dC * d.ds;
  // δ̄ = ā² − (4/3) λ ā s.
  d.dApproach = 2 * a - (4.0 / 3.0) * lambda * (s + a * d.ds);
  return d;
}

MdZeroContact mdZeroContactLimit(Real lambda) {
  requirePositive("lambda", lambda);
  // As ā → 0 with c̄ = mā fixed, s ≈ m → ∞ and
  //   A = s + (s²−1) atan s = (π/2)s² + O(1),
  //   B = s atan s − m + 1 = (π/2 − 1)s + O(1),
  // so (λā²/2)A → (π/4)λc̄² and (4λ²ā/3)B → (4/3)(π/2 − 1)λ²c̄.
  const Real q2 = 0.25 * kPi * lambda;
  const Real q1 = (4.0 / 3.0) * (0.5 * kPi - 1) * lambda * lambda;
  MdZeroContact z;
  z.c = 2 / (q1 + std::sqrt(q1 * q1 + 4 * q2));
  z.load = -0.5 * kPi * lambda * z.c * z.c;
  z.approach = -(4.0 / 3.0) * lambda * z.c;
  return z;
}

}  // namespace cgcm::analytic
