#pragma once
// The interaction between the bodies (Method 3) as a part of the discrete
// problem: gathers the current coordinates of every surface node on every
// rank (surfaces are small next to volumes), runs the closest-point search
// and the pair kernels of interaction::SurfaceInteraction, and scatters the
// pairs this rank owns (those of facets of its cells) into the overlap rows.
// It also lists the node couplings the matrix graph needs and sums the
// interaction force on each body.
//
// One part serves all bodies: each body's surface gets one AABB tree per
// evaluation, shared by every pair of bodies, and pairs of bodies farther
// apart than the cutoff are skipped by a bounding-box test inside
// SurfaceInteraction (one part per pair of bodies would rebuild each tree
// once per neighbour).
#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "cgcm/assembly/DofMap.hpp"
#include "cgcm/interaction/SurfaceInteraction.hpp"
#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::assembly {

class InteractionPart {
 public:
  using VectorView = Vector::dual_view_type::t_dev;

  /// The graph's search radius is `searchRadiusFactor` (> 1) times the
  /// interaction's current cutoff. Throws InputError for a factor <= 1.
  InteractionPart(Teuchos::RCP<const DofMap> dofs, const mesh::Mesh& mesh,
                  std::shared_ptr<interaction::SurfaceInteraction> interaction, Real searchRadiusFactor);

  const interaction::SurfaceInteraction& interaction() const { return *interaction_; }
  /// The graph's search radius now (it follows the cutoff).
  Real searchRadius() const { return searchRadiusFactor_ * interaction_->cutoff(); }

  /// Current coordinates (X + u) of every surface node of every body, as a
  /// mesh-wide array (dim entries per node; other nodes hold X). Collective.
  const std::vector<Real>& surfaceCoordinates(const Vector& u);

  /// f += f_C at u (overlap rows) and, if J is given (in assembly mode),
  /// J += its tangent. Returns the number of tangent entries that fell
  /// outside J's graph (they are dropped). A pair this rank cannot evaluate
  /// (the surfaces touch) ends its loop with the reason in `failure`, so
  /// that the caller can stop every rank together. Collective (the gather).
  int assemble(const Vector& u, const VectorView& f, Matrix* J, std::string& failure);
  /// Seconds the last assemble spent in the closest-point search (AABB trees and queries).
  double lastSearchSeconds() const { return searchSeconds_; }

  /// The couplings (row node, column node) of every pair that can occur for
  /// points within `radius` of another body at u, rows on this rank's overlap
  /// map. Collective.
  std::vector<std::pair<LocalIndex, LocalIndex>> couplings(const Vector& u, Real radius);

  /// Per body: the resultant of the interaction forces applied to it (x, y,
  /// z; z = 0 in 2D) at the state of the last assemble, summed over ranks.
  /// Collective.
  std::vector<std::array<Real, 3>> forces() const;

 private:
  Teuchos::RCP<const DofMap> dofs_;
  const mesh::Mesh* mesh_;
  int dim_;
  std::shared_ptr<interaction::SurfaceInteraction> interaction_;
  Real searchRadiusFactor_;
  std::vector<std::vector<char>> ownsFacet_;  ///< [body][facet]: this rank evaluates it
  Teuchos::RCP<const Map> surfaceMap_;        ///< every surface dof, on every rank
  Teuchos::RCP<const Import> surfaceImport_;
  Teuchos::RCP<Vector> uSurface_;
  std::vector<Real> coords_;      ///< mesh-wide current coordinates of surface nodes
  double searchSeconds_ = 0.0;
};

}  // namespace cgcm::assembly
