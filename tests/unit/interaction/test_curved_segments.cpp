// Method 3 on curved segments (Line3, the facets of quadratic 2D cells):
// the projection is the global closest point of the segment; on straight
// segments the curved kernel is the linear one; its tangent and blend
// gradient against central differences; a straight Line3 surface acts as the
// Line2 surface through its corners; on a circle the force converges to the
// exact Method 3 integral far faster than on the chords of the same nodes;
// the assembled tangent of a blended curved contact.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include "InteractionTestUtil.hpp"
#include "cgcm/interaction/Method3CurvedKernel.hpp"
#include "cgcm/interaction/PairPotential.hpp"
#include "cgcm/interaction/SurfaceInteraction.hpp"

using namespace cgcm;
using namespace cgcm::interaction;
using namespace cgcm::interaction::testing;

namespace {

constexpr Real kInf = std::numeric_limits<Real>::infinity();

TractionLaw<InversePowerPair> lawOf(const LennardJones& lj, Real beta = 1.2) {
  return {std::get<InversePowerPair>(lj.kernelPotential()), beta, kInf, kInf};
}

// The closest point of a Line3 by brute force: 20001 samples, then golden
// section on the best sample's neighbourhood.
Real bruteForceDistance(const Real x[2], const Real* y) {
  auto d2 = [&](Real e) {
    Real p[2], t[2];
    interaction::detail::curvePoint<3>(y, e, p, t);
    return (p[0] - x[0]) * (p[0] - x[0]) + (p[1] - x[1]) * (p[1] - x[1]);
  };
  const int n = 20000;
  int best = 0;
  for (int i = 1; i <= n; ++i)
    if (d2(Real(i) / n) < d2(Real(best) / n)) best = i;
  Real lo = std::max(0.0, Real(best - 1) / n), hi = std::min(1.0, Real(best + 1) / n);
  const Real g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int it = 0; it < 200; ++it) {
    const Real a = hi - g * (hi - lo), b = lo + g * (hi - lo);
    (d2(a) < d2(b) ? hi : lo) = d2(a) < d2(b) ? b : a;
  }
  return std::sqrt(std::min({d2(0.5 * (lo + hi)), d2(0.0), d2(1.0)}));
}

}  // namespace

// Strongly curved segments (up to a U whose mid node lies far off the chord)
// and points on both sides, beyond the centre of curvature and off the ends:
// the projection finds the global minimum over [0, 1], ends included.
TEST(CurvedSegments, ProjectionIsTheGlobalClosestPoint) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  Real worst = 0.0;
  int interior = 0, ends = 0;
  for (int c = 0; c < 4000; ++c) {
    const Real bow = 1.5 * u(rng);  // mid node off the chord, up to 1.5 x its half length
    const Real y[6] = {-1.0, 0.0, 1.0 + 0.2 * u(rng), 0.3 * u(rng), 0.1 * u(rng), bow};
    const Real x[2] = {2.0 * u(rng), 2.0 * u(rng)};
    Real eta, p[2];
    int region;
    const Real d = std::sqrt(projectOntoCurve<3>(x, y, eta, p, region));
    (region == 0 ? interior : ends)++;
    const Real ref = bruteForceDistance(x, y);
    worst = std::max(worst, d - ref);
    // the point returned is the curve's point at eta, at the distance returned
    Real q[2], t[2];
    interaction::detail::curvePoint<3>(y, eta, q, t);
    ASSERT_NEAR(std::hypot(q[0] - x[0], q[1] - x[1]), d, 1e-13);
    ASSERT_NEAR(q[0], p[0], 1e-13);
    ASSERT_NEAR(q[1], p[1], 1e-13);
  }
  std::printf("[curved] projection: %d interior, %d end projections, max(d - d_brute) = %.2e\n", interior, ends,
              worst);
  // never farther than the brute-force minimum (which is itself only accurate to ~1e-12 here)
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(interior, 1000);
  EXPECT_GT(ends, 100);
}

