// Pair potentials, half-space integrals, surface properties, normalisation.
#include <gtest/gtest.h>

#include <cmath>
#include <variant>

#include "InteractionTestUtil.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/interaction/Normalisation.hpp"
#include "cgcm/interaction/MorsePair.hpp"
#include "cgcm/interaction/PairPotential.hpp"
#include "cgcm/interaction/Quadrature.hpp"

using namespace cgcm;
using namespace cgcm::interaction;
using cgcm::interaction::testing::kPi;

namespace {

// Half-space integral of phi by quadrature, independent of the closed form:
//   Phi(h)/beta = int_h^inf psi(z) dz,  psi(z) = 2 pi int_z^inf phi(s) s ds
// (shells of radius s around the point cut by the plane at depth z); both
// semi-infinite integrals mapped to (0, 1] by s = z/u, z = h/v.
Real halfSpaceByQuadrature(const PairPotential& p, Real h) {
  const GaussRule g = gaussLegendreUnit(10);
  auto psi = [&](Real z) {
    return 2.0 * kPi *
           integrate(
               [&](Real u) {
                 const Real s = z / u;
                 return p.phi(s) * s * z / (u * u);
               },
               0.0, 1.0, 8, g);
  };
  return integrate([&](Real v) { return psi(h / v) * h / (v * v); }, 0.0, 1.0, 8, g);
}

// A potential that provides only phi and Phi (the Lennard-Jones formulas):
// its r_S0, w and sigma_max come from the numerical defaults of the base class.
class MinimalLJ final : public PairPotential {
 public:
  MinimalLJ(Real eps, Real r0) : PairPotential(eps, r0), lj_(eps, r0) {}
  std::string name() const override { return "minimal"; }
  Real phi(Real r) const override { return lj_.phi(r); }
  Real dphi(Real r) const override { return lj_.dphi(r); }
  Real halfSpace(Real r) const override { return lj_.halfSpace(r); }
  Real dHalfSpace(Real r) const override { return lj_.dHalfSpace(r); }
  KernelPotential kernelPotential() const override { return lj_.kernelPotential(); }

 private:
  LennardJones lj_;
};

class MinimalRepulsive final : public PairPotential {
 public:
  MinimalRepulsive(Real eps, Real r0) : PairPotential(eps, r0), p_(eps, r0) {}
  std::string name() const override { return "minimal-repulsive"; }
  Real phi(Real r) const override { return p_.phi(r); }
  Real dphi(Real r) const override { return p_.dphi(r); }
  Real halfSpace(Real r) const override { return p_.halfSpace(r); }
  Real dHalfSpace(Real r) const override { return p_.dHalfSpace(r); }
  KernelPotential kernelPotential() const override { return p_.kernelPotential(); }

 private:
  RepulsiveLennardJones p_;
};

}  // namespace

TEST(KernelPotential, IsThePotentialTheKernelsEvaluate) {
  // every potential a deck can name: its kernel struct gives the same phi,
  // dphi and half-space law, and scales as strength * phi(r / b) / b^3
  for (const PotentialEntry& e : potentialRegistry()) {
    const auto p = makePotential(e.deckName, 0.7, 1.3);
    std::visit(
        [&](const auto& c) {
          const auto s = c.scaled(1.7, 1.4);
          for (Real r : {0.8, 1.1, 1.3, 2.0, 7.0}) {
            EXPECT_NEAR(c.phi(r), p->phi(r), 1e-14 * std::abs(p->phi(r))) << p->name() << " r " << r;
            EXPECT_NEAR(2.0 * r * c.pointLaw(r * r).df, p->dphi(r),
                        1e-13 * (std::abs(p->dphi(r)) + std::abs(p->phi(r)) / r))
                << p->name() << " r " << r;
            Real v, d, vr, dr;
            c.halfSpace(r, v, d);
            p->halfSpaceWithDerivative(r, vr, dr);
            EXPECT_NEAR(v, vr, 1e-14 * std::abs(vr)) << p->name() << " r " << r;
            EXPECT_NEAR(d, dr, 1e-14 * std::abs(dr)) << p->name() << " r " << r;
            const Real scaledPhi = 1.7 * c.phi(r / 1.4) / (1.4 * 1.4 * 1.4);
            EXPECT_NEAR(s.phi(r), scaledPhi, 1e-13 * std::abs(scaledPhi)) << p->name() << " r " << r;
          }
        },
        p->kernelPotential());
  }
}

