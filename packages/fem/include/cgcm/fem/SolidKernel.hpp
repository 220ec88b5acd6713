#pragma once
// Updated-Lagrangian solid element kernel: internal force, consistent tangent,
// strain energy and averaged stress of one element, for one (formulation ×
// element type) pair chosen at compile time.
//
// Notation at a quadrature point (current configuration):
//   g_a = ∂N_a/∂x (dim components), h_a = N_a / r (axisymmetric hoop term),
//   σ the Cauchy stress, c = λ' I⊗I + 2μ' 𝕀^sym its spatial moduli
//   (material::IsotropicModuli), dv the current volume weight
//   (detJ_x · w, times 2π r in axisymmetry).
// The virtual displacement gradient of node a in direction i is the 3×3 tensor
//   G_ai = e_i ⊗ g_a   (+ h_a e_θ⊗e_θ when i = r, axisymmetric),
// so that
//   f_ai = ∫ σ : G_ai dv = ∫ (σ g_a)_i dv  (+ ∫ σ_θθ h_a dv for i = r),
//   K_ai,bk = ∫ [ G_ai : c : G_bk + G_ai : (G_bk σ) ] dv
//           = ∫ [ λ' t_ai t_bk + μ' (δ_ik g_a·g_b + g_ak g_bi) + δ_ik g_a·σ·g_b
//                 + δ_ir δ_kr h_a h_b (2μ' + σ_θθ) ] dv,
// with t_ai = g_ai + δ_ir h_a (the trace of G_ai). This is the exact
// linearisation of f (the change of dv, including the 2π r factor, is
// contained in the spatial form); K is symmetric. Element DOFs are node-major:
// dof = a*dim + i.
//
// Small strain (mat.kinematics == SmallStrain): the same expressions on the
// reference configuration (g_a = ∂N_a/∂X, h_a = N_a / R, dV), with the
// linear stress σ = c : ε and c = (Λ, μ); the geometric term G_ai : (G_bk σ)
// is absent, so K is constant.
//
// Precision. Each kernel takes the nodal displacements u beside the current
// coordinates x = X + u (the forms without u take u = x − X). The stress is
// formed from the displacement gradient H = ∂u/∂X (F = I + H), not from
// x − X: near F = I its rounding is then relative to σ, not to the modulus,
// so a body 1e6 times stiffer than its neighbour keeps a residual floor far
// below the force tolerance (doc/theory.md, "Stiffness contrast").
//
// The kernels return false, leaving their outputs unspecified, when the
// reference or current element Jacobian determinant, J = det F or (in
// axisymmetry) the reference or current radius is <= 0 at a quadrature point.
#include <Kokkos_Macros.hpp>

#include "cgcm/core/SmallTensor.hpp"
#include "cgcm/core/Types.hpp"
#include "cgcm/fem/Elements.hpp"
#include "cgcm/fem/Formulation.hpp"
#include "cgcm/material/NeoHookean.hpp"

namespace cgcm::fem {

template <class Formulation, class Element>
struct SolidKernel {
  static_assert(Formulation::dim == Element::dim, "element and formulation dimensions differ");

  using FormulationType = Formulation;
  using ElementType = Element;

  static constexpr int dim = Formulation::dim;
  static constexpr int numNodes = Element::numNodes;
  static constexpr int numQp = Element::numQp;
  static constexpr int numDofs = numNodes * dim;
  static constexpr bool axisymmetric = Formulation::axisymmetric;

  using Coordinates = Real[numNodes][dim];
  using Vector = Real[numDofs];
  using Matrix = Real[numDofs][numDofs];

  /// Kinematics at one quadrature point.
  struct PointKinematics {
    Real N[numNodes];        ///< shape functions
    Real g[numNodes][dim];   ///< gradients ∂N_a/∂x (∂N_a/∂X on the reference; filled only when requested)
    Real invR;               ///< 1/r (1/R on the reference) at the point (axisymmetric), else 0
    Mat3 H;                  ///< displacement gradient ∂u/∂X (3×3; H₃₃ = 0 or u_r/R in 2D)
    Mat3 F;                  ///< deformation gradient I + H
    Real J;                  ///< det F
    Real dv;                 ///< current volume weight of the point (reference on the reference)
    Real dV;                 ///< reference volume weight of the point
  };

