#pragma once
// Pull-off points of the analytic models (normalised as in Models.hpp).
//
// Load control (a dead load P is prescribed): the contact separates at the
// minimum of P̄(ā) along the equilibrium curve.
// Displacement control (fixed grips, δ prescribed): the contact separates
// where δ̄(ā) has its minimum, dδ̄/dā = 0; the force there is the
// displacement-control pull-off force.
//
//   Hertz: no adhesion, no pull-off; both points are reported as P̄ = 0 at
//          ā = 0, δ̄ = 0, with `adhesive` false.
//   JKR:   load control P̄ = −3/2 at ā³ = 3/2; displacement control P̄ = −5/6
//          at ā³ = 1/6 (closed form).
//   DMT:   both at ā = 0, P̄ = −2, δ̄ = 0.
//   M-D:   both found numerically (scan of the analytic slopes on a
//          logarithmic grid of ā, then Brent's root finder on dP̄/dā resp.
//          dδ̄/dā). Below λ ≈ 0.938 δ̄(ā) increases monotonically: under
//          displacement control the contact radius then shrinks continuously
//          to zero without a jump, and the point reported is the end of the
//          contact branch, ā → 0 (mdZeroContactLimit), with
//          `displacementJump` false. The transition is at λ = 0.93795
//          (Maugis: 0.938); just above it the minimum of δ̄ sits at tiny ā,
//          and if it lies below the scan's smallest radius (ā < 1e-6) the
//          same end point is reported, which differs from it by about 1e-6
//          in P̄.
#include "cgcm/analytic/Models.hpp"

namespace cgcm::analytic {

struct PullOffPoint {
  Real load = 0;      ///< P̄
  Real a = 0;         ///< ā
  Real approach = 0;  ///< δ̄
};

struct PullOff {
  PullOffPoint loadControl;
  PullOffPoint displacementControl;
  bool adhesive = true;          ///< false for Hertz (no pull-off)
  bool displacementJump = true;  ///< dδ̄/dā = 0 at some ā > 0 (a jump-off)
};

PullOff pullOff(const ContactModel& model);

/// The smallest ā of the Maugis-Dugdale scan (see above).
inline constexpr Real kPullOffScanMinA = 1e-6;

}  // namespace cgcm::analytic