TEST(KernelPotential, PointLawDerivativesMatchFiniteDifferences) {
  for (const PotentialEntry& e : potentialRegistry())
    std::visit(
        [&](const auto& c) {
          for (Real s : {0.6, 1.0, 1.7, 5.0}) {
            const Real h = 1e-6 * s;
            const RadialLaw L = c.pointLaw(s), Lp = c.pointLaw(s + h), Lm = c.pointLaw(s - h);
            EXPECT_NEAR(L.df, (Lp.f - Lm.f) / (2 * h), 1e-7 * (std::abs(L.df) + std::abs(L.f))) << e.deckName;
            EXPECT_NEAR(L.d2f, (Lp.df - Lm.df) / (2 * h), 1e-7 * (std::abs(L.d2f) + std::abs(L.df))) << e.deckName;
          }
        },
        makePotential(e.deckName, 0.9, 1.1)->kernelPotential());
}

TEST(KernelPotential, HalfSpaceLawIsTheIntegralOfThePotential) {
  // every named potential's half-space law against the quadrature of its phi
  for (const PotentialEntry& e : potentialRegistry()) {
    const auto p = makePotential(e.deckName, 0.9, 1.1);
    for (Real h : {0.7, 1.0, 1.6, 3.0}) {
      const Real integral = halfSpaceByQuadrature(*p, h);
      EXPECT_NEAR(p->halfSpace(h), integral, 1e-9 * std::abs(integral)) << e.deckName << " h " << h;
      const Real dh = 1e-6;
      EXPECT_NEAR(p->dHalfSpace(h), (p->halfSpace(h + dh) - p->halfSpace(h - dh)) / (2 * dh),
                  1e-7 * std::abs(p->dHalfSpace(h)))
          << e.deckName << " h " << h;
    }
  }
}

TEST(KernelPotential, MorseWithTheDefaultInverseWidthIsTheLennardJonesMatchBitForBit) {
  // a = 6 / r0 exactly as before the width became a parameter (runs must not move by an ulp)
  for (Real r0 : {0.01, 0.0123456789, 0.3, 1.0, 7.77}) {
    const auto morse = makePotential("Morse", 0.7, r0);
    const MorsePair law = std::get<MorsePair>(morse->kernelPotential());
    const MorsePair matched = MorsePair::matchedToLennardJones(0.7, r0);
    EXPECT_EQ(law.a, matched.a) << "r0 " << r0;
    EXPECT_EQ(law.eps, matched.eps);
    EXPECT_EQ(law.r0, matched.r0);
  }
}

TEST(KernelPotential, MorseSurfacePropertiesFromTheNumericalDefaults) {
  // PairPotential's numerical r_S0, w and sigma_max for Morse (a = 6/r0, eps = r0 = 1)
  // against the closed-form Phi solved in 30-digit arithmetic (mpmath):
  // r_S0 = 0.621453487527153, w = 0.334688515313923, sigma_max = 0.891655226769446 at 0.753122479876200
  const auto morse = makePotential("Morse", 1.0, 1.0);
  const auto rs = morse->surfaceEquilibriumDistance();
  ASSERT_TRUE(rs.has_value());
  EXPECT_NEAR(*rs, 0.621453487527153, 1e-12);
  EXPECT_NEAR(morse->adhesionWorkCoefficient(), 0.334688515313923, 1e-10);
  EXPECT_NEAR(morse->peakTractionCoefficient(), 0.891655226769446, 1e-10);
}

TEST(Quadrature, GaussLegendreUnitIsExactForDegree2nMinus1) {
  for (int n = 1; n <= 12; ++n) {
    const GaussRule g = gaussLegendreUnit(n);
    Real sumW = 0.0;
    for (Real w : g.weights) sumW += w;
    EXPECT_NEAR(sumW, 1.0, 1e-14) << n;
    // int_0^1 x^k dx = 1/(k+1) for k <= 2n - 1 (tolerance 1e-14)
    for (int k = 0; k <= 2 * n - 1; ++k) {
      Real s = 0.0;
      for (int i = 0; i < n; ++i) s += g.weights[i] * std::pow(g.points[i], k);
      EXPECT_NEAR(s, 1.0 / (k + 1), 1e-14) << "n=" << n << " k=" << k;
    }
    for (int i = 0; i + 1 < n; ++i) EXPECT_LT(g.points[i], g.points[i + 1]);
  }
  EXPECT_THROW(gaussLegendreUnit(0), InputError);
}

TEST(PairPotential, LennardJonesPairValues) {
  const LennardJones lj(0.7, 1.3);
  // phi(r0) = -eps, phi'(r0) = 0 (tolerance 1e-14 relative)
  EXPECT_NEAR(lj.phi(1.3), -0.7, 1e-14);
  EXPECT_NEAR(lj.dphi(1.3), 0.0, 1e-14);
  for (Real r : {0.9, 1.3, 2.0, 4.0}) {
    const Real h = 1e-6 * r;
    EXPECT_NEAR(lj.dphi(r), (lj.phi(r + h) - lj.phi(r - h)) / (2 * h), 1e-7 * (1.0 + std::abs(lj.dphi(r))));
  }
}

