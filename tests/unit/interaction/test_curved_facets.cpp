// Method 3 on curved 3D facets (TRI6, QUAD8, QUAD9: the faces of quadratic
// cells): the facets' shape functions; the projection is the closest point
// of the facet; the cover deviation bounds the distance of the facet from
// its cover; the kernel's tangent and blend gradient against central
// differences on every pair of facet types with projections inside, onto
// edges and onto corners; on flat facets the curved kernel is the linear one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <set>
#include <vector>

#include "cgcm/interaction/Method3CurvedKernel3D.hpp"
#include "cgcm/interaction/PairPotential.hpp"
#include "cgcm/interaction/SurfaceInteraction.hpp"

using namespace cgcm;
using namespace cgcm::interaction;

namespace {

constexpr Real kInf = std::numeric_limits<Real>::infinity();

TractionLaw<InversePowerPair> lawOf(const LennardJones& lj, Real beta = 1.2) {
  return {std::get<InversePowerPair>(lj.kernelPotential()), beta, kInf, kInf};
}

// A facet with N nodes: its parameters mapped to the plane z = height by
// (u, v) -> origin + scale (u, v) (a quadrilateral's [-1, 1]^2 to half the
// scale), bowed by bow (x^2 + y^2) and twisted by twist x y about its centre.
template <int N>
std::vector<Real> bowedFacet(Real ox, Real oy, Real height, Real scale, Real bow, Real twist) {
  std::vector<Real> y(3 * N);
  const bool tri = kFacetCorners<N> == 3;
  const Real half = tri ? 1.0 : 0.5, centre = tri ? scale / 3.0 : 0.0;
  for (int a = 0; a < N; ++a) {
    Real u, v;
    facetNodeParameters<N>(a, u, v);
    const Real x = ox + scale * half * u, yy = oy + scale * half * v, cx = x - ox - centre, cy = yy - oy - centre;
    y[3 * a] = x, y[3 * a + 1] = yy, y[3 * a + 2] = height + bow * (cx * cx + cy * cy) + twist * cx * cy;
  }
  return y;
}

// The smallest distance from x to the facet y over an (n + 1)^2 grid of its parameters.
template <int N>
Real sampledDistance(const Real* x, const Real* y, int n) {
  Real best = kInf;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      Real u, v;
      if constexpr (kFacetCorners<N> == 3) {
        if (i + j > n) continue;
        u = Real(i) / n, v = Real(j) / n;
      } else {
        u = -1.0 + 2.0 * i / n, v = -1.0 + 2.0 * j / n;
      }
      Real p[3];
      pointOnFacet<N>(y, u, v, p);
      best = std::min(best, std::sqrt((p[0] - x[0]) * (p[0] - x[0]) + (p[1] - x[1]) * (p[1] - x[1]) +
                                      (p[2] - x[2]) * (p[2] - x[2])));
    }
  return best;
}

