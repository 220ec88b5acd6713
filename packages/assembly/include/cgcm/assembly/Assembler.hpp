#pragma once
// Assembly of the bulk internal force and tangent into Tpetra objects.
//
// Element kernels (package fem) run in a Kokkos::parallel_for over the cells
// this rank owns and scatter into overlap (owned + shared) views with atomic
// adds; Tpetra then sums shared rows into their owners. The matrix graph is
// the union of the cell cliques and optional extra node couplings (interaction
// pairs), which may be replaced between solves.
#include <array>
#include <memory>
#include <utility>
#include <vector>

#include <Kokkos_Core.hpp>

#include "cgcm/assembly/DofMap.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/interaction/SurfaceInteraction.hpp"
#include "cgcm/material/NeoHookean.hpp"
#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::assembly {

enum class Formulation { PlaneStrain, Axisymmetric, ThreeD };

const char* formulationName(Formulation f);
/// Spatial dimension of the unknowns of a formulation.
int formulationDim(Formulation f);

/// Wall-clock seconds spent in evaluations, accumulated since construction.
struct AssemblyTimings {
  double residual = 0.0;     ///< residual-only evaluations of the bulk
  double jacobian = 0.0;     ///< residual + tangent evaluations of the bulk (incl. fill)
  double interaction = 0.0;  ///< interaction: coordinate gather, search, kernel, scatter
  int residualCalls = 0;
  int jacobianCalls = 0;
};

/// An interaction tangent entry fell outside the matrix graph (the set of
/// interacting surface elements moved beyond the graph's search radius). The
/// Jacobian is incomplete: rebuild the graph and redo the step.
struct GraphOutdatedError : NumericalError {
  using NumericalError::NumericalError;
};

class Assembler {
 public:
  /// One material for every body, or (bodyMaterials) one per body (index = body id).
  Assembler(Teuchos::RCP<const DofMap> dofs, std::shared_ptr<const mesh::Mesh> mesh, Formulation formulation,
            const material::NeoHookean& material);
  Assembler(Teuchos::RCP<const DofMap> dofs, std::shared_ptr<const mesh::Mesh> mesh, Formulation formulation,
            std::vector<material::NeoHookean> bodyMaterials);

  /// The material of a body.
  const material::NeoHookean& material(int body) const { return materials_.at(body); }

  const DofMap& dofs() const { return *dofs_; }
  const mesh::Mesh& mesh() const { return *mesh_; }
  Formulation formulation() const { return formulation_; }

  /// Couplings (row node, column node) added to the cell cliques in the graph.
  /// Rows must be nodes of this rank's overlap map. Takes effect on the next graph().
  void setExtraCouplings(std::vector<std::pair<LocalIndex, LocalIndex>> nodePairs);
  /// The current graph (built on first use and after setExtraCouplings).
  Teuchos::RCP<const Graph> graph();
  /// A new zero matrix on the current graph.
  Teuchos::RCP<Matrix> createMatrix();

  /// Internal force f_int(u) (owned rows, before boundary conditions); if J is
  /// given, also its tangent (J must come from createMatrix() of this graph).
  /// Collective. Throws InvertedElementError on every rank if any cell has J <= 0.
  void evaluate(const Vector& u, Vector& f, Matrix* J);

