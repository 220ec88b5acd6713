// Unit tests of the updated-Lagrangian solid kernels, for every
// (formulation × element) pair: force = derivative of energy, tangent =
// derivative of force (central differences), rigid-motion invariance, patch
// test, rejection of inverted elements, and the homogeneous uniaxial state
// against the closed-form Neo-Hookean stress.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "cgcm/fem/Dispatch.hpp"

using cgcm::Mat3;
using cgcm::Real;
using cgcm::fem::Axisymmetric;
using cgcm::fem::Hex8;
using cgcm::fem::PlaneStrain;
using cgcm::fem::Quad4;
using cgcm::fem::SolidKernel;
using cgcm::fem::Tet4;
using cgcm::fem::ThreeD;
using cgcm::material::NeoHookean;
using cgcm::material::VolumetricLaw;

namespace {

const VolumetricLaw kLaws[] = {VolumetricLaw::LogSquared, VolumetricLaw::QuadraticJ};

template <class Kernel>
constexpr bool isAxisymmetric() {
  return Kernel::axisymmetric;
}

// ---------------------------------------------------------------------------
// Geometry helpers

/// Reference element of unit size: Quad4/Hex8 on [0,1]^dim, Tet4 the unit corner
/// tetrahedron; axisymmetric elements shifted to R ∈ [1, 2].
template <class Kernel>
void unitElement(Real (&X)[Kernel::numNodes][Kernel::dim]) {
  using E = typename Kernel::ElementType;
  for (int a = 0; a < Kernel::numNodes; ++a) {
    Real xi[Kernel::dim];
    E::parentCoordinates(a, xi);
    for (int i = 0; i < Kernel::dim; ++i) {
      X[a][i] = std::is_same_v<E, Tet4> ? xi[i] : 0.5 * (xi[i] + 1.0);
    }
    if (isAxisymmetric<Kernel>()) X[a][0] += 1.0;
  }
}

/// A randomly distorted reference element (each node moved by up to `distortion`).
template <class Kernel>
void randomElement(std::mt19937& rng, Real distortion, Real (&X)[Kernel::numNodes][Kernel::dim]) {
  std::uniform_real_distribution<Real> u(-distortion, distortion);
  unitElement<Kernel>(X);
  for (int a = 0; a < Kernel::numNodes; ++a)
    for (int i = 0; i < Kernel::dim; ++i) X[a][i] += u(rng);
}

/// Random deformation gradient I + perturbation (amplitude), det > 0.5.
Mat3 randomF(std::mt19937& rng, Real amplitude, int dim) {
  std::uniform_real_distribution<Real> u(-amplitude, amplitude);
  for (;;) {
    Mat3 F = Mat3::identity();
    for (int i = 0; i < dim; ++i)
      for (int j = 0; j < dim; ++j) F.a[i][j] += u(rng);
    if (cgcm::det(F) > 0.5) return F;
  }
}

/// x = F X + c (+ random nodal noise); in axisymmetry F is restricted to
/// r = F00 R + F01 Z with the origin kept on the axis (c0 = 0).
template <class Kernel>
void deform(const Mat3& F, const Real (&c)[3], const Real (&X)[Kernel::numNodes][Kernel::dim],
            Real (&x)[Kernel::numNodes][Kernel::dim]) {
  for (int a = 0; a < Kernel::numNodes; ++a)
    for (int i = 0; i < Kernel::dim; ++i) {
      Real s = c[i];
      for (int j = 0; j < Kernel::dim; ++j) s += F.a[i][j] * X[a][j];
      x[a][i] = s;
    }
}

template <class Kernel>
void randomCurrent(std::mt19937& rng, const Real (&X)[Kernel::numNodes][Kernel::dim],
                   Real (&x)[Kernel::numNodes][Kernel::dim]) {
  const Mat3 F = randomF(rng, 0.3, Kernel::dim);
  std::uniform_real_distribution<Real> u(-0.1, 0.1);
  Real c[3] = {u(rng), u(rng), u(rng)};
  if (isAxisymmetric<Kernel>()) c[0] = 0.0;
  deform<Kernel>(F, c, X, x);
  for (int a = 0; a < Kernel::numNodes; ++a)
    for (int i = 0; i < Kernel::dim; ++i) x[a][i] += u(rng);
}

template <class Kernel>
Real maxAbsVec(const Real (&v)[Kernel::numDofs]) {
  Real m = 0.0;
  for (int d = 0; d < Kernel::numDofs; ++d) m = std::max(m, std::abs(v[d]));
  return m;
}

// ---------------------------------------------------------------------------
// Small structured patches: (n × n [× n]) cells of size h; Tet4 splits every
// cube into 6 tetrahedra (Kuhn triangulation, conforming).

struct Patch {
  int dim = 0;
  std::vector<std::array<Real, 3>> X;   // reference coordinates
  std::vector<std::vector<int>> cells;  // connectivity
  std::vector<int> interior;            // interior node ids
};

template <class Kernel>
Patch makePatch(int n, Real h, Real rOffset) {
  using E = typename Kernel::ElementType;
  constexpr int dim = Kernel::dim;
  Patch p;
  p.dim = dim;
  const int m = n + 1;
  const int nz = dim == 3 ? m : 1;
  auto id = [&](int i, int j, int k) { return i + m * j + m * m * k; };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        p.X.push_back({i * h + rOffset, j * h, k * h});
        const bool inner = i > 0 && i < n && j > 0 && j < n && (dim == 2 || (k > 0 && k < n));
        if (inner) p.interior.push_back(id(i, j, k));
      }
  const int cz = dim == 3 ? n : 1;
  for (int k = 0; k < cz; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        if constexpr (std::is_same_v<E, Quad4>) {
          p.cells.push_back({id(i, j, 0), id(i + 1, j, 0), id(i + 1, j + 1, 0), id(i, j + 1, 0)});
        } else if constexpr (std::is_same_v<E, Hex8>) {
          p.cells.push_back({id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k), id(i, j + 1, k),
                             id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)});
        } else {
          const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
          for (const auto& perm : perms) {
            int c[3] = {0, 0, 0};
            std::vector<int> tet{id(i, j, k)};
            for (int s = 0; s < 3; ++s) {
              c[perm[s]] = 1;
              tet.push_back(id(i + c[0], j + c[1], k + c[2]));
            }
            p.cells.push_back(tet);
          }
        }
      }
  return p;
}

