#pragma once
// Method 3 surface kernel (eq. 21, doc/theory.md#method-3) in 3D on curved
// facets: the faces of quadratic cells (TRI6, QUAD8, QUAD9; FacetShape.hpp),
// with the exact tangent.
//
// Unit of work: quadrature point q of facet e (NF nodes) of body k and one
// curved facet s (NS nodes) of body l. With the coordinates
//     z = [x_1 .. x_NF of e | y_1 .. y_NS of s]     (3 (NF + NS) entries)
// the point is x = sum_a N_a x_a on its curved facet, n = g1 x g2/|g1 x g2|
// its outward normal (g_i = dx/dxi_i), and the closest point of s is y(u*)
// with u* the minimiser of |x - y(u)| over the facet's parameter domain:
// inside (region 0: a stationary point, (y - x) . y_,i = 0), on an edge
// (region corners + 1 + e: the edge is the Line3 through its corners and mid
// node, projected exactly as a 2D curved segment: the roots of a cubic) or
// at a corner (region 1 + a). projectOntoPatch takes the closest of the
// edges' projections and of the interior stationary point that Newton finds
// from the closest point of the facet's cover (its nodes' grid split into
// flat triangles), which is global whenever that seed lies in the basin of
// the minimiser: the tests compare it with a dense sampling of bowed facets.
// Then, as on flat facets,
//     f_a = N_a T(r) rbar (rbar . n) da,  da = |g1 x g2| w   (or dA),
// and the blend distance rho = r + o^2/delta with o^2 = r^2 - ((x - p) .
// n_s)^2, n_s the unit normal of s at the foot p: 0 inside, and on a flat
// facet the linear version's o (Method3Kernel3D.hpp).
//
// Tangent by forward automatic differentiation (Sacado::Fad::SFad) of the
// same code with the region held fixed; the foot enters through one Newton
// step on the stationarity condition taken in the AD type (inside: the 2 x 2
// system with the full Hessian; on an edge: along the edge), whose value is
// 0 and whose derivative is the implicit function theorem's exactly. Unit
// tests compare it with central differences.
#include <Sacado.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "cgcm/core/Types.hpp"
#include "cgcm/interaction/ClosestPointSearch.hpp"
#include "cgcm/interaction/FacetShape.hpp"
#include "cgcm/interaction/Method3CurvedKernel.hpp"
#include "cgcm/interaction/Method3Kernel3D.hpp"
#include "cgcm/interaction/Quadrature.hpp"

namespace cgcm::interaction {

/// The closest point of a curved facet: its parameters and its region (0
/// inside, 1 + a at corner a, corners + 1 + e on edge e).
struct PatchFoot {
  Real u = 0.0, v = 0.0;
  int region = 0;
};

/// The cover of a curved facet: the grid of its nodes' parameters (6 points
/// on a triangle; 9 on a quadrilateral, the QUAD8 centre evaluated on the
/// facet) split into flat triangles (4 on a triangle, 8 on a quadrilateral).
template <int N>
inline constexpr int kCoverPoints = kFacetCorners<N> == 3 ? 6 : 9;
template <int N>
inline constexpr int kCoverTriangles = kFacetCorners<N> == 3 ? 4 : 8;

/// Triangle t of the cover: its points.
template <int N>
inline const int* coverTriangle(int t) {
  static constexpr int tri[4][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}};
  static constexpr int quad[8][3] = {{0, 4, 8}, {0, 8, 7}, {4, 1, 5}, {4, 5, 8},
                                     {8, 5, 2}, {8, 2, 6}, {7, 8, 6}, {7, 6, 3}};
  if constexpr (kFacetCorners<N> == 3) return tri[t];
  else return quad[t];
}

/// The point of the facet y (N nodes, 3 coordinates each) at (u, v).
template <int N>
inline void pointOnFacet(const Real* y, Real u, Real v, Real p[3]) {
  Real Nv[N], dN[2][N];
  facetShape<N>(u, v, Nv, dN);
  for (int i = 0; i < 3; ++i) p[i] = 0.0;
  for (int a = 0; a < N; ++a)
    for (int i = 0; i < 3; ++i) p[i] += Nv[a] * y[3 * a + i];
}

