#pragma once
// Method 3 surface kernel (eq. 21, doc/theory.md#method-3) for 2D segments, plane strain
// and axisymmetric, with its exact tangent.
//
// Unit of work: one interaction pair = (segment e of body k, quadrature
// point q of e, neighbour segment s of body l). With the 8 coordinates
//     z = [x_a(2), x_b(2) of e | y_a(2), y_b(2) of s]
// the quadrature point is x = (1 - xi) x_a + xi x_b, its projection x_P on s
// (clamped: a vertex of s in the vertex regions), r = |x - x_P|,
// rbar = (x - x_P)/r, n the outward normal of e, n = (t_y, -t_x)/|t| with
// t = x_b - x_a, and
//     f_a = N_a(xi) T(r) rbar (rbar . n) da,   a = 0, 1 (nodes of e),
//     da = |t| w              (plane strain, per unit thickness),
//     da = 2 pi x_0 |t| w     (axisymmetric, x_0 = radial coordinate of x),
// with w the Gauss weight on [0, 1] and T(r) = beta_k beta_l Phi(r)/beta.
// With the reference surface density (SurfaceDensity::ReferenceArea) the
// caller passes the point's reference area element dA (|T| w, or 2 pi X_0 |T| w,
// of the undeformed segment) and da is replaced by that constant: the layer's
// particles beta0 dA are counted once however the surface stretches.
// f is the contribution to the internal side of f_int + f_C - f_ext = 0;
// the force applied to body k is -f.
//
// The tangent K = d f / d z (4 x 8) is the exact derivative of this
// residual as implemented: projection with clamping, rbar, the factor
// rbar . n and da (including x_0 in the axisymmetric case; none with dA).
#include <Kokkos_Macros.hpp>
#include <cmath>

#include "cgcm/core/Formulation.hpp"
#include "cgcm/core/Types.hpp"
#include "cgcm/interaction/ClosestPointSearch.hpp"

