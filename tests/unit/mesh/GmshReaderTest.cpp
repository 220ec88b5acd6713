// gmsh input: the .geo files in meshes/ (counts, names, positive cells,
// outward surfaces, the contact restriction), a .msh written by gmsh read back
// to the same mesh, number overrides, and the errors of the convention.
#include <gmsh.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "Isoparametric.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/fem/Dispatch.hpp"
#include "cgcm/mesh/Benchmark.hpp"
#include "cgcm/mesh/Generators.hpp"
#include "cgcm/mesh/Geometry.hpp"
#include "cgcm/mesh/GmshReader.hpp"

namespace cgcm::mesh {
namespace {

namespace fs = std::filesystem;

const std::string kMeshes = CGCM_MESH_DIR;

class Gmsh : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("cgcm-gmsh-test-" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) const {
    const std::string path = (dir_ / name).string();
    std::ofstream(path) << text;
    return path;
  }
  fs::path dir_;
};

GmshOptions dim(int d) {
  GmshOptions o;
  o.dim = d;
  return o;
}

std::string errorOf(const std::string& path, const GmshOptions& options) {
  try {
    readGmsh(path, options);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no InputError";
}

#define EXPECT_CONTAINS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << (text)

double det3(const double a[3], const double b[3], const double c[3]) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

struct Point3 {
  double x[3] = {0, 0, 0};
};

Point3 at(const Mesh& m, LocalIndex n) {
  Point3 p;
  for (int i = 0; i < m.dim; ++i) p.x[i] = m.coord(n, i);
  return p;
}

double tetVolume(const Mesh& m, LocalIndex a, LocalIndex b, LocalIndex c, LocalIndex d) {
  double u[3], v[3], w[3];
  const Point3 pa = at(m, a), pb = at(m, b), pc = at(m, c), pd = at(m, d);
  for (int i = 0; i < 3; ++i) u[i] = pb.x[i] - pa.x[i], v[i] = pc.x[i] - pa.x[i], w[i] = pd.x[i] - pa.x[i];
  return det3(u, v, w) / 6.0;
}

// Smallest corner Jacobian of a cell (positive for a valid, positively ordered cell).
double minCornerJacobian(const Mesh& m, CellType type, const LocalIndex* c) {
  double smallest = 1e300;
  if (type == CellType::Quad4) {
    for (int k = 0; k < 4; ++k) {
      const Point3 p = at(m, c[k]), n = at(m, c[(k + 1) % 4]), q = at(m, c[(k + 3) % 4]);
      smallest = std::min(smallest, (n.x[0] - p.x[0]) * (q.x[1] - p.x[1]) - (n.x[1] - p.x[1]) * (q.x[0] - p.x[0]));
    }
  } else if (type == CellType::Tet4) {
    smallest = tetVolume(m, c[0], c[1], c[2], c[3]);
  } else {
    static const int corner[8][4] = {{0, 1, 3, 4}, {1, 2, 0, 5}, {2, 3, 1, 6}, {3, 0, 2, 7},
                                     {4, 7, 5, 0}, {5, 4, 6, 1}, {6, 5, 7, 2}, {7, 6, 4, 3}};
    for (const auto& k : corner) smallest = std::min(smallest, 6.0 * tetVolume(m, c[k[0]], c[k[1]], c[k[2]], c[k[3]]));
  }
  return smallest;
}

// Measure (area or volume) of a cell; hexahedra split into six tetrahedra.
double measure(const Mesh& m, CellType type, const LocalIndex* c) {
  if (type == CellType::Quad4) {
    double a = 0.0;
    for (int k = 0; k < 4; ++k)
      a += 0.5 * (m.coord(c[k], 0) * m.coord(c[(k + 1) % 4], 1) - m.coord(c[(k + 1) % 4], 0) * m.coord(c[k], 1));
    return a;
  }
  if (type == CellType::Tet4) return tetVolume(m, c[0], c[1], c[2], c[3]);
  static const int kTets[6][4] = {{0, 1, 2, 6}, {0, 2, 3, 6}, {0, 3, 7, 6}, {0, 7, 4, 6}, {0, 4, 5, 6}, {0, 5, 1, 6}};
  double v = 0.0;
  for (const auto& t : kTets) v += tetVolume(m, c[t[0]], c[t[1]], c[t[2]], c[t[3]]);
  return v;
}

// Outward normal times area of a facet (2D: of a segment; 3D: sum over a fan of triangles).
Point3 areaVector(const Mesh& m, const LocalIndex* f, int n) {
  Point3 a;
  if (m.dim == 2) {
    a.x[0] = m.coord(f[1], 1) - m.coord(f[0], 1);
    a.x[1] = -(m.coord(f[1], 0) - m.coord(f[0], 0));
    return a;
  }
  for (int t = 1; t + 1 < n; ++t) {
    const Point3 p = at(m, f[0]), q = at(m, f[t]), r = at(m, f[t + 1]);
    double u[3], v[3];
    for (int i = 0; i < 3; ++i) u[i] = q.x[i] - p.x[i], v[i] = r.x[i] - p.x[i];
    a.x[0] += 0.5 * (u[1] * v[2] - u[2] * v[1]);
    a.x[1] += 0.5 * (u[2] * v[0] - u[0] * v[2]);
    a.x[2] += 0.5 * (u[0] * v[1] - u[1] * v[0]);
  }
  return a;
}

Point3 centroid(const Mesh& m, const LocalIndex* n, int count) {
  Point3 c;
  for (int a = 0; a < count; ++a)
    for (int i = 0; i < m.dim; ++i) c.x[i] += m.coord(n[a], i) / count;
  return c;
}

// Checks every cell is positive, every surface facet points away from its cell,
// and the divergence theorem on each body's full boundary: sum x.n dA = dim * volume.
// Returns the volume of each body.
std::vector<double> checkGeometry(const Mesh& m) {
  std::vector<double> volume(m.numBodies, 0.0);
  std::vector<std::pair<const LocalIndex*, int>> cells;  // mesh-wide: nodes, count
  for (const auto& b : m.blocks) {
    const int npc = nodesPerCell(b.type);
    for (LocalIndex c = 0; c < b.numCells(); ++c) {
      const LocalIndex* nodes = &b.connectivity[std::size_t(c) * npc];
      EXPECT_GT(minCornerJacobian(m, b.type, nodes), 0.0) << b.name << " cell " << c;
      volume[b.body] += measure(m, b.type, nodes);
      cells.push_back({nodes, npc});
    }
  }
  for (const Surface& s : m.surfaces)
    for (LocalIndex f = 0; f < s.numFacets(); ++f) {
      const LocalIndex* nodes = &s.facets[std::size_t(f) * s.nodesPerFacet];
      const Point3 n = areaVector(m, nodes, s.nodesPerFacet), fc = centroid(m, nodes, s.nodesPerFacet);
      const auto [cellNodes, count] = cells.at(s.facetCells[f]);
      const Point3 cc = centroid(m, cellNodes, count);
      double outward = 0.0;
      for (int i = 0; i < 3; ++i) outward += (fc.x[i] - cc.x[i]) * n.x[i];
      EXPECT_GT(outward, 0.0) << "facet " << f << " of body " << s.body;
      for (int a = 0; a < s.nodesPerFacet; ++a)
        EXPECT_NE(std::find(cellNodes, cellNodes + count, nodes[a]), cellNodes + count) << "facet not on its cell";
    }
  Mesh closed = m;
  buildSurfaces(closed);
  for (const Surface& s : closed.surfaces) {
    double flux = 0.0;
    for (LocalIndex f = 0; f < s.numFacets(); ++f) {
      const LocalIndex* nodes = &s.facets[std::size_t(f) * s.nodesPerFacet];
      const Point3 n = areaVector(m, nodes, s.nodesPerFacet), c = centroid(m, nodes, s.nodesPerFacet);
      for (int i = 0; i < 3; ++i) flux += c.x[i] * n.x[i];
    }
    EXPECT_NEAR(flux, m.dim * volume[s.body], 1e-10 * std::max(1.0, volume[s.body])) << "body " << s.body;
  }
  return volume;
}

std::vector<std::string> nodeSetNames(const Mesh& m) {
  std::vector<std::string> names;
  for (const auto& [name, nodes] : m.nodeSets) names.push_back(name);
  return names;
}

// Every node of a surface satisfies `on`.
template <class F>
void expectSurfaceOn(const Mesh& m, int body, F on, const char* what) {
  const Surface& s = m.surfaces.at(body);
  EXPECT_GT(s.numFacets(), 0);
  for (LocalIndex n : s.facets) EXPECT_TRUE(on(at(m, n))) << what << ": node " << n;
}

TEST_F(Gmsh, QuarterDiscOnBlock) {
  const Mesh m = readGmsh(kMeshes + "/quarter-disc-on-block.geo", dim(2));
  EXPECT_EQ(m.dim, 2);
  ASSERT_EQ(m.numBodies, 2);
  ASSERT_EQ(m.blocks.size(), 2u);
  EXPECT_EQ(m.blocks[0].name, "sphere");
  EXPECT_EQ(m.blocks[1].name, "substrate");
  EXPECT_EQ(m.blocks[1].body, 1);
  // n = m = 6, nb = 12: disc 6*6 + 2*6*6 cells, block 12*12
  EXPECT_EQ(m.blocks[0].numCells(), 108);
  EXPECT_EQ(m.blocks[1].numCells(), 144);
  // disc: three 7 x 7 patches sharing two edges and their corner; block 13 x 13
  EXPECT_EQ(m.numNodes(), (49 + 42 + 36) + 169);
  EXPECT_EQ(nodeSetNames(m), (std::vector<std::string>{"apex", "axis", "contact:sphere", "contact:substrate", "driven",
                                                       "fixed", "lower apex"}));
  const auto volume = checkGeometry(m);
  EXPECT_NEAR(volume[0], cgcm::kPi / 4, 0.01);  // inscribed polygon
  EXPECT_NEAR(volume[1], 9.0, 1e-12);
  // contact surfaces: the arc and the block's top, 12 segments each
  EXPECT_EQ(m.surfaces[0].numFacets(), 12);
  EXPECT_EQ(m.surfaces[1].numFacets(), 12);
  expectSurfaceOn(
      m, 0, [](Point3 p) { return std::abs(std::hypot(p.x[0], p.x[1] - 1.05) - 1.0) < 1e-12; }, "arc");
  expectSurfaceOn(
      m, 1, [](Point3 p) { return p.x[1] == 0.0; }, "top");
  const LocalIndex apex = m.nodeSet("apex").at(0);
  EXPECT_EQ(m.coord(apex, 0), 0.0);
  EXPECT_NEAR(m.coord(apex, 1), 0.05, 1e-15);
  for (LocalIndex n : m.nodeSet("axis")) EXPECT_EQ(m.coord(n, 0), 0.0);
  for (LocalIndex n : m.nodeSet("fixed")) EXPECT_EQ(m.coord(n, 1), -3.0);
  for (LocalIndex n : m.nodeSet("driven")) EXPECT_NEAR(m.coord(n, 1), 1.05, 1e-15);
  EXPECT_EQ(m.nodeSet("axis").size(), 26u);
}

// Node coordinates sorted by column, then height (columns on a 1e-9 grid).
std::vector<std::pair<double, double>> sortedNodes(const Mesh& m) {
  std::vector<std::pair<double, double>> p;
  for (LocalIndex n = 0; n < m.numNodes(); ++n) p.push_back({std::round(m.coord(n, 0) * 1e9), m.coord(n, 1)});
  std::sort(p.begin(), p.end());
  return p;
}

void expectSameNodes(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.numNodes(), b.numNodes());
  ASSERT_EQ(a.numCells(), b.numCells());
  const auto pa = sortedNodes(a), pb = sortedNodes(b);
  double worst = 0.0;
  for (std::size_t k = 0; k < pa.size(); ++k)
    worst = std::max({worst, std::abs(pa[k].first - pb[k].first) * 1e-9, std::abs(pa[k].second - pb[k].second)});
  EXPECT_LT(worst, 1e-12);
}

// The benchmark .geo files make the built-in generator's meshes node for node.
TEST_F(Gmsh, BenchmarkGeoFilesMatchTheBuiltInGenerator) {
  const double rS0 = 0.02 / std::pow(15.0, 1.0 / 6.0);
  for (int level : {0, 1}) {
    GmshOptions o = dim(2);
    o.numbers["level"] = level;
    QuarterDiskSpec sphere;
    sphere.centerY = 1.0 + rS0;
    sphere.refinement = level;
    Mesh builtIn = quarterDisk(sphere);
    HalfSpaceSpec h;
    h.refinement = level;
    append(builtIn, halfSpaceBlock(h), "lower ");
    const Mesh onHalfSpace = readGmsh(kMeshes + "/sphere-on-half-space.geo", o);
    expectSameNodes(onHalfSpace, builtIn);
    EXPECT_EQ(onHalfSpace.nodeSet("driven").size(), builtIn.nodeSet("equator").size());
    EXPECT_EQ(onHalfSpace.nodeSet("fixed").size(), builtIn.nodeSet("lower bottom").size());
    EXPECT_EQ(onHalfSpace.surfaces[0].numFacets(), 32 << level);  // the arc
    EXPECT_EQ(onHalfSpace.surfaces[1].numFacets(), 30 << level);  // the top

    QuarterDiskSpec second;
    second.centerY = -1.0;
    second.lowerHalf = false;
    second.refinement = level;
    Mesh twoSpheres = quarterDisk(sphere);
    append(twoSpheres, quarterDisk(second), "lower ");
    expectSameNodes(readGmsh(kMeshes + "/sphere-on-sphere.geo", o), twoSpheres);
  }
}

TEST_F(Gmsh, HexBlock) {
  const Mesh m = readGmsh(kMeshes + "/hex-block.geo", dim(3));
  EXPECT_EQ(m.dim, 3);
  ASSERT_EQ(m.blocks.size(), 1u);
  EXPECT_EQ(m.blocks[0].name, "block");
  EXPECT_EQ(m.blocks[0].type, CellType::Hex8);
  EXPECT_EQ(m.numCells(), 4 * 4 * 2);
  EXPECT_EQ(m.numNodes(), 5 * 5 * 3);
  EXPECT_EQ(nodeSetNames(m), (std::vector<std::string>{"contact:block", "fixed", "symmetry x", "symmetry y"}));
  EXPECT_NEAR(checkGeometry(m)[0], 0.5, 1e-12);
  EXPECT_EQ(m.surfaces[0].nodesPerFacet, 4);
  EXPECT_EQ(m.surfaces[0].numFacets(), 16);  // the top only
  expectSurfaceOn(
      m, 0, [](Point3 p) { return std::abs(p.x[2] - 0.5) < 1e-12; }, "top");
  for (LocalIndex n : m.nodeSet("symmetry x")) EXPECT_EQ(m.coord(n, 0), 0.0);
  for (LocalIndex n : m.nodeSet("symmetry y")) EXPECT_EQ(m.coord(n, 1), 0.0);
  EXPECT_EQ(m.nodeSet("fixed").size(), 25u);
}

TEST_F(Gmsh, TetSphereOnBlock) {
  const Mesh m = readGmsh(kMeshes + "/sphere-on-block-3d.geo", dim(3));
  ASSERT_EQ(m.numBodies, 2);
  EXPECT_EQ(m.blocks[0].name, "sphere");
  EXPECT_EQ(m.blocks[1].name, "substrate");
  for (const auto& b : m.blocks) EXPECT_EQ(b.type, CellType::Tet4);
  EXPECT_GT(m.numNodes(), 150);
  EXPECT_LT(m.numNodes(), 600);
  EXPECT_EQ(nodeSetNames(m), (std::vector<std::string>{"contact:sphere", "contact:substrate", "driven", "fixed",
                                                       "symmetry x", "symmetry y"}));
  const auto volume = checkGeometry(m);
  EXPECT_NEAR(volume[0], cgcm::kPi / 6, 0.05 * cgcm::kPi / 6);  // a quarter of a hemisphere
  EXPECT_NEAR(volume[1], 1.5 * 1.5 * 1.0, 1e-12);
  for (const Surface& s : m.surfaces) EXPECT_EQ(s.nodesPerFacet, 3);
  const double zc = 1.05;
  expectSurfaceOn(
      m, 0, [&](Point3 p) { return std::abs(std::hypot(p.x[0], p.x[1], p.x[2] - zc) - 1.0) < 1e-9; }, "sphere");
  expectSurfaceOn(
      m, 1, [](Point3 p) { return std::abs(p.x[2]) < 1e-12; }, "top");
  for (LocalIndex n : m.nodeSet("symmetry x")) EXPECT_NEAR(m.coord(n, 0), 0.0, 1e-12);
  for (LocalIndex n : m.nodeSet("driven")) EXPECT_NEAR(m.coord(n, 2), zc, 1e-12);
  for (LocalIndex n : m.nodeSet("fixed")) EXPECT_NEAR(m.coord(n, 2), -1.0, 1e-12);
}

// The built-in 3D benchmark (a hexahedral quarter model) and the gmsh deck's tetrahedral one
// (inputs/3d/sphere-on-half-space.xml) make the same model: bodies, node sets, conditions, the
// responses P (4 x the quarter's) and P_lower, the start, u = 0 where the apexes are r_S0 apart.
TEST_F(Gmsh, TheBuiltInQuarterModelHasTheConventionsOfTheGmshOne) {
  const Real rS0 = 0.0127;
  auto model = [&](Teuchos::ParameterList g) {
    g.validateParametersAndSetDefaults(*validParameters());
    return buildModel(g, Formulation::ThreeD, [rS0] { return rS0; });
  };
  Teuchos::ParameterList gmsh;
  gmsh.set("Type", std::string("gmsh"));
  gmsh.set("File", kMeshes + "/sphere-on-half-space-3d.geo");
  const Model a = model(Teuchos::ParameterList()), b = model(gmsh);
  EXPECT_EQ(bodyNames(*a.mesh), bodyNames(*b.mesh));
  EXPECT_EQ(nodeSetNames(*a.mesh), nodeSetNames(*b.mesh));
  auto conditions = [](const std::vector<DisplacementCondition>& list) {
    std::vector<std::string> out;
    for (const auto& c : list)
      out.push_back(c.nodeSet + " " + std::to_string(c.component) + " " + std::to_string(c.scale));
    return out;
  };
  EXPECT_EQ(conditions(a.conditions), conditions(b.conditions));
  EXPECT_EQ(conditions(a.initialMotion), conditions(b.initialMotion));
  for (const auto& [x, y] : {std::pair{a.force, b.force}, std::pair{*a.balance, *b.balance}}) {
    EXPECT_EQ(x.nodeSet, y.nodeSet);
    EXPECT_EQ(x.component, y.component);
    EXPECT_EQ(x.sign, y.sign);
    EXPECT_EQ(x.scale, 4.0);
    EXPECT_EQ(x.scale, y.scale);
    EXPECT_EQ(x.direction, y.direction);
  }
  ASSERT_FALSE(b.report.empty());
  EXPECT_EQ(b.report.front().rfind("meshed by gmsh in ", 0), 0u) << b.report.front();
  EXPECT_EQ(a.report, std::vector<std::string>(b.report.begin() + 1, b.report.end()));  // the rest as built in
  EXPECT_EQ(a.areaFactors, b.areaFactors);
  EXPECT_TRUE(a.interacting && b.interacting);
  ASSERT_TRUE(a.contact && b.contact);
  EXPECT_EQ(a.contact->upperApex, b.contact->upperApex);
  EXPECT_EQ(a.contact->lowerApex, b.contact->lowerApex);
  EXPECT_EQ(a.contact->upperBody, b.contact->upperBody);
  EXPECT_EQ(a.contact->lowerBody, b.contact->lowerBody);
  // u = 0: the built-in sphere is drawn r_S0 above the half-space, the gmsh one is moved there by the drive's offset
  auto gapAtZero = [](const Model& m) {
    const Real offset = m.conditions.front().offset;
    return m.mesh->coord(m.mesh->nodeSet("apex").front(), 2) + offset -
           m.mesh->coord(m.mesh->nodeSet("lower apex").front(), 2);
  };
  EXPECT_NEAR(gapAtZero(a), rS0, 1e-15);
  EXPECT_NEAR(gapAtZero(b), rS0, 1e-15);
  EXPECT_EQ(a.conditions.front().offset, 0.0);
}

// Element order 2: gmsh's quadratic cells, their nodes on the curved geometry (Mesh.SecondOrderLinear = 0).
TEST_F(Gmsh, ElementOrderTwoPutsTheNodesOnTheCurvedGeometry) {
  for (bool serendipity : {false, true}) {
    GmshOptions o = dim(2);
    o.element = {2, serendipity};
    const Mesh m = readGmsh(kMeshes + "/quarter-disc-on-block.geo", o);
    for (const auto& b : m.blocks) EXPECT_EQ(b.type, serendipity ? CellType::Quad8 : CellType::Quad9) << b.name;
    EXPECT_EQ(m.blocks[0].numCells(), 108);
    EXPECT_EQ(m.blocks[1].numCells(), 144);
    const auto measure = testing::isoparametricMeasure(m);
    EXPECT_GT(measure.smallestJacobian, 0.0);
    // the inscribed polygon of order 1 is within 0.01 of pi/4; the curved cells' arc within 1e-5
    EXPECT_NEAR(measure.perBody[0], cgcm::kPi / 4, 1e-5);
    EXPECT_NEAR(measure.perBody[1], 9.0, 1e-12);
    for (const Surface& surface : m.surfaces) {
      EXPECT_EQ(surface.nodesPerFacet, 3);
      EXPECT_EQ(surface.numFacets(), 12);
    }
    expectSurfaceOn(
        m, 0, [](Point3 p) { return std::abs(std::hypot(p.x[0], p.x[1] - 1.05) - 1.0) < 1e-12; }, "arc");
    expectSurfaceOn(
        m, 1, [](Point3 p) { return p.x[1] == 0.0; }, "top");
    // the physical groups hold the mid-edge nodes of their lines: 2 x 13 corners and 2 x 12 edges on the axis
    EXPECT_EQ(m.nodeSet("axis").size(), 50u);
    for (LocalIndex n : m.nodeSet("axis")) EXPECT_EQ(m.coord(n, 0), 0.0);
    for (LocalIndex n : m.nodeSet("driven")) EXPECT_NEAR(m.coord(n, 1), 1.05, 1e-15);
  }
  GmshOptions o = dim(3);
  o.element.order = 2;
  const Mesh m = readGmsh(kMeshes + "/sphere-on-block-3d.geo", o);
  for (const auto& b : m.blocks) EXPECT_EQ(b.type, CellType::Tet10) << b.name;
  const auto measure = testing::isoparametricMeasure(m);
  EXPECT_GT(measure.smallestJacobian, 0.0);
  std::printf("[ tet10 ] quarter hemisphere volume %.6f, pi/6 = %.6f\n", measure.perBody[0], cgcm::kPi / 6);
  EXPECT_NEAR(measure.perBody[0], cgcm::kPi / 6, 1e-3 * cgcm::kPi / 6);  // linear: within 5 %
  EXPECT_NEAR(measure.perBody[1], 1.5 * 1.5 * 1.0, 1e-12);
  for (const Surface& surface : m.surfaces) EXPECT_EQ(surface.nodesPerFacet, 6);
  expectSurfaceOn(
      m, 0, [](Point3 p) { return std::abs(std::hypot(p.x[0], p.x[1], p.x[2] - 1.05) - 1.0) < 1e-9; }, "sphere");
  for (LocalIndex n : m.nodeSet("symmetry x")) EXPECT_NEAR(m.coord(n, 0), 0.0, 1e-12);
}

// Meshes `geo` with gmsh directly and writes it as .msh (gmsh's own format 4.1).
void writeMsh(const std::string& geo, int d, const std::string& msh) {
  gmsh::initialize(0, nullptr, false);
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::onelab::clear();  // DefineConstant[]s with a Name would take ONELAB values of earlier files
  gmsh::open(geo);
  gmsh::model::mesh::generate(d);
  gmsh::write(msh);
  gmsh::finalize();
}

TEST_F(Gmsh, MshWrittenByGmshReadsToTheSameMesh) {
  for (const auto& [name, d] : {std::pair<std::string, int>{"quarter-disc-on-block", 2}, {"sphere-on-block-3d", 3}}) {
    SCOPED_TRACE(name);
    const Mesh fromGeo = readGmsh(kMeshes + "/" + name + ".geo", dim(d));
    const std::string msh = (dir_ / (name + ".msh")).string();
    writeMsh(kMeshes + "/" + name + ".geo", d, msh);
    const Mesh fromMsh = readGmsh(msh, dim(d));
    ASSERT_EQ(fromMsh.numNodes(), fromGeo.numNodes());
    for (std::size_t k = 0; k < fromGeo.coords.size(); ++k)
      ASSERT_NEAR(fromMsh.coords[k], fromGeo.coords[k], 1e-15) << k;
    ASSERT_EQ(fromMsh.blocks.size(), fromGeo.blocks.size());
    for (std::size_t b = 0; b < fromGeo.blocks.size(); ++b) {
      EXPECT_EQ(fromMsh.blocks[b].name, fromGeo.blocks[b].name);
      EXPECT_EQ(fromMsh.blocks[b].connectivity, fromGeo.blocks[b].connectivity);
    }
    EXPECT_EQ(fromMsh.nodeSets, fromGeo.nodeSets);
    for (int b = 0; b < fromGeo.numBodies; ++b) {
      EXPECT_EQ(fromMsh.surfaces[b].facets, fromGeo.surfaces[b].facets);
      EXPECT_EQ(fromMsh.surfaces[b].facetCells, fromGeo.surfaces[b].facetCells);
    }
  }
}

TEST_F(Gmsh, NumberOverridesChangeTheMeshAndDoNotLeak) {
  const std::string geo = kMeshes + "/quarter-disc-on-block.geo";
  const LocalIndex coarse = readGmsh(geo, dim(2)).numNodes();
  GmshOptions finer = dim(2);
  finer.numbers = {{"n", 12}, {"nb", 24}};
  const Mesh fine = readGmsh(geo, finer);
  EXPECT_EQ(fine.surfaces[0].numFacets(), 24);
  EXPECT_EQ(fine.surfaces[1].numFacets(), 24);
  EXPECT_GT(fine.numNodes(), coarse);
  checkGeometry(fine);
  EXPECT_EQ(readGmsh(geo, dim(2)).numNodes(), coarse);  // the override is gone in the next read

  GmshOptions size = dim(3);
  size.numbers = {{"lc", 0.25}, {"lcContact", 0.08}};
  const std::string sphere = kMeshes + "/sphere-on-block-3d.geo";
  EXPECT_GT(readGmsh(sphere, size).numNodes(), readGmsh(sphere, dim(3)).numNodes());

  GmshOptions typo = dim(2);
  typo.numbers = {{"nn", 12}};
  const std::string e = errorOf(geo, typo);
  EXPECT_CONTAINS(e, "\"nn\"");
  EXPECT_CONTAINS(e, "quarter-disc-on-block.geo");
  const std::string msh = (dir_ / "disc.msh").string();
  writeMsh(geo, 2, msh);
  GmshOptions onMsh = dim(2);
  onMsh.numbers = {{"n", 12}};
  EXPECT_CONTAINS(errorOf(msh, onMsh), ".geo files only");
}

const char* kSquare = R"(
Point(1) = {0, 0, 0, 0.3}; Point(2) = {1, 0, 0, 0.3}; Point(3) = {1, 1, 0, 0.3}; Point(4) = {0, 1, 0, 0.3};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
)";

