#pragma once
// Distribution of cells and degrees of freedom over MPI ranks.
//
// Cells are numbered mesh-wide (block after block); each is evaluated by
// exactly one rank. The partition is geometric by default (Zoltan2's
// multi-jagged cuts of the cell centroids, weighted by the size of a cell's
// tangent): compact subdomains with short interfaces, whatever order the mesh
// generator numbered the cells in. Contiguous: ranges of the mesh-wide
// numbering. A node is owned by the lowest rank whose cells touch it.
// Nodes are named two ways: by their index in the mesh (the arrays of this
// rank) and by their global id (mesh::Mesh::globalNode, the label shared by
// the ranks). Degree of freedom (node n, component i) has global index
// globalNode(n) * dofsPerNode + i.
#include <Teuchos_ParameterList.hpp>

#include <string>
#include <unordered_map>
#include <vector>

#include "cgcm/core/Formulation.hpp"
#include "cgcm/assembly/TpetraTypes.hpp"
#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::assembly {

/// How a DofMap finds the cells it evaluates. Geometric and Contiguous split a
/// mesh that every rank holds whole; Subdomain: the mesh is this rank's subdomain of
/// a distributed mesh (mesh::subdomain), all its cells are this rank's.
enum class CellPartition { Geometric, Contiguous, Subdomain };
/// "geometric" or "contiguous"; throws InputError otherwise.
CellPartition parseCellPartition(const std::string& name);
/// What the assembly owns of the deck's Solver sublist: Partition (parseCellPartition reads it).
Teuchos::RCP<const Teuchos::ParameterList> validParameters();
/// The rank of every mesh-wide cell of `mesh` (held whole by every rank), the
/// same list on every rank: Geometric or Contiguous. Collective.
std::vector<int> partitionCells(const Comm& comm, const mesh::Mesh& mesh, CellPartition partition);
/// The same for `numSubdomains` ranks, computed by one process that holds the whole mesh (a root that sends
/// the subdomains: mesh::subdomain).
std::vector<int> partitionCells(const mesh::Mesh& mesh, CellPartition partition, int numSubdomains);

class DofMap {
 public:
  DofMap(const Teuchos::RCP<const Comm>& comm, const mesh::Mesh& mesh, int dofsPerNode,
         CellPartition partition = CellPartition::Geometric);

  const Teuchos::RCP<const Comm>& comm() const { return comm_; }
  int dofsPerNode() const { return dofsPerNode_; }
  /// Dofs owned by this rank (rows of the distributed system).
  const Teuchos::RCP<const Map>& ownedMap() const { return ownedMap_; }
  /// Owned dofs first, then the dofs of ghost nodes touched by local cells.
  const Teuchos::RCP<const Map>& overlapMap() const { return overlapMap_; }
  const Teuchos::RCP<const Import>& ownedToOverlap() const { return importer_; }
  /// The same distribution per node (global node ids, overlap node k = overlap dofs k * dofsPerNode + i).
  const Teuchos::RCP<const Map>& ownedNodeMap() const { return ownedNodeMap_; }
  const Teuchos::RCP<const Map>& overlapNodeMap() const { return overlapNodeMap_; }
  /// Per overlap node, the sum of `perOverlapNode` over every rank whose overlap has the node. Collective.
  std::vector<Real> sumOverSharers(const std::vector<Real>& perOverlapNode) const;

  /// Cells evaluated by this rank, per element block (block-local cell indices).
  const std::vector<LocalIndex>& localCells(std::size_t block) const { return localCells_[block]; }
  /// Rank that evaluates the mesh-wide cell `cell`.
  int cellOwner(LocalIndex cell) const { return cellOwner_[cell]; }
  /// Whether this rank evaluates `cell` (false for -1: a cell of another rank's subdomain).
  bool evaluatesCell(LocalIndex cell) const { return cell >= 0 && cellOwner_[cell] == comm_->getRank(); }
  bool ownsNode(LocalIndex node) const { return ownsNode_[node] != 0; }
  /// The global id of mesh node `node`.
  GlobalIndex globalNode(LocalIndex node) const { return nodeIds_.empty() ? GlobalIndex(node) : nodeIds_[node]; }
  /// The mesh node with global id `id`, or -1 if this rank's mesh has none.
  LocalIndex meshNode(GlobalIndex id) const;
  /// The mesh node of a dof's global index (-1 if this rank's mesh has none).
  LocalIndex meshNodeOfDof(GlobalIndex dof) const { return meshNode(dof / dofsPerNode_); }
  GlobalIndex dof(LocalIndex node, int component) const { return globalNode(node) * dofsPerNode_ + component; }

 private:
  Teuchos::RCP<const Comm> comm_;
  int dofsPerNode_;
  std::vector<int> cellOwner_;  ///< per cell of the mesh given (mesh-wide index)
  std::vector<char> ownsNode_;
  std::vector<GlobalIndex> nodeIds_;                     ///< the mesh's, empty for node n = id n
  std::unordered_map<GlobalIndex, LocalIndex> meshNodes_;  ///< inverse of nodeIds_ where it is not empty
  LocalIndex numMeshNodes_ = 0;
  std::vector<std::vector<LocalIndex>> localCells_;
  Teuchos::RCP<const Map> ownedMap_, overlapMap_, ownedNodeMap_, overlapNodeMap_;
  Teuchos::RCP<const Import> importer_, nodeImporter_;
};

/// The rigid-body motions of the reference configuration on the owned dofs:
/// the near-null space of the elasticity operator that smoothed aggregation
/// needs to build good coarse spaces. 3D: three translations and three
/// rotations; plane strain: two translations and the in-plane rotation.
/// Axisymmetric: null (only the axial translation is rigid; MueLu's default
/// of one unit vector per component is then as good). Collective.
Teuchos::RCP<MultiVector> rigidBodyModes(const DofMap& dofs, const mesh::Mesh& mesh, Formulation formulation);

}  // namespace cgcm::assembly
