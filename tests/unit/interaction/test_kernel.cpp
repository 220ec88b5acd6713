// Method 3 pair kernel: hand-derived tangent against central finite
// differences of the kernel residual and against forward AD (Sacado).
#include <gtest/gtest.h>

#include <Sacado.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
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
constexpr Real kNoCutoff = std::numeric_limits<Real>::infinity();

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
void residual(const Real z[8], Real xi, Real w, const TractionLaw<InversePowerPair>& law, Real f[4],
              const Real* referenceArea) {
  method3Pair<F>(z, xi, w, law, f, nullptr, nullptr, referenceArea);
}

// referenceArea: the constant dA of SurfaceDensity::ReferenceArea, or null (the current da)
template <Formulation F>
void checkCase(const Case& c, const PairPotential& pot, const Real* referenceArea = nullptr) {
  const TractionLaw<InversePowerPair> law{std::get<InversePowerPair>(pot.kernelPotential()), kBeta1 * kBeta2, kNoCutoff,
                                          kNoCutoff};
  const GaussRule rule = gaussLegendreUnit(4);
  Real worstFd = 0.0, worstAd = 0.0;
  for (int q = 0; q < rule.size(); ++q) {
    const Real xi = rule.points[q], w = rule.weights[q];
    Real f[4], K[4][8];
    const PairState st = method3Pair<F>(c.z, xi, w, law, f, K, nullptr, referenceArea);
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
      residual<F>(zp, xi, w, law, fp, referenceArea);
      residual<F>(zm, xi, w, law, fm, referenceArea);
      for (int i = 0; i < 4; ++i) Kfd[i][j] = (fp[i] - fm[i]) / (2 * h);
    }

    // forward AD of the generic residual over the 8 coordinates
    Fad zf[8], ff[4];
    for (int j = 0; j < 8; ++j) zf[j] = Fad(8, j, c.z[j]);
    const Real C = kBeta1 * kBeta2 * kPi * pot.epsilon() * std::pow(pot.r0(), 3);
    const bool repulsiveOnly = pot.name() == "repulsive";
    auto traction = [&](const Fad& r) {
      const Fad s = pot.r0() / r;
      const Fad s3 = s * s * s;
      return Fad(C * (s3 * s3 * s3 / 45.0 - (repulsiveOnly ? 0.0 : 1.0) * s3 / 3.0));
    };
    method3PairResidualGeneric<F>(zf, xi, w, traction, ff, referenceArea);

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
  std::printf("[kernel] %-13s %-14s %-13s %s max|K - K_fd|/max|K| = %.2e, max|K - K_ad|/max|K| = %.2e\n",
              formulationName(F), c.name.c_str(), pot.name().c_str(), referenceArea ? "dA" : "da", worstFd, worstAd);
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

TEST(Method3Kernel, TangentWithTheReferenceArea) {
  const LennardJones lj(1.0, 1.0);
  const Real dA = 0.37;  // any constant: the kernel takes it as given
  for (const Case& c : cases(0.0)) checkCase<Formulation::PlaneStrain>(c, lj, &dA);
  for (const Case& c : cases(2.5)) checkCase<Formulation::Axisymmetric>(c, lj, &dA);
}

// Given the current da as dA, the reference-area residual is the current-area one bit for bit,
// and the tangents differ by the d(da)/dz term alone: T c rbar (x) d(da)/dz, rank one per node.
TEST(Method3Kernel, ReferenceAreaEqualToTheCurrentOneChangesOnlyTheAreaTerm) {
  const LennardJones lj(1.0, 1.0);
  const TractionLaw<InversePowerPair> law{std::get<InversePowerPair>(lj.kernelPotential()), kBeta1 * kBeta2, kNoCutoff,
                                          kNoCutoff};
  const Case c = cases(0.0)[0];
  const Real xi = 0.3, w = 0.25;
  const Real da = std::hypot(c.z[2] - c.z[0], c.z[3] - c.z[1]) * w;
  Real f[4], K[4][8], fA[4], KA[4][8];
  method3Pair<Formulation::PlaneStrain>(c.z, xi, w, law, f, K);
  method3Pair<Formulation::PlaneStrain>(c.z, xi, w, law, fA, KA, nullptr, &da);
  // d(da)/dz: da = |t| w with t = z_b - z_a of the point's segment
  const Real L = std::hypot(c.z[2] - c.z[0], c.z[3] - c.z[1]);
  const Real e[2] = {(c.z[2] - c.z[0]) / L, (c.z[3] - c.z[1]) / L};
  const Real Jda[8] = {-e[0] * w, -e[1] * w, e[0] * w, e[1] * w, 0, 0, 0, 0};
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(fA[i], f[i]);
    for (int j = 0; j < 8; ++j) EXPECT_NEAR(K[i][j] - KA[i][j], f[i] / da * Jda[j], 1e-12 * std::abs(K[i][j]) + 1e-15);
  }
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
  const TractionLaw<InversePowerPair> law{std::get<InversePowerPair>(lj.kernelPotential()), 1.0, kNoCutoff, kNoCutoff};
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

TEST(Method3Kernel, CutoffTaperIsContinuouslyDifferentiable) {
  // T S(r) with the C1 taper on [1.6, 2]: T and dT/dr continuous at both ends,
  // dT/dr the derivative of T inside the band, and T = 0 from the cutoff on.
  const LennardJones lj(1.0, 1.0);
  const TractionLaw<InversePowerPair> law{std::get<InversePowerPair>(lj.kernelPotential()), kBeta1 * kBeta2, 1.6, 2.0};
  const TractionLaw<InversePowerPair> sharp{std::get<InversePowerPair>(lj.kernelPotential()), kBeta1 * kBeta2,
                                            kNoCutoff, kNoCutoff};
  auto T = [&](const TractionLaw<InversePowerPair>& l, Real r) {
    Real t, dt;
    l(r, t, dt);
    return std::pair<Real, Real>{t, dt};
  };
  const Real eps = 1e-9;
  const auto below = T(law, 1.6 - eps), above = T(law, 1.6 + eps), unTapered = T(sharp, 1.6);
  EXPECT_EQ(below.first, T(sharp, 1.6 - eps).first);
  EXPECT_NEAR(above.first, T(sharp, 1.6 + eps).first, 1e-15);
  EXPECT_NEAR(above.second, unTapered.second, 1e-7);  // C1: the slopes differ by O(eps)
  const auto atCutoff = T(law, 2.0 - eps);
  EXPECT_NEAR(atCutoff.first, 0.0, 1e-12);
  EXPECT_NEAR(atCutoff.second, 0.0, 1e-7);
  EXPECT_EQ(T(law, 2.0).first, 0.0);
  EXPECT_EQ(T(law, 2.5).second, 0.0);
  Real worst = 0.0;
  for (Real r = 1.62; r < 2.0; r += 0.02) {
    const Real h = 1e-6, fd = (T(law, r + h).first - T(law, r - h).first) / (2 * h);
    worst = std::max(worst, std::abs(T(law, r).second - fd) / std::abs(unTapered.second));
  }
  EXPECT_LT(worst, 1e-7);
  // strictly between the untapered traction and zero inside the band
  const Real mid = T(law, 1.8).first, full = T(sharp, 1.8).first;
  EXPECT_GT(mid / full, 0.0);
  EXPECT_LT(mid / full, 1.0);
  EXPECT_NEAR(mid / full, 0.5, 1e-12);  // S(1/2) = 1/2
}

TEST(SurfaceInteractionCutoff, NeglectedWorkOfTheTaperedCutoff) {
  // Lennard-Jones: Phi/beta ~ -(pi/3) r0^6 / r^3 far out, so a sharp cutoff
  // at r_c removes (pi/6) r0^6 / r_c^2 of w/(beta1 beta2) = (pi/8) 15^(1/3) r0^4.
  const LennardJones lj(1.0, 1.0);
  const Real w = lj.adhesionWorkCoefficient();
  const Real rc = 10.0;
  const Real farField = (kPi / 6.0) / (rc * rc) / w;
  const Real sharp = neglectedWorkFraction(lj, rc, rc);
  EXPECT_NEAR(sharp, farField, 1e-3 * farField);  // the r^-9 term adds 1e-6 relative
  // the taper removes more, but less than a sharp cutoff at its start
  const Real tapered = neglectedWorkFraction(lj, 0.8 * rc, rc);
  EXPECT_GT(tapered, sharp);
  EXPECT_LT(tapered, neglectedWorkFraction(lj, 0.8 * rc, 0.8 * rc));
  EXPECT_EQ(neglectedWorkFraction(RepulsiveLennardJones(1.0, 1.0), 8.0, 10.0), 0.0);
  EXPECT_EQ(neglectedWorkFraction(lj, kNoCutoff, kNoCutoff), 0.0);
}
