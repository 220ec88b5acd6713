#include "cgcm/assembly/InteractionPart.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <set>

namespace cgcm::assembly {

std::string InteractionPart::nodeForces(const Vector& u, Vector& forces) {
  Vector overlap(dofs_->overlapMap());  // zero
  const Outcome out = assemble(u, overlap.getLocalViewDevice(Tpetra::Access::ReadWrite), nullptr);
  if (exporter_.is_null()) exporter_ = Teuchos::rcp(new Export(dofs_->overlapMap(), dofs_->ownedMap()));
  forces.putScalar(0.0);
  forces.doExport(overlap, *exporter_, Tpetra::ADD);
  forces.scale(-1.0);  // f_C is the part's residual: the force on the body is -f_C
  return out.failure;
}

ReplicatedCoordinates::ReplicatedCoordinates(const DofMap& dofs, const mesh::Mesh& mesh,
                                             const std::vector<LocalIndex>& nodes)
    : mesh_(&mesh), coords_(mesh.coords) {
  const std::set<LocalIndex> unique(nodes.begin(), nodes.end());
  std::vector<GlobalIndex> gids;
  for (LocalIndex n : unique)
    for (int i = 0; i < dofs.dofsPerNode(); ++i) gids.push_back(dofs.dof(n, i));
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  map_ = Teuchos::rcp(new Map(invalid, gids.data(), gids.size(), 0, dofs.comm()));
  import_ = Teuchos::rcp(new Import(dofs.ownedMap(), map_));
  values_ = Teuchos::rcp(new Vector(map_));
  const int dim = dofs.dofsPerNode();
  coordOfValue_.resize(gids.size());
  for (std::size_t lid = 0; lid < gids.size(); ++lid) {
    const GlobalIndex gid = map_->getGlobalElement(LocalIndex(lid));
    coordOfValue_[lid] = std::size_t(dofs.meshNodeOfDof(gid)) * dim + std::size_t(gid % dim);
  }
}

const std::vector<Real>& ReplicatedCoordinates::update(const Vector& u) {
  values_->doImport(u, *import_, Tpetra::INSERT);
  auto v = values_->getLocalViewHost(Tpetra::Access::ReadOnly);
  for (std::size_t lid = 0; lid < coordOfValue_.size(); ++lid) {
    const std::size_t k = coordOfValue_[lid];
    coords_[k] = mesh_->coords[k] + v(lid, 0);
  }
  return coords_;
}

std::vector<std::array<Real, 3>> sumOverRanks(const Comm& comm, const std::vector<std::array<Real, 3>>& local) {
  const int n = int(local.size());
  std::vector<Real> in(3 * std::size_t(n)), out(in.size(), 0.0);
  for (int b = 0; b < n; ++b)
    for (int i = 0; i < 3; ++i) in[3 * std::size_t(b) + i] = local[b][i];
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, int(in.size()), in.data(), out.data());
  std::vector<std::array<Real, 3>> sum(n);
  for (int b = 0; b < n; ++b) sum[b] = {out[3 * b], out[3 * b + 1], out[3 * b + 2]};
  return sum;
}

}  // namespace cgcm::assembly
