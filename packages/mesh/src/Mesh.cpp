#include "cgcm/mesh/Mesh.hpp"

#include <stdexcept>
#include <string>

#include "cgcm/core/Error.hpp"

namespace cgcm::mesh {

const std::vector<std::vector<int>>& localFacets(CellType type) {
  static const auto all = [] {
    std::vector<std::vector<std::vector<int>>> out;
    for (const CellTypeInfo& row : kCellTypes) {
      auto& facets = out.emplace_back();
      for (int f = 0; f < row.numFacets; ++f) facets.emplace_back(row.facets[f], row.facets[f] + row.nodesPerFacet);
    }
    return out;
  }();
  return all[static_cast<std::size_t>(type)];
}

const CellTypeInfo& rowWithFacets(int dim, int nodesPerFacet) {
  for (const CellTypeInfo& row : kCellTypes)
    if (row.dim == dim && row.nodesPerFacet == nodesPerFacet) return row;
  throw std::logic_error("mesh::rowWithFacets: no cell type of dimension " + std::to_string(dim) + " has facets of " +
                         std::to_string(nodesPerFacet) + " nodes");
}

std::vector<std::string> bodyNames(const Mesh& mesh) {
  std::vector<std::string> names(std::size_t(mesh.numBodies));
  for (const auto& b : mesh.blocks)
    if (names[std::size_t(b.body)].empty()) names[std::size_t(b.body)] = b.name;
  return names;
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
