// Smoothed projection (softmin blend over the segments near the closest
// one) and the length scale of the traction law: tangent against central
// finite differences at a concave corner, a convex vertex and on a flat
// polyline; continuity across a concave corner's bisector; delta = 0 is the
// closest-segment kernel exactly; T(r) = s T_1(r/b) is the potential with
// r0 b and epsilon s / b^3.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "InteractionTestUtil.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/interaction/SurfaceInteraction.hpp"

using namespace cgcm;
using namespace cgcm::interaction;
using namespace cgcm::interaction::testing;

namespace {

struct Config {
  std::vector<Real> coords;
  std::vector<mesh::Surface> surfaces;
};

// Body 0: the polyline (x0 + 2, 2 slope) -> (x0, 0) -> (x0 - 2, 2 slope),
// outward normal up: slope > 0 a concave corner (valley), < 0 a convex one
// (ridge), both of angle 2 atan|slope| between the segments' normals.
// Body 1: one horizontal segment of length `len` centred at (x0 + xc, yc),
// outward normal down.
Config corner(Real slope, Real x0, Real xc, Real yc, Real len = 0.2) {
  Config c;
  c.surfaces.push_back(addPolyline(c.coords, {x0 + 2.0, 2.0 * slope, x0, 0.0, x0 - 2.0, 2.0 * slope}, 0));
  c.surfaces.push_back(addPolyline(c.coords, {x0 + xc - 0.5 * len, yc, x0 + xc + 0.5 * len, yc}, 1));
  return c;
}

// Body 0: flat y = 0 with uneven nodes (normal up); body 1: one segment at
// height yc centred at x0 + xc over the node at x0 (normal down).
Config flat(Real x0, Real xc, Real yc) {
  Config c;
  std::vector<Real> p;
  for (Real x : {2.0, 1.3, 0.9, 0.35, 0.0, -0.45, -0.8, -1.5, -2.0}) {
    p.push_back(x0 + x);
    p.push_back(0.0);
  }
  c.surfaces.push_back(addPolyline(c.coords, p, 0));
  c.surfaces.push_back(addPolyline(c.coords, {x0 + xc - 0.1, yc, x0 + xc + 0.1, yc}, 1));
  return c;
}

SurfaceInteractionOptions options(Formulation form, Real delta) {
  SurfaceInteractionOptions opt;
  opt.formulation = form;
  opt.projectionSmoothing = delta;
  return opt;
}

// Offset of Gauss point q of a segment of length len from its midpoint.
Real gaussOffset(int q, Real len) { return (gaussLegendreUnit(4).points[q] - 0.5) * len; }

void checkTangent(const char* name, Config c, Formulation form, Real delta, bool expectBlend) {
  auto lj = std::make_shared<LennardJones>(1.0, 1.0);
  SurfaceInteraction si(c.surfaces, {1.0, 1.2}, lj, options(form, delta));
  si.updatePairs(c.coords);
  if (expectBlend) {
    ASSERT_GT(si.summary().numBlended, 0) << name;
  }
  const Real worst = tangentError(si, c.coords, 1e-4 * delta);
  std::printf("[blend] %-24s %-13s delta = %.0e: %d of %d pairs blended, max|K - K_fd|/max|K| = %.2e\n", name,
              formulationName(form), delta, int(si.summary().numBlended), int(si.summary().numPairs), worst);
  // central differences with step 1e-4 delta: truncation ~ 1e-8 relative
  EXPECT_LT(worst, 1e-6) << name;
}

void checkTangents(Formulation form) {
  const Real x0 = form == Formulation::Axisymmetric ? 3.0 : 0.0;
  const Real angle = std::atan(0.15);  // half the corner angle
  for (Real delta : {1e-2, 1e-3}) {
    // concave corner, Gauss point 1 of the upper segment just beside the
    // bisector x = x0 (r_A - r_B = 2 u sin(angle) = 0.3 delta)
    const Real u = delta / (2.0 * std::sin(angle));
    checkTangent("concave corner", corner(0.15, x0, u - gaussOffset(1, 0.2), 1.0), form, delta, true);
    // convex vertex: every upper Gauss point lies in the vertex's region
    // (both segments project onto the vertex: equal distances and forces) ...
    checkTangent("convex vertex region", corner(-0.15, x0, 0.0, 1.0), form, delta, true);
    // ... and across the region's edge x = tan(angle) y (one foot inside)
    checkTangent("convex vertex edge", corner(-0.15, x0, std::tan(angle) * 0.8, 0.8), form, delta, true);
    // flat polyline, Gauss point 1 of the upper segment delta/2 beside a node:
    // blended with the neighbour's projection onto the node
    checkTangent("flat polyline", flat(x0, 0.5 * delta - gaussOffset(1, 0.2), 0.9), form, delta, true);
  }
}

}  // namespace

