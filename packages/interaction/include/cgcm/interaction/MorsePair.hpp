#pragma once
// The Morse potential as a kernel potential (KernelPotential.hpp):
//
//     phi(r) = eps [exp(-2a (r - r0)) - 2 exp(-a (r - r0))],
//
// a well of depth eps at r0 like Lennard-Jones, but with a finite value at
// r = 0 and an exponential tail. With a = 6/r0 (matchedToLennardJones) its
// curvature at r0 is Lennard-Jones's 72 eps/r0^2. The half-space integral is
// closed: integral over {z >= h} of exp(-b |x|) dv = 2 pi integral_h^inf
// exp(-b rho) rho (rho - h) d rho = 2 pi exp(-b h) (b h + 2) / b^3. The line
// and ring laws of Method 1 come from the generic quadratures (KernelLaws.hpp).
#include <Kokkos_Macros.hpp>

#include <cmath>

#include "cgcm/core/Types.hpp"
#include "cgcm/interaction/KernelLaws.hpp"

namespace cgcm::interaction {

struct MorsePair {
  Real eps = 0.0;
  Real r0 = 0.0;
  Real a = 0.0;  ///< inverse width

  static MorsePair matchedToLennardJones(Real eps, Real r0) { return {eps, r0, 6.0 / r0}; }

  /// The potential of strength * eps and length b r0: eps -> strength eps / b^3, r0 -> b r0, a -> a / b.
  MorsePair scaled(Real strength, Real b) const { return {strength * eps / (b * b * b), b * r0, a / b}; }

  KOKKOS_INLINE_FUNCTION Real phi(Real r) const {
    const Real e = std::exp(-a * (r - r0));
    return eps * e * (e - 2.0);
  }

  KOKKOS_INLINE_FUNCTION RadialLaw pointLaw(Real s) const {
    const Real r = std::sqrt(s), e = std::exp(-a * (r - r0));
    const Real phi = eps * e * (e - 2.0), dphi = 2.0 * a * eps * e * (1.0 - e),
               d2phi = 2.0 * a * a * eps * e * (2.0 * e - 1.0);
    // f(s) = phi(sqrt s): f' = phi' / (2 r), f'' = (phi'' r - phi') / (4 r^3)
    return {phi, 0.5 * dphi / r, 0.25 * (d2phi * r - dphi) / (s * r)};
  }

  KOKKOS_INLINE_FUNCTION void halfSpace(Real h, Real& value, Real& derivative) const {
    constexpr Real twoPi = 2.0 * kPi;
    const Real e = std::exp(-a * (h - r0)), a2 = a * a, a3 = a2 * a, ah = a * h;
    value = twoPi * eps * (e * e * (2.0 * ah + 2.0) / (8.0 * a3) - 2.0 * e * (ah + 2.0) / a3);
    derivative = twoPi * eps * (-e * e * (2.0 * ah + 1.0) / (4.0 * a2) + 2.0 * e * (ah + 1.0) / a2);
  }
};

}  // namespace cgcm::interaction