namespace {

struct KernelCase {
  const char* name;
  Real z[18];  // e (2 NE), s (2 NS), neighbour (2 NS)
  int neighbourEnd;
  int expectedRegion;
};

template <Formulation F, int NE, int NS>
void checkCurvedKernel(const KernelCase& c, Real delta, const Real* dA) {
  const LennardJones lj(1.0, 1.0);
  const auto law = lawOf(lj);
  constexpr int nz = 2 * (NE + 2 * NS), nf = 2 * NE;
  const GaussRule rule = gaussLegendreUnit(4);
  Real worstK = 0.0, worstRho = 0.0;
  for (int q = 0; q < rule.size(); ++q) {
    const Real xi = rule.points[q], w = rule.weights[q];
    Real f[nf], K[nf * nz], rho, Jrho[nz];
    const PairState st = method3CurvedPair<F, NE, NS>(c.z, xi, w, law, c.neighbourEnd, delta, dA, f, rho, K, Jrho);
    ASSERT_GT(st.distance, 0.0) << c.name;
    if (c.expectedRegion >= 0) {
      ASSERT_EQ(st.region, c.expectedRegion) << c.name << " qp " << q;
    }
    Real kmax = 0.0, gmax = 0.0;
    for (int j = 0; j < nz; ++j) gmax = std::max(gmax, std::abs(Jrho[j]));
    for (int i = 0; i < nf * nz; ++i) kmax = std::max(kmax, std::abs(K[i]));
    ASSERT_GT(kmax, 0.0);
    const Real h = 1e-6;
    for (int j = 0; j < nz; ++j) {
      Real zp[nz], zm[nz], fp[nf], fm[nf], rp, rm;
      std::copy(c.z, c.z + nz, zp);
      std::copy(c.z, c.z + nz, zm);
      zp[j] += h;
      zm[j] -= h;
      method3CurvedPair<F, NE, NS>(zp, xi, w, law, c.neighbourEnd, delta, dA, fp, rp, nullptr, nullptr);
      method3CurvedPair<F, NE, NS>(zm, xi, w, law, c.neighbourEnd, delta, dA, fm, rm, nullptr, nullptr);
      for (int i = 0; i < nf; ++i)
        worstK = std::max(worstK, std::abs(K[i * nz + j] - (fp[i] - fm[i]) / (2 * h)) / kmax);
      worstRho = std::max(worstRho, std::abs(Jrho[j] - (rp - rm) / (2 * h)) / gmax);
    }
  }
  std::printf("[curved] kernel %-13s NE %d NS %d %-22s delta %.0e %s: max|K - K_fd|/max|K| = %.2e, "
              "max|drho - drho_fd|/max|drho| = %.2e\n",
              formulationName(F), NE, NS, c.name, delta, dA ? "dA" : "da", worstK, worstRho);
  // central differences with step 1e-6 on O(1) coordinates: truncation and rounding ~1e-9 relative
  EXPECT_LT(worstK, 1e-6) << c.name;
  EXPECT_LT(worstRho, 1e-6) << c.name;
}

// Segment e above (body on top: a -> b to the right gives the outward normal
// down), target s below (a -> b to the left, normal up), both bowed.
template <int NE, int NS>
std::vector<KernelCase> curvedCases(Real shiftX) {
  std::vector<KernelCase> cases;
  auto make = [&](const char* name, std::initializer_list<Real> e, std::initializer_list<Real> s,
                  std::initializer_list<Real> n, int end, int region) {
    KernelCase k{name, {}, end, region};
    int j = 0;
    for (Real v : e) k.z[j++] = v;
    for (Real v : s) k.z[j++] = v;
    for (Real v : n) k.z[j++] = v;
    for (int i = 0; i < j; i += 2) k.z[i] += shiftX;
    return k;
  };
  // e: Line3 (a, b, mid) or Line2 (a, b); s, n likewise
  const std::initializer_list<Real> e3 = {0.1, 0.95, 1.2, 1.1, 0.62, 0.93};
  const std::initializer_list<Real> e2 = {0.1, 0.95, 1.2, 1.1};
  const bool q = NE == 3;
  if constexpr (NS == 3) {
    cases.push_back(make("interior", q ? e3 : e2, {1.6, 0.1, -0.4, -0.05, 0.55, 0.22}, {}, -1, 0));
    // s to the right: x projects onto s's end b = (2.0, 0.0), shared with the neighbour n
    // that goes on to the left-down ... (its end 0 is the vertex: a convex vertex, o_n > 0)
    cases.push_back(make("vertex b, neighbour", q ? e3 : e2, {3.1, 0.2, 2.0, 0.0, 2.6, 0.16},
                         {2.0, 0.0, 1.2, -0.5, 1.55, -0.2}, 0, 2));
    // s to the left: end a = (-0.6, 0.1), the neighbour continues the surface to the right (end 1)
    cases.push_back(make("vertex a, neighbour", q ? e3 : e2, {-0.6, 0.1, -1.8, 0.3, -1.2, 0.27},
                         {0.3, -0.2, -0.6, 0.1, -0.15, -0.02}, 1, 1));
  } else {
    cases.push_back(make("interior", q ? e3 : e2, {1.6, 0.1, -0.4, -0.05}, {}, -1, 0));
    cases.push_back(make("vertex b, neighbour", q ? e3 : e2, {3.1, 0.2, 2.0, 0.0}, {2.0, 0.0, 1.2, -0.5}, 0, 2));
    cases.push_back(make("vertex a, neighbour", q ? e3 : e2, {-0.6, 0.1, -1.8, 0.3}, {0.3, -0.2, -0.6, 0.1}, 1, 1));
  }
  for (KernelCase& k : cases)
    if (k.neighbourEnd < 0) {  // no neighbour: its slot holds a copy of s
      constexpr int off = 2 * NE;
      std::copy(k.z + off, k.z + off + 2 * NS, k.z + off + 2 * NS);
    }
  return cases;
}

template <int NE, int NS>
void checkCurvedKernels() {
  const Real dA = 0.37;
  for (const KernelCase& c : curvedCases<NE, NS>(0.0))
    for (Real delta : {0.0, 0.3}) {
      checkCurvedKernel<Formulation::PlaneStrain, NE, NS>(c, delta, nullptr);
      checkCurvedKernel<Formulation::PlaneStrain, NE, NS>(c, delta, &dA);
    }
  for (const KernelCase& c : curvedCases<NE, NS>(2.5)) checkCurvedKernel<Formulation::Axisymmetric, NE, NS>(c, 0.3, nullptr);
}

}  // namespace

