// Closed forms beyond the sphere: the JKR and Maugis-Dugdale cylinders in
// plane strain, Kendall's peel and the flat punch, against their limits and
// the relations between them.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <tuple>
#include <vector>

#include "cgcm/analytic/Cylinder.hpp"
#include "cgcm/analytic/FlatPunch.hpp"
#include "cgcm/analytic/Peel.hpp"
#include "cgcm/core/Error.hpp"
#include "Sampling.hpp"

namespace an = cgcm::analytic;
using cgcm::kPi;
using cgcm::Real;

namespace {

using cgcm::analytic::test::logspace;

Real degrees(Real d) { return d * kPi / 180; }

}  // namespace

// In physical units the normalised JKR cylinder is Barquins' law
// P/L = πE*a²/(4R) − √(2πE*wa), and its pull-off the quoted
// P_c/L = −3(πE*w²R/16)^(1/3) at a_c = (2wR²/(πE*))^(1/3), for any E*, w, R.
TEST(Cylinder, JkrInPhysicalUnitsIsBarquinsLaw) {
  for (const auto& [E, w, R] : {std::tuple<Real, Real, Real>{1.0, 1.0, 1.0}, {3e9, 0.05, 2e-6},
                                {1e6, 0.04, 1e-3}}) {
    const an::CylinderScales sc = an::CylinderScales::from(w, R, E);
    for (Real a : {0.1, 0.5871, 2.0}) {
      const an::CylinderPoint p = an::jkrCylinder(a);
      const Real aPhys = a * sc.length;
      const Real expected = kPi * E * aPhys * aPhys / (4 * R) - std::sqrt(2 * kPi * E * w * aPhys);
      EXPECT_NEAR(p.load * sc.force, expected, 1e-13 * std::fabs(sc.force));
    }
    const an::CylinderPoint c = an::jkrCylinderPullOff();
    EXPECT_NEAR(c.load * sc.force, -3 * std::cbrt(kPi * E * w * w * R / 16), 1e-13 * sc.force);
    EXPECT_NEAR(c.a * sc.length, std::cbrt(2 * w * R * R / (kPi * E)), 1e-13 * sc.length);
  }
  // And it is the minimum: the slope vanishes there.
  const an::CylinderPoint c = an::jkrCylinderPullOff();
  const Real h = 1e-5;
  EXPECT_NEAR((an::jkrCylinder(c.a + h).load - an::jkrCylinder(c.a - h).load) / (2 * h), 0, 1e-9);
  EXPECT_GT(an::jkrCylinder(c.a * 1.01).load, c.load);
  EXPECT_GT(an::jkrCylinder(c.a * 0.99).load, c.load);
}

// The gap equation has one root for every ā > 0 over λ ∈ [1e-3, 1e3] ×
// ā ∈ [1e-6, 10] (s from the JKR end, 1e-4, to the Dugdale end, 1e6), found
// to rounding, and the load slope from implicit differentiation matches a
// central difference.
TEST(Cylinder, MaugisDugdaleSolverAndSlope) {
  Real sMin = std::numeric_limits<Real>::infinity(), sMax = 0;
  for (Real lambda : logspace(1e-3, 1e3, 13)) {
    Real previous = std::numeric_limits<Real>::infinity();
    for (Real a : logspace(1e-6, 10, 33)) {
      const an::MdCylinderSolution sol = an::solveMdCylinder(lambda, a);
      ASSERT_TRUE(std::isfinite(sol.s) && sol.s > 0) << lambda << " " << a;
      EXPECT_LE(std::fabs(an::mdCylinderResidual(lambda, a, sol.s)), 1e-12) << lambda << " " << a;
      EXPECT_LT(an::mdCylinderResidual(lambda, a, sol.s * (1 - 1e-9)), 0.0);
      EXPECT_GT(an::mdCylinderResidual(lambda, a, sol.s * (1 + 1e-9)), 0.0);
      EXPECT_LT(sol.s, previous) << "s must fall with a (lambda " << lambda << ")";
      previous = sol.s;
      sMin = std::fmin(sMin, sol.s);
      sMax = std::fmax(sMax, sol.s);
      if (a >= 1e-3) {
        const Real h = 1e-6 * a;
        const Real fd = (an::solveMdCylinder(lambda, a + h).load - an::solveMdCylinder(lambda, a - h).load) / (2 * h);
        EXPECT_NEAR(sol.dLoad, fd, 1e-6 * (1 + std::fabs(fd))) << lambda << " " << a;
      }
    }
  }
  EXPECT_LT(sMin, 1e-3);
  EXPECT_GT(sMax, 1e5);
  EXPECT_NEAR(an::solveMdCylinder(0.7, 0.9, 1e-12).s, an::solveMdCylinder(0.7, 0.9).s, 1e-14);
  EXPECT_NEAR(an::solveMdCylinder(0.7, 0.9, 1e12).s, an::solveMdCylinder(0.7, 0.9).s, 1e-14);
}

