#include "cgcm/mesh/Generators.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <stdexcept>

#include "cgcm/core/Error.hpp"

namespace cgcm::mesh {

Real uniformGrading(Real s) { return s; }

Grading powerGrading(Real power) {
  if (!(power >= 1.0)) throw InputError("mesh grading power must be >= 1, got " + std::to_string(power));
  return [power](Real s) { return std::pow(s, power); };
}

namespace {

void checkCounts(const char* what, std::initializer_list<int> counts) {
  for (int n : counts)
    if (n < 1) throw InputError(std::string(what) + ": cell counts must be >= 1");
}

// The quadratic row a linear row becomes: of the same shape, the fewest nodes (serendipity) or the most.
const CellTypeInfo& quadraticRow(const CellTypeInfo& linear, bool serendipity) {
  const CellTypeInfo* out = nullptr;
  for (const CellTypeInfo& r : kCellTypes)
    if (r.order == 2 && r.dim == linear.dim && r.simplex == linear.simplex &&
        (!out || (serendipity ? r.numNodes < out->numNodes : r.numNodes > out->numNodes)))
      out = &r;
  if (linear.order != 1 || !out)
    throw std::logic_error(std::string("mesh::elevate: ") + linear.name + " cells are not linear ones it can elevate");
  return *out;
}

// The local corners of node a of a quadratic row: those of its edge, of its face, or all of the
// cell's (read from the facets, which list mid-edge nodes and face centres after their corners).
std::vector<int> cornersOfNode(const CellTypeInfo& row, int a) {
  const int fc = facetCornerCount(row);
  for (int f = 0; f < row.numFacets; ++f)
    for (int p = fc; p < row.nodesPerFacet; ++p)
      if (row.facets[f][p] == a) {
        const int k = p - fc;
        if (k < fc) return {row.facets[f][k], row.facets[f][(k + 1) % fc]};
        return std::vector<int>(row.facets[f], row.facets[f] + fc);
      }
  std::vector<int> all(std::size_t(cornerCount(row)));
  std::iota(all.begin(), all.end(), 0);
  return all;
}

void addNodeSet(Mesh& m, const std::string& name, std::vector<LocalIndex> nodes) {
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  m.nodeSets[name] = std::move(nodes);
}

}  // namespace

Mesh rectangle(const RectangleSpec& s) {
  checkCounts("rectangle", {s.nx, s.ny});
  Mesh m;
  m.dim = 2;
  m.numBodies = s.body + 1;
  const int px = s.nx + 1, py = s.ny + 1;
  m.coords.resize(std::size_t(px) * py * 2);
  auto id = [px](int i, int j) { return LocalIndex(j * px + i); };
  for (int j = 0; j < py; ++j)
    for (int i = 0; i < px; ++i) {
      m.coords[2 * id(i, j) + 0] = s.x0 + s.lx * s.gradeX(Real(i) / s.nx);
      m.coords[2 * id(i, j) + 1] = s.y0 + s.ly * s.gradeY(Real(j) / s.ny);
    }
  ElementBlock b;
  b.name = s.name;
  b.body = s.body;
  b.type = CellType::Quad4;
  b.connectivity.reserve(std::size_t(s.nx) * s.ny * 4);
  for (int j = 0; j < s.ny; ++j)
    for (int i = 0; i < s.nx; ++i)
      for (LocalIndex n : {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}) b.connectivity.push_back(n);
  m.blocks.push_back(std::move(b));
  std::vector<LocalIndex> left, right, bottom, top;
  for (int j = 0; j < py; ++j) left.push_back(id(0, j)), right.push_back(id(s.nx, j));
  for (int i = 0; i < px; ++i) bottom.push_back(id(i, 0)), top.push_back(id(i, s.ny));
  addNodeSet(m, "left", left);
  addNodeSet(m, "right", right);
  addNodeSet(m, "bottom", bottom);
  addNodeSet(m, "top", top);
  if (s.element.order == 2)
    elevate(m, s.element.serendipity);
  else
    buildSurfaces(m);
  return m;
}

Mesh box(const BoxSpec& s) {
  checkCounts("box", {s.nx, s.ny, s.nz});
  Mesh m;
  m.dim = 3;
  m.numBodies = s.body + 1;
  const int px = s.nx + 1, py = s.ny + 1, pz = s.nz + 1;
  m.coords.resize(std::size_t(px) * py * pz * 3);
  auto id = [px, py](int i, int j, int k) { return LocalIndex((k * py + j) * px + i); };
  for (int k = 0; k < pz; ++k)
    for (int j = 0; j < py; ++j)
      for (int i = 0; i < px; ++i) {
        const std::size_t n = id(i, j, k);
        m.coords[3 * n + 0] = s.x0 + s.lx * i / s.nx;
        m.coords[3 * n + 1] = s.y0 + s.ly * j / s.ny;
        m.coords[3 * n + 2] = s.z0 + s.lz * k / s.nz;
      }
  ElementBlock b;
  b.name = s.name;
  b.body = s.body;
  b.type = s.tetrahedra ? CellType::Tet4 : CellType::Hex8;
  // Kuhn split along the 0-6 diagonal: conforming between neighbours, all positive.
  static const int kTets[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6},
                                  {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
  for (int k = 0; k < s.nz; ++k)
    for (int j = 0; j < s.ny; ++j)
      for (int i = 0; i < s.nx; ++i) {
        const LocalIndex h[8] = {id(i, j, k),         id(i + 1, j, k),         id(i + 1, j + 1, k),
                                 id(i, j + 1, k),     id(i, j, k + 1),         id(i + 1, j, k + 1),
                                 id(i + 1, j + 1, k + 1), id(i, j + 1, k + 1)};
        if (s.tetrahedra) {
          for (const auto& t : kTets)
            for (int a = 0; a < 4; ++a) b.connectivity.push_back(h[t[a]]);
        } else {
          b.connectivity.insert(b.connectivity.end(), h, h + 8);
        }
      }
  m.blocks.push_back(std::move(b));
  std::vector<LocalIndex> sets[6];
  for (int k = 0; k < pz; ++k)
    for (int j = 0; j < py; ++j)
      for (int i = 0; i < px; ++i) {
        const LocalIndex n = id(i, j, k);
        if (i == 0) sets[0].push_back(n);
        if (i == s.nx) sets[1].push_back(n);
        if (j == 0) sets[2].push_back(n);
        if (j == s.ny) sets[3].push_back(n);
        if (k == 0) sets[4].push_back(n);
        if (k == s.nz) sets[5].push_back(n);
      }
  const char* names[6] = {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
  for (int f = 0; f < 6; ++f) addNodeSet(m, names[f], sets[f]);
  if (s.element.order == 2)
    elevate(m, s.element.serendipity);
  else
    buildSurfaces(m);
  return m;
}

void append(Mesh& mesh, const Mesh& other, const std::string& prefix) {
  if (mesh.dim != other.dim) throw InputError("cannot append a mesh of another dimension");
  if (!mesh.nodeIds.empty() || !other.nodeIds.empty())  // node ids: a part, or a test's relabelling
    throw std::logic_error("mesh::append: meshes with their own node ids are distributed parts, not built");
  const LocalIndex offset = mesh.numNodes();
  const int bodyOffset = mesh.numBodies;
  mesh.coords.insert(mesh.coords.end(), other.coords.begin(), other.coords.end());
  for (ElementBlock b : other.blocks) {
    for (auto& n : b.connectivity) n += offset;
    b.body += bodyOffset;
    mesh.blocks.push_back(std::move(b));
  }
  for (const auto& [name, nodes] : other.nodeSets) {
    std::vector<LocalIndex> shifted(nodes);
    for (auto& n : shifted) n += offset;
    mesh.nodeSets[prefix + name] = std::move(shifted);
  }
  mesh.numBodies += other.numBodies;
  buildSurfaces(mesh);
}

void buildSurfaces(Mesh& mesh) {
  // Every facet of every cell, keyed by its sorted nodes, sorted: a boundary facet is a key that
  // occurs once. Facets keep the order of their first occurrence (deterministic output).
  constexpr int kMaxFacetNodes = 9;
  struct FacetUse {
    std::array<LocalIndex, kMaxFacetNodes> key;  // sorted nodes, padded with -1
    LocalIndex cell;                             // mesh-wide
    std::uint8_t local;                          // the facet's index among its cell's
    std::uint8_t block;
  };
  mesh.surfaces.assign(mesh.numBodies, Surface{});
  if (mesh.blocks.size() > 255) throw std::logic_error("buildSurfaces: more than 255 element blocks");
  for (int body = 0; body < mesh.numBodies; ++body) {
    Surface& s = mesh.surfaces[body];
    s.body = body;
    s.nodesPerFacet = 0;
    std::vector<FacetUse> uses;
    for (std::size_t bi = 0; bi < mesh.blocks.size(); ++bi) {
      const auto& b = mesh.blocks[bi];
      if (b.body != body) continue;
      const int npc = nodesPerCell(b.type);
      const LocalIndex firstCell = mesh.firstCellOfBlock(bi);
      const auto& local = localFacets(b.type);
      uses.reserve(uses.size() + std::size_t(b.numCells()) * local.size());
      for (LocalIndex c = 0; c < b.numCells(); ++c) {
        const LocalIndex* cell = &b.connectivity[std::size_t(c) * npc];
        for (std::size_t f = 0; f < local.size(); ++f) {
          FacetUse u;
          u.key.fill(-1);
          for (std::size_t a = 0; a < local[f].size(); ++a) u.key[a] = cell[local[f][a]];
          std::sort(u.key.begin(), u.key.begin() + local[f].size());
          u.cell = firstCell + c, u.local = std::uint8_t(f), u.block = std::uint8_t(bi);
          uses.push_back(u);
        }
      }
    }
    const auto before = [](const FacetUse& a, const FacetUse& b) {
      return a.cell != b.cell ? a.cell < b.cell : a.local < b.local;
    };
    std::sort(uses.begin(), uses.end(), [&](const FacetUse& a, const FacetUse& b) {
      return a.key != b.key ? a.key < b.key : before(a, b);
    });
    std::vector<FacetUse> once;
    for (std::size_t i = 0; i < uses.size();) {
      std::size_t j = i + 1;
      while (j < uses.size() && uses[j].key == uses[i].key) ++j;
      if (j == i + 1) once.push_back(uses[i]);
      i = j;
    }
    std::vector<FacetUse>().swap(uses);
    std::sort(once.begin(), once.end(), before);
    for (const FacetUse& u : once) {
      const auto& b = mesh.blocks[u.block];
      const auto& lf = localFacets(b.type)[u.local];
      const LocalIndex* cell = &b.connectivity[std::size_t(u.cell - mesh.firstCellOfBlock(u.block)) * nodesPerCell(b.type)];
      if (s.nodesPerFacet == 0) s.nodesPerFacet = int(lf.size());
      if (int(lf.size()) != s.nodesPerFacet)
        throw InputError("body " + std::to_string(body) + " mixes boundary facets of different kinds");
      for (int a : lf) s.facets.push_back(cell[a]);
      s.facetCells.push_back(u.cell);
    }
    if (s.nodesPerFacet == 0) s.nodesPerFacet = mesh.dim == 2 ? 2 : 3;
  }
}

void elevate(Mesh& mesh, bool serendipity, const EdgeNodePlacement& place, const FaceNodePlacement& placeFace) {
  if (!mesh.nodeIds.empty()) throw std::logic_error("mesh::elevate: a mesh with its own node ids is a distributed part");
  const int dim = mesh.dim;
  const LocalIndex firstNew = mesh.numNodes();
  std::map<std::vector<LocalIndex>, LocalIndex> made;  // sorted corners -> their node
  std::vector<std::vector<LocalIndex>> cornersOf;      // of each new node, sorted
  for (auto& b : mesh.blocks) {
    const CellTypeInfo& linear = cellTypeInfo(b.type);
    const CellTypeInfo& quadratic = quadraticRow(linear, serendipity);
    const int nc = linear.numNodes, nq = quadratic.numNodes;
    std::vector<std::vector<int>> local(static_cast<std::size_t>(nq));
    for (int a = nc; a < nq; ++a) local[std::size_t(a)] = cornersOfNode(quadratic, a);
    std::vector<LocalIndex> connectivity;
    connectivity.reserve(std::size_t(b.numCells()) * nq);
    for (LocalIndex c = 0; c < b.numCells(); ++c) {
      const LocalIndex* corners = &b.connectivity[std::size_t(c) * nc];
      connectivity.insert(connectivity.end(), corners, corners + nc);
      for (int a = nc; a < nq; ++a) {
        std::vector<LocalIndex> key;
        for (int k : local[std::size_t(a)]) key.push_back(corners[k]);
        std::sort(key.begin(), key.end());
        auto [it, fresh] = made.try_emplace(key, LocalIndex(firstNew + LocalIndex(cornersOf.size())));
        if (fresh) cornersOf.push_back(key);
        connectivity.push_back(it->second);
      }
    }
    b.type = quadratic.type;
    b.connectivity = std::move(connectivity);
  }
  // edge nodes: at the midpoint, or where `place` puts them; the others at their corners' mean
  mesh.coords.resize(mesh.coords.size() + cornersOf.size() * std::size_t(dim), 0.0);
  for (std::size_t k = 0; k < cornersOf.size(); ++k) {
    Real* x = &mesh.coords[(std::size_t(firstNew) + k) * dim];
    for (LocalIndex corner : cornersOf[k])
      for (int i = 0; i < dim; ++i) x[i] += mesh.coord(corner, i) / Real(cornersOf[k].size());
    if (cornersOf[k].size() == 2 && place) place(cornersOf[k][0], cornersOf[k][1], x);
  }
  // face and cell nodes: the Coons blend adds 2^(1 - d) times the sum of the moves of the edge
  // nodes of their d-dimensional face or cell (1/2 for a quadrilateral, 1/4 for a hexahedron)
  // visit(cell's nodes, corner count, node count, a) for every added node a of every cell
  const auto forEachAddedNode = [&mesh](auto&& visit) {
    for (const auto& b : mesh.blocks) {
      const CellTypeInfo& row = cellTypeInfo(b.type);
      const int nc = cornerCount(row), nq = row.numNodes;
      for (LocalIndex c = 0; c < b.numCells(); ++c)
        for (int a = nc; a < nq; ++a) visit(&b.connectivity[std::size_t(c) * nq], nc, nq, a);
    }
  };
  std::vector<char> blended(cornersOf.size(), 0);
  forEachAddedNode([&](const LocalIndex* nodes, int nc, int nq, int a) {
    const std::size_t k = std::size_t(nodes[a] - firstNew);
    if (cornersOf[k].size() == 2 || blended[k]) return;
    blended[k] = 1;
    const Real weight = cornersOf[k].size() == 4 ? 0.5 : 0.25;
    for (int e = nc; e < nq; ++e) {
      const auto& edge = cornersOf[std::size_t(nodes[e] - firstNew)];
      if (edge.size() != 2 || !std::includes(cornersOf[k].begin(), cornersOf[k].end(), edge.begin(), edge.end()))
        continue;
      for (int i = 0; i < dim; ++i)
        mesh.coords[std::size_t(nodes[a]) * dim + i] +=
            weight * (mesh.coord(nodes[e], i) - 0.5 * (mesh.coord(edge[0], i) + mesh.coord(edge[1], i)));
    }
  });
  if (placeFace && dim == 3) {
    std::vector<std::array<Real, 3>> moved(cornersOf.size(), std::array<Real, 3>{});
    for (std::size_t k = 0; k < cornersOf.size(); ++k) {
      if (cornersOf[k].size() != 4) continue;
      Real* x = &mesh.coords[(std::size_t(firstNew) + k) * 3];
      const std::array<Real, 3> before = {x[0], x[1], x[2]};
      placeFace(cornersOf[k], x);
      for (int i = 0; i < 3; ++i) moved[k][std::size_t(i)] = x[i] - before[std::size_t(i)];
    }
    forEachAddedNode([&](const LocalIndex* nodes, int nc, int nq, int a) {
      if (cornersOf[std::size_t(nodes[a] - firstNew)].size() != 8) return;
      for (int f = nc; f < nq; ++f) {
        const auto& move = moved[std::size_t(nodes[f] - firstNew)];
        if (cornersOf[std::size_t(nodes[f] - firstNew)].size() == 4)
          for (int i = 0; i < 3; ++i) mesh.coords[std::size_t(nodes[a]) * 3 + i] += 0.5 * move[std::size_t(i)];
      }
    });
  }
  for (auto& [name, nodes] : mesh.nodeSets) {
    const std::size_t count = nodes.size();
    for (std::size_t k = 0; k < cornersOf.size(); ++k)
      if (std::all_of(cornersOf[k].begin(), cornersOf[k].end(),
                      [&](LocalIndex n) { return std::binary_search(nodes.begin(), nodes.begin() + count, n); }))
        nodes.push_back(LocalIndex(firstNew + LocalIndex(k)));
    std::sort(nodes.begin(), nodes.end());
  }
  buildSurfaces(mesh);
}

void removeFacetsOn(Mesh& mesh, int body, const std::vector<LocalIndex>& nodes) {
  Surface& s = mesh.surfaces.at(body);
  Surface kept;
  kept.body = s.body;
  kept.nodesPerFacet = s.nodesPerFacet;
  for (LocalIndex f = 0; f < s.numFacets(); ++f) {
    const LocalIndex* n = &s.facets[std::size_t(f) * s.nodesPerFacet];
    bool all = true;
    for (int a = 0; a < s.nodesPerFacet; ++a) all = all && std::binary_search(nodes.begin(), nodes.end(), n[a]);
    if (all) continue;
    kept.facets.insert(kept.facets.end(), n, n + s.nodesPerFacet);
    kept.facetCells.push_back(s.facetCells[f]);
  }
  s = std::move(kept);
}

void perturbInteriorNodes(Mesh& mesh, Real fraction, unsigned seed) {
  std::set<LocalIndex> boundary;
  for (const auto& s : mesh.surfaces) boundary.insert(s.facets.begin(), s.facets.end());
  // smallest edge length over all cells
  Real hmin = std::numeric_limits<Real>::max();
  for (const auto& b : mesh.blocks) {
    const int npc = nodesPerCell(b.type);
    for (LocalIndex c = 0; c < b.numCells(); ++c)
      for (int a = 0; a < npc; ++a)
        for (int e = a + 1; e < npc; ++e) {
          Real d2 = 0.0;
          for (int i = 0; i < mesh.dim; ++i) {
            const Real d = mesh.coord(b.connectivity[c * npc + a], i) - mesh.coord(b.connectivity[c * npc + e], i);
            d2 += d * d;
          }
          hmin = std::min(hmin, std::sqrt(d2));
        }
  }
  std::mt19937 gen(seed);
  std::uniform_real_distribution<Real> dist(-1.0, 1.0);
  for (LocalIndex n = 0; n < mesh.numNodes(); ++n) {
    if (boundary.count(n)) continue;
    for (int i = 0; i < mesh.dim; ++i) mesh.coords[std::size_t(n) * mesh.dim + i] += fraction * hmin * dist(gen);
  }
}

}  // namespace cgcm::mesh
