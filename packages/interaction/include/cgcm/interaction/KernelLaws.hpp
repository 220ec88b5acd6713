#pragma once
// The laws a kernel potential (KernelPotential.hpp) gives the kernels, as
// functions of squared distances, and the generic quadratures that derive
// the plane-strain and axisymmetric laws of Method 1 from the point law of a
// potential without closed forms for them.
//
//   point law  f(s) = phi(sqrt s), s = |x1 - x2|^2, with f' and f'' in s;
//   line law   L(s) = integral of f(s + z^2) dz over the out-of-plane line
//              (plane strain, per unit thickness), with L' and L'';
//   ring law   F(p, q) = (1/2 pi) integral_0^2pi f(p cos^2(t/2) + q sin^2(t/2)) dt,
//              the azimuthal average between the rings through (rho1, z1) and
//              (rho2, z2) with p = (rho1 - rho2)^2 + dz^2, q = (rho1 + rho2)^2 + dz^2,
//              and its first and second derivatives in (p, q).
//
// The generic quadratures are Gauss-Legendre (kGenericLawPoints points) after
// a change of variable that takes the peak of the integrand (the nearest
// points of the line or the rings) into an O(1) interval:
//   line  z = sqrt(s) tan(a):   L = 2 sqrt(s) int_0^pi/2 f(s / c^2) / c^2 da,
//   ring  tan(t/2) = sqrt(p/q) tan(a):
//                               F = (2/pi) int_0^pi/2 D^1/2 S^-1 f(D / S) da,
//                               D = p q, S = q c^2 + p s^2 (c = cos a, s = sin a).
// For f = s^-m both integrands are polynomials in c^2 and s^2, so the rules
// are exact up to m = 2 kGenericLawPoints; the derivatives are those of the
// discrete sums (the forces stay the exact gradient of the discrete energy).
#include <Kokkos_Macros.hpp>

#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <type_traits>

#include "cgcm/core/Types.hpp"