TEST(ProjectionSmoothing, BlendedTangentPlaneStrain) { checkTangents(Formulation::PlaneStrain); }
TEST(ProjectionSmoothing, BlendedTangentAxisymmetric) { checkTangents(Formulation::Axisymmetric); }

TEST(ProjectionSmoothing, ResidualIsContinuousAcrossAConcaveCornersBisector) {
  // One upper quadrature point (the segment's midpoint) moved across the
  // bisector of a concave corner of 2 atan(0.15) = 0.30 rad, in steps of
  // 1e-9 r0, pair list rebuilt at every position as in a Newton iteration.
  // With the closest segment alone the residual jumps by about T da 0.30;
  // with the blend it changes by O(step), bounded by the tangent.
  auto lj = std::make_shared<LennardJones>(1.0, 1.0);
  const Real step = 1e-9 * lj->r0();
  for (Formulation form : {Formulation::PlaneStrain, Formulation::Axisymmetric}) {
    const Real x0 = form == Formulation::Axisymmetric ? 3.0 : 0.0;
    for (Real delta : {-1.0, 1e-4, 0.0}) {  // -1: the default
      SurfaceInteractionOptions opt = options(form, delta);
      opt.quadraturePoints = 1;
      const Config c0 = corner(0.15, x0, 0.0, 1.0);
      SurfaceInteraction si(c0.surfaces, {1.0, 1.0}, lj, opt);
      const LocalIndex a = c0.surfaces[1].facets[0];  // upper segment's first node
      Real maxChange = 0.0, maxF = 0.0, maxK = 0.0;
      std::vector<Real> prev;
      for (int i = -100; i <= 100; ++i) {
        const Config c = corner(0.15, x0, i * step, 1.0);
        si.updatePairs(c.coords);
        const std::vector<Real> f = assembleResidual(si, c.coords);
        const std::vector<Real> fu(f.begin() + 2 * a, f.begin() + 2 * a + 4);  // the upper body's 4 dofs
        for (Real v : fu) maxF = std::max(maxF, std::abs(v));
        if (!prev.empty())
          for (int k = 0; k < 4; ++k) maxChange = std::max(maxChange, std::abs(fu[k] - prev[k]));
        prev = fu;
        if (i == 0)
          for (const auto& kv : assembleTangent(si, c.coords))
            if (kv.first.first >= 2 * a) maxK = std::max(maxK, std::abs(kv.second));
      }
      std::printf("[blend] %-13s delta = %.1e r0: max |f(x + dx) - f(x)| = %.3e (dx = %.0e, max |f| = %.3e, "
                  "max |K| dx = %.3e)\n",
                  formulationName(form), si.projectionSmoothing(), maxChange, step, maxF, maxK * step);
      if (delta == 0.0) {
        EXPECT_GT(maxChange, 0.1 * maxF);  // a jump: rbar turns by the corner angle
      } else {
        // a moved upper point changes f by about K dx (the 4 rows, 2 moved nodes)
        EXPECT_LT(maxChange, 4.0 * maxK * step);
        EXPECT_LT(maxChange, 1e-5 * maxF);
      }
    }
  }
}

