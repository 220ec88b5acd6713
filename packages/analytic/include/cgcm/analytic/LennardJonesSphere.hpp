#pragma once
// Elastic sphere on an elastic half-space with the Lennard-Jones 9-3 surface
// law in the Derjaguin approximation, coupled self-consistently with linear
// (Boussinesq) elasticity: the model of Greenwood (1997, Proc. R. Soc. A 453,
// 1277) and Feng (2000). It is the reference for a pull-off force at a finite
// Tabor parameter μ: its minimum force tends to JKR's −3/2 π w R as μ → ∞
// and to Bradley's −2 π w R as μ → 0.
//
// Traction at the local gap h (> 0 compressive), z0 the equilibrium gap:
//   σ(h) = (8w/(3 z0)) [(z0/h)⁹ − (z0/h)³],  ∫_z0^∞ σ dh = −w,
// peak tension 16w/(9√3 z0) at h = 3^(1/6) z0. Gap, with δ the approach
// (δ = 0: the undeformed surfaces are z0 apart on the axis):
//   h(r) = z0 − δ + r²/(2R) + u(r),
//   u(r) = (4/(π E*)) ∫_0^∞ σ(h(s)) (s/(r+s)) K(2√(rs)/(r+s)) ds,
// a compressive traction pushing the surfaces apart; 1/E* combines both
// bodies. Load P = 2π ∫ σ r dr (> 0 compressive).
//
// Dimensionless form (the only parameter is μ = (R w²/(E*² z0³))^(1/3)):
//   H = h/z0, Δ = δ/z0, ρ = r/√(R z0), σ̂ = σ z0/w, P/(π w R) = ∫ σ̂ d(ρ²),
//   H(ρ) = 1 − Δ + ρ²/2 + μ^(3/2) û(ρ), û = (4/π) ∫ σ̂ (s/(ρ+s)) K ds.
//
// Discretisation: rings [s_j, s_j+1] of constant traction, gaps at the ring
// midpoints r_i; u(r_i) = Σ_j C_ij σ_j with C_ij = D(r_i, s_j+1) − D(r_i, s_j)
// and D(r, b) the displacement at r under unit pressure on the disc of
// radius b (diskDisplacement). The N rings are equidistributed with the
// density 1/(ℓ + dist(ρ, band)) out to a far radius ρF ≥ 100 (the load
// beyond it, (32/3) ρF⁻⁴, is negligible): uniform in a band of a few ℓ around
// the contact edge, taken as the outermost peak of the tension, which holds
// the cohesive zone (ℓ = μ^(−3/2), the JKR cohesive length E* z0²/w in units
// of √(R z0), or 1 for μ < 1, the width of the Bradley interaction zone), and
// growing linearly with the distance from the band inwards and outwards. The
// band follows the edge: when the edge comes near a band end, the rings are
// rebuilt and the gap interpolated onto them. A fixed band would need of the
// order of μ² rings to cover the edge's path at the cohesive resolution; the
// moving one keeps the count independent of μ.
//
// Solution: Newton on H_i − [1 − Δ + ρ_i²/2 + Σ_j C_ij σ̂(H_j)] = 0 with the
// dense Jacobian I − C diag(σ̂'(H)) (LU with partial pivoting; the factors
// are reused while the residual drops fast), damped so that no H_i falls
// below half its value (the r⁻⁹ wall), to a residual of 1e-10 max(1, |Δ|).
// Path, under displacement control: at the starting approach Δ0 (in
// compression), continuation in an adhesion scale (σ̂ → sσ̂, s from 0.02 to
// 1) from the Hertz gap; then retraction, Δ decreasing in adaptive steps
// with a tangent predictor (a step is halved when Newton fails or the edge
// moves by more than ℓ), until the contact branch ends: a fold of Δ (no
// solution near the last one; the JKR jump-off) or separation (no
// compressive zone and H(0) > 3). The wanted pull-off force is the minimum
// of P along this branch (JKR: −3/2, reached before the displacement-control
// jump-off at −5/6). Rebuilding the rings shifts P slightly (by the change of
// the discretisation error), so the minimum is located again on one set of
// rings centred at the edge of the smallest sample, by Brent's minimiser.
#include <vector>