/// The cover's points (kCoverPoints, 3 coordinates each) of the facet y.
template <int N>
inline void coverPoints(const Real* y, Real (*pts)[3]) {
  for (int a = 0; a < kCoverPoints<N>; ++a) {
    if (a < N) {
      for (int i = 0; i < 3; ++i) pts[a][i] = y[3 * a + i];
    } else {
      pointOnFacet<N>(y, 0.0, 0.0, pts[a]);  // the QUAD8 centre
    }
  }
}

/// An upper bound of the distance between the facet y and its cover. Each
/// piece of the cover (a sub-triangle, or a sub-square split in two) carries
/// a quadratic (biquadratic) sub-patch, which lies in the convex hull of its
/// Bernstein control points b: within max |b - l| of the linear (bilinear)
/// interpolant of its corners, l that interpolant's control points. A
/// sub-square's two triangles lie within |twist|/4 of its bilinear patch.
template <int N>
inline Real coverDeviation(const Real* y) {
  Real pts[9][3];
  coverPoints<N>(y, pts);
  auto dist = [](const Real* a, const Real* b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
  };
  Real dev = 0.0;
  if constexpr (kFacetCorners<N> == 3) {
    for (int t = 0; t < 4; ++t) {
      const int* c = coverTriangle<N>(t);
      for (int e = 0; e < 3; ++e) {  // b - l on an edge: 2 (y(mid) - (y_i + y_j)/2)
        const int i = c[e], j = c[(e + 1) % 3];
        Real ui, vi, uj, vj, m[3], avg[3];
        facetNodeParameters<N>(i, ui, vi);
        facetNodeParameters<N>(j, uj, vj);
        pointOnFacet<N>(y, 0.5 * (ui + uj), 0.5 * (vi + vj), m);
        for (int k = 0; k < 3; ++k) avg[k] = 0.5 * (pts[i][k] + pts[j][k]);
        dev = std::max(dev, 2.0 * dist(m, avg));
      }
    }
  } else {
    constexpr int squares[4][4] = {{0, 4, 8, 7}, {4, 1, 5, 8}, {8, 5, 2, 6}, {7, 8, 6, 3}};  // a, b, c, d
    for (const auto& sq : squares) {
      Real ua, va, ub, vb, ud, vd;
      facetNodeParameters<N>(sq[0], ua, va);
      facetNodeParameters<N>(sq[1], ub, vb);
      facetNodeParameters<N>(sq[3], ud, vd);
      // values on the sub-square's 3 x 3 grid (s along a -> b, t along a -> d)
      Real L[3][3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          pointOnFacet<N>(y, ua + 0.5 * i * (ub - ua) + 0.5 * j * (ud - ua), va + 0.5 * i * (vb - va) + 0.5 * j * (vd - va),
                        L[i][j]);
      // Bernstein control points: b_1 = 2 y(1/2) - (y(0) + y(1))/2 along each direction (order 0, 2, 1 below)
      Real B[3][3][3];
      for (int k = 0; k < 3; ++k) {
        Real R[3][3];  // rows converted along s
        for (int j = 0; j < 3; ++j) {
          R[0][j] = L[0][j][k], R[2][j] = L[2][j][k];
          R[1][j] = 2.0 * L[1][j][k] - 0.5 * (L[0][j][k] + L[2][j][k]);
        }
        for (int i = 0; i < 3; ++i) {
          B[i][0][k] = R[i][0], B[i][2][k] = R[i][2];
          B[i][1][k] = 2.0 * R[i][1] - 0.5 * (R[i][0] + R[i][2]);
        }
      }
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          Real l[3];  // the bilinear interpolant's control point at (i/2, j/2)
          for (int k = 0; k < 3; ++k) {
            const Real s = 0.5 * i, t = 0.5 * j;
            l[k] = (1 - s) * (1 - t) * L[0][0][k] + s * (1 - t) * L[2][0][k] + s * t * L[2][2][k] + (1 - s) * t * L[0][2][k];
          }
          Real twist[3];
          for (int k = 0; k < 3; ++k) twist[k] = 0.25 * (L[0][0][k] - L[2][0][k] + L[2][2][k] - L[0][2][k]);
          const Real zero[3] = {0.0, 0.0, 0.0};
          dev = std::max(dev, dist(B[i][j], l) + dist(twist, zero));
        }
    }
  }
  return dev;
}

