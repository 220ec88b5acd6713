#include "cgcm/material/MaterialParameters.hpp"

#include "cgcm/core/ParameterValidators.hpp"
#include "cgcm/io/Deck.hpp"

namespace cgcm::material {

using Teuchos::ParameterList;

Teuchos::RCP<const ParameterList> validParameters() {
  static const Teuchos::RCP<const ParameterList> valid = [] {
    auto list = Teuchos::rcp(new ParameterList("Material"));
    list->set("Young's Modulus", 1.0, "Y > 0", validators::atLeast(1e-300));
    list->set("Poisson's Ratio", 0.2, "nu, -1 < nu < 0.5", validators::between(-0.999999, 0.499999));
    list->set("Volumetric Energy", "(Lambda/2)(ln J)^2",
              "U(J): \"(Lambda/2)(ln J)^2\" (default) or \"(Lambda/4)(J^2-1-2 ln J)\"",
              validators::choices({"(Lambda/2)(ln J)^2", "(Lambda/4)(J^2-1-2 ln J)"}));
    list->set("Kinematics", "finite strain",
              "\"finite strain\" (default, Neo-Hookean) or \"small strain\": the model linearised about the "
              "reference configuration (linear elasticity with the same Y, nu), to measure what finite strain "
              "changes",
              validators::choices({"finite strain", "small strain"}));
    return Teuchos::RCP<const ParameterList>(list);
  }();
  return valid;
}

NeoHookean fromParameters(const ParameterList& material) {
  const auto law = material.get<std::string>("Volumetric Energy") == "(Lambda/2)(ln J)^2" ? VolumetricLaw::LogSquared
                                                                                           : VolumetricLaw::QuadraticJ;
  auto m = NeoHookean::fromYoungPoisson(material.get<double>("Young's Modulus"),
                                        material.get<double>("Poisson's Ratio"), law);
  if (material.get<std::string>("Kinematics") == "small strain") m.kinematics = Kinematics::SmallStrain;
  return m;
}

NeoHookean fromParameters(const ParameterList& material, const ParameterList& overrides, const std::string& path) {
  ParameterList checked = overrides;  // the deck checker's messages, with `path` in front
  io::validateDeck(checked, *validParameters(), path);
  ParameterList own = material;
  for (auto it = overrides.begin(); it != overrides.end(); ++it)
    own.setEntry(overrides.name(it), checked.getEntry(overrides.name(it)));
  return fromParameters(own);
}

}  // namespace cgcm::material
