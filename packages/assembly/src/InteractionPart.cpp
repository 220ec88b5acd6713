#include "cgcm/assembly/InteractionPart.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <chrono>
#include <set>
#include <stdexcept>
#include <string>

#include "cgcm/core/Error.hpp"

namespace cgcm::assembly {

InteractionPart::InteractionPart(Teuchos::RCP<const DofMap> dofs, const mesh::Mesh& mesh,
                                 std::shared_ptr<interaction::SurfaceInteraction> interaction,
                                 Real searchRadiusFactor)
    : dofs_(std::move(dofs)), mesh_(&mesh), dim_(dofs_->dofsPerNode()), interaction_(std::move(interaction)),
      searchRadiusFactor_(searchRadiusFactor) {
  if (!(searchRadiusFactor > 1.0))
    throw InputError("Interaction/Search Radius Factor = " + std::to_string(searchRadiusFactor) +
                     ": the graph search radius must exceed the interaction cutoff (factor > 1)");
  ownsFacet_.assign(interaction_->numBodies(), {});
  const int rank = dofs_->comm()->getRank();
  std::set<LocalIndex> nodes;
  for (int b = 0; b < interaction_->numBodies(); ++b) {
    const auto& surf = interaction_->surface(b);
    if (surf.facetCells.size() != std::size_t(surf.numFacets()))
      throw std::logic_error("surface without facet-to-cell map");
    ownsFacet_[b].resize(surf.numFacets());
    for (LocalIndex f = 0; f < surf.numFacets(); ++f) ownsFacet_[b][f] = dofs_->cellOwner(surf.facetCells[f]) == rank;
    nodes.insert(surf.facets.begin(), surf.facets.end());
  }
  std::vector<GlobalIndex> gids;
  for (LocalIndex n : nodes)
    for (int i = 0; i < dim_; ++i) gids.push_back(dofs_->dof(n, i));
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  surfaceMap_ = Teuchos::rcp(new Map(invalid, gids.data(), gids.size(), 0, dofs_->comm()));
  surfaceImport_ = Teuchos::rcp(new Import(dofs_->ownedMap(), surfaceMap_));
  uSurface_ = Teuchos::rcp(new Vector(surfaceMap_));
  coords_ = mesh.coords;
}

const std::vector<Real>& InteractionPart::surfaceCoordinates(const Vector& u) {
  uSurface_->doImport(u, *surfaceImport_, Tpetra::INSERT);
  auto v = uSurface_->getLocalViewHost(Tpetra::Access::ReadOnly);
  const Map& map = *surfaceMap_;
  for (std::size_t lid = 0; lid < map.getNodeNumElements(); ++lid) {
    const GlobalIndex gid = map.getGlobalElement(LocalIndex(lid));
    coords_[gid] = mesh_->coords[gid] + v(lid, 0);  // dof gid = node * dim + i = coordinate index
  }
  return coords_;
}

int InteractionPart::assemble(const Vector& u, const VectorView& fv, Matrix* J, std::string& failure) {
  const std::vector<Real>& x = surfaceCoordinates(u);
  const auto t0 = std::chrono::steady_clock::now();
  interaction_->updatePairs(x.data());
  searchSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const Map& overlap = *dofs_->overlapMap();
  Matrix::local_matrix_device_type lclJ;
  Teuchos::RCP<const Map> colMap;
  if (J) {
    lclJ = J->getLocalMatrixDevice();
    colMap = J->getColMap();
  }
  int dropped = 0;
  auto scatter = [&](const interaction::PairContribution& c) {
    LocalIndex rows[12], cols[interaction::kMaxContributionColumns];
    const int nrows = dim_ * c.numRowNodes;
    for (int a = 0; a < c.numRowNodes; ++a)
      for (int i = 0; i < dim_; ++i) rows[dim_ * a + i] = overlap.getLocalElement(dofs_->dof(c.rowNodes[a], i));
    for (int r = 0; r < nrows; ++r) Kokkos::atomic_add(&fv(rows[r], 0), c.f[r]);
    if (!J) return;
    // the point's facet and every facet its projection is blended over
    const int ncols = dim_ * c.numColNodes;
    for (int b = 0; b < c.numColNodes; ++b)
      for (int j = 0; j < dim_; ++j) cols[dim_ * b + j] = colMap->getLocalElement(dofs_->dof(c.colNodes[b], j));
    // sumIntoValues skips columns missing from the row and returns how many it found
    for (int r = 0; r < nrows; ++r) dropped += ncols - lclJ.sumIntoValues(rows[r], cols, ncols, c.K[r], false, true);
  };
  // each pair is evaluated by exactly one rank
  auto owned = [&](const interaction::InteractionPair& p) { return bool(ownsFacet_[p.body][p.facet]); };
  try {
    interaction_->evaluate(x.data(), scatter, J != nullptr, owned);
  } catch (const NumericalError& e) {
    failure = e.what();
  }
  return dropped;
}

std::vector<std::pair<LocalIndex, LocalIndex>> InteractionPart::couplings(const Vector& u, Real radius) {
  const std::vector<Real>& x = surfaceCoordinates(u);
  const Map& overlap = *dofs_->overlapMap();
  std::vector<std::pair<LocalIndex, LocalIndex>> wanted;
  for (const auto& rc : interaction_->couplings(x.data(), radius))
    if (overlap.getLocalElement(dofs_->dof(rc.first, 0)) != Teuchos::OrdinalTraits<LocalIndex>::invalid())
      wanted.push_back(rc);
  return wanted;
}

std::vector<std::array<Real, 3>> InteractionPart::forces() const {
  const auto& mine = interaction_->summary().resultant;  // this rank's pairs
  const int nb = interaction_->numBodies();
  std::vector<Real> local(3 * std::size_t(nb)), global(local.size(), 0.0);
  for (int b = 0; b < nb; ++b)
    for (int i = 0; i < 3; ++i) local[3 * std::size_t(b) + i] = mine[b][i];
  Teuchos::reduceAll(*dofs_->comm(), Teuchos::REDUCE_SUM, int(local.size()), local.data(), global.data());
  std::vector<std::array<Real, 3>> out(nb);
  for (int b = 0; b < nb; ++b) out[b] = {global[3 * b], global[3 * b + 1], global[3 * b + 2]};
  return out;
}

}  // namespace cgcm::assembly