void expectSameMesh(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.numNodes(), b.numNodes());
  EXPECT_EQ(a.coords, b.coords);  // binary .msh: bit for bit
  ASSERT_EQ(a.blocks.size(), b.blocks.size());
  for (std::size_t k = 0; k < a.blocks.size(); ++k) {
    EXPECT_EQ(a.blocks[k].name, b.blocks[k].name);
    EXPECT_EQ(a.blocks[k].type, b.blocks[k].type);
    EXPECT_EQ(a.blocks[k].connectivity, b.blocks[k].connectivity);
  }
  EXPECT_EQ(a.nodeSets, b.nodeSets);
  ASSERT_EQ(a.numBodies, b.numBodies);
  for (int k = 0; k < a.numBodies; ++k) EXPECT_EQ(a.surfaces[k].facets, b.surfaces[k].facets);
}

std::vector<fs::path> filesIn(const fs::path& dir, const std::string& ext) {
  std::vector<fs::path> found;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ext) found.push_back(e.path());
  std::sort(found.begin(), found.end());
  return found;
}

// The cache reads back the mesh gmsh made, bit for bit (quadratic cells on a curved 3D geometry,
// with number overrides); its key follows what the mesh depends on, down to an included file; a
// damaged cached file is meshed again and replaced.
TEST_F(Gmsh, MeshCacheReadsTheSameMeshAndFollowsItsKey) {
  fs::create_directories(dir_ / "geo");
  const fs::path sphere = dir_ / "geo" / "sphere.geo";
  fs::copy_file(kMeshes + "/sphere-on-block-3d.geo", sphere);
  GmshOptions options = dim(3);
  options.numbers = {{"lcContact", 0.1}};
  options.element.order = 2;
  const Mesh direct = readGmsh(sphere.string(), options);
  options.cache = (dir_ / "cache").string();
  fs::create_directories(options.cache);
  GmshProvenance first, second;
  const Mesh meshed = readGmsh(sphere.string(), options, &first);
  EXPECT_CONTAINS(first.line, "meshed by gmsh in");
  EXPECT_CONTAINS(first.line, "kept in");
  ASSERT_EQ(filesIn(options.cache, ".msh").size(), 1u);
  EXPECT_EQ(filesIn(options.cache, ".crc64").size(), 1u);
  const Mesh cached = readGmsh(sphere.string(), options, &second);
  EXPECT_CONTAINS(second.line, "mesh read from");
  {
    SCOPED_TRACE("meshed, not cached");
    expectSameMesh(meshed, direct);
  }
  {
    SCOPED_TRACE("read from the cache");
    expectSameMesh(cached, direct);
  }

  // a damaged file (a byte changed in the middle) fails its checksum: meshed again, replaced
  const fs::path msh = filesIn(options.cache, ".msh").front();
  {
    std::fstream f(msh, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(std::streamoff(fs::file_size(msh) / 2));
    f.put('\x7f');
  }
  GmshProvenance again;
  expectSameMesh(readGmsh(sphere.string(), options, &again), direct);
  EXPECT_CONTAINS(again.line, "failed its checksum: meshed again");
  GmshProvenance replaced;
  readGmsh(sphere.string(), options, &replaced);
  EXPECT_CONTAINS(replaced.line, "mesh read from");
  // a truncated one too
  fs::resize_file(msh, fs::file_size(msh) / 3);
  GmshProvenance truncated;
  expectSameMesh(readGmsh(sphere.string(), options, &truncated), direct);
  EXPECT_CONTAINS(truncated.line, "meshed again");

  // another key: other numbers, other gmsh options, another order, an edited included file
  const std::string square = write("geo/square.geo", std::string(kSquare) + R"(
Include "cells.geo";
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = n; Transfinite Surface{1}; Recombine Surface{1};
Physical Surface("body:plate") = {1};
Physical Curve("driven") = {3};
)");
  write("geo/cells.geo", "n = 4;\n");
  GmshOptions plate = dim(2);
  plate.cache = options.cache;
  EXPECT_EQ(readGmsh(square, plate).numCells(), 9);
  write("geo/cells.geo", "n = 6;\n");
  GmshProvenance edited;
  EXPECT_EQ(readGmsh(square, plate, &edited).numCells(), 25);
  EXPECT_CONTAINS(edited.line, "meshed by gmsh");
  options.element.order = 1;
  GmshProvenance linear;
  const Mesh byDelaunay = readGmsh(sphere.string(), options, &linear);
  EXPECT_CONTAINS(linear.line, "meshed by gmsh");
  options.gmshOptions = {{"Mesh.Algorithm3D", 10}};  // HXT: another mesh of the same geometry
  GmshProvenance hxt;
  const Mesh byHxt = readGmsh(sphere.string(), options, &hxt);
  EXPECT_CONTAINS(hxt.line, "meshed by gmsh");
  EXPECT_NE(byHxt.coords, byDelaunay.coords);
  const auto volume = checkGeometry(byHxt);
  EXPECT_NEAR(volume[0], checkGeometry(byDelaunay)[0], 1e-3 * volume[0]);  // the faceted sphere's volume
  EXPECT_EQ(filesIn(options.cache, ".msh").size(), 5u);
  EXPECT_EQ(filesIn(options.cache, ".crc64").size(), 5u);
  for (const auto& e : fs::directory_iterator(options.cache))  // nothing half-written left
    EXPECT_EQ(e.path().string().find(".part-"), std::string::npos) << e.path();
}

TEST_F(Gmsh, GmshOptionsAreCheckedAndApplyToGeoFilesOnly) {
  const std::string geo = kMeshes + "/quarter-disc-on-block.geo";
  GmshOptions typo = dim(2);
  typo.gmshOptions = {{"Mesh.Algoritm", 6}};
  const std::string e = errorOf(geo, typo);
  EXPECT_CONTAINS(e, "\"Mesh.Algoritm\"");
  EXPECT_CONTAINS(e, "not a number option");
  typo.gmshOptions = {{"Algorithm", 6}};
  EXPECT_CONTAINS(errorOf(geo, typo), "\"Algorithm\"");
  typo.gmshOptions = {{"General.FileName", 1}};  // a string option
  EXPECT_CONTAINS(errorOf(geo, typo), "not a number option");

  const std::string msh = (dir_ / "disc.msh").string();
  writeMsh(geo, 2, msh);
  GmshOptions onMsh = dim(2);
  onMsh.gmshOptions = {{"Mesh.Algorithm", 6}};
  EXPECT_CONTAINS(errorOf(msh, onMsh), "meshing a .geo only");
  onMsh.gmshOptions.clear();
  onMsh.cache = dir_.string();
  EXPECT_CONTAINS(errorOf(msh, onMsh), "meshing a .geo only");
}


TEST_F(Gmsh, UnsupportedElementTypesNameFileGroupAndType) {
  const std::string triangles = write("triangles.geo", std::string(kSquare) + R"(
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Physical Surface("body:plate") = {1};
)");
  const std::string e = errorOf(triangles, dim(2));
  EXPECT_CONTAINS(e, "triangles.geo");
  EXPECT_CONTAINS(e, "\"body:plate\"");
  EXPECT_CONTAINS(e, "\"Triangle 3\"");

  // third order: a .geo is meshed with the options' order over the file's; a .msh holds what it holds
  const std::string cubic = write("cubic.geo", std::string(kSquare) + R"(
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1}; Recombine Surface{1};
Mesh.ElementOrder = 3;
Physical Surface("body:plate") = {1};
)");
  EXPECT_EQ(readGmsh(cubic, dim(2)).blocks.at(0).type, CellType::Quad4);
  const std::string cubicMsh = (dir_ / "cubic.msh").string();
  writeMsh(cubic, 2, cubicMsh);
  const std::string c = errorOf(cubicMsh, dim(2));
  EXPECT_CONTAINS(c, "\"body:plate\"");
  EXPECT_CONTAINS(c, "\"Quadrilateral 16\"");

  const std::string prisms = write("prisms.geo", std::string(kSquare) + R"(
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
out[] = Extrude{0, 0, 0.5}{ Surface{1}; Layers{2}; Recombine; };
Physical Volume("body:slab") = {out[1]};
)");
  const std::string p = errorOf(prisms, dim(3));
  EXPECT_CONTAINS(p, "\"body:slab\"");
  EXPECT_CONTAINS(p, "\"Prism 6\"");
}

