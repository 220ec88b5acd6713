// Method 3 pair kernel in 3D: the AD tangent against central finite
// differences of the residual for triangle and quadrilateral facets, with
// projections onto the face, the edges and the vertices of the target
// triangle; the integrand against the half-space traction of parallel faces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <set>
#include <vector>

#include "cgcm/interaction/Method3Kernel3D.hpp"
#include "cgcm/interaction/PairPotential.hpp"
#include "cgcm/interaction/SurfaceInteraction.hpp"

using namespace cgcm;
using namespace cgcm::interaction;

namespace {

constexpr Real kNoCutoff = std::numeric_limits<Real>::infinity();

// Target triangle, slightly tilted, outward normal up (+z).
const Real kTarget[9] = {0.0, 0.0, 0.0, 2.0, 0.1, 0.05, 0.2, 1.8, -0.05};

// Source facets above it, outward normal down (facing the target), around (0.5, 0.5, 1).
std::vector<Real> sourceFacet(int nodes, Real dx, Real dy) {
  std::vector<Real> z;
  if (nodes == 3) z = {0.5, 0.5, 1.0, 0.5, 1.0, 1.02, 1.0, 0.5, 0.98};
  else z = {0.4, 0.4, 1.0, 0.4, 0.9, 1.0, 0.9, 0.9, 1.03, 0.9, 0.4, 1.0};
  for (int a = 0; a < nodes; ++a) z[3 * a] += dx, z[3 * a + 1] += dy;
  z.insert(z.end(), kTarget, kTarget + 9);
  return z;
}

template <int NF>
Real worstTangentError(const std::vector<Real>& z, const TractionLaw<InversePowerPair>& law, std::set<int>& regions,
                       const Real* referenceArea = nullptr) {
  constexpr int nz = 3 * NF + 9, nf = 3 * NF;
  Real worst = 0.0;
  for (const FacetPoint& q : facetQuadrature(NF, 3)) {
    Real f[nf], K[nf * nz];
    const PairState st = method3Pair3D<NF>(z.data(), q, law, f, K, referenceArea);
    EXPECT_GT(st.distance, 0.0);
    EXPECT_LT(st.cosAlpha, 0.0);  // facing surfaces
    regions.insert(st.region);
    Real f0[nf];
    method3Pair3D<NF>(z.data(), q, law, f0, nullptr, referenceArea);
    Real kmax = 0.0;
    for (int i = 0; i < nf; ++i) {
      EXPECT_NEAR(f0[i], f[i], 1e-14 * std::abs(f[i]) + 1e-300);
      for (int j = 0; j < nz; ++j) kmax = std::max(kmax, std::abs(K[i * nz + j]));
    }
    const Real h = 1e-6;
    for (int j = 0; j < nz; ++j) {
      std::vector<Real> zp = z, zm = z;
      zp[j] += h;
      zm[j] -= h;
      Real fp[nf], fm[nf];
      method3Pair3D<NF>(zp.data(), q, law, fp, nullptr, referenceArea);
      method3Pair3D<NF>(zm.data(), q, law, fm, nullptr, referenceArea);
      for (int i = 0; i < nf; ++i)
        worst = std::max(worst, std::abs(K[i * nz + j] - (fp[i] - fm[i]) / (2 * h)) / kmax);
    }
  }
  return worst;
}

}  // namespace

