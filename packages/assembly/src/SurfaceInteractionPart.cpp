#include "cgcm/assembly/SurfaceInteractionPart.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <chrono>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "cgcm/core/Error.hpp"

namespace cgcm::assembly {

namespace {

std::vector<LocalIndex> surfaceNodes(const interaction::SurfaceInteraction& si) {
  std::vector<LocalIndex> nodes;
  for (int b = 0; b < si.numBodies(); ++b) nodes.insert(nodes.end(), si.surface(b).facets.begin(), si.surface(b).facets.end());
  return nodes;
}

}  // namespace

SurfaceInteractionPart::SurfaceInteractionPart(Teuchos::RCP<const DofMap> dofs, const mesh::Mesh& mesh,
                                               std::shared_ptr<interaction::SurfaceInteraction> interaction,
                                               Real searchRadiusFactor)
    : InteractionPart(std::move(dofs)), mesh_(&mesh), dim_(dofs_->dofsPerNode()), interaction_(std::move(interaction)),
      searchRadiusFactor_(searchRadiusFactor), coords_(*dofs_, mesh, surfaceNodes(*interaction_)) {
  if (!(searchRadiusFactor > 1.0))
    throw InputError("Interaction/Search Radius Factor = " + std::to_string(searchRadiusFactor) +
                     ": the graph search radius must exceed the interaction cutoff (factor > 1)");
  // Each pair is evaluated by exactly one rank: the owner of its facet's cell searches and pairs the
  // facet's points (against every whole surface); the pair list holds this rank's pairs only.
  std::vector<std::vector<char>> ownsFacet(interaction_->numBodies());
  for (int b = 0; b < interaction_->numBodies(); ++b) {
    const auto& surf = interaction_->surface(b);
    if (surf.facetCells.size() != std::size_t(surf.numFacets()))
      throw std::logic_error("surface without facet-to-cell map");
    ownsFacet[b].resize(surf.numFacets());
    for (LocalIndex f = 0; f < surf.numFacets(); ++f) ownsFacet[b][f] = dofs_->evaluatesCell(surf.facetCells[f]);
  }
  interaction_->setEvaluatedFacets(std::move(ownsFacet));
}

InteractionPart::Outcome SurfaceInteractionPart::assemble(const Vector& u, const VectorView& fv, Matrix* J) {
  const std::vector<Real>& x = coords_.update(u);
  const auto t0 = std::chrono::steady_clock::now();
  interaction_->updatePairs(x.data());
  searchSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const Map& overlap = *dofs_->overlapMap();
  const bool sortedRows = J && J->getCrsGraph()->isSorted();  // bisection in each row, not a scan
  Matrix::local_matrix_device_type lclJ;
  Teuchos::RCP<const Map> colMap;
  if (J) {
    lclJ = J->getLocalMatrixDevice();
    colMap = J->getColMap();
  }
  Outcome out;
  auto scatter = [&](const auto& c) {  // a PairContribution or, on curved 3D facets, a CurvedPairContribution
    using Contribution = std::decay_t<decltype(c)>;
    LocalIndex rows[Contribution::kMaxRows], cols[Contribution::kMaxColumns];
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
    for (int r = 0; r < nrows; ++r) {
      const int missing = ncols - lclJ.sumIntoValues(rows[r], cols, ncols, c.K[r], sortedRows, true);
      if (missing == 0) continue;
      out.dropped += missing;
      if (!out.firstDropped.empty()) continue;
      const Real zero = 0.0;  // probe the columns one by one for the first that is missing
      for (int k = 0; k < ncols; ++k)
        if (lclJ.sumIntoValues(rows[r], &cols[k], 1, &zero, sortedRows, true) == 0) {
          out.firstDropped = "row node " + std::to_string(dofs_->globalNode(c.rowNodes[r / dim_])) +
                             ", column node " + std::to_string(dofs_->globalNode(c.colNodes[k / dim_]));
          break;
        }
    }
  };
  try {
    interaction_->evaluate(x.data(), scatter, J != nullptr);
  } catch (const NumericalError& e) {
    out.failure = e.what();
  }
  return out;
}

std::vector<std::pair<LocalIndex, LocalIndex>> SurfaceInteractionPart::couplings(const Vector& u, Real radius) {
  // rows: the nodes of this rank's facets, all on its overlap map
  return interaction_->couplings(coords_.update(u).data(), radius);
}

std::vector<std::array<Real, 3>> SurfaceInteractionPart::forces() const {
  return sumOverRanks(*dofs_->comm(), interaction_->summary().resultant);  // this rank's pairs, summed
}

}  // namespace cgcm::assembly
