#pragma once
// Point-pair laws of Method 1 (the paper's eq. 16, THEORY §1): the energy of
// two quadrature points of two bodies, with its first and second derivatives,
// for a pair potential of inverse powers
//
//     phi(r) = c12 r^-12 - c6 r^-6        (Lennard-Jones: c12 = eps r0^12,
//                                          c6 = 2 eps r0^6; repulsive: c6 = 0)
//
// in the coordinates of each formulation:
//   3D            psi(x1, x2) = phi(|x1 - x2|);
//   plane strain  the line integral over the out-of-plane direction (per unit
//                 thickness of the other body): int (s + z^2)^-m dz =
//                 s^(1/2 - m) sqrt(pi) Gamma(m - 1/2) / Gamma(m), s = |x1 - x2|^2,
//                 i.e. 63 pi / 256 s^-5.5 for m = 6 and 3 pi / 8 s^-2.5 for m = 3;
//   axisymmetric  the ring average (1/2 pi) int_0^2pi phi dtheta between the
//                 rings through x1 = (rho1, z1) and x2 = (rho2, z2), in closed
//                 form: with A = rho1^2 + rho2^2 + dz^2, B = 2 rho1 rho2 and
//                 D = A^2 - B^2 = p q, p = (rho1 - rho2)^2 + dz^2,
//                 q = (rho1 + rho2)^2 + dz^2,
//                   (1/2pi) int (A - B cos theta)^-m dtheta = D^(-m/2) P_(m-1)(A / sqrt D)
//                 (P_n the Legendre polynomials), so
//                   m = 6: (63 A^5 - 70 A^3 D + 15 A D^2) / (8 D^5.5),
//                   m = 3: (3 A^2 - D) / (2 D^2.5).
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

#include <cmath>

#include "cgcm/core/Types.hpp"
#include "cgcm/interaction/InversePowerPair.hpp"

