#pragma once
// Vertical stress σz(r, z) in the half-space under an axisymmetric surface
// pressure p(r), by superposing Boussinesq point loads (45)-(46):
//
//   σz(r, z) = −(3/π) ∫₀^c s p(s) ∫₀^π z³/ρ'⁵ dφ ds,
//   ρ'² = r² − 2 r s cos φ + s² + z²,
//
// z ≥ 0 the depth below the surface, compressive stress negative, all
// lengths and stresses normalised as in Models.hpp (r, z like ā; σz like p̄).
//
// The φ-integral is closed-form: with α = r² + s² + z², β = 2 r s and the
// modulus k² = 2β/(α+β), k'² = 1 − k² = ((r−s)² + z²)/((r+s)² + z²),
//
//   ∫₀^π (α − β cos φ)^(−5/2) dφ = 2 [2(1 + k'²) E(k) − k'² K(k)]
//                                   / (3 ((r−s)² + z²)² √((r+s)² + z²)),
//
// (from ∫₀^{π/2} (1 − k² sin²θ)^(−5/2) dθ = [2(2−k²)E − k'²K]/(3k'⁴)), so that
// σz = −∫₀^c G(r, s, z) p(s) ds with the ring kernel
//
//   G = (2/π) s z³ [2(1 + k'²)E − k'²K] / (((r−s)² + z²)² √((r+s)² + z²)),
//
// which has unit mass, ∫₀^∞ G ds = 1 (a uniform pressure q gives σz = −q).
//
// Near the surface G is a spike of width ~z at s = r, so the s-integral is
// taken as
//
//   σz = −[ ∫₀^c G (p(s) − p(r)) ds + p(r) (1 − ∫_c^∞ G ds) ]    (r < c)
//
// (the spike multiplies p(s) − p(r), which vanishes at s = r), and directly
// for r ≥ c. The integrals are adaptive Gauss-Kronrod, split at s = r,
// r ± z·4ⁿ, a and c; [0, a] is mapped by s = a(1 − t²) (removing the square
// root and JKR edge singularities at s = a), [c, ∞) by s = c/t. At z = 0,
// σz = −p(r) is returned exactly. At the M-D jump r = c the limit z → 0⁺ is
// the mean of the two sides, σz → λ/2, while z = 0 itself gives −p(c) = λ
// (the interval a ≤ r ≤ c of (44) is closed).
#include <vector>

#include "cgcm/analytic/Pressure.hpp"

namespace cgcm::analytic {

/// The ring kernel G(r, s, z) above; r, s ≥ 0, z > 0.
Real boussinesqRingKernel(Real r, Real s, Real z);

struct StressOptions {
  /// Tolerance of each σz: an absolute error of relTol · PressureProfile::scale(),
  /// or relTol relative to the integral where that is larger (near the JKR
  /// edge singularity).
  Real relTol = 1e-9;
  /// Interval budget of each adaptive integral before NumericalError.
  int maxIntervals = 4000;
};

/// σz at (r, z), r ≥ 0 and z ≥ 0 finite (InputError otherwise). Throws
/// NumericalError if a quadrature does not reach its tolerance.
Real sigmaZ(const PressureProfile& p, Real r, Real z, const StressOptions& options = {});

/// σz on the grid r[i] × z[j], returned row-major by depth:
/// result[j * r.size() + i] = σz(r[i], z[j]). `threads` ≥ 1 worker threads
/// share the rows.
std::vector<Real> sigmaZGrid(const PressureProfile& p, const std::vector<Real>& r,
                             const std::vector<Real>& z, const StressOptions& options = {},
                             int threads = 1);

/// Closed-form σz on the axis under the Hertz pressure of peak p0 and contact
/// radius a (Johnson, Contact Mechanics, eq. 3.45 at r = 0):
/// σz(0, z) = −p0 (1 + z²/a²)^(−1).
Real hertzAxisSigmaZ(Real p0, Real a, Real z);

}  // namespace cgcm::analytic
