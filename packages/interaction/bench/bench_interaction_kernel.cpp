// Cost per interaction pair of the Method 3 kernel (prints; not a test).
//
//   bench_interaction_kernel [segments per body = 4000] [repetitions = 20]
//                            [projection smoothing / r0 = default]
//
// Geometry: axisymmetric sphere (R = 100 r0) at h0 = r_S0 above a flat, LJ
// potential, cutoff 10 r0, 4 Gauss points per segment. Reports the search
// (pair list), the evaluation with and without tangent through the driver,
// the bare kernel, and the same tangent by forward AD (Sacado) for scale;
// then the same bodies as curved segments through the same nodes, and in 3D
// a cube-sphere cap over a flat square as flat QUAD4 or curved QUAD9 facets
// through the same nodes.
#include <Kokkos_Core.hpp>
#include <Sacado.hpp>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "cgcm/interaction/SurfaceInteraction.hpp"

using namespace cgcm;
using namespace cgcm::interaction;

namespace {

using Clock = std::chrono::steady_clock;
double seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

template <class Curve>
mesh::Surface polyline(std::vector<Real>& coords, int n, Curve&& curve, int body) {
  mesh::Surface s;
  s.body = body;
  const LocalIndex first = LocalIndex(coords.size() / 2);
  for (int i = 0; i <= n; ++i) {
    Real x, y;
    curve(Real(i) / n, x, y);
    coords.push_back(x);
    coords.push_back(y);
  }
  for (int i = 0; i < n; ++i) {
    s.facets.push_back(first + i);
    s.facets.push_back(first + i + 1);
  }
  return s;
}

// n curved segments (Line3: end, end, mid) on the curve, 2n + 1 nodes.
template <class Curve>
mesh::Surface curvedChain(std::vector<Real>& coords, int n, Curve&& curve, int body) {
  mesh::Surface s{body, 3, {}, {}};
  const LocalIndex first = LocalIndex(coords.size() / 2);
  for (int i = 0; i <= 2 * n; ++i) {
    Real x, y;
    curve(Real(i) / (2 * n), x, y);
    coords.push_back(x);
    coords.push_back(y);
  }
  for (int i = 0; i < n; ++i) s.facets.insert(s.facets.end(), {first + 2 * i, first + 2 * i + 2, first + 2 * i + 1});
  return s;
}

// 3D: the (2m + 1)^2 grid points of a surface (point(i, j, x) for i, j in 0 .. 2m) as 2m x 2m flat
// QUAD4 or m x m curved QUAD9 facets; `flip` reverses their orientation.
template <class Point>
mesh::Surface grid3D(std::vector<Real>& coords, int m, bool curved, bool flip, Point&& point, int body) {
  const int n = 2 * m + 1;
  const LocalIndex first = LocalIndex(coords.size() / 3);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      Real x[3];
      point(i, j, x);
      coords.insert(coords.end(), x, x + 3);
    }
  auto id = [&](int i, int j) { return first + LocalIndex(flip ? i * n + j : j * n + i); };
  mesh::Surface s{body, curved ? 9 : 4, {}, {}};
  const int step = curved ? 2 : 1;
  for (int j = 0; j + step < n; j += step)
    for (int i = 0; i + step < n; i += step) {
      if (!curved) {
        s.facets.insert(s.facets.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
        continue;
      }
      s.facets.insert(s.facets.end(), {id(i, j), id(i + 2, j), id(i + 2, j + 2), id(i, j + 2), id(i + 1, j),
                                       id(i + 2, j + 1), id(i + 1, j + 2), id(i, j + 1), id(i + 1, j + 1)});
    }
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  Kokkos::ScopeGuard kokkos(argc, argv);  // the Method 3 driver runs its pairs through Kokkos
  const int n = argc > 1 ? std::atoi(argv[1]) : 4000;
  const int reps = argc > 2 ? std::atoi(argv[2]) : 20;
  const double smoothing = argc > 3 ? std::atof(argv[3]) : -1.0;  // < 0: the default
  const Real pi = kPi;
  const Real R = 100.0, r0 = 1.0;
  auto lj = std::make_shared<LennardJones>(1.0, r0);
  const Real h0 = *lj->surfaceEquilibriumDistance();
  const Real rhoMax = std::sqrt(2.0 * R * 15.0);

  const Real alpha = std::asin(rhoMax / R);
  auto flat = [&](Real t, Real& x, Real& y) {
    x = 1.1 * rhoMax * (1 - t);
    y = 0.0;
  };
  auto sphere = [&](Real t, Real& x, Real& y) {
    const Real th = -pi / 2 + alpha * t;
    x = R * std::cos(th);
    y = R + h0 + R * std::sin(th);
  };
  std::vector<Real> coords;
  std::vector<mesh::Surface> surfaces;
  surfaces.push_back(polyline(coords, n, flat, 0));
  surfaces.push_back(polyline(coords, n, sphere, 1));
  SurfaceInteractionOptions opt;
  opt.formulation = Formulation::Axisymmetric;
  opt.projectionSmoothing = smoothing < 0.0 ? smoothing : smoothing * r0;
  SurfaceInteraction si(surfaces, {1.0, 1.0}, lj, opt);

  std::vector<PairContribution> out;
  si.updatePairs(coords);
  si.evaluate(coords, out);  // warm-up
  const auto t0 = Clock::now();
  for (int r = 0; r < reps; ++r) si.setEvaluatedFacets({}), si.updatePairs(coords);  // forces a new search
  const auto t1 = Clock::now();
  for (int r = 0; r < reps; ++r) si.evaluate(coords, out, true);
  const auto t2 = Clock::now();
  for (int r = 0; r < reps; ++r) si.evaluate(coords, out, false);
  const auto t3 = Clock::now();
  // scatter form: f and K consumed at once (here summed), no stored array
  std::vector<Real> fglob(coords.size(), 0.0);
  Real ksum = 0.0;
  for (int r = 0; r < reps; ++r)
    si.evaluate(coords.data(), [&](const auto& c) {
      for (int a = 0; a < 2; ++a)
        for (int i = 0; i < 2; ++i) fglob[2 * c.rowNodes[a] + i] += c.f[2 * a + i];
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 8; ++j) ksum += c.K[i][j];
    });
  const auto t3b = Clock::now();
  const double np = double(si.summary().numPairs);

