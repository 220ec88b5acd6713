// Method 1 (element-pair volume interaction): the point-pair laws against
// direct quadrature and finite differences, the pair kernel's forces against
// the gradient of its energy, its tangent against finite differences of the
// forces, the balance of the forces on the two bodies, and two flat blocks
// against the half-space traction (doc/theory.md#method-3).
#include <gtest/gtest.h>

#include <Kokkos_Core.hpp>
#include <Sacado.hpp>

#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "cgcm/core/Error.hpp"
#include "cgcm/interaction/PairPotential.hpp"
#include "cgcm/interaction/Quadrature.hpp"
#include "cgcm/interaction/VolumeInteraction.hpp"
#include "cgcm/fem/Dispatch.hpp"
#include "cgcm/mesh/Benchmark.hpp"
#include "cgcm/mesh/Generators.hpp"
#include "cgcm/mesh/Mesh.hpp"
#include "cgcm/mesh/Mirror.hpp"
#include "cgcm/interaction/InteractionSetup.hpp"

namespace cgcm::interaction {
namespace {

const InversePowerPair kInversePowers{1.3, 2.1};
const MorsePair kMorse = MorsePair::matchedToLennardJones(0.8, 1.1);

/// The generic quadratures of KernelLaws.hpp as a potential without closed forms.
struct WithoutClosedForms {
  InversePowerPair p;
  RadialLaw pointLaw(Real s) const { return p.pointLaw(s); }
  Real phi(Real r) const { return p.phi(r); }
};

/// The closed-form ring law for any scalar type (forward AD checks the chain rule through (A, D)).
template <class T>
T ringAverage(const InversePowerPair& c, const T& p, const T& q) {
  using std::pow;
  const T A = 0.5 * (p + q), D = p * q, A2 = A * A;
  const T repulsive = A * (63.0 * A2 * A2 - 70.0 * A2 * D + 15.0 * D * D) / (8.0 * pow(D, 5.5));
  const T attractive = (3.0 * A2 - D) / (2.0 * pow(D, 2.5));
  return c.c12 * repulsive - c.c6 * attractive;
}

template <class P>
void expectRingLawIsTheAzimuthalMean(const P& c, Real tolerance) {
  // (rho1, z1, rho2, z2): near the axis, far from it, on the axis, far apart, near on a large ring
  const Real cases[][4] = {{0.2, 0.0, 0.5, 0.9},
                           {3.0, 0.1, 3.2, 1.0},
                           {0.0, 0.0, 1.0, 1.2},
                           {1.0, 0.0, 2.5, -2.0},
                           {100.0, 0.0, 100.4, 0.95}};
  for (const auto& p : cases) {
    // periodic integrand: the trapezoidal rule converges exponentially
    const int n = 200000;
    Real mean = 0.0;
    for (int k = 0; k < n; ++k) {
      const Real t = 2.0 * kPi * k / n;
      const Real r2 = p[0] * p[0] + p[2] * p[2] - 2.0 * p[0] * p[2] * std::cos(t) + (p[1] - p[3]) * (p[1] - p[3]);
      mean += c.phi(std::sqrt(r2)) / n;
    }
    Real psi, g[3];
    pairLawAxisymmetric(c, p, p + 2, psi, g, nullptr, nullptr);
    EXPECT_NEAR(psi, mean, tolerance * std::abs(mean)) << p[0] << " " << p[2];
  }
}

TEST(VolumePairLaw, RingAverageIsTheAzimuthalMeanOfThePotential) {
  expectRingLawIsTheAzimuthalMean(kInversePowers, 1e-10);  // closed form
  // measured: generic quadrature (20 points) within 2e-13 of the closed form on these cases
  expectRingLawIsTheAzimuthalMean(WithoutClosedForms{kInversePowers}, 1e-10);
  // measured: Morse through the generic quadrature within 6e-10 (its exponential
  // tail is not a polynomial in the quadrature's variable)
  expectRingLawIsTheAzimuthalMean(kMorse, 3e-9);
}

TEST(VolumePairLaw, GenericQuadraturesMatchTheClosedForms) {
  // the line and ring quadratures of KernelLaws.hpp against the closed forms
  // of r^-12 and r^-6, with all derivatives, from touching to far points
  const WithoutClosedForms generic{kInversePowers};
  for (Real s : {0.3, 1.0, 4.0, 100.0}) {
    const RadialLaw exact = kInversePowers.lineLaw(s), q = lineLaw(generic, s);
    EXPECT_NEAR(q.f, exact.f, 1e-12 * std::abs(exact.f)) << s;
    EXPECT_NEAR(q.df, exact.df, 1e-12 * std::abs(exact.df)) << s;
    EXPECT_NEAR(q.d2f, exact.d2f, 1e-12 * std::abs(exact.d2f)) << s;
  }
  const Real cases[][2] = {{0.5, 3.0}, {1.0, 1.0}, {0.9, 4e4}, {2.0, 9.0}, {1e-2, 1e6}};
  for (const auto& pq : cases) {
    const RingLaw exact = kInversePowers.ringLaw(pq[0], pq[1], true), q = ringLaw(generic, pq[0], pq[1], true);
    const Real got[6] = {q.F, q.Fp, q.Fq, q.Fpp, q.Fpq, q.Fqq},
               want[6] = {exact.F, exact.Fp, exact.Fq, exact.Fpp, exact.Fpq, exact.Fqq};
    for (int k = 0; k < 6; ++k)
      EXPECT_NEAR(got[k], want[k], 1e-11 * std::abs(want[k]) + 1e-300) << "p " << pq[0] << " q " << pq[1] << " " << k;
  }
}

TEST(VolumePairLaw, AxisymmetricDerivativesMatchForwardAD) {
  // the chain rule through (A, D) of the closed-form ring law against Sacado
  using F1 = Sacado::Fad::SFad<Real, 4>;
  using F2 = Sacado::Fad::SFad<F1, 4>;
  const InversePowerPair& c = kInversePowers;
  const Real x[4] = {0.7, 0.2, 1.1, 0.9};
  F2 v[4];
  for (int k = 0; k < 4; ++k) v[k] = F2(4, k, F1(4, k, x[k]));
  const F2 dr = v[0] - v[2], sr = v[0] + v[2], dz = v[1] - v[3];
  const F2 psiAD = ringAverage(c, F2(dr * dr + dz * dz), F2(sr * sr + dz * dz));
  Real psi, g[3], H11[3][3], H12[3][3];
  pairLawAxisymmetric(c, x, x + 2, psi, g, H11, H12);
  EXPECT_NEAR(psi, psiAD.val().val(), 1e-13 * std::abs(psi));
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(g[i], psiAD.dx(i).val(), 1e-12 * std::abs(g[i]));
    for (int j = 0; j < 2; ++j) {
      EXPECT_NEAR(H11[i][j], psiAD.dx(i).dx(j), 1e-11 * (std::abs(H11[i][j]) + 1.0));
      EXPECT_NEAR(H12[i][j], psiAD.dx(i).dx(2 + j), 1e-11 * (std::abs(H12[i][j]) + 1.0));
    }
  }
}

template <class P>
void expectLineLawIsTheLineIntegral(const P& c, Real tolerance) {
  for (Real d : {0.7, 1.0, 2.5}) {
    // z = d tan t over t in (-pi/2, pi/2)
    auto f = [&](Real t) { return c.phi(d / std::cos(t)) * d / (std::cos(t) * std::cos(t)); };
    const Real line = integrate(f, -0.5 * kPi, 0.5 * kPi, 200, gaussLegendreUnit(10));
    const Real x1[2] = {0.3, -0.2}, x2[2] = {0.3 + 0.6 * d, -0.2 + 0.8 * d};
    Real psi, g[3];
    pairLawPlaneStrain(c, x1, x2, psi, g, nullptr, nullptr);
    EXPECT_NEAR(psi, line, tolerance * std::abs(line)) << d;
  }
}

TEST(VolumePairLaw, PlaneStrainLawIsTheLineIntegralOfThePotential) {
  expectLineLawIsTheLineIntegral(kInversePowers, 1e-12);
  // measured: Morse through the generic quadrature within 1.4e-9 (the reference
  // agrees with an arbitrary-precision quadrature to 1e-15)
  expectLineLawIsTheLineIntegral(kMorse, 5e-9);
}

template <class P>
void checkLawDerivatives(const P& c, int dim, const Real* x1, const Real* x2) {
  auto law = [&](const Real* y1, const Real* y2, Real& psi, Real* g, Real(*H11)[3], Real(*H12)[3]) {
    if (dim == 3)
      pairLaw3D(c, y1, y2, psi, g, H11, H12);
    else if (dim == 2)
      pairLawPlaneStrain(c, y1, y2, psi, g, H11, H12);
    else
      pairLawAxisymmetric(c, y1, y2, psi, g, H11, H12);
  };
  if (dim < 0) dim = 2;  // axisymmetric
  Real psi, g[3], H11[3][3], H12[3][3];
  law(x1, x2, psi, g, H11, H12);
  const Real h = 1e-6;
  for (int j = 0; j < dim; ++j)
    for (int side = 0; side < 2; ++side) {
      Real a[3], b[3], pa, pb, ga[3], gb[3];
      for (int i = 0; i < dim; ++i) {
        a[i] = side == 0 ? x1[i] : x2[i];
        b[i] = a[i];
      }
      a[j] += h;
      b[j] -= h;
      if (side == 0) {
        law(a, x2, pa, ga, nullptr, nullptr);
        law(b, x2, pb, gb, nullptr, nullptr);
        EXPECT_NEAR(g[j], (pa - pb) / (2 * h), 1e-7 * (1.0 + std::abs(g[j])));
      } else {
        law(x1, a, pa, ga, nullptr, nullptr);
        law(x1, b, pb, gb, nullptr, nullptr);
      }
      for (int i = 0; i < dim; ++i) {
        const Real fd = (ga[i] - gb[i]) / (2 * h), exact = side == 0 ? H11[i][j] : H12[i][j];
        EXPECT_NEAR(exact, fd, 1e-6 * (1.0 + std::abs(exact))) << "dim " << dim << " side " << side;
      }
    }
}

template <class P>
void checkAllLawDerivatives(const P& c) {
  const Real a2[2] = {0.9, 0.1}, b2[2] = {1.3, 0.95};
  checkLawDerivatives(c, 2, a2, b2);
  checkLawDerivatives(c, -1, a2, b2);
  const Real axis[2] = {0.0, 0.0}, off[2] = {0.4, 1.0};  // a ring of radius 0 (on the axis)
  checkLawDerivatives(c, -1, axis, off);
  const Real a3[3] = {0.1, 0.2, -0.3}, b3[3] = {0.5, 0.9, 0.4};
  checkLawDerivatives(c, 3, a3, b3);
}

TEST(VolumePairLaw, DerivativesMatchFiniteDifferences) {
  checkAllLawDerivatives(InversePowerPair{1.0, 2.0});
  checkAllLawDerivatives(WithoutClosedForms{InversePowerPair{1.0, 2.0}});
  checkAllLawDerivatives(kMorse);
}

// ---- two small bodies --------------------------------------------------

/// A structured block of nx x ny (x nz) cells on [x0, x0 + lx] x ..., its
/// cells of `type`, perturbed by `jitter` times the cell size.
void addBlock(mesh::Mesh& m, int body, CellType type, const Real origin[3], const Real size[3],
              const int cells[3], Real jitter, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  const int d = m.dim;
  const LocalIndex first = m.numNodes();
  const int nz = d == 3 ? cells[2] : 0;
  auto id = [&](int i, int j, int k) { return first + LocalIndex((k * (cells[1] + 1) + j) * (cells[0] + 1) + i); };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= cells[1]; ++j)
      for (int i = 0; i <= cells[0]; ++i) {
        const int idx[3] = {i, j, k};
        for (int c = 0; c < d; ++c) {
          const Real h = size[c] / cells[c];
          m.coords.push_back(origin[c] + idx[c] * h + jitter * h * u(rng));
        }
      }
  mesh::ElementBlock b;
  b.name = "body" + std::to_string(body);
  b.body = body;
  b.type = type;
  for (int k = 0; k < std::max(nz, 1); ++k)
    for (int j = 0; j < cells[1]; ++j)
      for (int i = 0; i < cells[0]; ++i) {
        if (d == 2) {
          for (LocalIndex n : {id(i, j, 0), id(i + 1, j, 0), id(i + 1, j + 1, 0), id(i, j + 1, 0)})
            b.connectivity.push_back(n);
          continue;
        }
        const LocalIndex h[8] = {id(i, j, k),         id(i + 1, j, k),         id(i + 1, j + 1, k),
                                 id(i, j + 1, k),     id(i, j, k + 1),         id(i + 1, j, k + 1),
                                 id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        if (type == CellType::Hex8) {
          b.connectivity.insert(b.connectivity.end(), h, h + 8);
        } else {
          // six positively oriented tetrahedra around the diagonal 0-6
          const int t[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
          for (const auto& tt : t)
            for (int a : tt) b.connectivity.push_back(h[a]);
        }
      }
  m.blocks.push_back(b);
  m.numBodies = std::max(m.numBodies, body + 1);
}

struct TwoBodies {
  mesh::Mesh mesh;
  Formulation formulation;
};

TwoBodies twoBodies(Formulation f, CellType type) {
  TwoBodies t;
  t.formulation = f;
  t.mesh.dim = f == Formulation::ThreeD ? 3 : 2;
  t.mesh.numBodies = 2;
  // tetrahedra: one cube of six per body (the finite differences cost a
  // pair list of squared size per dof)
  const int c2[3] = {2, 2, 1}, c3[3] = {2, 1, 2}, c1[3] = {1, 1, 1};
  const Real o0[3] = {0.2, 0.0, 0.0}, s0[3] = {1.0, 0.6, 0.8};
  const Real o1[3] = {0.5, 0.95, 0.1}, s1[3] = {1.1, 0.7, 0.9};
  const int* cells = t.mesh.dim == 2 ? c2 : type == CellType::Tet4 ? c1 : c3;
  addBlock(t.mesh, 0, type, o0, s0, cells, 0.08, 1);
  addBlock(t.mesh, 1, type, o1, s1, cells, 0.08, 2);
  return t;
}

struct Assembled {
  std::vector<Real> f;
  std::map<std::pair<int, int>, Real> K;  ///< (dof, dof) -> value
};

Assembled assemble(VolumeInteraction& vi, const std::vector<Real>& x, bool tangent) {
  Assembled out;
  out.f.assign(x.size(), 0.0);
  const int d = vi.dim();
  vi.evaluate(
      x.data(),
      [&](const auto& c, long) {
        for (int a = 0; a < c.numRowNodes; ++a)
          for (int i = 0; i < d; ++i) {
            const int row = d * c.rowNodes[a] + i;
            out.f[row] += c.f[d * a + i];
            if (!tangent) continue;
            for (int b = 0; b < c.numColNodes; ++b)
              for (int j = 0; j < d; ++j) out.K[{row, d * c.colNodes[b] + j}] += c.K[d * a + i][d * b + j];
          }
      },
      tangent);
  return out;
}

// Forces = gradient of the energy; tangent = derivative of the forces (central differences), at x
// where `a` was assembled with its tangent.
void expectGradientAndTangent(VolumeInteraction& vi, const std::vector<Real>& x, const Assembled& a) {
  const Real h = 1e-6;
  Real fmax = 0.0;
  for (Real v : a.f) fmax = std::max(fmax, std::abs(v));
  Real kmax = 0.0;
  for (const auto& [ij, v] : a.K) kmax = std::max(kmax, std::abs(v));
  for (std::size_t dof = 0; dof < x.size(); ++dof) {
    std::vector<Real> xp = x, xm = x;
    xp[dof] += h;
    xm[dof] -= h;
    const Real ep = vi.energy(xp.data()), em = vi.energy(xm.data());
    EXPECT_NEAR(a.f[dof], (ep - em) / (2 * h), 1e-6 * fmax) << "dof " << dof;
    const Assembled ap = assemble(vi, xp, false), am = assemble(vi, xm, false);
    for (std::size_t row = 0; row < x.size(); ++row) {
      const auto it = a.K.find({int(row), int(dof)});
      const Real exact = it == a.K.end() ? 0.0 : it->second;
      EXPECT_NEAR(exact, (ap.f[row] - am.f[row]) / (2 * h), 1e-6 * kmax) << "row " << row << " col " << dof;
    }
  }
}

void checkKernelOn(const TwoBodies& t, Real r0, const std::string& potential) {
  const Formulation f = t.formulation;
  VolumeInteractionOptions o;
  o.formulation = f;
  o.quadratureOrder = 2;
  o.maxQuadratureOrder = 3;
  o.cutoff = 1e3;  // every pair
  VolumeInteraction vi(t.mesh, {1.2, 0.9}, makePotential(potential, 0.7, r0), o);
  std::vector<Real> x = t.mesh.coords;
  ASSERT_TRUE(vi.updatePairs(x.data()));
  ASSERT_GT(vi.pairs().size(), 0u);
  const Assembled a = assemble(vi, x, true);
  const auto resultant = vi.summary().resultant;
  // forces on the two bodies: equal and opposite (axisymmetric: the axial component)
  for (int i = f == Formulation::Axisymmetric ? 1 : 0; i < vi.dim(); ++i) {
    const Real scale = std::abs(resultant[0][i]) + std::abs(resultant[1][i]) + 1e-300;
    EXPECT_NEAR(resultant[0][i] + resultant[1][i], 0.0, 1e-13 * scale) << "component " << i;
  }
  EXPECT_GT(std::abs(resultant[0][1]), 0.0);
  expectGradientAndTangent(vi, x, a);
}

void checkKernel(Formulation f, CellType type, Real r0, const std::string& potential = "lennard-jones") {
  checkKernelOn(twoBodies(f, type), r0, potential);
}

TEST(VolumeInteraction, PlaneStrainForcesTangentAndBalance) { checkKernel(Formulation::PlaneStrain, CellType::Quad4, 0.3); }
TEST(VolumeInteraction, AxisymmetricForcesTangentAndBalance) {
  checkKernel(Formulation::Axisymmetric, CellType::Quad4, 0.3);
}
TEST(VolumeInteraction, Hex8ForcesTangentAndBalance) { checkKernel(Formulation::ThreeD, CellType::Hex8, 0.3); }
TEST(VolumeInteraction, Tet4ForcesTangentAndBalance) { checkKernel(Formulation::ThreeD, CellType::Tet4, 0.3); }
TEST(VolumeInteraction, MorseForcesTangentAndBalance) {
  // a potential with neither line nor ring law in closed form: the generic quadratures
  checkKernel(Formulation::PlaneStrain, CellType::Quad4, 0.3, "morse");
  checkKernel(Formulation::Axisymmetric, CellType::Quad4, 0.3, "morse");
  checkKernel(Formulation::ThreeD, CellType::Hex8, 0.3, "morse");
}

// ---- quadratic cells ------------------------------------------------------

/// The linear cell type that mesh::elevate makes `quadratic` of.
CellType linearOf(CellType quadratic) {
  return cellTypeInfo(quadratic).dim == 2 ? CellType::Quad4 : cellTypeInfo(quadratic).simplex ? CellType::Tet4
                                                                                                : CellType::Hex8;
}

/// twoBodies of the linear cells of `type`, elevated to `type`; the nodes elevate adds (every
/// node but the corners) moved by up to `curve` times 0.1 in every direction: curved cells.
TwoBodies quadraticBodies(Formulation f, CellType type, Real curve, unsigned seed = 3) {
  TwoBodies t = twoBodies(f, linearOf(type));
  const LocalIndex corners = t.mesh.numNodes();
  mesh::elevate(t.mesh, type == CellType::Quad8 || type == CellType::Hex20);
  EXPECT_EQ(t.mesh.blocks[0].type, type);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1.0, 1.0);
  for (std::size_t k = std::size_t(corners) * t.mesh.dim; k < t.mesh.coords.size(); ++k) t.mesh.coords[k] += 0.1 * curve * u(rng);
  return t;
}

// The exact tangent of the quadratic cells against central differences of the forces, and the
// forces against central differences of the energy, on curved cells (mid-edge, face and centre
// nodes moved off the straight cell by up to 0.1, a quarter of the cells' size): the same check
// and tolerance as the linear cells' (1e-6 of the largest entry: central differences with h = 1e-6
// leave O(h^2) ~ 1e-12 truncation and ~1e-10 round-off relative to it).
TEST(VolumeInteraction, QuadraticCellsForcesTangentAndBalance) {
  for (CellType type : {CellType::Quad8, CellType::Quad9}) {
    for (Formulation f : {Formulation::PlaneStrain, Formulation::Axisymmetric}) {
      SCOPED_TRACE(std::string(cellTypeInfo(type).name) + " " + formulationName(f));
      checkKernelOn(quadraticBodies(f, type, 1.0), 0.3, "lennard-jones");
    }
  }
}
TEST(VolumeInteraction, QuadraticHexahedraForcesTangentAndBalance) {
  for (CellType type : {CellType::Hex20, CellType::Hex27}) {
    SCOPED_TRACE(cellTypeInfo(type).name);
    checkKernelOn(quadraticBodies(Formulation::ThreeD, type, 1.0), 0.3, "lennard-jones");
  }
}
TEST(VolumeInteraction, Tet10ForcesTangentAndBalance) {
  checkKernelOn(quadraticBodies(Formulation::ThreeD, CellType::Tet10, 1.0), 0.3, "lennard-jones");
}

/// Energy and resultants on the two bodies of `t`.
std::pair<Real, std::vector<std::array<Real, 3>>> energyAndResultant(const TwoBodies& t, int order = 2) {
  VolumeInteractionOptions o;
  o.formulation = t.formulation;
  o.quadratureOrder = order;
  o.cutoff = 1e3;
  VolumeInteraction vi(t.mesh, {1.2, 0.9}, makePotential("lennard-jones", 0.7, 0.3), o);
  vi.updatePairs(t.mesh.coords.data());
  assemble(vi, t.mesh.coords, false);
  return {vi.summary().energy, vi.summary().resultant};
}

TEST(VolumeInteraction, StraightQuadraticCellsIntegrateAsTheirLinearCells) {
  // mid-edge, face and centre nodes where the linear cell has them: the quadratic map is the
  // linear one, so the same rule places the same points with the same weights (the pair orders
  // come from the same boxes): energy and resultant agree to round-off (the node forces differ)
  const std::pair<CellType, Formulation> cases[] = {
      {CellType::Quad8, Formulation::PlaneStrain}, {CellType::Quad9, Formulation::PlaneStrain},
      {CellType::Quad8, Formulation::Axisymmetric}, {CellType::Quad9, Formulation::Axisymmetric},
      {CellType::Hex20, Formulation::ThreeD},      {CellType::Hex27, Formulation::ThreeD},
      {CellType::Tet10, Formulation::ThreeD}};
  for (const auto& [type, f] : cases) {
    SCOPED_TRACE(std::string(cellTypeInfo(type).name) + " " + formulationName(f));
    const auto linear = energyAndResultant(twoBodies(f, linearOf(type)));
    const auto quadratic = energyAndResultant(quadraticBodies(f, type, 0.0));
    EXPECT_NEAR(quadratic.first, linear.first, 1e-12 * std::abs(linear.first));
    const Real scale = std::abs(linear.second[0][1]);
    ASSERT_GT(scale, 0.0);
    for (int b = 0; b < 2; ++b)
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(quadratic.second[b][i], linear.second[b][i], 1e-12 * scale) << b << i;
  }
}

TEST(VolumeInteraction, CellBoxHoldsTheCurvedCell) {
  // strongly curved cells (non-corner nodes moved by up to 0.3, most of a cell): every point of
  // the cell, sampled in its parent domain, lies in cellBox; and no point moves by more than
  // maxPointMotion times its nodes' largest motion (the Verlet test), which the sampling reaches
  // to 1e-2
  for (CellType type : {CellType::Quad8, CellType::Quad9, CellType::Hex20, CellType::Hex27, CellType::Tet10}) {
    SCOPED_TRACE(cellTypeInfo(type).name);
    const Formulation f = cellTypeInfo(type).dim == 2 ? Formulation::PlaneStrain : Formulation::ThreeD;
    const TwoBodies t = quadraticBodies(f, type, 3.0, 7);
    VolumeInteractionOptions o;
    o.formulation = f;
    VolumeInteraction vi(t.mesh, {1.0, 1.0}, makePotential("lennard-jones", 1.0, 0.3), o);
    const int d = t.mesh.dim, nn = mesh::nodesPerCell(type), steps = d == 2 ? 40 : 16;
    Real motion = 0.0;
    for (LocalIndex c = 0; c < t.mesh.numCells(); ++c) {
      Real lo[3], hi[3];
      vi.cellBox(c, t.mesh.coords.data(), lo, hi);
      const std::size_t block = c < t.mesh.blocks[0].numCells() ? 0 : 1;
      const LocalIndex local = block == 0 ? c : c - t.mesh.blocks[0].numCells();
      const LocalIndex* nodes = &t.mesh.blocks[block].connectivity[std::size_t(local) * nn];
      fem::withElement(type, [&](auto element) {
        using E = decltype(element);
        for (int i = 0; i <= steps; ++i)
          for (int j = 0; j <= steps; ++j)
            for (int k = 0; k <= (d == 3 ? steps : 0); ++k) {
              Real xi[E::dim];
              const int idx[3] = {i, j, k};
              Real sum = 0.0;
              for (int a = 0; a < E::dim; ++a) sum += xi[a] = cellTypeInfo(type).simplex ? Real(idx[a]) / steps
                                                                                           : -1.0 + 2.0 * idx[a] / steps;
              if (cellTypeInfo(type).simplex && sum > 1.0 + 1e-12) continue;
              Real N[E::numNodes], dN[E::numNodes][E::dim], x[3] = {0.0, 0.0, 0.0}, absSum = 0.0;
              E::shape(xi, N, dN);
              for (int a = 0; a < E::numNodes; ++a) {
                absSum += std::abs(N[a]);
                for (int q = 0; q < d; ++q) x[q] += N[a] * t.mesh.coords[std::size_t(d) * nodes[a] + q];
              }
              motion = std::max(motion, absSum);
              for (int q = 0; q < d; ++q) {
                EXPECT_GE(x[q], lo[q] - 1e-12) << "cell " << c;
                EXPECT_LE(x[q], hi[q] + 1e-12) << "cell " << c;
              }
            }
      });
    }
    EXPECT_LE(motion, vi.maxPointMotion() + 1e-12);
    EXPECT_GE(motion, vi.maxPointMotion() - 1e-2);
  }
}

TEST(VolumeInteraction, CurvedCellBeyondItsNodesBoxIsPaired) {
  // A Quad9 whose right edge runs through x = 1, 2, 2 (corner, mid-edge node, corner): the edge
  // x(t) = 1 + 3t - 2t^2 reaches 2.125 at t = 3/4, beyond its nodes' box (x <= 2). A square
  // 0.03 to its right (x >= 2.155) is 0.155 from that box, beyond cutoff + skin = 0.07, but
  // 0.03 from the cell, within the cutoff: the pair must be listed.
  mesh::Mesh m;
  m.dim = 2;
  m.numBodies = 2;
  const Real a[9][2] = {{0, 0}, {1, 0}, {2, 1}, {0, 1}, {0.5, 0}, {2, 0.5}, {1, 1}, {0, 0.5}, {1.0, 0.5}};
  const Real x0 = 2.155, b[9][2] = {{x0, 0},       {x0 + 1, 0},   {x0 + 1, 1},   {x0, 1},  {x0 + 0.5, 0},
                                    {x0 + 1, 0.5}, {x0 + 0.5, 1}, {x0, 0.5},     {x0 + 0.5, 0.5}};
  for (int body = 0; body < 2; ++body) {
    mesh::ElementBlock blk;
    blk.name = "body" + std::to_string(body);
    blk.body = body;
    blk.type = CellType::Quad9;
    for (int k = 0; k < 9; ++k) {
      blk.connectivity.push_back(m.numNodes());
      for (int i = 0; i < 2; ++i) m.coords.push_back(body == 0 ? a[k][i] : b[k][i]);
    }
    m.blocks.push_back(blk);
  }
  VolumeInteractionOptions o;
  o.formulation = Formulation::PlaneStrain;
  o.cutoff = 0.05;
  o.skin = 0.02;
  VolumeInteraction vi(m, {1.0, 1.0}, makePotential("lennard-jones", 1.0, 0.02), o);
  Real lo[3], hi[3];
  vi.cellBox(0, m.coords.data(), lo, hi);
  EXPECT_GE(hi[0], 2.125);
  ASSERT_TRUE(vi.updatePairs(m.coords.data()));
  EXPECT_EQ(vi.pairs().size(), 2u);  // both directions
  EXPECT_LT(vi.energy(m.coords.data()), 0.0);  // attraction across the 0.03 gap (r0 = 0.02)
}

/// Plane strain: the bottom of a ring (radii 0.5 .. 1 about (0, 1 + gap), polar angles within
/// 0.6 of straight down; nTheta x 2 cells) over a flat block (y in [-1, 0], |x| <= 1.2; 24 x 4
/// cells). Order 2: the ring's cells elevated with their arc nodes on the circles (a mid-edge
/// node of two nodes of one radius at that radius, half-way in angle). Returns the energy and
/// the vertical force on the ring, every pair integrated (no cutoff: nothing that depends on the
/// mesh but its geometry).
std::pair<Real, Real> ringOverBlock(int nTheta, bool quadratic, bool serendipity, Real r0, Real gap) {
  mesh::Mesh m;
  m.dim = 2;
  const Real blockOrigin[3] = {-1.2, -1.0, 0.0}, blockSize[3] = {2.4, 1.0, 0.0};
  const int blockCells[3] = {24, 4, 1};
  addBlock(m, 0, CellType::Quad4, blockOrigin, blockSize, blockCells, 0.0, 1);
  const Real cy = 1.0 + gap, half = 0.6;
  const LocalIndex first = m.numNodes();
  for (int j = 0; j <= 2; ++j)
    for (int i = 0; i <= nTheta; ++i) {
      const Real r = 0.5 + 0.25 * j, t = -0.5 * kPi - half + 2.0 * half * i / nTheta;
      m.coords.push_back(r * std::cos(t));
      m.coords.push_back(cy + r * std::sin(t));
    }
  mesh::ElementBlock ring;
  ring.name = "ring";
  ring.body = 1;
  ring.type = CellType::Quad4;
  auto id = [&](int i, int j) { return first + LocalIndex(j * (nTheta + 1) + i); };
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < nTheta; ++i)  // counter-clockwise: outer radius first (below)
      for (LocalIndex n : {id(i, j + 1), id(i + 1, j + 1), id(i + 1, j), id(i, j)}) ring.connectivity.push_back(n);
  m.blocks.push_back(ring);
  m.numBodies = 2;
  if (quadratic)
    mesh::elevate(m, serendipity, [&](LocalIndex a, LocalIndex b, Real* x) {
      const Real ax = m.coords[2 * a], ay = m.coords[2 * a + 1] - cy, bx = m.coords[2 * b], by = m.coords[2 * b + 1] - cy;
      const Real ra = std::hypot(ax, ay), rb = std::hypot(bx, by);
      if (a < first || b < first || std::abs(ra - rb) > 1e-12) return;  // block edges, radial edges: straight
      const Real t = 0.5 * (std::atan2(ay, ax) + std::atan2(by, bx));
      x[0] = ra * std::cos(t);
      x[1] = cy + ra * std::sin(t);
    });
  VolumeInteractionOptions o;
  o.formulation = Formulation::PlaneStrain;
  o.quadratureOrder = 4;
  o.cutoff = 1e3;
  VolumeInteraction vi(m, {1.0, 1.0}, makePotential("lennard-jones", 1.0, r0), o);
  vi.updatePairs(m.coords.data());
  assemble(vi, m.coords, false);
  return {vi.summary().energy, vi.summary().resultant[1][1]};
}

