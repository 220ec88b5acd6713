#pragma once
// Mapping between the Maugis-Dugdale (Johnson-Greenwood) normalisation (36)
// and the CGCM normalisation (R0 = Y = 1: ū = u/R0, P̄ = P/(Y R0²),
// σ̄ = σ/Y), for the benchmark of a sphere of radius R0 on a half-space
// (R = R0), both bodies with modulus Y, Poisson ratio ν and particle
// density β0 interacting by Lennard-Jones (4) through the half-space
// potential (17). All factors take the plain γL = R0/r0 and
// γW = Y/(β0² r0³ ε) of (22), (28).
//
//   w  = f_w β0² ε r0⁴,  f_w = (π/8) 15^(1/3)              (48)
//        (in CGCM units w/(Y R0) = f_w/(γW γL))
//   E* = f_E Y,          f_E = 1/(2(1 − ν²))               (49)
//   P̄_C = f_F P̄_MD,      f_F = π f_w/(γW γL)              (50)
//   ā_C = f_a ā_MD,      f_a = ((3/4) f_F/f_E)^(1/3)       (51)
//   δ̄_C = f_δ δ̄_MD,      f_δ = f_a²                        (52)
//   σ̄_C = f_σ σ̄_MD,      f_σ = ((2/9) f_F f_E²)^(1/3)      (53)
//
// Theoretical λ: the peak traction of two LJ half-spaces,
// σ0 = (2√5/9) π β0² ε r0³ (at (r0/h)⁶ = 5), is σ̄0_C = (2√5π/9)/γW in
// CGCM units, and λ (41) is σ0 in the M-D stress normalisation:
//   λ = σ̄0_C / f_σ = (2√5π/9) (9 γL / (2π f_w f_E² γW²))^(1/3).
// Tabor parameter with z0 = r_S0 = r0/15^(1/6) (the equilibrium distance of
// the half-space law): μ = (R w²/(E*² z0³))^(1/3)
//   = (f_w² √15 / f_E²)^(1/3) (γL/γW²)^(1/3).
#include "cgcm/core/Types.hpp"

namespace cgcm::analytic {

struct CgcmMapping {
  Real gammaL = 0;
  Real gammaW = 0;
  Real nu = 0;
  Real fw = 0;      ///< (π/8) 15^(1/3)
  Real fE = 0;      ///< E*/Y
  Real fF = 0;      ///< P̄_C / P̄_MD
  Real fa = 0;      ///< ā_C / ā_MD (also for r, z)
  Real fdelta = 0;  ///< δ̄_C / δ̄_MD
  Real fsigma = 0;  ///< σ̄_C / σ̄_MD (also for p)
  Real workOfAdhesion = 0;  ///< w/(Y R0) = f_w/(γW γL)
  Real sigmaMax = 0;        ///< σ0/Y = (2√5π/9)/γW
  Real lambdaTheory = 0;    ///< λ of the LJ half-space law
  Real muTabor = 0;         ///< Tabor parameter μ
};

/// The work-of-adhesion factor f_w = (π/8) 15^(1/3) of (48).
Real workOfAdhesionFactor();

/// γL > 0, γW > 0 finite, −1 < ν < 1/2 (InputError naming the parameter).
CgcmMapping cgcmMapping(Real gammaL, Real gammaW, Real nu);

}  // namespace cgcm::analytic
