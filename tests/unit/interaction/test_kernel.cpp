// Method 3 pair kernel: hand-derived tangent against central finite
// differences of the kernel residual and against forward AD (Sacado).
#include <gtest/gtest.h>

#include <Sacado.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "cgcm/interaction/Method3Kernel.hpp"
#include "cgcm/interaction/PairPotential.hpp"
#include "cgcm/interaction/Quadrature.hpp"
#include "cgcm/interaction/SurfaceInteraction.hpp"

using namespace cgcm;
using namespace cgcm::interaction;

namespace {

using Fad = Sacado::Fad::SFad<Real, 8>;

constexpr Real kBeta1 = 1.5, kBeta2 = 0.8;

struct Case {
  std::string name;
  Real z[8];
  int expectedRegion;  ///< -1: any (varies over the quadrature points)
};

// Segment e of the upper body (outward normal down: a -> b to the right),
// segment s of the lower body (outward normal up: a -> b to the left).
std::vector<Case> cases(Real shiftX) {
  std::vector<Case> c;
  c.push_back({"interior", {0.1, 0.95, 1.2, 1.1, 1.6, 0.1, -0.4, -0.05}, 0});
  c.push_back({"interior-close", {0.2, 0.62, 0.9, 0.70, 1.3, 0.05, -0.2, 0.0}, 0});
  // s lies to the right of e: the projection is s's vertex b (left end)
  c.push_back({"vertex-b", {0.1, 0.95, 1.2, 1.1, 3.1, 0.2, 2.0, 0.0}, 2});
  // s lies to the left of e: the projection is s's vertex a (right end)
  c.push_back({"vertex-a", {0.1, 0.95, 1.2, 1.1, -0.6, 0.1, -1.8, 0.3}, 1});
  for (Case& k : c)
    for (int i = 0; i < 8; i += 2) k.z[i] += shiftX;
  return c;
}

template <Formulation F>
void residual(const Real z[8], Real xi, Real w, const SurfaceInteraction::Law& law, Real f[4]) {
  method3Pair<F>(z, xi, w, law, f, nullptr);
}

template <Formulation F>
void checkCase(const Case& c, const PairPotential& pot) {
  const SurfaceInteraction::Law law{&pot, kBeta1 * kBeta2};
  const GaussRule rule = gaussLegendreUnit(4);
  Real worstFd = 0.0, worstAd = 0.0;
  for (int q = 0; q < rule.size(); ++q) {
    const Real xi = rule.points[q], w = rule.weights[q];
    Real f[4], K[4][8];
    const PairState st = method3Pair<F>(c.z, xi, w, law, f, K);
    if (c.expectedRegion >= 0) {
      ASSERT_EQ(st.region, c.expectedRegion) << c.name << " qp " << q;
    }
    ASSERT_GT(st.distance, 0.0);
    // facing surfaces
    EXPECT_LT(st.cosAlpha, 0.0) << c.name;

    // central finite differences of the kernel residual, step 1e-6 (coordinates O(1))
    Real Kfd[4][8];
    const Real h = 1e-6;
    for (int j = 0; j < 8; ++j) {
      Real zp[8], zm[8], fp[4], fm[4];
      std::copy(c.z, c.z + 8, zp);
      std::copy(c.z, c.z + 8, zm);
      zp[j] += h;
      zm[j] -= h;
      residual<F>(zp, xi, w, law, fp);
      residual<F>(zm, xi, w, law, fm);
      for (int i = 0; i < 4; ++i) Kfd[i][j] = (fp[i] - fm[i]) / (2 * h);
    }

    // forward AD of the generic residual over the 8 coordinates
    Fad zf[8], ff[4];
    for (int j = 0; j < 8; ++j) zf[j] = Fad(8, j, c.z[j]);
    const Real C = kBeta1 * kBeta2 * 3.14159265358979323846 * pot.epsilon() * std::pow(pot.r0(), 3);
    const bool repulsiveOnly = pot.name() == "repulsive";
    auto traction = [&](const Fad& r) {
      const Fad s = pot.r0() / r;
      const Fad s3 = s * s * s;
      return Fad(C * (s3 * s3 * s3 / 45.0 - (repulsiveOnly ? 0.0 : 1.0) * s3 / 3.0));
    };
    method3PairResidualGeneric<F>(zf, xi, w, traction, ff);

    Real kmax = 0.0;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 8; ++j) kmax = std::max(kmax, std::abs(K[i][j]));
    ASSERT_GT(kmax, 0.0);
    for (int i = 0; i < 4; ++i) {
      EXPECT_NEAR(ff[i].val(), f[i], 1e-13 * kmax) << c.name;
      for (int j = 0; j < 8; ++j) {
        worstFd = std::max(worstFd, std::abs(K[i][j] - Kfd[i][j]) / kmax);
        worstAd = std::max(worstAd, std::abs(K[i][j] - ff[i].dx(j)) / kmax);
      }
    }
  }
  std::printf("[kernel] %-13s %-14s %-13s max|K - K_fd|/max|K| = %.2e, max|K - K_ad|/max|K| = %.2e\n",
              formulationName(F), c.name.c_str(), pot.name().c_str(), worstFd, worstAd);
  // tolerances: 1e-6 relative to FD (step 1e-6), 1e-12 relative to AD (exact)
  EXPECT_LT(worstFd, 1e-6) << c.name;
  EXPECT_LT(worstAd, 1e-12) << c.name;
}

}  // namespace

