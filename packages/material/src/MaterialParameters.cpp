#include "cgcm/material/MaterialParameters.hpp"

#include <algorithm>
#include <sstream>

#include "cgcm/core/Error.hpp"
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

Teuchos::RCP<const ParameterList> validBodiesParameters() {
  static const Teuchos::RCP<const ParameterList> valid = [] {
    auto list = Teuchos::rcp(new ParameterList("Bodies"));
    list->disableRecursiveValidation();  // the body names are the mesh's: bodyMaterials checks them
    return Teuchos::RCP<const ParameterList>(list);
  }();
  return valid;
}

std::vector<NeoHookean> bodyMaterials(const ParameterList& material, const ParameterList& bodies,
                                      const std::vector<std::string>& names, const std::vector<std::string>& originals,
                                      std::vector<std::string>& report) {
  std::string known;
  for (const auto& n : names) known += (known.empty() ? "\"" : ", \"") + n + "\"";
  std::vector<NeoHookean> materials(names.size(), fromParameters(material));
  std::vector<char> hasEntry(names.size(), 0);
  for (auto it = bodies.begin(); it != bodies.end(); ++it) {
    const std::string name = bodies.name(it);
    if (!bodies.isSublist(name))
      throw InputError("Bodies/" + name + ": a sublist named after a body is expected; the bodies are " + known);
    const auto found = std::find(names.begin(), names.end(), name);
    if (found == names.end())
      throw InputError("Bodies/" + name + ": the mesh has no body of that name; its bodies are " + known);
    const std::size_t b = std::size_t(found - names.begin());
    ParameterList own = bodies.sublist(name);
    own.remove(kRigidParameter, false);  // rigidBodies reads it
    materials[b] = fromParameters(material, own, "Bodies/" + name + "/");
    hasEntry[b] = 1;
    std::ostringstream o;
    o << "body \"" << name << "\": Young's modulus " << materials[b].youngsModulus() << ", Poisson's ratio "
      << materials[b].poissonRatio();
    report.push_back(o.str());
  }
  for (std::size_t b = 0; b < names.size(); ++b) {
    if (hasEntry[b] || originals.at(b) == names[b]) continue;
    const auto original = std::find(names.begin(), names.end(), originals[b]);
    if (original == names.end() || !hasEntry[std::size_t(original - names.begin())]) continue;
    materials[b] = materials[std::size_t(original - names.begin())];
    report.push_back("body \"" + names[b] + "\": the material of \"" + originals[b] + "\" (its mirror image)");
  }
  return materials;
}

std::vector<char> rigidBodies(const ParameterList& bodies, const std::vector<std::string>& names,
                              const std::vector<std::string>& originals, std::vector<std::string>& report) {
  std::vector<char> rigid(names.size(), 0), hasEntry(names.size(), 0);
  for (std::size_t b = 0; b < names.size(); ++b) {
    if (!bodies.isSublist(names[b]) || !bodies.sublist(names[b]).isParameter(kRigidParameter)) continue;
    const auto& own = bodies.sublist(names[b]);
    const std::string path = "Bodies/" + names[b] + "/" + kRigidParameter;
    if (own.isType<bool>(kRigidParameter)) {
      rigid[b] = own.get<bool>(kRigidParameter);
    } else if (own.isType<std::string>(kRigidParameter)) {  // from the command line: "true" or "false"
      const std::string v = own.get<std::string>(kRigidParameter);
      if (v != "true" && v != "false") throw InputError(path + " = \"" + v + "\": allowed values are true, false");
      rigid[b] = v == "true";
    } else {
      throw InputError(path + ": a bool is expected (true or false)");
    }
    hasEntry[b] = 1;
  }
  for (std::size_t b = 0; b < names.size(); ++b) {
    if (!hasEntry[b] && originals.at(b) != names[b]) {
      const auto original = std::find(names.begin(), names.end(), originals[b]);
      if (original != names.end()) rigid[b] = rigid[std::size_t(original - names.begin())];
    }
    if (rigid[b]) report.push_back("body \"" + names[b] + "\": rigid (moved as a whole by its conditions)");
  }
  return rigid;
}

}  // namespace cgcm::material
