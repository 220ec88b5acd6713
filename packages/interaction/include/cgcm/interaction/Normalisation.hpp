#pragma once
// Normalisation of the interaction parameters (doc/theory.md#normalisation, eqs. 22, 28):
//
//     gammaL = R0 / r0,    gammaW = Y / (beta0^2 r0^3 eps).
//
// A run is set by (gammaL, gammaW): with reference length R0 and modulus Y,
// r0 = R0 / gammaL and beta0^2 eps = Y gammaL^3 / (gammaW R0^3); only the
// product beta0^2 eps matters, so beta0 = 1 unless physical values are given.
#include "cgcm/core/Types.hpp"

namespace cgcm::interaction {

/// Dimensionless pair (gammaL, gammaW) with the derived ratios.
struct ScalingParameters {
  Real gammaL = 0.0;                                ///< R0 / r0 (geometric scale)
  Real gammaW = 0.0;                                ///< Y / (beta0^2 r0^3 eps) (energy-density ratio)
  Real gammaPi() const { return gammaL * gammaW; }  ///< Pi_int,0 / Pi_C,0 (30)
  Real gammaK() const { return gammaW / gammaL; }   ///< K_int,0 / K_C,0 (33)
};

/// Physical interaction parameters together with the reference scales.
struct InteractionParameters {
  Real epsilon = 1.0;  ///< energy well of the pair potential
  Real r0 = 1.0;       ///< equilibrium distance of the pair potential
  Real beta0 = 1.0;    ///< reference particle density (both bodies)
  Real R0 = 1.0;       ///< reference length
  Real Y = 1.0;        ///< reference modulus
};

/// (gammaL, gammaW) -> physical parameters for given R0, Y and beta0:
/// r0 = R0 / gammaL, eps = Y gammaL^3 / (gammaW R0^3 beta0^2).
/// Throws InputError unless every argument is finite and > 0.
InteractionParameters fromScaling(Real gammaL, Real gammaW, Real R0 = 1.0, Real Y = 1.0, Real beta0 = 1.0);

/// Physical parameters -> (gammaL, gammaW). Throws InputError unless every
/// field is finite and > 0.
ScalingParameters toScaling(const InteractionParameters& p);

}  // namespace cgcm::interaction