  // bare kernel on the stored pairs' coordinates (closest target)
  std::vector<Real> z(8 * si.pairs().size());
  for (std::size_t i = 0; i < si.pairs().size(); ++i)
    for (int a = 0; a < 4; ++a)
      for (int k = 0; k < 2; ++k) z[8 * i + 2 * a + k] = coords[2 * out[i].colNodes[a] + k];
  const auto law = si.law(std::get<InversePowerPair>(si.kernelPotential()), 0, 1);
  const GaussRule& rule = si.quadrature();
  Real sink = 0.0;
  const auto t4 = Clock::now();
  for (int r = 0; r < reps; ++r)
    for (std::size_t i = 0; i < si.pairs().size(); ++i) {
      Real f[4], K[4][8];
      const int q = si.pairs()[i].qp;
      method3Pair<Formulation::Axisymmetric>(&z[8 * i], rule.points[q], rule.weights[q], law, f, K);
      for (int a = 0; a < 4; ++a) {
        sink += f[a];
        for (int j = 0; j < 8; ++j) sink += K[a][j];
      }
    }
  const auto t5 = Clock::now();
  using Fad = Sacado::Fad::SFad<Real, 8>;
  const Real C = pi * lj->epsilon() * r0 * r0 * r0;
  auto traction = [&](const Fad& r) {
    const Fad s = r0 / r;
    const Fad s3 = s * s * s;
    return Fad(C * (s3 * s3 * s3 / 45.0 - s3 / 3.0));
  };
  for (int r = 0; r < reps; ++r)
    for (std::size_t i = 0; i < si.pairs().size(); ++i) {
      Fad zf[8], ff[4];
      for (int j = 0; j < 8; ++j) zf[j] = Fad(8, j, z[8 * i + j]);
      const int q = si.pairs()[i].qp;
      method3PairResidualGeneric<Formulation::Axisymmetric>(zf, rule.points[q], rule.weights[q], traction,
                                                            ff);
      for (int a = 0; a < 4; ++a) {
        sink += ff[a].val();
        for (int j = 0; j < 8; ++j) sink += ff[a].dx(j);
      }
    }
  const auto t6 = Clock::now();