TEST(VolumeInteraction, QuadraticCellsOfACurvedBodyMatchAFinerLinearMesh) {
  // The ring's 8 cells per row: their chords (linear) cut a sag of R (1 - cos 0.075) = 2.8e-3 off
  // the arc, 3 % of r0, where the arc meets the block; the quadratic cells put the arc nodes on the
  // circle (the rest of the geometry, the block and the radial edges, is exact in both). Against
  // the linear mesh of 64 cells per row (a sag 64 times smaller) the quadratic cells are closer in
  // energy and in force by a factor 63 (measured; the linear ones: 2.4 % and 3.3 % off), asserted
  // 20: what is left is about the reference's own chord error, 1/64 of the linear cells'. (Quad8
  // and Quad9 agree: the Coons centre node is where the serendipity map puts the centre.)
  const Real r0 = 0.1, gap = 0.15;
  const auto reference = ringOverBlock(64, false, false, r0, gap), linear = ringOverBlock(8, false, false, r0, gap);
  for (bool serendipity : {false, true}) {
    SCOPED_TRACE(serendipity ? "QUAD8" : "QUAD9");
    const auto quadratic = ringOverBlock(8, true, serendipity, r0, gap);
    const Real linE = std::abs(linear.first - reference.first), quadE = std::abs(quadratic.first - reference.first);
    const Real linF = std::abs(linear.second - reference.second), quadF = std::abs(quadratic.second - reference.second);
    std::printf("energy %.8e linear %.8e quadratic %.8e; force %.8e linear %.8e quadratic %.8e\n", reference.first,
                linear.first, quadratic.first, reference.second, linear.second, quadratic.second);
    EXPECT_LT(20.0 * quadE, linE);
    EXPECT_LT(20.0 * quadF, linF);
  }
}

