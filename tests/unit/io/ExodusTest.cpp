// Exodus II writer: the file read back with the plain Exodus API (exactly),
// side sets against the Exodus side numbering, a writer killed with SIGKILL,
// errors, and the comparator (library and exo_compare).
#include <exodusII.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>

#include "cgcm/core/Error.hpp"
#include "cgcm/io/ExodusReader.hpp"
#include "cgcm/io/ExodusWriter.hpp"
#include "cgcm/mesh/Generators.hpp"

namespace cgcm::io {
namespace {

namespace fs = std::filesystem;

class Exodus : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cgcm-exodus-test-" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

// Two bodies: a 3 x 2 rectangle and a 2 x 2 one above it.
mesh::Mesh twoRectangles() {
  mesh::RectangleSpec a, b;
  a.nx = 3, a.ny = 2, a.name = "lower";
  b.nx = 2, b.ny = 2, b.y0 = 1.5, b.name = "upper";
  mesh::Mesh m = mesh::rectangle(a);
  mesh::append(m, mesh::rectangle(b), "upper ");
  return m;
}

// A hex box and a tet box beside it: two blocks of different types.
mesh::Mesh hexAndTets() {
  mesh::BoxSpec h, t;
  h.nx = 2, h.ny = 2, h.nz = 1, h.name = "hexes";
  t.x0 = 2.0, t.tetrahedra = true, t.name = "tets";
  mesh::Mesh m = mesh::box(h);
  mesh::append(m, mesh::box(t), "tets ");
  return m;
}

// The same with quadratic cells: QUAD9 and QUAD8 bodies; HEX27, HEX20 and TETRA10 boxes.
mesh::Mesh quadraticRectangles() {
  mesh::RectangleSpec a, b;
  a.nx = 3, a.ny = 2, a.name = "lower", a.element = {2, false};
  b.nx = 2, b.ny = 2, b.y0 = 1.5, b.name = "upper", b.element = {2, true};
  mesh::Mesh m = mesh::rectangle(a);
  mesh::append(m, mesh::rectangle(b), "upper ");
  return m;
}

mesh::Mesh quadraticBoxes() {
  mesh::BoxSpec h, s, t;
  h.nx = 2, h.ny = 2, h.nz = 1, h.name = "hex27", h.element = {2, false};
  s.x0 = 2.0, s.name = "hex20", s.element = {2, true};
  t.x0 = 4.0, t.tetrahedra = true, t.name = "tet10", t.element = {2, false};
  mesh::Mesh m = mesh::box(h);
  mesh::append(m, mesh::box(s), "hex20 ");
  mesh::append(m, mesh::box(t), "tet10 ");
  return m;
}

ExodusVariables variablesFor(int dim) {
  ExodusVariables v;
  for (int i = 0; i < dim; ++i) v.nodal.push_back(std::string("displacement_") + "xyz"[i]);
  v.element = {"J", "von_mises"};
  v.global = {"u", "P"};
  return v;
}

// Deterministic, step-dependent values for every declared variable.
struct StepValues {
  double time;
  ExodusWriter::Fields nodal, element;
  ExodusWriter::Scalars global;
};

StepValues valuesAt(int step, const mesh::Mesh& m, const ExodusVariables& v) {
  StepValues s;
  s.time = 0.25 * step;
  for (std::size_t k = 0; k < v.nodal.size(); ++k)
    for (LocalIndex n = 0; n < m.numNodes(); ++n) s.nodal[v.nodal[k]].push_back(std::sin(1.0 + n + 7.0 * k + step) / 3);
  for (std::size_t k = 0; k < v.element.size(); ++k)
    for (LocalIndex c = 0; c < m.numCells(); ++c) s.element[v.element[k]].push_back(1.0 / (1.0 + c + k + step));
  for (std::size_t k = 0; k < v.global.size(); ++k) s.global[v.global[k]] = std::exp(-double(k) - step);
  return s;
}

void write(ExodusWriter& w, const StepValues& s) { w.writeStep(s.time, s.nodal, s.element, s.global); }

// Exodus II side numbering (Exodus manual, 1-based local nodes), written out
// independently of mesh::localFacets.
std::vector<std::vector<int>> exodusSides(const std::string& type) {
  if (type == "QUAD4") return {{1, 2}, {2, 3}, {3, 4}, {4, 1}};
  if (type == "HEX8") return {{1, 2, 6, 5}, {2, 3, 7, 6}, {3, 4, 8, 7}, {1, 5, 8, 4}, {1, 4, 3, 2}, {5, 6, 7, 8}};
  if (type == "TETRA4") return {{1, 2, 4}, {2, 3, 4}, {1, 4, 3}, {1, 3, 2}};
  if (type == "QUAD8" || type == "QUAD9") return {{1, 2, 5}, {2, 3, 6}, {3, 4, 7}, {4, 1, 8}};
  if (type == "TETRA10")
    return {{1, 2, 4, 5, 9, 8}, {2, 3, 4, 6, 10, 9}, {1, 4, 3, 8, 10, 7}, {1, 3, 2, 7, 6, 5}};
  if (type == "HEX20" || type == "HEX27") {
    std::vector<std::vector<int>> sides = {{1, 2, 6, 5, 9, 14, 17, 13},  {2, 3, 7, 6, 10, 15, 18, 14},
                                           {3, 4, 8, 7, 11, 16, 19, 15}, {1, 5, 8, 4, 13, 20, 16, 12},
                                           {1, 4, 3, 2, 12, 11, 10, 9},  {5, 6, 7, 8, 17, 18, 19, 20}};
    if (type == "HEX27") {  // the face centres 21-26 (0-based) of sides 5, 6, 4, 2, 1, 3
      const int centre[6] = {26, 25, 27, 24, 22, 23};
      for (int k = 0; k < 6; ++k) sides[k].push_back(centre[k]);
    }
    return sides;
  }
  ADD_FAILURE() << "unexpected element type " << type;
  return {};
}

std::vector<std::string> names(int exoid, ex_entity_type type, int count, bool variables) {
  std::vector<std::array<char, 65>> buf(count);
  std::vector<char*> ptrs;
  for (auto& b : buf) ptrs.push_back(b.data());
  const int status =
      variables ? ex_get_variable_names(exoid, type, count, ptrs.data()) : ex_get_names(exoid, type, ptrs.data());
  EXPECT_GE(status, 0);
  return std::vector<std::string>(ptrs.begin(), ptrs.end());
}

// Reads the whole file back through the Exodus C API and compares it with the
// mesh and the values written, exactly.
void checkFile(const std::string& path, const mesh::Mesh& m, const ExodusVariables& v,
               const std::vector<StepValues>& steps) {
  int cpu = sizeof(double), io = 0;
  float version = 0;
  const int exoid = ex_open(path.c_str(), EX_READ, &cpu, &io, &version);
  ASSERT_GE(exoid, 0) << path;
  ex_set_max_name_length(exoid, 64);
  char title[MAX_LINE_LENGTH + 1];
  int dim, nodes, elems, blocks, nodeSets, sideSets;
  ASSERT_GE(ex_get_init(exoid, title, &dim, &nodes, &elems, &blocks, &nodeSets, &sideSets), 0);
  EXPECT_STREQ(title, "round trip");
  EXPECT_EQ(dim, m.dim);
  EXPECT_EQ(nodes, m.numNodes());
  EXPECT_EQ(elems, m.numCells());
  ASSERT_EQ(blocks, int(m.blocks.size()));
  EXPECT_EQ(nodeSets, int(m.nodeSets.size()));
  EXPECT_EQ(sideSets, m.numBodies);

  std::vector<double> xyz[3];
  for (auto& c : xyz) c.resize(nodes);
  ASSERT_GE(ex_get_coord(exoid, xyz[0].data(), xyz[1].data(), dim == 3 ? xyz[2].data() : nullptr), 0);
  for (int i = 0; i < dim; ++i)
    for (LocalIndex n = 0; n < m.numNodes(); ++n) ASSERT_EQ(xyz[i][n], m.coord(n, i));

  // blocks: names, types, connectivity (1-based)
  const auto blockNames = names(exoid, EX_ELEM_BLOCK, blocks, false);
  std::vector<std::vector<int>> conn(blocks);
  std::vector<std::string> types(blocks);
  for (int b = 0; b < blocks; ++b) {
    char type[MAX_STR_LENGTH + 1];
    int n, perElem, edges, faces, attrs;
    ASSERT_GE(ex_get_block(exoid, EX_ELEM_BLOCK, b + 1, type, &n, &perElem, &edges, &faces, &attrs), 0);
    EXPECT_EQ(blockNames[b], m.blocks[b].name);
    EXPECT_STREQ(type, mesh::cellTypeName(m.blocks[b].type));
    types[b] = type;
    ASSERT_EQ(n, m.blocks[b].numCells());
    conn[b].resize(std::size_t(n) * perElem);
    ASSERT_GE(ex_get_conn(exoid, EX_ELEM_BLOCK, b + 1, conn[b].data(), nullptr, nullptr), 0);
    for (std::size_t k = 0; k < conn[b].size(); ++k) ASSERT_EQ(conn[b][k], m.blocks[b].connectivity[k] + 1);
  }

  // node sets by name
  const auto setNames = names(exoid, EX_NODE_SET, nodeSets, false);
  for (int s = 0; s < nodeSets; ++s) {
    int n, df;
    ASSERT_GE(ex_get_set_param(exoid, EX_NODE_SET, s + 1, &n, &df), 0);
    std::vector<int> ids(n);
    ASSERT_GE(ex_get_set(exoid, EX_NODE_SET, s + 1, ids.data(), nullptr), 0);
    ASSERT_TRUE(m.nodeSets.count(setNames[s])) << setNames[s];
    const auto& expected = m.nodeSets.at(setNames[s]);
    ASSERT_EQ(ids.size(), expected.size());
    for (std::size_t k = 0; k < ids.size(); ++k) EXPECT_EQ(ids[k], expected[k] + 1);
  }

  // side sets: the Exodus side of each (element, side) pair has the nodes of
  // the surface facet, and the facet's outward normal points away from the cell.
  const auto sideNames = names(exoid, EX_SIDE_SET, sideSets, false);
  for (int s = 0; s < sideSets; ++s) {
    const mesh::Surface& surface = m.surfaces[s];
    EXPECT_EQ(sideNames[s], "contact:" + m.blocks[s].name);
    int n, df;
    ASSERT_GE(ex_get_set_param(exoid, EX_SIDE_SET, s + 1, &n, &df), 0);
    ASSERT_EQ(n, surface.numFacets());
    std::vector<int> elem(n), side(n);
    ASSERT_GE(ex_get_set(exoid, EX_SIDE_SET, s + 1, elem.data(), side.data()), 0);
    // sorted by element, then side; each pair is the side of one facet of its cell, each facet's once
    std::vector<std::pair<int, int>> pairs;
    for (int k = 0; k < n; ++k) pairs.emplace_back(elem[k], side[k]);
    EXPECT_TRUE(std::is_sorted(pairs.begin(), pairs.end())) << "side set " << s;
    std::vector<char> matched(std::size_t(n), 0);
    for (int f = 0; f < n; ++f) {  // f: the pair
      int b = 0, local = elem[f] - 1;
      while (local >= int(conn[b].size() / mesh::nodesPerCell(m.blocks[b].type)))
        local -= int(conn[b].size() / mesh::nodesPerCell(m.blocks[b].type)), ++b;
      const int npc = mesh::nodesPerCell(m.blocks[b].type);
      const int* cell = &conn[b][std::size_t(local) * npc];
      const auto sides = exodusSides(types[b]);
      const auto& sn = sides.at(side[f] - 1);
      std::set<int> sideNodes;
      for (int a : sn) sideNodes.insert(cell[a - 1] - 1);
      int facet = -1;
      for (int g = 0; g < n && facet < 0; ++g) {
        if (matched[std::size_t(g)] || surface.facetCells[g] + 1 != elem[f]) continue;
        std::set<int> facetNodes;
        for (int a = 0; a < surface.nodesPerFacet; ++a) facetNodes.insert(surface.facets[g * surface.nodesPerFacet + a]);
        if (facetNodes == sideNodes) facet = g;
      }
      ASSERT_GE(facet, 0) << "side " << side[f] << " of element " << elem[f] << " is no facet of the surface";
      matched[std::size_t(facet)] = 1;
      // outward: (facet centroid - cell centroid) . Exodus side normal > 0
      double fc[3] = {0, 0, 0}, cc[3] = {0, 0, 0}, normal[3] = {0, 0, 0};
      auto x = [&](int localNode, int i) { return i < dim ? m.coord(cell[localNode - 1] - 1, i) : 0.0; };
      for (int i = 0; i < 3; ++i) {
        for (int a : sn) fc[i] += x(a, i) / sn.size();
        for (int a = 1; a <= npc; ++a) cc[i] += x(a, i) / npc;
      }
      if (dim == 2) {
        normal[0] = x(sn[1], 1) - x(sn[0], 1), normal[1] = -(x(sn[1], 0) - x(sn[0], 0));
      } else {
        double u[3], w[3];
        for (int i = 0; i < 3; ++i) u[i] = x(sn[1], i) - x(sn[0], i), w[i] = x(sn[2], i) - x(sn[0], i);
        normal[0] = u[1] * w[2] - u[2] * w[1], normal[1] = u[2] * w[0] - u[0] * w[2],
        normal[2] = u[0] * w[1] - u[1] * w[0];
      }
      EXPECT_GT((fc[0] - cc[0]) * normal[0] + (fc[1] - cc[1]) * normal[1] + (fc[2] - cc[2]) * normal[2], 0.0);
    }
  }

  // variables
  EXPECT_EQ(names(exoid, EX_NODAL, int(v.nodal.size()), true), v.nodal);
  EXPECT_EQ(names(exoid, EX_ELEM_BLOCK, int(v.element.size()), true), v.element);
  EXPECT_EQ(names(exoid, EX_GLOBAL, int(v.global.size()), true), v.global);
  ASSERT_EQ(ex_inquire_int(exoid, EX_INQ_TIME), int(steps.size()));
  for (std::size_t s = 0; s < steps.size(); ++s) {
    const int step = int(s) + 1;
    double t;
    ASSERT_GE(ex_get_time(exoid, step, &t), 0);
    EXPECT_EQ(t, steps[s].time);
    for (std::size_t k = 0; k < v.nodal.size(); ++k) {
      std::vector<double> values(nodes);
      ASSERT_GE(ex_get_var(exoid, step, EX_NODAL, int(k) + 1, 1, nodes, values.data()), 0);
      EXPECT_EQ(values, steps[s].nodal.at(v.nodal[k])) << v.nodal[k] << " step " << step;
    }
    for (std::size_t k = 0; k < v.element.size(); ++k) {
      std::vector<double> all;
      for (int b = 0; b < blocks; ++b) {
        std::vector<double> values(m.blocks[b].numCells());
        ASSERT_GE(ex_get_var(exoid, step, EX_ELEM_BLOCK, int(k) + 1, b + 1, int(values.size()), values.data()), 0);
        all.insert(all.end(), values.begin(), values.end());
      }
      EXPECT_EQ(all, steps[s].element.at(v.element[k])) << v.element[k] << " step " << step;
    }
    std::vector<double> g(v.global.size());
    ASSERT_GE(ex_get_var(exoid, step, EX_GLOBAL, 1, 1, int(g.size()), g.data()), 0);
    for (std::size_t k = 0; k < g.size(); ++k) EXPECT_EQ(g[k], steps[s].global.at(v.global[k]));
  }
  ex_close(exoid);
}

TEST_F(Exodus, RoundTripOf2DAnd3DMeshes) {
  int k = 0;
  for (const mesh::Mesh& m : {twoRectangles(), hexAndTets(), quadraticRectangles(), quadraticBoxes()}) {
    const ExodusVariables v = variablesFor(m.dim);
    const std::string path = file("round-trip-" + std::to_string(k++) + ".e");
    std::vector<StepValues> steps = {valuesAt(1, m, v), valuesAt(2, m, v)};
    {
      ExodusWriter w(path, "round trip", m, v);
      for (const auto& s : steps) write(w, s);
      EXPECT_EQ(w.numSteps(), 2);
    }  // closed by the destructor
    SCOPED_TRACE(path);
    checkFile(path, m, v, steps);
  }
}

// The streamed writer puts the arrays in pieces, in any order: pieces of 3 nodes and 2 cells from the
// end backwards, the sets in pieces of 2, each step's fields in pieces of 4 and 3. The file is the one
// the whole-mesh writer makes, entry by entry.
TEST_F(Exodus, StreamedInPiecesIsTheFileWrittenWhole) {
  int k = 0;
  for (const mesh::Mesh& m : {twoRectangles(), hexAndTets(), quadraticRectangles(), quadraticBoxes()}) {
    const ExodusVariables v = variablesFor(m.dim);
    const std::string whole = file("whole-" + std::to_string(k) + ".e"), streamed = file("streamed-" + std::to_string(k++) + ".e");
    SCOPED_TRACE(streamed);
    const std::vector<StepValues> steps = {valuesAt(1, m, v), valuesAt(2, m, v)};
    {
      ExodusWriter w(whole, "round trip", m, v);
      for (const auto& s : steps) write(w, s);
    }
    // pieces [first, first + count) of n entries, `size` at a time, from the end backwards
    auto backwards = [](std::int64_t n, std::int64_t size, const std::function<void(std::int64_t, std::int64_t)>& put) {
      for (std::int64_t end = n; end > 0; end -= size) put(std::max<std::int64_t>(0, end - size), std::min(size, end));
    };
    {
      ExodusWriter w(streamed, "round trip", layoutOf(m), v);
      backwards(m.numNodes(), 3, [&](std::int64_t first, std::int64_t count) {
        std::vector<double> c[3];
        for (int i = 0; i < m.dim; ++i)
          for (std::int64_t n = first; n < first + count; ++n) c[i].push_back(m.coord(LocalIndex(n), i));
        w.putCoordinates(first, count, c[0].data(), c[1].data(), m.dim == 3 ? c[2].data() : nullptr);
      });
      for (std::size_t b = 0; b < m.blocks.size(); ++b) {
        const int npc = mesh::nodesPerCell(m.blocks[b].type);
        const std::vector<GlobalIndex> nodes(m.blocks[b].connectivity.begin(), m.blocks[b].connectivity.end());
        backwards(m.blocks[b].numCells(), 2, [&](std::int64_t first, std::int64_t count) {
          w.putConnectivity(b, first, count, nodes.data() + first * npc);
        });
      }
      std::size_t set = 0;
      for (const auto& [name, members] : m.nodeSets) {
        const std::vector<GlobalIndex> ids(members.begin(), members.end());
        for (std::size_t first = 0; first < ids.size(); first += 2)
          w.putNodeSet(set, std::int64_t(first), std::int64_t(std::min<std::size_t>(2, ids.size() - first)), ids.data() + first);
        ++set;
      }
      set = 0;
      for (const auto& surface : m.surfaces) {
        std::vector<std::pair<GlobalIndex, int>> pairs;
        for (LocalIndex f = 0; f < surface.numFacets(); ++f) {
          LocalIndex cell = surface.facetCells[f];
          std::size_t b = 0;
          while (cell >= m.blocks[b].numCells()) cell -= m.blocks[b++].numCells();
          pairs.emplace_back(surface.facetCells[f], exodusSide(m.blocks[b], cell, &surface.facets[std::size_t(f) * surface.nodesPerFacet],
                                                               surface.nodesPerFacet));
        }
        std::sort(pairs.begin(), pairs.end());
        std::vector<GlobalIndex> elements;
        std::vector<int> sides;
        for (const auto& [e, side] : pairs) elements.push_back(e), sides.push_back(side);
        for (std::size_t first = 0; first < pairs.size(); first += 2)
          w.putSideSet(set, std::int64_t(first), std::int64_t(std::min<std::size_t>(2, pairs.size() - first)),
                       elements.data() + first, sides.data() + first);
        ++set;
      }
      w.finishMesh();
      for (const auto& s : steps) {
        w.beginStep(s.time);
        for (std::size_t k = 0; k < v.nodal.size(); ++k)
          backwards(m.numNodes(), 4, [&](std::int64_t first, std::int64_t count) {
            w.putNodal(k, first, count, s.nodal.at(v.nodal[k]).data() + first);
          });
        for (std::size_t k = 0; k < v.element.size(); ++k) {
          std::int64_t blockStart = 0;
          for (std::size_t b = 0; b < m.blocks.size(); blockStart += m.blocks[b++].numCells())
            backwards(m.blocks[b].numCells(), 3, [&](std::int64_t first, std::int64_t count) {
              w.putElement(k, b, first, count, s.element.at(v.element[k]).data() + blockStart + first);
            });
        }
        w.endStep(s.global);
      }
      EXPECT_EQ(w.numSteps(), 2);
    }
    checkFile(streamed, m, v, steps);
    const auto differences = compareExodus(whole, streamed, {0.0, 0.0, {}});
    EXPECT_TRUE(differences.empty()) << differences.front();
  }
}

// A streamed file refuses a piece outside its array, a mesh or a step with entries never put, a node id
// beyond the mesh, a field put outside a step, and more nodes than 32-bit ids number.
TEST_F(Exodus, StreamedFileRefusesPiecesOutsideAndHoles) {
  const mesh::Mesh m = twoRectangles();
  const ExodusVariables v = variablesFor(2);
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  ExodusWriter w(file("holes.e"), "t", layoutOf(m), v);
  const std::vector<double> x(std::size_t(m.numNodes()), 0.0);
  const LocalIndex n = m.numNodes();
  EXPECT_NE(message([&] { w.putCoordinates(n - 1, 2, x.data(), x.data(), nullptr); })
                .find("coordinate entries " + std::to_string(n - 1) + " .. " + std::to_string(n) + " outside 0 .. " +
                      std::to_string(n - 1)),
            std::string::npos);
  w.putCoordinates(0, n - 1, x.data(), x.data(), nullptr);  // the last node missing
  const std::vector<GlobalIndex> beyond(4, n);
  EXPECT_NE(message([&] { w.putConnectivity(0, 0, 1, beyond.data()); }).find("has node " + std::to_string(n)),
            std::string::npos);
  const std::string hole = message([&] { w.finishMesh(); });
  EXPECT_NE(hole.find("mesh entries put of"), std::string::npos) << hole;
  EXPECT_NE(hole.find("holes.e"), std::string::npos) << hole;
  EXPECT_THROW(w.putNodal(0, 0, 1, x.data()), std::logic_error);  // outside a step
  w.beginStep(1.0);
  EXPECT_THROW(w.beginStep(2.0), std::logic_error);
  w.putNodal(0, 0, n, x.data());
  const std::string missing = message([&] { w.endStep({{"u", 0.0}, {"P", 0.0}}); });
  EXPECT_NE(missing.find("step 1 has " + std::to_string(n) + " field values of"), std::string::npos) << missing;

  ExodusLayout huge = layoutOf(m);
  huge.numNodes = std::int64_t(1) << 31;
  EXPECT_NE(message([&] { ExodusWriter(file("huge.e"), "t", huge, v); }).find("32-bit ids"), std::string::npos);
}

TEST_F(Exodus, ContactSurfaceWithoutSymmetryFacetsIsASideSubset) {
  // As the app builds them: only the interacting facets remain in the surface.
  mesh::Mesh m = twoRectangles();
  mesh::removeFacetsOn(m, 0, m.nodeSet("left"));
  mesh::removeFacetsOn(m, 1, m.nodeSet("upper left"));
  const ExodusVariables v = variablesFor(2);
  const std::string path = file("subset.e");
  std::vector<StepValues> steps = {valuesAt(1, m, v)};
  {
    ExodusWriter w(path, "round trip", m, v);
    write(w, steps[0]);
    w.close();
    w.close();  // idempotent
  }
  checkFile(path, m, v, steps);
}

TEST_F(Exodus, AKilledWriterLeavesEveryStepWrittenSoFar) {
  const mesh::Mesh m = hexAndTets();
  const ExodusVariables v = variablesFor(3);
  const std::string path = file("killed.e");
  std::vector<StepValues> steps = {valuesAt(1, m, v), valuesAt(2, m, v), valuesAt(3, m, v)};
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    try {
      ExodusWriter w(path, "round trip", m, v);
      for (const auto& s : steps) write(w, s);
      raise(SIGKILL);  // no close, no destructor, no exit handlers
    } catch (...) {
    }
    _exit(3);
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the child exited with " << WEXITSTATUS(status);
  EXPECT_EQ(WTERMSIG(status), SIGKILL);
  checkFile(path, m, v, steps);
  const ExodusReader r(path);
  EXPECT_EQ(r.numSteps(), 3);
  EXPECT_EQ(r.globals(3), (std::vector<double>{steps[2].global.at("u"), steps[2].global.at("P")}));
}

TEST_F(Exodus, ErrorsNameTheFileAndTheVariable) {
  const mesh::Mesh m = twoRectangles();
  const ExodusVariables v = variablesFor(2);
  auto message = [](auto&& f) {
    try {
      f();
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  // cannot create: a missing folder, a folder in the way
  EXPECT_THROW(ExodusWriter(file("missing/out.e"), "t", m, v), InputError);
  EXPECT_NE(message([&] { ExodusWriter(file("missing/out.e"), "t", m, v); }).find("missing/out.e"), std::string::npos);
  fs::create_directories(file("folder.e"));
  EXPECT_THROW(ExodusWriter(file("folder.e"), "t", m, v), InputError);

  ExodusVariables twice = v;
  twice.global.push_back("u");
  EXPECT_NE(message([&] { ExodusWriter(file("twice.e"), "t", m, twice); }).find("\"u\" declared twice"),
            std::string::npos);

  const std::string path = file("errors.e");
  ExodusWriter w(path, "t", m, v);
  StepValues good = valuesAt(1, m, v);
  StepValues wrongSize = good, unknown = good, missing = good, unknownGlobal = good;
  wrongSize.nodal["displacement_y"].pop_back();
  unknown.element["stress_rr"] = good.element["J"];
  missing.nodal.erase("displacement_x");
  unknownGlobal.global["gap"] = 0.0;
  const std::string size = message([&] { write(w, wrongSize); });
  EXPECT_NE(size.find(path), std::string::npos) << size;
  EXPECT_NE(size.find("\"displacement_y\" has " + std::to_string(m.numNodes() - 1) + " values"), std::string::npos)
      << size;
  EXPECT_NE(message([&] { write(w, unknown); }).find("element variable \"stress_rr\" was not declared"),
            std::string::npos);
  EXPECT_NE(message([&] { write(w, missing); }).find("\"displacement_x\" missing"), std::string::npos);
  EXPECT_NE(message([&] { write(w, unknownGlobal); }).find("global variable \"gap\""), std::string::npos);
  EXPECT_EQ(w.numSteps(), 0);  // nothing written by the failed calls
  write(w, good);
  w.close();
  EXPECT_NE(message([&] { write(w, good); }).find("after close"), std::string::npos);
  const ExodusReader r(path);
  EXPECT_EQ(r.numSteps(), 1);
  EXPECT_THROW(ExodusReader(file("nothing.e")), InputError);
  EXPECT_NE(message([&] { r.nodal("displacement_z", 1); }).find("no nodal variable \"displacement_z\""),
            std::string::npos);
}

TEST_F(Exodus, CompareFindsDifferencesByNameWithinTolerances) {
  const mesh::Mesh m = twoRectangles();
  const ExodusVariables v = variablesFor(2);
  auto writeFile = [&](const std::string& name, double scaleP, int numSteps, const ExodusVariables& vars) {
    ExodusWriter w(file(name), "t", m, vars);
    for (int s = 1; s <= numSteps; ++s) {
      StepValues values = valuesAt(s, m, vars);
      values.global["P"] *= scaleP;
      write(w, values);
    }
  };
  writeFile("a.e", 1.0, 3, v);
  writeFile("same.e", 1.0, 3, v);
  writeFile("p.e", 1.0 + 5e-8, 3, v);
  writeFile("short.e", 1.0, 2, v);
  ExodusVariables fewer = v;
  fewer.element.pop_back();
  writeFile("fewer.e", 1.0, 3, fewer);

  EXPECT_TRUE(compareExodus(file("a.e"), file("same.e"), {}).empty());
  EXPECT_TRUE(compareExodus(file("a.e"), file("p.e"), {0.0, 1e-6}).empty());
  const auto diff = compareExodus(file("a.e"), file("p.e"), {0.0, 1e-9});
  ASSERT_EQ(diff.size(), 3u);  // P at each step
  EXPECT_NE(diff[0].find("global \"P\" at step 1"), std::string::npos) << diff[0];
  const auto shorter = compareExodus(file("a.e"), file("short.e"), {});
  ASSERT_EQ(shorter.size(), 1u);
  EXPECT_NE(shorter[0].find("number of steps: 3 vs 2"), std::string::npos);
  const auto missing = compareExodus(file("a.e"), file("fewer.e"), {});
  ASSERT_EQ(missing.size(), 1u);
  EXPECT_NE(missing[0].find("element variable \"von_mises\" only in"), std::string::npos);
}

// The comparison reads the meshes too: a moved node (beyond the tolerance), a cell's nodes rotated, a
// node set with another node.
TEST_F(Exodus, CompareFindsMeshDifferences) {
  const mesh::Mesh m = twoRectangles();
  const ExodusVariables v = variablesFor(2);
  mesh::Mesh moved = m, swapped = m, otherSet = m;
  moved.coords[3] += 1e-6;
  // the first cell of "upper" with its nodes rotated: the same cell, other sides (its side set pairs change too)
  std::rotate(swapped.blocks[1].connectivity.begin(), swapped.blocks[1].connectivity.begin() + 1,
              swapped.blocks[1].connectivity.begin() + 4);
  otherSet.nodeSets.begin()->second.back() = otherSet.nodeSets.begin()->second.back() == 0 ? 1 : 0;
  std::sort(otherSet.nodeSets.begin()->second.begin(), otherSet.nodeSets.begin()->second.end());
  auto writeFile = [&](const std::string& name, const mesh::Mesh& mesh) {
    ExodusWriter w(file(name), "t", mesh, v);
    write(w, valuesAt(1, m, v));
  };
  writeFile("a.e", m);
  writeFile("moved.e", moved);
  writeFile("swapped.e", swapped);
  writeFile("set.e", otherSet);
  auto differences = [&](const char* name) { return compareExodus(file("a.e"), file(name), {}); };
  const auto moving = differences("moved.e"), rotated = differences("swapped.e"), set = differences("set.e");
  ASSERT_EQ(moving.size(), 1u);
  EXPECT_NE(moving[0].find("coordinate y"), std::string::npos) << moving[0];  // entry 3: node 1, y
  ASSERT_EQ(rotated.size(), 2u);
  EXPECT_EQ(rotated[0], "connectivity of block \"upper\" differs");
  EXPECT_EQ(rotated[1], "side set \"contact:upper\" differs");
  ASSERT_EQ(set.size(), 1u);
  EXPECT_EQ(set[0], "node set \"" + m.nodeSets.begin()->first + "\" differs");
  EXPECT_TRUE(compareExodus(file("a.e"), file("moved.e"), {1e-5, 0.0, {}}).empty());  // within the tolerance
}

TEST_F(Exodus, ExoCompareToolExitCodesAndDump) {
  const mesh::Mesh m = twoRectangles();
  const ExodusVariables v = variablesFor(2);
  for (const char* name : {"a.e", "b.e"}) {
    ExodusWriter w(file(name), "t", m, v);
    for (int s = 1; s <= 2; ++s) {
      StepValues values = valuesAt(s, m, v);
      if (std::string(name) == "b.e") values.nodal["displacement_x"][3] += 1e-6;
      write(w, values);
    }
  }
  const std::string tool = CGCM_EXO_COMPARE;
  auto run = [&](const std::string& args) {
    const int status = std::system((tool + " " + args + " > " + file("out.txt") + " 2>&1").c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  };
  EXPECT_EQ(run(file("a.e") + " " + file("a.e")), 0);
  EXPECT_EQ(run(file("a.e") + " " + file("b.e")), 1);
  EXPECT_EQ(run("--abs 1e-5 " + file("a.e") + " " + file("b.e")), 0);
  EXPECT_EQ(run(file("a.e") + " " + file("nothing.e")), 2);
  EXPECT_EQ(run("--abs"), 2);
  ASSERT_EQ(run("--dump " + file("a.e")), 0);
  std::ifstream in(file("out.txt"));
  const std::string out((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(out.find("nodal variables: displacement_x displacement_y"), std::string::npos) << out;
  EXPECT_NE(out.find("global variables: u P"), std::string::npos) << out;
  EXPECT_NE(out.find("steps: 2"), std::string::npos) << out;
  EXPECT_NE(out.find("\"lower\" (QUAD4, 6)"), std::string::npos) << out;
  EXPECT_NE(out.find("\"contact:upper\""), std::string::npos) << out;
}

}  // namespace
}  // namespace cgcm::io
