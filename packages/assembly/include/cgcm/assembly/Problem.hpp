#pragma once
// The discrete problem as a sum of parts: f(u) = sum over bodies of the bulk
// part + the interaction part, and the same for the tangent. The Problem owns
// what the parts share: the dof maps, the matrix graph (the bulk cliques and
// the interaction couplings, which may be replaced between solves), the
// overlap vectors and the export of shared rows to their owners, and the
// timings. Parts write into the overlap views; they do not see each other.
#include <array>
#include <string>
#include <memory>
#include <utility>
#include <vector>

#include "cgcm/assembly/BulkPart.hpp"
#include "cgcm/assembly/DofMap.hpp"
#include "cgcm/core/Formulation.hpp"
#include "cgcm/assembly/InteractionPart.hpp"
#include "cgcm/assembly/SurfaceInteractionPart.hpp"
#include "cgcm/assembly/VolumeInteractionPart.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/interaction/SurfaceInteraction.hpp"
#include "cgcm/interaction/VolumeInteraction.hpp"
#include "cgcm/material/NeoHookean.hpp"
#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::assembly {

/// Wall-clock seconds spent in evaluations, accumulated since construction.
struct AssemblyTimings {
  double residual = 0.0;     ///< residual-only evaluations of the bulk
  double jacobian = 0.0;     ///< residual + tangent evaluations of the bulk (incl. fill)
  double interaction = 0.0;  ///< interaction: coordinate gather, search, kernel, scatter
  double search = 0.0;       ///< the part of `interaction` in the closest-point search (trees and queries)
  double graph = 0.0;        ///< the matrix graph: its interaction couplings (checked once per solve) and builds
};

/// An interaction tangent entry fell outside the matrix graph (the set of
/// interacting surface elements moved beyond the graph's search radius). The
/// Jacobian is incomplete: rebuild the graph and redo the step.
struct GraphOutdatedError : NumericalError {
  using NumericalError::NumericalError;
};

class Problem {
 public:
  /// One material for every body, or (bodyMaterials) one per body (index = body id).
  Problem(Teuchos::RCP<const DofMap> dofs, std::shared_ptr<const mesh::Mesh> mesh, Formulation formulation,
          const material::NeoHookean& material);
  Problem(Teuchos::RCP<const DofMap> dofs, std::shared_ptr<const mesh::Mesh> mesh, Formulation formulation,
          std::vector<material::NeoHookean> bodyMaterials);

  const DofMap& dofs() const { return *dofs_; }
  const mesh::Mesh& mesh() const { return *mesh_; }
  Formulation formulation() const { return formulation_; }
  /// The material of a body.
  const material::NeoHookean& material(int body) const { return bulk_.at(body).material(); }
  const std::vector<BulkPart>& bulkParts() const { return bulk_; }
  /// Whether the bulk scatter adds at the cached row offsets (true, the default) or finds each entry by
  /// bisection (false): BulkPart::useScatterOffsets, for a test that compares the two.
  void useScatterOffsets(bool use) {
    for (auto& b : bulk_) b.useScatterOffsets(use);
  }
  /// Per owned row, 1/s² with s = max(1, Y_body / referenceModulus): the weights of the convergence
  /// test's 2-norm, which then measures the residual of each body stiffer than the reference in that
  /// body's own force unit (its round-off floor grows with its modulus). Null when no body is stiffer.
  Teuchos::RCP<Vector> residualWeights(Real referenceModulus) const;

  /// The current graph (built on first use and after updateInteractionGraph).
  Teuchos::RCP<const Graph> graph();
  /// A new zero matrix on the current graph.
  Teuchos::RCP<Matrix> createMatrix();

  /// f(u) = sum of the parts (owned rows, before boundary conditions); if J
  /// is given, also its tangent (J must come from createMatrix() of this
  /// graph). Collective. Throws InvertedElementError on every rank if any
  /// cell has J <= 0, GraphOutdatedError if an interaction tangent entry fell
  /// outside the graph.
  void evaluate(const Vector& u, Vector& f, Matrix* J);

