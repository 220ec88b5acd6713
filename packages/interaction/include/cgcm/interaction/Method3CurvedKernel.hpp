#pragma once
// Method 3 surface kernel (eq. 21, doc/theory.md#method-3) in 2D on curved
// segments: the facets of quadratic cells (Line3: end a, end b, mid node),
// and straight ones (Line2) facing them, with the exact tangent.
//
// Unit of work: quadrature point xi of segment e (NE = 2 or 3 nodes) of body
// k and one target segment s (NS nodes) of body l, with the segment n of l
// that shares the end of s onto which x projects (the blend's neighbour; NS
// nodes as well). With the coordinates
//     z = [x_1 .. x_NE of e | y_1 .. y_NS of s | v_1 .. v_NS of n]
// (2 (NE + 2 NS) entries) the point is x = sum_a N_a(xi) x_a on its curved
// segment, t = dx/dxi, n_e = (t_y, -t_x)/|t| its outward normal, and the
// closest point of s is y(eta*) with eta* the minimiser of |x - y(eta)|
// over [0, 1] (a vertex of s at eta* = 0 or 1: region 1, 2). On a Line3 the
// stationarity condition (y(eta) - x) . y'(eta) = 0 is a cubic in eta: every
// root in [0, 1] is found (monotone brackets between the roots of its
// derivative) and the closest candidate, ends included, is taken, so the
// projection is global on the segment and needs no starting guess. Then, as
// on straight segments,
//     f_a = N_a(xi) T(r) rbar (rbar . n_e) da,  da = |t| w (2 pi x_0 |t| w),
// or the reference area element dA instead of da. The blend distance
// (SurfaceInteraction.hpp) is rho = r + delta P, P = (o_s/delta)^2
// exp(-(o_n/delta)^2) in a vertex region, with the overshoot o of x beyond
// an end measured along the segment's tangent at that end,
//     o = max(0, +-(x - v) . y'(end)/|y'(end)|),
// which is the linear segments' overshoot when s is straight.
//
// Tangent by forward automatic differentiation (Sacado::Fad::SFad) of the
// same code with the region held fixed; inside s the closest point enters
// through one Newton step eta = eta* - g(eta*)/g'(eta*) taken in the AD
// type (g = 0 in value), which is the implicit function theorem's
// d eta = -g_z dz / g_eta exactly. Unit tests compare it with central
// differences.
#include <Sacado.hpp>

#include <cmath>

#include "cgcm/core/Formulation.hpp"
#include "cgcm/core/Types.hpp"
#include "cgcm/interaction/Method3Kernel.hpp"
#include "cgcm/interaction/Method3Kernel3D.hpp"