TEST(VolumeInteraction, QuadratureOfACellIntegratesItsVolume) {
  // far apart, psi is nearly constant over both cells: the energy is then
  // (beta1 V1)(beta2 V2) psi(distance of the centroids), whatever the cell types
  mesh::Mesh m;
  m.dim = 3;
  const Real o0[3] = {0, 0, 0}, s0[3] = {1, 1, 1}, o1[3] = {1000, 0, 0}, s1[3] = {2, 1, 1};
  const int c[3] = {1, 1, 1};
  addBlock(m, 0, CellType::Tet4, o0, s0, c, 0.0, 1);
  addBlock(m, 1, CellType::Hex8, o1, s1, c, 0.0, 2);
  VolumeInteractionOptions o;
  o.formulation = Formulation::ThreeD;
  o.cutoff = 1e4;
  auto pot = std::make_shared<RepulsiveLennardJones>(1.0, 1.0);
  VolumeInteraction vi(m, {1.0, 3.0}, pot, o);
  vi.updatePairs(m.coords.data());
  const Real e = vi.energy(m.coords.data());
  // distance between the centroids ~ 1000.5: energy ~ V1 V2 beta1 beta2 r^-12
  EXPECT_NEAR(e / (1.0 * 2.0 * 3.0 * std::pow(1000.5, -12)), 1.0, 1e-4);
}

