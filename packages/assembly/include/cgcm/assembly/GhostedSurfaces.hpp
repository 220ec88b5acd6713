#pragma once
// The interaction surfaces one rank holds: the facets of its own cells (it
// evaluates their quadrature points) and, as ghosts, the other ranks' facets
// that lie within a radius of its own, which its points can pair with.
// Nothing of the whole surfaces is held: ghosts come from their ranks at the
// first gather and again whenever the bodies have moved so far that a facet
// not held could come within reach (covers()).
//
// The held nodes are numbered on their own (the own facets' nodes first, then
// the ghosts'), with their global ids and reference coordinates; their current
// coordinates are imported from the owners of their dofs at each update.
//
// Which facets a rank sends: every rank publishes, per body, the bounding
// boxes of groups of at most kFacetsPerBox of its own facets (a recursive
// bisection of their centroids); a facet of body l goes to every rank with a
// box of another body within the radius of the facet's box. A facet's box is
// its nodes' box, and for curved facets that box about its centre scaled by
// the Lebesgue constant (a quadratic facet bulges beyond its nodes).
#include <vector>

#include "cgcm/assembly/DofMap.hpp"
#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::assembly {

class GhostedSurfaces {
 public:
  /// Own facets per body in publish boxes.
  static constexpr int kFacetsPerBox = 32;

  /// The facets of `mesh.surfaces` whose cells this rank evaluates are its
  /// own; `lebesgue` (>= 1) bounds how far a point of a facet moves per unit
  /// motion of its nodes (SurfaceInteraction::lebesgue). No ghosts until gather().
  GhostedSurfaces(Teuchos::RCP<const DofMap> dofs, const mesh::Mesh& mesh, Real lebesgue);

  /// One per body: its own facets first (numOwnFacets), then its ghosts; node
  /// indices in the held numbering, facetCells the mesh cell of an own facet and -1 for a ghost.
  const std::vector<mesh::Surface>& surfaces() const { return surfaces_; }
  LocalIndex numOwnFacets(int body) const { return numOwnFacets_[std::size_t(body)]; }
  /// Per body and held facet: 1 for the own facets.
  std::vector<std::vector<char>> ownFacetFlags() const;
  GlobalIndex globalNode(LocalIndex node) const { return ids_[std::size_t(node)]; }
  /// The mesh node of a held node of an own facet (-1 for a ghost's node).
  LocalIndex meshNode(LocalIndex node) const {
    return std::size_t(node) < ownMeshNodes_.size() ? ownMeshNodes_[std::size_t(node)] : -1;
  }
  /// Reference coordinates of the held nodes (dim per node).
  const std::vector<Real>& referenceCoordinates() const { return reference_; }

  /// The current coordinates X + u of the held nodes (dim per node). Collective.
  const std::vector<Real>& update(const Vector& u);
  /// The coordinates of the last update.
  const std::vector<Real>& coordinates() const { return current_; }

  /// Whether every rank holds every facet within `reach` of its own points at
  /// the coordinates of the last update: the largest reach of any rank plus
  /// twice the largest motion of a facet since the last gather stays within
  /// its radius. Collective (one reduction).
  bool covers(Real reach) const;
  /// Holds, as ghosts, every other rank's facet within `radius` (the largest
  /// any rank asks for) of this rank's own at u (infinite: every facet), and
  /// updates to u; the held numbering changes. Collective.
  void gather(const Vector& u, Real radius);
  /// The radius of the last gather (infinite on one rank; negative before the first).
  Real radius() const { return radius_; }
  /// Ghost facets held, of every body.
  long numGhostFacets() const;
  /// Gathers so far.
  long numGathers() const { return gathers_; }

 private:
  void rebuildImport();

  Teuchos::RCP<const DofMap> dofs_;
  int dim_;
  Real lebesgue_;
  std::vector<mesh::Surface> surfaces_;
  std::vector<LocalIndex> numOwnFacets_;
  LocalIndex numOwnNodes_ = 0;            ///< the own facets' nodes: the first held nodes
  std::vector<GlobalIndex> ids_;          ///< per held node
  std::vector<LocalIndex> ownMeshNodes_;  ///< per own facets' node: its mesh node
  std::vector<Real> reference_, current_;  ///< dim per held node
  std::vector<Real> atGather_;            ///< the own nodes' coordinates at the last gather
  Real radius_ = -1.0;
  long gathers_ = 0;
  Teuchos::RCP<const Import> import_;
  Teuchos::RCP<Vector> values_;
};

/// Sends toRank[r] to rank r and returns what each rank sent this one (one buffer per rank). Collective.
std::vector<std::vector<char>> exchangeBytes(const Comm& comm, const std::vector<std::vector<char>>& toRank);

}  // namespace cgcm::assembly