namespace cgcm::interaction {

/// Shape functions of a segment with N = 2 or 3 nodes on [0, 1] (node 0 at
/// 0, node 1 at 1, node 2 at 1/2) and their first derivatives.
template <int N>
inline void lineShape(Real xi, Real Nv[N], Real dN[N]) {
  if constexpr (N == 2) {
    Nv[0] = 1.0 - xi, Nv[1] = xi;
    dN[0] = -1.0, dN[1] = 1.0;
  } else {
    static_assert(N == 3, "segments have 2 or 3 nodes");
    Nv[0] = (1.0 - xi) * (1.0 - 2.0 * xi), Nv[1] = xi * (2.0 * xi - 1.0), Nv[2] = 4.0 * xi * (1.0 - xi);
    dN[0] = 4.0 * xi - 3.0, dN[1] = 4.0 * xi - 1.0, dN[2] = 4.0 - 8.0 * xi;
  }
}

/// Largest distance of the Line3 through y (end a, end b, mid) from its two
/// chords a-mid and mid-b: |y_a + y_b - 2 y_mid| / 8 (the curve is y_c0 +
/// c1 eta + c2 eta^2 with |c2| = 2 |y_a + y_b - 2 y_mid|, and the chord
/// interpolation error on a half is |c2| eta (1/2 - eta) <= |c2|/16).
inline Real line3ChordDeviation(const Real* ya, const Real* yb, const Real* ymid) {
  return std::hypot(ya[0] + yb[0] - 2.0 * ymid[0], ya[1] + yb[1] - 2.0 * ymid[1]) / 8.0;
}

/// Closest point of the segment y (NS = 2 or 3 nodes, D = 2 or 3 coordinates
/// each; straight segments in 2D only) to x: returns the squared distance; eta
/// in [0, 1] the local coordinate, p the point, region 0 inside, 1 at end a
/// (eta = 0), 2 at end b (eta = 1).
template <int NS, int D = 2>
inline Real projectOntoCurve(const Real* x, const Real* y, Real& eta, Real* p, int& region) {
  if constexpr (NS == 2) {
    static_assert(D == 2, "straight segments are projected in 2D");
    return projectOntoSegment(x, y, y + 2, eta, p, region);
  } else {
    // y(eta) = c0 + c1 eta + c2 eta^2; g(eta) = (y - x) . y' = a0 + a1 eta + a2 eta^2 + a3 eta^3
    Real c1[D], c2[D], q[D];
    for (int i = 0; i < D; ++i) {
      c1[i] = -3.0 * y[i] - y[D + i] + 4.0 * y[2 * D + i];
      c2[i] = 2.0 * y[i] + 2.0 * y[D + i] - 4.0 * y[2 * D + i];
      q[i] = y[i] - x[i];
    }
    auto dot = [](const Real* u, const Real* v) {
      Real s = 0.0;
      for (int i = 0; i < D; ++i) s += u[i] * v[i];
      return s;
    };
    const Real a3 = 2.0 * dot(c2, c2), a2 = 3.0 * dot(c1, c2), a1 = dot(c1, c1) + 2.0 * dot(q, c2), a0 = dot(q, c1);
    auto g = [&](Real e) { return a0 + e * (a1 + e * (a2 + e * a3)); };
    auto dg = [&](Real e) { return a1 + e * (2.0 * a2 + e * 3.0 * a3); };
    auto dist2 = [&](Real e) {
      Real s = 0.0;
      for (int i = 0; i < D; ++i) {
        const Real d = q[i] + e * (c1[i] + e * c2[i]);
        s += d * d;
      }
      return s;
    };
    // candidates: both ends and every minimum of the distance inside (g from - to +)
    Real best = dist2(0.0);
    eta = 0.0;
    region = 1;
    if (const Real d = dist2(1.0); d < best) best = d, eta = 1.0, region = 2;
    Real cut[4] = {0.0, 0.0, 0.0, 1.0};  // [0, 1] split at the roots of g' inside
    int nc = 1;
    {
      const Real A = 3.0 * a3, B = 2.0 * a2, C = a1;
      if (A > 0.0) {
        const Real disc = B * B - 4.0 * A * C;
        if (disc > 0.0) {
          const Real s = std::sqrt(disc), r0 = (-B - s) / (2.0 * A), r1 = (-B + s) / (2.0 * A);
          if (r0 > 0.0 && r0 < 1.0) cut[nc++] = r0;
          if (r1 > 0.0 && r1 < 1.0) cut[nc++] = r1;
        }
      } else if (B != 0.0) {
        const Real r0 = -C / B;
        if (r0 > 0.0 && r0 < 1.0) cut[nc++] = r0;
      }
      cut[nc++] = 1.0;
    }
    for (int k = 0; k + 1 < nc; ++k) {
      Real lo = cut[k], hi = cut[k + 1];
      if (!(g(lo) < 0.0 && g(hi) > 0.0)) continue;  // a minimum has g rising through 0
      Real e = 0.5 * (lo + hi);
      for (int it = 0; it < 100; ++it) {  // Newton safeguarded by the bracket
        const Real ge = g(e);
        if (ge == 0.0) break;
        (ge < 0.0 ? lo : hi) = e;
        const Real step = ge / dg(e);
        Real next = e - step;
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::abs(next - e) <= 1e-16 * (1.0 + std::abs(e)) || hi - lo <= 4e-16) {
          e = next;
          break;
        }
        e = next;
      }
      if (const Real d = dist2(e); d < best) best = d, eta = e, region = 0;
    }
    for (int i = 0; i < D; ++i) p[i] = x[i] + q[i] + eta * (c1[i] + eta * c2[i]);
    return best;
  }
}