TEST(VolumeInteraction, TetrahedronRuleIsSymmetric) {
  // a tetrahedron next to a box symmetric about x = 0: its mirror image in
  // x = 0, and any renumbering of its vertices, give the same energy only if
  // the quadrature points map onto each other
  const Real tet[4][3] = {{0.3, 0.1, 1.6}, {1.1, 0.2, 1.7}, {0.5, 0.9, 1.5}, {0.6, 0.4, 2.4}};
  auto energy = [&](const int order[4], Real sx) {
    mesh::Mesh m;
    m.dim = 3;
    const Real o1[3] = {-1.0, -0.5, 0.0}, s1[3] = {2.0, 1.5, 1.2};
    const int c[3] = {2, 2, 2};
    addBlock(m, 1, CellType::Hex8, o1, s1, c, 0.0, 1);
    mesh::ElementBlock b;
    b.body = 0;
    b.type = CellType::Tet4;
    for (int a = 0; a < 4; ++a) {
      b.connectivity.push_back(m.numNodes());
      for (int i = 0; i < 3; ++i) m.coords.push_back((i == 0 ? sx : 1.0) * tet[order[a]][i]);
    }
    m.blocks.push_back(b);
    VolumeInteractionOptions o;
    o.formulation = Formulation::ThreeD;
    o.cutoff = 1e3;
    o.quadratureOrder = 2;
    o.maxQuadratureOrder = 2;
    VolumeInteraction vi(m, {1.0, 1.0}, std::make_shared<LennardJones>(1.0, 0.4), o);
    vi.updatePairs(m.coords.data());
    return vi.energy(m.coords.data());
  };
  const int identity[4] = {0, 1, 2, 3}, even[4] = {1, 2, 0, 3}, odd[4] = {0, 2, 1, 3}, other[4] = {3, 1, 0, 2};
  const Real e = energy(identity, 1.0);
  EXPECT_NEAR(energy(even, 1.0), e, 1e-13 * std::abs(e));
  EXPECT_NEAR(energy(other, 1.0), e, 1e-13 * std::abs(e));
  EXPECT_NEAR(energy(odd, -1.0), e, 1e-13 * std::abs(e));  // the mirror image, positively oriented
}

