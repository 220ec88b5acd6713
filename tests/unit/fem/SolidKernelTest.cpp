// Unit tests of the updated-Lagrangian solid kernels, for every
// (formulation × element) pair: force = derivative of energy, tangent =
// derivative of force (central differences), rigid-motion invariance, patch
// test, rejection of inverted elements, and the homogeneous uniaxial state
// against the closed-form Neo-Hookean stress; and of the elements: shape
// functions interpolate and reproduce their polynomial space, quadrature
// rules are exact to their stated degree.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include "cgcm/fem/Dispatch.hpp"

using cgcm::Mat3;
using cgcm::Real;
using cgcm::fem::Axisymmetric;
using cgcm::fem::Hex20;
using cgcm::fem::Hex27;
using cgcm::fem::Hex8;
using cgcm::fem::PlaneStrain;
using cgcm::fem::Quad4;
using cgcm::fem::Quad8;
using cgcm::fem::Quad9;
using cgcm::fem::SolidKernel;
using cgcm::fem::Tet10;
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
// Element geometry

/// Whether E's parent domain is the unit simplex (node 0 at the origin) rather
/// than the cube [−1, 1]^dim (node 0 at (−1, …, −1)).
template <class E>
bool isSimplex() {
  Real xi[E::dim];
  E::parentCoordinates(0, xi);
  return xi[0] == 0.0;
}

/// The corners of E are its nodes 0 .. numCorners − 1, those of the linear element
/// of its shape (Quad4, Hex8, Tet4).
template <class E>
int numCorners() {
  return isSimplex<E>() ? E::dim + 1 : 1 << E::dim;
}

/// Polynomial order: 1 for the linear elements, 2 for those with nodes beyond the corners.
template <class E>
int order() {
  return E::numNodes > numCorners<E>() ? 2 : 1;
}

/// Shape functions of the linear element with E's corners at ξ (numCorners<E>() of them).
template <class E>
void linearShape(const Real (&xi)[E::dim], Real (&N)[8]) {
  if constexpr (E::dim == 2) {
    Real n[4], d[4][2];
    Quad4::shape(xi, n, d);
    std::copy(n, n + 4, N);
  } else if (isSimplex<E>()) {
    Real n[4], d[4][3];
    Tet4::shape(xi, n, d);
    std::copy(n, n + 4, N);
  } else {
    Real n[8], d[8][3];
    Hex8::shape(xi, n, d);
    std::copy(n, n + 8, N);
  }
}

/// Places the nodes beyond the corners where the linear map of the corners puts
/// them: a straight-sided element (the identity for linear elements).
template <class E>
void straightSided(Real (&x)[E::numNodes][E::dim]) {
  for (int a = numCorners<E>(); a < E::numNodes; ++a) {
    Real xi[E::dim], N[8];
    E::parentCoordinates(a, xi);
    linearShape<E>(xi, N);
    for (int i = 0; i < E::dim; ++i) {
      x[a][i] = 0.0;
      for (int b = 0; b < numCorners<E>(); ++b) x[a][i] += N[b] * x[b][i];
    }
  }
}

template <class E>
const char* elementName() {
  if constexpr (std::is_same_v<E, Quad4>) return "Quad4";
  if constexpr (std::is_same_v<E, Quad8>) return "Quad8";
  if constexpr (std::is_same_v<E, Quad9>) return "Quad9";
  if constexpr (std::is_same_v<E, Hex8>) return "Hex8";
  if constexpr (std::is_same_v<E, Hex20>) return "Hex20";
  if constexpr (std::is_same_v<E, Hex27>) return "Hex27";
  if constexpr (std::is_same_v<E, Tet4>) return "Tet4";
  if constexpr (std::is_same_v<E, Tet10>) return "Tet10";
  return "unnamed element";
}

// ---------------------------------------------------------------------------
// Geometry helpers

