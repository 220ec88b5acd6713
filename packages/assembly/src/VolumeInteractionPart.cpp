#include "cgcm/assembly/VolumeInteractionPart.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>
#include <type_traits>

#include "cgcm/core/Error.hpp"

namespace cgcm::assembly {

namespace {

std::vector<LocalIndex> cellNodes(const mesh::Mesh& mesh) {
  std::vector<LocalIndex> nodes;
  for (const auto& b : mesh.blocks) nodes.insert(nodes.end(), b.connectivity.begin(), b.connectivity.end());
  return nodes;
}

}  // namespace

VolumeInteractionPart::VolumeInteractionPart(Teuchos::RCP<const DofMap> dofs, const mesh::Mesh& mesh,
                                             std::shared_ptr<interaction::VolumeInteraction> interaction,
                                             Real searchRadiusFactor)
    : InteractionPart(std::move(dofs)),
      mesh_(&mesh),
      interaction_(std::move(interaction)),
      searchRadiusFactor_(searchRadiusFactor),
      // every node of every cell: the bodies' volumes near each other are not known in advance
      coords_(*dofs_, mesh, cellNodes(mesh)) {
  if (!(searchRadiusFactor > 1.0))
    throw InputError("Interaction/Search Radius Factor = " + std::to_string(searchRadiusFactor) +
                     ": the graph search radius must exceed the interaction cutoff (factor > 1)");
  // this rank lists and evaluates the pairs whose row cell it owns
  const int rank = dofs_->comm()->getRank();
  std::vector<char> owns(mesh.numCells());
  for (LocalIndex c = 0; c < mesh.numCells(); ++c) owns[c] = dofs_->cellOwner(c) == rank;
  interaction_->setRowCells(std::move(owns));
  const int dim = dofs_->dofsPerNode();
  const Map& overlap = *dofs_->overlapMap();
  rowIds_ = Kokkos::View<LocalIndex**>("cgcm::volume_row_ids", mesh.numNodes(), dim);
  for (LocalIndex n = 0; n < mesh.numNodes(); ++n)
    for (int i = 0; i < dim; ++i) rowIds_(n, i) = overlap.getLocalElement(dofs_->dof(n, i));
}

InteractionPart::Outcome VolumeInteractionPart::assemble(const Vector& u, const VectorView& fv, Matrix* J) {
  const std::vector<Real>& x = coords_.update(u);
  const auto t0 = std::chrono::steady_clock::now();
  interaction_->updatePairs(x.data());
  searchSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const int dim = dofs_->dofsPerNode();
  const bool sortedRows = J && J->getCrsGraph()->isSorted();  // bisection in each row, not a scan
  Matrix::local_matrix_device_type lclJ;
  if (J) {
    lclJ = J->getLocalMatrixDevice();
    if (J->getColMap().get() != colMapOfIds_.get()) {  // a new graph: its column ids, once
      const Map& colMap = *J->getColMap();
      colIds_ = Kokkos::View<LocalIndex**>("cgcm::volume_col_ids", rowIds_.extent(0), dim);
      for (std::size_t n = 0; n < rowIds_.extent(0); ++n)
        for (int i = 0; i < dim; ++i) colIds_(n, i) = colMap.getLocalElement(dofs_->dof(LocalIndex(n), i));
      colMapOfIds_ = J->getColMap();
    }
  }
  const auto colIds = colIds_;
  Kokkos::View<int[1]> dropped("cgcm::volume_dropped");
  Kokkos::View<LocalIndex[2]> nonFinite("cgcm::volume_non_finite");  // the first pair's cells + 1, 0: none
  Kokkos::View<LocalIndex[2]> firstMissing("cgcm::volume_first_missing");  // row, column node + 1, 0: none
  const auto rowIds = rowIds_;
  const bool withTangent = J != nullptr;
  auto scatter = [=](const auto& c, long) {
    constexpr int maxNodes = std::decay_t<decltype(c)>::maxNodes;  // linear meshes: 8, else 27
    LocalIndex rows[3 * maxNodes], cols[6 * maxNodes];
    const int nr = dim * c.numRowNodes, nc = dim * c.numColNodes;
    bool finite = true;
    for (int r = 0; r < nr; ++r) finite = finite && std::isfinite(c.f[r]);
    if (!finite) {  // coincident quadrature points: interpenetrating bodies
      if (Kokkos::atomic_compare_exchange(&nonFinite(0), LocalIndex(0), c.rowNodes[0] + 1) == 0)
        nonFinite(1) = c.colNodes[c.numRowNodes] + 1;
      return;
    }
    for (int a = 0; a < c.numRowNodes; ++a)
      for (int i = 0; i < dim; ++i) rows[dim * a + i] = rowIds(c.rowNodes[a], i);
    for (int r = 0; r < nr; ++r) Kokkos::atomic_add(&fv(rows[r], 0), c.f[r]);
    if (!withTangent) return;
    for (int b = 0; b < c.numColNodes; ++b)
      for (int j = 0; j < dim; ++j) cols[dim * b + j] = colIds(c.colNodes[b], j);
    int missing = 0;
    // sumIntoValues skips columns missing from the row and returns how many it found
    for (int r = 0; r < nr; ++r) {
      const int m = nc - lclJ.sumIntoValues(rows[r], cols, nc, c.K[r], sortedRows, true);
      if (m == 0) continue;
      missing += m;
      const Real zero = 0.0;  // probe the columns one by one for the first that is missing
      for (int k = 0; k < nc; ++k)
        if (lclJ.sumIntoValues(rows[r], &cols[k], 1, &zero, sortedRows, true) == 0) {
          if (Kokkos::atomic_compare_exchange(&firstMissing(0), LocalIndex(0), c.rowNodes[r / dim] + 1) == 0)
            firstMissing(1) = c.colNodes[k / dim] + 1;
          break;
        }
    }
    if (missing) Kokkos::atomic_add(&dropped(0), missing);
  };
  interaction_->evaluate(x.data(), scatter, withTangent);
  Outcome out;
  out.dropped = dropped(0);
  if (firstMissing(0) > 0)
    out.firstDropped = "row node " + std::to_string(dofs_->globalNode(firstMissing(0) - 1)) + ", column node " +
                       std::to_string(dofs_->globalNode(firstMissing(1) - 1));
  if (nonFinite(0) > 0)
    out.failure = "volume pair interaction: a non-finite force between the cells of nodes " +
              std::to_string(dofs_->globalNode(nonFinite(0) - 1)) + " and " +
              std::to_string(dofs_->globalNode(nonFinite(1) - 1)) +
              " (their quadrature points coincide: the bodies interpenetrate)";
  return out;
}

std::vector<std::pair<LocalIndex, GlobalIndex>> VolumeInteractionPart::couplings(const Vector& u, Real radius) {
  const std::vector<Real>& x = coords_.update(u);
  std::vector<std::pair<LocalIndex, GlobalIndex>> wanted;
  for (const auto& [row, column] : interaction_->couplings(x.data(), radius))
    if (rowIds_(row, 0) >= 0) wanted.emplace_back(row, dofs_->globalNode(column));
  std::sort(wanted.begin(), wanted.end());
  return wanted;
}

InteractionPart::HeldSurfaces VolumeInteractionPart::heldSurfaces(const Vector& u) {
  HeldSurfaces out;
  out.surfaces = &mesh_->surfaces;
  out.coords = &coords_.update(u);
  for (const auto& s : mesh_->surfaces) out.ownFacets.push_back(s.numFacets());
  return out;
}

std::vector<std::array<Real, 3>> VolumeInteractionPart::forces() const {
  return sumOverRanks(*dofs_->comm(), interaction_->summary().resultant);
}

}  // namespace cgcm::assembly
