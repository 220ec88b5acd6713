#include "cgcm/assembly/DofMap.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultSerialComm.hpp>
#include <Tpetra_TieBreak.hpp>
#include <Zoltan2_BasicVectorAdapter.hpp>
#include <Zoltan2_PartitioningProblem.hpp>

#include <algorithm>
#include <set>
#include <stdexcept>
#include <string>

#include "cgcm/core/Error.hpp"
#include "cgcm/core/ParameterValidators.hpp"

namespace cgcm::assembly {

CellPartition parseCellPartition(const std::string& name) {
  if (name == "geometric") return CellPartition::Geometric;
  if (name == "contiguous") return CellPartition::Contiguous;
  throw InputError("Solver/Partition = \"" + name + "\": allowed values are \"geometric\" and \"contiguous\"");
}

Teuchos::RCP<const Teuchos::ParameterList> validParameters() {
  static const Teuchos::RCP<const Teuchos::ParameterList> valid = [] {
    auto list = Teuchos::rcp(new Teuchos::ParameterList("Solver"));
    list->set("Partition", "geometric",
              "how cells are split over MPI ranks: \"geometric\" (Zoltan2 multi-jagged cuts of the cell "
              "centroids: compact subdomains, short interfaces) or \"contiguous\" (ranges of the mesh's cell "
              "numbering); no effect on one rank",
              validators::choices({"geometric", "contiguous"}));
    return Teuchos::RCP<const Teuchos::ParameterList>(list);
  }();
  return valid;
}

namespace {

// `numSubdomains` subdomains of the mesh-wide cells, computed by the ranks of `comm`, each of which holds the whole mesh.
std::vector<int> cellSubdomains(const Comm& comm, const mesh::Mesh& mesh, CellPartition partition, int numSubdomains) {
  if (partition == CellPartition::Subdomain) throw std::logic_error("partitionCells: a subdomain is partitioned");
  if (numSubdomains < 1) throw std::logic_error("partitionCells: " + std::to_string(numSubdomains) + " subdomains");
  const int rank = comm.getRank(), p = comm.getSize();
  const LocalIndex numCells = mesh.numCells();
  auto first = [&](int r, int of) { return LocalIndex((long long)numCells * r / of); };
  std::vector<int> owner(numCells, 0);
  if (numSubdomains == 1) return owner;
  if (partition == CellPartition::Contiguous) {
    for (int r = 0; r < numSubdomains; ++r)
      for (LocalIndex c = first(r, numSubdomains); c < first(r + 1, numSubdomains); ++c) owner[c] = r;
    return owner;
  }
  // Each rank hands Zoltan2 the centroids of a contiguous share; the parts come back per share and are
  // summed into the mesh-wide list.
  const int dim = mesh.dim;
  std::vector<GlobalIndex> ids;
  std::vector<Real> centroids[3], weights;
  LocalIndex cell = 0;
  for (const auto& block : mesh.blocks) {
    const int npc = mesh::nodesPerCell(block.type);
    for (LocalIndex c = 0; c < block.numCells(); ++c, ++cell) {
      if (cell < first(rank, p) || cell >= first(rank + 1, p)) continue;
      ids.push_back(cell);
      for (int i = 0; i < dim; ++i) {
        Real x = 0.0;
        for (int a = 0; a < npc; ++a) x += mesh.coords[std::size_t(dim) * block.connectivity[std::size_t(c) * npc + a] + i];
        centroids[i].push_back(x / npc);
      }
      weights.push_back(Real(dim * npc) * Real(dim * npc));  // tangent entries: the assembly work
    }
  }
  using Adapter = Zoltan2::BasicVectorAdapter<Zoltan2::BasicUserTypes<Real, LocalIndex, GlobalIndex>>;
  Adapter adapter(LocalIndex(ids.size()), ids.data(), centroids[0].data(), centroids[1].data(),
                  dim == 3 ? centroids[2].data() : nullptr, 1, 1, 1, true, weights.data(), 1);
  Teuchos::ParameterList params;
  params.set("algorithm", "multijagged");
  params.set("num_global_parts", numSubdomains);
  params.set("imbalance_tolerance", 1.02);
  Zoltan2::PartitioningProblem<Adapter> problem(&adapter, &params, Teuchos::rcpFromRef(comm));
  problem.solve();
  const auto* parts = problem.getSolution().getPartListView();
  std::vector<int> mine(numCells, 0);
  for (std::size_t k = 0; k < ids.size(); ++k) mine[ids[k]] = int(parts[k]);
  if (p == 1) return mine;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, int(numCells), mine.data(), owner.data());
  return owner;
}

}  // namespace