namespace {

Config wavyPair(Real x0) {
  Config c;
  c.surfaces.push_back(addPolyline(c.coords,
                                   samplePolyline(
                                       [&](Real s, Real& x, Real& y) {
                                         x = x0 + 4.5 - 4.4 * s;
                                         y = 0.08 * std::sin(2.0 * x);
                                       },
                                       30),
                                   0));
  c.surfaces.push_back(addPolyline(c.coords,
                                   samplePolyline(
                                       [&](Real s, Real& x, Real& y) {
                                         const Real t = -kPi / 2 - 0.3 + 0.6 * s;
                                         x = x0 + 1.4 + 4.0 * std::cos(t);
                                         y = 4.0 + 0.75 + 4.0 * std::sin(t);
                                       },
                                       17),
                                   1));
  return c;
}

template <Formulation F>
void checkClosestSegmentOnly() {
  // delta = 0: every pair is the Method 3 kernel on the closest segment
  // (brute-force search, ties to the lowest id), bit for bit.
  const Config c = wavyPair(F == Formulation::Axisymmetric ? 0.3 : -1.0);
  auto lj = std::make_shared<LennardJones>(1.0, 1.0);
  SurfaceInteractionOptions opt = options(F, 0.0);
  opt.cutoff = 1.5;
  SurfaceInteraction si(c.surfaces, {1.0, 1.3}, lj, opt);
  EXPECT_EQ(si.projectionSmoothing(), 0.0);
  si.updatePairs(c.coords);
  EXPECT_EQ(si.summary().numBlended, 0);
  std::vector<PairContribution> out;
  si.evaluate(c.coords, out, true);
  ASSERT_GT(out.size(), 50u);
  BruteForceSegmentSearch2D search[2];
  for (int l = 0; l < 2; ++l) search[l].build(c.coords, c.surfaces[l]);
  const GaussRule& rule = si.quadrature();
  for (std::size_t i = 0; i < out.size(); ++i) {
    const InteractionPair& p = si.pairs()[i];
    ASSERT_EQ(p.numTargets, 1);
    ASSERT_EQ(out[i].numColNodes, 4);
    const mesh::Surface &sk = c.surfaces[p.body], &sl = c.surfaces[p.otherBody];
    const LocalIndex nodes[4] = {sk.facets[2 * p.facet], sk.facets[2 * p.facet + 1], 0, 0};
    const Real xi = rule.points[p.qp];
    const Real x[2] = {(1.0 - xi) * c.coords[2 * nodes[0]] + xi * c.coords[2 * nodes[1]],
                       (1.0 - xi) * c.coords[2 * nodes[0] + 1] + xi * c.coords[2 * nodes[1] + 1]};
    const Projection pr = search[p.otherBody].project(x, 1.5);
    ASSERT_EQ(p.target(), pr.facet);
    const LocalIndex all[4] = {nodes[0], nodes[1], sl.facets[2 * pr.facet], sl.facets[2 * pr.facet + 1]};
    Real z[8], f[4], K[4][8];
    for (int a = 0; a < 4; ++a) {
      ASSERT_EQ(out[i].colNodes[a], all[a]);
      z[2 * a] = c.coords[2 * all[a]];
      z[2 * a + 1] = c.coords[2 * all[a] + 1];
    }
    method3Pair<F>(z, xi, rule.weights[p.qp],
                   si.law(std::get<InversePowerPair>(si.kernelPotential()), p.body, p.otherBody), f, K);
    for (int r = 0; r < 4; ++r) {
      EXPECT_EQ(out[i].f[r], f[r]);
      for (int j = 0; j < 8; ++j) EXPECT_EQ(out[i].K[r][j], K[r][j]);
    }
  }
}

}  // namespace

TEST(ProjectionSmoothing, ZeroSmoothingIsTheClosestSegmentKernel) {
  checkClosestSegmentOnly<Formulation::PlaneStrain>();
  checkClosestSegmentOnly<Formulation::Axisymmetric>();
}

TEST(ProjectionSmoothing, DefaultAndValidation) {
  const Config c = corner(0.15, 0.0, 0.0, 1.0);
  auto lj = std::make_shared<LennardJones>(1.0, 1.7);
  SurfaceInteraction def(c.surfaces, {1.0, 1.0}, lj);
  EXPECT_EQ(def.projectionSmoothing(), SurfaceInteractionOptions::kDefaultProjectionSmoothing * 1.7);
  SurfaceInteraction given(c.surfaces, {1.0, 1.0}, lj, options(Formulation::PlaneStrain, 0.01));
  EXPECT_EQ(given.projectionSmoothing(), 0.01);
  EXPECT_THROW(SurfaceInteraction(c.surfaces, {1.0, 1.0}, lj,
                                  options(Formulation::PlaneStrain, std::numeric_limits<Real>::quiet_NaN())),
               InputError);
  EXPECT_THROW(def.setLengthScale(0.0), InputError);
  EXPECT_THROW(def.setLengthScale(-2.0), InputError);
  EXPECT_THROW(def.setLengthScale(std::numeric_limits<Real>::infinity()), InputError);
}