TEST(PairPotential, HalfSpaceMatchesQuadratureOfPhi) {
  const LennardJones lj(0.7, 1.3);
  const RepulsiveLennardJones rep(0.7, 1.3);
  const Real scale = kPi * 0.7 * 1.3 * 1.3 * 1.3;  // pi eps r0^3
  for (Real h : {0.6, 0.8, 1.0, 1.3, 2.0, 4.0}) {
    const Real hh = h * 1.3;
    // absolute tolerance 1e-9 of pi eps r0^3 (Phi changes sign at r_S0)
    EXPECT_NEAR(lj.halfSpace(hh), halfSpaceByQuadrature(lj, hh), 1e-9 * scale) << "h/r0 = " << h;
    EXPECT_NEAR(rep.halfSpace(hh), halfSpaceByQuadrature(rep, hh), 1e-9 * scale) << "h/r0 = " << h;
  }
}

TEST(PairPotential, HalfSpaceDerivativeMatchesFiniteDifferences) {
  const LennardJones lj(0.7, 1.3);
  const RepulsiveLennardJones rep(0.7, 1.3);
  for (const PairPotential* p :
       {static_cast<const PairPotential*>(&lj), static_cast<const PairPotential*>(&rep)}) {
    for (Real r : {0.5, 0.8, 1.0, 1.5, 3.0, 8.0}) {
      const Real h = 1e-6 * r;
      const Real fd = (p->halfSpace(r + h) - p->halfSpace(r - h)) / (2 * h);
      // relative 1e-7 (central differences, step 1e-6 r)
      EXPECT_NEAR(p->dHalfSpace(r), fd, 1e-7 * std::abs(fd) + 1e-12) << p->name() << " r = " << r;
      Real v, d;
      p->halfSpaceWithDerivative(r, v, d);
      EXPECT_DOUBLE_EQ(v, p->halfSpace(r));
      EXPECT_DOUBLE_EQ(d, p->dHalfSpace(r));
    }
  }
}

TEST(PairPotential, SurfaceEquilibriumDistance) {
  const LennardJones lj(0.7, 1.3);
  const auto rs = lj.surfaceEquilibriumDistance();
  ASSERT_TRUE(rs.has_value());
  EXPECT_NEAR(*rs / 1.3, 0.636773, 1e-6);  // 15^(-1/6)
  EXPECT_NEAR(lj.halfSpace(*rs), 0.0, 1e-14 * kPi * 0.7 * 1.3 * 1.3 * 1.3);
  EXPECT_GT(lj.halfSpace(0.99 * *rs), 0.0);
  EXPECT_LT(lj.halfSpace(1.01 * *rs), 0.0);

  const RepulsiveLennardJones rep(0.7, 1.3);
  EXPECT_FALSE(rep.surfaceEquilibriumDistance().has_value());
}

TEST(PairPotential, WorkOfAdhesion) {
  const Real eps = 0.7, r0 = 1.3, b1 = 2.0, b2 = 0.5;
  const LennardJones lj(eps, r0);
  // f_w = (pi/8) 15^(1/3) = 0.96848... (tolerance 1e-5 on the printed digits)
  EXPECT_NEAR(LennardJones::workFactor(), 0.96848, 1e-5);
  EXPECT_NEAR(LennardJones::workFactor(), kPi / 8.0 * std::cbrt(15.0), 1e-15);
  // w = -beta int_{r_S0}^inf T dr by quadrature (T = b1 b2 Phi/beta), relative 1e-10
  const Real rs = *lj.surfaceEquilibriumDistance();
  const GaussRule g = gaussLegendreUnit(10);
  const Real integral =
      integrate([&](Real u) { return b1 * b2 * lj.halfSpace(rs / u) * rs / (u * u); }, 0.0, 1.0, 200, g);
  const Real w = lj.workOfAdhesion(b1, b2);
  EXPECT_NEAR(w, -integral, 1e-10 * w);
  EXPECT_NEAR(w, LennardJones::workFactor() * b1 * b2 * eps * std::pow(r0, 4), 1e-14 * w);

  const RepulsiveLennardJones rep(eps, r0);
  EXPECT_EQ(rep.workOfAdhesion(b1, b2), 0.0);
}