std::vector<int> partitionCells(const Comm& comm, const mesh::Mesh& mesh, CellPartition partition) {
  return cellSubdomains(comm, mesh, partition, comm.getSize());
}

std::vector<int> partitionCells(const mesh::Mesh& mesh, CellPartition partition, int numSubdomains) {
  return cellSubdomains(Teuchos::SerialComm<int>(), mesh, partition, numSubdomains);
}

namespace {

// Ownership of a node shared by several ranks: the lowest, as for a mesh held whole.
struct LowestRank : Tpetra::Details::TieBreak<LocalIndex, GlobalIndex> {
  bool mayHaveSideEffects() const override { return false; }
  std::size_t selectedIndex(GlobalIndex, const std::vector<std::pair<int, LocalIndex>>& pidAndLid) const override {
    return std::size_t(std::min_element(pidAndLid.begin(), pidAndLid.end()) - pidAndLid.begin());
  }
};

}  // namespace

DofMap::DofMap(const Teuchos::RCP<const Comm>& comm, const mesh::Mesh& mesh, int dofsPerNode,
               CellPartition partition)
    : comm_(comm),
      dofsPerNode_(dofsPerNode),
      cellOwner_(partition == CellPartition::Subdomain ? std::vector<int>(std::size_t(mesh.numCells()), comm->getRank())
                                                       : partitionCells(*comm, mesh, partition)),
      nodeIds_(mesh.nodeIds),
      numMeshNodes_(mesh.numNodes()) {
  const int rank = comm->getRank(), p = comm->getSize();
  std::string badIds;  // thrown on every rank at once: the ranks' subdomains have ids of their own
  if (!nodeIds_.empty()) {
    if (nodeIds_.size() != std::size_t(mesh.numNodes()))
      badIds = "the mesh has " + std::to_string(nodeIds_.size()) + " node ids for " + std::to_string(mesh.numNodes()) +
               " nodes";
    for (LocalIndex n = 0; badIds.empty() && n < mesh.numNodes(); ++n)
      if (nodeIds_[n] < 0 || !meshNodes_.emplace(nodeIds_[n], n).second)
        badIds = "node id " + std::to_string(nodeIds_[n]) + " is negative or repeated";
  }
  int anyBad = 0;
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, int(!badIds.empty()), Teuchos::outArg(anyBad));
  if (anyBad) throw std::logic_error("DofMap: " + (badIds.empty() ? std::string("another rank's node ids are wrong") : badIds));

  std::vector<int> nodeOwner(std::size_t(mesh.numNodes()), p);
  localCells_.resize(mesh.blocks.size());
  std::set<LocalIndex> touched;
  LocalIndex cell = 0;
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    const auto& blk = mesh.blocks[b];
    const int npc = mesh::nodesPerCell(blk.type);
    for (LocalIndex c = 0; c < blk.numCells(); ++c, ++cell) {
      const int owner = cellOwner_[cell];
      for (int a = 0; a < npc; ++a) {
        const LocalIndex n = blk.connectivity[std::size_t(c) * npc + a];
        nodeOwner[n] = std::min(nodeOwner[n], owner);
        if (owner == rank) touched.insert(n);
      }
      if (owner == rank) localCells_[b].push_back(c);
    }
  }
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  ownsNode_.assign(std::size_t(mesh.numNodes()), 0);
  if (partition != CellPartition::Subdomain) {
    // Nodes that belong to no cell would make the system singular.
    for (LocalIndex n = 0; n < mesh.numNodes(); ++n) ownsNode_[n] = nodeOwner[n] == rank || (nodeOwner[n] == p && rank == 0);
  } else {  // the ranks that share a node see only their own cells: Tpetra's directory settles it
    std::vector<GlobalIndex> ids;
    for (LocalIndex n : touched) ids.push_back(globalNode(n));
    const Teuchos::RCP<const Map> touchedMap = Teuchos::rcp(new Map(invalid, ids.data(), ids.size(), 0, comm));
    const LowestRank lowest;
    const auto oneToOne = Tpetra::createOneToOne(touchedMap, lowest);
    for (LocalIndex n : touched) ownsNode_[n] = oneToOne->isNodeGlobalElement(globalNode(n));
  }

  std::vector<GlobalIndex> ownedNodes, overlapNodes;
  for (LocalIndex n = 0; n < mesh.numNodes(); ++n)
    if (ownsNode_[n]) ownedNodes.push_back(globalNode(n));
  overlapNodes = ownedNodes;
  for (LocalIndex n : touched)
    if (!ownsNode_[n]) overlapNodes.push_back(globalNode(n));
  auto dofsOf = [dofsPerNode](const std::vector<GlobalIndex>& nodes) {
    std::vector<GlobalIndex> dofs;
    dofs.reserve(nodes.size() * dofsPerNode);
    for (GlobalIndex id : nodes)
      for (int i = 0; i < dofsPerNode; ++i) dofs.push_back(id * dofsPerNode + i);
    return dofs;
  };
  const std::vector<GlobalIndex> owned = dofsOf(ownedNodes), overlap = dofsOf(overlapNodes);

  ownedMap_ = Teuchos::rcp(new Map(invalid, owned.data(), owned.size(), 0, comm));
  overlapMap_ = Teuchos::rcp(new Map(invalid, overlap.data(), overlap.size(), 0, comm));
  importer_ = Teuchos::rcp(new Import(ownedMap_, overlapMap_));
  ownedNodeMap_ = Teuchos::rcp(new Map(invalid, ownedNodes.data(), ownedNodes.size(), 0, comm));
  overlapNodeMap_ = Teuchos::rcp(new Map(invalid, overlapNodes.data(), overlapNodes.size(), 0, comm));
  nodeImporter_ = Teuchos::rcp(new Import(ownedNodeMap_, overlapNodeMap_));
  // Output and restart gather the dofs by id (0 .. n - 1); ids with gaps would lose some.
  if (ownedMap_->getMaxAllGlobalIndex() + 1 != GlobalIndex(ownedMap_->getGlobalNumElements()))
    throw std::logic_error("DofMap: the mesh's node ids are not 0 .. (number of nodes) - 1");
}

