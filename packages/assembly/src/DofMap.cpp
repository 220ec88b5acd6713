#include "cgcm/assembly/DofMap.hpp"

#include <algorithm>
#include <set>

namespace cgcm::assembly {

int DofMap::cellOwner(LocalIndex cell) const {
  // inverse of the contiguous split below: first rank r with cell < begin(r + 1)
  const int p = comm_->getSize();
  for (int r = 0; r < p; ++r)
    if (cell < LocalIndex((long long)numCells_ * (r + 1) / p)) return r;
  return p - 1;
}

DofMap::DofMap(const Teuchos::RCP<const Comm>& comm, const mesh::Mesh& mesh, int dofsPerNode)
    : comm_(comm), dofsPerNode_(dofsPerNode), numCells_(mesh.numCells()) {
  const int rank = comm->getRank(), p = comm->getSize();
  const LocalIndex begin = LocalIndex((long long)numCells_ * rank / p);
  const LocalIndex end = LocalIndex((long long)numCells_ * (rank + 1) / p);

  nodeOwner_.assign(mesh.numNodes(), p);
  localCells_.resize(mesh.blocks.size());
  std::set<LocalIndex> touched;
  LocalIndex cell = 0;
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    const auto& blk = mesh.blocks[b];
    const int npc = mesh::nodesPerCell(blk.type);
    for (LocalIndex c = 0; c < blk.numCells(); ++c, ++cell) {
      const int owner = cellOwner(cell);
      for (int a = 0; a < npc; ++a) {
        const LocalIndex n = blk.connectivity[std::size_t(c) * npc + a];
        nodeOwner_[n] = std::min(nodeOwner_[n], owner);
        if (owner == rank) touched.insert(n);
      }
      if (cell >= begin && cell < end) localCells_[b].push_back(c);
    }
  }
  // Nodes that belong to no cell would make the system singular.
  for (LocalIndex n = 0; n < mesh.numNodes(); ++n)
    if (nodeOwner_[n] == p) nodeOwner_[n] = 0;

  std::vector<GlobalIndex> owned, overlap;
  for (LocalIndex n = 0; n < mesh.numNodes(); ++n)
    if (nodeOwner_[n] == rank)
      for (int i = 0; i < dofsPerNode; ++i) owned.push_back(dof(n, i));
  overlap = owned;
  for (LocalIndex n : touched)
    if (nodeOwner_[n] != rank)
      for (int i = 0; i < dofsPerNode; ++i) overlap.push_back(dof(n, i));

  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  ownedMap_ = Teuchos::rcp(new Map(invalid, owned.data(), owned.size(), 0, comm));
  overlapMap_ = Teuchos::rcp(new Map(invalid, overlap.data(), overlap.size(), 0, comm));
  importer_ = Teuchos::rcp(new Import(ownedMap_, overlapMap_));
}

}  // namespace cgcm::assembly
