#pragma once
// Compressible Neo-Hookean material (doc/theory.md#bulk):
//
//   W(F) = U(J) + μ/2 (I1 − 3) − μ ln J,   I1 = tr(Fᵀ F),  J = det F,
//
// with one of two volumetric laws U(J):
//
//   LogSquared (default, Bonet–Wood):  U = (Λ/2) (ln J)²
//       τ = J σ = Λ ln J I + μ (b − I)
//   QuadraticJ:                        U = (Λ/4) (J² − 1 − 2 ln J)
//       τ = J σ = (Λ/2)(J² − 1) I + μ (b − I)
//
// b = F Fᵀ. Both reduce to linear elasticity with Lamé constants (Λ, μ) at
// small strain.
//
// Spatial tangent. With p(J) := J U'(J) (so τ = p I + μ (b − I)), the
// Truesdell (Oldroyd) rate of τ is
//
//   τ̇ − l τ − τ lᵀ = J (dp/dJ) tr(d) I + 2 (μ − p) d ,
//
// since J̇ = J tr(d), ḃ = l b + b lᵀ. Hence c_τ = J p' I⊗I + 2 (μ − p) 𝕀^sym
// and the spatial moduli of the Cauchy stress c = c_τ / J are isotropic:
//
//   LogSquared: p = Λ ln J,       J p' = Λ     → λ' = Λ / J,  μ' = (μ − Λ ln J) / J
//   QuadraticJ: p = (Λ/2)(J²−1),  J p' = Λ J²  → λ' = Λ J,    μ' = (μ − (Λ/2)(J² − 1)) / J
//
// Small strain. With kinematics = SmallStrain the same constants describe
// the model linearised about the reference configuration: linear elasticity,
// σ = Λ tr(ε) I + 2μ ε with ε = sym(F) − I, equilibrium written on the
// reference configuration (fem::SolidKernel). Comparing the two isolates
// what finite strain changes in a result.
//
// Evaluation functions take no allocation and are usable inside Kokkos
// kernels; the factories validate their input on the host and throw
// cgcm::InputError.
#include <Kokkos_Macros.hpp>
#include <cmath>
#include <sstream>
#include <string>

#include "cgcm/core/Error.hpp"
#include "cgcm/core/SmallTensor.hpp"
#include "cgcm/core/Types.hpp"

namespace cgcm::material {

/// Volumetric part U(J) of the Neo-Hookean energy.
enum class VolumetricLaw {
  LogSquared,  ///< U = (Λ/2)(ln J)²            (default)
  QuadraticJ   ///< U = (Λ/4)(J² − 1 − 2 ln J)
};

/// Name of a volumetric law as used in input decks and output.
inline const char* toString(VolumetricLaw law) {
  return law == VolumetricLaw::LogSquared ? "LogSquared" : "QuadraticJ";
}

/// Finite strain (the Neo-Hookean model) or its small-strain linearisation.
enum class Kinematics {
  FiniteStrain,  ///< default
  SmallStrain    ///< linear elasticity with the same (Λ, μ)
};

/// Spatial tangent moduli of the Cauchy stress in the isotropic form
/// c = lambdaEff I⊗I + 2 muEff 𝕀^sym (the Truesdell-rate moduli of the
/// Kirchhoff stress divided by J).
struct IsotropicModuli {
  Real lambdaEff;
  Real muEff;
};

struct NeoHookean {
  Real lambda;  ///< first Lamé constant Λ
  Real mu;      ///< shear modulus μ
  VolumetricLaw law;
  Kinematics kinematics = Kinematics::FiniteStrain;

  /// Parameters from Young's modulus Y > 0 and Poisson's ratio −1 < ν < 0.5:
  /// μ = Y / (2(1+ν)), Λ = 2μν / (1 − 2ν).
  static NeoHookean fromYoungPoisson(Real Y, Real nu, VolumetricLaw law = VolumetricLaw::LogSquared) {
    if (!(std::isfinite(Y) && Y > 0.0)) {
      std::ostringstream os;
      os << "NeoHookean: Young's modulus Y = " << Y << " is out of range; allowed: 0 < Y < inf";
      throw InputError(os.str());
    }
    if (!(std::isfinite(nu) && nu > -1.0 && nu < 0.5)) {
      std::ostringstream os;
      os << "NeoHookean: Poisson's ratio nu = " << nu << " is out of range; allowed: -1 < nu < 0.5";
      throw InputError(os.str());
    }
    const Real mu = Y / (2.0 * (1.0 + nu));
    const Real lambda = 2.0 * mu * nu / (1.0 - 2.0 * nu);
    return fromLame(lambda, mu, law);
  }