TEST(CurvedSegments, KernelTangentCurvedOnCurved) { checkCurvedKernels<3, 3>(); }
TEST(CurvedSegments, KernelTangentCurvedOnStraight) { checkCurvedKernels<3, 2>(); }
TEST(CurvedSegments, KernelTangentStraightOnCurved) { checkCurvedKernels<2, 3>(); }

// On two straight segments the curved kernel is the hand-derived linear one
// (f and K to rounding), and its blend distance is r + the linear vertex penalty.
TEST(CurvedSegments, StraightSegmentsGiveTheLinearKernel) {
  const LennardJones lj(1.0, 1.0);
  const auto law = lawOf(lj);
  Real worst = 0.0;
  for (const KernelCase& c : curvedCases<2, 2>(2.5))
    for (int q = 0; q < 4; ++q) {
      const Real xi = gaussLegendreUnit(4).points[q], w = gaussLegendreUnit(4).weights[q];
      for (bool axi : {false, true}) {
        Real f[4], K[4 * 12], rho, fl[4], Kl[4][8];
        PairState a, b;
        if (axi) {
          a = method3CurvedPair<Formulation::Axisymmetric, 2, 2>(c.z, xi, w, law, -1, 0.0, nullptr, f, rho, K, nullptr);
          b = method3Pair<Formulation::Axisymmetric>(c.z, xi, w, law, fl, Kl);
        } else {
          a = method3CurvedPair<Formulation::PlaneStrain, 2, 2>(c.z, xi, w, law, -1, 0.0, nullptr, f, rho, K, nullptr);
          b = method3Pair<Formulation::PlaneStrain>(c.z, xi, w, law, fl, Kl);
        }
        ASSERT_EQ(a.region, b.region) << c.name;
        EXPECT_NEAR(rho, b.distance, 1e-15) << c.name;
        Real kmax = 0.0;
        for (int i = 0; i < 4; ++i)
          for (int j = 0; j < 8; ++j) kmax = std::max(kmax, std::abs(Kl[i][j]));
        for (int i = 0; i < 4; ++i) {
          EXPECT_NEAR(f[i], fl[i], 1e-14 * kmax) << c.name;
          for (int j = 0; j < 8; ++j) worst = std::max(worst, std::abs(K[i * 12 + j] - Kl[i][j]) / kmax);
          for (int j = 8; j < 12; ++j) EXPECT_EQ(K[i * 12 + j], 0.0) << c.name;  // no neighbour: no column
        }
      }
    }
  std::printf("[curved] straight segments: max|K_curved - K_linear|/max|K| = %.2e\n", worst);
  EXPECT_LT(worst, 1e-12);  // AD against the hand-derived tangent: rounding only
}

