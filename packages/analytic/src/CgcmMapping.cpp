#include "cgcm/analytic/CgcmMapping.hpp"

#include <cmath>
#include <sstream>

#include "cgcm/core/Error.hpp"

namespace cgcm::analytic {
namespace {
}

Real workOfAdhesionFactor() {
  // w = −β0 ∫_{r_S0}^∞ β0 Φ(h) dh with Φ of (17): the integral of
  // π ε r0³ [(r0/h)⁹/45 − (r0/h)³/3] from r_S0 = r0/15^(1/6) is
  // −(π/8) 15^(1/3) ε r0⁴.
  return kPi / 8 * std::cbrt(15.0);
}

CgcmMapping cgcmMapping(Real gammaL, Real gammaW, Real nu) {
  auto bad = [](const char* name, Real value, const char* allowed) {
    std::ostringstream msg;
    msg << name << " = " << value << " is out of range (allowed: " << allowed << ")";
    throw InputError(msg.str());
  };
  if (!(std::isfinite(gammaL) && gammaL > 0)) bad("gammaL", gammaL, "finite, > 0");
  if (!(std::isfinite(gammaW) && gammaW > 0)) bad("gammaW", gammaW, "finite, > 0");
  if (!(nu > -1 && nu < 0.5)) bad("nu", nu, "-1 < nu < 0.5");

  CgcmMapping m;
  m.gammaL = gammaL;
  m.gammaW = gammaW;
  m.nu = nu;
  m.fw = workOfAdhesionFactor();
  // 1/E* = 2(1 − ν²)/Y for two bodies of modulus Y (34).
  m.fE = 1 / (2 * (1 - nu * nu));
  // πwR/(Y R0²) with R = R0 and w = f_w Y R0/(γW γL) (48), (28), (22).
  m.fF = kPi * m.fw / (gammaW * gammaL);
  // (3πwR²/(4E*))^(1/3)/R0: the M-D length scale of ā in units of R0.
  m.fa = std::cbrt(0.75 * m.fF / m.fE);
  // (9π²w²R/(16E*²))^(1/3)/R0 = f_a².
  m.fdelta = m.fa * m.fa;
  // (2πwE*²/(9R))^(1/3)/Y.
  m.fsigma = std::cbrt(2.0 / 9.0 * m.fF * m.fE * m.fE);
  m.workOfAdhesion = m.fw / (gammaW * gammaL);
  // Peak traction of the half-space law, (2√5/9) π β0² ε r0³, over Y.
  m.sigmaMax = 2 * std::sqrt(5.0) / 9 * kPi / gammaW;
  m.lambdaTheory = m.sigmaMax / m.fsigma;
  m.muTabor = std::cbrt(m.fw * m.fw * std::sqrt(15.0) / (m.fE * m.fE) * gammaL / (gammaW * gammaW));
  return m;
}

}  // namespace cgcm::analytic