TEST(ProjectionSmoothing, FlatOnFlatIsNearlyUnchanged) {
  // The flat-on-flat case of test_surface_interaction.cpp with the default
  // delta: only upper points whose foot lies within a few delta of a lower
  // node are blended, with the neighbour's projection onto that node
  // (farther by d^2/(2h), tilted by d/h for a foot d from the node):
  // measured 6e-8 of the traction and a shear of 3e-7 of it at the default
  // delta = 1e-3 r0 (1e-12 and 0 with the closest segment alone). Without
  // the vertex penalty every point within sqrt(2 h c delta) of a node would
  // be blended: 1.3e-3 and 6e-4.
  const Real b1 = 2.0, b2 = 0.5;
  auto lj = std::make_shared<LennardJones>(0.7, 1.3);
  const Real scale = lj->peakTraction(b1, b2);
  for (Real hr : {0.55, 0.6368, 0.8, 1.0, 2.0}) {
    const Real h = hr * 1.3;
    Config c;
    c.surfaces.push_back(addPolyline(c.coords,
                                     samplePolyline(
                                         [](Real t, Real& x, Real& y) {
                                           x = 10.0 - 20.0 * t;
                                           y = 0.0;
                                         },
                                         40),
                                     0));
    c.surfaces.push_back(addPolyline(c.coords,
                                     samplePolyline(
                                         [&](Real t, Real& x, Real& y) {
                                           x = -5.0 + 10.0 * (t + 0.1 * std::sin(kPi * t));
                                           y = h;
                                         },
                                         23),
                                     1));
    SurfaceInteractionOptions opt;
    opt.cutoff = 30.0;
    SurfaceInteraction si(c.surfaces, {b1, b2}, lj, opt);
    si.updatePairs(c.coords);
    std::vector<PairContribution> out;
    si.evaluate(c.coords, out);
    const Real T = lj->traction(h, b1, b2);
    const auto& R = si.summary().resultant[1];
    const Real ref = std::max(std::abs(T), scale);
    std::printf("[blend] flat on flat h = %.4f r0, delta = %.1e r0: (F_y/L - T)/T = %+.2e, F_x/(L T) = %+.2e\n",
                hr, si.projectionSmoothing() / lj->r0(), (R[1] / 10.0 - T) / ref, R[0] / 10.0 / ref);
    EXPECT_NEAR(R[1] / 10.0, T, 3e-7 * ref) << hr;
    EXPECT_NEAR(R[0] / 10.0, 0.0, 1e-6 * ref) << hr;
  }
}

TEST(ProjectionSmoothing, ManyCandidatesAreTruncatedToTheClosest) {
  // A wide blend (delta = 0.1 r0, the segments' length) over a flat: more
  // than kMaxBlendTargets segments have rho within 30 delta of the lowest;
  // those of lowest rho are kept and counted; the tangent of the truncated
  // blend is still exact.
  Config c = flat(0.0, 0.0, 1.5);
  std::vector<Real> p;
  for (int i = 0; i <= 40; ++i) {
    p.push_back(2.0 - 0.1 * i);
    p.push_back(0.0);
  }
  c.coords.clear();
  c.surfaces.clear();
  c.surfaces.push_back(addPolyline(c.coords, p, 0));
  c.surfaces.push_back(addPolyline(c.coords, {-0.1, 1.5, 0.1, 1.5}, 1));
  auto lj = std::make_shared<LennardJones>(1.0, 1.0);
  SurfaceInteraction si(c.surfaces, {1.0, 1.0}, lj, options(Formulation::PlaneStrain, 0.1));
  si.updatePairs(c.coords);
  EXPECT_GT(si.summary().numTruncatedBlends, 0);
  for (const InteractionPair& q : si.pairs())
    if (q.body == 1) {
      EXPECT_EQ(q.numTargets, kMaxBlendTargets);
    }
  EXPECT_LT(tangentError(si, c.coords, 1e-6), 1e-6);
}

