#pragma once
// Turns a validated deck into a concrete problem: mesh, boundary conditions
// and the force responses written to the load curve.
#include <Teuchos_ParameterList.hpp>

#include <memory>
#include <string>
#include <vector>

#include "cgcm/assembly/Assembler.hpp"
#include "cgcm/material/NeoHookean.hpp"
#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::app {

/// u_component = offset + scale * (load parameter) on every node of a node set.
struct DisplacementCondition {
  std::string nodeSet;
  int component;
  Real offset;
  Real scale;
};

/// A resultant force: sign * sum of the internal force over a node set.
struct ForceResponse {
  std::string nodeSet;
  int component;
  Real sign;
};

struct ProblemSetup {
  std::shared_ptr<mesh::Mesh> mesh;
  assembly::Formulation formulation;
  material::NeoHookean material;
  std::vector<DisplacementCondition> conditions;
  ForceResponse load;  ///< the "P" column of the load curve
};

/// Every parameter a deck may hold, with defaults and documentation.
Teuchos::RCP<const Teuchos::ParameterList> validParameters();

/// Builds the problem a validated deck describes. Throws InputError for
/// combinations that the validators alone cannot reject.
ProblemSetup buildProblem(const Teuchos::ParameterList& deck);

assembly::Formulation parseFormulation(const std::string& name);

}  // namespace cgcm::app
