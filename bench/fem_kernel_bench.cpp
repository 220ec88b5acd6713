// Micro-benchmark of the solid element kernels: time per call of residual
// (internal force) and residualAndTangent (internal force + consistent
// tangent) on one core, for Hex8, Tet4, Hex20, Hex27, Tet10 (3D) and Quad4,
// Quad8, Quad9 (axisymmetric, plane strain).
//
// Usage: bench_fem_kernel [calls per kernel, default 100000]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "cgcm/fem/SolidKernel.hpp"

namespace {

using cgcm::Real;
using namespace cgcm::fem;

template <class Kernel>
struct Sample {
  Real X[Kernel::numNodes][Kernel::dim];
  Real x[Kernel::numNodes][Kernel::dim];
};

/// A set of distorted elements under random finite deformations, cycled through
/// so that nothing can be hoisted out of the timing loop. Unit cube elements on
/// [0,1]^dim, the unit corner tetrahedron (node 0 at the parent origin); the
/// nodes of quadratic elements moved half as far as those of linear ones.
template <class Kernel>
std::vector<Sample<Kernel>> makeSamples(int count, unsigned seed) {
  using E = typename Kernel::ElementType;
  Real xi0[Kernel::dim];
  E::parentCoordinates(0, xi0);
  const bool simplex = xi0[0] == 0.0;
  const int corners = simplex ? Kernel::dim + 1 : 1 << Kernel::dim;
  const Real scale = Kernel::numNodes > corners ? 0.5 : 1.0;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-0.1, 0.1);
  std::vector<Sample<Kernel>> s(count);
  for (auto& e : s) {
    Real F[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) F[i][j] = (i == j ? 1.0 : 0.0) + u(rng);
    for (int a = 0; a < Kernel::numNodes; ++a) {
      Real xi[Kernel::dim];
      E::parentCoordinates(a, xi);
      for (int i = 0; i < Kernel::dim; ++i) {
        e.X[a][i] = (simplex ? xi[i] : 0.5 * (xi[i] + 1.0)) + scale * u(rng);
        if (Kernel::axisymmetric && i == 0) e.X[a][i] += 1.0;
      }
    }
    for (int a = 0; a < Kernel::numNodes; ++a)
      for (int i = 0; i < Kernel::dim; ++i) {
        Real v = 0.0;
        for (int j = 0; j < Kernel::dim; ++j) v += F[i][j] * e.X[a][j];
        e.x[a][i] = v + 0.2 * scale * u(rng);
      }
  }
  return s;
}

/// Best of 3 runs of `calls` calls of call(sample), in µs per call.
template <class Samples, class Call>
double timePerCall(long calls, const Samples& samples, Call&& call) {
  double best = 1e300;
  for (int rep = 0; rep < 3; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    for (long n = 0; n < calls; ++n) call(n, samples[n & 63]);
    const auto t1 = std::chrono::steady_clock::now();
    best = std::min(best, std::chrono::duration<double, std::micro>(t1 - t0).count() / calls);
  }
  return best;
}

template <class Kernel>
void run(const char* name, long calls, const cgcm::material::NeoHookean& mat) {
  const auto samples = makeSamples<Kernel>(64, 12345u);
  Real f[Kernel::numDofs];
  Real K[Kernel::numDofs][Kernel::numDofs];
  double checksum = 0.0;
  long failures = 0;
  const double residual = timePerCall(calls, samples, [&](long n, const Sample<Kernel>& s) {
    if (!Kernel::residual(s.X, s.x, mat, f)) ++failures;
    checksum += f[n % Kernel::numDofs];
  });
  const double tangent = timePerCall(calls, samples, [&](long n, const Sample<Kernel>& s) {
    if (!Kernel::residualAndTangent(s.X, s.x, mat, f, K)) ++failures;
    checksum += f[n % Kernel::numDofs] + K[n % Kernel::numDofs][(n / 7) % Kernel::numDofs];
  });
  std::printf("%-22s %3d dofs %2d qp  %8.3f  %8.3f  (checksum %.6e, rejected %ld)\n", name, Kernel::numDofs,
              Kernel::numQp, residual, tangent, checksum, failures);
}

}  // namespace

int main(int argc, char** argv) {
  const long calls = argc > 1 ? std::atol(argv[1]) : 100000;
  const auto mat = cgcm::material::NeoHookean::fromYoungPoisson(1.0, 0.3);
  std::printf("us per cell, one core, best of 3 x %ld calls:   residual  residual+tangent\n", calls);
  run<SolidKernel<ThreeD, Hex8>>("ThreeD Hex8", calls, mat);
  run<SolidKernel<ThreeD, Tet4>>("ThreeD Tet4", calls, mat);
  run<SolidKernel<Axisymmetric, Quad4>>("Axisymmetric Quad4", calls, mat);
  run<SolidKernel<PlaneStrain, Quad4>>("PlaneStrain Quad4", calls, mat);
  run<SolidKernel<ThreeD, Hex20>>("ThreeD Hex20", calls, mat);
  run<SolidKernel<ThreeD, Hex27>>("ThreeD Hex27", calls, mat);
  run<SolidKernel<ThreeD, Tet10>>("ThreeD Tet10", calls, mat);
  run<SolidKernel<Axisymmetric, Quad8>>("Axisymmetric Quad8", calls, mat);
  run<SolidKernel<Axisymmetric, Quad9>>("Axisymmetric Quad9", calls, mat);
  run<SolidKernel<PlaneStrain, Quad8>>("PlaneStrain Quad8", calls, mat);
  run<SolidKernel<PlaneStrain, Quad9>>("PlaneStrain Quad9", calls, mat);
  return 0;
}
