// Unit tests of the compressible Neo-Hookean law: stress-free reference state,
// small-strain limit, stress = derivative of the energy, spatial moduli =
// Truesdell rate of the Kirchhoff stress, and input validation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>

#include "cgcm/material/NeoHookean.hpp"

using cgcm::Mat3;
using cgcm::Real;
using cgcm::material::NeoHookean;
using cgcm::material::VolumetricLaw;

namespace {

const VolumetricLaw kLaws[] = {VolumetricLaw::LogSquared, VolumetricLaw::QuadraticJ};

Mat3 leftCauchyGreen(const Mat3& F) { return F * cgcm::transpose(F); }

Real maxAbs(const Mat3& A) {
  Real m = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m = std::max(m, std::abs(A.a[i][j]));
  return m;
}

Mat3 operator-(const Mat3& A, const Mat3& B) {
  Mat3 C;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) C.a[i][j] = A.a[i][j] - B.a[i][j];
  return C;
}

/// A random finite deformation gradient: identity + perturbation of size `amplitude`, det > 0.
Mat3 randomF(std::mt19937& rng, Real amplitude) {
  std::uniform_real_distribution<Real> u(-amplitude, amplitude);
  for (;;) {
    Mat3 F = Mat3::identity();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) F.a[i][j] += u(rng);
    if (cgcm::det(F) > 0.3) return F;
  }
}

Mat3 randomMat(std::mt19937& rng) {
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  Mat3 A;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) A.a[i][j] = u(rng);
  return A;
}

// The stress the element kernels use: from the displacement gradient F − I.
Mat3 stressOf(const NeoHookean& m, const Mat3& F) {
  Mat3 H = F;
  for (int i = 0; i < 3; ++i) H.a[i][i] -= 1.0;
  return m.cauchyOfDisplacementGradient(H);
}

Mat3 kirchhoffOf(const NeoHookean& m, const Mat3& F) { return m.kirchhoff(leftCauchyGreen(F), cgcm::det(F)); }

}  // namespace

TEST(NeoHookean, ParametersFromYoungPoisson) {
  const NeoHookean m = NeoHookean::fromYoungPoisson(2.5, 0.2);
  const Real tol = 1e-14;
  EXPECT_NEAR(m.mu, 2.5 / 2.4, tol);
  EXPECT_NEAR(m.lambda, 2.0 * m.mu * 0.2 / 0.6, tol);
  EXPECT_NEAR(m.youngsModulus(), 2.5, tol);
  EXPECT_NEAR(m.poissonRatio(), 0.2, tol);
  EXPECT_EQ(m.law, VolumetricLaw::LogSquared);
  const NeoHookean q = NeoHookean::fromLame(m.lambda, m.mu, VolumetricLaw::QuadraticJ);
  EXPECT_EQ(q.law, VolumetricLaw::QuadraticJ);
  EXPECT_EQ(q.lambda, m.lambda);
  EXPECT_EQ(q.mu, m.mu);
}

TEST(NeoHookean, StressFreeAndEnergyFreeAtIdentity) {
  for (VolumetricLaw law : kLaws) {
    const NeoHookean m = NeoHookean::fromYoungPoisson(3.0, 0.3, law);
    const Mat3 I = Mat3::identity();
    const Real tol = 1e-15;
    EXPECT_LE(maxAbs(m.cauchy(I, 1.0)), tol);
    EXPECT_LE(maxAbs(m.kirchhoff(I, 1.0)), tol);
    EXPECT_NEAR(m.energy(I), 0.0, tol);
  }
}

TEST(NeoHookean, SmallStrainLimitIsLinearElasticity) {
  const Real Y = 3.0, nu = 0.3, e = 1e-7;
  const Real tol = 1e-6;  // relative to Y: the O(e) error of the linearisation is ~1e-7
  for (VolumetricLaw law : kLaws) {
    const NeoHookean m = NeoHookean::fromYoungPoisson(Y, nu, law);
    // Uniaxial stress: ε_xx = e, ε_yy = ε_zz = −ν e gives σ_xx = Y e and no lateral stress.
    Mat3 F = Mat3::identity();
    F.a[0][0] += e;
    F.a[1][1] -= nu * e;
    F.a[2][2] -= nu * e;
    const Mat3 s = stressOf(m, F);
    EXPECT_NEAR(s.a[0][0] / e, Y, tol * Y);
    EXPECT_NEAR(s.a[1][1] / e, 0.0, tol * Y);
    EXPECT_NEAR(s.a[2][2] / e, 0.0, tol * Y);

    // A general small displacement gradient: σ ≈ Λ tr(ε) I + 2μ ε, ε = sym(H).
    std::mt19937 rng(7);
    const Mat3 H = randomMat(rng);
    Mat3 G = Mat3::identity();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) G.a[i][j] += e * H.a[i][j];
    const Mat3 sg = stressOf(m, G);
    const Real trEps = e * cgcm::trace(H);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const Real eps = 0.5 * e * (H.a[i][j] + H.a[j][i]);
        const Real lin = (i == j ? m.lambda * trEps : 0.0) + 2.0 * m.mu * eps;
        EXPECT_NEAR(sg.a[i][j] / e, lin / e, tol * Y) << "component " << i << j;
      }
  }
}