  /// Parameters from the Lamé constants: μ > 0 and a positive bulk modulus,
  /// Λ > −2μ/3 (the same range as −1 < ν < 0.5).
  static NeoHookean fromLame(Real lambda, Real mu, VolumetricLaw law = VolumetricLaw::LogSquared) {
    if (!(std::isfinite(mu) && mu > 0.0)) {
      std::ostringstream os;
      os << "NeoHookean: shear modulus mu = " << mu << " is out of range; allowed: 0 < mu < inf";
      throw InputError(os.str());
    }
    if (!(std::isfinite(lambda) && lambda > -2.0 * mu / 3.0)) {
      std::ostringstream os;
      os << "NeoHookean: Lame constant lambda = " << lambda
         << " is out of range; allowed: -2*mu/3 < lambda < inf (positive bulk modulus), here mu = " << mu;
      throw InputError(os.str());
    }
    if (law != VolumetricLaw::LogSquared && law != VolumetricLaw::QuadraticJ) {
      throw InputError("NeoHookean: volumetric law is out of range; allowed: LogSquared, QuadraticJ");
    }
    return NeoHookean{lambda, mu, law, Kinematics::FiniteStrain};
  }

  /// Young's modulus Y = μ (3Λ + 2μ) / (Λ + μ).
  KOKKOS_INLINE_FUNCTION Real youngsModulus() const { return mu * (3.0 * lambda + 2.0 * mu) / (lambda + mu); }
  /// Poisson's ratio ν = Λ / (2 (Λ + μ)).
  KOKKOS_INLINE_FUNCTION Real poissonRatio() const { return lambda / (2.0 * (lambda + mu)); }
  /// Small-strain bulk modulus K = Λ + 2μ/3.
  KOKKOS_INLINE_FUNCTION Real bulkModulus() const { return lambda + 2.0 * mu / 3.0; }

  /// Volumetric energy U(J) (J > 0).
  KOKKOS_INLINE_FUNCTION Real volumetricEnergy(Real J) const {
    const Real lnJ = std::log(J);
    if (law == VolumetricLaw::LogSquared) return 0.5 * lambda * lnJ * lnJ;
    return 0.25 * lambda * (J * J - 1.0 - 2.0 * lnJ);
  }

  /// p(J) = J U'(J), the volumetric part of the Kirchhoff stress (τ = p I + μ (b − I)).
  KOKKOS_INLINE_FUNCTION Real volumetricKirchhoff(Real J) const {
    if (law == VolumetricLaw::LogSquared) return lambda * std::log(J);
    return 0.5 * lambda * (J * J - 1.0);
  }

  /// Strain energy per reference volume W(F); F must have det F > 0.
  KOKKOS_INLINE_FUNCTION Real energy(const Mat3& F) const {
    const Real J = det(F);
    Real I1 = 0.0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) I1 += F.a[i][j] * F.a[i][j];
    return volumetricEnergy(J) + 0.5 * mu * (I1 - 3.0) - mu * std::log(J);
  }

