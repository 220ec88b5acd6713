// Pressure distributions and the Boussinesq subsurface stress (46).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "cgcm/analytic/Pressure.hpp"
#include "cgcm/analytic/Quadrature.hpp"
#include "cgcm/analytic/SubsurfaceStress.hpp"
#include "cgcm/core/Error.hpp"

namespace an = cgcm::analytic;
using cgcm::Real;

namespace {

using cgcm::kPi;

std::vector<an::ContactModel> allModels() {
  std::vector<an::ContactModel> m = {an::ContactModel::hertz(), an::ContactModel::jkr(),
                                     an::ContactModel::dmt()};
  for (Real lambda : {1e-3, 0.1, 1.0, 10.0, 1e3}) m.push_back(an::ContactModel::maugisDugdale(lambda));
  return m;
}

}  // namespace

// Quadrature rule and elliptic integrals against exact values.
TEST(Quadrature, GaussKronrodIsExactForPolynomialsAndAdaptsToPeaks) {
  // K15 integrates degree 22 exactly: ∫₀¹ x²² dx = 1/23 on one interval
  // (the tolerance 1 accepts the first estimate, whose error bound is that
  // of the embedded 7-point Gauss rule).
  auto poly = [](Real x) { return std::pow(x, 22); };
  const auto r = an::integrateAdaptive(poly, {0.0, 1.0}, 1.0, 0.0, 1, "poly");
  EXPECT_EQ(r.intervals, 1);
  EXPECT_NEAR(r.value, 1.0 / 23.0, 1e-16);
  // A Lorentzian of width 1e-6: ∫_{-1}^{1} ε/(x²+ε²) dx = 2 atan(1/ε).
  const Real eps = 1e-6;
  auto peak = [&](Real x) { return eps / (x * x + eps * eps); };
  const auto p = an::integrateAdaptive(peak, {-1.0, 1.0}, 1e-10, 0.0, 5000, "peak");
  EXPECT_NEAR(p.value, 2 * std::atan(1 / eps), 1e-9);
  EXPECT_THROW(an::integrateAdaptive(peak, {-1.0, 1.0}, 1e-14, 0.0, 3, "budget"),
               cgcm::NumericalError);
}

TEST(Quadrature, EllipticIntegrals) {
  // K(0) = E(0) = π/2; k² = 1/2: K = 1.854074677301372, E = 1.350643881047675
  // (Abramowitz & Stegun table 17.1); k'² = 1e-12: K ≈ ln(4/k') = 15.2018...
  auto ke = an::ellipticKE(0.0, 1.0);
  EXPECT_NEAR(ke.K, kPi / 2, 1e-15);
  EXPECT_NEAR(ke.E, kPi / 2, 1e-15);
  ke = an::ellipticKE(0.5, 0.5);
  EXPECT_NEAR(ke.K, 1.854074677301372, 1e-14);
  EXPECT_NEAR(ke.E, 1.350643881047675, 1e-14);
  ke = an::ellipticKE(1 - 1e-12, 1e-12);
  EXPECT_NEAR(ke.K, std::log(4 / 1e-6), 1e-10);  // + O(k'² ln k')
  EXPECT_NEAR(ke.E, 1.0, 1e-10);
}

// ∫ 2π r p dr = P: in normalised form π ∫₀^c r̄ p̄ dr̄ = P̄ (ā³ = P̄ + 2 for
// DMT, whose adhesive force acts outside the contact), for every model and
// radius, to 1e-9 of the pressure's magnitude.
TEST(Pressure, IntegratesToTheLoad) {
  for (const auto& model : allModels()) {
    for (Real a : {0.2, 1.0, 3.0}) {
      const an::PressureProfile p(model, a);
      const Real expected = model.kind() == an::Model::Dmt ? a * a * a : p.load();
      EXPECT_NEAR(p.contactLoad(), expected, 1e-15 * std::fabs(expected));
      EXPECT_NEAR(p.integratedLoad(), expected, 1e-9 * (p.scale() * a * a + std::fabs(expected)))
          << model.describe() << " a " << a;
    }
  }
}