TEST(VolumeInteraction, RowCellsSplitThePairsBetweenRanks) {
  // two "ranks" listing the pairs of alternate cells add up to one listing all;
  // a Tet4 pair stays within the tetrahedron rule's order
  TwoBodies t = twoBodies(Formulation::ThreeD, CellType::Tet4);
  VolumeInteractionOptions o;
  o.formulation = Formulation::ThreeD;
  o.cutoff = 1e3;
  auto pot = std::make_shared<LennardJones>(0.7, 0.3);
  VolumeInteraction all(t.mesh, {1.0, 1.0}, pot, o);
  ASSERT_TRUE(all.updatePairs(t.mesh.coords.data()));
  for (const VolumePair& p : all.pairs()) EXPECT_LE(p.order, kMaxTetOrder);
  const Assembled full = assemble(all, t.mesh.coords, true);
  std::vector<Real> sum(full.f.size(), 0.0);
  std::size_t listed = 0;
  for (int part = 0; part < 2; ++part) {
    VolumeInteraction mine(t.mesh, {1.0, 1.0}, pot, o);
    std::vector<char> rows(t.mesh.numCells());
    for (std::size_t c = 0; c < rows.size(); ++c) rows[c] = int(c % 2) == part;
    mine.setRowCells(rows);
    mine.updatePairs(t.mesh.coords.data());
    listed += mine.pairs().size();
    const Assembled a = assemble(mine, t.mesh.coords, false);
    for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += a.f[i];
  }
  EXPECT_EQ(listed, all.pairs().size());
  Real fmax = 0.0;
  for (Real v : full.f) fmax = std::max(fmax, std::abs(v));
  for (std::size_t i = 0; i < sum.size(); ++i) EXPECT_NEAR(sum[i], full.f[i], 1e-13 * fmax) << "dof " << i;
}

// ---- symmetric parts: image cells --------------------------------------