template <int N>
void checkShape() {
  // nodal interpolation, partition of unity, and the derivatives against central differences
  for (int b = 0; b < N; ++b) {
    Real u, v, Nv[N], dN[2][N];
    facetNodeParameters<N>(b, u, v);
    facetShape<N>(u, v, Nv, dN);
    for (int a = 0; a < N; ++a) EXPECT_NEAR(Nv[a], a == b ? 1.0 : 0.0, 1e-15) << N << " " << a << " " << b;
  }
  const Real pts[3][2] = {{0.21, 0.13}, {0.05, 0.61}, {0.33, 0.33}};
  for (const auto& pt : pts) {
    const Real u = kFacetCorners<N> == 3 ? pt[0] : 2.0 * pt[0] - 0.7, v = kFacetCorners<N> == 3 ? pt[1] : 2.0 * pt[1] - 0.2;
    Real Nv[N], dN[2][N], d2N[3][N], sum = 0.0;
    facetShape<N>(u, v, Nv, dN, d2N);
    for (int a = 0; a < N; ++a) sum += Nv[a];
    EXPECT_NEAR(sum, 1.0, 1e-15);
    const Real h = 1e-6;
    Real Np[N], Nm[N], dNp[2][N], dNm[2][N];
    for (int i = 0; i < 2; ++i) {
      facetShape<N>(u + (i == 0 ? h : 0.0), v + (i == 1 ? h : 0.0), Np, dNp);
      facetShape<N>(u - (i == 0 ? h : 0.0), v - (i == 1 ? h : 0.0), Nm, dNm);
      for (int a = 0; a < N; ++a) {
        EXPECT_NEAR(dN[i][a], (Np[a] - Nm[a]) / (2 * h), 1e-9);
        // d2N: uu (i = 0, from dN_u), uv (from dN_u along v), vv (i = 1, from dN_v)
        EXPECT_NEAR(d2N[2 * i][a], (dNp[i][a] - dNm[i][a]) / (2 * h), 1e-8);
        if (i == 1) {
          EXPECT_NEAR(d2N[1][a], (dNp[0][a] - dNm[0][a]) / (2 * h), 1e-8);
        }
      }
    }
  }
  // the quadrature's weights sum to the parameter domain's area, its shape functions are facetShape's
  for (int n = 1; n <= 4; ++n) {
    Real area = 0.0;
    for (const FacetPoint& q : facetQuadrature(N, n)) {
      area += q.weight;
      Real Nv[N], dN[2][N];
      facetShape<N>(q.xi[0], q.xi[1], Nv, dN);
      for (int a = 0; a < N; ++a) EXPECT_EQ(q.N[a], Nv[a]);
    }
    EXPECT_NEAR(area, kFacetCorners<N> == 3 ? 0.5 : 4.0, 1e-14) << N << " " << n;
  }
}

}  // namespace

TEST(CurvedFacets, ShapeFunctions) {
  checkShape<6>();
  checkShape<8>();
  checkShape<9>();
}

