#pragma once
// phi(r) = c12 r^-12 - c6 r^-6 as a kernel potential (KernelPotential.hpp):
// Lennard-Jones (c12 = eps r0^12, c6 = 2 eps r0^6) and its repulsive part
// (c6 = 0). Every law in closed form:
//   point pair    f(s) = phi(sqrt s), s = r^2;
//   half-space    integral over {z >= r} of C s^-n dv = 2 pi C r^(3 - n) / ((n - 2)(n - 3))
//                 (doc/theory.md#method-3), so Phi/beta = (pi/45) c12 r^-9 - (pi/6) c6 r^-3;
//   line          int (s + z^2)^-m dz = s^(1/2 - m) sqrt(pi) Gamma(m - 1/2) / Gamma(m):
//                 63 pi / 256 s^-5.5 for m = 6 and 3 pi / 8 s^-2.5 for m = 3;
//   ring          (1/2 pi) int (A - B cos theta)^-m dtheta = D^(-m/2) P_(m-1)(A / sqrt D)
//                 with A = (p + q)/2, D = p q (P_n the Legendre polynomials):
//                 m = 6: (63 A^5 - 70 A^3 D + 15 A D^2) / (8 D^5.5),
//                 m = 3: (3 A^2 - D) / (2 D^2.5);
//                 its derivatives in (p, q) by the chain rule through (A, D).
#include <Kokkos_Macros.hpp>

#include <cmath>

#include "cgcm/core/Types.hpp"
#include "cgcm/interaction/KernelLaws.hpp"

namespace cgcm::interaction {

struct InversePowerPair {
  Real c12 = 0.0;
  Real c6 = 0.0;

  /// The potential of strength * eps and length b r0: c12 -> strength b^9 c12, c6 -> strength b^3 c6.
  InversePowerPair scaled(Real strength, Real b) const {
    const Real b3 = b * b * b;
    return {strength * b3 * b3 * b3 * c12, strength * b3 * c6};
  }

  KOKKOS_INLINE_FUNCTION Real phi(Real r) const {
    const Real i2 = 1.0 / (r * r), i6 = i2 * i2 * i2;
    return (c12 * i6 - c6) * i6;
  }

  KOKKOS_INLINE_FUNCTION RadialLaw pointLaw(Real s) const {
    const Real i1 = 1.0 / s, i3 = i1 * i1 * i1;
    return radialInversePowers(6.0, 3.0, c12 * i3 * i3, c6 * i3, s);
  }

  KOKKOS_INLINE_FUNCTION void halfSpace(Real r, Real& value, Real& derivative) const {
    constexpr Real pi = kPi;
    const Real i1 = 1.0 / r, i3 = i1 * i1 * i1, i9 = i3 * i3 * i3;
    const Real a = (pi / 45.0) * c12 * i9, b = (pi / 6.0) * c6 * i3;
    value = a - b;
    derivative = (-9.0 * a + 3.0 * b) * i1;
  }

  KOKKOS_INLINE_FUNCTION RadialLaw lineLaw(Real s) const {
    constexpr Real pi = kPi;
    const Real i1 = 1.0 / s, i2 = i1 * i1, root = std::sqrt(i1);
    return radialInversePowers(5.5, 2.5, c12 * (63.0 * pi / 256.0) * i2 * i2 * i1 * root,
                               c6 * (3.0 * pi / 8.0) * i2 * root, s);
  }

  KOKKOS_INLINE_FUNCTION RingLaw ringLaw(Real p, Real q, bool withHessian) const {
    const Real A = 0.5 * (p + q), D = p * q, A2 = A * A, invD = 1.0 / D, root = std::sqrt(invD);
    const Real D2 = invD * invD, D55 = D2 * D2 * invD * root, D25 = D2 * root;
    // 8 x repulsive polynomial 63 A^5 - 70 A^3 D + 15 A D^2; 2 x attractive 3 A^2 - D
    const Term R = term(5.5, D55, invD, A * (63.0 * A2 * A2 - 70.0 * A2 * D + 15.0 * D * D) / 8.0,
                        (315.0 * A2 * A2 - 210.0 * A2 * D + 15.0 * D * D) / 8.0, (-70.0 * A2 * A + 30.0 * A * D) / 8.0,
                        (1260.0 * A2 * A - 420.0 * A * D) / 8.0, (-210.0 * A2 + 30.0 * D) / 8.0, 30.0 * A / 8.0);
    const Term T = term(2.5, D25, invD, 0.5 * (3.0 * A2 - D), 3.0 * A, -0.5, 3.0, 0.0, 0.0);
    const Real FA = c12 * R.A - c6 * T.A, FD = c12 * R.D - c6 * T.D;
    RingLaw out{};
    out.F = c12 * R.v - c6 * T.v;
    out.Fp = 0.5 * FA + q * FD;  // A_p = 1/2, D_p = q
    out.Fq = 0.5 * FA + p * FD;
    if (!withHessian) return out;
    const Real FAA = c12 * R.AA - c6 * T.AA, FAD = c12 * R.AD - c6 * T.AD, FDD = c12 * R.DD - c6 * T.DD;
    out.Fpp = 0.25 * FAA + q * FAD + q * q * FDD;
    out.Fpq = 0.25 * FAA + 0.5 * (p + q) * FAD + p * q * FDD + FD;
    out.Fqq = 0.25 * FAA + p * FAD + p * p * FDD;
    return out;
  }

 private:
  /// Value and derivatives (A, D, AA, AD, DD) of poly(A, D) D^-k, from those of the polynomial.
  struct Term {
    Real v, A, D, AA, AD, DD;
  };
  KOKKOS_INLINE_FUNCTION static Term term(Real k, Real Dk, Real invD, Real P, Real PA, Real PD, Real PAA, Real PAD,
                                          Real PDD) {
    // F = P D^-k: F_D = (P_D - k P / D) D^-k, F_DD = (P_DD - 2k P_D / D + k (k + 1) P / D^2) D^-k
    return {P * Dk,
            PA * Dk,
            (PD - k * P * invD) * Dk,
            PAA * Dk,
            (PAD - k * PA * invD) * Dk,
            (PDD - 2.0 * k * PD * invD + k * (k + 1.0) * P * invD * invD) * Dk};
  }
};

}  // namespace cgcm::interaction
