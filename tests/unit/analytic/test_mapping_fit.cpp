// CGCM <-> Maugis-Dugdale mapping, theoretical λ and Tabor μ, load-curve
// reading and the least-squares fit of λ.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "cgcm/analytic/CgcmMapping.hpp"
#include "cgcm/analytic/LoadCurveFit.hpp"
#include "cgcm/analytic/MaugisDugdale.hpp"
#include "cgcm/analytic/PullOff.hpp"
#include "cgcm/analytic/Quadrature.hpp"
#include "cgcm/core/Error.hpp"

namespace an = cgcm::analytic;
using cgcm::Real;

namespace {

using cgcm::kPi;

std::string tempPath(const std::string& name) {
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir ? dir : "/tmp") + "/cgcm_analytic_test_" + name;
}

}  // namespace

// γL = 50, γW = 200, ν = 0.2, checked from first principles in CGCM units
// (R0 = Y = 1, so r0 = 1/γL and β0²ε = γL³/γW by (22), (28)), not from the
// formulas of the mapping:
//  - w = −∫_{r_S0}^∞ T(h) dh by quadrature of the half-space traction
//    T(h) = π β0² ε r0³ [(r0/h)⁹/45 − (r0/h)³/3], r_S0 = r0/15^(1/6);
//  - σ0 = max(−T) by golden-section search;
//  - E* from 1/E* = (1−ν²)/Y + (1−ν²)/Y, R = R0 (R2 = ∞);
//  - every factor from its definition in (36) with these w, E*, R.
// By hand: f_w = (π/8)·15^(1/3) = 0.392699·2.466212 = 0.968479;
// f_E = 1/(2·0.96) = 0.520833; f_F = π·0.968479/(200·50) = 3.04257e-4;
// f_a = (0.75·3.04257e-4/0.520833)^(1/3) = (4.38130e-4)^(1/3) = 0.0759511;
// f_δ = 0.0759511² = 5.76857e-3; f_σ = ((2/9)·3.04257e-4·0.271267)^(1/3)
// = (1.83411e-5)^(1/3) = 0.0263719; σ0 = (2√5π/9)/200 = 7.80535e-3;
// λ = σ0/f_σ = 0.295972; μ = (0.968479²·√15/0.271267·50/200²)^(1/3)
// = (0.0167390)^(1/3) = 0.255807.
TEST(CgcmMapping, HandCheckedFactorsForGammaL50GammaW200Nu02) {
  const Real gL = 50, gW = 200, nu = 0.2;
  const Real r0 = 1 / gL, b2e = gL * gL * gL / gW;
  auto T = [&](Real h) { return kPi * b2e * std::pow(r0, 3) * (std::pow(r0 / h, 9) / 45 - std::pow(r0 / h, 3) / 3); };
  const Real rS0 = r0 / std::pow(15.0, 1.0 / 6.0);
  EXPECT_NEAR(T(rS0), 0.0, 1e-12);
  // h = rS0/t maps [rS0, ∞) onto (0, 1].
  auto tail = [&](Real t) { return T(rS0 / t) * rS0 / (t * t); };
  const Real w = -an::integrateAdaptive(tail, {0.0, 1.0}, 0.0, 1e-12, 2000, "w").value;
  Real lo = rS0, hi = 3 * r0;  // golden section for the most tensile traction
  for (int i = 0; i < 200; ++i) {
    const Real x1 = hi - 0.618033988749895 * (hi - lo), x2 = lo + 0.618033988749895 * (hi - lo);
    if (T(x1) < T(x2)) hi = x2; else lo = x1;
  }
  const Real sigma0 = -T(0.5 * (lo + hi));
  const Real Estar = 1 / (2 * (1 - nu * nu));
  const Real R = 1;
  const auto jg = an::JohnsonGreenwoodScales::from(w, R, Estar);

  const an::CgcmMapping m = an::cgcmMapping(gL, gW, nu);
  EXPECT_NEAR(m.fw, w / (b2e * std::pow(r0, 4)), 1e-12);
  EXPECT_NEAR(m.workOfAdhesion, w, 1e-15);
  EXPECT_NEAR(m.fE, Estar, 1e-15);
  EXPECT_NEAR(m.fF, jg.force, 1e-12 * m.fF);          // P = P̄_MD · πwR, in units of Y R0²
  EXPECT_NEAR(m.fa, jg.length, 1e-12 * m.fa);         // a = ā_MD · L, in units of R0
  EXPECT_NEAR(m.fdelta, jg.approach, 1e-12 * m.fdelta);
  EXPECT_NEAR(m.fsigma, jg.pressure, 1e-12 * m.fsigma);
  EXPECT_NEAR(m.sigmaMax, sigma0, 1e-10 * sigma0);
  EXPECT_NEAR(m.lambdaTheory, sigma0 / jg.pressure, 1e-9);  // (41): λ = σ0 in p̄ units
  EXPECT_NEAR(m.muTabor, std::cbrt(R * w * w / (Estar * Estar * std::pow(rS0, 3))), 1e-12);

  // The hand values above, to their printed digits.
  EXPECT_NEAR(m.fw, 0.968479, 1e-6);
  EXPECT_NEAR(m.fE, 0.520833, 1e-6);
  EXPECT_NEAR(m.fF, 3.04257e-4, 1e-9);
  EXPECT_NEAR(m.fa, 0.0759511, 1e-7);
  EXPECT_NEAR(m.fdelta, 5.76857e-3, 1e-8);
  EXPECT_NEAR(m.fsigma, 0.0263719, 1e-7);
  EXPECT_NEAR(m.sigmaMax, 7.80535e-3, 1e-8);
  EXPECT_NEAR(m.lambdaTheory, 0.295972, 1e-6);
  EXPECT_NEAR(m.muTabor, 0.255807, 1e-6);
  // λ/μ = 1.1570 for this law (theory sheet §5), whatever γL, γW, ν.
  EXPECT_NEAR(m.lambdaTheory / m.muTabor, 1.1570, 1e-4);
  const an::CgcmMapping m2 = an::cgcmMapping(5, 20, 0.35);
  EXPECT_NEAR(m2.lambdaTheory / m2.muTabor, m.lambdaTheory / m.muTabor, 1e-13);
}

