#pragma once
// Contact pressure p̄(r) of the analytic models at a given contact radius ā
// (p > 0 compressive; r normalised like ā, see Models.hpp).
//
//   Hertz (38):  p̄ = (3ā/π) √(1 − ρ²),  ρ = r/a < 1;  0 outside.
//   JKR:         p̄ = (3ā/π) √(1 − ρ²) − √(6/ā) / (π √(1 − ρ²)),  ρ < 1;  0
//                outside. The adhesive term is the flat-punch tension whose
//                resultant is −√(6ā³) (39); p̄ → −∞ at r = a (returned as -inf).
//   M-D (44):    p̄ = (3ā/π) √(1 − ρ²) − (2λ/π) atan(√(m²−1) / √(1 − ρ²)),
//                ρ < 1;  p̄ = −λ for a ≤ r ≤ c = m a;  0 beyond.
//   DMT:         p̄ is the Hertz pressure in r < a. The DMT adhesive force
//                (P̄ = −2) acts outside the contact with a vanishing stress
//                spread over an unbounded annulus (the λ → 0 limit of M-D:
//                tension λ → 0 over c = m a → ∞ with πλc̄²/2 → 2), so it
//                contributes nothing to p̄ or to the stress at any finite
//                point; the pressure then integrates to P̄ + 2 = ā³.
//
// In every case π ∫₀^c r p̄(r) dr equals the model's load carried by the
// pressure (contactLoad(): P̄, and ā³ for DMT); in physical units this is
// ∫ 2π r p dr = P (the scales of (36) satisfy length² · pressure = πwR/2).
#include "cgcm/analytic/Models.hpp"

namespace cgcm::analytic {

class PressureProfile {
 public:
  /// The pressure of `model` at contact radius ā > 0 (InputError otherwise).
  PressureProfile(const ContactModel& model, Real a);

  Model kind() const { return kind_; }
  Real contactRadius() const { return a_; }
  /// c̄: m ā for Maugis-Dugdale, ā otherwise; p̄ = 0 for r > c̄.
  Real outerRadius() const { return c_; }
  /// √(m²−1) of Maugis-Dugdale (0 otherwise).
  Real mdS() const { return s_; }
  /// The model's load P̄ at this ā.
  Real load() const { return load_; }
  /// The load carried by p̄: P̄, except ā³ = P̄ + 2 for DMT (see above).
  Real contactLoad() const { return contactLoad_; }
  /// A magnitude of p̄ for tolerances: the largest coefficient of its terms.
  Real scale() const { return scale_; }

  /// p̄ at normalised radius r ≥ 0 (InputError for r < 0 or NaN). At r = a,
  /// the value for a ≤ r (−λ for M-D, 0 for Hertz and DMT, −∞ for JKR); at
  /// r = c the M-D value −λ (the interval of (44) is closed).
  Real operator()(Real r) const;
  /// p̄ at r/a.
  Real atRelative(Real rOverA) const { return (*this)(rOverA * a_); }
  /// p̄ at r = ā (1 − t²), 0 < t ≤ 1, with √(1 − ρ²) = t √(2 − t²) formed
  /// without cancellation: accurate as r → a⁻ (t → 0), where the JKR and
  /// M-D terms vary fastest.
  Real nearEdge(Real t) const;

  /// π ∫₀^c r p̄ dr by adaptive quadrature (the substitution r = ā(1 − t²)
  /// on [0, a] removes the edge singularity), to an absolute error of
  /// relTol · (scale ā² + |P̄|).
  Real integratedLoad(Real relTol = 1e-12) const;

 private:
  /// p̄ for r < a, given u = √(1 − (r/a)²) > 0.
  Real inside(Real u) const;

  Model kind_;
  Real a_;
  Real c_;
  Real lambda_ = 0;
  Real s_ = 0;
  Real hertz_;      ///< 3ā/π
  Real jkr_ = 0;    ///< √(6/ā)/π
  Real load_;
  Real contactLoad_;
  Real scale_;
};

}  // namespace cgcm::analytic