// The same in physical units: w = 0.3, R = 2, E* = 5, so r = r̄ L,
// p = p̄ S and P = P̄ πwR; ∫ 2π r p dr = 2π L² S ∫ r̄ p̄ dr̄ = 2 L² S (π ∫ r̄ p̄).
TEST(Pressure, IntegratesToTheLoadInPhysicalUnits) {
  const Real w = 0.3, R = 2, Estar = 5;
  const auto s = an::JohnsonGreenwoodScales::from(w, R, Estar);
  const Real aPhys = 0.2;
  for (const auto& model : {an::ContactModel::jkr(), an::ContactModel::maugisDugdale(0.7)}) {
    const an::PressureProfile p(model, aPhys / s.length);
    // ∫ 2π r p dr by a plain composite rule in physical units on [0, c]
    // (the edge handled by the substitution r = a(1 − t²)).
    const Real a = aPhys;
    auto f = [&](Real t) {
      const Real r = a * (1 - t * t);
      return 2 * kPi * r * p.nearEdge(t) * s.pressure * 2 * a * t;
    };
    Real P = an::integrateAdaptive(f, {0.0, 1.0}, 1e-14, 0.0, 2000, "phys").value;
    const Real c = p.outerRadius() * s.length;
    if (c > a) P += kPi * (c * c - a * a) * p(p.outerRadius()) * s.pressure;
    EXPECT_NEAR(P, p.load() * s.force, 1e-10 * std::fabs(p.load() * s.force)) << model.describe();
  }
}

TEST(Pressure, ShapeOfTheDistributions) {
  const an::PressureProfile md(an::ContactModel::maugisDugdale(1.0), 1.0);
  const Real c = md.outerRadius();
  ASSERT_GT(c, 1.0);
  // (44): continuous at r = a (the atan → π/2 gives −λ), −λ on [a, c], 0 beyond.
  EXPECT_NEAR(md(1 - 1e-12), -1.0, 1e-5);
  EXPECT_EQ(md(1.0), -1.0);
  EXPECT_EQ(md(0.5 * (1 + c)), -1.0);
  EXPECT_EQ(md(c), -1.0);
  EXPECT_EQ(md(c * (1 + 1e-12)), 0.0);
  // Hertz at the centre: p̄0 = 3ā/π; zero at and beyond the edge.
  const an::PressureProfile hz(an::ContactModel::hertz(), 2.0);
  EXPECT_DOUBLE_EQ(hz(0.0), 6 / kPi);
  EXPECT_EQ(hz(2.0), 0.0);
  // JKR: −∞ at r = a, 1/√ singular just inside.
  const an::PressureProfile jkr(an::ContactModel::jkr(), 1.0);
  EXPECT_TRUE(std::isinf(jkr(1.0)) && jkr(1.0) < 0);
  EXPECT_NEAR(jkr.nearEdge(1e-4) * 1e-4 * std::sqrt(2.0), -std::sqrt(6.0) / kPi, 1e-7);
  EXPECT_THROW(jkr(-0.1), cgcm::InputError);
}

// σz(r, 0) = −p(r) exactly, for every model, inside, at and outside the
// contact and the adhesive zone.
TEST(SubsurfaceStress, SurfaceValueIsMinusPressure) {
  for (const auto& model : allModels()) {
    const an::PressureProfile p(model, 1.0);
    const Real c = p.outerRadius();
    for (Real r : {0.0, 0.3, 0.9, 0.999, 1.0, 0.5 * (1 + c), c, 1.2 * c, 5.0}) {
      EXPECT_EQ(an::sigmaZ(p, r, 0.0), -p(r)) << model.describe() << " r " << r;
    }
  }
}