TEST(CgcmMapping, RejectsBadParameters) {
  EXPECT_THROW(an::cgcmMapping(0, 200, 0.2), cgcm::InputError);
  EXPECT_THROW(an::cgcmMapping(50, -1, 0.2), cgcm::InputError);
  EXPECT_THROW(an::cgcmMapping(50, 200, 0.5), cgcm::InputError);
  EXPECT_THROW(an::cgcmMapping(50, 200, -1.0), cgcm::InputError);
}

namespace {

/// A synthetic CGCM load curve from the M-D model itself: an approach phase
/// (the bodies still apart, slight attraction) that the default window must
/// drop, then the displacement-control branch from its end ā_d to ā = 3,
/// mapped by f_F, f_δ and shifted by `offset`.
an::LoadCurve syntheticCurve(const an::CgcmMapping& map, Real lambda, Real offset, int n) {
  an::LoadCurve c;
  const an::PullOff po = an::pullOff(an::ContactModel::maugisDugdale(lambda));
  const Real uEnd = map.fdelta * po.displacementControl.approach + offset;
  for (int i = 0; i < 15; ++i) {
    c.u.push_back(uEnd - 0.03 + 0.002 * i);
    c.P.push_back(-1e-6 * (i + 1));
  }
  const Real a0 = std::fmax(po.displacementControl.a, 1e-3);
  for (int i = 0; i <= n; ++i) {
    const Real a = a0 + (3.0 - a0) * i / n;
    const an::MdSolution s = an::solveMaugisDugdale(lambda, a);
    c.u.push_back(map.fdelta * s.approach + offset);
    c.P.push_back(map.fF * s.load);
  }
  return c;
}

void writeCsv(const std::string& path, const an::LoadCurve& c) {
  std::ofstream out(path);
  out << "# synthetic load curve (Maugis-Dugdale)\n";
  out << "step,u,P,gap,contact_radius,newton_iterations,jump\n";
  for (std::size_t i = 0; i < c.u.size(); ++i) {
    char line[200];
    std::snprintf(line, sizeof line, "%zu,%.17g,%.17g,0.01,0.1,3,0\n", i, c.u[i], c.P[i]);
    out << line;
  }
}

}  // namespace

TEST(LoadCurve, ReadsColumnsByName) {
  const std::string path = tempPath("read.csv");
  {
    std::ofstream out(path);
    out << "# comment\n\nP, step ,u,jump\n1.5,0,-0.1,0\n-2e-3,1,0.25,1\n";
  }
  const an::LoadCurve c = an::readLoadCurveCsv(path);
  ASSERT_EQ(c.u.size(), 2u);
  EXPECT_EQ(c.u[0], -0.1);
  EXPECT_EQ(c.P[1], -2e-3);
  std::remove(path.c_str());
}