std::vector<Real> DofMap::sumOverSharers(const std::vector<Real>& perOverlapNode) const {
  if (perOverlapNode.size() != overlapNodeMap_->getNodeNumElements())
    throw std::logic_error("DofMap::sumOverSharers: one value per overlap node expected");
  Vector local(overlapNodeMap_), total(ownedNodeMap_);
  {
    auto h = local.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (std::size_t k = 0; k < perOverlapNode.size(); ++k) h(k, 0) = perOverlapNode[k];
  }
  total.doExport(local, *nodeImporter_, Tpetra::ADD);  // the import in reverse: sharers to owners
  local.doImport(total, *nodeImporter_, Tpetra::INSERT);
  auto h = local.getLocalViewHost(Tpetra::Access::ReadOnly);
  std::vector<Real> sum(perOverlapNode.size());
  for (std::size_t k = 0; k < sum.size(); ++k) sum[k] = h(k, 0);
  return sum;
}

LocalIndex DofMap::meshNode(GlobalIndex id) const {
  if (nodeIds_.empty()) return id >= 0 && id < numMeshNodes_ ? LocalIndex(id) : -1;
  const auto it = meshNodes_.find(id);
  return it == meshNodes_.end() ? -1 : it->second;
}

Teuchos::RCP<MultiVector> rigidBodyModes(const DofMap& dofs, const mesh::Mesh& mesh, Formulation formulation) {
  if (formulation == Formulation::Axisymmetric) return Teuchos::null;
  const int dim = dofs.dofsPerNode();
  const int numModes = dim == 3 ? 6 : 3;
  auto modes = Teuchos::rcp(new MultiVector(dofs.ownedMap(), numModes));
  // About the centroid, so that the rotations are not dominated by a translation.
  const Map& map = *dofs.ownedMap();
  Real sum[3] = {0.0, 0.0, 0.0}, centre[3] = {0.0, 0.0, 0.0};
  for (std::size_t lid = 0; lid < map.getNodeNumElements(); ++lid) {
    const GlobalIndex gid = map.getGlobalElement(LocalIndex(lid));
    sum[gid % dim] += mesh.coord(dofs.meshNodeOfDof(gid), int(gid % dim));
  }
  Teuchos::reduceAll(*dofs.comm(), Teuchos::REDUCE_SUM, dim, sum, centre);
  const auto numNodes = Real(map.getGlobalNumElements() / std::size_t(dim));
  for (int i = 0; i < dim; ++i) centre[i] /= numNodes;
  auto v = modes->getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (std::size_t lid = 0; lid < map.getNodeNumElements(); ++lid) {
    const GlobalIndex gid = map.getGlobalElement(LocalIndex(lid));
    const LocalIndex node = dofs.meshNodeOfDof(gid);
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
