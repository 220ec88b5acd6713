#pragma once
// In-memory finite-element mesh of one or more bodies.
//
// A whole mesh, or a rank's subdomain of one (mesh::subdomain); the distribution
// of degrees of freedom and the element partition are made by the assembly
// package. Node indices are 0-based indices into this mesh's arrays; a node's
// global id, which labels its degrees of freedom across the ranks, is its
// index unless `nodeIds` says otherwise.
#include <map>
#include <string>
#include <vector>

#include "cgcm/core/CellType.hpp"
#include "cgcm/core/Types.hpp"

namespace cgcm::mesh {

inline int nodesPerCell(CellType type) { return cellTypeInfo(type).numNodes; }
/// The Exodus II name of the type ("QUAD4"), as messages use it.
inline const char* cellTypeName(CellType type) { return cellTypeInfo(type).name; }
/// Local facets of a cell (edges in 2D, faces in 3D) as local node indices,
/// oriented outward as Surface documents, in Exodus II side order: side s
/// (1-based) of a cell is entry s - 1 (the rows of core/CellType.hpp).
const std::vector<std::vector<int>>& localFacets(CellType type);

/// The cells a mesh is made of (generated, or meshed by gmsh): linear, or quadratic with or
/// without the face and volume centre nodes of quadrilaterals and hexahedra.
struct ElementOrder {
  int order = 1;             ///< 1 or 2
  bool serendipity = false;  ///< order 2: QUAD8, HEX20 instead of QUAD9, HEX27 (tetrahedra: TETRA10 either way)
};

/// Cells of one type belonging to one body.
struct ElementBlock {
  std::string name;
  int body = 0;
  CellType type = CellType::Quad4;
  std::vector<LocalIndex> connectivity;  ///< nodesPerCell(type) node indices per cell
  /// Per cell, its index in the whole mesh's block (a rank's subdomain: mesh::subdomain); empty: the cell's own.
  std::vector<LocalIndex> cellIds;
  LocalIndex cellId(LocalIndex cell) const { return cellIds.empty() ? cell : cellIds[std::size_t(cell)]; }
  LocalIndex numCells() const { return LocalIndex(connectivity.size() / nodesPerCell(type)); }
};

/// Boundary surface of one body: segments (2D) or triangles/quads (3D),
/// oriented so that the outward normal is
///   2D: n = (t_y, -t_x)/|t| with t = x_b - x_a  (body on the left of a->b),
///   3D: right-hand rule over the facet's node order.
struct Surface {
  int body = 0;
  int nodesPerFacet = 2;
  std::vector<LocalIndex> facets;
  /// Per facet: the cell it bounds (mesh-wide cell index; in a rank's subdomain of a distributed mesh the
  /// subdomain's cell, or -1 where another rank holds it: mesh::subdomain).
  std::vector<LocalIndex> facetCells;
  LocalIndex numFacets() const { return LocalIndex(facets.size() / nodesPerFacet); }
};

/// A row of core/CellType.hpp whose facets have `nodesPerFacet` nodes in `dim` dimensions: what a
/// Surface's facets are (their corners, facetCornerCount; their reflection). The rows that share
/// such facets agree on them. Throws std::logic_error if no cell type has such facets.
const CellTypeInfo& rowWithFacets(int dim, int nodesPerFacet);

/// The surface with every quad4 facet split into the triangles (0, 1, 2),
/// (0, 2, 3) (facet f -> 2f, 2f + 1; facetCells follow); triangles and 2D
/// segments unchanged.
Surface triangulated(const Surface& surface);

struct Mesh {
  int dim = 2;                    ///< spatial dimension of the coordinates (2 or 3)
  std::vector<Real> coords;       ///< reference coordinates, dim per node
  std::vector<ElementBlock> blocks;
  std::map<std::string, std::vector<LocalIndex>> nodeSets;  ///< sorted, unique node indices
  std::vector<Surface> surfaces;  ///< one per body, index = body id
  int numBodies = 1;
  /// Global id of each node: its dofs are id * dofsPerNode + component. Empty: node n has id n
  /// (what the generators and readers make). Over all ranks the ids are 0 .. (nodes of the whole mesh) - 1.
  std::vector<GlobalIndex> nodeIds;

  LocalIndex numNodes() const { return LocalIndex(coords.size() / dim); }
  LocalIndex numCells() const;
  /// Mesh-wide index of the first cell of block b (cells are numbered block after block).
  LocalIndex firstCellOfBlock(std::size_t b) const;
  Real coord(LocalIndex node, int i) const { return coords[std::size_t(node) * dim + i]; }
  GlobalIndex globalNode(LocalIndex node) const { return nodeIds.empty() ? GlobalIndex(node) : nodeIds[node]; }
  /// Node set by name; throws InputError listing the available names.
  const std::vector<LocalIndex>& nodeSet(const std::string& name) const;
};

/// The names of a mesh's bodies (index = body id): of each body's first element block.
std::vector<std::string> bodyNames(const Mesh& mesh);

}  // namespace cgcm::mesh