TEST(PairPotential, PeakTraction) {
  const Real eps = 0.7, r0 = 1.3, b1 = 2.0, b2 = 0.5;
  const LennardJones lj(eps, r0);
  // (2 sqrt5/9) pi = 1.5611 (tolerance 1e-4 on the printed digits)
  EXPECT_NEAR(LennardJones::peakTractionFactor(), 1.5611, 1e-4);
  // brute-force maximum of the tensile traction over r, relative 1e-8
  Real best = 0.0;
  for (int i = 0; i <= 200000; ++i) {
    const Real r = r0 * (0.6 + 1.4 * i / 200000.0);
    best = std::max(best, -lj.traction(r, b1, b2));
  }
  const Real smax = lj.peakTraction(b1, b2);
  EXPECT_NEAR(smax, best, 1e-8 * smax);
  EXPECT_NEAR(smax, LennardJones::peakTractionFactor() * b1 * b2 * eps * r0 * r0 * r0, 1e-14 * smax);
  // at (r0/r)^6 = 5
  EXPECT_NEAR(-lj.traction(r0 / std::pow(5.0, 1.0 / 6.0), b1, b2), smax, 1e-14 * smax);
  EXPECT_EQ(RepulsiveLennardJones(eps, r0).peakTraction(b1, b2), 0.0);
}

TEST(PairPotential, NumericalDefaultsOfANewPotentialClass) {
  // A new potential only implements phi and Phi; the base class finds
  // r_S0, w and sigma_max numerically (relative tolerance 1e-9).
  const MinimalLJ p(0.7, 1.3);
  const LennardJones lj(0.7, 1.3);
  ASSERT_TRUE(p.surfaceEquilibriumDistance().has_value());
  EXPECT_NEAR(*p.surfaceEquilibriumDistance(), *lj.surfaceEquilibriumDistance(), 1e-12);
  EXPECT_NEAR(p.adhesionWorkCoefficient(), lj.adhesionWorkCoefficient(), 1e-9 * lj.adhesionWorkCoefficient());
  EXPECT_NEAR(p.peakTractionCoefficient(), lj.peakTractionCoefficient(), 1e-9 * lj.peakTractionCoefficient());

  const MinimalRepulsive rep(0.7, 1.3);
  EXPECT_FALSE(rep.surfaceEquilibriumDistance().has_value());
  EXPECT_EQ(rep.adhesionWorkCoefficient(), 0.0);
  EXPECT_EQ(rep.peakTractionCoefficient(), 0.0);
}

TEST(PairPotential, FactoryAndValidation) {
  EXPECT_EQ(makePotential("lennard-jones", 1.0, 1.0)->name(), "lennard-jones");
  EXPECT_EQ(makePotential("lj", 1.0, 1.0)->name(), "lennard-jones");
  EXPECT_EQ(makePotential("repulsive", 1.0, 1.0)->name(), "repulsive");
  EXPECT_EQ(makePotential("Morse", 1.0, 1.0)->name(), "morse");
  EXPECT_THROW(makePotential("buckingham", 1.0, 1.0), InputError);
  // every potential a deck can name is made by its deck name
  for (const auto& e : potentialRegistry()) EXPECT_NE(makePotential(e.deckName, 1.0, 1.0), nullptr) << e.deckName;
  EXPECT_EQ(makePotential("Lennard-Jones", 1.0, 1.0)->name(), "lennard-jones");
  EXPECT_THROW(LennardJones(0.0, 1.0), InputError);
  EXPECT_THROW(LennardJones(1.0, -1.0), InputError);
}

TEST(Normalisation, ScalingRoundTrip) {
  // R0 = Y = 1, beta0 = 1: r0 = 1/gammaL, eps = gammaL^3/gammaW (exact to 1e-14 relative)
  const InteractionParameters p = fromScaling(50.0, 200.0);
  EXPECT_NEAR(p.r0, 0.02, 1e-16);
  EXPECT_NEAR(p.epsilon, 625.0, 625.0 * 1e-14);
  EXPECT_EQ(p.beta0, 1.0);
  const ScalingParameters s = toScaling(p);
  EXPECT_NEAR(s.gammaL, 50.0, 50.0 * 1e-14);
  EXPECT_NEAR(s.gammaW, 200.0, 200.0 * 1e-14);
  EXPECT_NEAR(s.gammaPi(), 1e4, 1e-10);
  EXPECT_NEAR(s.gammaK(), 4.0, 1e-13);

  // physical values: only beta0^2 eps matters
  InteractionParameters q;
  q.epsilon = 3.2e-21;
  q.r0 = 0.4e-9;
  q.beta0 = 3.0e28;
  q.R0 = 50e-9;
  q.Y = 2.0e9;
  const ScalingParameters t = toScaling(q);
  EXPECT_NEAR(t.gammaL, 125.0, 125.0 * 1e-12);
  const InteractionParameters back = fromScaling(t.gammaL, t.gammaW, q.R0, q.Y, q.beta0);
  EXPECT_NEAR(back.r0, q.r0, 1e-12 * q.r0);
  EXPECT_NEAR(back.epsilon, q.epsilon, 1e-12 * q.epsilon);

  EXPECT_THROW(fromScaling(0.0, 1.0), InputError);
  EXPECT_THROW(fromScaling(1.0, -2.0), InputError);
  q.r0 = 0.0;
  EXPECT_THROW(toScaling(q), InputError);
}