namespace cgcm::interaction {

/// A law of s = r^2: value and first and second derivatives in s.
struct RadialLaw {
  Real f, df, d2f;
};

/// The ring law and its derivatives in (p, q) (the second ones only when asked).
struct RingLaw {
  Real F, Fp, Fq, Fpp, Fpq, Fqq;
};

/// a s^-alpha - b s^-beta from its two terms ta = a s^-alpha, tb = b s^-beta at s.
KOKKOS_INLINE_FUNCTION RadialLaw radialInversePowers(Real alpha, Real beta, Real ta, Real tb, Real s) {
  return {ta - tb, (-alpha * ta + beta * tb) / s, (alpha * (alpha + 1.0) * ta - beta * (beta + 1.0) * tb) / (s * s)};
}

constexpr unsigned kGenericLawPoints = 20;

namespace detail {
/// The Gauss-Legendre points of [0, pi/2] as cos^2 a, sin^2 a and weights
/// (including the interval's pi/4), computed once.
struct AngleRule {
  static constexpr unsigned kPoints = kGenericLawPoints;
  Real c2[kPoints], s2[kPoints], w[kPoints];
  static const AngleRule& get() {
    static const AngleRule rule = [] {
      using Rule = boost::math::quadrature::gauss<Real, kPoints>;
      constexpr Real quarterPi = 0.25 * kPi;
      AngleRule r{};
      unsigned n = 0;
      for (std::size_t i = 0; i < Rule::abscissa().size(); ++i)
        for (const Real sign : {1.0, -1.0}) {
          if (Rule::abscissa()[i] == 0.0 && sign < 0.0) continue;  // odd point counts: the centre once
          const Real a = quarterPi * (1.0 + sign * Rule::abscissa()[i]), c = std::cos(a), sn = std::sin(a);
          r.c2[n] = c * c;
          r.s2[n] = sn * sn;
          r.w[n++] = quarterPi * Rule::weights()[i];
        }
      return r;
    }();
    return rule;
  }
};

template <class P, class = void>
struct HasLineLaw : std::false_type {};
template <class P>
struct HasLineLaw<P, std::void_t<decltype(std::declval<const P&>().lineLaw(Real()))>> : std::true_type {};
template <class P, class = void>
struct HasRingLaw : std::false_type {};
template <class P>
struct HasRingLaw<P, std::void_t<decltype(std::declval<const P&>().ringLaw(Real(), Real(), bool()))>>
    : std::true_type {};
}  // namespace detail

/// The line law by quadrature of the point law.
template <class P>
RadialLaw lineLawByQuadrature(const P& potential, Real s) {
  RadialLaw L{0.0, 0.0, 0.0};
  const Real rs = std::sqrt(s);
  const detail::AngleRule& rule = detail::AngleRule::get();
  for (unsigned k = 0; k < rule.kPoints; ++k) {
    const Real ic2 = 1.0 / rule.c2[k], w = rule.w[k];
    const RadialLaw f = potential.pointLaw(s * ic2);
    // g = 2 s^1/2 c^-2 f(s/c^2) and its s-derivatives
    L.f += w * 2.0 * rs * ic2 * f.f;
    L.df += w * (ic2 * f.f / rs + 2.0 * rs * ic2 * ic2 * f.df);
    L.d2f += w * (-0.5 * ic2 * f.f / (s * rs) + 2.0 * ic2 * ic2 * f.df / rs + 2.0 * rs * ic2 * ic2 * ic2 * f.d2f);
  }
  return L;
}

/// The ring law by quadrature of the point law.
template <class P>
RingLaw ringLawByQuadrature(const P& potential, Real p, Real q, bool withHessian) {
  RingLaw F{0.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  const Real D = p * q, rD = std::sqrt(D);
  constexpr Real twoOverPi = 2.0 / kPi;
  const detail::AngleRule& rule = detail::AngleRule::get();
  for (unsigned k = 0; k < rule.kPoints; ++k) {
    const Real c2 = rule.c2[k], s2 = rule.s2[k], S = q * c2 + p * s2, iS = 1.0 / S;
    const RadialLaw f = potential.pointLaw(D * iS);
    // h(D, S) = D^1/2 S^-1 f(D/S) and its derivatives in D and S
    const Real W = twoOverPi * rule.w[k], iS2 = iS * iS, iS3 = iS2 * iS;
    const Real h = rD * iS * f.f;
    const Real hD = 0.5 * iS * f.f / rD + rD * iS2 * f.df;
    const Real hS = -rD * iS2 * f.f - D * rD * iS3 * f.df;
    F.F += W * h;
    F.Fp += W * (hD * q + hS * s2);
    F.Fq += W * (hD * p + hS * c2);
    if (!withHessian) continue;
    const Real hDD = -0.25 * iS * f.f / (D * rD) + iS2 * f.df / rD + rD * iS3 * f.d2f;
    const Real hDS = -0.5 * iS2 * f.f / rD - 2.5 * rD * iS3 * f.df - D * rD * iS3 * iS * f.d2f;
    const Real hSS = 2.0 * rD * iS3 * f.f + 4.0 * D * rD * iS3 * iS * f.df + D * D * rD * iS3 * iS2 * f.d2f;
    F.Fpp += W * (hDD * q * q + 2.0 * hDS * q * s2 + hSS * s2 * s2);
    F.Fpq += W * (hDD * D + hDS * S + hSS * s2 * c2 + hD);
    F.Fqq += W * (hDD * p * p + 2.0 * hDS * p * c2 + hSS * c2 * c2);
  }
  return F;
}

/// The potential's own line law when it has one in closed form, else the quadrature.
template <class P>
KOKKOS_INLINE_FUNCTION RadialLaw lineLaw(const P& potential, Real s) {
  if constexpr (detail::HasLineLaw<P>::value)
    return potential.lineLaw(s);
  else
    return lineLawByQuadrature(potential, s);
}

/// The potential's own ring law when it has one in closed form, else the quadrature.
template <class P>
KOKKOS_INLINE_FUNCTION RingLaw ringLaw(const P& potential, Real p, Real q, bool withHessian) {
  if constexpr (detail::HasRingLaw<P>::value)
    return potential.ringLaw(p, q, withHessian);
  else
    return ringLawByQuadrature(potential, p, q, withHessian);
}

}  // namespace cgcm::interaction