#include "cgcm/core/Types.hpp"

namespace cgcm::analytic {

/// The traction law σ̂(H) = (8/3)(H⁻⁹ − H⁻³), i.e. σ z0/w at h/z0 = H > 0.
Real ljTraction(Real gap);

/// E* u/p: the surface displacement at radius r of a half-space pair under a
/// uniform pressure p on the disc of radius b ≥ 0 (Johnson, Contact
/// Mechanics, eq. 3.39): (4b/π) E(r/b) for r < b, (4r/π)[E(b/r) −
/// (1 − b²/r²) K(b/r)] for r > b, with K, E the complete elliptic integrals
/// of the modulus k. D(0, b) = 2b, D(r, b) → b²/r for r ≫ b, D(r, 0) = 0.
Real diskDisplacement(Real r, Real b);

struct LjSphereOptions {
  /// Number of rings N (50 to 5000); each Newton step costs O(N³). P_min is
  /// converged to about 1e-4 with 150 rings for 0.05 ≤ μ ≤ 20; at large μ the
  /// fold ending the branch needs more (with 150 at μ = 20 the branch ends
  /// early, at P ≈ −0.90 instead of −0.84).
  int rings = 200;
  /// Starting approach Δ0 = δ0/z0; 0 chooses max(1, the JKR approach at the
  /// contact radius 1.2 a0), a0 the JKR zero-load radius. Must lie in
  /// compression, on the contact branch.
  Real deltaStart = 0;
  /// Bound on the number of accepted retraction steps (10 to 1e6).
  int maxSteps = 20000;
};

/// A point of the retraction branch. delta = δ/z0; load = P/(π w R); radii in
/// the Johnson-Greenwood normalisation of Models.hpp, ā = a (4E*/(3π w R²))^(1/3):
///   contactRadius: the outermost radius where σ changes sign (h = z0), 0 if
///     there is no compressive zone. In the JKR limit it tends to
///     a√(1 − p0'/p0), inside JKR's contact radius a, since the JKR pressure
///     turns tensile before the edge (0.58 a at the load-control pull-off).
///   peakRadius: the outermost radius of peak tension (h = 3^(1/6) z0), in the
///     cohesive zone; it tends to JKR's a as μ → ∞.
/// The Johnson-Greenwood approach is δ̄ = (δ/z0)(16/(9π²))^(1/3)/μ.
struct LjSpherePoint {
  Real delta = 0;
  Real load = 0;
  Real contactRadius = 0;
  Real peakRadius = 0;
};

struct LjSphereCurve {
  Real mu = 0;
  /// Accepted points, Δ decreasing from Δ0.
  std::vector<LjSpherePoint> retraction;
  Real minimumLoad = 0;     ///< min P/(π w R) along the branch
  Real deltaAtMinimum = 0;  ///< Δ there
  Real contactRadiusAtMinimum = 0;  ///< ā (sign change of σ) there
  Real peakRadiusAtMinimum = 0;     ///< ā (peak tension) there
  /// The branch ended at a fold or by separation (not at maxSteps).
  bool reachedEnd = false;
  /// The minimum is not the first or last point, i.e. it is bracketed.
  bool minimumInterior = false;
  /// The minimum was refined on fixed rings (see above); otherwise it is the
  /// smallest sample of the branch.
  bool refined = false;
  int rings = 0;              ///< N
  int remeshes = 0;           ///< rebuilds of the rings
  long factorisations = 0;    ///< of the Jacobian, failed attempts included
};

/// The retraction branch at Tabor parameter μ (finite, 1e-3 ≤ μ ≤ 1e3;
/// InputError otherwise, and for options out of range). Throws
/// NumericalError if the path cannot be started (no solution at Δ0). The
/// number of steps grows like μ² above μ ≈ 3 (the edge travels about √μ in
/// steps of ℓ = μ^(−3/2)): with 150 rings about 0.3 s at μ = 3, 2 s at
/// μ = 10, 10 s at μ = 20 on one core.
LjSphereCurve ljSphereRetraction(Real mu, const LjSphereOptions& options = {});

}  // namespace cgcm::analytic
