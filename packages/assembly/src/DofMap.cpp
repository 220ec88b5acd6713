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

Teuchos::RCP<MultiVector> rigidBodyModes(const DofMap& dofs, const mesh::Mesh& mesh, Formulation formulation) {
  if (formulation == Formulation::Axisymmetric) return Teuchos::null;
  const int dim = dofs.dofsPerNode();
  const int numModes = dim == 3 ? 6 : 3;
  auto modes = Teuchos::rcp(new MultiVector(dofs.ownedMap(), numModes));
  // About the centroid, so that the rotations are not dominated by a translation.
  Real centre[3] = {0.0, 0.0, 0.0};
  for (LocalIndex n = 0; n < mesh.numNodes(); ++n)
    for (int i = 0; i < dim; ++i) centre[i] += mesh.coord(n, i) / Real(mesh.numNodes());
  auto v = modes->getLocalViewHost(Tpetra::Access::OverwriteAll);
  const Map& map = *dofs.ownedMap();
  for (std::size_t lid = 0; lid < map.getNodeNumElements(); ++lid) {
    const GlobalIndex gid = map.getGlobalElement(LocalIndex(lid));
    const auto node = LocalIndex(gid / dim);
    const int c = int(gid % dim);
    Real x[3] = {0.0, 0.0, 0.0};
    for (int i = 0; i < dim; ++i) x[i] = mesh.coord(node, i) - centre[i];
    for (int m = 0; m < numModes; ++m) v(lid, m) = 0.0;
    v(lid, c) = 1.0;  // translations
    if (dim == 2) {
      v(lid, 2) = c == 0 ? -x[1] : x[0];  // rotation in the plane
    } else {
      // rotations about x, y, z: omega x r
      const Real rot[3][3] = {{0.0, -x[2], x[1]}, {x[2], 0.0, -x[0]}, {-x[1], x[0], 0.0}};
      for (int axis = 0; axis < 3; ++axis) v(lid, 3 + axis) = rot[axis][c];
    }
  }
  return modes;
}

}  // namespace cgcm::assembly