namespace detail {

/// Point, first and second derivatives of the facet y (N nodes) at (u, v), in S.
template <int N, class S>
struct FacetJet {
  S y[3], yu[3], yv[3], yuu[3], yuv[3], yvv[3];
  FacetJet(const S* nodes, Real u, Real v) {
    Real Nv[N], dN[2][N], d2N[3][N];
    facetShape<N>(u, v, Nv, dN, d2N);
    for (int i = 0; i < 3; ++i) y[i] = yu[i] = yv[i] = yuu[i] = yuv[i] = yvv[i] = S(0.0);
    for (int a = 0; a < N; ++a)
      for (int i = 0; i < 3; ++i) {
        const S& c = nodes[3 * a + i];
        y[i] += Nv[a] * c;
        yu[i] += dN[0][a] * c;
        yv[i] += dN[1][a] * c;
        yuu[i] += d2N[0][a] * c;
        yuv[i] += d2N[1][a] * c;
        yvv[i] += d2N[2][a] * c;
      }
  }
};

/// The foot p of x on the facet y in the region of `foot`, and the facet's
/// tangents there (see the header: one Newton step in S).
template <int N, class S>
inline void footOnFacet(const S* x, const S* y, const PatchFoot& foot, S p[3], S tu[3], S tv[3]) {
  constexpr int nc = kFacetCorners<N>;
  const FacetJet<N, S> j(y, foot.u, foot.v);
  S r[3];
  for (int i = 0; i < 3; ++i) r[i] = j.y[i] - x[i];
  S du(0.0), dv(0.0);
  if (foot.region == 0) {
    const S g0 = dot3(r, j.yu), g1 = dot3(r, j.yv);
    const S h00 = dot3(j.yu, j.yu) + dot3(r, j.yuu), h01 = dot3(j.yu, j.yv) + dot3(r, j.yuv),
            h11 = dot3(j.yv, j.yv) + dot3(r, j.yvv);
    const S det = h00 * h11 - h01 * h01;
    du = -(h11 * g0 - h01 * g1) / det;
    dv = -(h00 * g1 - h01 * g0) / det;
  } else if (foot.region > nc) {
    Real start[2], dir[2];
    facetEdge<N>(foot.region - nc - 1, start, dir);
    S ye[3], yee[3];
    for (int i = 0; i < 3; ++i) {
      ye[i] = dir[0] * j.yu[i] + dir[1] * j.yv[i];
      yee[i] = dir[0] * dir[0] * j.yuu[i] + 2.0 * dir[0] * dir[1] * j.yuv[i] + dir[1] * dir[1] * j.yvv[i];
    }
    const S de = -dot3(r, ye) / (dot3(ye, ye) + dot3(r, yee));
    du = dir[0] * de;
    dv = dir[1] * de;
  }
  for (int i = 0; i < 3; ++i) {
    p[i] = j.y[i] + j.yu[i] * du + j.yv[i] * dv;
    tu[i] = j.yu[i] + j.yuu[i] * du + j.yuv[i] * dv;
    tv[i] = j.yv[i] + j.yuv[i] * du + j.yvv[i] * dv;
  }
}

/// rho = r + o^2/delta of x with foot p where the facet's tangents are tu, tv (header).
template <class S>
inline S facetBlendDistance(const S* d, const S& r, const S* tu, const S* tv, int region, Real delta) {
  if (!(delta > 0.0) || region == 0) return r;
  S n[3];
  cross3(tu, tv, n);
  const S h = dot3(d, n);
  return r + (r * r - h * h / dot3(n, n)) / delta;
}

/// f (3 NF entries) and rho of the pair in z (header) for a fixed region.
template <int NF, int NS, class S, class Law>
inline void curvedPairResidual3D(const S* z, const FacetPoint& q, const PatchFoot& foot, const Law& law, Real delta,
                                 const Real* referenceArea, S* f, S& rho, PairState& st) {
  S x[3], m[3], jac;
  sourcePoint<NF>(z, q, x, m, jac);
  S p[3], tu[3], tv[3];
  footOnFacet<NS>(x, z + 3 * NF, foot, p, tu, tv);
  S d[3];
  for (int i = 0; i < 3; ++i) d[i] = x[i] - p[i];
  const S r = sourceForce<NF>(d, m, jac, q, law, referenceArea, f, st);
  rho = facetBlendDistance(d, r, tu, tv, foot.region, delta);
  st.region = foot.region;
}

}  // namespace detail