// The part x >= 0 (and y >= 0 in 3D) of a symmetric model of three bodies: two cut by the
// planes, one beside them that only y = 0 cuts (its image in x = 0 is another body of the whole
// model, which it interacts with). Jittered cells, the nodes on the planes kept on them.
mesh::Mesh symmetricPart(int dim) {
  mesh::Mesh m;
  m.dim = dim;
  const CellType type = dim == 3 ? CellType::Hex8 : CellType::Quad4;
  const int cells[3] = {2, 1, 2};
  const int planes = dim == 3 ? 2 : 1;  // x (and y)
  const Real o0[3] = {0.0, 0.0, 0.0}, s0[3] = {0.6, 0.5, 0.7};
  const Real o1[3] = {0.0, 0.85, 0.0}, s1[3] = {0.7, 0.6, 0.8};    // 2D: above along y
  const Real o1z[3] = {0.0, 0.0, 0.85};                              // 3D: above along z
  const Real o2[3] = {0.25, -0.7, 0.0}, o2z[3] = {0.25, 0.0, -0.65}, s2[3] = {0.3, 0.4, 0.4};
  addBlock(m, 0, type, o0, s0, cells, 0.08, 1);
  addBlock(m, 1, type, dim == 3 ? o1z : o1, s1, cells, 0.08, 2);
  addBlock(m, 2, type, dim == 3 ? o2z : o2, s2, cells, 0.08, 3);
  for (LocalIndex n = 0; n < m.numNodes(); ++n)
    for (int i = 0; i < planes; ++i)
      if (std::abs(m.coords[std::size_t(dim) * n + i]) < 0.1) m.coords[std::size_t(dim) * n + i] = 0.0;
  for (int i = 0; i < planes; ++i) {
    auto& set = m.nodeSets[std::string("symmetry ") + "xy"[i]];
    for (LocalIndex n = 0; n < m.numNodes(); ++n)
      if (m.coords[std::size_t(dim) * n + i] == 0.0) set.push_back(n);
  }
  mesh::buildSurfaces(m);
  return m;
}

// Method 1 on a symmetric part with image cells: the forces on its nodes are the whole (mirrored)
// model's to round-off (on a plane: their share), its energy the whole's over the number of images, its forces the gradient
// of its energy and its tangent their derivative (central differences).
void checkImagesActAsTheWholeModel(int dim) {
  const Formulation f = dim == 3 ? Formulation::ThreeD : Formulation::PlaneStrain;
  const mesh::Mesh part = symmetricPart(dim);
  mesh::Mesh whole = part;
  for (int i = 0; i < (dim == 3 ? 2 : 1); ++i) mesh::mirror(whole, i);
  ASSERT_EQ(whole.numBodies, 4);  // body 2 and its image in x = 0 are two
  VolumeInteractionOptions o;
  o.formulation = f;
  o.quadratureOrder = 2;
  o.quadratureTolerance = 0.0;  // the same rule for every pair of both models
  o.cutoff = 1e3;
  auto pot = std::make_shared<LennardJones>(0.7, 0.3);
  VolumeInteraction all(whole, std::vector<Real>(4, 1.0), pot, o);

  // the planes as the interaction set-up finds them from the node sets
  InteractionSetup setup;
  setup.method = Method::VolumePair;
  setup.potential = pot;
  setup.volumeOptions = o;
  setup.checkMesh(part, f);
  auto created = std::dynamic_pointer_cast<VolumeInteraction>(setup.create(part));
  ASSERT_TRUE(created);
  const int planes = dim == 3 ? 3 : 1;
  EXPECT_EQ(created->options().symmetryPlanes, planes);
  EXPECT_EQ(created->options().bodySymmetryPlanes, (std::vector<int>{planes, planes, planes & ~1}));
  VolumeInteraction& mine = *created;

  ASSERT_TRUE(mine.updatePairs(part.coords.data()));
  ASSERT_TRUE(all.updatePairs(whole.coords.data()));
  const Assembled a = assemble(mine, part.coords, true);
  const Assembled w = assemble(all, whole.coords, false);
  const Real images = dim == 3 ? 4.0 : 2.0;
  EXPECT_NEAR(images * mine.summary().energy, all.summary().energy, 1e-12 * std::abs(all.summary().energy));
  EXPECT_LT(all.summary().energy, 0.0);
  std::map<std::vector<Real>, LocalIndex> wholeNode;
  for (LocalIndex n = 0; n < whole.numNodes(); ++n)
    wholeNode[std::vector<Real>(whole.coords.begin() + dim * n, whole.coords.begin() + dim * (n + 1))] = n;
  Real fmax = 0.0;
  for (Real v : w.f) fmax = std::max(fmax, std::abs(v));
  for (LocalIndex n = 0; n < part.numNodes(); ++n) {
    const auto it = wholeNode.find(std::vector<Real>(part.coords.begin() + dim * n, part.coords.begin() + dim * (n + 1)));
    ASSERT_NE(it, wholeNode.end()) << "node " << n;
    // a node on k planes is its own image 2^k times: the whole model's force there is 2^k times the
    // part's in the planes, and 0 across them (the part's, there, meets the symmetry condition)
    Real multiplicity = 1.0;
    for (int i = 0; i < dim; ++i)
      if (planes & (1 << i) && part.coords[dim * n + i] == 0.0) multiplicity *= 2.0;
    for (int i = 0; i < dim; ++i) {
      const bool across = planes & (1 << i) && part.coords[dim * n + i] == 0.0;
      EXPECT_NEAR(across ? 0.0 : multiplicity * a.f[dim * n + i], w.f[dim * it->second + i], 1e-12 * fmax)
          << "node " << n << " component " << i;
    }
  }

  expectGradientAndTangent(mine, part.coords, a);
}

TEST(VolumeInteraction, ImageCellsActAsTheWholeModelInPlaneStrain) { checkImagesActAsTheWholeModel(2); }
TEST(VolumeInteraction, ImageCellsActAsTheWholeModelIn3D) { checkImagesActAsTheWholeModel(3); }

// The pair list's size, counted without building it, is the list's (images included); the count
// stops once past a memory limit.
TEST(VolumeInteraction, PairListSizeIsCountedBeforeTheListIsBuilt) {
  for (int dim : {2, 3}) {
    const mesh::Mesh part = symmetricPart(dim);
    VolumeInteractionOptions o;
    o.formulation = dim == 3 ? Formulation::ThreeD : Formulation::PlaneStrain;
    o.symmetryPlanes = dim == 3 ? 3 : 1;
    o.bodySymmetryPlanes = {o.symmetryPlanes, o.symmetryPlanes, o.symmetryPlanes & ~1};
    o.cutoff = 0.3;
    VolumeInteraction vi(part, {1.0, 1.0, 1.0}, std::make_shared<LennardJones>(0.7, 0.1), o);
    const auto size = vi.pairListSize(part.coords.data());
    ASSERT_TRUE(vi.updatePairs(part.coords.data()));
    EXPECT_EQ(size.pairs, double(vi.pairs().size()));
    EXPECT_GT(size.pairs, 0.0);
    EXPECT_FALSE(size.stopped);
    const double perCell = dim == 3 ? 64.0 : 16.0;
    EXPECT_EQ(size.couplings, perCell * size.pairs);
    EXPECT_GT(size.megabytes, 0.0);
  }
}