/// Makes every tetrahedron of the patch positively oriented in the reference configuration.
void orientTets(Patch& p) {
  for (auto& t : p.cells) {
    if (t.size() != 4) continue;
    Real e[3][3];
    for (int s = 0; s < 3; ++s)
      for (int i = 0; i < 3; ++i) e[s][i] = p.X[t[s + 1]][i] - p.X[t[0]][i];
    const Real vol = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                     e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                     e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
    if (vol < 0.0) std::swap(t[1], t[2]);
  }
}

/// Assembled internal force of the patch at current coordinates x.
template <class Kernel>
bool assemble(const Patch& p, const std::vector<std::array<Real, 3>>& x, const NeoHookean& mat,
              std::vector<Real>& F) {
  constexpr int dim = Kernel::dim;
  F.assign(p.X.size() * dim, 0.0);
  for (const auto& cell : p.cells) {
    Real Xe[Kernel::numNodes][dim], xe[Kernel::numNodes][dim], fe[Kernel::numDofs];
    for (int a = 0; a < Kernel::numNodes; ++a)
      for (int i = 0; i < dim; ++i) {
        Xe[a][i] = p.X[cell[a]][i];
        xe[a][i] = x[cell[a]][i];
      }
    if (!Kernel::residual(Xe, xe, mat, fe)) return false;
    for (int a = 0; a < Kernel::numNodes; ++a)
      for (int i = 0; i < dim; ++i) F[cell[a] * dim + i] += fe[a * dim + i];
  }
  return true;
}

// ---------------------------------------------------------------------------

template <class Kernel>
class SolidKernelTest : public ::testing::Test {};

// Every kernel fem::withSolidKernel dispatches to (the test below checks that none is missing).
using KernelTuple = std::tuple<SolidKernel<PlaneStrain, Quad4>, SolidKernel<Axisymmetric, Quad4>,
                               SolidKernel<ThreeD, Hex8>, SolidKernel<ThreeD, Tet4>>;
template <class Tuple>
struct TestTypesOf;
template <class... K>
struct TestTypesOf<std::tuple<K...>> {
  using type = ::testing::Types<K...>;
  template <class Kernel>
  static constexpr bool holds = (std::is_same_v<Kernel, K> || ...);
};
using Kernels = TestTypesOf<KernelTuple>::type;

