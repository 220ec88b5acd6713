#include "cgcm/mesh/Subdomain.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "cgcm/core/Bytes.hpp"

namespace cgcm::mesh {

Mesh subdomain(const Mesh& whole, const std::vector<int>& cellOwner, int rank, const std::vector<LocalIndex>& alsoKept) {
  if (!whole.nodeIds.empty()) throw std::logic_error("mesh::subdomain: the mesh is a subdomain already");
  if (!whole.blocks.empty() && !whole.blocks[0].cellIds.empty())
    throw std::logic_error("mesh::subdomain: the mesh is a subdomain already");
  if (cellOwner.size() != std::size_t(whole.numCells()))
    throw std::logic_error("mesh::subdomain: " + std::to_string(cellOwner.size()) + " cell owners for " +
                           std::to_string(whole.numCells()) + " cells");
  const LocalIndex numNodes = whole.numNodes();
  std::vector<char> kept(std::size_t(numNodes), 0);
  std::vector<LocalIndex> cellInSubdomain(cellOwner.size(), -1);
  LocalIndex cell = 0, subdomainCells = 0;
  for (const auto& block : whole.blocks) {
    const int npc = nodesPerCell(block.type);
    for (LocalIndex c = 0; c < block.numCells(); ++c, ++cell) {
      if (cellOwner[std::size_t(cell)] != rank) continue;
      cellInSubdomain[std::size_t(cell)] = subdomainCells++;
      for (int a = 0; a < npc; ++a) kept[std::size_t(block.connectivity[std::size_t(c) * npc + a])] = 1;
    }
  }
  // Nodes of no cell would belong to no rank: the generators and the gmsh reader make none.
  std::vector<char> inCell(std::size_t(numNodes), 0);
  for (const auto& block : whole.blocks)
    for (LocalIndex n : block.connectivity) inCell[std::size_t(n)] = 1;
  const auto orphan = std::find(inCell.begin(), inCell.end(), 0);
  if (orphan != inCell.end())
    throw std::logic_error("mesh::subdomain: node " + std::to_string(orphan - inCell.begin()) + " belongs to no cell");
  for (LocalIndex n : alsoKept) kept.at(std::size_t(n)) = 1;

  Mesh sub;
  sub.dim = whole.dim;
  sub.numBodies = whole.numBodies;
  std::vector<LocalIndex> index(std::size_t(numNodes), -1);  // whole -> subdomain
  for (LocalIndex n = 0; n < numNodes; ++n) {
    if (!kept[std::size_t(n)]) continue;
    index[std::size_t(n)] = LocalIndex(sub.nodeIds.size());
    sub.nodeIds.push_back(n);
    for (int i = 0; i < whole.dim; ++i) sub.coords.push_back(whole.coord(n, i));
  }
  cell = 0;
  for (const auto& block : whole.blocks) {
    ElementBlock b;
    b.name = block.name;
    b.body = block.body;
    b.type = block.type;
    const int npc = nodesPerCell(block.type);
    for (LocalIndex c = 0; c < block.numCells(); ++c, ++cell) {
      if (cellOwner[std::size_t(cell)] != rank) continue;
      b.cellIds.push_back(c);
      for (int a = 0; a < npc; ++a) b.connectivity.push_back(index[std::size_t(block.connectivity[std::size_t(c) * npc + a])]);
    }
    sub.blocks.push_back(std::move(b));
  }
  for (const auto& [name, nodes] : whole.nodeSets) {
    auto& mine = sub.nodeSets[name];
    for (LocalIndex n : nodes)
      if (index[std::size_t(n)] >= 0) mine.push_back(index[std::size_t(n)]);
  }
  for (const auto& s : whole.surfaces) {
    Surface t;
    t.body = s.body;
    t.nodesPerFacet = s.nodesPerFacet;
    for (LocalIndex f = 0; f < s.numFacets(); ++f) {
      const LocalIndex c = cellInSubdomain[std::size_t(s.facetCells[f])];
      if (c < 0) continue;  // another rank's facet
      for (int a = 0; a < s.nodesPerFacet; ++a)
        t.facets.push_back(index[std::size_t(s.facets[std::size_t(f) * s.nodesPerFacet + a])]);
      t.facetCells.push_back(c);
    }
    sub.surfaces.push_back(std::move(t));
  }
  return sub;
}

std::vector<char> toBytes(const Mesh& mesh) {
  core::ByteWriter out;
  out.put(mesh.dim);
  out.put(mesh.numBodies);
  out.put(mesh.coords);
  out.put(mesh.nodeIds);
  out.put(std::uint64_t(mesh.blocks.size()));
  for (const auto& b : mesh.blocks) {
    out.put(b.name);
    out.put(b.body);
    out.put(b.type);
    out.put(b.connectivity);
    out.put(b.cellIds);
  }
  out.put(std::uint64_t(mesh.nodeSets.size()));
  for (const auto& [name, nodes] : mesh.nodeSets) {
    out.put(name);
    out.put(nodes);
  }
  out.put(std::uint64_t(mesh.surfaces.size()));
  for (const auto& s : mesh.surfaces) {
    out.put(s.body);
    out.put(s.nodesPerFacet);
    out.put(s.facets);
    out.put(s.facetCells);
  }
  return out.take();
}

Mesh meshFromBytes(const std::vector<char>& bytes) {
  core::ByteReader in(bytes);
  Mesh mesh;
  mesh.dim = in.get<int>();
  mesh.numBodies = in.get<int>();
  mesh.coords = in.getVector<Real>();
  mesh.nodeIds = in.getVector<GlobalIndex>();
  mesh.blocks.resize(in.getCount(1));
  for (auto& b : mesh.blocks) {
    b.name = in.getString();
    b.body = in.get<int>();
    b.type = in.get<CellType>();
    b.connectivity = in.getVector<LocalIndex>();
    b.cellIds = in.getVector<LocalIndex>();
  }
  for (auto n = in.getCount(1); n > 0; --n) {
    std::string name = in.getString();
    mesh.nodeSets[name] = in.getVector<LocalIndex>();
  }
  mesh.surfaces.resize(in.getCount(1));
  for (auto& s : mesh.surfaces) {
    s.body = in.get<int>();
    s.nodesPerFacet = in.get<int>();
    s.facets = in.getVector<LocalIndex>();
    s.facetCells = in.getVector<LocalIndex>();
  }
  if (!in.atEnd()) throw std::logic_error("mesh::meshFromBytes: bytes left over");
  return mesh;
}

}  // namespace cgcm::mesh
