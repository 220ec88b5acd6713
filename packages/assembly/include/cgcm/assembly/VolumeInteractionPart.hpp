#pragma once
// Method 1 (element-pair volume integration) as the interaction part of the
// discrete problem: replicates the current coordinates of the interacting
// bodies' nodes on every rank, keeps interaction::VolumeInteraction's pair
// list, runs its Kokkos kernel over the directed pairs whose row cell this
// rank owns and scatters each pair's rows (the row cell's nodes, all on this
// rank's overlap map) with atomic adds into the overlap residual and the
// local matrix.
#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "cgcm/assembly/DofMap.hpp"
#include "cgcm/assembly/InteractionPart.hpp"
#include "cgcm/interaction/VolumeInteraction.hpp"
#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::assembly {

class VolumeInteractionPart final : public InteractionPart {
 public:
  /// The graph's search radius is the interaction's cutoff plus
  /// `searchRadiusFactor` (> 1) times its skin: the pair list covers cutoff +
  /// skin, and a wider graph only makes the Jacobian denser (every cell pair
  /// within the radius couples all its nodes). Throws InputError for a factor <= 1.
  VolumeInteractionPart(Teuchos::RCP<const DofMap> dofs, const mesh::Mesh& mesh,
                        std::shared_ptr<interaction::VolumeInteraction> interaction, Real searchRadiusFactor);

  const interaction::VolumeInteraction& interaction() const { return *interaction_; }
  Real cutoff() const override { return interaction_->cutoff() + interaction_->skin(); }
  Real searchRadius() const override {
    return interaction_->cutoff() + searchRadiusFactor_ * interaction_->skin();
  }
  /// The mesh's surfaces (every rank holds the whole mesh), all of them counted as own.
  HeldSurfaces heldSurfaces(const Vector& u) override;
  Outcome assemble(const Vector& u, const VectorView& f, Matrix* J) override;
  /// Building the pair list (when it is rebuilt).
  double lastSearchSeconds() const override { return searchSeconds_; }
  /// Every node of a cell with every node of each cell of another body
  /// whose bounding box is within `radius`.
  std::vector<std::pair<LocalIndex, GlobalIndex>> couplings(const Vector& u, Real radius) override;
  std::vector<std::array<Real, 3>> forces() const override;

 private:
  const mesh::Mesh* mesh_;
  std::shared_ptr<interaction::VolumeInteraction> interaction_;
  Real searchRadiusFactor_;
  ReplicatedCoordinates coords_;
  Kokkos::View<LocalIndex**> rowIds_;  ///< [node][i]: overlap-map id of the node's dof i, or -1
  Kokkos::View<LocalIndex**> colIds_;  ///< [node][i]: column id in the matrix of colMapOfIds_
  Teuchos::RCP<const Map> colMapOfIds_;  ///< held, so that a new map never reuses its address
  double searchSeconds_ = 0.0;
};

}  // namespace cgcm::assembly
