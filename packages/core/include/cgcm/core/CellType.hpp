#pragma once
// The cell types of the meshes, one row each: everything the mesh readers,
// the mirror, the Exodus writer and the kernels' dispatch (fem/Dispatch.hpp)
// need to know about a cell's nodes. A new cell type is one enumerator, one
// row of kCellTypes, its shape functions (fem/Elements.hpp) and one entry in
// fem::Elements.
//
// Local node orders are the Exodus II / VTK ones (fem/Elements.hpp draws
// them); facets are listed in Exodus side order (side s, 1-based, is entry
// s - 1), each oriented so that the right-hand rule over its nodes (2D: the
// body on the left of node 0 -> node 1) points out of the cell.
#include <cstddef>

namespace cgcm {

enum class CellType { Quad4, Hex8, Tet4 };

inline constexpr int kMaxCellNodes = 8;    ///< the most nodes of any row below
inline constexpr int kMaxCellFacets = 6;   ///< the most facets of any row below
inline constexpr int kMaxFacetNodes = 4;   ///< the most nodes of any row's facets
inline constexpr int kMaxCellCorners = 8;  ///< the most corners of any row's orientation test

struct CellTypeInfo {
  CellType type;
  const char* name;  ///< the Exodus II element type, also the name in messages: "QUAD4"
  int dim;           ///< of the cell and of the formulation that takes it
  int numNodes;
  bool simplex;  ///< parent domain: the unit simplex (else the cube [-1, 1]^dim)
  int numFacets;
  int nodesPerFacet;
  int facets[kMaxCellFacets][kMaxFacetNodes];  ///< local nodes, outward, Exodus side order
  /// gmsh's element type number and name, and its facets' type number (lower-dimensional groups).
  int gmshType;
  const char* gmshName;
  int gmshFacetType;
  /// Node a of the cell is node fromGmsh[a] of gmsh's ordering of the same element.
  int fromGmsh[kMaxCellNodes];
  /// Node order of the mirror image of a cell that keeps its orientation: image node a is
  /// the reflection of node reflected[a]. reflectedFacet: the same for a facet.
  int reflected[kMaxCellNodes];
  int reflectedFacet[kMaxFacetNodes];
  /// The orientation test: per corner, the vertex and its edge neighbours in the order that
  /// makes the edge vectors right-handed (2D: positive cross product of the first two; 3D:
  /// positive triple product) in a positively ordered cell.
  int numCorners;
  int corners[kMaxCellCorners][4];
};

// clang-format off
inline constexpr CellTypeInfo kCellTypes[] = {
    {CellType::Quad4, "QUAD4", 2, 4, false,
     4, 2, {{0, 1}, {1, 2}, {2, 3}, {3, 0}},
     3, "Quadrilateral 4", 1, {0, 1, 2, 3},
     {0, 3, 2, 1}, {1, 0},
     4, {{0, 1, 3}, {1, 2, 0}, {2, 3, 1}, {3, 0, 2}}},
    {CellType::Hex8, "HEX8", 3, 8, false,
     6, 4, {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}},
     5, "Hexahedron 8", 3, {0, 1, 2, 3, 4, 5, 6, 7},
     {0, 3, 2, 1, 4, 7, 6, 5}, {0, 3, 2, 1},
     8, {{0, 1, 3, 4}, {1, 2, 0, 5}, {2, 3, 1, 6}, {3, 0, 2, 7},
         {4, 7, 5, 0}, {5, 4, 6, 1}, {6, 5, 7, 2}, {7, 6, 4, 3}}},
    {CellType::Tet4, "TETRA4", 3, 4, true,
     4, 3, {{0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {0, 2, 1}},
     4, "Tetrahedron 4", 2, {0, 1, 2, 3},
     {0, 2, 1, 3}, {0, 2, 1},
     1, {{0, 1, 2, 3}}},
};
// clang-format on

inline constexpr std::size_t kNumCellTypes = sizeof(kCellTypes) / sizeof(kCellTypes[0]);

/// The row of a cell type.
constexpr const CellTypeInfo& cellTypeInfo(CellType type) { return kCellTypes[static_cast<int>(type)]; }

namespace detail {
constexpr bool cellTypeTableIsConsistent() {
  for (std::size_t k = 0; k < kNumCellTypes; ++k) {
    const CellTypeInfo& r = kCellTypes[k];
    if (static_cast<std::size_t>(r.type) != k) return false;  // rows in enumerator order
    if (r.numNodes > kMaxCellNodes || r.numFacets > kMaxCellFacets || r.nodesPerFacet > kMaxFacetNodes ||
        r.numCorners > kMaxCellCorners)
      return false;
    for (int a = 0; a < r.numNodes; ++a)
      if (r.fromGmsh[a] < 0 || r.fromGmsh[a] >= r.numNodes || r.reflected[a] < 0 || r.reflected[a] >= r.numNodes)
        return false;
    for (int f = 0; f < r.numFacets; ++f)
      for (int a = 0; a < r.nodesPerFacet; ++a)
        if (r.facets[f][a] < 0 || r.facets[f][a] >= r.numNodes) return false;
    for (int a = 0; a < r.nodesPerFacet; ++a)
      if (r.reflectedFacet[a] < 0 || r.reflectedFacet[a] >= r.nodesPerFacet) return false;
    for (int k = 0; k < r.numCorners; ++k)
      for (int a = 0; a <= r.dim; ++a)
        if (r.corners[k][a] < 0 || r.corners[k][a] >= r.numNodes) return false;
  }
  return true;
}
}  // namespace detail
static_assert(detail::cellTypeTableIsConsistent(),
              "kCellTypes: a row out of order, beyond the kMax* bounds, or naming a node it does not have");

}  // namespace cgcm
