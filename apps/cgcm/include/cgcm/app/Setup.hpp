#pragma once
// Turns a validated deck into a concrete problem: mesh, boundary conditions
// and the force responses written to the load curve.
#include <Teuchos_ParameterList.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cgcm/assembly/Problem.hpp"
#include "cgcm/interaction/InteractionSetup.hpp"
#include "cgcm/material/NeoHookean.hpp"
#include "cgcm/mesh/Geometry.hpp"
#include "cgcm/solver/ModelEvaluator.hpp"

namespace cgcm::app {

/// What a run solves: the formulation, the bodies' materials, the model (mesh,
/// conditions, responses) and the interaction between the bodies.
struct ProblemSetup {
  Formulation formulation = Formulation::Axisymmetric;
  material::NeoHookean material;  ///< the deck's Material: every body's unless bodyMaterials says otherwise
  /// Per body (index = body id): Material overridden by Bodies/<name>; empty: `material` everywhere.
  std::vector<material::NeoHookean> bodyMaterials;
  /// The mesh (null on ranks other than 0 of buildProblem(comm, deck)), its conditions and force responses.
  mesh::Model model;
  std::optional<interaction::InteractionSetup> interaction;  ///< when the bodies interact
  std::vector<std::string> report;  ///< scales and derived parameters, printed at the start of a run
  assembly::CellPartition partition = assembly::CellPartition::Geometric;  ///< Solver/Partition
  /// Force scale F_ref of the convergence test: the paper's force unit
  /// E0/R0 = Y R0^2 for contact (Y R0 per unit thickness in plane strain), Y
  /// times the loaded area for a block.
  Real forceScale = 1.0;
  std::size_t numNodes = 0, numCells = 0;  ///< of the whole mesh (every rank knows them, held or not)
};

/// Every parameter a deck may hold, with defaults and documentation.
Teuchos::RCP<const Teuchos::ParameterList> validParameters();

/// Makes a relative Geometry/File absolute, taking it from the folder of the
/// deck file `deckPath` (before validation; nothing to do without one).
void resolveMeshFile(Teuchos::ParameterList& deck, const std::string& deckPath);

/// Runs `work` on rank 0 only; what it throws is thrown on every rank with its message (an InputError
/// as InputError, a NumericalError as NumericalError, anything else as std::runtime_error; rank 0
/// rethrows its own). Collective.
void runOnRoot(const Teuchos::Comm<int>& comm, const std::function<void()>& work);

/// Builds the problem a validated deck describes. Throws InputError for
/// combinations that the validators alone cannot reject.
ProblemSetup buildProblem(const Teuchos::ParameterList& deck);
/// The same on several ranks: rank 0 builds the problem (it alone meshes and reads mesh files) and
/// sends the others its model without the mesh, the body materials and the report; they read the
/// rest of the deck themselves (their `model.mesh` is null; discretize() gives each its part as
/// Discretization::mesh). What rank 0's build throws, every rank throws. Collective.
ProblemSetup buildProblem(const Teuchos::Comm<int>& comm, const Teuchos::ParameterList& deck);

/// The discrete problem of a set-up: dof distribution, problem (with the
/// interaction when there is one), Dirichlet conditions and ModelEvaluator,
/// whose p(0) is (u, gammaW, gammaL) with an interaction and (u) without.
struct Discretization {
  /// The mesh this rank assembles: on several ranks its part of the set-up's mesh (mesh::localPart: its
  /// cells, their nodes and the whole surfaces), except with Method 1, whose pairs need the whole mesh.
  std::shared_ptr<const mesh::Mesh> mesh;
  Teuchos::RCP<assembly::DofMap> dofs;
  std::shared_ptr<assembly::Problem> problem;
  std::shared_ptr<assembly::DirichletConditions> dirichlet;
  Teuchos::RCP<solver::ModelEvaluator> model;
};

/// Distributes and assembles `setup` on `comm`: rank 0 partitions its mesh and sends every rank its
/// part (Method 1: the whole mesh); the other ranks' `setup.model.mesh`, if any, is not read. Collective.
Discretization discretize(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const ProblemSetup& setup,
                          Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> linearSolver);
/// The same, with the linear solver built from a validated "Linear Solver"
/// sublist (and, when asked for, the rigid-body modes of the mesh).
Discretization discretize(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const ProblemSetup& setup,
                          const Teuchos::ParameterList& linearSolver);

}  // namespace cgcm::app