namespace detail {

/// Point and derivative of the segment y (N nodes) at eta, in S.
template <int N, class S, class E>
inline void curvePoint(const S* y, const E& eta, S p[2], S dp[2]) {
  if constexpr (N == 2) {
    for (int i = 0; i < 2; ++i) {
      dp[i] = y[2 + i] - y[i];
      p[i] = y[i] + eta * dp[i];
    }
  } else {
    for (int i = 0; i < 2; ++i) {
      const S c1 = -3.0 * y[i] - y[2 + i] + 4.0 * y[4 + i], c2 = 2.0 * y[i] + 2.0 * y[2 + i] - 4.0 * y[4 + i];
      p[i] = y[i] + eta * (c1 + eta * c2);
      dp[i] = c1 + 2.0 * eta * c2;
    }
  }
}

/// The closest point of the segment y (N nodes) to x in the region found by
/// projectOntoCurve (eta its value there).
template <int N, class S>
inline void footOnCurve(const S x[2], const S* y, Real eta, int region, S p[2]) {
  if (region == 1 || region == 2) {
    const int v = region - 1;
    p[0] = y[2 * v], p[1] = y[2 * v + 1];
    return;
  }
  S e(eta);
  if constexpr (N == 3) {  // one Newton step on g = (y - x) . y' in S: the implicit derivative of eta*
    S yp[2], dyp[2];
    curvePoint<3>(y, e, yp, dyp);
    S c2[2];
    for (int i = 0; i < 2; ++i) c2[i] = 2.0 * y[i] + 2.0 * y[2 + i] - 4.0 * y[4 + i];
    const S gv = (yp[0] - x[0]) * dyp[0] + (yp[1] - x[1]) * dyp[1];
    const S dg = dyp[0] * dyp[0] + dyp[1] * dyp[1] + 2.0 * ((yp[0] - x[0]) * c2[0] + (yp[1] - x[1]) * c2[1]);
    e = e - gv / dg;
  } else {  // the straight segment's foot, eta = (x - y_a) . d / (d . d)
    const S d0 = y[2] - y[0], d1 = y[3] - y[1];
    e = ((x[0] - y[0]) * d0 + (x[1] - y[1]) * d1) / (d0 * d0 + d1 * d1);
  }
  S dp[2];
  curvePoint<N>(y, e, p, dp);
}

/// Overshoot of x beyond end `end` (0: a, 1: b) of the segment y along its tangent there.
template <int N, class S>
inline S overshootAlongEnd(const S x[2], const S* y, int end) {
  S p[2], t[2];
  curvePoint<N>(y, Real(end), p, t);
  using std::sqrt;
  const S o = (end == 0 ? -1.0 : 1.0) * ((x[0] - p[0]) * t[0] + (x[1] - p[1]) * t[1]) / sqrt(t[0] * t[0] + t[1] * t[1]);
  return o > 0.0 ? o : S(0.0);
}

/// f (2 NE entries) and the blend distance rho of the pair in z (header) for
/// a fixed region; neighbourEnd: the end of n at the shared vertex, or -1 (no
/// neighbour, or the foot inside s: P = 0). delta <= 0: rho = r.
template <Formulation Form, int NE, int NS, class S, class Law>
inline void curvedPairResidual(const S* z, Real xi, Real weight, const Law& law, Real eta, int region,
                               int neighbourEnd, Real delta, const Real* referenceArea, S* f, S& rho, PairState& st) {
  constexpr Real twoPi = 2.0 * kPi;
  Real Nv[NE], dN[NE];
  lineShape<NE>(xi, Nv, dN);
  S x[2] = {0.0, 0.0}, t[2] = {0.0, 0.0};
  for (int a = 0; a < NE; ++a)
    for (int i = 0; i < 2; ++i) {
      x[i] += Nv[a] * z[2 * a + i];
      t[i] += dN[a] * z[2 * a + i];
    }
  using std::sqrt;
  const S L = sqrt(t[0] * t[0] + t[1] * t[1]);
  const S* y = z + 2 * NE;
  S p[2];
  footOnCurve<NS>(x, y, eta, region, p);
  const S d[2] = {x[0] - p[0], x[1] - p[1]};
  const S r = sqrt(d[0] * d[0] + d[1] * d[1]);
  Real dT;
  const S T = tractionOf(law, r, dT);
  // rbar (rbar . n) = d (d . (t_y, -t_x)) / (L r^2)
  const S dn = d[0] * t[1] - d[1] * t[0];
  const S da = referenceArea != nullptr ? S(*referenceArea)
               : (Form == Formulation::Axisymmetric) ? S(twoPi * x[0] * L * weight)
                                                      : S(L * weight);
  const S s = T * dn * da / (L * r * r);
  for (int a = 0; a < NE; ++a)
    for (int i = 0; i < 2; ++i) f[2 * a + i] = Nv[a] * s * d[i];
  st.distance = scalarValue(r);
  st.traction = scalarValue(T);
  st.cosAlpha = scalarValue(dn / (L * r));
  st.region = region;
  rho = r;
  if (delta > 0.0 && region != 0 && neighbourEnd >= 0) {
    using std::exp;
    const S os = overshootAlongEnd<NS>(x, y, region - 1) / delta;
    const S on = overshootAlongEnd<NS>(x, y + 2 * NS, neighbourEnd) / delta;
    rho = rho + delta * os * os * exp(-on * on);
  }
}

}  // namespace detail

