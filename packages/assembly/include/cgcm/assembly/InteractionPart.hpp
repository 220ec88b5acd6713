#pragma once
// The interaction between the bodies as a part of the discrete problem: what
// the Problem asks of it, whichever method evaluates it (Method 3 on the
// surfaces: SurfaceInteractionPart; Method 1 over element pairs:
// VolumeInteractionPart). A part writes the forces of the pairs this rank
// owns into the overlap rows, lists the node couplings the matrix graph
// needs, and sums the interaction force on each body. Its output services
// (the interaction force on each node) are the same for every method: they
// are computed from what assemble writes.
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "cgcm/assembly/DofMap.hpp"
#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::assembly {

class InteractionPart {
 public:
  using VectorView = Vector::dual_view_type::t_dev;
  virtual ~InteractionPart() = default;

  /// The interaction's current cutoff (absolute).
  virtual Real cutoff() const = 0;
  /// The graph's search radius now (a factor > 1 times the cutoff).
  virtual Real searchRadius() const = 0;

  /// What one assemble met on this rank.
  struct Outcome {
    int dropped = 0;           ///< tangent entries outside J's graph (left out)
    std::string firstDropped;  ///< where the first was: "row node R, column node C"
    std::string failure;       ///< the reason the loop ended early (e.g. touching surfaces), or empty
  };
  /// f += f_C at u (overlap rows) and, if J is given (in assembly mode),
  /// J += its tangent. A failure this rank meets ends its loop with the
  /// reason in the outcome, so that the caller can stop every rank together.
  /// Collective.
  virtual Outcome assemble(const Vector& u, const VectorView& f, Matrix* J) = 0;
  /// Seconds the last assemble spent searching (trees, pair lists).
  virtual double lastSearchSeconds() const = 0;

  /// The couplings (row node, column node) of every pair that can occur for
  /// bodies within `radius` of each other at u: the row a mesh node on this
  /// rank's overlap map, the column a global node id (it may be held by
  /// another rank only); sorted and unique. Collective.
  virtual std::vector<std::pair<LocalIndex, GlobalIndex>> couplings(const Vector& u, Real radius) = 0;

  /// Per body: the resultant of the interaction forces on it (x, y, z; z = 0
  /// in 2D) at the state of the last assemble, summed over ranks. Collective.
  virtual std::vector<std::array<Real, 3>> forces() const = 0;

  /// The bodies' surfaces this rank holds, at a state.
  struct HeldSurfaces {
    const std::vector<mesh::Surface>* surfaces = nullptr;  ///< one per body, node indices into coords
    const std::vector<Real>* coords = nullptr;             ///< current coordinates X + u, dim per node
    /// Per body: its leading facets that are this rank's own; the others are held because they lie
    /// near the own ones (every facet within the interaction's reach of them is held).
    std::vector<LocalIndex> ownFacets;
  };
  /// The surfaces held at u, for measurements on them (the contact probe). Collective.
  virtual HeldSurfaces heldSurfaces(const Vector& u) = 0;

  /// The interaction force on each node at u, into `forces` (on the owned
  /// map): minus the part's own share of the residual, f_C, assembled alone
  /// into a zero vector and exported to the rows' owners. Exact by
  /// construction and the same for every method: Method 3's forces sit on
  /// the surface nodes, Method 1's (a body force) on every node of the cells
  /// within reach of another body. Summed over a body's nodes it is that
  /// body's entry of forces() (at this u). Returns the reason this rank's
  /// assemble failed, or empty (the caller stops every rank together).
  /// Collective.
  std::string nodeForces(const Vector& u, Vector& forces);

 protected:
  explicit InteractionPart(Teuchos::RCP<const DofMap> dofs) : dofs_(std::move(dofs)) {}
  Teuchos::RCP<const DofMap> dofs_;

 private:
  Teuchos::RCP<const Export> exporter_;  ///< overlap -> owned, made on the first nodeForces
};

/// Current coordinates of a set of nodes on every rank: the displacements
/// of their dofs imported from their owners each call.
class ReplicatedCoordinates {
 public:
  /// `nodes`: the nodes to replicate (any order, repeats allowed).
  ReplicatedCoordinates(const DofMap& dofs, const mesh::Mesh& mesh, const std::vector<LocalIndex>& nodes);
  /// X + u on the nodes, X elsewhere (mesh-wide array). Collective.
  const std::vector<Real>& update(const Vector& u);

 private:
  const mesh::Mesh* mesh_;
  Teuchos::RCP<const Map> map_;
  Teuchos::RCP<const Import> import_;
  Teuchos::RCP<Vector> values_;
  std::vector<std::size_t> coordOfValue_;  ///< per entry of values_: its index in coords_ (mesh node * dim + i)
  std::vector<Real> coords_;
};

/// Per body, the three resultant components of `local` summed over the ranks of `comm`.
std::vector<std::array<Real, 3>> sumOverRanks(const Comm& comm, const std::vector<std::array<Real, 3>>& local);

}  // namespace cgcm::assembly
