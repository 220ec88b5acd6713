#pragma once
// Method 3 surface kernel (eq. 21, doc/theory.md#method-3) in 3D, with its exact tangent.
//
// Unit of work: one interaction pair = (facet e of body k with NF = 3 or 4
// nodes, quadrature point q of e, triangle s of the surface of body l). With
// the coordinates
//     z = [x_1 .. x_NF of e | y_1, y_2, y_3 of s]     (3 NF + 9 entries)
// the quadrature point is x = sum_a N_a x_a, its projection x_P on s (the
// closest point of the triangle: inside the face, on an edge or at a vertex),
// r = |x - x_P|, rbar = (x - x_P)/r, n the outward unit normal of e at q,
// n = g1 x g2 / |g1 x g2| with g_i = dx/dxi_i, and
//     f_a = N_a T(r) rbar (rbar . n) da,    da = |g1 x g2| w,
// T(r) = beta_k beta_l Phi(r)/beta the half-space traction (the same law as
// in 2D). With the reference surface density the caller passes the point's
// reference area element dA = |G1 x G2| w of the undeformed facet, which
// replaces da (as in 2D). f is the contribution to the internal side of
// f_int + f_C - f_ext; the force applied to body k is -f.
//
// The target surface is piecewise flat: a quad4 facet of l enters the search
// as two triangles, so a projection never needs a Newton solve on a bilinear
// patch. The source facet keeps its bilinear geometry (normal and area
// element of the element face).
//
// Tangent: K = df/dz (3 NF x (3 NF + 9)) by forward automatic
// differentiation (Sacado::Fad::SFad) of the same residual code, with the
// projection region held fixed (the region is where the residual is smooth;
// across region boundaries the projection, hence f, is continuous). It is
// exact to round-off, and the unit tests compare it with central differences.
#include <Sacado.hpp>

#include <cmath>

#include "cgcm/core/Types.hpp"
#include "cgcm/interaction/ClosestPointSearch.hpp"
#include "cgcm/interaction/Method3Kernel.hpp"
#include "cgcm/interaction/Quadrature.hpp"

