#pragma once
// Method 3 (half-space point formulation) as the interaction part of the
// discrete problem: holds the surfaces this rank needs (GhostedSurfaces: the
// facets of its cells and the other ranks' facets within reach of them),
// runs the closest-point search and the pair kernels of
// interaction::SurfaceInteraction for the points of its own facets against
// the held ones, and scatters them into the overlap rows. It also lists the
// node couplings of those facets for the matrix graph and sums the
// interaction force on each body. The interaction's pair list is therefore
// this rank's share only.
//
// The ghosts are gathered anew (collectively, inside assemble and couplings)
// when the reach asked for, plus twice the largest motion of any facet since
// the last gather, exceeds the radius they were gathered with; the new radius
// is the reach of the graph's couplings at the search radius plus the graph's
// skin, so that gathers follow the graph's rebuilds. In 2D every rank holds
// every facet (a polyline: the projection blend reads a target's neighbours).
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
#include "cgcm/assembly/GhostedSurfaces.hpp"
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

  HeldSurfaces heldSurfaces(const Vector& u) override;
  /// The surfaces held (own facets and ghosts) and their gathers.
  const GhostedSurfaces& held() const { return held_; }

  /// A pair this rank cannot evaluate (the surfaces touch) ends the loop
  /// with the reason in `failure`.
  Outcome assemble(const Vector& u, const VectorView& f, Matrix* J) override;
  /// The closest-point search (AABB trees and queries).
  double lastSearchSeconds() const override { return searchSeconds_; }

  /// Points within `radius` of another body couple their facet with what
  /// their projections can reach (SurfaceInteraction::couplings).
  std::vector<std::pair<LocalIndex, GlobalIndex>> couplings(const Vector& u, Real radius) override;

  std::vector<std::array<Real, 3>> forces() const override;

 private:
  int dim_;
  std::shared_ptr<interaction::SurfaceInteraction> interaction_;
  Real searchRadiusFactor_;
  /// The held coordinates at u, with every facet within `reach` of the own points held (gathering
  /// the ghosts anew if they no longer cover it). Collective.
  const std::vector<Real>& coordinatesCovering(const Vector& u, Real reach);
  /// Hands the held surfaces to the interaction (after each gather).
  void installHeldSurfaces();

  GhostedSurfaces held_;
  double searchSeconds_ = 0.0;
};

}  // namespace cgcm::assembly
