#include "cgcm/analytic/Peel.hpp"

#include <cmath>
#include <sstream>

#include "cgcm/core/Error.hpp"

namespace cgcm::analytic {
namespace {

void requireAngle(Real theta, bool allowZero) {
  if (!(std::isfinite(theta) && (allowZero ? theta >= 0 : theta > 0) && theta <= kPi)) {
    std::ostringstream msg;
    msg << "peel: the angle theta must be " << (allowZero ? "in [0, pi]" : "in (0, pi]")
        << " radians, got " << theta;
    throw InputError(msg.str());
  }
}

/// 1 − cos θ = 2 sin²(θ/2), exact to rounding at small θ.
Real oneMinusCos(Real theta) {
  const Real h = std::sin(0.5 * theta);
  return 2 * h * h;
}

void requireStrain(Real epsilon) {
  if (!(std::isfinite(epsilon) && epsilon >= 0)) {
    std::ostringstream msg;
    msg << "peel: epsilon = w/(E_t h) must be finite and >= 0, got " << epsilon;
    throw InputError(msg.str());
  }
}

}  // namespace

Real kendallPeelForce(Real theta, Real epsilon) {
  requireStrain(epsilon);
  requireAngle(theta, epsilon > 0);
  const Real c = oneMinusCos(theta);
  return 2 / (c + std::sqrt(c * c + 2 * epsilon));
}

Real heldEndPeelForce(Real theta, Real epsilon) {
  requireStrain(epsilon);
  requireAngle(theta, false);
  const Real c = oneMinusCos(theta), s = std::sin(theta);
  return 2 / (c + std::sqrt(c * c + 2 * epsilon * s * s));
}

Real inextensiblePeelForce(Real theta) {
  requireAngle(theta, false);
  return 1 / oneMinusCos(theta);
}

}  // namespace cgcm::analytic
