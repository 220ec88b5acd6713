#pragma once
// Shape functions of 3D surface facets on their parameter domains, with
// first and second derivatives: the linear facets TRI3 and QUAD4 and the
// curved facets of quadratic cells, TRI6, QUAD8 and QUAD9, in the node order
// of core/CellType.hpp (corners, then the mid-edge nodes of edges 0-1, 1-2,
// ..., then the QUAD9 face centre).
//
// Triangles: (u, v) in the unit simplex, corners (0, 0), (1, 0), (0, 1).
// Quadrilaterals: [-1, 1]^2, corners (-1, -1), (1, -1), (1, 1), (-1, 1).
// QUAD8 (serendipity) is QUAD9 with the centre value eliminated: the
// serendipity space lies in the biquadratic one, and its centre value is
// -1/4 (sum of corners) + 1/2 (sum of mids), so N8_corner = N9_corner -
// N9_centre / 4 and N8_mid = N9_mid + N9_centre / 2.
#include "cgcm/core/Types.hpp"

namespace cgcm::interaction {

/// Corners of a facet with N nodes (3, 6: triangle; 4, 8, 9: quadrilateral).
template <int N>
inline constexpr int kFacetCorners = (N == 3 || N == 6) ? 3 : 4;

/// Parameters (u, v) of node a of a facet with N nodes.
template <int N>
inline void facetNodeParameters(int a, Real& u, Real& v) {
  if constexpr (kFacetCorners<N> == 3) {
    constexpr Real tri[6][2] = {{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}, {0.5, 0.0}, {0.5, 0.5}, {0.0, 0.5}};
    u = tri[a][0], v = tri[a][1];
  } else {
    constexpr Real quad[9][2] = {{-1.0, -1.0}, {1.0, -1.0}, {1.0, 1.0}, {-1.0, 1.0}, {0.0, -1.0},
                                 {1.0, 0.0},   {0.0, 1.0},  {-1.0, 0.0}, {0.0, 0.0}};
    u = quad[a][0], v = quad[a][1];
  }
}

/// Whether (u, v) lies in the facet's parameter domain, within tol.
template <int N>
inline bool insideFacetDomain(Real u, Real v, Real tol = 0.0) {
  if constexpr (kFacetCorners<N> == 3) return u >= -tol && v >= -tol && u + v <= 1.0 + tol;
  else return u >= -1.0 - tol && u <= 1.0 + tol && v >= -1.0 - tol && v <= 1.0 + tol;
}

/// N_a(u, v), dN[i][a] = dN_a/du_i and (if d2N is not null) d2N[k][a] with
/// k = 0: uu, 1: uv, 2: vv.
template <int N>
inline void facetShape(Real u, Real v, Real Nv[N], Real dN[2][N], Real (*d2N)[N] = nullptr) {
  if constexpr (N == 3 || N == 6) {
    const Real L[3] = {1.0 - u - v, u, v};
    constexpr Real dL[3][2] = {{-1.0, -1.0}, {1.0, 0.0}, {0.0, 1.0}};
    if constexpr (N == 3) {
      for (int a = 0; a < 3; ++a) {
        Nv[a] = L[a];
        dN[0][a] = dL[a][0], dN[1][a] = dL[a][1];
        if (d2N) d2N[0][a] = d2N[1][a] = d2N[2][a] = 0.0;
      }
    } else {
      for (int a = 0; a < 3; ++a) {  // corners: L (2 L - 1)
        Nv[a] = L[a] * (2.0 * L[a] - 1.0);
        for (int i = 0; i < 2; ++i) dN[i][a] = (4.0 * L[a] - 1.0) * dL[a][i];
        if (d2N) {
          d2N[0][a] = 4.0 * dL[a][0] * dL[a][0];
          d2N[1][a] = 4.0 * dL[a][0] * dL[a][1];
          d2N[2][a] = 4.0 * dL[a][1] * dL[a][1];
        }
      }
      constexpr int ends[3][2] = {{0, 1}, {1, 2}, {2, 0}};
      for (int e = 0; e < 3; ++e) {  // mids: 4 L_i L_j
        const int i0 = ends[e][0], j0 = ends[e][1], a = 3 + e;
        Nv[a] = 4.0 * L[i0] * L[j0];
        for (int i = 0; i < 2; ++i) dN[i][a] = 4.0 * (dL[i0][i] * L[j0] + L[i0] * dL[j0][i]);
        if (d2N) {
          d2N[0][a] = 8.0 * dL[i0][0] * dL[j0][0];
          d2N[1][a] = 4.0 * (dL[i0][0] * dL[j0][1] + dL[i0][1] * dL[j0][0]);
          d2N[2][a] = 8.0 * dL[i0][1] * dL[j0][1];
        }
      }
    }
  } else if constexpr (N == 4) {
    constexpr Real su[4] = {-1.0, 1.0, 1.0, -1.0}, sv[4] = {-1.0, -1.0, 1.0, 1.0};
    for (int a = 0; a < 4; ++a) {
      Nv[a] = 0.25 * (1.0 + su[a] * u) * (1.0 + sv[a] * v);
      dN[0][a] = 0.25 * su[a] * (1.0 + sv[a] * v);
      dN[1][a] = 0.25 * sv[a] * (1.0 + su[a] * u);
      if (d2N) d2N[0][a] = d2N[2][a] = 0.0, d2N[1][a] = 0.25 * su[a] * sv[a];
    }
  } else {
    static_assert(N == 8 || N == 9, "facets have 3, 4, 6, 8 or 9 nodes");
    // 1D quadratics on [-1, 1] with nodes -1, 1, 0 (index 0, 1, 2), and node a's pair of them
    auto l = [](Real s, Real out[3], Real d[3], Real dd[3]) {
      out[0] = 0.5 * s * (s - 1.0), out[1] = 0.5 * s * (s + 1.0), out[2] = 1.0 - s * s;
      d[0] = s - 0.5, d[1] = s + 0.5, d[2] = -2.0 * s;
      dd[0] = 1.0, dd[1] = 1.0, dd[2] = -2.0;
    };
    constexpr int iu[9] = {0, 1, 1, 0, 2, 1, 2, 0, 2}, iv[9] = {0, 0, 1, 1, 0, 2, 1, 2, 2};
    Real lu[3], dlu[3], ddlu[3], lv[3], dlv[3], ddlv[3];
    l(u, lu, dlu, ddlu);
    l(v, lv, dlv, ddlv);
    Real n9[9], d9[2][9], dd9[3][9];
    for (int a = 0; a < 9; ++a) {
      n9[a] = lu[iu[a]] * lv[iv[a]];
      d9[0][a] = dlu[iu[a]] * lv[iv[a]];
      d9[1][a] = lu[iu[a]] * dlv[iv[a]];
      dd9[0][a] = ddlu[iu[a]] * lv[iv[a]];
      dd9[1][a] = dlu[iu[a]] * dlv[iv[a]];
      dd9[2][a] = lu[iu[a]] * ddlv[iv[a]];
    }
    for (int a = 0; a < N; ++a) {
      const Real c = N == 9 ? 0.0 : (a < 4 ? -0.25 : 0.5);  // QUAD8: the centre eliminated
      Nv[a] = n9[a] + c * n9[8];
      for (int i = 0; i < 2; ++i) dN[i][a] = d9[i][a] + c * d9[i][8];
      if (d2N)
        for (int k = 0; k < 3; ++k) d2N[k][a] = dd9[k][a] + c * dd9[k][8];
    }
  }
}

/// Edge e of a facet with N nodes: from corner e to corner (e + 1) mod corners,
/// mid node corners + e on curved facets; eta in [0, 1] along it maps to
/// (u, v) = start + eta dir.
template <int N>
inline void facetEdge(int e, Real start[2], Real dir[2]) {
  constexpr int nc = kFacetCorners<N>;
  Real u1, v1;
  facetNodeParameters<N>(e, start[0], start[1]);
  facetNodeParameters<N>((e + 1) % nc, u1, v1);
  dir[0] = u1 - start[0], dir[1] = v1 - start[1];
}

}  // namespace cgcm::interaction
