#include "cgcm/interaction/Normalisation.hpp"

#include <cmath>
#include <sstream>

#include "cgcm/core/Error.hpp"

namespace cgcm::interaction {

namespace {
void requirePositive(const char* name, Real v) {
  if (!(v > 0.0) || !std::isfinite(v)) {
    std::ostringstream os;
    os << "normalisation: " << name << " must be finite and > 0, got " << v;
    throw InputError(os.str());
  }
}
}  // namespace

InteractionParameters fromScaling(Real gammaL, Real gammaW, Real R0, Real Y, Real beta0) {
  requirePositive("gammaL", gammaL);
  requirePositive("gammaW", gammaW);
  requirePositive("R0", R0);
  requirePositive("Y", Y);
  requirePositive("beta0", beta0);
  InteractionParameters p;
  p.R0 = R0;
  p.Y = Y;
  p.beta0 = beta0;
  p.r0 = R0 / gammaL;
  p.epsilon = Y * gammaL * gammaL * gammaL / (gammaW * R0 * R0 * R0 * beta0 * beta0);
  return p;
}

ScalingParameters toScaling(const InteractionParameters& p) {
  requirePositive("epsilon", p.epsilon);
  requirePositive("r0", p.r0);
  requirePositive("beta0", p.beta0);
  requirePositive("R0", p.R0);
  requirePositive("Y", p.Y);
  ScalingParameters s;
  s.gammaL = p.R0 / p.r0;
  s.gammaW = p.Y / (p.beta0 * p.beta0 * p.r0 * p.r0 * p.r0 * p.epsilon);
  return s;
}

}  // namespace cgcm::interaction