struct KernelNames {
  template <class T>
  static std::string GetName(int) {
    return std::string(T::FormulationType::name) +
           (std::is_same_v<typename T::ElementType, Quad4>   ? "Quad4"
            : std::is_same_v<typename T::ElementType, Hex8> ? "Hex8"
                                                             : "Tet4");
  }
};
TYPED_TEST_SUITE(SolidKernelTest, Kernels, KernelNames);

TEST(SolidKernelCoverage, EveryKernelTheDispatchReachesIsTestedHere) {
  for (const cgcm::CellTypeInfo& row : cgcm::kCellTypes)
    for (cgcm::Formulation f : {cgcm::Formulation::PlaneStrain, cgcm::Formulation::Axisymmetric, cgcm::Formulation::ThreeD})
      cgcm::fem::withSolidKernel(f, row.type, [&](auto kernel) {
        EXPECT_TRUE(TestTypesOf<KernelTuple>::holds<decltype(kernel)>)
            << cgcm::formulationName(f) << " x " << row.name << ": add its kernel to KernelTuple";
      });
}

}  // namespace

// (1) f = ∂W/∂x by central differences.
TYPED_TEST(SolidKernelTest, ResidualIsDerivativeOfEnergy) {
  using K = TypeParam;
  const Real h = 1e-6;
  const Real tol = 1e-7;  // relative to max |f|
  std::mt19937 rng(101);
  Real worst = 0.0;
  for (VolumetricLaw law : kLaws) {
    const NeoHookean mat = NeoHookean::fromYoungPoisson(1.0, 0.3, law);
    for (int trial = 0; trial < 4; ++trial) {
      Real X[K::numNodes][K::dim], x[K::numNodes][K::dim], f[K::numDofs], fd[K::numDofs];
      randomElement<K>(rng, 0.15, X);
      randomCurrent<K>(rng, X, x);
      ASSERT_TRUE(K::residual(X, x, mat, f));
      for (int a = 0; a < K::numNodes; ++a)
        for (int i = 0; i < K::dim; ++i) {
          Real xp[K::numNodes][K::dim], xm[K::numNodes][K::dim];
          std::copy(&x[0][0], &x[0][0] + K::numDofs, &xp[0][0]);
          std::copy(&x[0][0], &x[0][0] + K::numDofs, &xm[0][0]);
          xp[a][i] += h;
          xm[a][i] -= h;
          Real Wp, Wm;
          ASSERT_TRUE(K::energy(X, xp, mat, Wp));
          ASSERT_TRUE(K::energy(X, xm, mat, Wm));
          fd[a * K::dim + i] = (Wp - Wm) / (2.0 * h);
        }
      Real err = 0.0;
      for (int d = 0; d < K::numDofs; ++d) err = std::max(err, std::abs(fd[d] - f[d]));
      err /= maxAbsVec<K>(f);
      worst = std::max(worst, err);
      EXPECT_LE(err, tol) << cgcm::material::toString(law) << " trial " << trial;
    }
  }
  std::printf("[ fd-energy ] %s: max relative |f - dW/dx| = %.3e\n",
              ::testing::UnitTest::GetInstance()->current_test_info()->test_suite_name(), worst);
}