namespace cgcm::interaction {

/// Diagnostics of one pair evaluation.
struct PairState {
  Real distance = 0.0;  ///< r
  Real traction = 0.0;  ///< T(r)
  Real cosAlpha = 0.0;  ///< rbar . n
  int region = 0;       ///< 0: projection inside s; 1, 2: vertex a, b of s
};

/// Distance o >= 0 by which the unclamped projection of x onto the line of
/// the segment a -> b lies beyond the segment's end `end` (0: a, 1: b); 0
/// when it lies on the segment's side of that end. With g (may be null) also
/// do/d(x, a, b), 6 entries. o is continuous, o^2 continuously differentiable.
KOKKOS_INLINE_FUNCTION Real overshootBeyondEnd(const Real x[2], const Real a[2], const Real b[2], int end,
                                               Real g[6]) {
  const Real d0 = b[0] - a[0], d1 = b[1] - a[1];
  const Real L = std::sqrt(d0 * d0 + d1 * d1);
  const Real e[2] = {d0 / L, d1 / L}, p[2] = {x[0] - a[0], x[1] - a[1]};
  const Real s = p[0] * e[0] + p[1] * e[1];  // signed distance of the foot from a
  const Real o = end == 0 ? -s : s - L;
  if (g != nullptr) {
    for (int i = 0; i < 6; ++i) g[i] = 0.0;
    if (o > 0.0) {
      // end a: o = -(x - a).e, end b: o = (x - b).e, with de = P (db - da)/L,
      // P = I - e e^T, and (x - a) P = (x - b) P = p_perp
      const Real sign = end == 0 ? -1.0 : 1.0;
      const Real q[2] = {(p[0] - s * e[0]) / L, (p[1] - s * e[1]) / L};  // p_perp / L
      for (int i = 0; i < 2; ++i) {
        g[i] = sign * e[i];
        g[2 + i] = (end == 0 ? e[i] : 0.0) - sign * q[i];
        g[4 + i] = (end == 1 ? -e[i] : 0.0) + sign * q[i];
      }
    }
  }
  return o > 0.0 ? o : 0.0;
}

/// Evaluates one pair. `law(r, T, dT)` gives the traction T(r) and dT/dr.
/// f receives the 4 residual entries [a_x, a_y, b_x, b_y] of segment e's
/// nodes; K (may be null) the 4 x 8 derivative with respect to z; Jr (may be
/// null, filled only together with K) the gradient dr/dz of the distance.
/// referenceArea (may be null): the point's reference area element dA, used
/// instead of the current da (see the header). The caller checks
/// state.distance > 0 (r = 0: the point lies on the other surface).
template <Formulation Form, class Law>
KOKKOS_INLINE_FUNCTION PairState method3Pair(const Real z[8], Real xi, Real weight, const Law& law, Real f[4],
                                             Real (*K)[8], Real* Jr = nullptr, const Real* referenceArea = nullptr) {
  constexpr Real twoPi = 2.0 * kPi;
  PairState st;
  const Real N0 = 1.0 - xi, N1 = xi;
  const Real x[2] = {N0 * z[0] + N1 * z[2], N0 * z[1] + N1 * z[3]};
  const Real t[2] = {z[2] - z[0], z[3] - z[1]};
  const Real L = std::sqrt(t[0] * t[0] + t[1] * t[1]);
  const Real n[2] = {t[1] / L, -t[0] / L};
  const Real ds = L * weight;
  const Real da = referenceArea != nullptr               ? *referenceArea
                  : (Form == Formulation::Axisymmetric) ? twoPi * x[0] * ds
                                                         : ds;

  Real lam, xp[2];
  const Real d2 = projectOntoSegment(x, z + 4, z + 6, lam, xp, st.region);
  const Real r = std::sqrt(d2);
  st.distance = r;
  const Real rb[2] = {(x[0] - xp[0]) / r, (x[1] - xp[1]) / r};
  const Real c = rb[0] * n[0] + rb[1] * n[1];
  Real T, dT;
  law(r, T, dT);
  st.traction = T;
  st.cosAlpha = c;
  const Real s = T * c * da;
  f[0] = N0 * s * rb[0];
  f[1] = N0 * s * rb[1];
  f[2] = N1 * s * rb[0];
  f[3] = N1 * s * rb[1];
  if (K == nullptr) return st;

  // Jacobians (2 x 8) of the intermediate vectors with respect to z.
  Real Jx[2][8] = {}, Jt[2][8] = {}, JxP[2][8] = {};
  for (int i = 0; i < 2; ++i) {
    Jx[i][i] = N0;
    Jx[i][2 + i] = N1;
    Jt[i][i] = -1.0;
    Jt[i][2 + i] = 1.0;
  }
  if (st.region == 1) {
    JxP[0][4] = 1.0;
    JxP[1][5] = 1.0;
  } else if (st.region == 2) {
    JxP[0][6] = 1.0;
    JxP[1][7] = 1.0;
  } else {
    // x_P = y_a + lam d, lam = (x - y_a).d / (d.d):
    // dlam = [d.(dx - dy_a) + (p - 2 lam d).dd] / (d.d), p = x - y_a, dd = dy_b - dy_a
    const Real d[2] = {z[6] - z[4], z[7] - z[5]};
    const Real dd = d[0] * d[0] + d[1] * d[1];
    const Real q[2] = {x[0] - z[4] - 2.0 * lam * d[0], x[1] - z[5] - 2.0 * lam * d[1]};
    Real Jlam[8];
    for (int j = 0; j < 4; ++j) Jlam[j] = (d[0] * Jx[0][j] + d[1] * Jx[1][j]) / dd;
    for (int i = 0; i < 2; ++i) {
      Jlam[4 + i] = (-d[i] - q[i]) / dd;
      Jlam[6 + i] = q[i] / dd;
    }
    for (int i = 0; i < 2; ++i) {
      for (int j = 0; j < 8; ++j) JxP[i][j] = d[i] * Jlam[j];
      JxP[i][4 + i] += 1.0 - lam;
      JxP[i][6 + i] += lam;
    }
  }
  // r, rbar
  Real JrLocal[8], Jrb[2][8];
  if (Jr == nullptr) Jr = JrLocal;
  for (int j = 0; j < 8; ++j) {
    const Real g0 = Jx[0][j] - JxP[0][j], g1 = Jx[1][j] - JxP[1][j];
    Jr[j] = rb[0] * g0 + rb[1] * g1;
    Jrb[0][j] = (g0 - rb[0] * Jr[j]) / r;
    Jrb[1][j] = (g1 - rb[1] * Jr[j]) / r;
  }
  // L, n = (t_1, -t_0)/L, da
  Real Jc[8], Jda[8];
  for (int j = 0; j < 8; ++j) {
    const Real JL = (t[0] * Jt[0][j] + t[1] * Jt[1][j]) / L;
    const Real Jn0 = (Jt[1][j] - n[0] * JL) / L;
    const Real Jn1 = (-Jt[0][j] - n[1] * JL) / L;
    Jc[j] = n[0] * Jrb[0][j] + n[1] * Jrb[1][j] + rb[0] * Jn0 + rb[1] * Jn1;
    const Real Jds = weight * JL;
    Jda[j] = referenceArea != nullptr               ? 0.0
             : (Form == Formulation::Axisymmetric) ? twoPi * (Jx[0][j] * ds + x[0] * Jds)
                                                    : Jds;
  }
  // F = s rbar with s = T c da
  for (int j = 0; j < 8; ++j) {
    const Real Js = dT * Jr[j] * c * da + T * Jc[j] * da + T * c * Jda[j];
    const Real JF0 = Js * rb[0] + s * Jrb[0][j];
    const Real JF1 = Js * rb[1] + s * Jrb[1][j];
    K[0][j] = N0 * JF0;
    K[1][j] = N0 * JF1;
    K[2][j] = N1 * JF0;
    K[3][j] = N1 * JF1;
  }
  return st;
}

/// The same residual written for a generic scalar type S (double or a
/// forward-AD type such as Sacado::Fad::SFad<double, 8>): a reference for
/// checking the hand-derived tangent. `traction(r)` returns T(r) as an S;
/// referenceArea as in method3Pair.
template <Formulation Form, class S, class TractionFn>
void method3PairResidualGeneric(const S z[8], Real xi, Real weight, const TractionFn& traction, S f[4],
                                const Real* referenceArea = nullptr) {
  using std::sqrt;
  constexpr Real twoPi = 2.0 * kPi;
  const Real N0 = 1.0 - xi, N1 = xi;
  const S x0 = N0 * z[0] + N1 * z[2], x1 = N0 * z[1] + N1 * z[3];
  const S t0 = z[2] - z[0], t1 = z[3] - z[1];
  const S L = sqrt(t0 * t0 + t1 * t1);
  const S n0 = t1 / L, n1 = -t0 / L;
  const S ds = L * weight;
  const S da = referenceArea != nullptr ? S(*referenceArea) : (Form == Formulation::Axisymmetric) ? S(twoPi * x0 * ds) : ds;
  const S d0 = z[6] - z[4], d1 = z[7] - z[5];
  const S dd = d0 * d0 + d1 * d1;
  const S lam = ((x0 - z[4]) * d0 + (x1 - z[5]) * d1) / dd;
  S p0, p1;
  if (!(lam > 0.0)) {
    p0 = z[4];
    p1 = z[5];
  } else if (lam >= 1.0) {
    p0 = z[6];
    p1 = z[7];
  } else {
    p0 = z[4] + lam * d0;
    p1 = z[5] + lam * d1;
  }
  const S g0 = x0 - p0, g1 = x1 - p1;
  const S r = sqrt(g0 * g0 + g1 * g1);
  const S rb0 = g0 / r, rb1 = g1 / r;
  const S s = traction(r) * (rb0 * n0 + rb1 * n1) * da;
  f[0] = N0 * s * rb0;
  f[1] = N0 * s * rb1;
  f[2] = N1 * s * rb0;
  f[3] = N1 * s * rb1;
}

}  // namespace cgcm::interaction