/// The closest point of a target segment: its local coordinate and region (projectOntoCurve).
struct CurveFoot {
  Real eta = 0.0;
  int region = 0;
};

/// The point of segment e at xi (z as in the header) projected onto the target s (NS nodes).
template <int NE, int NS>
CurveFoot footOnTarget(const Real* z, Real xi) {
  Real Nv[NE], dN[NE], x[2] = {0.0, 0.0}, p[2];
  lineShape<NE>(xi, Nv, dN);
  for (int a = 0; a < NE; ++a)
    for (int i = 0; i < 2; ++i) x[i] += Nv[a] * z[2 * a + i];
  CurveFoot foot;
  projectOntoCurve<NS>(x, z + 2 * NE, foot.eta, p, foot.region);
  return foot;
}

/// Evaluates one pair on curved (or straight) segments, z as in the header,
/// at the target's closest point `foot` (footOnTarget; the caller that needs
/// the region first, to pick the neighbour, projects once). The neighbour's
/// slot is read only when neighbourEnd >= 0 and the projection is a vertex
/// of s; without it, WithNeighbour = false, z ends after s and neighbourEnd
/// must be -1. f: 2 NE entries; rho: the blend distance (r without
/// smoothing, delta <= 0). With K (may be null), K[i * nz + j] = df_i/dz_j
/// and Jrho[j] = drho/dz_j, nz = 2 (NE + 2 NS), 2 (NE + NS) without the
/// neighbour. The caller checks state.distance > 0.
template <Formulation Form, int NE, int NS, bool WithNeighbour = true, class Law>
PairState method3CurvedPair(const Real* z, Real xi, Real weight, const Law& law, const CurveFoot& foot,
                            int neighbourEnd, Real delta, const Real* referenceArea, Real* f, Real& rho, Real* K,
                            Real* Jrho) {
  constexpr int nz = 2 * (NE + (WithNeighbour ? 2 : 1) * NS), nf = 2 * NE;
  if (!WithNeighbour) neighbourEnd = -1;
  PairState st;
  if (K == nullptr) {
    detail::curvedPairResidual<Form, NE, NS>(z, xi, weight, law, foot.eta, foot.region, neighbourEnd, delta,
                                             referenceArea, f, rho, st);
    return st;
  }
  using Fad = Sacado::Fad::SFad<Real, nz>;
  Fad zf[nz], ff[nf], rf;
  for (int j = 0; j < nz; ++j) zf[j] = Fad(nz, j, z[j]);
  detail::curvedPairResidual<Form, NE, NS>(zf, xi, weight, law, foot.eta, foot.region, neighbourEnd, delta,
                                           referenceArea, ff, rf, st);
  for (int i = 0; i < nf; ++i) {
    f[i] = ff[i].val();
    for (int j = 0; j < nz; ++j) K[i * nz + j] = ff[i].dx(j);
  }
  rho = rf.val();
  if (Jrho != nullptr)
    for (int j = 0; j < nz; ++j) Jrho[j] = rf.dx(j);
  return st;
}

/// The same, projecting first.
template <Formulation Form, int NE, int NS, bool WithNeighbour = true, class Law>
PairState method3CurvedPair(const Real* z, Real xi, Real weight, const Law& law, int neighbourEnd, Real delta,
                            const Real* referenceArea, Real* f, Real& rho, Real* K, Real* Jrho) {
  return method3CurvedPair<Form, NE, NS, WithNeighbour>(z, xi, weight, law, footOnTarget<NE, NS>(z, xi),
                                                        neighbourEnd, delta, referenceArea, f, rho, K, Jrho);
}

}  // namespace cgcm::interaction