/// Reference element of unit size: the cube elements on [0,1]^dim, the
/// tetrahedra the unit corner tetrahedron; axisymmetric elements shifted to R ∈ [1, 2].
template <class Kernel>
void unitElement(Real (&X)[Kernel::numNodes][Kernel::dim]) {
  using E = typename Kernel::ElementType;
  for (int a = 0; a < Kernel::numNodes; ++a) {
    Real xi[Kernel::dim];
    E::parentCoordinates(a, xi);
    for (int i = 0; i < Kernel::dim; ++i) {
      X[a][i] = isSimplex<E>() ? xi[i] : 0.5 * (xi[i] + 1.0);
    }
    if (isAxisymmetric<Kernel>()) X[a][0] += 1.0;
  }
}

/// A randomly distorted reference element (each node moved by up to
/// `distortion` / order: quadratic elements' nodes are half as far apart).
template <class Kernel>
void randomElement(std::mt19937& rng, Real distortion, Real (&X)[Kernel::numNodes][Kernel::dim]) {
  std::uniform_real_distribution<Real> u(-distortion, distortion);
  const Real scale = 1.0 / order<typename Kernel::ElementType>();
  unitElement<Kernel>(X);
  for (int a = 0; a < Kernel::numNodes; ++a)
    for (int i = 0; i < Kernel::dim; ++i) X[a][i] += scale * u(rng);
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
  const Real scale = 1.0 / order<typename Kernel::ElementType>();
  for (int a = 0; a < Kernel::numNodes; ++a)
    for (int i = 0; i < Kernel::dim; ++i) x[a][i] += scale * u(rng);
}

template <class Kernel>
Real maxAbsVec(const Real (&v)[Kernel::numDofs]) {
  Real m = 0.0;
  for (int d = 0; d < Kernel::numDofs; ++d) m = std::max(m, std::abs(v[d]));
  return m;
}

// ---------------------------------------------------------------------------
// Small structured patches: (n × n [× n]) cells of size h; the tetrahedra split
// every cube into 6 (Kuhn triangulation, conforming). Each cell's nodes are
// its parent nodes mapped by the linear map of its corners (mid-edge nodes at
// edge midpoints, ...), nodes at the same place shared between cells.

struct Patch {
  int dim = 0;
  std::vector<std::array<Real, 3>> X;   // reference coordinates
  std::vector<std::vector<int>> cells;  // connectivity
  std::vector<int> interior;            // interior node ids
  std::vector<bool> vertex;             // whether a node is a vertex of the cell grid
  int centre = -1;                      // the grid vertex at the centre of the patch (n even)
};

