#pragma once
// Maugis-Dugdale model in the Johnson-Greenwood normalisation.
//
// For the transition parameter λ (41) and the contact radius ā, the ratio
// m = c/a of the adhesive-zone radius c to the contact radius solves (42)
//
//   (λā²/2)[√(m²−1) + (m²−2) atan√(m²−1)]
//     + (4λ²ā/3)[√(m²−1) atan√(m²−1) − m + 1] = 1,
//
// and then (43) P̄ = ā³ − λā²[√(m²−1) + m² atan√(m²−1)],
//               δ̄ = ā² − (4/3) ā λ √(m²−1).
//
// The unknown used throughout is s = √(m²−1) ≥ 0, not m: near the JKR limit
// (λā large) m − 1 is below the rounding of m, while s keeps full relative
// precision; in the DMT limit (λā small) s and m are both large and equal to
// within 1/(2m).
#include "cgcm/core/Types.hpp"

namespace cgcm::analytic {

struct MdSolution {
  Real lambda = 0;
  Real a = 0;         ///< contact radius ā
  Real s = 0;         ///< √(m²−1)
  Real m = 1;         ///< c/a
  Real load = 0;      ///< P̄ (43)
  Real approach = 0;  ///< δ̄ (43)
};

/// Left side of (42) minus 1, as a function of s = √(m²−1). Strictly
/// increasing in s from −1 at s = 0 to +∞, so (42) has exactly one root.
Real mdResidual(Real lambda, Real a, Real s);

/// Solves (42) for s by bracketing and safeguarded Newton. λ > 0, ā > 0 and
/// both finite (InputError otherwise); throws NumericalError if the iteration
/// fails (never returns an unconverged value). sGuess (optional, > 0) is a
/// starting point, e.g. the solution at a neighbouring ā.
Real solveMdS(Real lambda, Real a, Real sGuess = -1);

/// The full state (s, m, P̄, δ̄) at (λ, ā).
MdSolution solveMaugisDugdale(Real lambda, Real a, Real sGuess = -1);

/// Derivatives along the curve at fixed λ, from implicit differentiation of
/// (42): ds/dā = −(∂F/∂ā)/(∂F/∂s).
struct MdSlopes {
  Real ds = 0;
  Real dLoad = 0;
  Real dApproach = 0;
};
MdSlopes mdSlopes(const MdSolution& sol);

/// The limit ā → 0⁺ at fixed λ. The adhesive zone keeps a finite radius c̄ = mā,
/// which solves the limit of (42), (πλ/4) c̄² + (4/3)(π/2 − 1) λ² c̄ = 1; then
/// P̄ → −(π/2) λ c̄² (the tension −λ over the disc of radius c̄) and
/// δ̄ → −(4/3) λ c̄. As λ → 0, P̄ → −2 (DMT/Bradley).
struct MdZeroContact {
  Real c = 0;
  Real load = 0;
  Real approach = 0;
};
MdZeroContact mdZeroContactLimit(Real lambda);

}  // namespace cgcm::analytic
