#include "cgcm/interaction/PairPotential.hpp"

#include <cctype>

#include <algorithm>
#include <boost/math/tools/minima.hpp>
#include <boost/math/tools/toms748_solve.hpp>
#include <limits>
#include <cmath>
#include <sstream>

#include "cgcm/core/Error.hpp"
#include "cgcm/core/ParameterValidators.hpp"
#include "cgcm/interaction/Quadrature.hpp"

namespace cgcm::interaction {

PairPotential::PairPotential(Real epsilon, Real r0) : epsilon_(epsilon), r0_(r0) {
  if (!(epsilon > 0.0) || !std::isfinite(epsilon)) {
    std::ostringstream os;
    os << "pair potential: epsilon must be finite and > 0, got " << epsilon;
    throw InputError(os.str());
  }
  if (!(r0 > 0.0) || !std::isfinite(r0)) {
    std::ostringstream os;
    os << "pair potential: r0 must be finite and > 0, got " << r0;
    throw InputError(os.str());
  }
}

void PairPotential::halfSpaceWithDerivative(Real r, Real& value, Real& derivative) const {
  value = halfSpace(r);
  derivative = dHalfSpace(r);
}

// ---------------------------------------------------------------------------
// Numerical defaults. They scan r over [1e-3 r0, 1e3 r0] on a logarithmic
// grid; a potential whose features lie outside this range overrides them.

std::optional<Real> PairPotential::surfaceEquilibriumDistance() const {
  const int n = 3000;
  const Real lo = 1e-3 * r0_, hi = 1e3 * r0_;
  const Real ratio = std::pow(hi / lo, 1.0 / n);
  // outermost sign change, scanning inwards from large r; exact zeros (an
  // exponential tail underflows) are no sign
  Real rOut = hi, fOut = halfSpace(hi);
  for (int i = n - 1; i >= 0; --i) {
    const Real rIn = lo * std::pow(ratio, i);
    const Real fIn = halfSpace(rIn);
    if (fIn == 0.0) {
      if (fOut != 0.0) return rIn;
      continue;
    }
    if (fOut != 0.0 && (fIn > 0.0) != (fOut > 0.0)) {
      boost::uintmax_t iterations = 200;
      const auto root = boost::math::tools::toms748_solve([&](Real r) { return halfSpace(r); }, rIn, rOut, fIn, fOut,
                                                          boost::math::tools::eps_tolerance<Real>(50), iterations);
      return 0.5 * (root.first + root.second);
    }
    rOut = rIn;
    fOut = fIn;
  }
  return std::nullopt;
}

Real PairPotential::adhesionWorkCoefficient() const {
  const auto rs = surfaceEquilibriumDistance();
  if (!rs) return 0.0;
  // r = rs / u maps u in (0, 1] onto [rs, inf); dr = rs / u^2 du.
  const Real a = *rs;
  const GaussRule rule = gaussLegendreUnit(8);
  const Real integral =
      integrate([&](Real u) { return halfSpace(a / u) * a / (u * u); }, 0.0, 1.0, 400, rule);
  return -integral;
}

Real PairPotential::peakTractionCoefficient() const {
  const int n = 3000;
  const Real lo = 1e-3 * r0_, hi = 1e3 * r0_;
  const Real ratio = std::pow(hi / lo, 1.0 / n);
  int best = -1;
  Real bestValue = 0.0;
  for (int i = 0; i <= n; ++i) {
    const Real v = -halfSpace(lo * std::pow(ratio, i));
    if (v > bestValue) {
      bestValue = v;
      best = i;
    }
  }
  if (best < 0) return 0.0;
  // Brent's minimisation of halfSpace between the neighbouring samples
  const Real a = lo * std::pow(ratio, std::max(best - 1, 0)), b = lo * std::pow(ratio, std::min(best + 1, n));
  const auto minimum = boost::math::tools::brent_find_minima([&](Real r) { return halfSpace(r); }, a, b,
                                                             std::numeric_limits<Real>::digits / 2);
  return std::max(bestValue, -minimum.second);
}

// ---------------------------------------------------------------------------
// Lennard-Jones 12-6

Real LennardJones::phi(Real r) const {
  const Real q = r0() / r;
  const Real q6 = q * q * q * q * q * q;
  return epsilon() * (q6 * q6 - 2.0 * q6);
}

Real LennardJones::dphi(Real r) const {
  const Real q = r0() / r;
  const Real q6 = q * q * q * q * q * q;
  return -12.0 * epsilon() * (q6 * q6 - q6) / r;
}

KernelPotential LennardJones::kernelPotential() const {
  const Real r6 = std::pow(r0(), 6);
  return InversePowerPair{epsilon() * r6 * r6, 2.0 * epsilon() * r6};
}

KernelPotential RepulsiveLennardJones::kernelPotential() const {
  const Real r6 = std::pow(r0(), 6);
  return InversePowerPair{epsilon() * r6 * r6, 0.0};
}

Real LennardJones::halfSpace(Real r) const {
  const Real q = r0() / r;
  const Real q3 = q * q * q;
  const Real c = kPi * epsilon() * r0() * r0() * r0();
  return c * (q3 * q3 * q3 / 45.0 - q3 / 3.0);
}

Real LennardJones::dHalfSpace(Real r) const {
  const Real q = r0() / r;
  const Real q3 = q * q * q;
  const Real c = kPi * epsilon() * r0() * r0() * r0();
  return c * (q3 - q3 * q3 * q3 / 5.0) / r;
}

void LennardJones::halfSpaceWithDerivative(Real r, Real& value, Real& derivative) const {
  const Real q = r0() / r;
  const Real q3 = q * q * q;
  const Real q9 = q3 * q3 * q3;
  const Real c = kPi * epsilon() * r0() * r0() * r0();
  value = c * (q9 / 45.0 - q3 / 3.0);
  derivative = c * (q3 - q9 / 5.0) / r;
}

std::optional<Real> LennardJones::surfaceEquilibriumDistance() const { return surfaceEquilibriumDistance(r0()); }

Real LennardJones::surfaceEquilibriumDistance(Real r0) { return r0 / std::pow(15.0, 1.0 / 6.0); }

Real LennardJones::workFactor() { return kPi / 8.0 * std::cbrt(15.0); }

Real LennardJones::peakTractionFactor() { return 2.0 * std::sqrt(5.0) / 9.0 * kPi; }

Real LennardJones::adhesionWorkCoefficient() const {
  const Real r0v = r0();
  return workFactor() * epsilon() * r0v * r0v * r0v * r0v;
}

Real LennardJones::peakTractionCoefficient() const {
  const Real r0v = r0();
  return peakTractionFactor() * epsilon() * r0v * r0v * r0v;
}

// ---------------------------------------------------------------------------
// Repulsive-only

Real RepulsiveLennardJones::phi(Real r) const {
  const Real q = r0() / r;
  const Real q6 = q * q * q * q * q * q;
  return epsilon() * q6 * q6;
}

Real RepulsiveLennardJones::dphi(Real r) const {
  const Real q = r0() / r;
  const Real q6 = q * q * q * q * q * q;
  return -12.0 * epsilon() * q6 * q6 / r;
}

Real RepulsiveLennardJones::halfSpace(Real r) const {
  const Real q = r0() / r;
  const Real q3 = q * q * q;
  return kPi * epsilon() * r0() * r0() * r0() * q3 * q3 * q3 / 45.0;
}

Real RepulsiveLennardJones::dHalfSpace(Real r) const {
  const Real q = r0() / r;
  const Real q3 = q * q * q;
  return -kPi * epsilon() * r0() * r0() * r0() * q3 * q3 * q3 / (5.0 * r);
}

void RepulsiveLennardJones::halfSpaceWithDerivative(Real r, Real& value, Real& derivative) const {
  const Real q = r0() / r;
  const Real q3 = q * q * q;
  value = kPi * epsilon() * r0() * r0() * r0() * q3 * q3 * q3 / 45.0;
  derivative = -9.0 * value / r;
}

// ---------------------------------------------------------------------------

const std::vector<PotentialEntry>& potentialRegistry() {
  static const std::vector<PotentialEntry> entries = {
      {"Lennard-Jones", "adhesion and repulsion", nullptr,
       [](Real eps, Real r0, const Teuchos::ParameterList&) -> std::shared_ptr<const PairPotential> {
         return std::make_shared<LennardJones>(eps, r0);
       }},
      {"repulsive", "its r^-12 part only: a smooth barrier", nullptr,
       [](Real eps, Real r0, const Teuchos::ParameterList&) -> std::shared_ptr<const PairPotential> {
         return std::make_shared<RepulsiveLennardJones>(eps, r0);
       }},
      {"Morse", "exp(-2a(r - r0)) - 2 exp(-a(r - r0)) with a = Interaction/Morse/Inverse Width / r0",
       [](Teuchos::ParameterList& own) {
         own.set("Inverse Width", 6.0,
                 "a r0 of the Morse potential (>= 0.001): 6 matches Lennard-Jones's well depth, position and "
                 "curvature; larger is a narrower well of shorter range",
                 validators::atLeast(1e-3));
       },
       [](Real eps, Real r0, const Teuchos::ParameterList& own) -> std::shared_ptr<const PairPotential> {
         return std::make_shared<PlainPairPotential<MorsePair>>("morse", eps, r0,
                                                                MorsePair{eps, r0, own.get<double>("Inverse Width") / r0});
       }},
  };
  return entries;
}

std::shared_ptr<const PairPotential> makePotential(const std::string& name, Real epsilon, Real r0,
                                                   const Teuchos::ParameterList& own) {
  auto lower = [](std::string t) {
    for (char& c : t) c = char(std::tolower(static_cast<unsigned char>(c)));
    return t;
  };
  const std::string wanted = lower(name) == "lj" ? "lennard-jones" : lower(name);
  std::string allowed;
  for (const PotentialEntry& e : potentialRegistry()) {
    if (lower(e.deckName) == wanted) {
      Teuchos::ParameterList declared(e.deckName), given(own);
      if (e.declareParameters) e.declareParameters(declared);
      given.setName(std::string("Interaction/") + e.deckName);
      try {
        given.validateParametersAndSetDefaults(declared);
      } catch (const std::exception& err) {
        throw InputError(std::string("pair potential \"") + e.deckName + "\": " + err.what());
      }
      return e.make(epsilon, r0, given);
    }
    allowed += std::string(allowed.empty() ? "" : ", ") + "\"" + e.deckName + "\"";
  }
  throw InputError("pair potential: unknown name \"" + name + "\" (allowed: " + allowed + ")");
}

}  // namespace cgcm::interaction
