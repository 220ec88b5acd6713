#pragma once
// Point-pair laws of Method 1 (the paper's eq. 16, doc/theory.md#method-1): the energy of
// two quadrature points of two bodies, with its first and second derivatives,
// in the coordinates of each formulation, for a kernel potential P
// (KernelPotential.hpp):
//   3D            psi(x1, x2) = phi(|x1 - x2|), P's point law;
//   plane strain  the line integral over the out-of-plane direction (per unit
//                 thickness of the other body), P's line law;
//   axisymmetric  the ring average (1/2 pi) int_0^2pi phi dtheta between the
//                 rings through x1 = (rho1, z1) and x2 = (rho2, z2), P's ring
//                 law in p = (rho1 - rho2)^2 + dz^2, q = (rho1 + rho2)^2 + dz^2
// (closed forms where P has them, else KernelLaws.hpp's quadratures).
// The energy of two bodies is then sum_i sum_j W1_i W2_j psi(x1_i, x2_j)
// with W = beta0 w det J0 (times 2 pi R in the axisymmetric case): the
// current density times the current volume is beta0 dV0 (beta = beta0 / J),
// so the weights are constant and the J dependence of the paper's
// beta1 beta2 dv1 dv2 is exact without a term of its own.
//
// Each law returns psi, g = d psi / d x1 and the blocks H11 = d2 psi / dx1 dx1,
// H12 = d2 psi / dx1 dx2 (dim x dim); the derivatives in x2 follow by swapping
// the points.
#include <Kokkos_Macros.hpp>

#include "cgcm/core/Types.hpp"
#include "cgcm/interaction/KernelLaws.hpp"

namespace cgcm::interaction {

/// psi = L(s), s = |x1 - x2|^2 in `Dim` dimensions.
template <int Dim>
KOKKOS_INLINE_FUNCTION void radialPairLaw(const RadialLaw& L, const Real* d, Real& psi, Real* g, Real (*H11)[3],
                                          Real (*H12)[3]) {
  psi = L.f;
  for (int i = 0; i < Dim; ++i) {
    g[i] = 2.0 * L.df * d[i];
    if (H11 == nullptr) continue;
    for (int j = 0; j < Dim; ++j) {
      const Real h = 4.0 * L.d2f * d[i] * d[j] + (i == j ? 2.0 * L.df : 0.0);
      H11[i][j] = h;
      H12[i][j] = -h;
    }
  }
}

/// 3D: psi = phi(|x1 - x2|).
template <class P>
KOKKOS_INLINE_FUNCTION void pairLaw3D(const P& potential, const Real* x1, const Real* x2, Real& psi, Real* g,
                                      Real (*H11)[3], Real (*H12)[3]) {
  const Real d[3] = {x1[0] - x2[0], x1[1] - x2[1], x1[2] - x2[2]};
  radialPairLaw<3>(potential.pointLaw(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), d, psi, g, H11, H12);
}

/// Plane strain: psi = integral of phi along the out-of-plane line through x2.
template <class P>
KOKKOS_INLINE_FUNCTION void pairLawPlaneStrain(const P& potential, const Real* x1, const Real* x2, Real& psi, Real* g,
                                               Real (*H11)[3], Real (*H12)[3]) {
  const Real d[2] = {x1[0] - x2[0], x1[1] - x2[1]};
  radialPairLaw<2>(lineLaw(potential, d[0] * d[0] + d[1] * d[1]), d, psi, g, H11, H12);
}

/// Axisymmetric: x = (rho, z); psi = the ring average of phi, its derivatives
/// by the chain rule through p and q.
template <class P>
KOKKOS_INLINE_FUNCTION void pairLawAxisymmetric(const P& potential, const Real* x1, const Real* x2, Real& psi, Real* g,
                                                Real (*H11)[3], Real (*H12)[3]) {
  const Real dr = x1[0] - x2[0], sr = x1[0] + x2[0], dz = x1[1] - x2[1];
  const Real p = dr * dr + dz * dz, q = sr * sr + dz * dz;
  const RingLaw F = ringLaw(potential, p, q, H11 != nullptr);
  psi = F.F;
  // gradients of p and q in (rho1, z1, rho2, z2); their Hessians are constant
  const Real gp[4] = {2.0 * dr, 2.0 * dz, -2.0 * dr, -2.0 * dz};
  const Real gq[4] = {2.0 * sr, 2.0 * dz, 2.0 * sr, -2.0 * dz};
  for (int i = 0; i < 2; ++i) g[i] = F.Fp * gp[i] + F.Fq * gq[i];
  if (H11 == nullptr) return;
  // d2p: +2 on (rho1, rho1), (z1, z1), -2 on (rho1, rho2), (z1, z2); d2q: +2 on (rho1, rho1),
  // (z1, z1), (rho1, rho2), -2 on (z1, z2)
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 4; ++j) {
      Real h = F.Fpp * gp[i] * gp[j] + F.Fpq * (gp[i] * gq[j] + gq[i] * gp[j]) + F.Fqq * gq[i] * gq[j];
      if (j == i) h += 2.0 * (F.Fp + F.Fq);
      if (j == i + 2) h += i == 0 ? 2.0 * (F.Fq - F.Fp) : -2.0 * (F.Fp + F.Fq);
      if (j < 2)
        H11[i][j] = h;
      else
        H12[i][j - 2] = h;
    }
}

}  // namespace cgcm::interaction
