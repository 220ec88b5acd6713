// Curves of the analytic models: the Maugis-Dugdale solver over its whole
// validated range, its slopes, its JKR (λ → ∞) and DMT (λ → 0) limits, and
// the Hertz limit w → 0 in physical units.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "cgcm/analytic/MaugisDugdale.hpp"
#include "cgcm/analytic/Models.hpp"
#include "cgcm/core/Error.hpp"
#include "Sampling.hpp"

namespace an = cgcm::analytic;
using cgcm::Real;

namespace {

using cgcm::analytic::test::logspace;

}  // namespace

// (42) has one root s = √(m²−1) > 0 for every ā > 0; the solver must find it
// over λ ∈ [1e-3, 1e3] × ā ∈ [1e-4, 10] (from m − 1 ≈ 1e-8 to m ≈ 4e5),
// to rounding, and s must fall with ā (∂F/∂ā > 0, ∂F/∂s > 0).
TEST(MaugisDugdale, SolverCoversTheValidatedRange) {
  Real sMin = std::numeric_limits<Real>::infinity();
  Real sMax = 0;
  for (Real lambda : logspace(1e-3, 1e3, 25)) {
    Real previous = std::numeric_limits<Real>::infinity();
    for (Real a : logspace(1e-4, 10, 41)) {
      const an::MdSolution sol = an::solveMaugisDugdale(lambda, a);
      ASSERT_TRUE(std::isfinite(sol.s) && sol.s > 0) << "lambda " << lambda << " a " << a;
      EXPECT_GT(sol.m, 1.0);
      // F(s) = 0 to rounding: F is a sum of positive terms equal to 1.
      EXPECT_LE(std::fabs(an::mdResidual(lambda, a, sol.s)), 1e-13) << lambda << " " << a;
      // The root is bracketed a relative 1e-9 either side (no spurious stop).
      EXPECT_LT(an::mdResidual(lambda, a, sol.s * (1 - 1e-9)), 0.0);
      EXPECT_GT(an::mdResidual(lambda, a, sol.s * (1 + 1e-9)), 0.0);
      EXPECT_LT(sol.s, previous) << "s must decrease with a (lambda " << lambda << ")";
      previous = sol.s;
      sMin = std::fmin(sMin, sol.s);
      sMax = std::fmax(sMax, sol.s);
    }
  }
  // Both limits were really exercised.
  EXPECT_LT(sMin, 1e-3);
  EXPECT_GT(sMax, 1e5);
}

TEST(MaugisDugdale, WarmStartGivesTheSameRoot) {
  for (Real guess : {1e-12, 1e-3, 1.0, 1e3, 1e9}) {
    EXPECT_NEAR(an::solveMdS(0.7, 0.9, guess), an::solveMdS(0.7, 0.9), 1e-14);
  }
}

TEST(MaugisDugdale, RejectsBadInput) {
  EXPECT_THROW(an::solveMdS(0.0, 1.0), cgcm::InputError);
  EXPECT_THROW(an::solveMdS(-1.0, 1.0), cgcm::InputError);
  EXPECT_THROW(an::solveMdS(1.0, 0.0), cgcm::InputError);
  EXPECT_THROW(an::solveMdS(std::nan(""), 1.0), cgcm::InputError);
  EXPECT_THROW(an::solveMdS(1.0, std::numeric_limits<Real>::infinity()), cgcm::InputError);
  EXPECT_THROW(an::ContactModel::maugisDugdale(0.0), cgcm::InputError);
  EXPECT_THROW(an::ContactModel::make(an::Model::MaugisDugdale, std::nullopt), cgcm::InputError);
  EXPECT_THROW(an::ContactModel::make(an::Model::Jkr, 1.0), cgcm::InputError);
  EXPECT_THROW(an::parseModel("bradley"), cgcm::InputError);
  EXPECT_THROW(an::ContactModel::jkr().at(-1.0), cgcm::InputError);
}

TEST(Models, ParseAndName) {
  for (auto m : {an::Model::Hertz, an::Model::Jkr, an::Model::Dmt, an::Model::MaugisDugdale}) {
    EXPECT_EQ(an::parseModel(an::modelName(m)), m);
  }
}

// The closed-form slopes (implicit differentiation of (42) for M-D) against
// central differences of P̄(ā), δ̄(ā); h = 1e-5 ā gives a truncation error
// ~1e-10 and a rounding error ~1e-11 relative.
TEST(Models, SlopesMatchFiniteDifferences) {
  std::vector<an::ContactModel> models = {an::ContactModel::hertz(), an::ContactModel::jkr(),
                                          an::ContactModel::dmt()};
  for (Real lambda : {0.01, 0.3, 1.0, 10.0, 300.0}) models.push_back(an::ContactModel::maugisDugdale(lambda));
  for (const auto& model : models) {
    for (Real a : {0.05, 0.5, 1.2, 3.0}) {
      const Real h = 1e-5 * a;
      const an::CurvePoint p = model.at(a + h);
      const an::CurvePoint m = model.at(a - h);
      const an::CurveSlopes d = model.slopes(a);
      EXPECT_NEAR(d.dLoad, (p.load - m.load) / (2 * h), 1e-6 * std::fmax(1.0, std::fabs(d.dLoad)))
          << model.describe() << " a " << a;
      EXPECT_NEAR(d.dApproach, (p.approach - m.approach) / (2 * h),
                  1e-6 * std::fmax(1.0, std::fabs(d.dApproach)))
          << model.describe() << " a " << a;
    }
  }
}