namespace {

// Bowed and twisted facets (up to a bow of 0.8 over a facet of size 1: far
// more curved than a facet of any mesh), points on both sides, above the
// interior, beyond edges and corners: the projection is never farther than
// the closest of a 201 x 201 sampling, lies on the facet, and is
// stationary where it is inside.
template <int N>
void checkProjection(std::mt19937& rng) {
  std::uniform_real_distribution<Real> U(-1.0, 1.0);
  int regions[3] = {0, 0, 0};  // inside, corner, edge
  Real worst = 0.0;
  for (int c = 0; c < 60; ++c) {
    const std::vector<Real> y = bowedFacet<N>(0.0, 0.0, 0.0, 1.0, 0.8 * U(rng), 0.5 * U(rng));
    for (int k = 0; k < 5; ++k) {
      const Real x[3] = {0.3 + 0.9 * U(rng), 0.3 + 0.9 * U(rng), 0.6 * U(rng)};
      PatchFoot foot;
      const Real d = std::sqrt(projectOntoFacet<N>(x, y.data(), foot));
      const Real sampled = sampledDistance<N>(x, y.data(), 200);
      EXPECT_LE(d, sampled + 1e-13) << N << " case " << c;
      worst = std::max(worst, d - sampled);
      EXPECT_TRUE(insideFacetDomain<N>(foot.u, foot.v, 1e-14));
      Real p[3];
      pointOnFacet<N>(y.data(), foot.u, foot.v, p);
      EXPECT_NEAR(std::sqrt((p[0] - x[0]) * (p[0] - x[0]) + (p[1] - x[1]) * (p[1] - x[1]) + (p[2] - x[2]) * (p[2] - x[2])),
                  d, 1e-13);
      constexpr int nc = kFacetCorners<N>;
      ++regions[foot.region == 0 ? 0 : foot.region <= nc ? 1 : 2];
      // the same far from the origin (coordinates 1000 times the facet's size): the same foot, the
      // interior Newton's convergence test scaled to the coordinates' rounding
      const Real offset[3] = {700.0, -400.0, 900.0};
      std::vector<Real> yo = y;
      for (int a = 0; a < N; ++a)
        for (int i = 0; i < 3; ++i) yo[3 * a + i] += offset[i];
      const Real xo[3] = {x[0] + offset[0], x[1] + offset[1], x[2] + offset[2]};
      PatchFoot farFoot;
      EXPECT_NEAR(std::sqrt(projectOntoFacet<N>(xo, yo.data(), farFoot)), d, 1e-10) << N << " case " << c;
      EXPECT_EQ(farFoot.region, foot.region) << N << " case " << c;
    }
  }
  std::printf("[curved 3D] %d-node facets: projection - sampled minimum <= %.1e; inside / corner / edge: %d / %d / %d\n", N,
              worst, regions[0], regions[1], regions[2]);
  for (int r = 0; r < 3; ++r) EXPECT_GT(regions[r], 0) << N << " region kind " << r;
}

// The cover deviation bounds the distance of every point of the facet from
// the cover (the closest of its triangles), and is not loose by more than 3x.
template <int N>
void checkCoverDeviation(std::mt19937& rng) {
  std::uniform_real_distribution<Real> U(-1.0, 1.0);
  Real ratio = 0.0;
  for (int c = 0; c < 30; ++c) {
    const std::vector<Real> y = bowedFacet<N>(0.0, 0.0, 0.0, 1.0, 0.5 * U(rng), 0.5 * U(rng));
    const Real bound = coverDeviation<N>(y.data());
    Real pts[9][3], worst = 0.0;
    coverPoints<N>(y.data(), pts);
    const int n = 60;
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        Real u = -1.0 + 2.0 * i / n, v = -1.0 + 2.0 * j / n;
        if (kFacetCorners<N> == 3) {
          if (i + j > n) continue;
          u = Real(i) / n, v = Real(j) / n;
        }
        Real p[3], best = kInf;
        pointOnFacet<N>(y.data(), u, v, p);
        for (int t = 0; t < kCoverTriangles<N>; ++t) {
          const int* tri = coverTriangle<N>(t);
          Real xi[2], q[3];
          int region;
          best = std::min(best, projectOntoTriangle(p, pts[tri[0]], pts[tri[1]], pts[tri[2]], xi, q, region));
        }
        worst = std::max(worst, std::sqrt(best));
      }
    EXPECT_LE(worst, bound * (1.0 + 1e-12)) << N << " case " << c;
    ratio = std::max(ratio, worst / bound);
  }
  EXPECT_GT(ratio, 1.0 / 3.0);  // measured 0.64 .. 0.89
  std::printf("[curved 3D] %d-node facets: largest distance from the cover / bound = %.2f\n", N, ratio);
}

}  // namespace

TEST(CurvedFacets, ProjectionIsTheClosestPoint) {
  std::mt19937 rng(11);
  checkProjection<6>(rng);
  checkProjection<8>(rng);
  checkProjection<9>(rng);
}

TEST(CurvedFacets, CoverDeviationBoundsTheFacet) {
  std::mt19937 rng(5);
  checkCoverDeviation<6>(rng);
  checkCoverDeviation<8>(rng);
  checkCoverDeviation<9>(rng);
}