// (2) K = ∂f/∂x by central differences; K symmetric; residualAndTangent's f = residual's f.
TYPED_TEST(SolidKernelTest, TangentIsDerivativeOfResidual) {
  using K = TypeParam;
  const Real h = 1e-6;
  const Real tol = 1e-6;  // relative to max |K|
  std::mt19937 rng(202);
  Real worst = 0.0;
  for (VolumetricLaw law : kLaws) {
    for (Real nu : {0.2, 0.45}) {
      const NeoHookean mat = NeoHookean::fromYoungPoisson(1.0, nu, law);
      for (int trial = 0; trial < 4; ++trial) {
        Real X[K::numNodes][K::dim], x[K::numNodes][K::dim];
        Real f[K::numDofs], f2[K::numDofs], Kt[K::numDofs][K::numDofs], Kfd[K::numDofs][K::numDofs];
        randomElement<K>(rng, 0.15, X);
        randomCurrent<K>(rng, X, x);
        ASSERT_TRUE(K::residualAndTangent(X, x, mat, f, Kt));
        ASSERT_TRUE(K::residual(X, x, mat, f2));
        for (int d = 0; d < K::numDofs; ++d) EXPECT_NEAR(f[d], f2[d], 1e-14 * maxAbsVec<K>(f2));
        for (int a = 0; a < K::numNodes; ++a)
          for (int i = 0; i < K::dim; ++i) {
            Real xp[K::numNodes][K::dim], xm[K::numNodes][K::dim], fp[K::numDofs], fm[K::numDofs];
            std::copy(&x[0][0], &x[0][0] + K::numDofs, &xp[0][0]);
            std::copy(&x[0][0], &x[0][0] + K::numDofs, &xm[0][0]);
            xp[a][i] += h;
            xm[a][i] -= h;
            ASSERT_TRUE(K::residual(X, xp, mat, fp));
            ASSERT_TRUE(K::residual(X, xm, mat, fm));
            for (int d = 0; d < K::numDofs; ++d) Kfd[d][a * K::dim + i] = (fp[d] - fm[d]) / (2.0 * h);
          }
        Real kmax = 0.0, err = 0.0, asym = 0.0;
        for (int d = 0; d < K::numDofs; ++d)
          for (int e = 0; e < K::numDofs; ++e) {
            kmax = std::max(kmax, std::abs(Kt[d][e]));
            err = std::max(err, std::abs(Kt[d][e] - Kfd[d][e]));
            asym = std::max(asym, std::abs(Kt[d][e] - Kt[e][d]));
          }
        err /= kmax;
        worst = std::max(worst, err);
        EXPECT_LE(err, tol) << cgcm::material::toString(law) << " nu " << nu << " trial " << trial;
        EXPECT_LE(asym, 1e-14 * kmax);
      }
    }
  }
  std::printf("[ fd-tangent ] %s: max relative |K - df/dx| = %.3e\n",
              ::testing::UnitTest::GetInstance()->current_test_info()->test_suite_name(), worst);
}

// (3) A rigid motion gives no force and no energy.
TYPED_TEST(SolidKernelTest, RigidMotionGivesZeroResidual) {
  using K = TypeParam;
  const Real tol = 1e-13;  // relative to μ × element size^(dim−1) (forces of order 1)
  std::mt19937 rng(303);
  const NeoHookean mat = NeoHookean::fromYoungPoisson(1.0, 0.3);
  for (int trial = 0; trial < 5; ++trial) {
    Real X[K::numNodes][K::dim], x[K::numNodes][K::dim], f[K::numDofs];
    randomElement<K>(rng, 0.15, X);
    std::uniform_real_distribution<Real> u(-1.0, 1.0);
    Mat3 Q = Mat3::identity();
    Real c[3] = {5.0 * u(rng), 5.0 * u(rng), 5.0 * u(rng)};
    if (isAxisymmetric<K>()) {
      c[0] = 0.0;  // only axial translation is rigid in axisymmetry
    } else if (K::dim == 2) {
      const Real t = 3.0 * u(rng);
      Q.a[0][0] = std::cos(t), Q.a[0][1] = -std::sin(t), Q.a[1][0] = std::sin(t), Q.a[1][1] = std::cos(t);
    } else {
      // Rodrigues rotation about a random axis.
      Real n[3] = {u(rng), u(rng), u(rng)};
      const Real nn = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      for (Real& v : n) v /= nn;
      const Real t = 3.0 * u(rng), ct = std::cos(t), st = std::sin(t);
      const Real Wm[3][3] = {{0, -n[2], n[1]}, {n[2], 0, -n[0]}, {-n[1], n[0], 0}};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) Q.a[i][j] = (i == j ? ct : 0.0) + st * Wm[i][j] + (1 - ct) * n[i] * n[j];
    }
    deform<K>(Q, c, X, x);
    ASSERT_TRUE(K::residual(X, x, mat, f));
    EXPECT_LE(maxAbsVec<K>(f), tol * (isAxisymmetric<K>() ? 10.0 : 1.0)) << "trial " << trial;
    Real W;
    ASSERT_TRUE(K::energy(X, x, mat, W));
    EXPECT_NEAR(W, 0.0, 1e-13);
    Mat3 s;
    Real J;
    ASSERT_TRUE(K::averageStress(X, x, mat, s, J));
    EXPECT_NEAR(J, 1.0, 1e-13);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(s.a[i][j], 0.0, 1e-13);
  }
}