// λ → ∞: M-D tends to JKR (39). The gap shrinks with λ; at λ = 1e3 it is
// below 2e-5 in P̄ and δ̄ for ā ∈ [0.3, 3].
TEST(MaugisDugdale, TendsToJkrAsLambdaGrows) {
  const an::ContactModel jkr = an::ContactModel::jkr();
  for (Real a : {0.3, 0.6, 1.0, 1.5, 3.0}) {
    Real previous = std::numeric_limits<Real>::infinity();
    for (Real lambda : {10.0, 100.0, 1000.0}) {
      const an::CurvePoint md = an::ContactModel::maugisDugdale(lambda).at(a);
      const an::CurvePoint ref = jkr.at(a);
      const Real gap = std::fmax(std::fabs(md.load - ref.load), std::fabs(md.approach - ref.approach));
      EXPECT_LT(gap, previous) << "a " << a << " lambda " << lambda;
      previous = gap;
    }
    EXPECT_LT(previous, 2e-5) << "a " << a;
  }
}

// λ → 0: M-D tends to DMT (40). From (42) and (43) at large s the gaps are
// P̄_MD − P̄_DMT ≈ −πλā² and δ̄_MD − δ̄_DMT ≈ −(4/3)√(4λ/π), so they are
// checked against 4λā² and 2√λ over four decades of λ (and they vanish).
TEST(MaugisDugdale, TendsToDmtAsLambdaVanishes) {
  const an::ContactModel dmt = an::ContactModel::dmt();
  for (Real a : {0.5, 1.0, 1.5, 3.0}) {
    const an::CurvePoint ref = dmt.at(a);
    for (Real lambda : {1e-3, 1e-5, 1e-7}) {
      const an::CurvePoint md = an::ContactModel::maugisDugdale(lambda).at(a);
      EXPECT_NEAR(md.load, ref.load, 4 * lambda * a * a) << "a " << a << " lambda " << lambda;
      EXPECT_LT(md.load, ref.load) << "a " << a << " lambda " << lambda;
      EXPECT_NEAR(md.approach, ref.approach, 2 * std::sqrt(lambda)) << "a " << a << " lambda " << lambda;
    }
  }
}

// The ā → 0 end of the M-D branch against the solver at small ā: the limit
// of P̄ and δ̄ is approached linearly in ā.
TEST(MaugisDugdale, ZeroContactLimit) {
  for (Real lambda : {1e-3, 0.1, 1.0, 10.0, 1e3}) {
    const an::MdZeroContact z = an::mdZeroContactLimit(lambda);
    const an::MdSolution sol = an::solveMaugisDugdale(lambda, 1e-9);
    EXPECT_NEAR(sol.m * sol.a, z.c, 1e-6 * z.c) << lambda;
    EXPECT_NEAR(sol.load, z.load, 1e-6 * std::fmax(1e-3, std::fabs(z.load))) << lambda;
    EXPECT_NEAR(sol.approach, z.approach, 1e-6) << lambda;
  }
  // λ → 0: the DMT/Bradley value −2.
  EXPECT_NEAR(an::mdZeroContactLimit(1e-8).load, -2.0, 1e-6);
}

// Hertz is recovered as w → 0: at a fixed physical contact radius the
// normalised ā = a/L grows like w^(−1/3), and the adhesive corrections to
// P = P̄ πwR and δ = δ̄ L_δ vanish. Physical units: R = 2, E* = 3, a = 0.1;
// Hertz: P = 4E*a³/(3R), δ = a²/R.
TEST(Models, HertzIsRecoveredAsWorkOfAdhesionVanishes) {
  const Real R = 2, Estar = 3, a = 0.1;
  const Real hertzP = 4 * Estar * a * a * a / (3 * R);
  const Real hertzDelta = a * a / R;
  std::vector<an::ContactModel> models = {an::ContactModel::hertz(), an::ContactModel::jkr(),
                                          an::ContactModel::dmt(),
                                          an::ContactModel::maugisDugdale(1.0)};
  for (const auto& model : models) {
    Real previous = std::numeric_limits<Real>::infinity();
    for (Real w : {1e-4, 1e-7, 1e-10, 1e-13}) {
      const auto s = an::JohnsonGreenwoodScales::from(w, R, Estar);
      const an::CurvePoint p = model.at(a / s.length);
      const Real errP = std::fabs(p.load * s.force - hertzP) / hertzP;
      const Real errD = std::fabs(p.approach * s.approach - hertzDelta) / hertzDelta;
      if (model.kind() == an::Model::Hertz) {
        // (37) with (36): w cancels exactly.
        EXPECT_LT(errP, 1e-13);
        EXPECT_LT(errD, 1e-13);
      } else {
        EXPECT_LT(std::fmax(errP, errD), previous) << model.describe() << " w " << w;
        previous = std::fmax(errP, errD);
      }
    }
    // At w = 1e-13 the JKR-like corrections are ~√(w/...) ≈ 1e-4.
    if (model.kind() != an::Model::Hertz) {
      EXPECT_LT(previous, 1e-3) << model.describe();
    }
  }
}

TEST(Models, JohnsonGreenwoodScalesAreConsistent) {
  const auto s = an::JohnsonGreenwoodScales::from(0.3, 2.0, 5.0);
  // L_δ = L²/R and L² S = πwR/2 (the pressure integrates to the load).
  EXPECT_NEAR(s.approach, s.length * s.length / 2.0, 1e-14);
  EXPECT_NEAR(s.length * s.length * s.pressure, s.force / 2, 1e-14);
  EXPECT_THROW(an::JohnsonGreenwoodScales::from(0.0, 1.0, 1.0), cgcm::InputError);
}