namespace {

// z of a pair: a bowed source facet facing down at height 1 above a bowed
// target facing up at 0, the source shifted by (dx, dy) so that its points
// project inside the target, onto an edge or onto a corner.
template <int NF, int NS>
std::vector<Real> pairCoordinates(Real dx, Real dy) {
  std::vector<Real> src = bowedFacet<NF>(0.1 + dx, 0.15 + dy, 0.45, 0.6, -0.15, 0.1);
  // facing down: reverse the orientation by mirroring the facet in its plane (x -> -x about its centre)
  const Real cx = 0.1 + dx + (kFacetCorners<NF> == 3 ? 0.2 : 0.0);
  for (int a = 0; a < NF; ++a) src[3 * a] = 2.0 * cx - src[3 * a];
  std::vector<Real> z = src;
  const std::vector<Real> tgt = bowedFacet<NS>(0.0, 0.0, 0.0, 1.0, 0.2, -0.15);
  z.insert(z.end(), tgt.begin(), tgt.end());
  return z;
}

template <int NF, int NS>
void checkKernel(Real dx, Real dy, Real delta, std::set<int>& regions, Real& worstK, Real& worstRho) {
  constexpr int nz = 3 * (NF + NS), nf = 3 * NF;
  auto lj = std::make_shared<LennardJones>(1.0, 0.3);
  const auto law = lawOf(*lj);
  const std::vector<Real> z = pairCoordinates<NF, NS>(dx, dy);
  for (const FacetPoint& q : facetQuadrature(NF, 2)) {
    const PatchFoot foot = facetFootOnTarget<NF, NS>(z.data(), q);
    Real f[nf], K[nf * nz], rho, Jrho[nz], f0[nf], rho0;
    const PairState st = method3CurvedPair3D<NF, NS>(z.data(), q, law, foot, delta, nullptr, f, rho, K, Jrho);
    method3CurvedPair3D<NF, NS>(z.data(), q, law, foot, delta, nullptr, f0, rho0, nullptr, nullptr);
    ASSERT_GT(st.distance, 0.0);
    EXPECT_LT(st.cosAlpha, 0.0) << "facing surfaces";
    regions.insert(st.region);
    Real kmax = 0.0, gmax = 0.0;
    for (int i = 0; i < nf; ++i) {
      EXPECT_NEAR(f0[i], f[i], 1e-13 * std::abs(f[i]) + 1e-300);
      for (int j = 0; j < nz; ++j) kmax = std::max(kmax, std::abs(K[i * nz + j]));
    }
    EXPECT_NEAR(rho0, rho, 1e-14);
    for (int j = 0; j < nz; ++j) gmax = std::max(gmax, std::abs(Jrho[j]));
    const Real h = 1e-6;
    for (int j = 0; j < nz; ++j) {
      std::vector<Real> zp = z, zm = z;
      zp[j] += h;
      zm[j] -= h;
      const PatchFoot fp = facetFootOnTarget<NF, NS>(zp.data(), q), fm = facetFootOnTarget<NF, NS>(zm.data(), q);
      ASSERT_EQ(fp.region, foot.region);
      ASSERT_EQ(fm.region, foot.region);
      Real ffp[nf], ffm[nf], rp, rm;
      method3CurvedPair3D<NF, NS>(zp.data(), q, law, fp, delta, nullptr, ffp, rp, nullptr, nullptr);
      method3CurvedPair3D<NF, NS>(zm.data(), q, law, fm, delta, nullptr, ffm, rm, nullptr, nullptr);
      for (int i = 0; i < nf; ++i)
        worstK = std::max(worstK, std::abs((ffp[i] - ffm[i]) / (2 * h) - K[i * nz + j]) / kmax);
      if (gmax > 0.0) worstRho = std::max(worstRho, std::abs((rp - rm) / (2 * h) - Jrho[j]) / gmax);
    }
  }
}

template <int NF, int NS>
void checkKernels() {
  std::set<int> regions;
  Real worstK = 0.0, worstRho = 0.0;
  // inside; beyond the edge v = min (onto it); beyond the corner; and the blend on
  for (const auto& [dx, dy] : std::vector<std::pair<Real, Real>>{{0.15, 0.1}, {0.2, -0.55}, {-0.6, -0.6}, {0.9, 0.5}})
    for (Real delta : {0.0, 0.05}) checkKernel<NF, NS>(dx, dy, delta, regions, worstK, worstRho);
  std::printf("[curved 3D] kernel %d on %d nodes: K vs central differences %.1e, d rho %.1e of max; regions", NF, NS,
              worstK, worstRho);
  for (int r : regions) std::printf(" %d", r);
  std::printf("\n");
  EXPECT_LT(worstK, 1e-6);
  EXPECT_LT(worstRho, 1e-6);
  constexpr int nc = kFacetCorners<NS>;
  bool inside = false, corner = false, edge = false;
  for (int r : regions) inside |= r == 0, corner |= r >= 1 && r <= nc, edge |= r > nc;
  EXPECT_TRUE(inside && corner && edge) << NF << " on " << NS;
}

}  // namespace