TEST(Method3Kernel, TangentPlaneStrain) {
  const LennardJones lj(1.0, 1.0);
  const RepulsiveLennardJones rep(1.0, 1.0);
  for (const Case& c : cases(0.0)) {
    checkCase<Formulation::PlaneStrain>(c, lj);
    checkCase<Formulation::PlaneStrain>(c, rep);
  }
}

TEST(Method3Kernel, TangentAxisymmetric) {
  const LennardJones lj(1.0, 1.0);
  // shift to rho > 0: every radial coordinate positive
  for (const Case& c : cases(2.5)) checkCase<Formulation::Axisymmetric>(c, lj);
  // the axis itself (node at rho = 0)
  Case onAxis{"axis-node", {0.0, 0.95, 1.1, 1.1, 1.6, 0.1, 0.0, -0.05}, 0};
  checkCase<Formulation::Axisymmetric>(onAxis, lj);
}

TEST(Method3Kernel, TangentOfTheOtherBodysPoint) {
  // The lower body's quadrature point projecting onto the upper segment:
  // the same kernel with the roles of the two segments swapped.
  const LennardJones lj(1.0, 1.0);
  for (const Case& c : cases(0.0)) {
    if (c.expectedRegion != 0) continue;
    Case swapped{c.name + "-swapped", {}, -1};
    std::copy(c.z + 4, c.z + 8, swapped.z);
    std::copy(c.z, c.z + 4, swapped.z + 4);
    checkCase<Formulation::PlaneStrain>(swapped, lj);
    for (int i = 0; i < 8; i += 2) swapped.z[i] += 2.5;
    checkCase<Formulation::Axisymmetric>(swapped, lj);
  }
}

TEST(Method3Kernel, SignAndMagnitudeForParallelSegments) {
  // Parallel facing segments at gap h: f = N_a T(h) rbar (rbar.n) ds, with
  // rbar = +y (from the lower surface to the upper point), n = -y: the force
  // applied to the upper body, -f, is +T ds in y (repulsive for T > 0).
  const LennardJones lj(1.0, 1.0);
  const SurfaceInteraction::Law law{&lj, 1.0};
  for (Real h : {0.5, 1.0}) {
    const Real z[8] = {0.0, h, 1.0, h, 5.0, 0.0, -5.0, 0.0};
    Real f[4];
    const PairState st = method3Pair<Formulation::PlaneStrain>(z, 0.5, 1.0, law, f, nullptr);
    EXPECT_NEAR(st.cosAlpha, -1.0, 1e-15);
    EXPECT_NEAR(st.distance, h, 1e-15);
    const Real T = lj.halfSpace(h);
    EXPECT_NEAR(-(f[1] + f[3]), T, 1e-14 * std::abs(T));  // ds = 1, w = 1
    EXPECT_NEAR(f[0] + f[2], 0.0, 1e-15);
  }
}