namespace {

SurfaceInteractionOptions curvedOptions(Formulation form, Real delta = -1.0, Real cutoff = 0.0) {
  SurfaceInteractionOptions opt;
  opt.formulation = form;
  opt.projectionSmoothing = delta;
  opt.cutoff = cutoff;
  return opt;
}

}  // namespace

// A wavy lower surface as Line2 segments and as straight Line3 segments (the
// mid node at the middle of each chord), under a curved upper surface: the
// same pairs, resultants and closest distance, for either body's points.
TEST(CurvedSegments, StraightLine3SurfaceActsAsTheLine2One) {
  auto wave = [](Real s, Real& x, Real& y) {
    x = 2.0 - 4.0 * s;  // right to left: body below
    y = 0.05 * std::sin(3.0 * x);
  };
  auto arch = [](Real s, Real& x, Real& y) {
    x = -1.0 + 2.0 * s;
    y = 0.35 + 0.3 * x * x;
  };
  for (Formulation form : {Formulation::PlaneStrain, Formulation::Axisymmetric}) {
    const Real shift = form == Formulation::Axisymmetric ? 3.0 : 0.0;
    auto shifted = [&](auto curve) {
      return [=](Real s, Real& x, Real& y) {
        curve(s, x, y);
        x += shift;
      };
    };
    std::vector<Real> linear, quadratic;
    std::vector<mesh::Surface> sl, sq;
    sl.push_back(addPolyline(linear, samplePolyline(shifted(wave), 40), 0));
    sl.push_back(addCurvedChain(linear, shifted(arch), 12, 1));
    // the same corners; mid nodes at the chords' middles
    std::vector<Real> corners = samplePolyline(shifted(wave), 40);
    mesh::Surface straight{0, 3, {}, {}};
    for (int i = 0; i <= 40; ++i) quadratic.insert(quadratic.end(), {corners[2 * i], corners[2 * i + 1]});
    for (int i = 0; i < 40; ++i) {
      quadratic.insert(quadratic.end(), {0.5 * (corners[2 * i] + corners[2 * i + 2]),
                                         0.5 * (corners[2 * i + 1] + corners[2 * i + 3])});
      straight.facets.insert(straight.facets.end(), {LocalIndex(i), LocalIndex(i + 1), LocalIndex(41 + i)});
    }
    sq.push_back(straight);
    sq.push_back(addCurvedChain(quadratic, shifted(arch), 12, 1));
    auto lj = std::make_shared<LennardJones>(1.0, 0.1);
    SurfaceInteraction a(sl, {1.0, 1.3}, lj, curvedOptions(form));
    SurfaceInteraction b(sq, {1.0, 1.3}, lj, curvedOptions(form));
    a.updatePairs(linear);
    b.updatePairs(quadratic);
    std::vector<PairContribution> ca, cb;
    a.evaluate(linear, ca, false);
    b.evaluate(quadratic, cb, false);
    EXPECT_EQ(a.summary().numPairs, b.summary().numPairs);
    EXPECT_GT(a.summary().numPairs, 150);
    EXPECT_NEAR(a.summary().minDistance, b.summary().minDistance, 1e-14);
    for (int body = 0; body < 2; ++body)
      for (int i = 0; i < 2; ++i) {
        const Real ra = a.summary().resultant[body][i], rb = b.summary().resultant[body][i];
        EXPECT_NEAR(ra, rb, 1e-11 * std::abs(a.summary().resultant[body][1])) << formulationName(form) << body << i;
      }
    std::printf("[curved] straight Line3 = Line2 (%s): %d pairs, resultant y of the lower body %.10e / %.10e\n",
                formulationName(form), int(b.summary().numPairs), a.summary().resultant[0][1],
                b.summary().resultant[0][1]);
  }
}

