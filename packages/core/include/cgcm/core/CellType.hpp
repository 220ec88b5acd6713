#pragma once
// The cell types of the meshes, one row each: everything the mesh readers,
// the mirror, the Exodus writer and the kernels' dispatch (fem/Dispatch.hpp)
// need to know about a cell's nodes. A new cell type is one enumerator, one
// row of kCellTypes, its shape functions (fem/Elements.hpp) and one entry in
// fem::Elements.
//
// Local node orders are the Exodus II ones (fem/Elements.hpp draws them; the
// linear cells' are also VTK's); facets are listed in Exodus side order (side
// s, 1-based, is entry s - 1), each oriented so that the right-hand rule over
// its corners (2D: the body on the left of node 0 -> node 1) points out of the
// cell. A quadratic cell's facet lists its corners, then its mid-edge nodes in
// the order of the edges (corner 0 -> 1, 1 -> 2, ...), then its face centre:
// the node order of the facet's own element (Line3, Tri6, Quad8, Quad9).
#include <cstddef>

namespace cgcm {

enum class CellType { Quad4, Hex8, Tet4, Quad8, Quad9, Tet10, Hex20, Hex27 };

inline constexpr int kMaxCellNodes = 27;   ///< the most nodes of any row below
inline constexpr int kMaxCellFacets = 6;   ///< the most facets of any row below
inline constexpr int kMaxFacetNodes = 9;   ///< the most nodes of any row's facets
inline constexpr int kMaxCellCorners = 8;  ///< the most corners of any row's orientation test

struct CellTypeInfo {
  CellType type;
  const char* name;  ///< the Exodus II element type, also the name in messages: "QUAD4"
  int dim;           ///< of the cell and of the formulation that takes it
  int numNodes;
  bool simplex;  ///< parent domain: the unit simplex (else the cube [-1, 1]^dim)
  int order;     ///< of the shape functions: 1 (straight edges) or 2 (mid-edge nodes, curved edges and facets)
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
  /// positive triple product) in a positively ordered cell. Corners only: a quadratic cell
  /// is tested as the linear cell of its corners.
  int numCorners;
  int corners[kMaxCellCorners][4];
};

// clang-format off
inline constexpr CellTypeInfo kCellTypes[] = {
    {CellType::Quad4, "QUAD4", 2, 4, false, 1,
     4, 2, {{0, 1}, {1, 2}, {2, 3}, {3, 0}},
     3, "Quadrilateral 4", 1, {0, 1, 2, 3},
     {0, 3, 2, 1}, {1, 0},
     4, {{0, 1, 3}, {1, 2, 0}, {2, 3, 1}, {3, 0, 2}}},
    {CellType::Hex8, "HEX8", 3, 8, false, 1,
     6, 4, {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}},
     5, "Hexahedron 8", 3, {0, 1, 2, 3, 4, 5, 6, 7},
     {0, 3, 2, 1, 4, 7, 6, 5}, {0, 3, 2, 1},
     8, {{0, 1, 3, 4}, {1, 2, 0, 5}, {2, 3, 1, 6}, {3, 0, 2, 7},
         {4, 7, 5, 0}, {5, 4, 6, 1}, {6, 5, 7, 2}, {7, 6, 4, 3}}},
    {CellType::Tet4, "TETRA4", 3, 4, true, 1,
     4, 3, {{0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {0, 2, 1}},
     4, "Tetrahedron 4", 2, {0, 1, 2, 3},
     {0, 2, 1, 3}, {0, 2, 1},
     1, {{0, 1, 2, 3}}},
    {CellType::Quad8, "QUAD8", 2, 8, false, 2,
     4, 3, {{0, 1, 4}, {1, 2, 5}, {2, 3, 6}, {3, 0, 7}},
     16, "Quadrilateral 8", 8, {0, 1, 2, 3, 4, 5, 6, 7},
     {0, 3, 2, 1, 7, 6, 5, 4}, {1, 0, 2},
     4, {{0, 1, 3}, {1, 2, 0}, {2, 3, 1}, {3, 0, 2}}},
    {CellType::Quad9, "QUAD9", 2, 9, false, 2,
     4, 3, {{0, 1, 4}, {1, 2, 5}, {2, 3, 6}, {3, 0, 7}},
     10, "Quadrilateral 9", 8, {0, 1, 2, 3, 4, 5, 6, 7, 8},
     {0, 3, 2, 1, 7, 6, 5, 4, 8}, {1, 0, 2},
     4, {{0, 1, 3}, {1, 2, 0}, {2, 3, 1}, {3, 0, 2}}},
    {CellType::Tet10, "TETRA10", 3, 10, true, 2,
     4, 6, {{0, 1, 3, 4, 8, 7}, {1, 2, 3, 5, 9, 8}, {0, 3, 2, 7, 9, 6}, {0, 2, 1, 6, 5, 4}},
     11, "Tetrahedron 10", 9, {0, 1, 2, 3, 4, 5, 6, 7, 9, 8},
     {0, 2, 1, 3, 6, 5, 4, 7, 9, 8}, {0, 2, 1, 5, 4, 3},
     1, {{0, 1, 2, 3}}},
    {CellType::Hex20, "HEX20", 3, 20, false, 2,
     6, 8, {{0, 1, 5, 4, 8, 13, 16, 12}, {1, 2, 6, 5, 9, 14, 17, 13}, {2, 3, 7, 6, 10, 15, 18, 14},
            {0, 4, 7, 3, 12, 19, 15, 11}, {0, 3, 2, 1, 11, 10, 9, 8}, {4, 5, 6, 7, 16, 17, 18, 19}},
     17, "Hexahedron 20", 16, {0, 1, 2, 3, 4, 5, 6, 7, 8, 11, 13, 9, 10, 12, 14, 15, 16, 18, 19, 17},
     {0, 3, 2, 1, 4, 7, 6, 5, 11, 10, 9, 8, 12, 15, 14, 13, 19, 18, 17, 16}, {0, 3, 2, 1, 7, 6, 5, 4},
     8, {{0, 1, 3, 4}, {1, 2, 0, 5}, {2, 3, 1, 6}, {3, 0, 2, 7},
         {4, 7, 5, 0}, {5, 4, 6, 1}, {6, 5, 7, 2}, {7, 6, 4, 3}}},
    {CellType::Hex27, "HEX27", 3, 27, false, 2,
     6, 9, {{0, 1, 5, 4, 8, 13, 16, 12, 25}, {1, 2, 6, 5, 9, 14, 17, 13, 24}, {2, 3, 7, 6, 10, 15, 18, 14, 26},
            {0, 4, 7, 3, 12, 19, 15, 11, 23}, {0, 3, 2, 1, 11, 10, 9, 8, 21}, {4, 5, 6, 7, 16, 17, 18, 19, 22}},
     12, "Hexahedron 27", 10,
     {0, 1, 2, 3, 4, 5, 6, 7, 8, 11, 13, 9, 10, 12, 14, 15, 16, 18, 19, 17, 26, 20, 25, 22, 23, 21, 24},
     {0, 3, 2, 1, 4, 7, 6, 5, 11, 10, 9, 8, 12, 15, 14, 13, 19, 18, 17, 16, 20, 21, 22, 25, 26, 23, 24},
     {0, 3, 2, 1, 7, 6, 5, 4, 8},
     8, {{0, 1, 3, 4}, {1, 2, 0, 5}, {2, 3, 1, 6}, {3, 0, 2, 7},
         {4, 7, 5, 0}, {5, 4, 6, 1}, {6, 5, 7, 2}, {7, 6, 4, 3}}},
};
// clang-format on

inline constexpr std::size_t kNumCellTypes = sizeof(kCellTypes) / sizeof(kCellTypes[0]);

/// The row of a cell type.
constexpr const CellTypeInfo& cellTypeInfo(CellType type) { return kCellTypes[static_cast<int>(type)]; }

/// The corners of a row's cells (nodes 0 .. corners - 1) and of its facets (their first nodes).
constexpr int cornerCount(const CellTypeInfo& r) { return r.simplex ? r.dim + 1 : 1 << r.dim; }
constexpr int facetCornerCount(const CellTypeInfo& r) { return r.simplex ? r.dim : 1 << (r.dim - 1); }

namespace detail {
constexpr bool cellTypeTableIsConsistent() {
  for (std::size_t k = 0; k < kNumCellTypes; ++k) {
    const CellTypeInfo& r = kCellTypes[k];
    if (static_cast<std::size_t>(r.type) != k) return false;  // rows in enumerator order
    if (r.numNodes > kMaxCellNodes || r.numFacets > kMaxCellFacets || r.nodesPerFacet > kMaxFacetNodes ||
        r.numCorners > kMaxCellCorners)
      return false;
    if ((r.order != 1 && r.order != 2) || (r.order == 1) != (r.numNodes == cornerCount(r)) ||
        (r.order == 1) != (r.nodesPerFacet == facetCornerCount(r)))
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
        if (r.corners[k][a] < 0 || r.corners[k][a] >= cornerCount(r)) return false;
    // the mirror finds a facet's reflection by (dimension, nodes per facet): one order per kind
    for (std::size_t l = 0; l < k; ++l)
      if (kCellTypes[l].dim == r.dim && kCellTypes[l].nodesPerFacet == r.nodesPerFacet)
        for (int a = 0; a < r.nodesPerFacet; ++a)
          if (kCellTypes[l].reflectedFacet[a] != r.reflectedFacet[a]) return false;
  }
  return true;
}
}  // namespace detail
static_assert(detail::cellTypeTableIsConsistent(),
              "kCellTypes: a row out of order, beyond the kMax* bounds, naming a node it does not have, with an order "
              "its node counts contradict, or reflecting a kind of facet unlike another row");

}  // namespace cgcm