TEST(VolumeInteraction, SymmetricPartMustLieOnThePositiveSide) {
  mesh::Mesh part = symmetricPart(3);
  InteractionSetup setup;
  setup.method = Method::VolumePair;
  setup.potential = std::make_shared<LennardJones>(0.7, 0.3);
  setup.volumeOptions.formulation = Formulation::ThreeD;
  setup.volumeOptions.quadratureTolerance = 0.0;
  auto errorOf = [&](const mesh::Mesh& m) {
    try {
      setup.checkMesh(m, Formulation::ThreeD);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no InputError");
  };
  EXPECT_EQ(errorOf(part), "no InputError");
  mesh::Mesh across = part;
  across.coords[3 * 5 + 0] = -0.01;  // node 5 on the other side of x = 0
  EXPECT_NE(errorOf(across).find("\"symmetry x\""), std::string::npos) << errorOf(across);
  EXPECT_NE(errorOf(across).find("node 5 has x = -0.01"), std::string::npos) << errorOf(across);
  mesh::Mesh offPlane = part;
  offPlane.nodeSets["symmetry y"].push_back(LocalIndex(offPlane.numNodes() - 1));  // a node at y > 0
  EXPECT_NE(errorOf(offPlane).find("the part y >= 0"), std::string::npos) << errorOf(offPlane);
}

TEST(VolumeInteraction, RejectsBadInput) {
  TwoBodies t = twoBodies(Formulation::PlaneStrain, CellType::Quad4);
  auto pot = std::make_shared<LennardJones>(1.0, 0.3);
  VolumeInteractionOptions o;
  o.formulation = Formulation::ThreeD;
  EXPECT_THROW(VolumeInteraction(t.mesh, {1.0, 1.0}, pot, o), InputError);
  o.formulation = Formulation::PlaneStrain;
  EXPECT_THROW(VolumeInteraction(t.mesh, {1.0}, pot, o), InputError);
  o.quadratureOrder = 0;
  EXPECT_THROW(VolumeInteraction(t.mesh, {1.0, 1.0}, pot, o), InputError);
  o.quadratureOrder = 2;
  o.maxQuadratureOrder = kMaxVolumeOrder2D + 1;
  EXPECT_THROW(VolumeInteraction(t.mesh, {1.0, 1.0}, pot, o), InputError);
}

TEST(VolumeInteraction, PairListIsKeptWhileNodesMoveLessThanHalfTheSkin) {
  TwoBodies t = twoBodies(Formulation::PlaneStrain, CellType::Quad4);
  VolumeInteractionOptions o;
  o.formulation = Formulation::PlaneStrain;
  o.cutoff = 0.3;
  o.skin = 0.2;
  VolumeInteraction vi(t.mesh, {1.0, 1.0}, std::make_shared<LennardJones>(1.0, 0.1), o);
  std::vector<Real> x = t.mesh.coords;
  EXPECT_TRUE(vi.updatePairs(x.data()));
  x[1] += 0.09;
  EXPECT_FALSE(vi.updatePairs(x.data()));
  x[1] += 0.02;
  EXPECT_TRUE(vi.updatePairs(x.data()));
  EXPECT_EQ(vi.summary().numListBuilds, 2);
}

// ---- two flat blocks: the half-space traction ---------------------------

/// Plane strain: body 0 below y = 0, body 1 above y = gap, both `width`
/// wide and deep enough for the cutoff, with cells of width `cell` r0 graded
/// in depth from cell / 2. Returns the traction on body 1 measured on its
/// central column of nodes.
Real blockTraction(Real gap, Real r0, Real cutoff, int order, int maxOrder,
                   const std::string& potential = "lennard-jones", Real cell = 0.5) {
  mesh::Mesh m;
  m.dim = 2;
  m.numBodies = 2;
  const Real dx = cell * r0, width = 2.0 * (cutoff + 3.0 * r0);
  const int nx = int(std::round(width / dx));
  std::vector<Real> depths = {0.0};
  for (Real h = 0.5 * cell * r0; depths.back() < cutoff + 2.0 * r0; h *= 1.5) depths.push_back(depths.back() + h);
  for (int body = 0; body < 2; ++body) {
    const LocalIndex first = m.numNodes();
    for (std::size_t j = 0; j < depths.size(); ++j)
      for (int i = 0; i <= nx; ++i) {
        m.coords.push_back(i * dx);
        m.coords.push_back(body == 0 ? -depths[j] : gap + depths[j]);
      }
    mesh::ElementBlock b;
    b.body = body;
    b.name = "block" + std::to_string(body);
    auto id = [&](int i, std::size_t j) { return first + LocalIndex(j * (nx + 1) + i); };
    for (std::size_t j = 0; j + 1 < depths.size(); ++j)
      for (int i = 0; i < nx; ++i) {
        // counter-clockwise in both bodies
        if (body == 0)
          for (LocalIndex n : {id(i, j + 1), id(i + 1, j + 1), id(i + 1, j), id(i, j)}) b.connectivity.push_back(n);
        else
          for (LocalIndex n : {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}) b.connectivity.push_back(n);
      }
    m.blocks.push_back(b);
  }
  VolumeInteractionOptions o;
  o.formulation = Formulation::PlaneStrain;
  o.cutoff = cutoff;
  o.quadratureOrder = order;
  o.maxQuadratureOrder = maxOrder;
  VolumeInteraction vi(m, {1.0, 1.0}, makePotential(potential, 1.0, r0), o);
  vi.updatePairs(m.coords.data());
  const Assembled a = assemble(vi, m.coords, false);
  // body 1's central column of nodes carries the traction over one cell width
  const LocalIndex firstUpper = LocalIndex((nx + 1) * depths.size());
  Real fy = 0.0;
  for (std::size_t j = 0; j < depths.size(); ++j) fy += a.f[2 * (firstUpper + j * (nx + 1) + nx / 2) + 1];
  return fy / dx;  // force per area on body 1 (positive: pulled towards body 0 is fy > 0 in f = dPi/dx)
}

TEST(VolumeInteraction, FlatBlocksReproduceTheHalfSpaceTraction) {
  const Real r0 = 1.0;
  LennardJones lj(1.0, r0);
  const Real sigmaMax = lj.peakTraction(1.0, 1.0);
  // measured: errors of 0.7e-3, 1.7e-3, 1.6e-3 sigma_max, nearly all from the
  // cutoff (15 r0 leaves 0.6e-3; orders 4 and 6 at 15 r0 agree to 2e-6)
  for (Real gap : {0.7, 1.0, 1.5}) {
    // f = dPi/dx on body 1's nodes: the traction pulling it up is -f; T > 0 repels
    const Real T = blockTraction(gap, r0, 10.0 * r0, 2, 8), exact = lj.traction(gap, 1.0, 1.0);
    EXPECT_NEAR(-T, exact, 2.5e-3 * sigmaMax) << "gap " << gap;
  }
}

TEST(VolumeInteraction, CloseCellsOfR0AreIntegratedToTheHalfSpaceTraction) {
  // The default orders (base 2, each pair raised to Volume Quadrature Tolerance 1e-4 by the error
  // estimate, up to the kernel's 12) on surface cells of r0 and 2 r0, where the r^-12 repulsion
  // varies much within a cell. Against the half-space law the error is the cutoff's (1.3e-3 ..
  // 1.7e-3 sigma_max; it depends on the cell size because the cutoff acts on the cells'
  // bounding boxes); against orders 10-12 on every pair of the same mesh, at the closest gap, it
  // is the quadrature's: within 1e-5 sigma_max (the size rule with one extra point per size over
  // gap, of earlier versions: 1.4e-2 on cells of 2 r0).
  const Real r0 = 1.0;
  LennardJones lj(1.0, r0);
  const Real sigmaMax = lj.peakTraction(1.0, 1.0);
  for (Real cell : {1.0, 2.0}) {
    for (Real gap : {0.7, 1.0, 1.5}) {
      const Real T = blockTraction(gap, r0, 10.0 * r0, 2, 0, "lennard-jones", cell), exact = lj.traction(gap, 1.0, 1.0);
      EXPECT_NEAR(-T, exact, 2.5e-3 * sigmaMax) << "cell " << cell << " r0, gap " << gap;
    }
    const Real T = blockTraction(0.7, r0, 10.0 * r0, 2, 0, "lennard-jones", cell),
               converged = blockTraction(0.7, r0, 10.0 * r0, 10, 12, "lennard-jones", cell);
    EXPECT_NEAR(T, converged, 1e-5 * sigmaMax) << "cell " << cell << " r0";
  }
}

TEST(VolumeInteraction, MorseFlatBlocksReproduceItsHalfSpaceTraction) {
  // the volume integral of Method 1 against the closed-form half-space law
  // of Method 3, both from MorsePair (an exponential tail: a 6 r0 cutoff
  // leaves less than 1e-9)
  const Real r0 = 1.0;
  const auto morse = makePotential("morse", 1.0, r0);
  const Real sigmaMax = morse->peakTraction(1.0, 1.0);
  for (Real gap : {0.7, 1.0, 1.5}) {
    const Real T = blockTraction(gap, r0, 6.0 * r0, 2, 8, "morse"), exact = morse->traction(gap, 1.0, 1.0);
    EXPECT_NEAR(-T, exact, 1e-3 * sigmaMax) << "gap " << gap;
  }
}

TEST(VolumeInteraction, WorkOfAdhesionLostToThePairCutoff) {
  // Lennard-Jones phi = eps ((r0/r)^12 - 2 (r0/r)^6): pi integral_{rc}^inf r (r - g)^2 phi dr in
  // closed form, each power r^-k contributing [rc^(2-k)/(k-2) - 2 g rc^(1-k)/(k-1) + g^2 rc^(-k)/k].
  const LennardJones lj(1.0, 1.0);
  const Real w = lj.adhesionWorkCoefficient(), g = *lj.surfaceEquilibriumDistance();
  auto power = [g](Real rc, int k) {
    return std::pow(rc, 2 - k) / (k - 2) - 2.0 * g * std::pow(rc, 1 - k) / (k - 1) + g * g * std::pow(rc, -k) / k;
  };
  for (Real rc : {5.0, 10.0, 20.0, 30.0}) {
    const Real exact = -kPi * (power(rc, 10) - 2.0 * power(rc, 4)) / w;
    // Simpson on 400 intervals of t = rc / r: the integrand is a polynomial in t of degree 11
    EXPECT_NEAR(pairCutoffWorkFraction(lj, rc), exact, 1e-9 * exact) << "rc = " << rc;
  }
  // about (pi/rc^2)(1 - 4 g/(3 rc)) of w: 3.0 % at 10 r0; five to six times the half-space law's own loss at the same cutoff
  EXPECT_NEAR(pairCutoffWorkFraction(lj, 10.0), 0.0297, 1e-4);
  EXPECT_EQ(pairCutoffWorkFraction(RepulsiveLennardJones(1.0, 1.0), 10.0), 0.0);
  EXPECT_EQ(pairCutoffWorkFraction(lj, std::numeric_limits<Real>::infinity()), 0.0);
}

}  // namespace
}  // namespace cgcm::interaction