// λ → ∞ is the JKR cylinder: the Dugdale zone shrinks to the crack tip and
// 2σ0√(c²−a²) → √(2πE*wa), so P̄ = πā²/4 − λās → πā²/4 − √(2ā); the
// difference falls like 1/λ² (measured 5.8e-7 at λ = 1e3 and ā = 1; it
// changes sign near ā = 0.5, so the ratio is checked away from there).
TEST(Cylinder, MaugisDugdaleTendsToJkr) {
  for (Real a : {0.2, 1.0, 3.0}) {
    const Real jkr = an::jkrCylinder(a).load;
    const Real d100 = std::fabs(an::solveMdCylinder(100, a).load - jkr);
    const Real d1000 = std::fabs(an::solveMdCylinder(1000, a).load - jkr);
    EXPECT_LT(d1000, 5e-6) << a;
    EXPECT_NEAR(d100 / d1000, 100, 5) << a;  // second order in 1/λ
  }
  const Real jkrPullOff = an::jkrCylinderPullOff().load;
  // The JKR end of the cylinder map: λ ≥ 5 within 0.1 % of JKR.
  for (Real lambda : {5.0, 10.0, 100.0, 1000.0}) {
    const an::CylinderPoint p = an::mdCylinderPullOff(lambda);
    EXPECT_LE(std::fabs(p.load / jkrPullOff - 1), 1e-3) << lambda;
    EXPECT_GE(p.load, jkrPullOff - 1e-12) << "the M-D pull-off never exceeds JKR's (lambda " << lambda << ")";
  }
}

// λ → 0 is a rigid cylinder held by a Dugdale zone of half-width c with the
// Hertz gap c²/(2R) = h0: P → −2σ0c = −2σ0√(2Rh0), in normalised form
// P̄ → −2√(λ/π), reached at ā → 0 (the minimum sits at ā ≈ 0.65λ); the
// relative difference falls like √λ.
TEST(Cylinder, MaugisDugdaleDugdaleLimit) {
  for (Real lambda : {1e-3, 1e-2}) {
    const an::CylinderPoint p = an::mdCylinderPullOff(lambda);
    const Real rigid = -2 * std::sqrt(lambda / kPi);
    EXPECT_LE(std::fabs(p.load / rigid - 1), 5 * std::sqrt(lambda)) << lambda;
    EXPECT_LT(p.a, lambda);
    // The physical form: σ0 = λ·stress/2 and h0 = w/σ0 give −2√(2Rwσ0).
    const Real w = 0.02, R = 3e-6, E = 2e9;
    const an::CylinderScales sc = an::CylinderScales::from(w, R, E);
    const Real sigma0 = 0.5 * lambda * sc.stress;
    EXPECT_NEAR(rigid * sc.force, -2 * std::sqrt(2 * R * w * sigma0), 1e-12 * sc.force);
  }
  // The pull-off deepens monotonically from the Dugdale to the JKR end.
  Real previous = 0;
  for (Real lambda : logspace(1e-3, 1e3, 19)) {
    const Real p = an::mdCylinderPullOff(lambda).load;
    EXPECT_LT(p, previous) << lambda;
    previous = p;
  }
}