  /// Adds the interaction part to every evaluation: Method 3 (half-space
  /// point formulation on the surfaces) or Method 1 (element pairs). The
  /// matrix graph holds the couplings of everything within the search
  /// radius, `searchRadiusFactor` (> 1) times the interaction's current
  /// reach (the cutoff; Method 1: cutoff + skin), refreshed by
  /// updateInteractionGraph.
  void setInteraction(std::shared_ptr<interaction::Interaction> interaction, Real searchRadiusFactor);
  bool hasInteraction() const { return bool(interactionPart_); }
  /// Method 1's interaction, or null (for its pair statistics in the run's summary).
  const interaction::VolumeInteraction* volumeInteraction() const {
    const auto* part = dynamic_cast<const VolumeInteractionPart*>(interactionPart_.get());
    return part ? &part->interaction() : nullptr;
  }
  /// The interaction's reach now (0 without interaction).
  Real interactionCutoff() const { return interactionPart_ ? interactionPart_->cutoff() : 0.0; }
  /// The graph's search radius now (it follows the cutoff; 0 without interaction).
  Real searchRadius() const { return interactionPart_ ? interactionPart_->searchRadius() : 0.0; }
  /// Refreshes the interaction couplings from the state u: if some are missing
  /// from the graph, the graph is rebuilt (with the old couplings kept when
  /// `keepExisting`) and true is returned on every rank. `radiusFactor` scales
  /// the search radius. Collective.
  bool updateInteractionGraph(const Vector& u, bool keepExisting = false, Real radiusFactor = 1.0);
  /// True if the graph holds every coupling of surface facets within
  /// `radius` of each other at the state u (true without interaction). Collective.
  bool interactionGraphCovers(const Vector& u, Real radius);
  /// True if an evaluation since the last clearGraphOutdated() met interaction
  /// tangent entries outside the graph (it then threw GraphOutdatedError).
  bool graphOutdated() const { return graphOutdated_; }
  void clearGraphOutdated() { graphOutdated_ = false; }
  /// The bodies' surfaces this rank holds at u (InteractionPart::heldSurfaces).
  /// Collective; requires an interaction.
  InteractionPart::HeldSurfaces heldSurfaces(const Vector& u) { return interactionPart_->heldSurfaces(u); }
  /// Method 3's part, or null (for the surfaces it holds, in the run's summary).
  const SurfaceInteractionPart* surfaceInteractionPart() const {
    return dynamic_cast<const SurfaceInteractionPart*>(interactionPart_.get());
  }
  /// Per body: the interaction force on it at the state of the last
  /// evaluation (x, y, z), summed over ranks. Collective; empty without interaction.
  std::vector<std::array<Real, 3>> interactionForces() const;
  /// The interaction force on each node at the state u, on the owned map
  /// (zero without interaction): the interaction part evaluated alone, its
  /// residual share exported to the owners, with the sign of a force on the
  /// body (InteractionPart::nodeForces; whichever method). Summed over a
  /// body's nodes it is that body's interactionForces(). u must be the state
  /// of the last evaluate() (std::logic_error otherwise: at another state the
  /// interaction's search state would move with the output). Timed as
  /// `interaction` (and `search`). Collective; throws NumericalError on
  /// every rank if a rank's pairs cannot be evaluated (as evaluate).
  Teuchos::RCP<Vector> interactionNodeForces(const Vector& u);

  const AssemblyTimings& timings() const { return timings_; }

  /// Component `component` of `v` at `node`, on every rank (collective).
  Real nodeValue(const Vector& v, LocalIndex node, int component) const;

  /// Where v (a vector on one of the dof maps) is first NaN or Inf on this
  /// rank: "node N, component i (nan)", empty if nowhere. evaluate reports a
  /// non-finite residual with it.
  std::string firstNonFinite(const Vector& v) const;
  /// Sum of component `component` of the owned entries of `f` over a node set (collective).
  Real sumOverNodes(const Vector& f, const std::vector<LocalIndex>& nodes, int component) const;

 private:
  void buildGraph();
  void findCellNeighbours();
  /// The interaction couplings at u within `radius` (timed as `graph`).
  std::vector<std::pair<LocalIndex, GlobalIndex>> interactionCouplings(const Vector& u, Real radius);
  /// Whether the graph holds `wanted` on every rank (collective).
  bool graphHoldsEverywhere(const std::vector<std::pair<LocalIndex, GlobalIndex>>& wanted) const;

  Teuchos::RCP<const DofMap> dofs_;
  std::shared_ptr<const mesh::Mesh> mesh_;
  Formulation formulation_;
  int dim_;
  std::vector<BulkPart> bulk_;                         ///< one per body
  std::unique_ptr<InteractionPart> interactionPart_;  ///< null without interaction

  std::vector<std::pair<LocalIndex, GlobalIndex>> extraCouplings_;  ///< (row mesh node, column global node)
  /// The part of the graph fixed with the mesh, found at the first build: per
  /// overlap node, the overlap nodes it shares one of this rank's cells with
  /// (sorted, unique), and a bound on the nodes other ranks' cells add to it.
  std::vector<std::vector<LocalIndex>> cellNeighbours_;
  std::vector<long long> remoteCellNodes_;
  bool cellNeighboursFound_ = false;  ///< on every rank at once (finding them is collective)
  Teuchos::RCP<Graph> graph_;
  int graphVersion_ = 0;  ///< incremented on every rebuild: cached column ids follow it
  int columnsVersion_ = -1;
  bool graphOutdated_ = false;

  Teuchos::RCP<Vector> uOverlap_, fOverlap_;
  Teuchos::RCP<const Export> exporter_;
  AssemblyTimings timings_;
};

}  // namespace cgcm::assembly
