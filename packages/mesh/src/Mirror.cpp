#include "cgcm/mesh/Mirror.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "cgcm/core/Error.hpp"

namespace cgcm::mesh {

void mirror(Mesh& mesh, int axis, Real tolerance) {
  if (axis < 0 || axis >= mesh.dim) throw InputError("mirror plane axis out of range");
  if (!mesh.nodeIds.empty()) throw std::logic_error("mesh::mirror: a mesh with its own node ids is a distributed part");
  const char name = "xyz"[axis];
  const LocalIndex nn = mesh.numNodes();
  Real extent = 0.0;
  for (LocalIndex n = 0; n < nn; ++n) extent = std::max(extent, std::abs(mesh.coord(n, axis)));
  for (int i = 0; i < mesh.dim; ++i) {
    Real lo = 0.0, hi = 0.0;
    for (LocalIndex n = 0; n < nn; ++n) lo = std::min(lo, mesh.coord(n, i)), hi = std::max(hi, mesh.coord(n, i));
    extent = std::max(extent, hi - lo);
  }
  const Real tol = tolerance * extent;

  // image[n]: the reflected node (n itself on the plane)
  std::vector<LocalIndex> image(nn);
  std::vector<char> onPlane(nn, 0);
  for (LocalIndex n = 0; n < nn; ++n) {
    const Real x = mesh.coord(n, axis);
    if (x < -tol)
      throw InputError(std::string("mirror in ") + name + ": node " + std::to_string(n) + " has " + name + " = " +
                       std::to_string(x) + " < 0; draw the half on the side " + name + " >= 0");
    if (x <= tol) {
      onPlane[n] = 1;
      image[n] = n;
      mesh.coords[std::size_t(n) * mesh.dim + axis] = 0.0;  // exactly on the plane
      continue;
    }
    image[n] = mesh.numNodes();
    for (int i = 0; i < mesh.dim; ++i) mesh.coords.push_back(i == axis ? -x : mesh.coord(n, i));
  }

  onPlane.resize(mesh.numNodes(), 0);  // image nodes lie off the plane

  // bodies: joined with their image when they touch the plane, else a new image body
  std::vector<char> touches(mesh.numBodies, 0);
  for (const auto& b : mesh.blocks)
    for (LocalIndex n : b.connectivity) touches[b.body] = touches[b.body] || onPlane[n];
  std::vector<int> imageBody(mesh.numBodies);
  int bodies = mesh.numBodies;
  for (int b = 0; b < mesh.numBodies; ++b) imageBody[b] = touches[b] ? b : bodies++;

  const LocalIndex cellsBefore = mesh.numCells();
  const std::size_t blocksBefore = mesh.blocks.size();
  for (std::size_t bi = 0; bi < blocksBefore; ++bi) {
    ElementBlock img = mesh.blocks[bi];
    const int npc = nodesPerCell(img.type);
    const int* order = cellTypeInfo(img.type).reflected;
    const auto& src = mesh.blocks[bi].connectivity;
    for (std::size_t c = 0; c < src.size() / npc; ++c)
      for (int a = 0; a < npc; ++a) img.connectivity[c * npc + a] = image[src[c * npc + order[a]]];
    img.name += std::string(" mirrored in ") + name;
    img.body = imageBody[img.body];
    mesh.blocks.push_back(std::move(img));
  }

  for (auto it = mesh.nodeSets.begin(); it != mesh.nodeSets.end();) {
    if (it->first == std::string("symmetry ") + name) {
      it = mesh.nodeSets.erase(it);
      continue;
    }
    auto& nodes = it->second;
    const std::size_t count = nodes.size();
    for (std::size_t k = 0; k < count; ++k) nodes.push_back(image[nodes[k]]);
    std::sort(nodes.begin(), nodes.end());
    nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    ++it;
  }

  mesh.surfaces.resize(bodies);
  for (int b = 0; b < mesh.numBodies; ++b) {
    Surface src = mesh.surfaces[b];
    Surface& dst = mesh.surfaces[imageBody[b]];
    dst.body = imageBody[b];
    dst.nodesPerFacet = src.nodesPerFacet;
    const int npf = src.nodesPerFacet;
    if (npf == 0 || src.facets.empty()) continue;
    const int* order = rowWithFacets(mesh.dim, npf).reflectedFacet;
    for (LocalIndex f = 0; f < src.numFacets(); ++f) {
      const LocalIndex* nodes = &src.facets[std::size_t(f) * npf];
      bool inPlane = true;
      for (int a = 0; a < npf; ++a) inPlane = inPlane && onPlane[nodes[a]];
      if (inPlane) continue;  // interior once both halves are there
      for (int a = 0; a < npf; ++a) dst.facets.push_back(image[nodes[order[a]]]);
      if (!src.facetCells.empty()) dst.facetCells.push_back(cellsBefore + src.facetCells[f]);
    }
  }
  // facets in the plane of joined bodies were exterior only while the other half was missing
  for (int b = 0; b < mesh.numBodies; ++b) {
    if (!touches[b]) continue;
    Surface& s = mesh.surfaces[b];
    const int npf = s.nodesPerFacet;
    Surface kept{s.body, npf, {}, {}};
    for (LocalIndex f = 0; f < s.numFacets(); ++f) {
      const LocalIndex* nodes = &s.facets[std::size_t(f) * npf];
      bool inPlane = true;
      for (int a = 0; a < npf; ++a) inPlane = inPlane && onPlane[nodes[a]];
      if (inPlane) continue;
      kept.facets.insert(kept.facets.end(), nodes, nodes + npf);
      if (!s.facetCells.empty()) kept.facetCells.push_back(s.facetCells[f]);
    }
    s = std::move(kept);
  }
  mesh.numBodies = bodies;
}

std::string unmirroredName(std::string name) {
  const std::string ending = " mirrored in ";  // + the plane's letter, as mirror() names an image body
  while (name.size() > ending.size() + 1 && name.compare(name.size() - ending.size() - 1, ending.size(), ending) == 0)
    name.resize(name.size() - ending.size() - 1);
  return name;
}

}  // namespace cgcm::mesh