TEST_F(Gmsh, ConventionErrorsAreClear) {
  auto square = [&](const std::string& name, const std::string& groups) {
    return write(name, std::string(kSquare) +
                           "Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};\n"
                           "Transfinite Curve{1, 2, 3, 4} = 4; Transfinite Surface{1}; Recombine Surface{1};\n" +
                           groups + "\n");
  };
  EXPECT_CONTAINS(errorOf(square("none.geo", ""), dim(2)), "no physical groups");
  EXPECT_CONTAINS(errorOf(square("plain.geo", "Physical Surface(\"plate\") = {1};"), dim(2)), "\"body:<name>\"");
  EXPECT_CONTAINS(
      errorOf(square("unnamed.geo", "Physical Surface(\"body:a\") = {1}; Physical Curve(7) = {1};"), dim(2)),
      "has no name");
  EXPECT_CONTAINS(
      errorOf(square("contact.geo", "Physical Surface(\"body:a\") = {1}; Physical Curve(\"contact:b\") = {1};"),
              dim(2)),
      "\"contact:b\" names no body; the bodies are \"a\"");
  EXPECT_CONTAINS(errorOf(square("dim.geo", "Physical Surface(\"body:a\") = {1};"), dim(3)),
                  "a 3D mesh was expected but the physical groups are at most 2D");
  EXPECT_CONTAINS(errorOf(square("syntax.geo", "Physical Surface(\"body:a\") = {1}; Foo;"), dim(2)), "gmsh:");
  EXPECT_CONTAINS(errorOf((dir_ / "missing.geo").string(), dim(2)), "does not exist");
  EXPECT_CONTAINS(errorOf(write("mesh.txt", ""), dim(2)), "expected a gmsh .geo or .msh file");
  // gmsh 4.8 drops the last statement of a final line without a newline
  EXPECT_CONTAINS(errorOf(write("no-newline.geo", std::string(kSquare) + "Physical Curve(\"a\") = {1};"), dim(2)),
                  "does not end with a newline");

  // A clockwise surface (normal -z) still gives positive cells.
  const std::string clockwise = write("clockwise.geo", std::string(kSquare) + R"(
Curve Loop(1) = {-4, -3, -2, -1}; Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 5; Transfinite Surface{1}; Recombine Surface{1};
Physical Surface("body:a") = {1};
Physical Curve("fixed") = {1};
)");
  const Mesh m = readGmsh(clockwise, dim(2));
  EXPECT_NEAR(checkGeometry(m)[0], 1.0, 1e-12);
  EXPECT_EQ(m.surfaces[0].numFacets(), 16);  // no contact group: all exterior facets
  EXPECT_CONTAINS(errorOf(square("stray.geo",
                                 "Point(9) = {0.5, 0.5, 0, 0.1};\n"
                                 "Physical Surface(\"body:a\") = {1}; Physical Point(\"p\") = {9};"),
                          dim(2)),
                  "belongs to no body's cell");
}

