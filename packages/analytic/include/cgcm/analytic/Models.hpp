#pragma once
// Closed-form adhesive contact of a sphere on a half-space: Hertz, JKR, DMT
// and Maugis-Dugdale, all in the Johnson-Greenwood normalisation (36):
//
//   P̄ = P/(π w R),            ā = a (4E*/(3π w R²))^(1/3),
//   δ̄ = δ (16E*²/(9π² w² R))^(1/3),   p̄ = p (9R/(2π w E*²))^(1/3),
//
// with w the work of adhesion, R the combined radius (34) and E* the combined
// modulus (35). Radii r of the pressure and stress fields are normalised like
// ā. P > 0 is compressive, δ > 0 an approach (interpenetration of the
// undeformed profiles).
#include <optional>
#include <string>
#include <string_view>

#include "cgcm/core/Types.hpp"

namespace cgcm::analytic {

enum class Model { Hertz, Jkr, Dmt, MaugisDugdale };

/// Range of λ over which the Maugis-Dugdale solver is swept by the tests and
/// which the app accepts. The library itself takes any finite λ > 0.
inline constexpr Real kLambdaMin = 1e-3;
inline constexpr Real kLambdaMax = 1e3;

/// The names accepted by parseModel, for messages.
inline constexpr std::string_view kModelNames = "hertz, jkr, dmt, md";

/// "hertz", "jkr", "dmt" or "md"; throws InputError naming the allowed values.
Model parseModel(std::string_view name);
std::string_view modelName(Model model);

/// The scales of (36): a physical quantity is its normalised value times the
/// scale, e.g. P = P̄ · force, a = ā · length, r = r̄ · length.
struct JohnsonGreenwoodScales {
  Real force = 0;     ///< π w R
  Real length = 0;    ///< (3π w R² / (4E*))^(1/3), for a and r (and z)
  Real approach = 0;  ///< (9π² w² R / (16 E*²))^(1/3)
  Real pressure = 0;  ///< (2π w E*² / (9R))^(1/3), for p and σ

  /// w > 0, R > 0, E* > 0 (InputError otherwise).
  static JohnsonGreenwoodScales from(Real w, Real R, Real Estar);
};

/// A point of a model's equilibrium curve, normalised: contact radius ā,
/// load P̄, approach δ̄.
struct CurvePoint {
  Real a = 0;
  Real load = 0;
  Real approach = 0;
};

/// Derivatives of P̄ and δ̄ with respect to ā along the curve.
struct CurveSlopes {
  Real dLoad = 0;
  Real dApproach = 0;
};

/// One of the four models; for Maugis-Dugdale it carries λ (41).
class ContactModel {
 public:
  static ContactModel hertz() { return ContactModel(Model::Hertz, 0); }
  static ContactModel jkr() { return ContactModel(Model::Jkr, 0); }
  static ContactModel dmt() { return ContactModel(Model::Dmt, 0); }
  /// λ finite and > 0 (InputError otherwise).
  static ContactModel maugisDugdale(Real lambda);
  /// λ is required for Maugis-Dugdale and must be absent for the others
  /// (InputError otherwise), so that a λ given by mistake is not ignored.
  static ContactModel make(Model model, std::optional<Real> lambda);

  Model kind() const { return kind_; }
  /// λ of a Maugis-Dugdale model; 0 for the others.
  Real lambda() const { return lambda_; }
  /// e.g. "md(lambda=0.25)" or "jkr".
  std::string describe() const;

  /// The curve at contact radius ā > 0 (InputError for ā ≤ 0 or non-finite).
  CurvePoint at(Real a) const;
  /// dP̄/dā and dδ̄/dā at ā > 0.
  CurveSlopes slopes(Real a) const;
  /// The limit ā → 0⁺ of the contact branch: Hertz and JKR end at P̄ = δ̄ = 0,
  /// DMT at P̄ = −2, δ̄ = 0, Maugis-Dugdale at a finite adhesive zone
  /// (see mdZeroContactLimit).
  CurvePoint atZeroContact() const;
  /// Outer radius of the loaded zone: c̄ = m ā for Maugis-Dugdale, ā otherwise.
  Real outerRadius(Real a) const;

 private:
  ContactModel(Model kind, Real lambda) : kind_(kind), lambda_(lambda) {}
  Model kind_;
  Real lambda_;
};

}  // namespace cgcm::analytic