namespace {

// int_{-h}^{h} g(t) dt: composite 16-point Gauss on 400 panels.
template <class G>
Real integrateSymmetric(const G& g, Real h) {
  const GaussRule rule = gaussLegendreUnit(16);
  const int panels = 400;
  Real sum = 0.0;
  for (int p = 0; p < panels; ++p)
    for (int q = 0; q < rule.size(); ++q) sum += rule.weights[q] * g(-h + 2.0 * h * (p + rule.points[q]) / panels);
  return sum * 2.0 * h / panels;
}

// The Method 3 force on the circle x^2 + (y - c)^2 = R^2 over |theta| <= theta_max from
// its lower arc's points (outward normal n = (sin theta, -cos theta), x = R sin theta,
// y = c - R cos theta) against the flat y = 0: rbar = (0, 1), rbar . n = -cos theta,
// da = R dtheta, and the force applied to the circle -f_y = -T(y) (rbar . n) R dtheta.
template <class Law>
Real circlePointsOnFlat(const Law& law, Real R, Real c, Real thetaMax) {
  return integrateSymmetric(
      [&](Real th) {
        Real T, dT;
        law(c - R * std::cos(th), T, dT);
        return T * std::cos(th) * R;
      },
      thetaMax);
}

// The flat's points (x, 0), |x| <= a, outward normal (0, 1), against the same circle:
// r = |x - C| - R, rbar = (x - C)/|x - C|, rbar_y = rbar . n = -c/|x - C|; -f_y on the flat.
template <class Law>
Real flatPointsOnCircle(const Law& law, Real R, Real c, Real a) {
  return integrateSymmetric(
      [&](Real x) {
        const Real d = std::hypot(x, c);
        Real T, dT;
        law(d - R, T, dT);
        return -T * (c / d) * (c / d);
      },
      a);
}

}  // namespace

