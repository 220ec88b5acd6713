#include "cgcm/analytic/Cylinder.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "Numerics.hpp"
#include "cgcm/analytic/Models.hpp"
#include "cgcm/core/Error.hpp"

namespace cgcm::analytic {
namespace {

void requirePositive(const char* what, Real value) {
  if (!(std::isfinite(value) && value > 0)) {
    std::ostringstream msg;
    msg << "cylinder: " << what << " must be finite and > 0, got " << value;
    throw InputError(msg.str());
  }
}

/// The two brackets of the gap equation in s = √(m²−1), m = √(1+s²), and
/// their derivatives:
///   A = ms − arsinh s = ∫₀ˢ 2t²/√(1+t²) dt,         A' = 2s²/m,
///   B = s arsinh s − 2m atan((m−1)/(m+1)),
///   B' = arsinh s + s/m − (2s/m) atan((m−1)/(m+1)) − 2s/(1+m²).
/// A ≈ 2s³/3 cancels as s → 0 (the JKR end), so below s = 0.1 it is the
/// integral's binomial series, whose terms fall by s² ≤ 1e-2 each (14 terms
/// reach rounding); B ≈ s²/2 loses only a factor 2, with m − 1 = s²/(1+m).
struct Brackets {
  Real A, B, dA, dB;
};

Brackets brackets(Real s) {
  const Real m2 = 1 + s * s;
  const Real m = std::sqrt(m2);
  const Real ash = std::asinh(s);
  const Real t = std::atan(s * s / ((1 + m) * (m + 1)));  // atan((m−1)/(m+1))
  Brackets b;
  if (s < 0.1) {
    Real coeff = 1;  // binom(−1/2, k)
    Real power = s * s * s;
    b.A = 0;
    for (int k = 0; k < 14; ++k) {
      b.A += 2 * coeff * power / (2 * k + 3);
      coeff *= -static_cast<Real>(2 * k + 1) / static_cast<Real>(2 * k + 2);
      power *= s * s;
    }
  } else {
    b.A = m * s - ash;
  }
  b.B = s * ash - 2 * m * t;
  b.dA = 2 * s * s / m;
  b.dB = ash + s / m - 2 * s * t / m - 2 * s / (1 + m2);
  return b;
}

Real residual(Real lambda, Real a, const Brackets& b) {
  return 0.25 * kPi * lambda * a * a * b.A + lambda * lambda * a * b.B - 1;
}

// Scan of dP̄/dā for the pull-off: from ā = 1e-8 (the minimum sits at
// ā ≈ 0.65λ at small λ: 6.5e-4 at λ = 1e-3) upwards, 24 points per decade,
// until past ā = 10 with P̄ > 0 (the JKR pull-off radius 0.587 is the
// largest; beyond it P̄ only rises).
constexpr Real kScanMinA = 1e-8;
constexpr int kScanPerDecade = 24;

}  // namespace

CylinderScales CylinderScales::from(Real w, Real R, Real Estar) {
  requirePositive("work of adhesion w", w);
  requirePositive("radius R", R);
  requirePositive("modulus E*", Estar);
  CylinderScales s;
  s.length = std::cbrt(kPi * w * R * R / Estar);
  s.force = std::cbrt(kPi * kPi * w * w * Estar * R);
  s.stress = std::cbrt(kPi * w * Estar * Estar / R);
  return s;
}

CylinderPoint jkrCylinder(Real a) {
  requirePositive("half-width a", a);
  return {a, 0.25 * kPi * a * a - std::sqrt(2 * a), a};
}

CylinderPoint jkrCylinderPullOff() {
  // dP̄/dā = πā/2 − 1/√(2ā) = 0 gives ā³ = 2/π²; there √(2ā) = πā², so
  // P̄ = −3πā²/4 = −3/(16π)^(1/3).
  const Real a = std::cbrt(2 / (kPi * kPi));
  return {a, -3 / std::cbrt(16 * kPi), a};
}

Real mdCylinderResidual(Real lambda, Real a, Real s) { return residual(lambda, a, brackets(s)); }

MdCylinderSolution solveMdCylinder(Real lambda, Real a, Real sGuess) {
  requirePositive("lambda", lambda);
  requirePositive("half-width a", a);
  auto f = [&](Real s) { return residual(lambda, a, brackets(s)); };
  std::ostringstream what;
  what.precision(17);
  what << "Maugis-Dugdale cylinder (lambda = " << lambda << ", a = " << a << ")";

  // Bracket the root by geometric steps from the guess: F(0) = −1 and F
  // increases strictly, so a sign change is always found unless the root
  // leaves the floating-point range.
  Real s = (std::isfinite(sGuess) && sGuess > 0) ? sGuess : 1;
  Real fs = f(s);
  if (fs == 0) {
    // the guess is the root
  } else {
    Real lo = s, hi = s, flo = fs, fhi = fs;
    if (fs < 0) {
      while (fhi < 0) {
        lo = hi;
        flo = fhi;
        hi *= 4;
        if (hi > 1e150) throw NumericalError(what.str() + ": no sign change below s = 1e150");
        fhi = f(hi);
      }
    } else {
      while (flo > 0) {
        hi = lo;
        fhi = flo;
        lo *= 0.25;
        if (lo < 1e-150) throw NumericalError(what.str() + ": no sign change above s = 1e-150");
        flo = f(lo);
      }
    }
    s = detail::bracketedRoot(f, lo, hi, flo, fhi, 0, what.str());
  }

  MdCylinderSolution sol;
  sol.lambda = lambda;
  sol.a = a;
  sol.s = s;
  sol.m = std::sqrt(1 + s * s);
  sol.load = 0.25 * kPi * a * a - lambda * a * s;
  // Implicit slope: F(s, ā) = 0, ds/dā = −F_ā/F_s.
  const Brackets b = brackets(s);
  const Real dFda = 0.5 * kPi * lambda * a * b.A + lambda * lambda * b.B;
  const Real dFds = 0.25 * kPi * lambda * a * a * b.dA + lambda * lambda * a * b.dB;
  const Real ds = -dFda / dFds;
  sol.dLoad = 0.5 * kPi * a - lambda * s - lambda * a * ds;
  return sol;
}

CylinderPoint mdCylinderPullOff(Real lambda) {
  if (!(lambda >= kLambdaMin && lambda <= kLambdaMax)) {
    std::ostringstream msg;
    msg << "Maugis-Dugdale cylinder pull-off: lambda = " << lambda << " is out of range (allowed: "
        << kLambdaMin << " <= lambda <= " << kLambdaMax << ")";
    throw InputError(msg.str());
  }
  std::ostringstream what;
  what << "Maugis-Dugdale cylinder pull-off (lambda = " << lambda << ")";
  const Real factor = std::pow(10.0, 1.0 / kScanPerDecade);
  MdCylinderSolution previous = solveMdCylinder(lambda, kScanMinA);
  if (previous.dLoad >= 0) throw NumericalError(what.str() + ": the load rises already at a = 1e-8");
  MdCylinderSolution lo, hi;
  bool found = false;
  for (Real a = kScanMinA * factor;; a *= factor) {
    const MdCylinderSolution next = solveMdCylinder(lambda, a, previous.s);
    // Keep the deepest − to + sign change of the slope.
    if (previous.dLoad < 0 && next.dLoad >= 0 &&
        (!found || std::fmin(previous.load, next.load) < std::fmin(lo.load, hi.load))) {
      lo = previous;
      hi = next;
      found = true;
    }
    previous = next;
    if (a > 10 && next.load > 0) break;
    if (a > 1e6) throw NumericalError(what.str() + ": the load still falls at a = 1e6");
  }
  if (!found) throw NumericalError(what.str() + ": no minimum of the load found");
  Real sGuess = lo.s;
  auto slope = [&](Real a) {
    const MdCylinderSolution sol = solveMdCylinder(lambda, a, sGuess);
    sGuess = sol.s;
    return sol.dLoad;
  };
  const Real a = detail::bracketedRoot(slope, lo.a, hi.a, lo.dLoad, hi.dLoad, 1e-14 * hi.a, what.str());
  const MdCylinderSolution sol = solveMdCylinder(lambda, a, lo.s);
  if (!(sol.load <= std::fmax(lo.load, hi.load))) {
    throw NumericalError(what.str() + ": refined point is not a minimum");
  }
  return {a, sol.load, sol.m * a};
}

}  // namespace cgcm::analytic