TEST_F(Gmsh, EveryCellBelongsToABody) {
  const std::string forgotten = write("forgotten.geo", R"(
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 1, 1};
Rectangle(2) = {2, 0, 0, 1, 1};
Transfinite Curve{:} = 3; Transfinite Surface{:}; Recombine Surface{:};
Physical Surface("body:a") = {1};
)");
  EXPECT_CONTAINS(errorOf(forgotten, dim(2)), "surface 2 is meshed but in no \"body:<name>\" group");
}

TEST_F(Gmsh, BodiesMustNotShareNodes) {
  const std::string glued = write("glued.geo", R"(
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 1, 1};
Rectangle(2) = {0, 1, 0, 1, 1};
BooleanFragments{ Surface{1}; Delete; }{ Surface{2}; Delete; }
Transfinite Curve{:} = 3; Transfinite Surface{:}; Recombine Surface{:};
Physical Surface("body:lower") = {1};
Physical Surface("body:upper") = {2};
)");
  const std::string e = errorOf(glued, dim(2));
  EXPECT_CONTAINS(e, "bodies \"body:lower\" and \"body:upper\" share the node");
}


// Each row's gmsh type, name and node order against gmsh's own description of
// the element: node a of ours sits where gmsh puts its node fromGmsh[a] in the
// parent cell (both use [-1, 1]^d for tensor cells and the unit simplex).
TEST(CellTypeTableAgainstGmsh, TypeNameAndNodeOrder) {
  gmsh::initialize(0, nullptr, false);
  for (const CellTypeInfo& row : kCellTypes) {
    SCOPED_TRACE(row.name);
    std::string name;
    int dim = 0, order = 0, numNodes = 0, numPrimary = 0;
    std::vector<double> local;
    gmsh::model::mesh::getElementProperties(row.gmshType, name, dim, order, numNodes, local, numPrimary);
    EXPECT_EQ(name, row.gmshName);
    EXPECT_EQ(dim, row.dim);
    ASSERT_EQ(numNodes, row.numNodes);
    ASSERT_EQ(local.size(), std::size_t(dim) * std::size_t(numNodes));  // dim coordinates per node
    std::string facetName;
    int facetDim = 0;
    std::vector<double> facetLocal;
    gmsh::model::mesh::getElementProperties(row.gmshFacetType, facetName, facetDim, order, numNodes, facetLocal,
                                            numPrimary);
    EXPECT_EQ(facetDim, row.dim - 1);
    ASSERT_EQ(numNodes, row.nodesPerFacet) << facetName;
    // gmsh's facet element orders its nodes as our facets do (core/CellType.hpp): the corners,
    // then mid-edge node k between corners k and k + 1, then the face centre
    const int corners = facetCornerCount(row), fd = std::max(facetDim, 1);
    auto facetAt = [&](int a, int i) { return facetLocal[std::size_t(fd) * std::size_t(a) + i]; };
    for (int a = corners; a < numNodes; ++a)
      for (int i = 0; i < facetDim; ++i) {
        const int k = a - corners;
        Real want = 0.0;
        if (k < corners) want = 0.5 * (facetAt(k, i) + facetAt((k + 1) % corners, i));
        else
          for (int c = 0; c < corners; ++c) want += facetAt(c, i) / corners;
        EXPECT_NEAR(facetAt(a, i), want, 1e-14) << facetName << " node " << a;
      }
    fem::withElement(row.type, [&](auto element) {
      using E = decltype(element);
      for (int a = 0; a < E::numNodes; ++a) {
        Real xi[E::dim];
        E::parentCoordinates(a, xi);
        for (int i = 0; i < E::dim; ++i) EXPECT_EQ(xi[i], local[std::size_t(E::dim) * std::size_t(row.fromGmsh[a]) + i]) << "node " << a;
      }
    });
  }
  gmsh::finalize();
}

}  // namespace
}  // namespace cgcm::mesh