// A cylinder (radius 1) over a flat at gap h = 1.5 r0 (r0 = 0.02: the
// attractive side of the Lennard-Jones law), meshed on its lower 120-degree arc with n curved segments
// or with the 2n chords through the same nodes. Each direction separately
// (setEvaluatedFacets): the circle's points on the flat, and the flat's points
// on the circle. The curved surface's force converges to the exact integral
// at high order; the chords' stays off by the chords' sag, which is of the
// order of r0 on these meshes.
TEST(CurvedSegments, CircleOnFlatConvergesToTheExactForce) {
  const Real R = 1.0, r0 = 0.02, h = 1.5 * r0, c = R + h, thetaMax = kPi / 3.0, a = 0.3;
  auto lj = std::make_shared<LennardJones>(1.0, r0);
  const auto law = lawOf(*lj, 1.0);
  const Real exactCircle = circlePointsOnFlat(law, R, c, thetaMax), exactFlat = flatPointsOnCircle(law, R, c, a);
  auto arc = [&](Real s, Real& x, Real& y) {  // left to right along the bottom: body above
    const Real th = -thetaMax + 2.0 * thetaMax * s;
    x = R * std::sin(th);
    y = c - R * std::cos(th);
  };
  Real previousCurved[2] = {kInf, kInf};
  for (int n : {16, 32, 64}) {
    Real error[2][2];  // [curved, chords][circle's points, flat's points]
    for (int curvedMesh = 1; curvedMesh >= 0; --curvedMesh) {
      std::vector<Real> coords;
      std::vector<mesh::Surface> s;
      // the flat: x in [-1, 1] (wider than the arc, for the circle's points), 400 straight segments
      std::vector<Real> flat;
      const int nf = 400;
      for (int i = 0; i <= nf; ++i) flat.insert(flat.end(), {1.0 - 2.0 * i / nf, 0.0});
      s.push_back(addPolyline(coords, flat, 0));
      s.push_back(curvedMesh ? addCurvedChain(coords, arc, n, 1) : addPolyline(coords, samplePolyline(arc, 2 * n), 1));
      SurfaceInteraction si(s, {1.0, 1.0}, lj, curvedOptions(Formulation::PlaneStrain, -1.0, kInf));
      for (int dir = 0; dir < 2; ++dir) {
        std::vector<std::vector<char>> on(2);
        on[0].assign(s[0].numFacets(), 0);
        on[1].assign(s[1].numFacets(), dir == 0 ? 1 : 0);
        if (dir == 1)  // the flat's facets within |x| <= a
          for (LocalIndex e = 0; e < s[0].numFacets(); ++e)
            on[0][e] = std::abs(coords[2 * s[0].facets[2 * e]] + coords[2 * s[0].facets[2 * e + 1]]) <= 2.0 * a;
        si.setEvaluatedFacets(on);
        si.updatePairs(coords);
        std::vector<PairContribution> out;
        si.evaluate(coords, out, false);
        const Real F = si.summary().resultant[dir == 0 ? 1 : 0][1];
        const Real exact = dir == 0 ? exactCircle : exactFlat;
        error[curvedMesh ? 0 : 1][dir] = std::abs(F / exact - 1.0);
      }
    }
    std::printf("[curved] circle on flat, %3d curved segments / %3d chords: relative force error, circle's points "
                "%.2e / %.2e, flat's points %.2e / %.2e\n",
                n, 2 * n, error[0][0], error[1][0], error[0][1], error[1][1]);
    for (int dir = 0; dir < 2; ++dir) {
      // the chords of these meshes sag by R (pi/(6n))^2/2 = 5e-3 .. 3e-4 r0-scale lengths: their
      // force is off by percents; the curved segments' by far less, and falling with n
      EXPECT_LT(error[0][dir], 0.1 * error[1][dir]) << n << " " << dir;
      EXPECT_LT(error[0][dir], previousCurved[dir]) << n << " " << dir;
      previousCurved[dir] = error[0][dir];
    }
  }
  EXPECT_LT(previousCurved[0], 1e-4);
  EXPECT_LT(previousCurved[1], 1e-4);
}

// The assembled tangent of curved surfaces against central differences of
// the assembled residual: a curved arc over a curved valley whose two halves
// meet at a concave corner (the blend active), and over its convex ridge.
TEST(CurvedSegments, AssembledTangentWithTheBlend) {
  for (Formulation form : {Formulation::PlaneStrain, Formulation::Axisymmetric})
    for (Real slope : {0.15, -0.15}) {
      const Real x0 = form == Formulation::Axisymmetric ? 3.0 : 0.0;
      std::vector<Real> coords;
      std::vector<mesh::Surface> s;
      // lower body: right half then left half of a corner at x0, each half a chain of 4 bowed segments
      auto valley = [&](Real t, Real& x, Real& y) {
        x = x0 + 1.0 - 2.0 * t;
        const Real u = x - x0;
        y = slope * std::abs(u) + 0.05 * std::sin(4.0 * u) * std::abs(u);
      };
      s.push_back(addCurvedChain(coords, valley, 8, 0));
      auto upper = [&](Real t, Real& x, Real& y) {
        x = x0 - 0.2 + 0.4 * t + 0.0031;
        y = 0.25 + 0.4 * (x - x0) * (x - x0);
      };
      s.push_back(addCurvedChain(coords, upper, 3, 1));
      auto lj = std::make_shared<LennardJones>(1.0, 0.1);
      const Real delta = 1e-3;
      SurfaceInteraction si(s, {1.0, 1.2}, lj, curvedOptions(form, delta, kInf));
      si.updatePairs(coords);
      const Real worst = tangentError(si, coords, 1e-4 * delta);
      std::printf("[curved] assembled tangent %-13s slope %+.2f: %d pairs, %d blended, max|K - K_fd|/max|K| = %.2e\n",
                  formulationName(form), slope, int(si.summary().numPairs), int(si.summary().numBlended), worst);
      EXPECT_GT(si.summary().numBlended, 0);
      // central differences with step 1e-4 delta: truncation ~ 1e-8 relative
      EXPECT_LT(worst, 1e-6);
    }
}