  // the 2D search on the sphere's surface, queried from the flat's points
  std::vector<Real> qpts;
  for (LocalIndex e = 0; e < surfaces[0].numFacets(); ++e)
    for (int q = 0; q < rule.size(); ++q) {
      const Real xi = rule.points[q];
      const LocalIndex a = surfaces[0].facets[2 * e], b = surfaces[0].facets[2 * e + 1];
      qpts.push_back((1 - xi) * coords[2 * a] + xi * coords[2 * b]);
      qpts.push_back((1 - xi) * coords[2 * a + 1] + xi * coords[2 * b + 1]);
    }
  AabbTreeSearch2D tree;
  const auto a = Clock::now();
  for (int r = 0; r < reps; ++r) tree.build(coords, surfaces[1]);
  const auto b = Clock::now();
  for (int r = 0; r < reps; ++r)
    for (std::size_t i = 0; i < qpts.size() / 2; ++i)
      sink += tree.project(&qpts[2 * i], si.cutoff()).found() ? 1.0 : 0.0;
  const auto c = Clock::now();
  const double buildCost = 1e3 * seconds(a, b) / reps;
  const double searchCost = 1e9 * seconds(b, c) / reps / (qpts.size() / 2);

  // the same bodies as n/2 curved segments each (the same nodes): search and driver per pair
  std::vector<Real> curvedCoords;
  std::vector<mesh::Surface> curved;
  curved.push_back(curvedChain(curvedCoords, n / 2, flat, 0));
  curved.push_back(curvedChain(curvedCoords, n / 2, sphere, 1));
  SurfaceInteraction ci(curved, {1.0, 1.0}, lj, opt);
  std::vector<PairContribution> curvedOut;
  ci.updatePairs(curvedCoords);
  ci.evaluate(curvedCoords, curvedOut);  // warm-up
  const auto u0 = Clock::now();
  for (int r = 0; r < reps; ++r) ci.setEvaluatedFacets({}), ci.updatePairs(curvedCoords);  // forces a new search
  const auto u1 = Clock::now();
  for (int r = 0; r < reps; ++r) ci.evaluate(curvedCoords, curvedOut, true);
  const auto u2 = Clock::now();
  for (int r = 0; r < reps; ++r) ci.evaluate(curvedCoords, curvedOut, false);
  const auto u3 = Clock::now();
  const InteractionSummary& cs = ci.summary();

  const InteractionSummary& s = si.summary();
  std::printf(
      "bench_interaction_kernel: axisymmetric sphere R = %.0f r0 at h0 = r_S0 above a flat, %d segments per "
      "body\n",
      R, n);
  std::printf(
      "  quadrature points searched %d, pairs %d, beyond cutoff %d (cutoff %.1f r0, |T(r_c)| = %.2e)\n",
      int(s.numQuadraturePoints), int(s.numPairs), int(s.numBeyondCutoff), s.cutoff / r0, s.cutoffTraction);
  std::printf("  projection smoothing %.1e r0: %d pairs blended (%d truncated to %d segments)\n",
              si.projectionSmoothing() / r0, int(s.numBlended), int(s.numTruncatedBlends), kMaxBlendTargets);
  std::printf("  search (pair list)            %8.1f ns per quadrature point (%.2f ms per update)\n",
              1e9 * seconds(t0, t1) / reps / s.numQuadraturePoints, 1e3 * seconds(t0, t1) / reps);
  std::printf("  flat points onto the sphere: CGAL AABB tree %.1f ns per query (build %.3f ms)\n", searchCost,
              buildCost);
  std::printf("  driver f + K                  %8.1f ns per pair (%.2f ms per evaluation)\n",
              1e9 * seconds(t1, t2) / reps / np, 1e3 * seconds(t1, t2) / reps);
  std::printf("  driver f + K, scatter callback%8.1f ns per pair\n", 1e9 * seconds(t3, t3b) / reps / np);
  std::printf("  driver f only                 %8.1f ns per pair\n", 1e9 * seconds(t2, t3) / reps / np);
  std::printf("  bare kernel f + K (hand)      %8.1f ns per pair\n", 1e9 * seconds(t4, t5) / reps / np);
  std::printf("  bare kernel f + K (Sacado AD) %8.1f ns per pair\n", 1e9 * seconds(t5, t6) / reps / np);
  std::printf("  resultants: sphere %.4f, flat %.4f (-2 pi w R = %.4f)\n", s.resultant[1][1], s.resultant[0][1],
              -2 * pi * lj->workOfAdhesion(1, 1) * R);
  std::printf("curved segments (Line3, %d per body, the same nodes): %d pairs, %d blended\n", n / 2, int(cs.numPairs),
              int(cs.numBlended));
  std::printf("  search (pair list)            %8.1f ns per quadrature point (%.2f ms per update)\n",
              1e9 * seconds(u0, u1) / reps / cs.numQuadraturePoints, 1e3 * seconds(u0, u1) / reps);
  std::printf("  driver f + K (Sacado AD)      %8.1f ns per pair (%.2f ms per evaluation)\n",
              1e9 * seconds(u1, u2) / reps / cs.numPairs, 1e3 * seconds(u1, u2) / reps);
  std::printf("  driver f only                 %8.1f ns per pair\n", 1e9 * seconds(u2, u3) / reps / cs.numPairs);
  std::printf("  resultants: sphere %.4f, flat %.4f\n", cs.resultant[1][1], cs.resultant[0][1]);