namespace cgcm::interaction {

/// Radial law psi(s) = a s^-alpha - b s^-beta of s = |x1 - x2|^2 in `Dim`
/// dimensions (3D: the potential itself; plane strain: its line integral),
/// given the two terms ta = a s^-alpha, tb = b s^-beta at s.
template <int Dim>
KOKKOS_INLINE_FUNCTION void radialPairLaw(Real alpha, Real beta, Real ta, Real tb, Real s, const Real* d, Real& psi,
                                          Real* g, Real (*H11)[3], Real (*H12)[3]) {
  psi = ta - tb;
  const Real dpsi = (-alpha * ta + beta * tb) / s;                                          // d psi / ds
  const Real d2psi = (alpha * (alpha + 1.0) * ta - beta * (beta + 1.0) * tb) / (s * s);  // d2 psi / ds2
  for (int i = 0; i < Dim; ++i) {
    g[i] = 2.0 * dpsi * d[i];
    if (H11 == nullptr) continue;
    for (int j = 0; j < Dim; ++j) {
      const Real h = 4.0 * d2psi * d[i] * d[j] + (i == j ? 2.0 * dpsi : 0.0);
      H11[i][j] = h;
      H12[i][j] = -h;
    }
  }
}

/// 3D: psi = phi(|x1 - x2|).
KOKKOS_INLINE_FUNCTION void pairLaw3D(const InversePowerPair& p, const Real* x1, const Real* x2, Real& psi, Real* g,
                                      Real (*H11)[3], Real (*H12)[3]) {
  const Real d[3] = {x1[0] - x2[0], x1[1] - x2[1], x1[2] - x2[2]};
  const Real s = d[0] * d[0] + d[1] * d[1] + d[2] * d[2], i3 = 1.0 / (s * s * s);
  radialPairLaw<3>(6.0, 3.0, p.c12 * i3 * i3, p.c6 * i3, s, d, psi, g, H11, H12);
}

/// Plane strain: psi = integral of phi along the out-of-plane line through x2.
KOKKOS_INLINE_FUNCTION void pairLawPlaneStrain(const InversePowerPair& p, const Real* x1, const Real* x2, Real& psi,
                                               Real* g, Real (*H11)[3], Real (*H12)[3]) {
  constexpr Real pi = 3.14159265358979323846;
  const Real d[2] = {x1[0] - x2[0], x1[1] - x2[1]};
  const Real s = d[0] * d[0] + d[1] * d[1], i1 = 1.0 / s, i2 = i1 * i1, root = std::sqrt(i1);
  radialPairLaw<2>(5.5, 2.5, p.c12 * (63.0 * pi / 256.0) * i2 * i2 * i1 * root, p.c6 * (3.0 * pi / 8.0) * i2 * root, s,
                   d, psi, g, H11, H12);
}

/// The ring average as a function of p = (rho1 - rho2)^2 + dz^2 and
/// q = (rho1 + rho2)^2 + dz^2, for any scalar type (forward AD checks the
/// hand-derived derivatives of pairLawAxisymmetric with it).
template <class T>
KOKKOS_INLINE_FUNCTION T ringAverage(const InversePowerPair& c, const T& p, const T& q) {
  using std::pow;
  const T A = 0.5 * (p + q), D = p * q, A2 = A * A;
  const T repulsive = A * (63.0 * A2 * A2 - 70.0 * A2 * D + 15.0 * D * D) / (8.0 * pow(D, 5.5));
  const T attractive = (3.0 * A2 - D) / (2.0 * pow(D, 2.5));
  return c.c12 * repulsive - c.c6 * attractive;
}

namespace detail {
/// Value and derivatives (A, D, AA, AD, DD) of poly(A, D) D^-k, from those of the polynomial.
struct RingTerm {
  Real v, A, D, AA, AD, DD;
};
KOKKOS_INLINE_FUNCTION RingTerm ringTerm(Real k, Real Dk, Real invD, Real P, Real PA, Real PD, Real PAA, Real PAD,
                                         Real PDD) {
  // F = P D^-k: F_D = (P_D - k P / D) D^-k, F_DD = (P_DD - 2k P_D / D + k (k + 1) P / D^2) D^-k
  return {P * Dk,
          PA * Dk,
          (PD - k * P * invD) * Dk,
          PAA * Dk,
          (PAD - k * PA * invD) * Dk,
          (PDD - 2.0 * k * PD * invD + k * (k + 1.0) * P * invD * invD) * Dk};
}
}  // namespace detail

/// Axisymmetric: x = (rho, z); psi = the ring average of phi (closed form
/// above; the derivatives by the chain rule through A = (p + q)/2, D = p q).
KOKKOS_INLINE_FUNCTION void pairLawAxisymmetric(const InversePowerPair& c, const Real* x1, const Real* x2, Real& psi,
                                                Real* g, Real (*H11)[3], Real (*H12)[3]) {
  const Real dr = x1[0] - x2[0], sr = x1[0] + x2[0], dz = x1[1] - x2[1];
  const Real p = dr * dr + dz * dz, q = sr * sr + dz * dz;
  const Real A = 0.5 * (p + q), D = p * q, A2 = A * A, invD = 1.0 / D, root = std::sqrt(invD);
  const Real D2 = invD * invD, D55 = D2 * D2 * invD * root, D25 = D2 * root;
  // 8 x repulsive polynomial 63 A^5 - 70 A^3 D + 15 A D^2; 2 x attractive 3 A^2 - D
  const detail::RingTerm R = detail::ringTerm(
      5.5, D55, invD, A * (63.0 * A2 * A2 - 70.0 * A2 * D + 15.0 * D * D) / 8.0,
      (315.0 * A2 * A2 - 210.0 * A2 * D + 15.0 * D * D) / 8.0, (-70.0 * A2 * A + 30.0 * A * D) / 8.0,
      (1260.0 * A2 * A - 420.0 * A * D) / 8.0, (-210.0 * A2 + 30.0 * D) / 8.0, 30.0 * A / 8.0);
  const detail::RingTerm T = detail::ringTerm(2.5, D25, invD, 0.5 * (3.0 * A2 - D), 3.0 * A, -0.5, 3.0, 0.0, 0.0);
  const Real FA = c.c12 * R.A - c.c6 * T.A, FD = c.c12 * R.D - c.c6 * T.D;
  psi = c.c12 * R.v - c.c6 * T.v;
  const Real Pp = 0.5 * FA + q * FD, Pq = 0.5 * FA + p * FD;
  // gradients of p and q in (rho1, z1, rho2, z2); their Hessians are constant
  const Real gp[4] = {2.0 * dr, 2.0 * dz, -2.0 * dr, -2.0 * dz};
  const Real gq[4] = {2.0 * sr, 2.0 * dz, 2.0 * sr, -2.0 * dz};
  for (int i = 0; i < 2; ++i) g[i] = Pp * gp[i] + Pq * gq[i];
  if (H11 == nullptr) return;
  const Real FAA = c.c12 * R.AA - c.c6 * T.AA, FAD = c.c12 * R.AD - c.c6 * T.AD, FDD = c.c12 * R.DD - c.c6 * T.DD;
  const Real Ppp = 0.25 * FAA + q * FAD + q * q * FDD;
  const Real Ppq = 0.25 * FAA + 0.5 * (p + q) * FAD + p * q * FDD + FD;
  const Real Pqq = 0.25 * FAA + p * FAD + p * p * FDD;
  // d2p: +2 on (rho1, rho1), (z1, z1), -2 on (rho1, rho2), (z1, z2); d2q: +2 on (rho1, rho1),
  // (z1, z1), (rho1, rho2), -2 on (z1, z2)
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 4; ++j) {
      Real h = Ppp * gp[i] * gp[j] + Ppq * (gp[i] * gq[j] + gq[i] * gp[j]) + Pqq * gq[i] * gq[j];
      if (j == i) h += 2.0 * (Pp + Pq);
      if (j == i + 2) h += i == 0 ? 2.0 * (Pq - Pp) : -2.0 * (Pp + Pq);
      if (j < 2)
        H11[i][j] = h;
      else
        H12[i][j - 2] = h;
    }
}

}  // namespace cgcm::interaction
