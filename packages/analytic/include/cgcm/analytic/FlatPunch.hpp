#pragma once
// Pull-off of a rigid flat punch bonded to an elastic half-space (E* = E/(1−ν²)
// of the half-space; w the work of adhesion, σ_max the interface strength).
//
//   axisymmetric, radius a (Kendall, J. Phys. D 4 (1971) 1186):
//     F_K = √(8π a³ E* w);  strength limit F_S = π a² σ_max
//   plane-strain strip, half-width a, per unit length (the same Griffith
//   balance on the flat-punch stress intensity K = F/√(πa), G = K²/(2E*)):
//     F_K = √(2π a E* w);   strength limit F_S = 2 a σ_max
//
// F_K is the fracture of the interface from the punch's corner; F_S the
// uniform detachment at σ_max. They are equal at the critical size (Gao &
// Yao, PNAS 101 (2004) 7851)
//
//   a_cr = 8 E* w/(π σ_max²) (axisymmetric),   a_cr = π E* w/(2 σ_max²) (strip),
//
// and in both geometries F_K/F_S = √(a_cr/a): below a_cr the punch detaches
// at its strength (flaw-tolerant), far above it at Kendall's force. Between,
// the pull-off depends on the shape of the interaction law.
#include <string_view>

#include "cgcm/core/Types.hpp"

namespace cgcm::analytic {

enum class PunchGeometry { Axisymmetric, Strip };

/// "axisymmetric" or "strip" (InputError naming the allowed values otherwise).
PunchGeometry parsePunchGeometry(std::string_view name);

class FlatPunch {
 public:
  /// E* > 0, w > 0, σ_max > 0, all finite (InputError otherwise).
  FlatPunch(PunchGeometry geometry, Real Estar, Real w, Real sigmaMax);

  PunchGeometry geometry() const { return geometry_; }
  /// a_cr, where Kendall's force equals the strength limit.
  Real criticalSize() const;
  /// Kendall's pull-off force at radius (half-width) a > 0.
  Real kendallForce(Real a) const;
  /// The strength limit at a > 0.
  Real strengthForce(Real a) const;

 private:
  PunchGeometry geometry_;
  Real Estar_, w_, sigmaMax_;
};

}  // namespace cgcm::analytic