  // 3D: the sphere's lower cube face (m x m patches, nodes on the sphere) over a flat square, as flat
  // QUAD4 facets or as curved QUAD9 facets through the same nodes
  const int m = 24;
  for (bool curvedFacets : {false, true}) {
    std::vector<Real> c3;
    std::vector<mesh::Surface> s3;
    const Real L = 1.1 * rhoMax;
    s3.push_back(grid3D(c3, m, curvedFacets, false, [&](int i, int j, Real* x) {
      x[0] = -L + 2.0 * L * i / (2 * m), x[1] = -L + 2.0 * L * j / (2 * m), x[2] = 0.0;
    }, 0));
    s3.push_back(grid3D(c3, m, curvedFacets, true, [&](int i, int j, Real* x) {
      const Real a = std::tan(0.25 * pi * (-1.0 + Real(i) / m)), b = std::tan(0.25 * pi * (-1.0 + Real(j) / m));
      const Real len = std::sqrt(a * a + b * b + 1.0);
      x[0] = R * a / len, x[1] = R * b / len, x[2] = R + h0 - R / len;
    }, 1));
    SurfaceInteractionOptions o3;
    o3.formulation = Formulation::ThreeD;
    SurfaceInteraction s3i(s3, {1.0, 1.0}, lj, o3);
    s3i.updatePairs(c3);
    Real sum3 = 0.0;
    auto consume = [&](const auto& c) { sum3 += c.f[0] + c.K[0][0]; };
    s3i.evaluate(c3.data(), consume);  // warm-up
    const auto v0 = Clock::now();
    for (int r = 0; r < reps; ++r) s3i.setEvaluatedFacets({}), s3i.updatePairs(c3);
    const auto v1 = Clock::now();
    for (int r = 0; r < reps; ++r) s3i.evaluate(c3.data(), consume, true);
    const auto v2 = Clock::now();
    for (int r = 0; r < reps; ++r) s3i.evaluate(c3.data(), consume, false);
    const auto v3 = Clock::now();
    const InteractionSummary& s3s = s3i.summary();
    std::printf("3D sphere cap over a flat, %s facets through %d x %d nodes each: %d pairs, %d blended\n",
                curvedFacets ? "curved QUAD9" : "flat QUAD4", 2 * m + 1, 2 * m + 1, int(s3s.numPairs),
                int(s3s.numBlended));
    std::printf("  search (pair list)            %8.1f ns per quadrature point (%.2f ms per update)\n",
                1e9 * seconds(v0, v1) / reps / s3s.numQuadraturePoints, 1e3 * seconds(v0, v1) / reps);
    std::printf("  driver f + K (Sacado AD)      %8.1f ns per pair (%.2f ms per evaluation)\n",
                1e9 * seconds(v1, v2) / reps / s3s.numPairs, 1e3 * seconds(v1, v2) / reps);
    std::printf("  driver f only                 %8.1f ns per pair (%.2f ms per evaluation)\n",
                1e9 * seconds(v2, v3) / reps / s3s.numPairs, 1e3 * seconds(v2, v3) / reps);
    std::printf("  resultants: sphere %.4f, flat %.4f (-2 pi w R = %.4f)\n", s3s.resultant[1][2], s3s.resultant[0][2],
                -2 * pi * lj->workOfAdhesion(1, 1) * R);
    sink += sum3;
  }
  volatile Real keep = sink + ksum;  // keeps the timed loops from being optimised away
  (void)keep;
  return 0;
}
