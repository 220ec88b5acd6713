#pragma once
// Adhesive line contact: an elastic cylinder (radius R) on an elastic
// half-space in plane strain, per unit length, with E* the plane-strain
// combined modulus (1/E* = (1−ν1²)/E1 + (1−ν2²)/E2) and w the work of
// adhesion. Half-width of the contact a, load per unit length P (> 0
// compressive).
//
//   Hertz:  P = πE*a²/(4R)
//   JKR (Barquins 1988; Chaudhury et al. 1996):
//           P = πE*a²/(4R) − √(2πE* w a);
//           load-control pull-off P_c = −3(πE* w² R/16)^(1/3) at
//           a_c = (2wR²/(πE*))^(1/3)
//   Maugis–Dugdale (the cohesive-zone cylinder of Baney & Hui 1997): a
//           Dugdale tension σ0 over a < |x| < c, with w = σ0 h0. Maugis's
//           method applied to line contact (doc/analytic-models.md derives it):
//             P = πE*a²/(4R) − 2σ0 √(c² − a²)                      (no stress
//                                                     singularity at x = a)
//             h0 = (1/(2R))[c√(c²−a²) − a² arcosh(c/a)]
//                + (4σ0/(πE*))[√(c²−a²) arcosh(c/a) − 2c atan((c−a)/(c+a))]
//                                                     (the gap at x = c).
//
// There is no approach δ: the displacement of a half-plane under a line load
// grows like the logarithm of the distance, so δ depends on where it is
// measured; only load control has a pull-off here.
//
// Normalisation (ours; chosen so that λ multiplies each Dugdale term once):
//
//   ā = a/ℓ, ℓ = (π w R²/E*)^(1/3);   P̄ = P/F, F = (π² w² E* R)^(1/3);
//   λ = 2σ0 (R/(π w E*²))^(1/3)
//
// (Maugis's λ = 2σ0(R/(πwK²))^(1/3) for the sphere, with K = 4E*/3 replaced
// by E*.) Then, with m = c/a and s = √(m²−1),
//
//   JKR:  P̄ = πā²/4 − √(2ā),  pull-off P̄_c = −3/(16π)^(1/3) at ā_c = (2/π²)^(1/3)
//   M-D:  P̄ = πā²/4 − λās,
//         (πλā²/4)[ms − arsinh s] + λ²ā[s arsinh s − 2m atan((m−1)/(m+1))] = 1.
//
// The M-D curve tends to JKR as λ → ∞ and, as λ → 0, to the rigid-cylinder
// Dugdale limit P̄ → −2√(λ/π) at ā → 0 (P = −2σ0√(2R h0): no finite DMT
// force in 2D, it grows with √σ0).
#include "cgcm/core/Types.hpp"

namespace cgcm::analytic {

/// Scales of the normalisation above: a = ā·length, P = P̄·force,
/// σ0 = λ·stress/2.
struct CylinderScales {
  Real length = 0;  ///< (π w R²/E*)^(1/3)
  Real force = 0;   ///< (π² w² E* R)^(1/3), per unit length
  Real stress = 0;  ///< (π w E*²/R)^(1/3): σ0 = λ·stress/2

  /// w > 0, R > 0, E* > 0, all finite (InputError otherwise).
  static CylinderScales from(Real w, Real R, Real Estar);
};

/// A normalised point of a cylinder's equilibrium curve: half-width ā, load
/// P̄, and the outer half-width of the loaded zone c̄ (= ā except for M-D).
struct CylinderPoint {
  Real a = 0;
  Real load = 0;
  Real c = 0;
};

/// JKR cylinder at ā > 0 (InputError for ā ≤ 0 or non-finite).
CylinderPoint jkrCylinder(Real a);
/// Its load-control pull-off (closed form).
CylinderPoint jkrCylinderPullOff();

/// Left side of the M-D gap equation minus 1 as a function of s = √(m²−1):
/// −1 at s = 0 and strictly increasing, so it has exactly one root.
Real mdCylinderResidual(Real lambda, Real a, Real s);

struct MdCylinderSolution {
  Real lambda = 0;
  Real a = 0;
  Real s = 0;     ///< √(m²−1)
  Real m = 1;     ///< c/a
  Real load = 0;  ///< P̄
  Real dLoad = 0; ///< dP̄/dā along the curve at fixed λ
};

/// The M-D cylinder at (λ, ā), λ > 0 and ā > 0 finite (InputError
/// otherwise); NumericalError if the root is not found (never an unconverged
/// value). sGuess > 0 (optional) starts the bracket search.
MdCylinderSolution solveMdCylinder(Real lambda, Real a, Real sGuess = -1);

/// Load-control pull-off of the M-D cylinder: the minimum of P̄(ā), from a
/// scan of dP̄/dā over ā ∈ [1e-8, 10] refined by a bracketing root finder.
/// λ ∈ [1e-3, 1e3] (InputError otherwise).
CylinderPoint mdCylinderPullOff(Real lambda);

}  // namespace cgcm::analytic