/// The patch, its grid vertices numbered first (i + m j + m² k, m = n + 1); the
/// centre vertex moved by `shift` (n even) before the other nodes are placed, so
/// that the cells stay straight-sided.
template <class Kernel>
Patch makePatch(int n, Real h, Real rOffset, std::array<Real, 3> shift = {0.0, 0.0, 0.0}) {
  using E = typename Kernel::ElementType;
  constexpr int dim = Kernel::dim;
  const int p = order<E>();
  Patch patch;
  patch.dim = dim;
  const int m = n + 1;
  const int nz = dim == 3 ? m : 1;
  // Nodes by their place on the lattice of spacing h / p.
  std::map<std::array<int, 3>, int> byPlace;
  auto interiorPlace = [&](const std::array<int, 3>& l) {
    for (int i = 0; i < dim; ++i)
      if (l[i] <= 0 || l[i] >= p * n) return false;
    return true;
  };
  auto add = [&](const std::array<int, 3>& l, const std::array<Real, 3>& X, bool isVertex) {
    const int id = int(patch.X.size());
    byPlace[l] = id;
    patch.X.push_back(X);
    patch.vertex.push_back(isVertex);
    if (interiorPlace(l)) patch.interior.push_back(id);
    return id;
  };
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        std::array<Real, 3> X{i * h + rOffset, j * h, k * h};
        if (n % 2 == 0 && i == n / 2 && j == n / 2 && (dim == 2 || k == n / 2)) {
          for (int d = 0; d < dim; ++d) X[d] += shift[d];
          patch.centre = int(patch.X.size());
        }
        add({p * i, p * j, p * k}, X, true);
      }

  // One cell from its corners' grid indices: its nodes, created where new.
  auto addCell = [&](std::vector<std::array<int, 3>> corners) {
    if (isSimplex<E>()) {
      // orient it positively in the reference configuration
      Real e[3][3];
      for (int s = 0; s < 3; ++s)
        for (int i = 0; i < 3; ++i)
          e[s][i] = patch.X[byPlace.at({p * corners[s + 1][0], p * corners[s + 1][1], p * corners[s + 1][2]})][i] -
                    patch.X[byPlace.at({p * corners[0][0], p * corners[0][1], p * corners[0][2]})][i];
      const Real vol = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
                       e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                       e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
      if (vol < 0.0) std::swap(corners[1], corners[2]);
    }
    std::vector<int> cell;
    for (int a = 0; a < E::numNodes; ++a) {
      Real xi[dim], N[8];
      E::parentCoordinates(a, xi);
      linearShape<E>(xi, N);
      Real l[3] = {0.0, 0.0, 0.0};
      std::array<Real, 3> X{0.0, 0.0, 0.0};
      for (size_t b = 0; b < corners.size(); ++b) {
        const int v = byPlace.at({p * corners[b][0], p * corners[b][1], p * corners[b][2]});
        for (int i = 0; i < 3; ++i) {
          l[i] += N[b] * p * corners[b][i];
          X[i] += N[b] * patch.X[v][i];
        }
      }
      const std::array<int, 3> place{int(std::lround(l[0])), int(std::lround(l[1])), int(std::lround(l[2]))};
      const auto found = byPlace.find(place);
      cell.push_back(found != byPlace.end() ? found->second : add(place, X, false));
    }
    patch.cells.push_back(cell);
  };

  const int cz = dim == 3 ? n : 1;
  for (int k = 0; k < cz; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        if (!isSimplex<E>()) {
          std::vector<std::array<int, 3>> corners;
          for (int a = 0; a < numCorners<E>(); ++a) {
            Real xi[dim];
            E::parentCoordinates(a, xi);
            corners.push_back({i + (xi[0] > 0.0), j + (xi[1] > 0.0), dim == 3 ? k + (xi[dim - 1] > 0.0) : 0});
          }
          addCell(corners);
        } else {
          const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
          for (const auto& perm : perms) {
            int c[3] = {0, 0, 0};
            std::vector<std::array<int, 3>> corners{{i, j, k}};
            for (int s = 0; s < 3; ++s) {
              c[perm[s]] = 1;
              corners.push_back({i + c[0], j + c[1], k + c[2]});
            }
            addCell(corners);
          }
        }
      }
  return patch;
}