TEST(CurvedFacets, KernelTangentTri6) {
  checkKernels<6, 6>();
  checkKernels<6, 9>();
  checkKernels<6, 8>();
}
TEST(CurvedFacets, KernelTangentQuad9) {
  checkKernels<9, 9>();
  checkKernels<9, 6>();
  checkKernels<9, 8>();
}
TEST(CurvedFacets, KernelTangentQuad8) {
  checkKernels<8, 8>();
  checkKernels<8, 6>();
  checkKernels<8, 9>();
}

// On flat facets (mid nodes at the middle of their edges) the curved kernel
// gives the linear kernel's force on the point, in every region: the flat
// TRI6 target is the TRI3 through its corners.
TEST(CurvedFacets, FlatFacetsGiveTheLinearKernel) {
  auto lj = std::make_shared<LennardJones>(1.0, 0.3);
  const auto law = lawOf(*lj);
  std::set<int> regions;
  for (const auto& [dx, dy] : std::vector<std::pair<Real, Real>>{{0.15, 0.1}, {0.2, -0.55}, {-0.6, -0.6}}) {
    std::vector<Real> z = pairCoordinates<6, 6>(dx, dy);
    for (int a = 0; a < 6; ++a) z[3 * a + 2] = 0.45;  // the source flat
    for (int a = 0; a < 6; ++a) z[18 + 3 * a + 2] = 0.1 * z[18 + 3 * a] - 0.05 * z[18 + 3 * a + 1];  // the target a tilted plane
    Real zl[18];
    for (int a = 0; a < 3; ++a)
      for (int i = 0; i < 3; ++i) zl[3 * a + i] = z[3 * a + i], zl[9 + 3 * a + i] = z[18 + 3 * a + i];
    for (const FacetPoint& q6 : facetQuadrature(6, 3)) {
      FacetPoint q3 = q6;  // the same point with the linear shape functions
      q3.N[0] = 1.0 - q6.xi[0] - q6.xi[1], q3.N[1] = q6.xi[0], q3.N[2] = q6.xi[1];
      q3.dN[0][0] = -1.0, q3.dN[0][1] = 1.0, q3.dN[0][2] = 0.0, q3.dN[1][0] = -1.0, q3.dN[1][1] = 0.0, q3.dN[1][2] = 1.0;
      Real f6[18], f3[9], rho;
      const PairState s6 =
          method3CurvedPair3D<6, 6>(z.data(), q6, law, facetFootOnTarget<6, 6>(z.data(), q6), 0.0, nullptr, f6, rho,
                                    nullptr, nullptr);
      const PairState s3 = method3Pair3D<3>(zl, q3, law, f3, nullptr);
      regions.insert(s6.region);
      EXPECT_NEAR(s6.distance, s3.distance, 1e-14);
      EXPECT_NEAR(s6.cosAlpha, s3.cosAlpha, 1e-14);
      for (int i = 0; i < 3; ++i) {
        Real a6 = 0.0, a3 = 0.0;
        for (int a = 0; a < 6; ++a) a6 += f6[3 * a + i];
        for (int a = 0; a < 3; ++a) a3 += f3[3 * a + i];
        EXPECT_NEAR(a6, a3, 1e-13 * std::abs(a3) + 1e-300);
      }
    }
  }
  EXPECT_GE(regions.size(), 3u);
}