  /// Kinematics at quadrature point q. With withGradients = false the
  /// gradients g are not computed (energy, stress output). With onReference
  /// (small strain) g, invR and dv are those of the reference configuration.
  /// Returns false for a degenerate or inverted point.
  template <bool withGradients>
  KOKKOS_INLINE_FUNCTION static bool kinematics(int q, const Coordinates& X, const Coordinates& x,
                                                const Coordinates& u, PointKinematics& k,
                                                bool onReference = false) {
    Real dN[numNodes][dim];
    Real w;
    Element::shapeAtQp(q, k.N, dN, w);

    // Reference and current Jacobians ∂X/∂ξ, ∂x/∂ξ, and ∂u/∂ξ.
    Mat<dim> JX = Mat<dim>::zero();
    Mat<dim> Jx = Mat<dim>::zero();
    Mat<dim> Ju = Mat<dim>::zero();
    for (int a = 0; a < numNodes; ++a)
      for (int i = 0; i < dim; ++i)
        for (int j = 0; j < dim; ++j) {
          JX.a[i][j] += X[a][i] * dN[a][j];
          Jx.a[i][j] += x[a][i] * dN[a][j];
          Ju.a[i][j] += u[a][i] * dN[a][j];
        }
    const Real detJX = det(JX);
    const Real detJx = det(Jx);
    if (!(detJX > 0.0) || !(detJx > 0.0)) return false;

    // In-plane (or full 3D) displacement gradient H = Ju JX⁻¹, F = I + H.
    const Mat<dim> Hd = Ju * inverse(JX, detJX);
    k.H = Mat3::zero();
    for (int i = 0; i < dim; ++i)
      for (int j = 0; j < dim; ++j) k.H.a[i][j] = Hd.a[i][j];

    if constexpr (axisymmetric) {
      Real R = 0.0, r = 0.0, ur = 0.0;
      for (int a = 0; a < numNodes; ++a) {
        R += k.N[a] * X[a][0];
        r += k.N[a] * x[a][0];
        ur += k.N[a] * u[a][0];
      }
      if (!(R > 0.0) || !(r > 0.0)) return false;
      k.H.a[2][2] = ur / R;  // F₃₃ − 1 = (r − R)/R
      k.invR = 1.0 / r;
      k.dV = Formulation::ringFactor * R * detJX * w;
      k.dv = Formulation::ringFactor * r * detJx * w;
    } else {
      k.invR = 0.0;
      k.dV = detJX * w;
      k.dv = detJx * w;
    }
    k.F = k.H;
    for (int i = 0; i < 3; ++i) k.F.a[i][i] += 1.0;
    k.J = 1.0 + material::NeoHookean::detOfIdentityPlusMinusOne(k.H);
    if (!(k.J > 0.0)) return false;
    if (onReference) {
      k.dv = k.dV;
      if constexpr (axisymmetric) k.invR = k.F.a[2][2] * k.invR;  // r/R · 1/r
    }

    if constexpr (withGradients) {
      // g_a = Jx⁻ᵀ ∂N_a/∂ξ (JX on the reference)
      const Mat<dim> iJx = onReference ? inverse(JX, detJX) : inverse(Jx, detJx);
      for (int a = 0; a < numNodes; ++a)
        for (int i = 0; i < dim; ++i) {
          Real s = 0.0;
          for (int j = 0; j < dim; ++j) s += iJx.a[j][i] * dN[a][j];
          k.g[a][i] = s;
        }
    }
    return true;
  }

  /// σ at the point from the displacement gradient: Neo-Hookean Cauchy
  /// stress, or the small-strain stress.
  KOKKOS_INLINE_FUNCTION static Mat3 stress(const material::NeoHookean& mat, const PointKinematics& k) {
    if (mat.kinematics == material::Kinematics::SmallStrain) return mat.linearStressOfDisplacementGradient(k.H);
    return mat.cauchyOfDisplacementGradient(k.H);
  }

