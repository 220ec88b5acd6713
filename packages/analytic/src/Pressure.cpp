#include "cgcm/analytic/Pressure.hpp"

#include <cmath>
#include <limits>
#include <sstream>

#include "cgcm/analytic/MaugisDugdale.hpp"
#include "cgcm/analytic/Quadrature.hpp"
#include "cgcm/core/Error.hpp"

namespace cgcm::analytic {
namespace {
}

PressureProfile::PressureProfile(const ContactModel& model, Real a)
    : kind_(model.kind()), a_(a), c_(a) {
  if (!(std::isfinite(a) && a > 0)) {
    std::ostringstream msg;
    msg << "pressure: contact radius a must be finite and > 0, got " << a;
    throw InputError(msg.str());
  }
  hertz_ = 3 * a / kPi;
  scale_ = hertz_;
  load_ = kind_ == Model::MaugisDugdale ? 0 : model.at(a).load;  // M-D: below
  contactLoad_ = load_;
  switch (kind_) {
    case Model::Hertz:
      break;
    case Model::Dmt:
      contactLoad_ = a * a * a;  // P̄ + 2: the adhesive −2 acts at infinity
      break;
    case Model::Jkr:
      // The flat-punch term −C/√(1−ρ²) carries π ∫ r (−C/√(1−ρ²)) dr = −π C ā²,
      // which must equal the adhesive part −√(6ā³) of (39): C = √(6/ā)/π.
      jkr_ = std::sqrt(6 / a) / kPi;
      scale_ = std::fmax(scale_, jkr_);
      break;
    case Model::MaugisDugdale: {
      const MdSolution sol = solveMaugisDugdale(model.lambda(), a);
      lambda_ = model.lambda();
      s_ = sol.s;
      c_ = sol.m * a;
      load_ = contactLoad_ = sol.load;
      scale_ = std::fmax(scale_, lambda_);
      break;
    }
  }
}

Real PressureProfile::inside(Real u) const {
  Real p = hertz_ * u;
  if (kind_ == Model::Jkr) p -= jkr_ / u;
  // atan2(s, u) = atan(s/u) for u > 0, and π/2 at u = 0 (the value −λ at r = a).
  if (kind_ == Model::MaugisDugdale) p -= (2 * lambda_ / kPi) * std::atan2(s_, u);
  return p;
}

Real PressureProfile::operator()(Real r) const {
  if (!(r >= 0) || std::isinf(r)) {
    std::ostringstream msg;
    msg << "pressure: radius r must be finite and >= 0, got " << r;
    throw InputError(msg.str());
  }
  if (r < a_) {
    const Real rho = r / a_;
    return inside(std::sqrt((1 - rho) * (1 + rho)));
  }
  switch (kind_) {
    case Model::Jkr:
      return r == a_ ? -std::numeric_limits<Real>::infinity() : 0;
    case Model::MaugisDugdale:
      return r <= c_ ? -lambda_ : 0;
    default:
      return 0;
  }
}

Real PressureProfile::nearEdge(Real t) const {
  if (!(t > 0 && t <= 1)) {
    std::ostringstream msg;
    msg << "pressure: edge coordinate t must lie in (0, 1], got " << t;
    throw InputError(msg.str());
  }
  return inside(t * std::sqrt(2 - t * t));
}

Real PressureProfile::integratedLoad(Real relTol) const {
  const Real tol = relTol * (scale_ * a_ * a_ + std::fabs(load_));
  // [0, a] with r = ā(1 − t²), dr = 2ā t dt: the JKR term ~ 1/√(1−ρ²) ~ 1/t
  // becomes bounded and the square-root edges become smooth.
  auto inner = [&](Real t) { return a_ * (1 - t * t) * nearEdge(t) * 2 * a_ * t; };
  Real sum = integrateAdaptive(inner, {0.0, 1.0}, 0.5 * tol, 0.0, 2000, "pressure integral").value;
  if (c_ > a_) {
    auto outer = [&](Real r) { return r * (*this)(r); };
    sum += integrateAdaptive(outer, {a_, c_}, 0.5 * tol, 0.0, 2000, "pressure integral").value;
  }
  return kPi * sum;
}

}  // namespace cgcm::analytic
