#pragma once
// The pair potentials of cgcm as plain data for the kernels (no virtual
// calls): phi(r) = c12 r^-12 - c6 r^-6 (Lennard-Jones: c12 = eps r0^12,
// c6 = 2 eps r0^6; repulsive: c6 = 0), with the half-space integral of
// Method 3 (THEORY §2: integral over {z >= r} of C s^-n dv = 2 pi C r^(3 - n)
// / ((n - 2)(n - 3))) and the point-pair laws of Method 1 (VolumePairLaw.hpp).
// PairPotential::inversePowers() gives a potential's coefficients.
#include <Kokkos_Macros.hpp>

#include "cgcm/core/Types.hpp"

namespace cgcm::interaction {

struct InversePowerPair {
  Real c12 = 0.0;
  Real c6 = 0.0;

  KOKKOS_INLINE_FUNCTION Real phi(Real r) const {
    const Real i2 = 1.0 / (r * r), i6 = i2 * i2 * i2;
    return (c12 * i6 - c6) * i6;
  }
  /// Half-space integral per unit density, Phi(r)/beta = (pi/45) c12 r^-9 -
  /// (pi/6) c6 r^-3, and its derivative.
  KOKKOS_INLINE_FUNCTION void halfSpace(Real r, Real& value, Real& derivative) const {
    constexpr Real pi = 3.14159265358979323846;
    const Real i1 = 1.0 / r, i3 = i1 * i1 * i1, i9 = i3 * i3 * i3;
    const Real a = (pi / 45.0) * c12 * i9, b = (pi / 6.0) * c6 * i3;
    value = a - b;
    derivative = (-9.0 * a + 3.0 * b) * i1;
  }
};

}  // namespace cgcm::interaction
