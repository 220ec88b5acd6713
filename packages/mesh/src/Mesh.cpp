#include "cgcm/mesh/Mesh.hpp"

#include "cgcm/core/Error.hpp"

namespace cgcm::mesh {

int nodesPerCell(CellType type) {
  switch (type) {
    case CellType::Quad4: return 4;
    case CellType::Hex8: return 8;
    case CellType::Tet4: return 4;
  }
  return 0;
}

const char* cellTypeName(CellType type) {
  switch (type) {
    case CellType::Quad4: return "QUAD4";
    case CellType::Hex8: return "HEX8";
    case CellType::Tet4: return "TETRA4";
  }
  return "?";
}

const std::vector<std::vector<int>>& localFacets(CellType type) {
  static const std::vector<std::vector<int>> quad = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  static const std::vector<std::vector<int>> hex = {{0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6},
                                                    {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}};
  static const std::vector<std::vector<int>> tet = {{0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {0, 2, 1}};
  switch (type) {
    case CellType::Quad4: return quad;
    case CellType::Hex8: return hex;
    case CellType::Tet4: return tet;
  }
  return quad;
}

LocalIndex Mesh::numCells() const {
  LocalIndex n = 0;
  for (const auto& b : blocks) n += b.numCells();
  return n;
}

LocalIndex Mesh::firstCellOfBlock(std::size_t b) const {
  LocalIndex n = 0;
  for (std::size_t i = 0; i < b; ++i) n += blocks[i].numCells();
  return n;
}

const std::vector<LocalIndex>& Mesh::nodeSet(const std::string& name) const {
  auto it = nodeSets.find(name);
  if (it == nodeSets.end()) {
    std::string names;
    for (const auto& [n, s] : nodeSets) names += (names.empty() ? "" : ", ") + ("\"" + n + "\"");
    throw InputError("unknown node set \"" + name + "\"; this mesh has: " + names);
  }
  return it->second;
}

Surface triangulated(const Surface& s) {
  if (s.nodesPerFacet != 4) return s;
  Surface t;
  t.body = s.body;
  t.nodesPerFacet = 3;
  for (LocalIndex f = 0; f < s.numFacets(); ++f) {
    const LocalIndex* n = &s.facets[std::size_t(f) * 4];
    t.facets.insert(t.facets.end(), {n[0], n[1], n[2], n[0], n[2], n[3]});
    if (!s.facetCells.empty()) t.facetCells.insert(t.facetCells.end(), 2, s.facetCells[f]);
  }
  return t;
}

}  // namespace cgcm::mesh
