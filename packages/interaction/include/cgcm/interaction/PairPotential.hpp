#pragma once
// Pair potentials and their half-space integrals (Method 3, doc/theory.md#method-3).
//
// A potential phi(r) between two particles is integrated over a flat
// half-space of unit density at distance r from a point (eq. 17):
//
//     halfSpace(r) = Phi(r) / beta = integral over {z >= r} of phi(|x - y|) dv_y .
//
// The surface traction of Method 3 between bodies k and l is
//     T(r) = beta_k Phi_l(r) = beta_k beta_l halfSpace(r)
// (reference densities), so T is the same for both bodies of a pair.
//
// The kernels of both methods evaluate a potential through its plain-data
// form (kernelPotential(): KernelPotential.hpp, no virtual calls); this class
// names it and gives the surface properties (r_S0, work of adhesion, peak
// traction: numerical defaults, overridden by closed forms). A potential
// with no closed forms of its own is a PlainPairPotential of its struct.
#include <Teuchos_ParameterList.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cgcm/core/Types.hpp"
#include "cgcm/interaction/KernelPotential.hpp"

namespace cgcm::interaction {

class PairPotential {
 public:
  /// epsilon: energy scale (> 0); r0: length scale (> 0). Throws InputError otherwise.
  PairPotential(Real epsilon, Real r0);
  virtual ~PairPotential() = default;

  virtual std::string name() const = 0;

  /// The plain-data form the kernels evaluate.
  virtual KernelPotential kernelPotential() const = 0;

  Real epsilon() const { return epsilon_; }
  Real r0() const { return r0_; }

  /// Pair potential phi(r) and its derivative d phi / dr.
  virtual Real phi(Real r) const = 0;
  virtual Real dphi(Real r) const = 0;

  /// Half-space integral per unit density, Phi(r)/beta (eq. 17), and d/dr.
  virtual Real halfSpace(Real r) const = 0;
  virtual Real dHalfSpace(Real r) const = 0;

  /// Both at once (the kernel's inner loop); the default calls the two above.
  virtual void halfSpaceWithDerivative(Real r, Real& value, Real& derivative) const;

  /// Surface equilibrium distance r_S0, the zero of Phi (doc/theory.md#method-3). Empty when
  /// Phi never changes sign (a purely repulsive potential has no equilibrium).
  /// Default: numerical root search on [1e-3 r0, 1e3 r0].
  virtual std::optional<Real> surfaceEquilibriumDistance() const;

  /// Work of adhesion per unit density product, w / (beta1 beta2) =
  /// -integral_{r_S0}^inf Phi(r)/beta dr (eqs. 47-48). Zero without r_S0.
  /// Default: numerical quadrature.
  virtual Real adhesionWorkCoefficient() const;

  /// Peak adhesive (tensile) traction between two half-spaces per unit
  /// density product, sigma_max / (beta1 beta2) = max_r (-Phi(r)/beta).
  /// Zero when Phi is never negative. Default: numerical maximisation.
  virtual Real peakTractionCoefficient() const;

  /// The same with densities: T(r) = beta_k beta_l Phi/beta.
  Real traction(Real r, Real betaK, Real betaL) const { return betaK * betaL * halfSpace(r); }
  Real workOfAdhesion(Real beta1, Real beta2) const { return beta1 * beta2 * adhesionWorkCoefficient(); }
  Real peakTraction(Real beta1, Real beta2) const { return beta1 * beta2 * peakTractionCoefficient(); }

 private:
  Real epsilon_;
  Real r0_;
};

/// Lennard-Jones 12-6, eq. (4): phi = eps [(r0/r)^12 - 2 (r0/r)^6].
/// Phi/beta = pi eps r0^3 [(1/45)(r0/r)^9 - (1/3)(r0/r)^3], r_S0 = r0/15^(1/6),
/// w = f_w beta1 beta2 eps r0^4 with f_w = (pi/8) 15^(1/3),
/// sigma_max = (2 sqrt5 / 9) pi beta1 beta2 eps r0^3.
class LennardJones final : public PairPotential {
 public:
  LennardJones(Real epsilon, Real r0) : PairPotential(epsilon, r0) {}
  std::string name() const override { return "lennard-jones"; }
  KernelPotential kernelPotential() const override;
  Real phi(Real r) const override;
  Real dphi(Real r) const override;
  Real halfSpace(Real r) const override;
  Real dHalfSpace(Real r) const override;
  void halfSpaceWithDerivative(Real r, Real& value, Real& derivative) const override;
  std::optional<Real> surfaceEquilibriumDistance() const override;
  Real adhesionWorkCoefficient() const override;
  Real peakTractionCoefficient() const override;

