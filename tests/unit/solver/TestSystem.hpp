#pragma once
// The system tests' problems from the packages alone, as the app builds them:
// a deck of the packages' sublists under the app's names, its set-up (the
// model of mesh::buildModel, the material, the interaction when the bodies
// interact, the force scale) and, through solver::discretize, the discrete
// problem on the test's ranks.
#include <Teuchos_ParameterList.hpp>

#include <string>

#include "cgcm/core/ParameterValidators.hpp"
#include "cgcm/material/MaterialParameters.hpp"
#include "cgcm/solver/Discretization.hpp"
#include "cgcm/solver/LinearSolver.hpp"
#include "cgcm/solver/NewtonSolver.hpp"
#include "cgcm/solver/PathFollower.hpp"

namespace cgcm::test {

/// What a system test's deck may hold: Problem/Formulation, Geometry, Material, Interaction, Loading,
/// Solver/Partition, Solver/Newton and Solver/Linear Solver, with the packages' defaults.
inline Teuchos::RCP<const Teuchos::ParameterList> deckParameters() {
  static Teuchos::RCP<Teuchos::ParameterList> valid;
  if (!valid.is_null()) return valid;
  valid = Teuchos::rcp(new Teuchos::ParameterList("cgcm"));
  valid->sublist("Problem").set("Formulation", "axisymmetric", "kinematics",
                                validators::choices({"plane strain", "axisymmetric", "3D"}));
  valid->sublist("Geometry") = *mesh::validParameters();
  valid->sublist("Material") = *material::validParameters();
  valid->sublist("Interaction") = *interaction::validParameters();
  valid->sublist("Loading") = *solver::PathPlan::validParameters();
  auto& solverList = valid->sublist("Solver");
  solverList.setParameters(*assembly::validParameters());
  solverList.sublist("Newton").setParameters(*solver::NewtonSettings::validParameters());
  solverList.sublist("Linear Solver").setParameters(*solver::linearSolverValidParameters());
  return valid;
}

/// The set-up of a deck validated against deckParameters(), on this rank alone (it builds the whole mesh;
/// solver::discretize gives each rank its subdomain of rank 0's).
inline solver::ProblemSetup setupOf(const Teuchos::ParameterList& deck) {
  solver::ProblemSetup s;
  s.formulation = parseFormulation(deck.sublist("Problem").get<std::string>("Formulation"));
  s.material = material::fromParameters(deck.sublist("Material"));
  s.partition = assembly::parseCellPartition(deck.sublist("Solver").get<std::string>("Partition"));
  const auto& geometry = deck.sublist("Geometry");
  auto readInteraction = [&]() -> const interaction::InteractionSetup& {
    if (!s.interaction)
      s.interaction = interaction::fromParameters(
          deck.sublist("Interaction"),
          {geometry.get<double>("Sphere Radius"), s.material.youngsModulus(), s.material.poissonRatio(),
           mesh::reducedRadius(geometry)},
          s.formulation);
    return *s.interaction;
  };
  s.model = mesh::buildModel(geometry, s.formulation, [&] { return readInteraction().contactDistance(); });
  if (s.model.interacting) readInteraction();
  s.forceScale = s.model.forceScale(s.material.youngsModulus());
  s.numNodes = std::size_t(s.model.mesh->numNodes());
  s.numCells = std::size_t(s.model.mesh->numCells());
  return s;
}

}  // namespace cgcm::test
