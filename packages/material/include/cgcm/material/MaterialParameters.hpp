#pragma once
// The deck's Material sublist, declared and read here: its parameters with
// defaults and help, the NeoHookean they describe, and per-body overrides
// (Bodies/<name>) checked like the sublist itself.
#include <Teuchos_ParameterList.hpp>

#include <string>
#include <vector>

#include "cgcm/material/NeoHookean.hpp"

namespace cgcm::material {

/// The Material sublist: Young's Modulus, Poisson's Ratio, Volumetric Energy, Kinematics.
Teuchos::RCP<const Teuchos::ParameterList> validParameters();

/// The material of a validated Material sublist (defaults filled).
NeoHookean fromParameters(const Teuchos::ParameterList& material);

/// One body's material: the validated `material` sublist with the entries of
/// `overrides` (any of its parameters) replacing its own. The overrides are
/// checked as the sublist is: unknown names, text that is not a number and
/// values out of range throw InputError naming `path` + the parameter.
NeoHookean fromParameters(const Teuchos::ParameterList& material, const Teuchos::ParameterList& overrides,
                          const std::string& path);

/// The Bodies sublist: a sublist per body, named after it, with any of Material's parameters and Rigid.
Teuchos::RCP<const Teuchos::ParameterList> validBodiesParameters();

/// Per body (index = body id; `names` the bodies' names): the validated `material` with the
/// entries of bodies/<name> replacing its own (each checked as fromParameters does); a body
/// without an entry whose `original` (a mirror image's: the body it was made of; else itself)
/// has one takes the original's. Appends a line per body with a material of its own to
/// `report`. Throws InputError naming Bodies/<name> for a name no body has or an entry that is
/// not a sublist.
std::vector<NeoHookean> bodyMaterials(const Teuchos::ParameterList& material, const Teuchos::ParameterList& bodies,
                                      const std::vector<std::string>& names, const std::vector<std::string>& originals,
                                      std::vector<std::string>& report);

/// The name of the per-body flag that makes a body rigid (Bodies/<name>/Rigid, bool, default false): the
/// limit of an infinitely stiff material, the body moved as a whole by its conditions (mesh::makeRigid).
/// bodyMaterials ignores it; rigidBodies reads it.
inline constexpr const char* kRigidParameter = "Rigid";

/// Per body (index = body id): 1 where bodies/<name>/Rigid is true; a mirror image without an entry
/// follows its original, as bodyMaterials does. Throws InputError naming Bodies/<name>/Rigid when it
/// is not a bool. Appends a line per rigid body to `report`.
std::vector<char> rigidBodies(const Teuchos::ParameterList& bodies, const std::vector<std::string>& names,
                              const std::vector<std::string>& originals, std::vector<std::string>& report);

}  // namespace cgcm::material