// (4) Patch test: a homogeneous deformation of a distorted patch gives zero
// force at the interior node(s).
TYPED_TEST(SolidKernelTest, PatchTestHomogeneousDeformation) {
  using K = TypeParam;
  constexpr int dim = K::dim;
  const Real tol = 1e-12;  // relative to the largest assembled nodal force
  Patch p = makePatch<K>(2, 1.0, isAxisymmetric<K>() ? 1.0 : 0.0);
  ASSERT_EQ(p.interior.size(), 1u);
  const int c = p.interior[0];
  p.X[c][0] += 0.2;
  p.X[c][1] -= 0.15;
  if (dim == 3) p.X[c][2] += 0.1;
  orientTets(p);

  std::mt19937 rng(404);
  for (VolumetricLaw law : kLaws) {
    const NeoHookean mat = NeoHookean::fromYoungPoisson(1.0, 0.3, law);
    for (int trial = 0; trial < 3; ++trial) {
      Mat3 F = randomF(rng, 0.3, dim);
      Real t[3] = {0.3, -0.2, 0.1};
      if (isAxisymmetric<K>()) {
        // r = a R, z = c Z + d: homogeneous in 3D as well.
        const Real a = F.a[0][0], cz = F.a[1][1];
        F = Mat3::identity();
        F.a[0][0] = a;
        F.a[1][1] = cz;
        t[0] = 0.0;
      }
      std::vector<std::array<Real, 3>> x(p.X.size());
      for (size_t n = 0; n < p.X.size(); ++n) {
        x[n] = {0.0, 0.0, 0.0};
        for (int i = 0; i < dim; ++i) {
          x[n][i] = t[i];
          for (int j = 0; j < dim; ++j) x[n][i] += F.a[i][j] * p.X[n][j];
        }
      }
      std::vector<Real> R;
      ASSERT_TRUE(assemble<K>(p, x, mat, R));
      Real rmax = 0.0;
      for (Real v : R) rmax = std::max(rmax, std::abs(v));
      ASSERT_GT(rmax, 1e-3);
      for (int i = 0; i < dim; ++i)
        EXPECT_LE(std::abs(R[c * dim + i]), tol * rmax) << cgcm::material::toString(law) << " trial " << trial
                                                        << " component " << i;
    }
  }
}