/// Curves the cells of a patch of cube elements of order 2: every interior node
/// that is not a grid vertex moved by up to 0.05 h (the patch test holds on
/// curved isoparametric cells when the rule integrates their Jacobians exactly,
/// as 3-point Gauss does for Quad8/9, Hex20/27; the 4-point rule of Tet10
/// does not, so its cells stay straight).
template <class Kernel>
void curveCells(Patch& p, Real h) {
  using E = typename Kernel::ElementType;
  if (isSimplex<E>() || order<E>() == 1) return;
  for (int c : p.interior) {
    if (p.vertex[c]) continue;
    const Real s = 0.05 * h;
    p.X[c][0] += s * std::sin(1.3 * c + 0.4);
    p.X[c][1] += s * std::cos(0.7 * c + 0.1);
    if (p.dim == 3) p.X[c][2] += s * std::sin(2.1 * c + 0.9);
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

// Every kernel fem::withSolidKernel dispatches to (the test below checks that none is
// missing), and those of the quadratic elements, which it does not reach yet.
using KernelTuple =
    std::tuple<SolidKernel<PlaneStrain, Quad4>, SolidKernel<Axisymmetric, Quad4>, SolidKernel<ThreeD, Hex8>,
               SolidKernel<ThreeD, Tet4>, SolidKernel<PlaneStrain, Quad8>, SolidKernel<Axisymmetric, Quad8>,
               SolidKernel<PlaneStrain, Quad9>, SolidKernel<Axisymmetric, Quad9>, SolidKernel<ThreeD, Tet10>,
               SolidKernel<ThreeD, Hex20>, SolidKernel<ThreeD, Hex27>>;
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
    return std::string(T::FormulationType::name) + elementName<typename T::ElementType>();
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

// (3b) Precision near F = I: the stress comes from the displacement gradient,
// not from x − X, so a translation of a very stiff element (Y = 1e9) far from
// the origin gives no force beyond the rounding of Σ_a ∂N_a = 0, 1e-7 of the
// forces of a strain of 1e-9 (σ of order 1), and that strain on top of the
// translation gives the force of the strain alone to 1e-7. From x − X, u itself
// would lose eps·|x| ≈ 2e-14 against the strain's 1e-7 over the element: a
// relative error of order 1e-4 in the forces.
TYPED_TEST(SolidKernelTest, StiffElementKeepsItsPrecisionUnderTranslation) {
  using K = TypeParam;
  std::mt19937 rng(909);
  for (bool small : {false, true}) {
    NeoHookean mat = NeoHookean::fromYoungPoisson(1e9, 0.3);
    if (small) mat.kinematics = cgcm::material::Kinematics::SmallStrain;
    Real X[K::numNodes][K::dim], x[K::numNodes][K::dim], u[K::numNodes][K::dim];
    Real x0[K::numNodes][K::dim], u0[K::numNodes][K::dim], f[K::numDofs], f0[K::numDofs];
    randomElement<K>(rng, 0.15, X);
    for (auto& node : X) node[0] += 100.0;  // far from the origin (the axis, in axisymmetry)
    const Real t[3] = {isAxisymmetric<K>() ? 0.0 : 0.0317, -0.0213, 0.011};
    // u0 = ε A X with ε = 1e-9: σ is of order Y ε = 1; u = t + u0.
    const Real A[3][3] = {{0.3, -0.2, 0.1}, {0.5, 0.7, -0.4}, {0.2, 0.1, -0.6}};
    Real ut[K::numNodes][K::dim], xt[K::numNodes][K::dim], ft[K::numDofs];
    for (int a = 0; a < K::numNodes; ++a)
      for (int i = 0; i < K::dim; ++i) {
        Real s = 0.0;
        for (int j = 0; j < K::dim; ++j) s += 1e-9 * A[i][j] * X[a][j];
        u0[a][i] = s;
        x0[a][i] = X[a][i] + s;
        u[a][i] = t[i] + s;
        x[a][i] = X[a][i] + u[a][i];
        ut[a][i] = t[i];
        xt[a][i] = X[a][i] + t[i];
      }
    ASSERT_TRUE(K::residual(X, x0, u0, mat, f0));
    const Real scale = maxAbsVec<K>(f0);
    ASSERT_TRUE(K::residual(X, xt, ut, mat, ft));
    EXPECT_LE(maxAbsVec<K>(ft), 1e-7 * scale) << (small ? "small strain" : "finite strain");
    ASSERT_TRUE(K::residual(X, x, u, mat, f));
    Real err = 0.0;
    for (int d = 0; d < K::numDofs; ++d) err = std::max(err, std::abs(f[d] - f0[d]));
    EXPECT_LE(err, 1e-7 * scale) << (small ? "small strain" : "finite strain");
    EXPECT_GT(maxAbsVec<K>(f0), 1e-3);  // the strain really loads the element
  }
}

// (4) Patch test: a homogeneous deformation of a distorted patch gives zero
// force at the interior nodes. The patch is 2 × 2 (× 2) cells (48 tetrahedra)
// sharing their nodes, its centre vertex moved; the quadratic cube cells are
// curved as well.
TYPED_TEST(SolidKernelTest, PatchTestHomogeneousDeformation) {
  using K = TypeParam;
  constexpr int dim = K::dim;
  const Real tol = 1e-12;  // relative to the largest assembled nodal force
  Patch p = makePatch<K>(2, 1.0, isAxisymmetric<K>() ? 1.0 : 0.0, {0.2, -0.15, dim == 3 ? 0.1 : 0.0});
  curveCells<K>(p, 1.0);
  ASSERT_FALSE(p.interior.empty());

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
      for (int c : p.interior)
        for (int i = 0; i < dim; ++i)
          EXPECT_LE(std::abs(R[c * dim + i]), tol * rmax)
              << cgcm::material::toString(law) << " trial " << trial << " node " << c << " component " << i;
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
  Patch p = makePatch<K>(2, 1.0, isAxisymmetric<K>() ? 1.0 : 0.0, {0.2, -0.15, K::dim == 3 ? 0.1 : 0.0});
  curveCells<K>(p, 1.0);
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
  for (int c : p.interior)
    for (int i = 0; i < K::dim; ++i)
      EXPECT_LE(std::abs(R[c * K::dim + i]), 1e-12 * rmax) << "node " << c << " component " << i;
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

  // One corner pushed through the element (the other nodes on the straight
  // sides): inverted at some quadrature points.
  std::copy(&X[0][0], &X[0][0] + K::numDofs, &x[0][0]);
  if (isSimplex<E>()) {
    x[3][2] = -0.5;
  } else {
    const int far = numCorners<E>() - 2;  // the corner opposite node 0
    for (int i = 0; i < K::dim; ++i) x[far][i] = X[0][i] + 0.05;
  }
  straightSided<E>(x);
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

    // One cell (tetrahedra: the box split into 6) of size L, origin at 0 (R0 in axisymmetry).
    Patch patch = makePatch<K>(1, 1.0, 0.0);
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
  const Real parentVolume = isSimplex<E>() ? (dim == 3 ? 1.0 / 6.0 : 0.5) : std::pow(2.0, dim);
  EXPECT_NEAR(wsum, parentVolume, tol);
}

namespace {
/// ξ^e (η^f ζ^g) and its gradient.
template <int Dim>
Real monomial(const int (&e)[Dim], const Real (&xi)[Dim], Real (&grad)[Dim]) {
  Real m = 1.0;
  for (int i = 0; i < Dim; ++i) m *= std::pow(xi[i], e[i]);
  for (int j = 0; j < Dim; ++j) {
    grad[j] = e[j] == 0 ? 0.0 : e[j] * std::pow(xi[j], e[j] - 1);
    for (int i = 0; i < Dim; ++i)
      if (i != j) grad[j] *= std::pow(xi[i], e[i]);
  }
  return m;
}

/// Every exponent tuple with entries 0 .. maxExponent.
template <int Dim>
std::vector<std::array<int, Dim>> exponents(int maxExponent) {
  std::vector<std::array<int, Dim>> out;
  int count = 1;
  for (int i = 0; i < Dim; ++i) count *= maxExponent + 1;
  for (int n = 0; n < count; ++n) {
    std::array<int, Dim> e;
    for (int i = 0, r = n; i < Dim; ++i, r /= maxExponent + 1) e[i] = r % (maxExponent + 1);
    out.push_back(e);
  }
  return out;
}

/// Whether E's shape functions span the monomial with exponents e: P_p on the simplex,
/// Q_p for the Lagrange cube elements ((p+1)^dim nodes), the serendipity space (at most
/// one exponent above 1) for the others.
template <class E, std::size_t Dim>
bool spans(const std::array<int, Dim>& e) {
  const int p = order<E>();
  int sum = 0, max = 0, superlinear = 0;
  for (int v : e) sum += v, max = std::max(max, v), superlinear += v > 1;
  if (isSimplex<E>()) return sum <= p;
  if (E::numNodes == int(std::pow(p + 1, E::dim))) return max <= p;
  return max <= p && superlinear <= 1;
}

/// A random point of E's parent domain.
template <class E>
void randomParentPoint(std::mt19937& rng, Real (&xi)[E::dim]) {
  if (isSimplex<E>()) {
    std::uniform_real_distribution<Real> u(0.0, 1.0);
    for (;;) {
      Real sum = 0.0;
      for (int i = 0; i < E::dim; ++i) sum += (xi[i] = u(rng));
      if (sum <= 1.0) return;
    }
  }
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  for (int i = 0; i < E::dim; ++i) xi[i] = u(rng);
}
}  // namespace

// Shape functions reproduce exactly the polynomials of their space, through
// the interpolant Σ_a m(ξ_a) N_a(ξ) = m(ξ) and its gradient, at random points
// of the parent domain: constants and linear fields (completeness) and the
// quadratic ones of each element; the monomials of degree <= 2 in each
// coordinate outside the space are not reproduced, and the space has as many
// monomials as the element nodes.
TYPED_TEST(SolidKernelTest, ShapeFunctionsReproduceTheirPolynomialSpace) {
  using K = TypeParam;
  using E = typename K::ElementType;
  constexpr int dim = K::dim;
  // Values of order 1 summed over <= 27 nodes; gradients up to ~4 per node.
  const Real tolValue = 1e-14, tolGradient = 1e-13;
  std::mt19937 rng(606);
  std::vector<std::array<Real, dim>> points(10);
  for (auto& pt : points) {
    Real xi[dim];
    randomParentPoint<E>(rng, xi);
    std::copy(xi, xi + dim, pt.begin());
  }
  int spanned = 0;
  for (const auto& ex : exponents<dim>(2)) {
    int e[dim];
    std::copy(ex.begin(), ex.end(), e);
    Real nodal[E::numNodes];
    for (int a = 0; a < E::numNodes; ++a) {
      Real xa[dim], g[dim];
      E::parentCoordinates(a, xa);
      nodal[a] = monomial(e, xa, g);
    }
    Real worst = 0.0, worstGradient = 0.0;
    for (const auto& pt : points) {
      Real xi[dim], N[E::numNodes], dN[E::numNodes][dim], grad[dim];
      std::copy(pt.begin(), pt.end(), xi);
      E::shape(xi, N, dN);
      const Real m = monomial(e, xi, grad);
      Real v = 0.0, dv[dim] = {};
      for (int a = 0; a < E::numNodes; ++a) {
        v += nodal[a] * N[a];
        for (int i = 0; i < dim; ++i) dv[i] += nodal[a] * dN[a][i];
      }
      worst = std::max(worst, std::abs(v - m));
      for (int i = 0; i < dim; ++i) worstGradient = std::max(worstGradient, std::abs(dv[i] - grad[i]));
    }
    std::string name = "xi^(";
    for (int i = 0; i < dim; ++i) name += std::to_string(e[i]) + (i + 1 < dim ? "," : ")");
    if (spans<E>(ex)) {
      ++spanned;
      EXPECT_LE(worst, tolValue) << name;
      EXPECT_LE(worstGradient, tolGradient) << name;
    } else {
      EXPECT_GT(std::max(worst, worstGradient), 1e-6) << name << " is reproduced but outside the element's space";
    }
  }
  EXPECT_EQ(spanned, E::numNodes);
}

// The quadrature rule integrates over the parent domain exactly every monomial
// of degree <= quadratureDegree in each coordinate (cube) or in total
// (simplex), and not every one of the next degree (the stated degree is sharp).
TYPED_TEST(SolidKernelTest, QuadratureIsExactToItsDegree) {
  using K = TypeParam;
  using E = typename K::ElementType;
  constexpr int dim = K::dim;
  const int degree = E::quadratureDegree;
  const Real tol = 1e-14;  // absolute: integrals <= 8, sums of <= 27 terms
  Real worstBeyond = 0.0;
  for (const auto& ex : exponents<dim>(degree + 1)) {
    int e[dim], sum = 0, max = 0;
    std::copy(ex.begin(), ex.end(), e);
    for (int v : e) sum += v, max = std::max(max, v);
    // exact integral: Π 2/(e+1) over even exponents (cube); Π e_i! / (Σ e + dim)! (simplex)
    Real exact = 1.0;
    if (isSimplex<E>()) {
      if (sum > degree + 1) continue;
      for (int v : e) exact *= std::tgamma(v + 1.0);
      exact /= std::tgamma(sum + dim + 1.0);
    } else {
      for (int v : e) exact *= v % 2 ? 0.0 : 2.0 / (v + 1);
    }
    Real q = 0.0;
    for (int k = 0; k < E::numQp; ++k) {
      Real xi[dim], w, g[dim];
      E::quadraturePoint(k, xi, w);
      q += w * monomial(e, xi, g);
    }
    const bool withinDegree = isSimplex<E>() ? sum <= degree : max <= degree;
    if (withinDegree) {
      EXPECT_NEAR(q, exact, tol) << "exponents " << e[0] << " " << e[1]
                                 << (dim == 3 ? " " + std::to_string(e[dim - 1]) : "");
    } else {
      worstBeyond = std::max(worstBeyond, std::abs(q - exact));
    }
  }
  EXPECT_GT(worstBeyond, 1e-6) << "the rule is exact beyond its stated degree " << degree;
}

namespace {
/// Checks that node corners.size() + k (k = 0, 1, …) of E sits at the mean of the parent
/// coordinates of the corners listed in between[k]: the node orders of Elements.hpp.
template <class E>
void expectNodesBetween(const std::vector<std::vector<int>>& between) {
  SCOPED_TRACE(elementName<E>());
  const int first = E::numNodes - int(between.size());
  ASSERT_EQ(first, numCorners<E>());
  for (size_t k = 0; k < between.size(); ++k) {
    Real xi[E::dim], mean[E::dim] = {};
    E::parentCoordinates(first + int(k), xi);
    for (int c : between[k]) {
      Real xc[E::dim];
      E::parentCoordinates(c, xc);
      for (int i = 0; i < E::dim; ++i) mean[i] += xc[i] / Real(between[k].size());
    }
    for (int i = 0; i < E::dim; ++i) EXPECT_EQ(xi[i], mean[i]) << "node " << first + int(k) << " coordinate " << i;
  }
}
}  // namespace

// The higher-order nodes in the Exodus II order (SEACAS Ioss: the edge and face
// node tables of quad8/quad9, tetra10, hex20, hex27), each as the corners it
// sits between.
TEST(ElementNodeOrder, HigherOrderNodesAreTheExodusOnes) {
  const std::vector<std::vector<int>> quadEdges{{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  expectNodesBetween<Quad8>(quadEdges);
  auto quad9 = quadEdges;
  quad9.push_back({0, 1, 2, 3});
  expectNodesBetween<Quad9>(quad9);

  expectNodesBetween<Tet10>({{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}});

  const std::vector<std::vector<int>> hexEdges{{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5},
                                               {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}};
  expectNodesBetween<Hex20>(hexEdges);
  auto hex27 = hexEdges;
  hex27.push_back({0, 1, 2, 3, 4, 5, 6, 7});  // 20: the centre
  // 21-26: the faces of Exodus sides 5, 6, 4, 2, 1, 3 (-ζ, +ζ, -ξ, +ξ, -η, +η)
  for (const std::vector<int>& face : std::vector<std::vector<int>>{
           {0, 3, 2, 1}, {4, 5, 6, 7}, {0, 4, 7, 3}, {1, 2, 6, 5}, {0, 1, 5, 4}, {2, 3, 7, 6}})
    hex27.push_back(face);
  expectNodesBetween<Hex27>(hex27);
}