namespace {

// The lower face of a cube sphere of radius R about (0, 0, c): a (2m + 1)^2
// grid of points on the sphere (equiangular on the face z = -1 of the cube),
// as m x m curved facets with nodesPerFacet 9, 8 or 6 (two TRI6 per square)
// or as the 2m x 2m flat QUAD4 facets through the same points; outward
// normals (away from the centre).
mesh::Surface sphereCap(std::vector<Real>& coords, Real R, Real c, int m, int nodesPerFacet, int body) {
  const int n = 2 * m + 1;
  const LocalIndex first = LocalIndex(coords.size() / 3);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Real a = std::tan(0.25 * kPi * (-1.0 + 2.0 * i / (n - 1))), b = std::tan(0.25 * kPi * (-1.0 + 2.0 * j / (n - 1)));
      const Real len = std::sqrt(a * a + b * b + 1.0);
      coords.insert(coords.end(), {R * a / len, R * b / len, c - R / len});
    }
  auto id = [&](int i, int j) { return first + LocalIndex(j * n + i); };
  mesh::Surface s{body, nodesPerFacet, {}, {}};
  // seen from below (outside) the grid's (i, j) turn clockwise: corners (i, j), (i, j+1), (i+1, j+1), (i+1, j)
  if (nodesPerFacet == 4) {
    for (int j = 0; j + 1 < n; ++j)
      for (int i = 0; i + 1 < n; ++i) s.facets.insert(s.facets.end(), {id(i, j), id(i, j + 1), id(i + 1, j + 1), id(i + 1, j)});
    return s;
  }
  for (int j = 0; j + 2 < n; j += 2)
    for (int i = 0; i + 2 < n; i += 2) {
      const LocalIndex c0 = id(i, j), c1 = id(i, j + 2), c2 = id(i + 2, j + 2), c3 = id(i + 2, j);
      const LocalIndex m01 = id(i, j + 1), m12 = id(i + 1, j + 2), m23 = id(i + 2, j + 1), m30 = id(i + 1, j),
                       centre = id(i + 1, j + 1);
      if (nodesPerFacet == 9) s.facets.insert(s.facets.end(), {c0, c1, c2, c3, m01, m12, m23, m30, centre});
      else if (nodesPerFacet == 8) s.facets.insert(s.facets.end(), {c0, c1, c2, c3, m01, m12, m23, m30});
      else s.facets.insert(s.facets.end(), {c0, c1, c2, m01, m12, centre, c0, c2, c3, centre, m23, m30});
    }
  return s;
}

// The flat z = 0 over [-L, L]^2, outward normal up: k x k QUAD9 facets, or 2k x 2k QUAD4.
mesh::Surface flatSquare(std::vector<Real>& coords, Real L, int k, int nodesPerFacet, int body) {
  const int n = 2 * k + 1;
  const LocalIndex first = LocalIndex(coords.size() / 3);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) coords.insert(coords.end(), {-L + 2.0 * L * i / (n - 1), -L + 2.0 * L * j / (n - 1), 0.0});
  auto id = [&](int i, int j) { return first + LocalIndex(j * n + i); };
  mesh::Surface s{body, nodesPerFacet, {}, {}};
  const int step = nodesPerFacet == 4 ? 1 : 2;
  for (int j = 0; j + step < n; j += step)
    for (int i = 0; i + step < n; i += step) {
      if (nodesPerFacet == 4) {
        s.facets.insert(s.facets.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
        continue;
      }
      const std::vector<LocalIndex> q9 = {id(i, j),     id(i + 2, j),     id(i + 2, j + 2), id(i, j + 2), id(i + 1, j),
                                          id(i + 2, j + 1), id(i + 1, j + 2), id(i, j + 1),     id(i + 1, j + 1)};
      s.facets.insert(s.facets.end(), q9.begin(), q9.begin() + nodesPerFacet);
    }
  return s;
}

// int_0^a g(t) dt: composite 16-point Gauss on 400 panels.
template <class G>
Real integrate0(const G& g, Real a) {
  const GaussRule rule = gaussLegendreUnit(16);
  const int panels = 400;
  Real sum = 0.0;
  for (int p = 0; p < panels; ++p)
    for (int q = 0; q < rule.size(); ++q) sum += rule.weights[q] * g(a * (p + rule.points[q]) / panels);
  return sum * a / panels;
}

}  // namespace