/// Closest point of the curved facet y (N nodes, 3 coordinates each) to x:
/// the squared distance, and the foot's parameters and region (header).
template <int N>
inline Real projectOntoFacet(const Real* x, const Real* y, PatchFoot& foot) {
  constexpr int nc = kFacetCorners<N>;
  Real best = std::numeric_limits<Real>::infinity();
  for (int e = 0; e < nc; ++e) {  // the edges, and with them the corners
    Real ye[9], eta, pe[3];
    const int nodes[3] = {e, (e + 1) % nc, nc + e};
    for (int a = 0; a < 3; ++a)
      for (int i = 0; i < 3; ++i) ye[3 * a + i] = y[3 * nodes[a] + i];
    int region;
    const Real d2 = projectOntoCurve<3, 3>(x, ye, eta, pe, region);
    if (!(d2 < best)) continue;
    best = d2;
    Real start[2], dir[2];
    facetEdge<N>(e, start, dir);
    foot.u = start[0] + eta * dir[0], foot.v = start[1] + eta * dir[1];
    foot.region = region == 0 ? nc + 1 + e : region == 1 ? 1 + e : 1 + (e + 1) % nc;
  }
  // inside: Newton on (y - x) . y_,i = 0 from the closest point of the cover
  Real pts[9][3], u = 0.0, v = 0.0;
  {
    coverPoints<N>(y, pts);
    Real seed = std::numeric_limits<Real>::infinity();
    for (int t = 0; t < kCoverTriangles<N>; ++t) {
      const int* c = coverTriangle<N>(t);
      Real xi[2], p[3], P[3][2];
      int region;
      const Real d2 = projectOntoTriangle(x, pts[c[0]], pts[c[1]], pts[c[2]], xi, p, region);
      if (!(d2 < seed)) continue;
      seed = d2;
      for (int a = 0; a < 3; ++a) facetNodeParameters<N>(c[a], P[a][0], P[a][1]);
      u = P[0][0] + xi[0] * (P[1][0] - P[0][0]) + xi[1] * (P[2][0] - P[0][0]);
      v = P[0][1] + xi[0] * (P[1][1] - P[0][1]) + xi[1] * (P[2][1] - P[0][1]);
    }
  }
  for (int it = 0; it < 40; ++it) {
    const detail::FacetJet<N, Real> j(y, u, v);
    Real r[3];
    for (int i = 0; i < 3; ++i) r[i] = j.y[i] - x[i];
    const Real g0 = detail::dot3(r, j.yu), g1 = detail::dot3(r, j.yv);
    Real h00 = detail::dot3(j.yu, j.yu) + detail::dot3(r, j.yuu), h01 = detail::dot3(j.yu, j.yv) + detail::dot3(r, j.yuv),
         h11 = detail::dot3(j.yv, j.yv) + detail::dot3(r, j.yvv);
    const bool minimum = h00 > 0.0 && h00 * h11 - h01 * h01 > 0.0;
    if (!minimum) {  // Gauss-Newton away from a minimum's basin
      h00 = detail::dot3(j.yu, j.yu), h01 = detail::dot3(j.yu, j.yv), h11 = detail::dot3(j.yv, j.yv);
    }
    const Real det = h00 * h11 - h01 * h01;
    if (!(det > 0.0)) break;
    const Real du = -(h11 * g0 - h01 * g1) / det, dv = -(h00 * g1 - h01 * g0) / det;
    const Real step = std::max(std::abs(du), std::abs(dv));
    // converged: a step at the rounding of g, eps (|x| + |r|) |y_,i|, over |y_,i|^2 (coordinates far
    // from the origin, or facets much smaller than the distance, have a larger floor than 1e-13)
    const Real scale = std::max({std::abs(x[0]), std::abs(x[1]), std::abs(x[2])}) + std::sqrt(detail::dot3(r, r));
    const Real floor = 16.0 * std::numeric_limits<Real>::epsilon() * scale /
                       std::sqrt(std::min(detail::dot3(j.yu, j.yu), detail::dot3(j.yv, j.yv)));
    if (step <= std::max(1e-13, floor) && minimum) {
      if (!insideFacetDomain<N>(u, v)) break;  // on or beyond the boundary: the edges hold it
      const Real d2 = detail::dot3(r, r);
      if (d2 < best) best = d2, foot.u = u, foot.v = v, foot.region = 0;
      break;
    }
    Real lam = 1.0;  // a step out of the domain is shortened, never taken
    while (!insideFacetDomain<N>(u + lam * du, v + lam * dv) && lam > 1e-6) lam *= 0.5;
    if (!insideFacetDomain<N>(u + lam * du, v + lam * dv)) break;
    u += lam * du, v += lam * dv;
  }
  return best;
}

