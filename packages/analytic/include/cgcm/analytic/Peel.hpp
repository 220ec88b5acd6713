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
//
// Kendall's bonded part carries no load: the bond holds it in shear. A bond
// that carries no shear (a Lennard-Jones attraction to a flat substrate is
// invariant under sliding) leaves the pull's part along the substrate, F cos θ,
// to whatever holds the strip's far end, and the bonded part carries it as a
// uniform tension (compression beyond 90°), ε_b = F cos θ/(E_t h b), while the
// arm carries ε_a = F/(E_t h b). Per unit advance the load point moves by
// (1 + ε_a) − (1 + ε_b) cos θ along the pull and the strain energy changes by
// E_t h b (ε_a² − ε_b²)/2, so
//
//   (F/b)² sin²θ/(2 E_t h) + (F/b)(1 − cos θ) − w = 0:
//
// Kendall's law with ε sin²θ for ε. The two agree at 90° and in the
// inextensible limit; at 180° the held strip's stretching term vanishes; at
// θ → 0 (lap shear) nothing is released and the force grows without bound.
#include "cgcm/core/Types.hpp"

namespace cgcm::analytic {

/// F/(b w) of Kendall's extensible law. θ in radians, 0 ≤ θ ≤ π; ε ≥ 0,
/// finite; θ = 0 needs ε > 0 (InputError otherwise, naming the argument).
Real kendallPeelForce(Real theta, Real epsilon);

/// F/(b w) of the strip held at its far end on a bond without shear
/// (above): 2 / [(1 − cos θ) + √((1 − cos θ)² + 2 ε sin²θ)]. θ in radians,
/// 0 < θ ≤ π; ε ≥ 0, finite (InputError otherwise).
Real heldEndPeelForce(Real theta, Real epsilon);

/// F/(b w) = 1/(1 − cos θ) of the inextensible strip, 0 < θ ≤ π.
Real inextensiblePeelForce(Real theta);

}  // namespace cgcm::analytic