// Just below the surface σz → −p(r): at z = 1e-7 within 1e-6 of the pressure
// scale, at every r at least 0.02 away from a and c; and across the M-D jump
// at r = c the stress tends to the mean of the two sides, λ/2.
TEST(SubsurfaceStress, ContinuousToTheSurfaceAndAcrossTheJump) {
  for (const auto& model : allModels()) {
    const an::PressureProfile p(model, 1.0);
    const Real a = 1.0, c = p.outerRadius();
    for (Real r = 0; r < 1.5 * c; r += 0.0731 * c) {
      if (std::fabs(r - a) < 0.02 || std::fabs(r - c) < 0.02) continue;
      EXPECT_NEAR(an::sigmaZ(p, r, 1e-7), -p(r), 1e-6 * p.scale()) << model.describe() << " r " << r;
    }
    if (model.kind() == an::Model::MaugisDugdale && c - a > 1e-3) {
      const Real lambda = model.lambda();
      EXPECT_NEAR(an::sigmaZ(p, c, 1e-9), lambda / 2, 1e-6 * lambda) << model.describe();
      EXPECT_NEAR(an::sigmaZ(p, c - 1e-4 * (c - a), 1e-9), lambda, 1e-4 * lambda);
      EXPECT_NEAR(an::sigmaZ(p, c + 1e-4 * (c - a), 1e-9), 0.0, 1e-4 * lambda);
    }
  }
}

// Johnson (3.45): under the Hertz pressure σz(0, z) = −p0/(1 + z²/a²),
// to 1e-9 p0 from just below the surface to z = 20a.
TEST(SubsurfaceStress, HertzAxisMatchesClosedForm) {
  for (Real a : {0.4, 1.0, 2.5}) {
    const an::PressureProfile p(an::ContactModel::hertz(), a);
    const Real p0 = 3 * a / kPi;
    for (Real zr : {1e-6, 1e-3, 0.05, 0.3, 0.78, 1.0, 2.0, 5.0, 20.0}) {
      EXPECT_NEAR(an::sigmaZ(p, 0.0, zr * a), an::hertzAxisSigmaZ(p0, a, zr * a), 1e-9 * p0)
          << "a " << a << " z/a " << zr;
    }
  }
}

// The ring kernel: the closed form of the φ-integral against direct
// quadrature, its unit mass, and on the axis the uniform-disc solution
// ∫₀^c G(0, s, z) ds = 1 − z³/(c² + z²)^(3/2).
TEST(SubsurfaceStress, RingKernel) {
  for (auto [r, s, z] : {std::tuple{0.7, 0.4, 0.3}, std::tuple{1.0, 1.02, 0.01},
                         std::tuple{2.0, 0.1, 1.5}, std::tuple{0.3, 3.0, 0.05}}) {
    auto integrand = [&](Real phi) {
      const Real rho2 = r * r - 2 * r * s * std::cos(phi) + s * s + z * z;
      return z * z * z / (rho2 * rho2 * std::sqrt(rho2));
    };
    const Real phiInt =
        an::integrateAdaptive(integrand, {0.0, 0.01, 0.1, kPi}, 1e-13, 1e-13, 2000, "phi").value;
    EXPECT_NEAR(an::boussinesqRingKernel(r, s, z), 3 / kPi * s * phiInt,
                1e-11 * an::boussinesqRingKernel(r, s, z));
  }
  for (Real r : {0.0, 0.5, 2.0}) {
    const Real z = 0.3;
    std::vector<Real> pts{0.0, 1.0};
    // ∫₀^∞ G ds by s = t/(1 − t).
    auto f = [&](Real t) { return an::boussinesqRingKernel(r, t / (1 - t), z) / ((1 - t) * (1 - t)); };
    for (Real s : {r - z, r, r + z}) {
      if (s > 0) pts.push_back(s / (1 + s));
    }
    EXPECT_NEAR(an::integrateAdaptive(f, pts, 1e-12, 0.0, 2000, "mass").value, 1.0, 1e-11) << r;
  }
  const Real c = 1.3, z = 0.4;
  auto g = [&](Real s) { return an::boussinesqRingKernel(0.0, s, z); };
  EXPECT_NEAR(an::integrateAdaptive(g, {0.0, c}, 1e-13, 0.0, 2000, "disc").value,
              1 - std::pow(z, 3) / std::pow(c * c + z * z, 1.5), 1e-12);
}