// (4b) Small strain is the linearisation of the finite-strain kernel about
// the reference configuration: its tangent is the finite-strain tangent at
// x = X for every x, its force the finite-strain force to second order in the
// displacement, its force the derivative of its energy, and it passes the
// patch test.
TYPED_TEST(SolidKernelTest, SmallStrainIsTheLinearisation) {
  using K = TypeParam;
  using cgcm::material::Kinematics;
  std::mt19937 rng(505);
  for (VolumetricLaw law : kLaws) {
    const NeoHookean finite = NeoHookean::fromYoungPoisson(1.0, 0.3, law);
    NeoHookean small = finite;
    small.kinematics = Kinematics::SmallStrain;
    for (int trial = 0; trial < 3; ++trial) {
      Real X[K::numNodes][K::dim], x[K::numNodes][K::dim];
      Real f0[K::numDofs], K0[K::numDofs][K::numDofs], fs[K::numDofs], Ks[K::numDofs][K::numDofs];
      randomElement<K>(rng, 0.15, X);
      randomCurrent<K>(rng, X, x);
      ASSERT_TRUE(K::residualAndTangent(X, X, finite, f0, K0));
      ASSERT_TRUE(K::residualAndTangent(X, x, small, fs, Ks));
      Real kmax = 0.0, err = 0.0;
      for (int d = 0; d < K::numDofs; ++d)
        for (int e = 0; e < K::numDofs; ++e) {
          kmax = std::max(kmax, std::abs(K0[d][e]));
          err = std::max(err, std::abs(Ks[d][e] - K0[d][e]));
        }
      EXPECT_LE(err, 1e-13 * kmax) << "tangent at x != X, trial " << trial;

      // f_small(X + t du) - f_finite(X + t du) = O(t^2): halving t quarters it.
      Real du[K::numNodes][K::dim];
      for (int a = 0; a < K::numNodes; ++a)
        for (int i = 0; i < K::dim; ++i) du[a][i] = x[a][i] - X[a][i];
      Real gap[2];
      for (int h = 0; h < 2; ++h) {
        const Real t = h == 0 ? 1e-3 : 5e-4;
        Real xt[K::numNodes][K::dim], ff[K::numDofs], fl[K::numDofs];
        for (int a = 0; a < K::numNodes; ++a)
          for (int i = 0; i < K::dim; ++i) xt[a][i] = X[a][i] + t * du[a][i];
        ASSERT_TRUE(K::residual(X, xt, finite, ff));
        ASSERT_TRUE(K::residual(X, xt, small, fl));
        gap[h] = 0.0;
        for (int d = 0; d < K::numDofs; ++d) gap[h] = std::max(gap[h], std::abs(ff[d] - fl[d]));
        ASSERT_GT(maxAbsVec<K>(fl), 1e2 * gap[h]) << "the two differ at first order, t = " << t;
      }
      EXPECT_NEAR(gap[0] / gap[1], 4.0, 0.05) << "trial " << trial;

      // f = dW/dx by central differences (W quadratic: exact up to rounding).
      Real fd[K::numDofs];
      for (int a = 0; a < K::numNodes; ++a)
        for (int i = 0; i < K::dim; ++i) {
          Real xp[K::numNodes][K::dim], xm[K::numNodes][K::dim], Wp, Wm;
          std::copy(&x[0][0], &x[0][0] + K::numDofs, &xp[0][0]);
          std::copy(&x[0][0], &x[0][0] + K::numDofs, &xm[0][0]);
          xp[a][i] += 1e-4;
          xm[a][i] -= 1e-4;
          ASSERT_TRUE(K::energy(X, xp, small, Wp));
          ASSERT_TRUE(K::energy(X, xm, small, Wm));
          fd[a * K::dim + i] = (Wp - Wm) / 2e-4;
        }
      for (int d = 0; d < K::numDofs; ++d) EXPECT_NEAR(fd[d], fs[d], 1e-9 * maxAbsVec<K>(fs)) << "dof " << d;
    }
  }
  // patch test: a homogeneous displacement gradient leaves the interior node in equilibrium
  Patch p = makePatch<K>(2, 1.0, isAxisymmetric<K>() ? 1.0 : 0.0);
  const int c = p.interior[0];
  p.X[c][0] += 0.2;
  p.X[c][1] -= 0.15;
  if (K::dim == 3) p.X[c][2] += 0.1;
  orientTets(p);
  NeoHookean small = NeoHookean::fromYoungPoisson(1.0, 0.3);
  small.kinematics = Kinematics::SmallStrain;
  Mat3 F = randomF(rng, 0.3, K::dim);
  if (isAxisymmetric<K>()) F.a[0][1] = F.a[1][0] = 0.0;
  std::vector<std::array<Real, 3>> x(p.X.size());
  for (size_t n = 0; n < p.X.size(); ++n) {
    x[n] = {0.0, 0.0, 0.0};
    for (int i = 0; i < K::dim; ++i)
      for (int j = 0; j < K::dim; ++j) x[n][i] += F.a[i][j] * p.X[n][j];
  }
  std::vector<Real> R;
  ASSERT_TRUE(assemble<K>(p, x, small, R));
  Real rmax = 0.0;
  for (Real v : R) rmax = std::max(rmax, std::abs(v));
  for (int i = 0; i < K::dim; ++i) EXPECT_LE(std::abs(R[c * K::dim + i]), 1e-12 * rmax) << "component " << i;
}