TEST(NeoHookean, CauchyStressIsDerivativeOfEnergy) {
  // P = ∂W/∂F by central differences, then σ = P Fᵀ / J.
  const Real h = 1e-6;
  const Real tol = 1e-7;  // relative to max |σ|
  std::mt19937 rng(11);
  for (VolumetricLaw law : kLaws) {
    const NeoHookean m = NeoHookean::fromYoungPoisson(1.7, 0.35, law);
    Real worst = 0.0;
    for (int trial = 0; trial < 5; ++trial) {
      const Mat3 F = randomF(rng, 0.4);
      Mat3 P;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          Mat3 Fp = F, Fm = F;
          Fp.a[i][j] += h;
          Fm.a[i][j] -= h;
          P.a[i][j] = (m.energy(Fp) - m.energy(Fm)) / (2.0 * h);
        }
      const Real J = cgcm::det(F);
      Mat3 sigmaFd = P * cgcm::transpose(F);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) sigmaFd.a[i][j] /= J;
      const Mat3 sigma = stressOf(m, F);
      const Real err = maxAbs(sigmaFd - sigma) / maxAbs(sigma);
      worst = std::max(worst, err);
      EXPECT_LE(err, tol) << cgcm::material::toString(law) << " trial " << trial;
    }
    std::printf("[ fd-stress ] %s: max relative |sigma - dW/dF F^T/J| = %.3e\n", cgcm::material::toString(law),
                worst);
  }
}

TEST(NeoHookean, SpatialModuliGiveTruesdellRateOfKirchhoffStress) {
  // (τ(F + ε l F) − τ(F − ε l F)) / 2ε = J c : sym(l) + l τ + τ lᵀ.
  const Real h = 1e-6;
  const Real tol = 1e-6;  // relative to max |rate|
  std::mt19937 rng(23);
  for (VolumetricLaw law : kLaws) {
    const NeoHookean m = NeoHookean::fromYoungPoisson(1.3, 0.28, law);
    Real worst = 0.0;
    for (int trial = 0; trial < 10; ++trial) {
      const Mat3 F = randomF(rng, 0.5);
      const Mat3 l = randomMat(rng);
      const Mat3 lF = l * F;
      Mat3 Fp = F, Fm = F;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          Fp.a[i][j] += h * lF.a[i][j];
          Fm.a[i][j] -= h * lF.a[i][j];
        }
      const Mat3 tp = kirchhoffOf(m, Fp), tm = kirchhoffOf(m, Fm);
      Mat3 rateFd;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) rateFd.a[i][j] = (tp.a[i][j] - tm.a[i][j]) / (2.0 * h);

      const Real J = cgcm::det(F);
      const Mat3 tau = kirchhoffOf(m, F);
      const cgcm::material::IsotropicModuli c = m.spatialModuli(J);
      const Real trD = cgcm::trace(l);
      const Mat3 lt = l * tau;
      Mat3 rate;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          const Real d = 0.5 * (l.a[i][j] + l.a[j][i]);
          const Real cd = (i == j ? c.lambdaEff * trD : 0.0) + 2.0 * c.muEff * d;
          rate.a[i][j] = J * cd + lt.a[i][j] + lt.a[j][i];  // τ lᵀ = (l τ)ᵀ
        }
      const Real err = maxAbs(rateFd - rate) / maxAbs(rate);
      worst = std::max(worst, err);
      EXPECT_LE(err, tol) << cgcm::material::toString(law) << " trial " << trial;
    }
    std::printf("[ fd-moduli ] %s: max relative error of the Truesdell rate = %.3e\n",
                cgcm::material::toString(law), worst);
  }
}

TEST(NeoHookean, ModuliAtIdentityAreLame) {
  const Real tol = 1e-15;
  for (VolumetricLaw law : kLaws) {
    const NeoHookean m = NeoHookean::fromYoungPoisson(2.0, 0.25, law);
    const cgcm::material::IsotropicModuli c = m.spatialModuli(1.0);
    EXPECT_NEAR(c.lambdaEff, m.lambda, tol);
    EXPECT_NEAR(c.muEff, m.mu, tol);
  }
}