TEST(LoadCurve, ReportsBadFiles) {
  EXPECT_THROW(an::readLoadCurveCsv(tempPath("does_not_exist.csv")), cgcm::InputError);
  const std::string path = tempPath("bad.csv");
  auto expectBad = [&](const std::string& text, const std::string& fragment) {
    {
      std::ofstream out(path);
      out << text;
    }
    try {
      an::readLoadCurveCsv(path);
      ADD_FAILURE() << "no error for: " << text;
    } catch (const cgcm::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  expectBad("step,P\n0,1\n", "no column 'u'");
  expectBad("u,P\n0,1\n1,abc\n", "not a finite number");
  expectBad("u,P\n0,1\n1,2,3\n", "3 fields");
  expectBad("u,P\n", "no data rows");
  expectBad("u,P\n0,nan\n", "not a finite number");
  std::remove(path.c_str());
}

TEST(LoadCurveFit, DefaultWindowStartsAtTheMinimumLoad) {
  an::LoadCurve c;
  c.u = {-0.2, -0.1, 0.0, 0.1, 0.2};
  c.P = {0.0, -0.5, -1.0, -0.2, 0.7};
  const std::vector<std::size_t> idx = an::fitWindow(c, {});
  EXPECT_EQ(idx, (std::vector<std::size_t>{2, 3, 4}));
  an::FitOptions o;
  o.uMin = -0.15;
  o.uMax = 0.05;
  EXPECT_EQ(an::fitWindow(c, o), (std::vector<std::size_t>{1, 2}));
}

// The fit recovers the λ (and offset) a curve was made with. The data is
// exact, so λ is found to 1e-6 and the residual is at rounding level.
TEST(LoadCurveFit, RecoversLambdaOfASyntheticCurve) {
  const an::CgcmMapping map = an::cgcmMapping(50, 200, 0.2);
  const Real lambda = 0.4, offset = 2e-3;
  const std::string path = tempPath("synthetic.csv");
  writeCsv(path, syntheticCurve(map, lambda, offset, 120));
  const an::LoadCurve curve = an::readLoadCurveCsv(path);
  std::remove(path.c_str());

  // The model reproduces a data point exactly.
  EXPECT_NEAR(an::mdCgcmLoadAtApproach(map, lambda, offset, curve.u[40]), curve.P[40],
              1e-12 * map.fF);

  an::FitOptions fixed;
  fixed.offset = offset;
  const an::FitResult r1 = an::fitMaugisDugdale(curve, map, fixed);
  EXPECT_NEAR(r1.lambda, lambda, 1e-6 * lambda);
  // The fit's minimiser (Boost's Brent) locates a minimum to 2^-26 ≈ 1.5e-8
  // relative, so even an exact curve leaves an rms of about 5e-10 fF here
  // (5e-8 fF with the offset fitted too, a minimisation nested in another).
  EXPECT_LT(r1.rms, 1e-8 * map.fF);
  // The window is u ≥ u(P_min): the approach phase and the descending part
  // of the branch before the load minimum are left out.
  const std::size_t iMin = static_cast<std::size_t>(
      std::min_element(curve.P.begin(), curve.P.end()) - curve.P.begin());
  std::size_t inWindow = 0;
  for (Real u : curve.u) inWindow += (u >= curve.u[iMin]) ? 1 : 0;
  EXPECT_EQ(r1.points, inWindow);
  EXPECT_GT(inWindow, 80u);
  EXPECT_LT(inWindow, 121u);
  EXPECT_EQ(r1.uFrom, curve.u[iMin]);
  EXPECT_FALSE(r1.atBound);

  an::FitOptions free;
  free.fitOffset = true;  // search centred at 0, half-width = half the u-span
  const an::FitResult r2 = an::fitMaugisDugdale(curve, map, free);
  EXPECT_NEAR(r2.lambda, lambda, 1e-6 * lambda);
  EXPECT_NEAR(r2.offset, offset, 1e-9);
  EXPECT_LT(r2.rms, 1e-6 * map.fF);

  // With a wrong fixed offset the fit is worse and λ is off.
  an::FitOptions wrong;
  wrong.offset = offset + 2e-3;
  const an::FitResult r3 = an::fitMaugisDugdale(curve, map, wrong);
  EXPECT_GT(r3.rms, 1e3 * r2.rms);
}

// Noise of 0.3 % of the load range moves the best fit only a little.
TEST(LoadCurveFit, IsRobustToSmallNoise) {
  const an::CgcmMapping map = an::cgcmMapping(50, 20, 0.2);
  const Real lambda = 1.3;
  an::LoadCurve c = syntheticCurve(map, lambda, 0.0, 80);
  Real pMin = 0, pMax = 0;
  for (Real p : c.P) {
    pMin = std::fmin(pMin, p);
    pMax = std::fmax(pMax, p);
  }
  for (std::size_t i = 0; i < c.P.size(); ++i) c.P[i] += 3e-3 * (pMax - pMin) * std::sin(7.0 * i);
  const an::FitResult r = an::fitMaugisDugdale(c, map, {});
  EXPECT_NEAR(r.lambda, lambda, 0.05 * lambda);
  EXPECT_NEAR(r.rmsRelative, 3e-3 / std::sqrt(2.0), 1e-3);
}

TEST(LoadCurveFit, RejectsBadOptions) {
  const an::CgcmMapping map = an::cgcmMapping(50, 200, 0.2);
  const an::LoadCurve c = syntheticCurve(map, 0.5, 0.0, 20);
  an::FitOptions o;
  o.lambdaMin = 10;
  o.lambdaMax = 1;
  EXPECT_THROW(an::fitMaugisDugdale(c, map, o), cgcm::InputError);
  an::FitOptions w;
  w.uMin = 100;
  w.uMax = 200;
  EXPECT_THROW(an::fitMaugisDugdale(c, map, w), cgcm::InputError);
}