// (5) Inverted or degenerate elements are rejected.
TYPED_TEST(SolidKernelTest, InvertedElementReturnsFalse) {
  using K = TypeParam;
  using E = typename K::ElementType;
  const NeoHookean mat = NeoHookean::fromYoungPoisson(1.0, 0.3);
  Real X[K::numNodes][K::dim], x[K::numNodes][K::dim], f[K::numDofs], Kt[K::numDofs][K::numDofs], W, J;
  Mat3 s;
  unitElement<K>(X);
  auto expectRejected = [&](const char* what) {
    EXPECT_FALSE(K::residual(X, x, mat, f)) << what;
    EXPECT_FALSE(K::residualAndTangent(X, x, mat, f, Kt)) << what;
    EXPECT_FALSE(K::energy(X, x, mat, W)) << what;
    EXPECT_FALSE(K::averageStress(X, x, mat, s, J)) << what;
  };

  // Mirror image: det F < 0 everywhere (in axisymmetry mirror z, keeping r > 0).
  const int mirrored = isAxisymmetric<K>() ? 1 : 0;
  std::copy(&X[0][0], &X[0][0] + K::numDofs, &x[0][0]);
  for (int a = 0; a < K::numNodes; ++a) x[a][mirrored] = -x[a][mirrored];
  expectRejected("mirrored");

  // One node pushed through the element: inverted at some quadrature points.
  std::copy(&X[0][0], &X[0][0] + K::numDofs, &x[0][0]);
  if constexpr (std::is_same_v<E, Tet4>) {
    x[3][2] = -0.5;
  } else {
    const int far = std::is_same_v<E, Quad4> ? 2 : 6;  // node opposite node 0
    for (int i = 0; i < K::dim; ++i) x[far][i] = X[0][i] + 0.05;
  }
  expectRejected("node pushed through");

  // The reference element inverted as well.
  std::copy(&X[0][0], &X[0][0] + K::numDofs, &x[0][0]);
  Real Xm[K::numNodes][K::dim];
  std::copy(&X[0][0], &X[0][0] + K::numDofs, &Xm[0][0]);
  for (int a = 0; a < K::numNodes; ++a) Xm[a][mirrored] = -Xm[a][mirrored];
  EXPECT_FALSE(K::residual(Xm, x, mat, f));

  if (isAxisymmetric<K>()) {
    // Element moved across the axis: r < 0 at quadrature points while det ∂x/∂ξ > 0.
    for (int a = 0; a < K::numNodes; ++a) x[a][0] = X[a][0] - 1.9;
    expectRejected("across the axis");
    // Reference and current element both across the axis (J = 1 but R, r < 0).
    for (int a = 0; a < K::numNodes; ++a) Xm[a][0] = X[a][0] - 1.9, Xm[a][1] = X[a][1];
    EXPECT_FALSE(K::residual(Xm, x, mat, f));
    EXPECT_FALSE(K::energy(Xm, x, mat, W));
  }
}

// (6) Uniaxial homogeneous stretch of one cell: boundary reaction = σ × current area.
TYPED_TEST(SolidKernelTest, UniaxialStretchReactionMatchesClosedForm) {
  using K = TypeParam;
  using E = typename K::ElementType;
  constexpr int dim = K::dim;
  const Real tol = 1e-12;  // relative
  const Real L[3] = {1.3, 0.8, 0.6};
  const Real stretch[3] = {1.25, 0.9, 0.95};
  const Real R0 = 0.5;  // inner radius of the axisymmetric ring

  for (VolumetricLaw law : kLaws) {
    const NeoHookean mat = NeoHookean::fromYoungPoisson(2.0, 0.3, law);
    // Closed-form Cauchy stress for F = diag(stretch) (F₃₃ = 1 in plane strain,
    // = the radial stretch in axisymmetry).
    Real lam3[3] = {stretch[0], stretch[1], stretch[2]};
    if (dim == 2) lam3[2] = isAxisymmetric<K>() ? stretch[0] : 1.0;
    const Real Jt = lam3[0] * lam3[1] * lam3[2];
    const Real p = law == VolumetricLaw::LogSquared ? mat.lambda * std::log(Jt) : 0.5 * mat.lambda * (Jt * Jt - 1.0);
    Real sig[3];
    for (int i = 0; i < 3; ++i) sig[i] = (p + mat.mu * (lam3[i] * lam3[i] - 1.0)) / Jt;

    // One cell (Tet4: the box split into 6 tetrahedra) of size L, origin at 0 (R0 in axisymmetry).
    Patch patch = makePatch<K>(1, 1.0, 0.0);
    orientTets(patch);
    for (auto& Xn : patch.X) {
      for (int i = 0; i < dim; ++i) Xn[i] *= L[i];
      if (isAxisymmetric<K>()) Xn[0] += R0;
    }
    std::vector<std::array<Real, 3>> x(patch.X.size());
    for (size_t n = 0; n < x.size(); ++n)
      for (int i = 0; i < 3; ++i) x[n][i] = stretch[i] * patch.X[n][i];
    std::vector<Real> R;
    ASSERT_TRUE(assemble<K>(patch, x, mat, R));

    // Reaction on the face X_i = max (component i), against σ_ii × current area.
    for (int i = 0; i < dim; ++i) {
      if (isAxisymmetric<K>() && i == 0) continue;  // the hoop stress loads the radial faces too
      Real reaction = 0.0;
      Real Xmax = 0.0;
      for (const auto& Xn : patch.X) Xmax = std::max(Xmax, Xn[i]);
      for (size_t n = 0; n < patch.X.size(); ++n)
        if (std::abs(patch.X[n][i] - Xmax) < 1e-12) reaction += R[n * dim + i];
      Real area = 1.0;
      if (isAxisymmetric<K>()) {
        const Real r0 = stretch[0] * R0, r1 = stretch[0] * (R0 + L[0]);
        area = Axisymmetric::ringFactor / 2.0 * (r1 * r1 - r0 * r0);
      } else {
        for (int j = 0; j < dim; ++j)
          if (j != i) area *= stretch[j] * L[j];
      }
      EXPECT_NEAR(reaction, sig[i] * area, tol * std::abs(sig[i] * area))
          << cgcm::material::toString(law) << " direction " << i;
    }

    // The averaged stress of each cell is the closed-form one.
    for (const auto& cell : patch.cells) {
      Real Xe[K::numNodes][dim], xe[K::numNodes][dim];
      for (int a = 0; a < K::numNodes; ++a)
        for (int i = 0; i < dim; ++i) Xe[a][i] = patch.X[cell[a]][i], xe[a][i] = x[cell[a]][i];
      Mat3 s;
      Real J;
      ASSERT_TRUE(K::averageStress(Xe, xe, mat, s, J));
      EXPECT_NEAR(J, Jt, 1e-14);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(s.a[i][j], i == j ? sig[i] : 0.0, 1e-13);
    }

    if constexpr (std::is_same_v<E, Tet4>) {
      // A single tetrahedron with its face 0-2-3 in X = 0: node 1 carries σ_xx × area(0-2-3) / 3.
      Real Xe[4][3], xe[4][3], fe[12];
      unitElement<K>(Xe);
      for (int a = 0; a < 4; ++a)
        for (int i = 0; i < 3; ++i) Xe[a][i] *= L[i], xe[a][i] = stretch[i] * Xe[a][i];
      ASSERT_TRUE(K::residual(Xe, xe, mat, fe));
      const Real area = 0.5 * stretch[1] * L[1] * stretch[2] * L[2];
      EXPECT_NEAR(fe[3], sig[0] * area / 3.0, tol * std::abs(sig[0] * area));
    }
  }
}