// A rigid sphere (R = 1) at gap 1.5 r0 over a flat (r0 = 0.02: the
// attractive side of the Lennard-Jones law, cutoff 10 r0), the sphere's lower
// cap meshed with m x m curved facets through points on the sphere, or with
// the 2m x 2m flat facets through the same points. Each direction separately
// against the exact Method 3 integral of the same law: the sphere's points
// on the flat, int T(h) cos(theta) 2 pi R^2 sin(theta) dtheta, h = D + R (1 -
// cos theta); the flat's points on the sphere, -int T(d - R) (c/d)^2 2 pi rho
// d rho, d = |(rho, -c)|. The curved facets carry the force within 0.5 %
// already on coarse caps; the flat facets through the same points are off by
// their sag (of the order of r0 on these meshes).
TEST(CurvedFacets, SphereOverAFlatCarriesTheExactForce) {
  const Real R = 1.0, r0 = 0.02, D = 1.5 * r0, c = R + D, L = 0.75;
  auto lj = std::make_shared<LennardJones>(1.0, r0);
  SurfaceInteractionOptions options;
  options.formulation = Formulation::ThreeD;
  options.quadraturePoints = 5;  // the quadrature converged to 1e-4 on every facet: the geometry is what differs
  Real exact[2] = {0.0, 0.0};
  {
    std::vector<Real> coords;
    SurfaceInteraction si({flatSquare(coords, L, 2, 9, 0), sphereCap(coords, R, c, 2, 9, 1)}, {1.0, 1.0}, lj, options);
    const auto law = si.law(std::get<InversePowerPair>(si.kernelPotential()), 0, 1);
    auto T = [&](Real r) {
      Real t, dt;
      law(r, t, dt);
      return t;
    };
    exact[0] = integrate0([&](Real th) { return T(D + R * (1.0 - std::cos(th))) * std::cos(th) * 2.0 * kPi * R * R * std::sin(th); },
                          std::acos(1.0 - (si.cutoff() - D) / R));
    exact[1] = integrate0(
        [&](Real rho) {
          const Real d = std::hypot(rho, c);
          return -T(d - R) * (c / d) * (c / d) * 2.0 * kPi * rho;
        },
        std::sqrt((R + si.cutoff()) * (R + si.cutoff()) - c * c));
  }
  auto error = [&](int nodesPerFacet, int m) {
    std::vector<Real> coords;
    const int flatNodes = nodesPerFacet == 4 ? 4 : 9;
    std::vector<mesh::Surface> s = {flatSquare(coords, L, 12, flatNodes, 0), sphereCap(coords, R, c, m, nodesPerFacet, 1)};
    SurfaceInteraction si(s, {1.0, 1.0}, lj, options);
    std::array<Real, 2> e{};
    for (int dir = 0; dir < 2; ++dir) {
      std::vector<std::vector<char>> on = {std::vector<char>(s[0].numFacets(), dir == 1),
                                           std::vector<char>(s[1].numFacets(), dir == 0)};
      si.setEvaluatedFacets(on);
      si.updatePairs(coords);
      si.evaluate(coords.data(), [](const auto&) {}, false);  // the resultants alone: no stored contributions
      const Real F = si.summary().resultant[dir == 0 ? 1 : 0][2];
      e[dir] = std::abs(F / exact[dir] - 1.0);
    }
    return e;
  };
  // measured (sphere's points / flat's points): flat 0.32 / 0.10 / 0.027 at m = 4, 8, 16 (second
  // order); QUAD9 3.3e-3 / 2.5e-4 / 1.2e-5, QUAD8 2.4e-2 / 2.2e-3 / 1.4e-4, TRI6 1.7e-2 / 1.1e-3 / 7e-5
  // (third to fourth order): the QUAD9 cap of 81 points within 0.5 %, every curved one from 289 points
  for (int m : {4, 8}) {
    const auto flat = error(4, m);
    std::printf("[curved 3D] sphere over a flat, %2d x %2d cap (%4d points): flat QUAD4 %.2e / %.2e", m, m,
                (2 * m + 1) * (2 * m + 1), flat[0], flat[1]);
    for (int npf : {9, 8, 6}) {
      const auto curvedError = error(npf, m);
      std::printf(", %d nodes %.2e / %.2e", npf, curvedError[0], curvedError[1]);
      for (int dir = 0; dir < 2; ++dir) {
        if (m == 8 || npf == 9) {  // braces: EXPECT_LT is an if-else of its own
          EXPECT_LT(curvedError[dir], 5e-3) << npf << " m " << m << " dir " << dir;
        }
        EXPECT_LT(curvedError[dir], (m == 4 ? 0.1 : 0.03) * flat[dir]) << npf << " m " << m << " dir " << dir;
      }
    }
    std::printf(" (sphere's points / flat's points)\n");
  }
}
