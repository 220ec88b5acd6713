#include "cgcm/analytic/Models.hpp"

#include <cmath>
#include <sstream>

#include "cgcm/analytic/MaugisDugdale.hpp"
#include "cgcm/core/Error.hpp"

namespace cgcm::analytic {
namespace {


void requireRadius(Real a) {
  if (!(std::isfinite(a) && a > 0)) {
    std::ostringstream msg;
    msg << "contact radius a must be finite and > 0, got " << a;
    throw InputError(msg.str());
  }
}

}  // namespace

Model parseModel(std::string_view name) {
  if (name == "hertz") return Model::Hertz;
  if (name == "jkr") return Model::Jkr;
  if (name == "dmt") return Model::Dmt;
  if (name == "md") return Model::MaugisDugdale;
  throw InputError("unknown model '" + std::string(name) + "' (allowed: " +
                   std::string(kModelNames) + ")");
}

std::string_view modelName(Model model) {
  switch (model) {
    case Model::Hertz: return "hertz";
    case Model::Jkr: return "jkr";
    case Model::Dmt: return "dmt";
    case Model::MaugisDugdale: return "md";
  }
  return "?";
}

JohnsonGreenwoodScales JohnsonGreenwoodScales::from(Real w, Real R, Real Estar) {
  if (!(std::isfinite(w) && w > 0 && std::isfinite(R) && R > 0 && std::isfinite(Estar) &&
        Estar > 0)) {
    std::ostringstream msg;
    msg << "Johnson-Greenwood scales need w, R, E* finite and > 0, got w = " << w << ", R = " << R
        << ", E* = " << Estar;
    throw InputError(msg.str());
  }
  JohnsonGreenwoodScales s;
  s.force = kPi * w * R;
  s.length = std::cbrt(3 * kPi * w * R * R / (4 * Estar));
  s.approach = std::cbrt(9 * kPi * kPi * w * w * R / (16 * Estar * Estar));
  s.pressure = std::cbrt(2 * kPi * w * Estar * Estar / (9 * R));
  return s;
}

ContactModel ContactModel::maugisDugdale(Real lambda) {
  if (!(std::isfinite(lambda) && lambda > 0)) {
    std::ostringstream msg;
    msg << "Maugis-Dugdale lambda must be finite and > 0, got " << lambda;
    throw InputError(msg.str());
  }
  return ContactModel(Model::MaugisDugdale, lambda);
}

ContactModel ContactModel::make(Model model, std::optional<Real> lambda) {
  if (model == Model::MaugisDugdale) {
    if (!lambda) throw InputError("model md needs lambda (the transition parameter (41))");
    return maugisDugdale(*lambda);
  }
  if (lambda) {
    throw InputError("lambda applies only to model md, not to " + std::string(modelName(model)));
  }
  return ContactModel(model, 0);
}

std::string ContactModel::describe() const {
  std::ostringstream out;
  out << modelName(kind_);
  if (kind_ == Model::MaugisDugdale) out << "(lambda=" << lambda_ << ")";
  return out.str();
}

CurvePoint ContactModel::at(Real a) const {
  requireRadius(a);
  switch (kind_) {
    case Model::Hertz:  // (37)
      return {a, a * a * a, a * a};
    case Model::Jkr:  // (39)
      return {a, a * a * a - std::sqrt(6 * a * a * a), a * a - (2.0 / 3.0) * std::sqrt(6 * a)};
    case Model::Dmt:  // (40)
      return {a, a * a * a - 2, a * a};
    case Model::MaugisDugdale: {
      const MdSolution sol = solveMaugisDugdale(lambda_, a);
      return {a, sol.load, sol.approach};
    }
  }
  return {};
}

CurveSlopes ContactModel::slopes(Real a) const {
  requireRadius(a);
  switch (kind_) {
    case Model::Hertz:
    case Model::Dmt:
      return {3 * a * a, 2 * a};
    case Model::Jkr:
      // d/dā of ā³ − √6 ā^(3/2) and of ā² − (2/3)√6 ā^(1/2).
      return {3 * a * a - 1.5 * std::sqrt(6 * a), 2 * a - std::sqrt(6.0) / (3 * std::sqrt(a))};
    case Model::MaugisDugdale: {
      const MdSlopes d = mdSlopes(solveMaugisDugdale(lambda_, a));
      return {d.dLoad, d.dApproach};
    }
  }
  return {};
}

CurvePoint ContactModel::atZeroContact() const {
  switch (kind_) {
    case Model::Hertz:
    case Model::Jkr:
      return {0, 0, 0};
    case Model::Dmt:
      return {0, -2, 0};
    case Model::MaugisDugdale: {
      const MdZeroContact z = mdZeroContactLimit(lambda_);
      return {0, z.load, z.approach};
    }
  }
  return {};
}

Real ContactModel::outerRadius(Real a) const {
  requireRadius(a);
  if (kind_ == Model::MaugisDugdale) return solveMaugisDugdale(lambda_, a).m * a;
  return a;
}

}  // namespace cgcm::analytic