// Shape functions: partition of unity and consistent derivatives at random points.
TYPED_TEST(SolidKernelTest, ShapeFunctionsArePartitionOfUnity) {
  using K = TypeParam;
  using E = typename K::ElementType;
  constexpr int dim = K::dim;
  std::mt19937 rng(505);
  std::uniform_real_distribution<Real> u(0.0, 0.3);
  const Real tol = 1e-14, h = 1e-6;
  for (int trial = 0; trial < 5; ++trial) {
    Real xi[dim];
    for (int i = 0; i < dim; ++i) xi[i] = u(rng);
    Real N[E::numNodes], dN[E::numNodes][dim];
    E::shape(xi, N, dN);
    Real sum = 0.0, dsum[dim] = {};
    for (int a = 0; a < E::numNodes; ++a) {
      sum += N[a];
      for (int i = 0; i < dim; ++i) dsum[i] += dN[a][i];
    }
    EXPECT_NEAR(sum, 1.0, tol);
    for (int i = 0; i < dim; ++i) EXPECT_NEAR(dsum[i], 0.0, tol);
    for (int i = 0; i < dim; ++i) {
      Real xp[dim], xm[dim], Np[E::numNodes], Nm[E::numNodes], d[E::numNodes][dim];
      std::copy(xi, xi + dim, xp);
      std::copy(xi, xi + dim, xm);
      xp[i] += h;
      xm[i] -= h;
      E::shape(xp, Np, d);
      E::shape(xm, Nm, d);
      for (int a = 0; a < E::numNodes; ++a) EXPECT_NEAR((Np[a] - Nm[a]) / (2 * h), dN[a][i], 1e-9);
    }
  }
  // Nodal interpolation: N_a(ξ_b) = δ_ab; quadrature weights sum to the parent volume.
  for (int b = 0; b < E::numNodes; ++b) {
    Real xi[dim], N[E::numNodes], dN[E::numNodes][dim];
    E::parentCoordinates(b, xi);
    E::shape(xi, N, dN);
    for (int a = 0; a < E::numNodes; ++a) EXPECT_NEAR(N[a], a == b ? 1.0 : 0.0, tol);
  }
  Real wsum = 0.0;
  for (int q = 0; q < E::numQp; ++q) {
    Real xi[dim], w;
    E::quadraturePoint(q, xi, w);
    wsum += w;
  }
  const Real parentVolume = std::is_same_v<E, Tet4> ? 1.0 / 6.0 : std::pow(2.0, dim);
  EXPECT_NEAR(wsum, parentVolume, tol);
}
