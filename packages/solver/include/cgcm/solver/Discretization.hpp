#pragma once
// From a problem's set-up (formulation, materials, the model of mesh::buildModel,
// the interaction) to the discrete problem on the ranks: each rank's subdomain of
// the mesh and its dofs, the assembled problem, the Dirichlet conditions and
// the ModelEvaluator. Rank 0 alone holds (meshes, reads) the whole mesh and
// sends the others their subdomains.
#include <Teuchos_Comm.hpp>
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

namespace cgcm::solver {

/// What a run solves: the formulation, the bodies' materials, the model (mesh,
/// conditions, responses) and the interaction between the bodies.
struct ProblemSetup {
  Formulation formulation = Formulation::Axisymmetric;
  material::NeoHookean material;  ///< every body's unless bodyMaterials says otherwise
  /// Per body (index = body id): its own material; empty: `material` everywhere.
  std::vector<material::NeoHookean> bodyMaterials;
  /// The mesh (rank 0 only, when rank 0 built the set-up for every rank), its conditions and force responses.
  mesh::Model model;
  std::optional<interaction::InteractionSetup> interaction;  ///< when the bodies interact
  std::vector<std::string> report;  ///< scales and derived parameters, printed at the start of a run
  assembly::CellPartition partition = assembly::CellPartition::Geometric;  ///< how the cells are split over ranks
  /// Force scale F_ref of the convergence test: the paper's force unit
  /// E0/R0 = Y R0^2 for contact (Y R0 per unit thickness in plane strain), Y
  /// times the loaded area for a block.
  Real forceScale = 1.0;
  std::size_t numNodes = 0, numCells = 0;  ///< of the whole mesh (every rank knows them, held or not)
};

/// Runs `work` on rank 0 only; what it throws is thrown on every rank with its message (an InputError
/// as InputError, a NumericalError as NumericalError, anything else as std::runtime_error; rank 0
/// rethrows its own). Collective.
void runOnRoot(const Teuchos::Comm<int>& comm, const std::function<void()>& work);
/// Rank 0's `bytes` on every rank. Collective.
void broadcastBytes(const Teuchos::Comm<int>& comm, std::vector<char>& bytes);
/// Runs `decode` (of bytes another rank sent) on every rank; if it fails on any, every rank throws
/// (the ranks stay in step). Collective.
void decodeOnEveryRank(const Teuchos::Comm<int>& comm, const std::function<void()>& decode);

/// The mesh a rank assembles, and its dofs.
struct Distribution {
  std::shared_ptr<const mesh::Mesh> mesh;  ///< Discretization::mesh
  Teuchos::RCP<assembly::DofMap> dofs;
};

/// One rank: the set-up's mesh. Several: rank 0 partitions its mesh (setup.partition) and sends each
/// rank its subdomain (mesh::subdomain, with the contact probe's apex nodes); Method 1: the whole mesh to
/// every rank. The other ranks' `setup.model.mesh`, if any, is not read. Collective.
Distribution distribute(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const ProblemSetup& setup);

/// The discrete problem of a set-up: dof distribution, problem (with the
/// interaction when there is one), Dirichlet conditions and ModelEvaluator,
/// whose p(0) is (u, gammaW, gammaL) with an interaction and (u) without.
struct Discretization {
  /// The mesh this rank assembles: on several ranks its subdomain of the set-up's mesh (mesh::subdomain: its
  /// cells, their nodes and their surface facets), except with Method 1, whose pairs need the whole mesh.
  std::shared_ptr<const mesh::Mesh> mesh;
  Teuchos::RCP<assembly::DofMap> dofs;
  std::shared_ptr<assembly::Problem> problem;
  std::shared_ptr<assembly::DirichletConditions> dirichlet;
  Teuchos::RCP<ModelEvaluator> model;
};

/// Distributes (distribute()) and assembles `setup` on `comm`. Collective.
Discretization discretize(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const ProblemSetup& setup,
                          Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> linearSolver);
/// The same, with the linear solver built from a validated "Linear Solver"
/// sublist (and, when asked for, the rigid-body modes of the mesh).
Discretization discretize(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const ProblemSetup& setup,
                          const Teuchos::ParameterList& linearSolver);

}  // namespace cgcm::solver