  /// Adds the surface interaction (Method 3) to every evaluation. The matrix
  /// graph holds the couplings of all surface elements within the search
  /// radius, `searchRadiusFactor` (> 1) times the interaction's current cutoff,
  /// of each other, refreshed by updateInteractionGraph.
  void setInteraction(std::shared_ptr<interaction::SurfaceInteraction> interaction, Real searchRadiusFactor);
  const interaction::SurfaceInteraction* interaction() const { return interaction_.get(); }
  /// The graph's search radius now (it follows the cutoff).
  Real searchRadius() const;
  /// Refreshes the interaction couplings from the state u: if some are missing
  /// from the graph, the graph is rebuilt (with the old couplings kept when
  /// `keepExisting`) and true is returned on every rank. `radiusFactor` scales
  /// the search radius. Collective.
  bool updateInteractionGraph(const Vector& u, bool keepExisting = false, Real radiusFactor = 1.0);
  /// True if the graph holds every coupling of surface elements within
  /// `radius` of each other at the state u (true without interaction). Collective.
  bool interactionGraphCovers(const Vector& u, Real radius);
  /// True if an evaluation since the last clearGraphOutdated() met interaction
  /// tangent entries outside the graph (it then threw GraphOutdatedError).
  bool graphOutdated() const { return graphOutdated_; }
  void clearGraphOutdated() { graphOutdated_ = false; }
  /// Current coordinates (X + u) of every surface node of every body, as a
  /// mesh-wide array (dim entries per node; other nodes hold X). Collective.
  const std::vector<Real>& surfaceCoordinates(const Vector& u);

  const AssemblyTimings& timings() const { return timings_; }

  /// Per body: the resultant of the interaction forces applied to it (x, y,
  /// z; z = 0 in 2D) at the state of the last evaluation, summed over ranks.
  /// Collective. Empty without interaction.
  std::vector<std::array<Real, 3>> interactionForces() const;

  /// Component `component` of `v` at `node`, on every rank (collective).
  Real nodeValue(const Vector& v, LocalIndex node, int component) const;

  /// Sum of component `component` of the owned entries of `f` over a node set (collective).
  Real sumOverNodes(const Vector& f, const std::vector<LocalIndex>& nodes, int component) const;

 private:
  void buildGraph();
  void cacheColumnIndices(const Matrix& J);
  int assembleInteraction(const Vector& u, Vector::dual_view_type::t_dev f, Matrix* J);

  Teuchos::RCP<const DofMap> dofs_;
  std::shared_ptr<const mesh::Mesh> mesh_;
  Formulation formulation_;
  std::vector<material::NeoHookean> materials_;  ///< per body
  int dim_;

  // per block: this rank's cells, their overlap dof ids and reference coordinates
  struct BlockData {
    mesh::CellType type;
    int numNodes;
    material::NeoHookean material;
    Kokkos::View<LocalIndex**, Kokkos::LayoutRight> dofLids;  // [cell][a*dim+i], overlap local ids
    Kokkos::View<LocalIndex**, Kokkos::LayoutRight> colLids;  // [cell][a*dim+i], matrix column ids
    Kokkos::View<Real***, Kokkos::LayoutRight> X;             // [cell][a][i]
  };
  std::vector<BlockData> blocks_;

  std::vector<std::pair<LocalIndex, LocalIndex>> extraCouplings_;
  Teuchos::RCP<Graph> graph_;
  int graphVersion_ = 0;  ///< incremented on every rebuild: cached column ids follow it
  int colLidsVersion_ = -1;

  /// The couplings (row node, column node) of the interaction at u within radius, rows on this rank.
  std::vector<std::pair<LocalIndex, LocalIndex>> interactionCouplings(const Vector& u, Real radius);

  std::shared_ptr<interaction::SurfaceInteraction> interaction_;
  Real searchRadiusFactor_ = 0.0;
  bool graphOutdated_ = false;
  std::vector<std::vector<char>> ownsFacet_;  ///< [body][facet]: this rank evaluates it
  Teuchos::RCP<const Map> surfaceMap_;        ///< every surface dof, on every rank
  Teuchos::RCP<const Import> surfaceImport_;
  Teuchos::RCP<Vector> uSurface_;
  std::vector<Real> coords_;                  ///< mesh-wide current coordinates of surface nodes
  std::vector<interaction::PairContribution> pairScratch_;
  std::vector<Real> bodyForces_;  ///< [3 body + i]: this rank's pairs' forces on the bodies, last evaluation

  Teuchos::RCP<Vector> uOverlap_, fOverlap_;
  Teuchos::RCP<const Export> exporter_;
  AssemblyTimings timings_;
};

}  // namespace cgcm::assembly
