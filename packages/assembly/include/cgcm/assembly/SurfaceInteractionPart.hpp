#pragma once
// Method 3 (half-space point formulation) as the interaction part of the
// discrete problem: gathers the current coordinates of every surface node on every
// rank (surfaces are small next to volumes), runs the closest-point search
// and the pair kernels of interaction::SurfaceInteraction for the points of
// the facets this rank owns (those of its cells), against every whole
// surface, and scatters them into the overlap rows. It also lists the node
// couplings of those facets for the matrix graph and sums the interaction
// force on each body. The interaction's pair list is therefore this rank's
// share only.
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
#include "cgcm/assembly/InteractionPart.hpp"
#include "cgcm/interaction/SurfaceInteraction.hpp"
#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::assembly {

class SurfaceInteractionPart final : public InteractionPart {
 public:
  /// The graph's search radius is `searchRadiusFactor` (> 1) times the
  /// interaction's current cutoff. Throws InputError for a factor <= 1.
  SurfaceInteractionPart(Teuchos::RCP<const DofMap> dofs, const mesh::Mesh& mesh,
                  std::shared_ptr<interaction::SurfaceInteraction> interaction, Real searchRadiusFactor);

  const interaction::SurfaceInteraction& interaction() const { return *interaction_; }
  Real cutoff() const override { return interaction_->cutoff(); }
  Real searchRadius() const override { return searchRadiusFactor_ * interaction_->cutoff(); }

  /// Every surface node's current coordinates (other nodes hold X).
  const std::vector<Real>& currentCoordinates(const Vector& u) override { return coords_.update(u); }

  /// A pair this rank cannot evaluate (the surfaces touch) ends the loop
  /// with the reason in `failure`.
  Outcome assemble(const Vector& u, const VectorView& f, Matrix* J) override;
  /// The closest-point search (AABB trees and queries).
  double lastSearchSeconds() const override { return searchSeconds_; }

  /// Points within `radius` of another body couple their facet with what
  /// their projections can reach (SurfaceInteraction::couplings).
  std::vector<std::pair<LocalIndex, LocalIndex>> couplings(const Vector& u, Real radius) override;

  std::vector<std::array<Real, 3>> forces() const override;

 private:
  const mesh::Mesh* mesh_;
  int dim_;
  std::shared_ptr<interaction::SurfaceInteraction> interaction_;
  Real searchRadiusFactor_;
  ReplicatedCoordinates coords_;  ///< every surface node, on every rank
  double searchSeconds_ = 0.0;
};

}  // namespace cgcm::assembly
