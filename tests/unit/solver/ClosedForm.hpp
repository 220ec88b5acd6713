#pragma once
// Closed-form homogeneous states of the compressible Neo-Hookean solid.
#include <cmath>
#include <stdexcept>
#include <string>

#include "cgcm/core/Types.hpp"
#include "cgcm/material/NeoHookean.hpp"

namespace cgcm::test {

/// Volumetric stress term J U'(J) of the Kirchhoff stress.
inline double kirchhoffPressure(const material::NeoHookean& m, double J) {
  return m.law == material::VolumetricLaw::LogSquared ? m.lambda * std::log(J) : 0.5 * m.lambda * (J * J - 1.0);
}

/// Uniaxial stress with stretch `axial` along one axis and free lateral faces:
/// solves for the lateral stretch (nLateral = 2 free directions in 3D and
/// axisymmetry, 1 in plane strain where the out-of-plane stretch is 1) and
/// returns the axial Cauchy stress; `lateral` receives the lateral stretch.
inline double uniaxialCauchyStress(const material::NeoHookean& m, double axial, int nLateral, double& lateral) {
  // lateral Kirchhoff stress: J U' + mu (l^2 - 1) = 0 with J = axial * l^nLateral
  double l = 1.0;
  for (int it = 0; it < 100; ++it) {
    const double J = axial * std::pow(l, nLateral);
    const double g = kirchhoffPressure(m, J) + m.mu * (l * l - 1.0);
    const double dJ = nLateral * J / l;
    const double dP = m.law == material::VolumetricLaw::LogSquared ? m.lambda / J : m.lambda * J;
    const double dg = dP * dJ + 2.0 * m.mu * l;
    const double step = g / dg;
    l -= step;
    if (std::abs(step) < 1e-15 * l) break;
  }
  lateral = l;
  const double J = axial * std::pow(l, nLateral);
  return (kirchhoffPressure(m, J) + m.mu * (axial * axial - 1.0)) / J;
}

// Number of free lateral directions and the loaded area factor of the unit block.
inline double loadedArea(const std::string& formulation, double lateralStretch) {
  if (formulation == "plane strain") return lateralStretch;                // width 1, unit thickness
  if (formulation == "axisymmetric") return cgcm::kPi * lateralStretch * lateralStretch;  // disc of radius 1
  return lateralStretch * lateralStretch;                                  // 1 x 1 face
}
inline int lateralDirections(const std::string& formulation) { return formulation == "plane strain" ? 1 : 2; }

}  // namespace cgcm::test