  /// u = x − X, for the forms that take only X and x.
  KOKKOS_INLINE_FUNCTION static void displacementOf(const Coordinates& X, const Coordinates& x, Coordinates& u) {
    for (int a = 0; a < numNodes; ++a)
      for (int i = 0; i < dim; ++i) u[a][i] = x[a][i] - X[a][i];
  }

  KOKKOS_INLINE_FUNCTION static bool residual(const Coordinates& X, const Coordinates& x,
                                              const material::NeoHookean& mat, Vector& f) {
    Coordinates u;
    displacementOf(X, x, u);
    return residual(X, x, u, mat, f);
  }

  /// Internal force f = ∫ B_ULᵀ σ dv.
  KOKKOS_INLINE_FUNCTION static bool residual(const Coordinates& X, const Coordinates& x, const Coordinates& u,
                                              const material::NeoHookean& mat, Vector& f) {
    for (int d = 0; d < numDofs; ++d) f[d] = 0.0;
    const bool small = mat.kinematics == material::Kinematics::SmallStrain;
    for (int q = 0; q < numQp; ++q) {
      PointKinematics k;
      if (!kinematics<true>(q, X, x, u, k, small)) return false;
      const Mat3 sigma = stress(mat, k);
      for (int a = 0; a < numNodes; ++a) {
        for (int i = 0; i < dim; ++i) {
          Real s = 0.0;
          for (int j = 0; j < dim; ++j) s += sigma.a[i][j] * k.g[a][j];
          f[a * dim + i] += k.dv * s;
        }
        if constexpr (axisymmetric) f[a * dim] += k.dv * sigma.a[2][2] * k.N[a] * k.invR;
      }
    }
    return true;
  }

  KOKKOS_INLINE_FUNCTION static bool residualAndTangent(const Coordinates& X, const Coordinates& x,
                                                        const material::NeoHookean& mat, Vector& f,
                                                        Matrix& K) {
    Coordinates u;
    displacementOf(X, x, u);
    return residualAndTangent(X, x, u, mat, f, K);
  }

  /// Internal force and its consistent (material + geometric) tangent K = ∂f/∂x.
  KOKKOS_INLINE_FUNCTION static bool residualAndTangent(const Coordinates& X, const Coordinates& x,
                                                        const Coordinates& u, const material::NeoHookean& mat,
                                                        Vector& f, Matrix& K) {
    for (int d = 0; d < numDofs; ++d) f[d] = 0.0;
    for (int d = 0; d < numDofs; ++d)
      for (int e = 0; e < numDofs; ++e) K[d][e] = 0.0;

    const bool small = mat.kinematics == material::Kinematics::SmallStrain;
    const Real geometric = small ? 0.0 : 1.0;  // the geometric (initial-stress) term's weight
    for (int q = 0; q < numQp; ++q) {
      PointKinematics k;
      if (!kinematics<true>(q, X, x, u, k, small)) return false;
      const Mat3 sigma = stress(mat, k);
      const material::IsotropicModuli c =
          small ? material::IsotropicModuli{mat.lambda, mat.mu} : mat.spatialModuli(k.J);
      const Real dv = k.dv;
      const Real lam = c.lambdaEff * dv;
      const Real mu = c.muEff * dv;

      // Per node: σ g_a dv (force), (μ' dv I + σ dv) g_a (diagonal term of the
      // blocks), λ' dv t_a and μ' dv g_a (rank-one terms).
      Real sg[numNodes][dim];
      Real wg[numNodes][dim];
      Real lt[numNodes][dim];
      Real t[numNodes][dim];
      Real mg[numNodes][dim];
      Real h[numNodes];
      for (int a = 0; a < numNodes; ++a) {
        for (int i = 0; i < dim; ++i) {
          Real s = 0.0;
          for (int j = 0; j < dim; ++j) s += sigma.a[i][j] * k.g[a][j];
          sg[a][i] = dv * s;
          wg[a][i] = geometric * sg[a][i] + mu * k.g[a][i];
          t[a][i] = k.g[a][i];
          mg[a][i] = mu * k.g[a][i];
        }
        if constexpr (axisymmetric) {
          h[a] = k.N[a] * k.invR;
          t[a][0] += h[a];
        } else {
          h[a] = 0.0;
        }
        for (int i = 0; i < dim; ++i) lt[a][i] = lam * t[a][i];
        for (int i = 0; i < dim; ++i) f[a * dim + i] += sg[a][i];
        if constexpr (axisymmetric) f[a * dim] += dv * sigma.a[2][2] * h[a];
      }
      const Real hoopCoef = axisymmetric ? (2.0 * mu + geometric * dv * sigma.a[2][2]) : 0.0;

      // Upper block triangle b >= a; the lower one is mirrored after the loop.
      for (int a = 0; a < numNodes; ++a) {
        for (int b = a; b < numNodes; ++b) {
          Real s = 0.0;
          for (int i = 0; i < dim; ++i) s += k.g[a][i] * wg[b][i];
          for (int i = 0; i < dim; ++i) {
            Real* Krow = &K[a * dim + i][b * dim];
            for (int m = 0; m < dim; ++m) Krow[m] += lt[a][i] * t[b][m] + mg[a][m] * k.g[b][i];
            Krow[i] += s;
          }
          if constexpr (axisymmetric) K[a * dim][b * dim] += hoopCoef * h[a] * h[b];
        }
      }
    }

    for (int a = 0; a < numNodes; ++a)
      for (int b = a + 1; b < numNodes; ++b)
        for (int i = 0; i < dim; ++i)
          for (int m = 0; m < dim; ++m) K[b * dim + m][a * dim + i] = K[a * dim + i][b * dim + m];
    return true;
  }

