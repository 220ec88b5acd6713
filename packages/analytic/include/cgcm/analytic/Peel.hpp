#pragma once
// Steady-state peeling of an elastic strip (thickness h, width b) from a rigid
// substrate at the angle θ between the peeled arm and the substrate
// (Kendall, J. Phys. D 8 (1975) 1449). The energy balance per unit advance
// of the front,
//
//   (F/b)²/(2 E_t h) + (F/b)(1 − cos θ) − w = 0,
//
// with E_t the strip's modulus in tension: E/(1 − ν²) for a wide strip in
// plane strain (and for the interior of a wide 3D tape), E for a narrow one.
// Its positive root, normalised by the work of adhesion w,
//
//   F/(b w) = 2 / [(1 − cos θ) + √((1 − cos θ)² + 2ε)],   ε = w/(E_t h),
//
// written without the cancellation of the textbook form at small θ. The
// inextensible limit ε → 0 is Rivlin's F/(b w) = 1/(1 − cos θ); the lap-shear
// limit θ → 0 is √(2/ε). Bending stiffness is neglected (a long arm).
#include "cgcm/core/Types.hpp"

namespace cgcm::analytic {

/// F/(b w) of Kendall's extensible law. θ in radians, 0 ≤ θ ≤ π; ε ≥ 0,
/// finite; θ = 0 needs ε > 0 (InputError otherwise, naming the argument).
Real kendallPeelForce(Real theta, Real epsilon);

/// F/(b w) = 1/(1 − cos θ) of the inextensible strip, 0 < θ ≤ π.
Real inextensiblePeelForce(Real theta);

}  // namespace cgcm::analytic