TEST(Method3Kernel3D, TangentOnFacesEdgesAndVertices) {
  const LennardJones lj(1.0, 1.0);
  const RepulsiveLennardJones rep(1.0, 1.0);
  // lateral shifts of the source facet: above the face, beyond each edge and each vertex
  const Real shifts[][2] = {{0.0, 0.0}, {-1.5, -1.5}, {0.6, -1.5}, {2.5, -0.3}, {1.0, 1.2},
                            {-0.2, 2.3}, {-1.5, 0.6}, {-0.2, 0.1}};
  for (const PairPotential* pot : {static_cast<const PairPotential*>(&lj), static_cast<const PairPotential*>(&rep)}) {
    const TractionLaw<InversePowerPair> law{std::get<InversePowerPair>(pot->kernelPotential()), 1.2, kNoCutoff,
                                            kNoCutoff};
    const Real dA = 0.21;  // SurfaceDensity::ReferenceArea: any constant, the kernel takes it as given
    for (const Real* referenceArea : {static_cast<const Real*>(nullptr), &dA}) {
      std::set<int> regions;
      Real worst3 = 0.0, worst4 = 0.0;
      for (const auto& s : shifts) {
        worst3 = std::max(worst3, worstTangentError<3>(sourceFacet(3, s[0], s[1]), law, regions, referenceArea));
        worst4 = std::max(worst4, worstTangentError<4>(sourceFacet(4, s[0], s[1]), law, regions, referenceArea));
      }
      std::printf("[kernel3d] %-12s %s max|K - K_fd|/max|K|: tri3 %.2e, quad4 %.2e; regions met %zu of 7\n",
                  pot->name().c_str(), referenceArea ? "dA" : "da", worst3, worst4, regions.size());
      EXPECT_EQ(regions.size(), 7u) << "face, 3 edges and 3 vertices";
      EXPECT_LT(worst3, 1e-6);
      EXPECT_LT(worst4, 1e-6);
    }
  }
}

TEST(Method3Kernel3D, ParallelFacesCarryTheHalfSpaceTraction) {
  // A flat unit square facing a (large) flat triangle at distance d: the
  // forces on the square sum to -T(d) times its area along the normal.
  const LennardJones lj(1.0, 1.0);
  const TractionLaw<InversePowerPair> law{std::get<InversePowerPair>(lj.kernelPotential()), 1.0, kNoCutoff, kNoCutoff};
  const Real d = 1.3;
  std::vector<Real> z = {0.0, 0.0, d, 0.0, 1.0, d, 1.0, 1.0, d, 1.0, 0.0, d,
                         -5.0, -5.0, 0.0, 10.0, -5.0, 0.0, -5.0, 10.0, 0.0};
  Real sum[3] = {0.0, 0.0, 0.0};
  for (const FacetPoint& q : facetQuadrature(4, 2)) {
    Real f[12];
    method3Pair3D<4>(z.data(), q, law, f, nullptr);
    for (int a = 0; a < 4; ++a)
      for (int i = 0; i < 3; ++i) sum[i] += f[3 * a + i];
  }
  Real T, dT;
  law(d, T, dT);
  EXPECT_NEAR(sum[2], -T, 1e-14 * std::abs(T));
  EXPECT_NEAR(sum[0], 0.0, 1e-15 * std::abs(T));
  EXPECT_NEAR(sum[1], 0.0, 1e-15 * std::abs(T));
  // the triangle rule integrates the area exactly too
  Real area = 0.0;
  for (const FacetPoint& q : facetQuadrature(3, 3)) area += q.weight;
  EXPECT_NEAR(area, 0.5, 1e-15);
}

TEST(FacetQuadrature, TriangleRulesAreSymmetricAndExact) {
  // integral of s^i t^j over the reference triangle = i! j! / (i + j + 2)!
  auto exact = [](int i, int j) {
    return std::tgamma(i + 1.0) * std::tgamma(j + 1.0) / std::tgamma(i + j + 3.0);
  };
  for (int n = 1; n <= 5; ++n) {
    const auto rule = facetQuadrature(3, n);
    for (int i = 0; i <= 2 * n - 1; ++i)
      for (int j = 0; i + j <= 2 * n - 1; ++j) {
        Real sum = 0.0;
        for (const auto& q : rule) {
          EXPECT_GT(q.weight, 0.0);
          sum += q.weight * std::pow(q.N[1], i) * std::pow(q.N[2], j);
        }
        EXPECT_NEAR(sum, exact(i, j), 1e-14) << "n = " << n << ", s^" << i << " t^" << j;
      }
    // swapping two vertices maps the rule onto itself
    for (const auto& q : rule) {
      bool found = false;
      for (const auto& p : rule)
        found = found || (std::abs(p.N[1] - q.N[2]) < 1e-15 && std::abs(p.N[2] - q.N[1]) < 1e-15 &&
                          std::abs(p.weight - q.weight) < 1e-16);
      EXPECT_TRUE(found) << "n = " << n;
    }
  }
}