namespace cgcm::interaction {
namespace {

// Two facing squares of edge h, g apart (plane strain), each split into k x k cells: the resultant
// on the upper square's part of the pair integral, split into its repulsive and attractive parts.
struct PairForce {
  Real repulsive, attractive;
};
PairForce squarePairForce(Real h, Real g, int k, int order) {
  mesh::Mesh m;
  m.dim = 2;
  m.numBodies = 2;
  for (int body = 0; body < 2; ++body) {
    const LocalIndex first = m.numNodes();
    const Real y0 = body == 0 ? -h : g;
    for (int j = 0; j <= k; ++j)
      for (int i = 0; i <= k; ++i) {
        m.coords.push_back(h * i / k);
        m.coords.push_back(y0 + h * j / k);
      }
    mesh::ElementBlock b;
    b.body = body;
    b.name = "square" + std::to_string(body);
    for (int j = 0; j < k; ++j)
      for (int i = 0; i < k; ++i)
        for (int c : {j * (k + 1) + i, j * (k + 1) + i + 1, (j + 1) * (k + 1) + i + 1, (j + 1) * (k + 1) + i})
          b.connectivity.push_back(first + c);
    m.blocks.push_back(b);
  }
  VolumeInteractionOptions o;
  o.formulation = Formulation::PlaneStrain;
  o.quadratureOrder = order;
  o.maxQuadratureOrder = order;
  o.quadratureTolerance = 0.0;  // every pair at `order`
  o.cutoff = 100.0;
  auto force = [&](std::shared_ptr<const PairPotential> p) {
    VolumeInteraction vi(m, {1.0, 1.0}, p, o);
    vi.updatePairs(m.coords.data());
    vi.evaluate(m.coords.data(), [](const auto&, long) {}, false);
    return vi.summary().resultant[1][1];
  };
  const Real rep = force(std::make_shared<RepulsiveLennardJones>(1.0, 1.0));
  return {rep, force(std::make_shared<LennardJones>(1.0, 1.0)) - rep};
}

// The error estimate that sets each pair's order (volumeQuadratureError) against the error of the
// rule measured on one pair of facing squares at the contact gap (0.6 r0) and at 1.5 r0, with
// edges of 1 and 2 gaps: the force at order n against the same squares split into 6 x 6 cells at
// order 12 (each sub-pair then has h/g <= 1/3: converged to 1e-12), relative to the larger part.
// The estimate is an upper bound (it is the envelope of the same measurement on the r^-12 and
// r^-6 parts alone, taken in the ratio of the half-space tractions) and not a loose one: within a
// factor 30 of the measured error wherever that is above round-off (measured ratios 1.0-12).
TEST(VolumeQuadrature, EstimateBoundsTheMeasuredErrorOfOnePair) {
  for (Real g : {0.6, 1.5})
    for (Real tau : {1.0, 2.0}) {
      const Real h = tau * g;
      const PairForce ref = squarePairForce(h, g, 6, 12);
      const Real scale = std::max(std::abs(ref.repulsive), std::abs(ref.attractive));
      for (int n : {3, 5, 7, 9, 11}) {
        const PairForce f = squarePairForce(h, g, 1, n);
        const Real measured =
            std::abs(f.repulsive + f.attractive - ref.repulsive - ref.attractive) / scale;
        const Real estimate = volumeQuadratureError(2, n, h, g, 1.0);
        std::printf("[estimate] g = %.1f r0, h/g = %.0f, order %2d: measured %.2e, estimate %.2e (ratio %.1f)\n", g,
                    tau, n, measured, estimate, estimate / std::max(measured, 1e-300));
        EXPECT_LE(measured, estimate) << "g " << g << " h/g " << tau << " order " << n;
        if (measured > 1e-12) {
          EXPECT_LE(estimate, 100.0 * measured) << "g " << g << " h/g " << tau << " order " << n;
        }
      }
    }
}


// A base order above what a tetrahedron's rule holds (kMaxTetOrder on each of its sub-hexahedra) is
// capped for tetrahedra, with the error estimate on or off: no pair asks for more points than the
// kernel holds, and the forces are those of the capped order.
TEST(VolumeInteraction, TetrahedraCapTheBaseOrder) {
  const TwoBodies t = twoBodies(Formulation::ThreeD, CellType::Tet4);
  auto forces = [&](int order, Real tolerance) {
    VolumeInteractionOptions o;
    o.formulation = Formulation::ThreeD;
    o.quadratureOrder = order;
    o.quadratureTolerance = tolerance;
    o.cutoff = 1e3;  // every pair
    VolumeInteraction vi(t.mesh, {1.2, 0.9}, makePotential("lennard-jones", 0.7, 0.3), o);
    std::vector<Real> x = t.mesh.coords;
    EXPECT_TRUE(vi.updatePairs(x.data()));
    EXPECT_LE(vi.summary().maxOrderUsed, kMaxTetOrder) << order << " " << tolerance;
    assemble(vi, x, false);
    return vi.summary().resultant[0];
  };
  const auto capped = forces(kMaxTetOrder, 0.0);
  for (Real tolerance : {0.0, 1e-4}) {
    const auto above = forces(6, tolerance);
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(above[i], capped[i], 1e-12 * (std::abs(capped[i]) + 1e-300)) << tolerance;
  }
}

}  // namespace
}  // namespace cgcm::interaction