TEST(Cylinder, RefusesBadInput) {
  EXPECT_THROW(an::jkrCylinder(0), cgcm::InputError);
  EXPECT_THROW(an::solveMdCylinder(-1, 1), cgcm::InputError);
  EXPECT_THROW(an::solveMdCylinder(1, std::nan("")), cgcm::InputError);
  EXPECT_THROW(an::mdCylinderPullOff(1e4), cgcm::InputError);
  EXPECT_THROW(an::CylinderScales::from(0, 1, 1), cgcm::InputError);
}

// Kendall's law solves its energy balance, tends to Rivlin's inextensible
// 1/(1 − cos θ) as ε → 0 and to lap shear √(2/ε) as θ → 0; at 90° and
// ε → 0 the force is the work of adhesion (F = bw), at 180° half of it.
TEST(Peel, KendallLaw) {
  for (Real thetaDeg : {0.5, 15.0, 30.0, 90.0, 150.0, 180.0}) {
    for (Real eps : {1e-8, 1e-4, 1e-3, 1e-1, 10.0}) {
      const Real theta = degrees(thetaDeg);
      const Real f = an::kendallPeelForce(theta, eps);
      // f²/(2ε)·... : (F/b)²/(2E_t h) + (F/b)(1 − cos θ) − w = 0 divided by w.
      const Real balance = 0.5 * eps * f * f + f * (1 - std::cos(theta)) - 1;
      EXPECT_NEAR(balance, 0, 1e-12) << thetaDeg << " " << eps;
      EXPECT_LT(f, an::inextensiblePeelForce(theta));  // stretching releases energy
    }
    if (thetaDeg >= 15) {
      EXPECT_NEAR(an::kendallPeelForce(degrees(thetaDeg), 1e-12) / an::inextensiblePeelForce(degrees(thetaDeg)), 1, 1e-9);
    }
  }
  EXPECT_NEAR(an::kendallPeelForce(degrees(90), 0), 1, 1e-15);
  EXPECT_NEAR(an::kendallPeelForce(degrees(180), 0), 0.5, 1e-15);
  for (Real eps : {1e-6, 1e-3, 1.0}) EXPECT_NEAR(an::kendallPeelForce(0, eps), std::sqrt(2 / eps), 1e-12 * std::sqrt(2 / eps));
  // Rounding at small angles: 1 − cos θ is not formed by subtraction.
  EXPECT_NEAR(an::inextensiblePeelForce(1e-6) * 0.5e-12, 1, 1e-9);
  EXPECT_THROW(an::kendallPeelForce(0, 0), cgcm::InputError);
  EXPECT_THROW(an::kendallPeelForce(4, 1e-3), cgcm::InputError);
  EXPECT_THROW(an::kendallPeelForce(1, -1), cgcm::InputError);
  EXPECT_THROW(an::inextensiblePeelForce(0), cgcm::InputError);
}