/// The point q of facet e projected onto the target facet s (z as in the header).
template <int NF, int NS>
PatchFoot facetFootOnTarget(const Real* z, const FacetPoint& q) {
  Real x[3] = {0.0, 0.0, 0.0};
  for (int a = 0; a < NF; ++a)
    for (int i = 0; i < 3; ++i) x[i] += q.N[a] * z[3 * a + i];
  PatchFoot foot;
  projectOntoFacet<NS>(x, z + 3 * NF, foot);
  return foot;
}

/// Evaluates one pair on curved facets (z as in the header) at the target's
/// closest point `foot` (facetFootOnTarget): f (3 NF entries) and rho (r
/// without smoothing, delta <= 0). With K (may be null), K[i * nz + j] =
/// df_i/dz_j and Jrho[j] = drho/dz_j, nz = 3 (NF + NS). referenceArea (may be
/// null): the point's reference area element dA instead of da. The caller
/// checks state.distance > 0.
template <int NF, int NS, class Law>
PairState method3CurvedPair3D(const Real* z, const FacetPoint& q, const Law& law, const PatchFoot& foot, Real delta,
                              const Real* referenceArea, Real* f, Real& rho, Real* K, Real* Jrho) {
  constexpr int nz = 3 * (NF + NS), nf = 3 * NF;
  PairState st;
  if (K == nullptr) {
    detail::curvedPairResidual3D<NF, NS>(z, q, foot, law, delta, referenceArea, f, rho, st);
    return st;
  }
  using Fad = Sacado::Fad::SFad<Real, nz>;
  Fad zf[nz], ff[nf], rf;
  for (int j = 0; j < nz; ++j) zf[j] = Fad(nz, j, z[j]);
  detail::curvedPairResidual3D<NF, NS>(zf, q, foot, law, delta, referenceArea, ff, rf, st);
  for (int i = 0; i < nf; ++i) {
    f[i] = ff[i].val();
    for (int j = 0; j < nz; ++j) K[i * nz + j] = ff[i].dx(j);
  }
  rho = rf.val();
  if (Jrho != nullptr)
    for (int j = 0; j < nz; ++j) Jrho[j] = rf.dx(j);
  return st;
}

/// rho of the point x against the facet y (N nodes), and its distance into *r (may be null).
template <int N>
Real facetBlendDistance(const Real* x, const Real* y, Real delta, Real* r = nullptr) {
  PatchFoot foot;
  projectOntoFacet<N>(x, y, foot);
  Real p[3], tu[3], tv[3], d[3];
  detail::footOnFacet<N>(x, y, foot, p, tu, tv);
  for (int i = 0; i < 3; ++i) d[i] = x[i] - p[i];
  const Real dist = std::sqrt(detail::dot3(d, d));
  if (r != nullptr) *r = dist;
  return detail::facetBlendDistance(d, dist, tu, tv, foot.region, delta);
}

}  // namespace cgcm::interaction