  /// Strain energy ∫ W dV over the reference element (2π R dA in axisymmetry);
  /// residual() is its derivative with respect to x.
  KOKKOS_INLINE_FUNCTION static bool energy(const Coordinates& X, const Coordinates& x,
                                            const material::NeoHookean& mat, Real& W) {
    Coordinates u;
    displacementOf(X, x, u);
    W = 0.0;
    for (int q = 0; q < numQp; ++q) {
      PointKinematics k;
      if (!kinematics<false>(q, X, x, u, k)) return false;
      W += (mat.kinematics == material::Kinematics::SmallStrain ? mat.linearEnergy(k.F) : mat.energy(k.F)) * k.dV;
    }
    return true;
  }

  KOKKOS_INLINE_FUNCTION static bool averageStress(const Coordinates& X, const Coordinates& x,
                                                   const material::NeoHookean& mat, Mat3& sigma, Real& J) {
    Coordinates u;
    displacementOf(X, x, u);
    return averageStress(X, x, u, mat, sigma, J);
  }

  /// Cauchy stress and J, each the plain mean over the element's quadrature points (for output).
  KOKKOS_INLINE_FUNCTION static bool averageStress(const Coordinates& X, const Coordinates& x, const Coordinates& u,
                                                   const material::NeoHookean& mat, Mat3& sigma, Real& J) {
    sigma = Mat3::zero();
    J = 0.0;
    for (int q = 0; q < numQp; ++q) {
      PointKinematics k;
      if (!kinematics<false>(q, X, x, u, k)) return false;
      const Mat3 s = stress(mat, k);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) sigma.a[i][j] += s.a[i][j];
      J += k.J;
    }
    const Real inv = 1.0 / numQp;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) sigma.a[i][j] *= inv;
    J *= inv;
    return true;
  }
};

/// The element kernels the code uses.
using PlaneStrainQuad4 = SolidKernel<PlaneStrain, Quad4>;
using AxisymmetricQuad4 = SolidKernel<Axisymmetric, Quad4>;
using ThreeDHex8 = SolidKernel<ThreeD, Hex8>;
using ThreeDTet4 = SolidKernel<ThreeD, Tet4>;

}  // namespace cgcm::fem