TEST(NeoHookean, ClosedFormStressForBothLaws) {
  // σ = (p(J)/J) I + (μ/J)(b − I), p = Λ ln J or (Λ/2)(J² − 1).
  const NeoHookean a = NeoHookean::fromLame(1.1, 0.7, VolumetricLaw::LogSquared);
  const NeoHookean b = NeoHookean::fromLame(1.1, 0.7, VolumetricLaw::QuadraticJ);
  Mat3 F = Mat3::zero();
  F.a[0][0] = 1.4;
  F.a[1][1] = 0.9;
  F.a[2][2] = 0.8;
  const Real J = 1.4 * 0.9 * 0.8;
  const Mat3 B = leftCauchyGreen(F);
  const Real tol = 1e-14;
  EXPECT_NEAR(a.cauchy(B, J).a[0][0], 1.1 * std::log(J) / J + 0.7 / J * (1.4 * 1.4 - 1.0), tol);
  EXPECT_NEAR(b.cauchy(B, J).a[0][0], 0.55 * (J - 1.0 / J) + 0.7 / J * (1.4 * 1.4 - 1.0), tol);
  EXPECT_NEAR(a.energy(F), 0.55 * std::log(J) * std::log(J) + 0.35 * (1.96 + 0.81 + 0.64 - 3.0) - 0.7 * std::log(J), tol);
  EXPECT_NEAR(b.energy(F), 0.275 * (J * J - 1.0 - 2.0 * std::log(J)) + 0.35 * (1.96 + 0.81 + 0.64 - 3.0) - 0.7 * std::log(J),
              tol);
}

// The stress from the displacement gradient H = F − I is cauchy(F Fᵀ, det F)
// for any H, and keeps its relative precision as H → 0, where cauchy() is
// left with the rounding of b − I and ln J (about eps·μ).
TEST(NeoHookean, StressOfDisplacementGradientIsPreciseNearIdentity) {
  std::mt19937 rng(77);
  for (VolumetricLaw law : {VolumetricLaw::LogSquared, VolumetricLaw::QuadraticJ}) {
    const NeoHookean m = NeoHookean::fromYoungPoisson(2.0, 0.3, law);
    for (int trial = 0; trial < 20; ++trial) {
      const Mat3 F = randomF(rng, 0.3);
      Mat3 H = F;
      for (int i = 0; i < 3; ++i) H.a[i][i] -= 1.0;
      const Mat3 a = m.cauchyOfDisplacementGradient(H);
      const Mat3 b = m.cauchy(leftCauchyGreen(F), cgcm::det(F));
      EXPECT_LE(maxAbs(a - b), 1e-13 * (1 + maxAbs(b)));
      EXPECT_NEAR(NeoHookean::detOfIdentityPlusMinusOne(H), cgcm::det(F) - 1.0, 1e-14);
    }
    // H = 1e-12 A: σ = Λ tr(H) I + μ(H + Hᵀ) to first order, i.e. relative
    // 1e-12; the result must hold 1e-9 of it (cauchy() holds about 1e-4).
    const Mat3 A = randomMat(rng);
    Mat3 H;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) H.a[i][j] = 1e-12 * A.a[i][j];
    const Mat3 linear = m.linearStressOfDisplacementGradient(H);
    EXPECT_LE(maxAbs(m.cauchyOfDisplacementGradient(H) - linear), 1e-9 * maxAbs(linear));
  }
}

TEST(NeoHookean, InvalidParametersThrowInputError) {
  auto expectThrowNaming = [](auto&& call, const std::string& name) {
    try {
      call();
      ADD_FAILURE() << "no InputError for " << name;
    } catch (const cgcm::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("allowed"), std::string::npos) << e.what();
    }
  };
  expectThrowNaming([] { NeoHookean::fromYoungPoisson(1.0, 0.5); }, "nu");
  expectThrowNaming([] { NeoHookean::fromYoungPoisson(1.0, -1.0); }, "nu");
  expectThrowNaming([] { NeoHookean::fromYoungPoisson(1.0, std::nan("")); }, "nu");
  expectThrowNaming([] { NeoHookean::fromYoungPoisson(-1.0, 0.3); }, "Y");
  expectThrowNaming([] { NeoHookean::fromYoungPoisson(0.0, 0.3); }, "Y");
  expectThrowNaming([] { NeoHookean::fromLame(1.0, 0.0); }, "mu");
  expectThrowNaming([] { NeoHookean::fromLame(-1.0, 1.0); }, "lambda");
  EXPECT_NO_THROW(NeoHookean::fromYoungPoisson(1.0, -0.5));
  EXPECT_NO_THROW(NeoHookean::fromLame(-0.5, 1.0));
}