  /// Kirchhoff stress τ = J σ given b = F Fᵀ and J = det F > 0.
  KOKKOS_INLINE_FUNCTION Mat3 kirchhoff(const Mat3& b, Real J) const {
    const Real p = volumetricKirchhoff(J);
    Mat3 tau;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) tau.a[i][j] = mu * b.a[i][j];
    for (int i = 0; i < 3; ++i) tau.a[i][i] += p - mu;
    return tau;
  }

  /// Cauchy stress σ given b = F Fᵀ and J = det F > 0: the textbook form,
  /// kept as the reference cauchyOfDisplacementGradient() is tested against
  /// (the kernels use the latter).
  KOKKOS_INLINE_FUNCTION Mat3 cauchy(const Mat3& b, Real J) const {
    const Real invJ = 1.0 / J;
    const Real p = volumetricKirchhoff(J);
    const Real muJ = mu * invJ;
    Mat3 s;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) s.a[i][j] = muJ * b.a[i][j];
    const Real diag = (p - mu) * invJ;
    for (int i = 0; i < 3; ++i) s.a[i][i] += diag;
    return s;
  }

  /// det(I + H) − 1 = I₁(H) + I₂(H) + I₃(H) for the displacement gradient
  /// H = F − I: J − 1 without forming J, so that it keeps its relative
  /// precision when F is close to I.
  KOKKOS_INLINE_FUNCTION static Real detOfIdentityPlusMinusOne(const Mat3& H) {
    const Real i1 = H.a[0][0] + H.a[1][1] + H.a[2][2];
    const Real i2 = H.a[0][0] * H.a[1][1] - H.a[0][1] * H.a[1][0] + H.a[1][1] * H.a[2][2] -
                    H.a[1][2] * H.a[2][1] + H.a[0][0] * H.a[2][2] - H.a[0][2] * H.a[2][0];
    return i1 + i2 + det(H);
  }

  /// Cauchy stress from the displacement gradient H = F − I, with
  /// b − I = H + Hᵀ + H Hᵀ and ln J = log1p(J − 1) formed without
  /// subtracting 1 from quantities near 1. Equal to cauchy(F Fᵀ, det F) in
  /// exact arithmetic; near F = I its rounding error is relative to σ, not
  /// to the modulus (cauchy()'s floor is about eps·μ), which is what lets a
  /// stiff body meet an absolute force tolerance next to a soft one.
  KOKKOS_INLINE_FUNCTION Mat3 cauchyOfDisplacementGradient(const Mat3& H) const {
    const Real Jm1 = detOfIdentityPlusMinusOne(H);
    const Real invJ = 1.0 / (1.0 + Jm1);
    const Real p = law == VolumetricLaw::LogSquared ? lambda * std::log1p(Jm1) : 0.5 * lambda * Jm1 * (2.0 + Jm1);
    const Real muJ = mu * invJ;
    Mat3 s;
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j) {
        Real hh = 0.0;
        for (int m = 0; m < 3; ++m) hh += H.a[i][m] * H.a[j][m];
        s.a[i][j] = muJ * (H.a[i][j] + H.a[j][i] + hh);
        s.a[j][i] = s.a[i][j];
      }
    const Real diag = p * invJ;
    for (int i = 0; i < 3; ++i) s.a[i][i] += diag;
    return s;
  }

  /// Small-strain stress σ = Λ tr(ε) I + 2μ ε with ε = sym(H), H = F − I:
  /// the linearisation of cauchy() about F = I.
  KOKKOS_INLINE_FUNCTION Mat3 linearStressOfDisplacementGradient(const Mat3& H) const {
    const Real trEps = H.a[0][0] + H.a[1][1] + H.a[2][2];
    Mat3 s;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) s.a[i][j] = mu * (H.a[i][j] + H.a[j][i]);
    for (int i = 0; i < 3; ++i) s.a[i][i] += lambda * trEps;
    return s;
  }

  /// Small-strain energy per volume W = Λ/2 (tr ε)² + μ ε:ε; linearStressOfDisplacementGradient() is its
  /// derivative.
  KOKKOS_INLINE_FUNCTION Real linearEnergy(const Mat3& F) const {
    Real trEps = 0.0, epsEps = 0.0;
    for (int i = 0; i < 3; ++i) {
      trEps += F.a[i][i] - 1.0;
      for (int j = 0; j < 3; ++j) {
        const Real e = 0.5 * (F.a[i][j] + F.a[j][i]) - (i == j ? 1.0 : 0.0);
        epsEps += e * e;
      }
    }
    return 0.5 * lambda * trEps * trEps + mu * epsEps;
  }

  /// Spatial moduli c of the Cauchy stress at J = det F > 0 (see the header comment).
  KOKKOS_INLINE_FUNCTION IsotropicModuli spatialModuli(Real J) const {
    const Real invJ = 1.0 / J;
    IsotropicModuli c;
    if (law == VolumetricLaw::LogSquared) {
      c.lambdaEff = lambda * invJ;
      c.muEff = (mu - lambda * std::log(J)) * invJ;
    } else {
      c.lambdaEff = lambda * J;
      c.muEff = (mu - 0.5 * lambda * (J * J - 1.0)) * invJ;
    }
    return c;
  }
};

}  // namespace cgcm::material
