#pragma once
// The mesh a rank assembles, and its dofs: what discretize() builds on.
#include <memory>

#include "cgcm/app/Setup.hpp"

namespace cgcm::app {

struct Distribution {
  std::shared_ptr<const mesh::Mesh> mesh;  ///< Discretization::mesh
  Teuchos::RCP<assembly::DofMap> dofs;
};

/// What the deck alone gives (every rank builds it): formulation, material, partition.
ProblemSetup setupFromDeck(const Teuchos::ParameterList& deck);
/// Joins a model to the deck's set-up: the force scale, the interaction when the bodies interact (read
/// from the deck if not yet) with its report lines, the model's lines.
void attachModel(ProblemSetup& setup, mesh::Model model, const Teuchos::ParameterList& deck);

/// One rank: the set-up's mesh. Several: rank 0 partitions its mesh (Solver/Partition) and sends each
/// rank its part (mesh::localPart, with the contact probe's apex nodes); Method 1: the whole mesh to
/// every rank. Collective.
Distribution distribute(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const ProblemSetup& setup);

}  // namespace cgcm::app