TEST(ProjectionSmoothing, LengthScaleIsThePotentialWithScaledR0AndEpsilon) {
  // strength s and length scale b: T(r) = s T_1(r/b) with the cutoff, taper
  // and smoothing scaled by b, which for Lennard-Jones (Phi ~ eps r0^3
  // f(r0/r)) is the potential with r0 b and eps s / b^3.
  const Real s = 0.6, b = 1.7;
  const Config c = wavyPair(-1.0);
  for (Formulation form : {Formulation::PlaneStrain, Formulation::Axisymmetric}) {
    const Config cf = form == Formulation::Axisymmetric ? wavyPair(0.3) : c;
    SurfaceInteractionOptions opt = options(form, -1.0);  // default cutoff and smoothing, both ~ r0
    auto lj = std::make_shared<LennardJones>(2.0, 0.5);
    auto scaled = std::make_shared<LennardJones>(2.0 * s / (b * b * b), 0.5 * b);
    SurfaceInteraction si(cf.surfaces, {1.0, 1.3}, lj, opt), ref(cf.surfaces, {1.0, 1.3}, scaled, opt);
    EXPECT_EQ(si.lengthScale(), 1.0);
    si.setStrength(s);
    si.setLengthScale(b);
    EXPECT_EQ(si.lengthScale(), b);
    EXPECT_NEAR(si.cutoff(), ref.cutoff(), 1e-15 * ref.cutoff());
    EXPECT_NEAR(si.cutoff(), 10.0 * 0.5 * b, 1e-14);
    EXPECT_NEAR(si.summary().cutoff, ref.summary().cutoff, 1e-15 * ref.cutoff());
    EXPECT_NEAR(si.summary().taperStart, ref.summary().taperStart, 1e-15 * ref.cutoff());
    EXPECT_NEAR(si.projectionSmoothing(), ref.projectionSmoothing(), 1e-15 * ref.projectionSmoothing());

    // the law itself, including the taper
    const auto L = si.law(std::get<InversePowerPair>(si.kernelPotential()), 0, 1);
    const auto Lr = ref.law(std::get<InversePowerPair>(ref.kernelPotential()), 0, 1);
    for (Real r = 0.3; r < 1.1 * si.cutoff(); r *= 1.05) {
      Real T, dT, Tr, dTr;
      L(r, T, dT);
      Lr(r, Tr, dTr);
      EXPECT_NEAR(T, Tr, 1e-13 * std::abs(Tr) + 1e-300) << r;
      EXPECT_NEAR(dT, dTr, 1e-13 * std::abs(dTr) + 1e-300) << r;
    }

    // every pair's f and K
    si.updatePairs(cf.coords);
    ref.updatePairs(cf.coords);
    ASSERT_EQ(si.pairs().size(), ref.pairs().size());
    std::vector<PairContribution> a, e;
    si.evaluate(cf.coords, a);
    ref.evaluate(cf.coords, e);
    Real worstF = 0.0, scaleF = 0.0, worstK = 0.0, scaleK = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      ASSERT_EQ(a[i].numColNodes, e[i].numColNodes);
      for (int r = 0; r < 4; ++r) {
        worstF = std::max(worstF, std::abs(a[i].f[r] - e[i].f[r]));
        scaleF = std::max(scaleF, std::abs(e[i].f[r]));
        for (int j = 0; j < 2 * a[i].numColNodes; ++j) {
          worstK = std::max(worstK, std::abs(a[i].K[r][j] - e[i].K[r][j]));
          scaleK = std::max(scaleK, std::abs(e[i].K[r][j]));
        }
      }
    }
    EXPECT_GT(scaleF, 0.0);
    EXPECT_LT(worstF, 1e-12 * scaleF);
    EXPECT_LT(worstK, 1e-10 * scaleK);  // the blend divides by delta (rounding of f amplified)

    // and the tangent at b != 1 against finite differences
    const Real worst = tangentError(si, cf.coords, 1e-7);
    std::printf("[blend] %-13s length scale %.1f, strength %.1f: %d pairs, max|K - K_fd|/max|K| = %.2e\n",
                formulationName(form), b, s, int(si.summary().numPairs), worst);
    EXPECT_LT(worst, 1e-6);
  }
}