namespace cgcm::interaction {

namespace detail {

template <class S>
inline S dot3(const S* a, const S* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

template <class S>
inline void cross3(const S* a, const S* b, S* c) {
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

/// Foot of x on triangle (a, b, c) in the region found by projectOntoTriangle
/// (0 face, 1..3 vertex a, b, c, 4..6 edge ab, bc, ca).
template <class S>
inline void footInRegion(const S* x, const S* a, const S* b, const S* c, int region, S* p) {
  auto onEdge = [&](const S* e0, const S* e1) {
    S d[3], q[3];
    for (int i = 0; i < 3; ++i) d[i] = e1[i] - e0[i], q[i] = x[i] - e0[i];
    const S lam = dot3(q, d) / dot3(d, d);
    for (int i = 0; i < 3; ++i) p[i] = e0[i] + lam * d[i];
  };
  switch (region) {
    case 1: for (int i = 0; i < 3; ++i) p[i] = a[i]; return;
    case 2: for (int i = 0; i < 3; ++i) p[i] = b[i]; return;
    case 3: for (int i = 0; i < 3; ++i) p[i] = c[i]; return;
    case 4: onEdge(a, b); return;
    case 5: onEdge(b, c); return;
    case 6: onEdge(c, a); return;
    default: {
      S ab[3], ac[3], m[3], q[3];
      for (int i = 0; i < 3; ++i) ab[i] = b[i] - a[i], ac[i] = c[i] - a[i], q[i] = x[i] - a[i];
      cross3(ab, ac, m);
      const S h = dot3(q, m) / dot3(m, m);
      for (int i = 0; i < 3; ++i) p[i] = x[i] - h * m[i];
    }
  }
}

inline Real scalarValue(Real v) { return v; }
template <class S>
inline Real scalarValue(const S& v) {
  return v.val();
}

/// T(r) as an S: the law's value, and for an AD type its chain rule.
template <class Law>
inline Real tractionOf(const Law& law, Real r, Real& dT) {
  Real T;
  law(r, T, dT);
  return T;
}
template <class Law, class S>
inline S tractionOf(const Law& law, const S& r, Real& dT) {
  Real T;
  law(r.val(), T, dT);
  S out(r);
  out.val() = T;
  for (int i = 0; i < r.size(); ++i) out.fastAccessDx(i) = dT * r.fastAccessDx(i);
  return out;
}

/// The point x of quadrature point q on the source facet (the first NF nodes of z), its area
/// normal m = g1 x g2 and |m|.
template <int NF, class S>
inline void sourcePoint(const S* z, const FacetPoint& q, S x[3], S m[3], S& jac) {
  S g[2][3] = {{0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}};
  for (int i = 0; i < 3; ++i) x[i] = S(0.0);
  for (int a = 0; a < NF; ++a)
    for (int i = 0; i < 3; ++i) {
      x[i] += q.N[a] * z[3 * a + i];
      g[0][i] += q.dN[0][a] * z[3 * a + i];
      g[1][i] += q.dN[1][a] * z[3 * a + i];
    }
  cross3(g[0], g[1], m);
  using std::sqrt;
  jac = sqrt(dot3(m, m));
}

/// f_a = N_a T(r) rbar (rbar . n) da (3 NF entries) of the point with d = x - p, area normal m and
/// |m| = jac (sourcePoint); the state's distance, traction and cos(alpha). Returns r.
template <int NF, class S, class Law>
inline S sourceForce(const S* d, const S* m, const S& jac, const FacetPoint& q, const Law& law,
                     const Real* referenceArea, S* f, PairState& st) {
  using std::sqrt;
  const S r = sqrt(dot3(d, d));
  Real dT;
  const S T = tractionOf(law, r, dT);
  // T rbar (rbar . n) da = T d (d . m) w / r^2; with dA: T d (d . m) dA / (|m| r^2)
  const S s = referenceArea != nullptr ? S(T * dot3(d, m) * *referenceArea / (jac * r * r))
                                       : S(T * dot3(d, m) * q.weight / (r * r));
  for (int a = 0; a < NF; ++a)
    for (int i = 0; i < 3; ++i) f[3 * a + i] = q.N[a] * s * d[i];
  st.distance = scalarValue(r);
  st.traction = scalarValue(T);
  st.cosAlpha = scalarValue(dot3(d, m) / (r * jac));
  return r;
}

/// The residual f (3 NF entries) for a fixed projection region; also the
/// state's distance, traction and cos(alpha). referenceArea: as in method3Pair3D.
template <int NF, class S, class Law>
inline void method3Residual3D(const S* z, const FacetPoint& q, int region, const Law& law, S* f, PairState& st,
                              const Real* referenceArea) {
  S x[3], m[3], jac;
  sourcePoint<NF>(z, q, x, m, jac);
  const S* y = z + 3 * NF;
  S p[3];
  footInRegion(x, y, y + 3, y + 6, region, p);
  S d[3];
  for (int i = 0; i < 3; ++i) d[i] = x[i] - p[i];
  sourceForce<NF>(d, m, jac, q, law, referenceArea, f, st);
  st.region = region;
}

/// The blend distance of the projection of x onto triangle y (SurfaceInteraction.hpp):
/// rho = r + o^2/delta, o the distance from the foot on the triangle's plane
/// to the projection (0 inside the face): o^2 = r^2 - h^2, h the height of x
/// above the plane.
template <class S>
inline S blendDistanceAt(const S* x, const S* y, int region, Real delta) {
  S p[3], d[3], e1[3], e2[3], m[3], xa[3];
  footInRegion(x, y, y + 3, y + 6, region, p);
  for (int i = 0; i < 3; ++i) d[i] = x[i] - p[i], e1[i] = y[3 + i] - y[i], e2[i] = y[6 + i] - y[i], xa[i] = x[i] - y[i];
  cross3(e1, e2, m);
  using std::sqrt;
  const S r2 = dot3(d, d), hm = dot3(xa, m);
  const S o2 = region == 0 ? S(0.0) : r2 - hm * hm / dot3(m, m);
  return sqrt(r2) + o2 / delta;
}

/// The same for the quadrature point q of the facet in z (as method3Residual3D).
template <int NF, class S>
inline S blendDistance3D(const S* z, const FacetPoint& q, int region, Real delta) {
  S x[3] = {0.0, 0.0, 0.0};
  for (int a = 0; a < NF; ++a)
    for (int i = 0; i < 3; ++i) x[i] += q.N[a] * z[3 * a + i];
  return blendDistanceAt(x, z + 3 * NF, region, delta);
}

}  // namespace detail

/// rho = r + o^2/delta of a pair (detail::blendDistance3D) and, if grad is
/// not null, d rho/dz (3 NF + 9 entries), for the projection region of x.
template <int NF>
Real method3BlendDistance3D(const Real* z, const FacetPoint& q, int region, Real delta, Real* grad) {
  constexpr int nz = 3 * NF + 9;
  if (grad == nullptr) return detail::blendDistance3D<NF>(z, q, region, delta);
  using Fad = Sacado::Fad::SFad<Real, nz>;
  Fad zf[nz];
  for (int j = 0; j < nz; ++j) zf[j] = Fad(nz, j, z[j]);
  const Fad rho = detail::blendDistance3D<NF>(zf, q, region, delta);
  for (int j = 0; j < nz; ++j) grad[j] = rho.dx(j);
  return rho.val();
}

/// Evaluates one pair: f (3 NF entries, node-major) and, if K is not null,
/// K[i * (3 NF + 9) + j] = df_i/dz_j. `law(r, T, dT)` gives T(r) and dT/dr.
/// referenceArea (may be null): the point's reference area element dA, used
/// instead of the current da. The caller checks state.distance > 0 (r = 0:
/// the point lies on s).
template <int NF, class Law>
PairState method3Pair3D(const Real* z, const FacetPoint& q, const Law& law, Real* f, Real* K,
                        const Real* referenceArea = nullptr) {
  constexpr int nz = 3 * NF + 9, nf = 3 * NF;
  PairState st;
  Real x[3] = {0.0, 0.0, 0.0};
  for (int a = 0; a < NF; ++a)
    for (int i = 0; i < 3; ++i) x[i] += q.N[a] * z[3 * a + i];
  Real xi[2], p[3];
  int region = 0;
  projectOntoTriangle(x, z + nf, z + nf + 3, z + nf + 6, xi, p, region);
  if (K == nullptr) {
    detail::method3Residual3D<NF>(z, q, region, law, f, st, referenceArea);
    return st;
  }
  using Fad = Sacado::Fad::SFad<Real, nz>;
  Fad zf[nz], ff[nf];
  for (int j = 0; j < nz; ++j) zf[j] = Fad(nz, j, z[j]);
  detail::method3Residual3D<NF>(zf, q, region, law, ff, st, referenceArea);
  for (int i = 0; i < nf; ++i) {
    f[i] = ff[i].val();
    for (int j = 0; j < nz; ++j) K[i * nz + j] = ff[i].dx(j);
  }
  return st;
}

}  // namespace cgcm::interaction