// Off the axis, σz from the elliptic kernel against a brute-force double
// quadrature of (46) (φ inside, s outside), for the M-D pressure with its
// edge kink at a and jump at c.
TEST(SubsurfaceStress, MatchesDoubleQuadratureOffAxis) {
  const an::PressureProfile p(an::ContactModel::maugisDugdale(1.0), 1.0);
  const Real a = 1.0, c = p.outerRadius();
  for (auto [r, z] : {std::pair{0.7, 0.4}, std::pair{1.3, 0.2}, std::pair{c, 0.5}, std::pair{2.5, 1.0}}) {
    auto phiIntegral = [&](Real s) {
      auto inner = [&](Real phi) {
        const Real rho2 = r * r - 2 * r * s * std::cos(phi) + s * s + z * z;
        return z * z * z / (rho2 * rho2 * std::sqrt(rho2));
      };
      return an::integrateAdaptive(inner, {0.0, kPi}, 1e-13, 1e-12, 2000, "phi").value;
    };
    auto outerA = [&](Real t) {  // s = a(1 − t²) on [0, a]
      const Real s = a * (1 - t * t);
      return s * p.nearEdge(t) * phiIntegral(s) * 2 * a * t;
    };
    auto outerB = [&](Real s) { return s * p(s) * phiIntegral(s); };
    const Real brute = -3 / kPi *
                       (an::integrateAdaptive(outerA, {0.0, 1.0}, 1e-12, 0.0, 2000, "A").value +
                        an::integrateAdaptive(outerB, {a, c}, 1e-12, 0.0, 2000, "B").value);
    EXPECT_NEAR(an::sigmaZ(p, r, z), brute, 1e-9) << "r " << r << " z " << z;
  }
}

// Far from the contact the pressure acts like a point load P̄ (Boussinesq
// (45) with P = πwR P̄ becomes σ̄z = −(3/π) P̄ z³/ρ⁵ in this normalisation).
// The next term of the multipole expansion is O((c/ρ)²): doubling ρ must cut
// the relative deviation by about 4 (at least 3), and at ρ = 400 it is below
// 1e-3.
TEST(SubsurfaceStress, FarFieldIsAPointLoad) {
  an::StressOptions tight;
  tight.relTol = 1e-13;
  for (const auto& model : {an::ContactModel::hertz(), an::ContactModel::maugisDugdale(0.5)}) {
    const an::PressureProfile p(model, 1.5);
    Real previous = 0;
    for (Real rho : {100.0, 200.0, 400.0}) {
      const Real r = 0.6 * rho, z = 0.8 * rho;
      const Real point = -3 / kPi * p.contactLoad() * std::pow(z, 3) / std::pow(rho, 5);
      const Real dev = std::fabs(an::sigmaZ(p, r, z, tight) / point - 1);
      if (previous > 0) {
        EXPECT_LT(dev, previous / 3) << model.describe() << " rho " << rho;
      }
      previous = dev;
    }
    EXPECT_LT(previous, 1e-3) << model.describe();
  }
}

TEST(SubsurfaceStress, GridMatchesPointwiseAndThreads) {
  const an::PressureProfile p(an::ContactModel::maugisDugdale(0.25), 0.8);
  const std::vector<Real> r{0.0, 0.4, 0.8, 1.2, 2.0};
  const std::vector<Real> z{0.0, 0.01, 0.5};
  const std::vector<Real> one = an::sigmaZGrid(p, r, z, {}, 1);
  const std::vector<Real> two = an::sigmaZGrid(p, r, z, {}, 2);
  ASSERT_EQ(one.size(), r.size() * z.size());
  for (std::size_t j = 0; j < z.size(); ++j) {
    for (std::size_t i = 0; i < r.size(); ++i) {
      EXPECT_EQ(one[j * r.size() + i], an::sigmaZ(p, r[i], z[j]));
      EXPECT_EQ(two[j * r.size() + i], one[j * r.size() + i]);
    }
  }
  EXPECT_THROW(an::sigmaZ(p, 0.5, -0.1), cgcm::InputError);
  EXPECT_THROW(an::sigmaZGrid(p, r, z, {}, 0), cgcm::InputError);
}