// The strip held at its far end on a bond without shear: its balance (F²
// sin²θ ε/2 + F(1 − cos θ) = 1 in units of w) is met; it is Kendall's at 90°
// and for ε → 0, lies above Kendall's below 90° and between 90° and 180°,
// where its stretching term vanishes (F = w/2), and reproduces the
// derivation's pieces: load-point travel and strain energy of arm and
// bonded part per unit advance, computed here from the strains.
TEST(Peel, HeldEndLaw) {
  for (Real thetaDeg : {0.5, 15.0, 30.0, 60.0, 90.0, 120.0, 150.0, 179.0, 180.0}) {
    for (Real eps : {1e-8, 1e-4, 1e-3, 1e-2, 1.0}) {
      const Real theta = degrees(thetaDeg);
      const Real f = an::heldEndPeelForce(theta, eps);
      const Real s = std::sin(theta), c = std::cos(theta);
      EXPECT_NEAR(0.5 * eps * s * s * f * f + f * (1 - c) - 1, 0, 1e-12) << thetaDeg << " " << eps;
      // energy per unit advance in units of w, with strains e_a = f eps (arm), e_b = f eps cos θ (bonded)
      const Real ea = f * eps, eb = f * eps * c;
      const Real work = f * ((1 + ea) - (1 + eb) * c), strainEnergy = 0.5 * (ea * ea - eb * eb) / eps;
      EXPECT_NEAR(work - strainEnergy, 1, 1e-11 * std::max(1.0, work)) << thetaDeg << " " << eps;
      if (thetaDeg != 90 && thetaDeg != 180) {
        EXPECT_GT(f, an::kendallPeelForce(theta, eps));
      }
    }
    if (thetaDeg >= 15) {  // the limit needs eps sin²θ << (1 − cos θ)²
      EXPECT_NEAR(an::heldEndPeelForce(degrees(thetaDeg), 1e-12) / an::inextensiblePeelForce(degrees(thetaDeg)), 1, 1e-9);
    }
  }
  for (Real eps : {1e-3, 0.1}) {
    EXPECT_NEAR(an::heldEndPeelForce(degrees(90), eps), an::kendallPeelForce(degrees(90), eps), 1e-15);
    EXPECT_NEAR(an::heldEndPeelForce(degrees(180), eps), 0.5, 1e-12);
  }
  EXPECT_THROW(an::heldEndPeelForce(0, 1e-3), cgcm::InputError);
  EXPECT_THROW(an::heldEndPeelForce(1, std::nan("")), cgcm::InputError);
}

// Kendall's punch and the strength limit meet at the critical size, their
// ratio is √(a_cr/a) in both geometries, and the strip's Kendall force is the
// adhesive term of the JKR cylinder (the same crack at the contact edge).
TEST(FlatPunch, KendallAndStrengthLimit) {
  const Real E = 2e6, w = 0.05, sigma = 3e5;
  for (auto g : {an::PunchGeometry::Axisymmetric, an::PunchGeometry::Strip}) {
    const an::FlatPunch punch(g, E, w, sigma);
    const Real acr = punch.criticalSize();
    EXPECT_NEAR(punch.kendallForce(acr) / punch.strengthForce(acr), 1, 1e-14);
    for (Real x : {0.01, 0.05, 1.0, 50.0, 1e3}) {
      EXPECT_NEAR(punch.kendallForce(x * acr) / punch.strengthForce(x * acr), 1 / std::sqrt(x), 1e-13);
    }
  }
  const an::FlatPunch axi(an::PunchGeometry::Axisymmetric, E, w, sigma);
  EXPECT_NEAR(axi.criticalSize(), 8 * E * w / (kPi * sigma * sigma), 1e-15);
  EXPECT_NEAR(axi.kendallForce(1e-3), std::sqrt(8 * kPi * 1e-9 * E * w), 1e-15);
  const an::FlatPunch strip(an::PunchGeometry::Strip, E, w, sigma);
  const an::CylinderScales sc = an::CylinderScales::from(w, 1e-3, E);
  const Real a = 0.7;  // normalised half-width of the cylinder
  const Real adhesiveTerm = (an::jkrCylinder(a).load - 0.25 * kPi * a * a) * sc.force;
  EXPECT_NEAR(strip.kendallForce(a * sc.length), -adhesiveTerm, 1e-12 * sc.force);
  EXPECT_EQ(an::parsePunchGeometry("strip"), an::PunchGeometry::Strip);
  EXPECT_THROW(an::parsePunchGeometry("square"), cgcm::InputError);
  EXPECT_THROW(an::FlatPunch(an::PunchGeometry::Strip, E, 0, sigma), cgcm::InputError);
  EXPECT_THROW(axi.kendallForce(-1), cgcm::InputError);
}
