#include "cgcm/assembly/SurfaceInteractionPart.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <chrono>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "cgcm/core/Error.hpp"

namespace cgcm::assembly {

SurfaceInteractionPart::SurfaceInteractionPart(Teuchos::RCP<const DofMap> dofs, const mesh::Mesh& mesh,
                                               std::shared_ptr<interaction::SurfaceInteraction> interaction,
                                               Real searchRadiusFactor)
    : InteractionPart(std::move(dofs)), dim_(dofs_->dofsPerNode()), interaction_(std::move(interaction)),
      searchRadiusFactor_(searchRadiusFactor), held_(dofs_, mesh, interaction_->lebesgue()) {
  if (!(searchRadiusFactor > 1.0))
    throw InputError("Interaction/Search Radius Factor = " + std::to_string(searchRadiusFactor) +
                     ": the graph search radius must exceed the interaction cutoff (factor > 1)");
  // Each pair is evaluated by exactly one rank: the owner of its facet's cell searches and pairs the
  // facet's points (against the held surfaces); the pair list holds this rank's pairs only.
  installHeldSurfaces();
}

void SurfaceInteractionPart::installHeldSurfaces() {
  interaction_->setSurfaces(held_.surfaces());
  interaction_->setEvaluatedFacets(held_.ownFacetFlags());
  if (interaction_->options().surfaceDensity == interaction::SurfaceDensity::ReferenceArea)
    interaction_->setReferenceConfiguration(held_.referenceCoordinates());
}

const std::vector<Real>& SurfaceInteractionPart::coordinatesCovering(const Vector& u, Real radius) {
  const std::vector<Real>& x = held_.update(u);
  const Real deviation = interaction_->largestCoverDeviation(x.data());
  const Real reach = interaction_->readingReach(radius, deviation);
  if (held_.covers(reach)) return x;
  // Gather out to the reach of the graph's couplings at the search radius, and the graph's skin beyond:
  // a gather is then due about when the graph's couplings are (after a motion of half the skin).
  const Real skin = (searchRadius() - cutoff()) * interaction_->lebesgue();
  const Real gatherRadius = dim_ == 2 ? std::numeric_limits<Real>::infinity()
                                      : std::max(reach, interaction_->readingReach(searchRadius(), deviation)) + skin;
  held_.gather(u, gatherRadius);
  installHeldSurfaces();
  return held_.coordinates();
}

InteractionPart::HeldSurfaces SurfaceInteractionPart::heldSurfaces(const Vector& u) {
  HeldSurfaces out;
  coordinatesCovering(u, cutoff());
  out.surfaces = &held_.surfaces();
  out.coords = &held_.coordinates();
  for (int b = 0; b < interaction_->numBodies(); ++b) out.ownFacets.push_back(held_.numOwnFacets(b));
  return out;
}

InteractionPart::Outcome SurfaceInteractionPart::assemble(const Vector& u, const VectorView& fv, Matrix* J) {
  const std::vector<Real>& x = coordinatesCovering(u, cutoff());
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
  auto dofOf = [&](LocalIndex heldNode, int i) { return held_.globalNode(heldNode) * dim_ + i; };
  auto scatter = [&](const auto& c) {  // a PairContribution or, on curved 3D facets, a CurvedPairContribution
    using Contribution = std::decay_t<decltype(c)>;
    LocalIndex rows[Contribution::kMaxRows], cols[Contribution::kMaxColumns];
    const int nrows = dim_ * c.numRowNodes;
    for (int a = 0; a < c.numRowNodes; ++a)
      for (int i = 0; i < dim_; ++i) rows[dim_ * a + i] = overlap.getLocalElement(dofOf(c.rowNodes[a], i));
    for (int r = 0; r < nrows; ++r) Kokkos::atomic_add(&fv(rows[r], 0), c.f[r]);
    if (!J) return;
    // the point's facet and every facet its projection is blended over
    const int ncols = dim_ * c.numColNodes;
    for (int b = 0; b < c.numColNodes; ++b)
      for (int j = 0; j < dim_; ++j) cols[dim_ * b + j] = colMap->getLocalElement(dofOf(c.colNodes[b], j));
    // sumIntoValues skips columns missing from the row and returns how many it found
    for (int r = 0; r < nrows; ++r) {
      const int missing = ncols - lclJ.sumIntoValues(rows[r], cols, ncols, c.K[r], sortedRows, true);
      if (missing == 0) continue;
      out.dropped += missing;
      if (!out.firstDropped.empty()) continue;
      const Real zero = 0.0;  // probe the columns one by one for the first that is missing
      for (int k = 0; k < ncols; ++k)
        if (lclJ.sumIntoValues(rows[r], &cols[k], 1, &zero, sortedRows, true) == 0) {
          out.firstDropped = "row node " + std::to_string(held_.globalNode(c.rowNodes[r / dim_])) +
                             ", column node " + std::to_string(held_.globalNode(c.colNodes[k / dim_]));
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

std::vector<std::pair<LocalIndex, GlobalIndex>> SurfaceInteractionPart::couplings(const Vector& u, Real radius) {
  const std::vector<Real>& x = coordinatesCovering(u, radius);
  // rows: the nodes of this rank's facets, all on its overlap map; columns: any held node
  std::vector<std::pair<LocalIndex, GlobalIndex>> out;
  for (const auto& [row, column] : interaction_->couplings(x.data(), radius)) {
    const LocalIndex meshRow = held_.meshNode(row);
    if (meshRow < 0) throw std::logic_error("SurfaceInteractionPart: a coupling row off this rank's mesh");
    out.emplace_back(meshRow, held_.globalNode(column));
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::array<Real, 3>> SurfaceInteractionPart::forces() const {
  return sumOverRanks(*dofs_->comm(), interaction_->summary().resultant);  // this rank's pairs, summed
}

}  // namespace cgcm::assembly
