// Micro-benchmark of the solid element kernels: time per call of
// residualAndTangent (internal force + consistent tangent) on one core, for
// Hex8 and Tet4 (3D) and Quad4 (axisymmetric, plane strain).
//
// Usage: bench_fem_kernel [calls per kernel, default 100000]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <type_traits>
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
/// so that nothing can be hoisted out of the timing loop.
template <class Kernel>
std::vector<Sample<Kernel>> makeSamples(int count, unsigned seed) {
  using E = typename Kernel::ElementType;
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
        e.X[a][i] = (std::is_same_v<E, Tet4> ? xi[i] : 0.5 * (xi[i] + 1.0)) + u(rng);
        if (Kernel::axisymmetric && i == 0) e.X[a][i] += 1.0;
      }
    }
    for (int a = 0; a < Kernel::numNodes; ++a)
      for (int i = 0; i < Kernel::dim; ++i) {
        Real v = 0.0;
        for (int j = 0; j < Kernel::dim; ++j) v += F[i][j] * e.X[a][j];
        e.x[a][i] = v + 0.2 * u(rng);
      }
  }
  return s;
}

template <class Kernel>
void run(const char* name, long calls, const cgcm::material::NeoHookean& mat) {
  const auto samples = makeSamples<Kernel>(64, 12345u);
  Real f[Kernel::numDofs];
  Real K[Kernel::numDofs][Kernel::numDofs];
  double best = 1e300;
  double checksum = 0.0;
  long failures = 0;
  for (int rep = 0; rep < 3; ++rep) {
    const auto t0 = std::chrono::steady_clock::now();
    for (long n = 0; n < calls; ++n) {
      const auto& s = samples[n & 63];
      if (!Kernel::residualAndTangent(s.X, s.x, mat, f, K)) ++failures;
      checksum += f[n % Kernel::numDofs] + K[n % Kernel::numDofs][(n / 7) % Kernel::numDofs];
    }
    const auto t1 = std::chrono::steady_clock::now();
    best = std::min(best, std::chrono::duration<double, std::micro>(t1 - t0).count() / calls);
  }
  std::printf("%-26s %3d dofs  %8.3f us/cell  (best of 3 x %ld calls; checksum %.6e, rejected %ld)\n", name,
              Kernel::numDofs, best, calls, checksum, failures);
}

}  // namespace

int main(int argc, char** argv) {
  const long calls = argc > 1 ? std::atol(argv[1]) : 100000;
  const auto mat = cgcm::material::NeoHookean::fromYoungPoisson(1.0, 0.3);
  std::printf("residualAndTangent, one core\n");
  run<SolidKernel<ThreeD, Hex8>>("ThreeD Hex8", calls, mat);
  run<SolidKernel<ThreeD, Tet4>>("ThreeD Tet4", calls, mat);
  run<SolidKernel<Axisymmetric, Quad4>>("Axisymmetric Quad4", calls, mat);
  run<SolidKernel<PlaneStrain, Quad4>>("PlaneStrain Quad4", calls, mat);
  return 0;
}
