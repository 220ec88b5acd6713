#pragma once
// Turns a validated deck into a concrete problem: mesh, boundary conditions
// and the force responses written to the load curve.
#include <Teuchos_ParameterList.hpp>

#include <string>

#include "cgcm/solver/Discretization.hpp"

namespace cgcm::app {

/// Every parameter a deck may hold, with defaults and documentation.
Teuchos::RCP<const Teuchos::ParameterList> validParameters();

/// Makes a relative Geometry/File and Geometry/Mesh Cache absolute, taking them from the folder of the
/// deck file `deckPath` (before validation; nothing to do without one).
void resolveMeshFile(Teuchos::ParameterList& deck, const std::string& deckPath);

/// Builds the problem a validated deck describes. Throws InputError for
/// combinations that the validators alone cannot reject.
solver::ProblemSetup buildProblem(const Teuchos::ParameterList& deck);
/// The same on several ranks: rank 0 builds the problem (it alone meshes and reads mesh files) and
/// sends the others its model without the mesh, the body materials and the report; they read the
/// rest of the deck themselves (their `model.mesh` is null; solver::discretize() gives each its subdomain as
/// solver::Discretization::mesh). What rank 0's build throws, every rank throws. Collective.
solver::ProblemSetup buildProblem(const Teuchos::Comm<int>& comm, const Teuchos::ParameterList& deck);

}  // namespace cgcm::app
