#include "cgcm/analytic/FlatPunch.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "cgcm/core/Error.hpp"

namespace cgcm::analytic {
namespace {

void requirePositive(const char* what, Real value) {
  if (!(std::isfinite(value) && value > 0)) {
    std::ostringstream msg;
    msg << "flat punch: " << what << " must be finite and > 0, got " << value;
    throw InputError(msg.str());
  }
}

}  // namespace

PunchGeometry parsePunchGeometry(std::string_view name) {
  if (name == "axisymmetric") return PunchGeometry::Axisymmetric;
  if (name == "strip") return PunchGeometry::Strip;
  throw InputError("flat punch: unknown geometry '" + std::string(name) +
                   "' (allowed: axisymmetric, strip)");
}

FlatPunch::FlatPunch(PunchGeometry geometry, Real Estar, Real w, Real sigmaMax)
    : geometry_(geometry), Estar_(Estar), w_(w), sigmaMax_(sigmaMax) {
  requirePositive("modulus E*", Estar);
  requirePositive("work of adhesion w", w);
  requirePositive("strength sigma_max", sigmaMax);
}

Real FlatPunch::criticalSize() const {
  const Real s2 = sigmaMax_ * sigmaMax_;
  return geometry_ == PunchGeometry::Axisymmetric ? 8 * Estar_ * w_ / (kPi * s2)
                                                  : kPi * Estar_ * w_ / (2 * s2);
}

Real FlatPunch::kendallForce(Real a) const {
  requirePositive("radius a", a);
  return geometry_ == PunchGeometry::Axisymmetric ? std::sqrt(8 * kPi * a * a * a * Estar_ * w_)
                                                  : std::sqrt(2 * kPi * a * Estar_ * w_);
}

Real FlatPunch::strengthForce(Real a) const {
  requirePositive("radius a", a);
  return geometry_ == PunchGeometry::Axisymmetric ? kPi * a * a * sigmaMax_ : 2 * a * sigmaMax_;
}

}  // namespace cgcm::analytic