  /// r_S0 = r0 / 15^(1/6) for the length scale r0.
  static Real surfaceEquilibriumDistance(Real r0);
  /// f_w = (pi/8) 15^(1/3) = 0.96848...
  static Real workFactor();
  /// (2 sqrt5 / 9) pi = 1.5611...
  static Real peakTractionFactor();
};

/// Repulsive part of Lennard-Jones only: phi = eps (r0/r)^12, a smooth
/// barrier without adhesion. Phi/beta = (pi/45) eps r0^3 (r0/r)^9; no r_S0,
/// w = 0, sigma_max = 0.
class RepulsiveLennardJones final : public PairPotential {
 public:
  RepulsiveLennardJones(Real epsilon, Real r0) : PairPotential(epsilon, r0) {}
  std::string name() const override { return "repulsive"; }
  KernelPotential kernelPotential() const override;
  Real phi(Real r) const override;
  Real dphi(Real r) const override;
  Real halfSpace(Real r) const override;
  Real dHalfSpace(Real r) const override;
  void halfSpaceWithDerivative(Real r, Real& value, Real& derivative) const override;
  std::optional<Real> surfaceEquilibriumDistance() const override { return std::nullopt; }
  Real adhesionWorkCoefficient() const override { return 0.0; }
  Real peakTractionCoefficient() const override { return 0.0; }
};

/// A potential given by its kernel struct alone (KernelPotential.hpp): phi,
/// dphi and the half-space law from the struct, the surface properties from
/// PairPotential's numerical defaults.
template <class P>
class PlainPairPotential final : public PairPotential {
 public:
  PlainPairPotential(std::string name, Real epsilon, Real r0, const P& law)
      : PairPotential(epsilon, r0), name_(std::move(name)), law_(law) {}
  std::string name() const override { return name_; }
  KernelPotential kernelPotential() const override { return law_; }
  Real phi(Real r) const override { return law_.phi(r); }
  Real dphi(Real r) const override { return 2.0 * r * law_.pointLaw(r * r).df; }
  Real halfSpace(Real r) const override {
    Real value, derivative;
    law_.halfSpace(r, value, derivative);
    return value;
  }
  Real dHalfSpace(Real r) const override {
    Real value, derivative;
    law_.halfSpace(r, value, derivative);
    return derivative;
  }
  void halfSpaceWithDerivative(Real r, Real& value, Real& derivative) const override {
    law_.halfSpace(r, value, derivative);
  }

 private:
  std::string name_;
  P law_;
};

/// The potentials a deck can name, in one place: a new potential is its class
/// above and one entry here (the deck's choices, its own parameters and their
/// help follow).
struct PotentialEntry {
  const char* deckName;     ///< Interaction/Potential value
  const char* description;  ///< for the deck's help
  /// Declares the potential's own parameters, with defaults, help and validators, in the
  /// sublist Interaction/<deckName>; null when it has none.
  void (*declareParameters)(Teuchos::ParameterList& own);
  /// The potential of energy epsilon and length r0; `own` holds its parameters, defaults set.
  std::shared_ptr<const PairPotential> (*make)(Real epsilon, Real r0, const Teuchos::ParameterList& own);
};
const std::vector<PotentialEntry>& potentialRegistry();

/// Factory by deck name, case-insensitive (the deck names lower-cased are the
/// potentials' name(); "lj" also works). `own`: the potential's parameters
/// (Interaction/<deckName>); what it leaves out takes the default, what the
/// potential does not declare is refused. Throws InputError naming the allowed values.
std::shared_ptr<const PairPotential> makePotential(const std::string& name, Real epsilon, Real r0,
                                                   const Teuchos::ParameterList& own = Teuchos::ParameterList());

}  // namespace cgcm::interaction
