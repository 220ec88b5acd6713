// Mesh generators: positive cells, closed outward-oriented surfaces (checked
// with the divergence theorem), node sets where they belong.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>

#include "Isoparametric.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/mesh/Benchmark.hpp"
#include "cgcm/mesh/Generators.hpp"
#include "cgcm/mesh/Mirror.hpp"
#include "cgcm/mesh/Overlap.hpp"
#include "cgcm/mesh/Subdomain.hpp"

namespace cgcm::mesh {
namespace {

// Signed measure (area in 2D, volume in 3D) of all cells, and the smallest cell measure.
std::pair<double, double> cellMeasures(const Mesh& m) {
  double total = 0.0, smallest = 1e300;
  for (const auto& b : m.blocks) {
    const int n = nodesPerCell(b.type);
    for (LocalIndex c = 0; c < b.numCells(); ++c) {
      const LocalIndex* q = &b.connectivity[std::size_t(c) * n];
      double v = 0.0;
      if (b.type == CellType::Quad4) {
        for (int k = 0; k < 4; ++k)
          v += 0.5 * (m.coord(q[k], 0) * m.coord(q[(k + 1) % 4], 1) - m.coord(q[(k + 1) % 4], 0) * m.coord(q[k], 1));
      } else if (b.type == CellType::Tet4) {
        double d[3][3];
        for (int a = 0; a < 3; ++a)
          for (int i = 0; i < 3; ++i) d[a][i] = m.coord(q[a + 1], i) - m.coord(q[0], i);
        v = (d[0][0] * (d[1][1] * d[2][2] - d[1][2] * d[2][1]) - d[0][1] * (d[1][0] * d[2][2] - d[1][2] * d[2][0]) +
             d[0][2] * (d[1][0] * d[2][1] - d[1][1] * d[2][0])) / 6.0;
      } else {  // hex8 of an axis-aligned box
        v = 1.0;
        for (int i = 0; i < 3; ++i) v *= m.coord(q[6], i) - m.coord(q[0], i);
      }
      total += v;
      smallest = std::min(smallest, v);
    }
  }
  return {total, smallest};
}

// Divergence theorem on the straight facets of a body, over the fan of each facet's corners (the
// first `corners` nodes): sum of (x . n) dA = dim * volume.
double cornerFlux(const Mesh& m, int body, int corners) {
  const Surface& s = m.surfaces.at(body);
  double flux = 0.0;
  for (LocalIndex f = 0; f < s.numFacets(); ++f) {
    const LocalIndex* n = &s.facets[std::size_t(f) * s.nodesPerFacet];
    if (m.dim == 2) {
      const double tx = m.coord(n[1], 0) - m.coord(n[0], 0), ty = m.coord(n[1], 1) - m.coord(n[0], 1);
      flux += 0.5 * (m.coord(n[0], 0) + m.coord(n[1], 0)) * ty - 0.5 * (m.coord(n[0], 1) + m.coord(n[1], 1)) * tx;
      continue;
    }
    for (int t = 1; t + 1 < corners; ++t) {
      double u[3], v[3], cen[3];
      for (int i = 0; i < 3; ++i) {
        u[i] = m.coord(n[t], i) - m.coord(n[0], i);
        v[i] = m.coord(n[t + 1], i) - m.coord(n[0], i);
        cen[i] = (m.coord(n[0], i) + m.coord(n[t], i) + m.coord(n[t + 1], i)) / 3.0;
      }
      flux += 0.5 * (cen[0] * (u[1] * v[2] - u[2] * v[1]) + cen[1] * (u[2] * v[0] - u[0] * v[2]) +
                     cen[2] * (u[0] * v[1] - u[1] * v[0]));
    }
  }
  return flux;
}

// The same on linear facets (all their nodes are corners).
double surfaceFlux(const Mesh& m, int body) { return cornerFlux(m, body, m.surfaces.at(body).nodesPerFacet); }

TEST(Generators, RectangleAndBoxSurfacesAreClosedAndOutward) {
  RectangleSpec r;
  r.lx = 2.0, r.ly = 3.0, r.nx = 4, r.ny = 5;
  Mesh rect = rectangle(r);
  EXPECT_EQ(rect.numNodes(), 30);
  EXPECT_NEAR(cellMeasures(rect).first, 6.0, 1e-12);
  EXPECT_EQ(rect.surfaces[0].numFacets(), 18);
  EXPECT_NEAR(surfaceFlux(rect, 0), 2 * 6.0, 1e-12);
  for (bool tets : {false, true}) {
    BoxSpec b;
    b.lx = 1.0, b.ly = 2.0, b.lz = 0.5, b.nx = 2, b.ny = 3, b.nz = 2, b.tetrahedra = tets;
    Mesh box3 = box(b);
    const auto [volume, smallest] = cellMeasures(box3);
    EXPECT_NEAR(volume, 1.0, 1e-12);
    EXPECT_GT(smallest, 0.0);
    EXPECT_NEAR(surfaceFlux(box3, 0), 3 * 1.0, 1e-12);
    EXPECT_EQ(box3.surfaces[0].nodesPerFacet, tets ? 3 : 4);
    EXPECT_EQ(box3.nodeSet("zmax").size(), 12u);
  }
}

// Every mid-edge node of a facet (the node after its corners, 2D) lies at the midpoint of its corners.
void expectStraightFacets2d(const Mesh& m, int body) {
  const Surface& s = m.surfaces.at(body);
  ASSERT_EQ(s.nodesPerFacet, 3);
  for (LocalIndex f = 0; f < s.numFacets(); ++f) {
    const LocalIndex* n = &s.facets[std::size_t(f) * 3];
    for (int i = 0; i < 2; ++i) EXPECT_NEAR(m.coord(n[2], i), 0.5 * (m.coord(n[0], i) + m.coord(n[1], i)), 1e-14);
  }
}

TEST(Elevate, RectangleBecomesQuad9OrQuad8WithSharedNodesAndFullNodeSets) {
  for (bool serendipity : {false, true}) {
    RectangleSpec r;
    r.lx = 2.0, r.ly = 3.0, r.nx = 4, r.ny = 5;
    const Mesh linear = rectangle(r);
    r.element = {2, serendipity};
    const Mesh m = rectangle(r);
    ASSERT_EQ(m.blocks.size(), 1u);
    EXPECT_EQ(m.blocks[0].type, serendipity ? CellType::Quad8 : CellType::Quad9);
    // 9 x 11 grid points; Quad8 lacks the 20 cell centres
    EXPECT_EQ(m.numNodes(), serendipity ? 79 : 99);
    for (LocalIndex n = 0; n < linear.numNodes(); ++n)
      for (int i = 0; i < 2; ++i) EXPECT_EQ(m.coord(n, i), linear.coord(n, i));  // the corners keep their indices
    const auto measure = testing::isoparametricMeasure(m);
    EXPECT_NEAR(measure.perBody[0], 6.0, 1e-12);
    EXPECT_GT(measure.smallestJacobian, 0.0);
    EXPECT_EQ(m.surfaces[0].numFacets(), 18);
    EXPECT_NEAR(cornerFlux(m, 0, 2), 2 * 6.0, 1e-12);
    expectStraightFacets2d(m, 0);
    // a node set holds the mid-edge nodes of its edges, no others
    EXPECT_EQ(m.nodeSet("top").size(), 9u);
    EXPECT_EQ(m.nodeSet("left").size(), 11u);
    for (LocalIndex n : m.nodeSet("top")) EXPECT_EQ(m.coord(n, 1), 3.0);
    for (LocalIndex n : m.nodeSet("left")) EXPECT_EQ(m.coord(n, 0), 0.0);
  }
}

TEST(Elevate, BoxBecomesHex27Hex20OrTet10) {
  for (bool tets : {false, true})
    for (bool serendipity : {false, true}) {
      BoxSpec b;
      b.lx = 1.0, b.ly = 2.0, b.lz = 0.5, b.nx = 2, b.ny = 3, b.nz = 2, b.tetrahedra = tets;
      b.element = {2, serendipity};
      const Mesh m = box(b);
      const CellType type = tets ? CellType::Tet10 : serendipity ? CellType::Hex20 : CellType::Hex27;
      EXPECT_EQ(m.blocks[0].type, type);
      const auto measure = testing::isoparametricMeasure(m);
      EXPECT_NEAR(measure.perBody[0], 1.0, 1e-12);
      EXPECT_GT(measure.smallestJacobian, 0.0);
      EXPECT_EQ(m.surfaces[0].nodesPerFacet, cellTypeInfo(type).nodesPerFacet);
      EXPECT_NEAR(cornerFlux(m, 0, facetCornerCount(cellTypeInfo(type))), 3 * 1.0, 1e-12);
      // 5 x 7 x 5 grid points; Hex20 lacks the 52 face and 12 cell centres
      if (!tets) {
        EXPECT_EQ(m.numNodes(), serendipity ? 111 : 175);
      }
      // the face z = lz: its node set is every node on it
      std::size_t onTop = 0;
      for (LocalIndex n = 0; n < m.numNodes(); ++n) onTop += m.coord(n, 2) == 0.5;
      EXPECT_EQ(m.nodeSet("zmax").size(), onTop);
      for (LocalIndex n : m.nodeSet("zmax")) EXPECT_EQ(m.coord(n, 2), 0.5);
      if (!tets) {
        EXPECT_EQ(onTop, serendipity ? 35u - 6u : 35u);
      }
    }
}

TEST(Elevate, QuarterDiskPutsTheArcsEdgeNodesOnTheCircle) {
  QuarterDiskSpec s;
  s.radius = 1.0;
  s.centerY = 1.01;
  const double linearError = std::abs(cellMeasures(quarterDisk(s)).first - cgcm::kPi / 4);
  s.element.order = 2;
  const Mesh m = quarterDisk(s);
  EXPECT_EQ(m.blocks[0].type, CellType::Quad9);
  const auto measure = testing::isoparametricMeasure(m);
  EXPECT_GT(measure.smallestJacobian, 0.0);
  const Surface& arc = m.surfaces[0];
  ASSERT_EQ(arc.nodesPerFacet, 3);
  int onArc = 0;
  auto radius = [&](LocalIndex n) { return std::hypot(m.coord(n, 0), m.coord(n, 1) - 1.01); };
  for (LocalIndex f = 0; f < arc.numFacets(); ++f) {
    const LocalIndex* n = &arc.facets[std::size_t(f) * 3];
    if (std::abs(radius(n[0]) - 1.0) > 1e-12 || std::abs(radius(n[1]) - 1.0) > 1e-12) continue;
    ++onArc;
    EXPECT_NEAR(radius(n[2]), 1.0, 1e-14);
    // at the middle of the arc between the corners
    const double d0 = std::hypot(m.coord(n[2], 0) - m.coord(n[0], 0), m.coord(n[2], 1) - m.coord(n[0], 1));
    const double d1 = std::hypot(m.coord(n[2], 0) - m.coord(n[1], 0), m.coord(n[2], 1) - m.coord(n[1], 1));
    EXPECT_NEAR(d0, d1, 1e-14);
  }
  EXPECT_EQ(onArc, 32);  // the arc's segments at level 0
  // the curved cells hold the disk far better than the inscribed polygon: the arc's error drops from
  // O(h^2) to O(h^4) (chord sagitta h^2 / 8R against the parabola's h^4 error)
  const double error = std::abs(measure.perBody[0] - cgcm::kPi / 4);
  std::printf("[ quarter disk ] area error: linear %.3e, quadratic %.3e\n", linearError, error);
  EXPECT_LT(error, 1e-3 * linearError);
  for (LocalIndex n : m.nodeSet("axis")) EXPECT_EQ(m.coord(n, 0), 0.0);
  for (LocalIndex n : m.nodeSet("equator")) EXPECT_NEAR(m.coord(n, 1), 1.01, 1e-14);
  EXPECT_EQ(m.nodeSet("apex").size(), 1u);
}

TEST(Generators, AppendKeepsBodiesApart) {
  RectangleSpec a, b;
  a.nx = a.ny = 2;
  b.nx = b.ny = 3;
  b.y0 = 1.5;
  Mesh m = rectangle(a);
  append(m, rectangle(b), "upper ");
  EXPECT_EQ(m.numBodies, 2);
  ASSERT_EQ(m.surfaces.size(), 2u);
  EXPECT_EQ(m.surfaces[0].numFacets(), 8);
  EXPECT_EQ(m.surfaces[1].numFacets(), 12);
  EXPECT_NEAR(surfaceFlux(m, 1), 2 * 1.0, 1e-12);
  EXPECT_EQ(m.nodeSet("upper top").size(), 4u);
  EXPECT_THROW(m.nodeSet("middle"), InputError);
}

TEST(Benchmark, QuarterDiskIsValidAndConvergesToTheDisk) {
  double previousError = 1.0;
  for (int level = 0; level <= 2; ++level) {
    QuarterDiskSpec s;
    s.radius = 1.0;
    s.centerY = 1.01;
    s.refinement = level;
    const Mesh m = quarterDisk(s);
    const auto [area, smallest] = cellMeasures(m);
    EXPECT_GT(smallest, 0.0);
    const double error = std::abs(area - cgcm::kPi / 4);
    EXPECT_LT(error, 2e-3);
    EXPECT_LT(error, 0.3 * previousError + 1e-15);  // second order: /4 per level
    previousError = error;
    EXPECT_NEAR(surfaceFlux(m, 0), 2 * area, 1e-10);
    const LocalIndex apex = m.nodeSet("apex").at(0);
    EXPECT_NEAR(m.coord(apex, 0), 0.0, 1e-14);
    EXPECT_NEAR(m.coord(apex, 1), 0.01, 1e-14);
    for (const auto& [name, nodes] : m.nodeSets)
      EXPECT_TRUE(std::adjacent_find(nodes.begin(), nodes.end()) == nodes.end()) << name << " repeats a node";
    for (LocalIndex n : m.nodeSet("axis")) EXPECT_EQ(m.coord(n, 0), 0.0);
    for (LocalIndex n : m.nodeSet("equator")) EXPECT_NEAR(m.coord(n, 1), 1.01, 1e-14);
    if (level == 0) {
      EXPECT_GT(m.numNodes(), 500);
      EXPECT_LT(m.numNodes(), 900);
    }
  }
  QuarterDiskSpec upper;
  upper.lowerHalf = false;
  const Mesh m = quarterDisk(upper);
  EXPECT_GT(cellMeasures(m).second, 0.0);
  EXPECT_NEAR(m.coord(m.nodeSet("apex").at(0), 1), 1.0, 1e-14);
}

TEST(Benchmark, HalfSpaceBlockIsGradedTowardsTheContactZone) {
  HalfSpaceSpec s;
  const Mesh m = halfSpaceBlock(s);
  const auto [area, smallest] = cellMeasures(m);
  EXPECT_NEAR(area, 64.0, 1e-10);
  EXPECT_GT(smallest, 0.0);
  EXPECT_NEAR(surfaceFlux(m, 0), 2 * 64.0, 1e-9);
  const LocalIndex apex = m.nodeSet("apex").at(0);
  EXPECT_EQ(m.coord(apex, 0), 0.0);
  EXPECT_NEAR(m.coord(apex, 1), 0.0, 1e-14);
  // the surface cells next to the axis are the fine ones
  const auto& top = m.nodeSet("top");
  EXPECT_NEAR(m.coord(top[1], 0) - m.coord(top[0], 0), 0.025, 1e-12);
  EXPECT_GT(m.coord(top.back(), 0) - m.coord(top[top.size() - 2], 0), 1.0);
}

TEST(Benchmark, ContactZoneSetsTheFineCellsAlongAndUnderTheSurface) {
  // A smaller fine zone shrinks the surface cells and the first layer under
  // them alike: 20 (half-space) and 16 (sphere) cells over the zone at level 0.
  for (Real zone : {0.5, 0.1}) {
    HalfSpaceSpec h;
    h.fineLength = zone;
    const Mesh block = halfSpaceBlock(h);
    EXPECT_GT(cellMeasures(block).second, 0.0);
    EXPECT_NEAR(cellMeasures(block).first, 64.0, 1e-9);
    const auto& top = block.nodeSet("top");
    EXPECT_NEAR(block.coord(top[1], 0) - block.coord(top[0], 0), zone / 20, 1e-12);
    EXPECT_NEAR(block.coord(top[20], 0), zone, 1e-12);
    const LocalIndex apex = block.nodeSet("apex").at(0);
    const LocalIndex below = apex - LocalIndex(top.size());  // the node under the apex, one row down
    EXPECT_NEAR(block.coord(apex, 1) - block.coord(below, 1), zone / 20, 1e-12);

    QuarterDiskSpec d;
    d.fineAngle = 0.8 * zone;
    const Mesh disk = quarterDisk(d);
    EXPECT_GT(cellMeasures(disk).second, 0.0);
    EXPECT_NEAR(cellMeasures(disk).first, cgcm::kPi / 4, 0.01);  // the coarse cells away from the zone are longer
    // the surface segment at the apex and the apex's neighbour below it on the axis
    const LocalIndex tip = disk.nodeSet("apex").at(0);
    Real shortest = 1e300, step = 1e300;
    for (LocalIndex e = 0; e < disk.surfaces[0].numFacets(); ++e) {
      const LocalIndex a = disk.surfaces[0].facets[2 * e], b = disk.surfaces[0].facets[2 * e + 1];
      if (a == tip || b == tip)
        shortest = std::hypot(disk.coord(a, 0) - disk.coord(b, 0), disk.coord(a, 1) - disk.coord(b, 1));
    }
    for (LocalIndex n : disk.nodeSet("axis"))
      if (n != tip) step = std::min(step, std::abs(disk.coord(n, 1) - disk.coord(tip, 1)));
    EXPECT_NEAR(shortest, 0.8 * zone / 16, 1e-3 * zone);  // a chord of the arc
    EXPECT_NEAR(step, 0.8 * zone / 16, 1e-12);
  }
}

TEST(Benchmark, GradingsFillTheirLength) {
  const auto g = geometric(2.0, 0.01, 30);
  EXPECT_EQ(g.size(), 31u);
  EXPECT_NEAR(g[1], 0.01, 1e-12);
  EXPECT_EQ(g.back(), 2.0);
  const auto f = fineThenGeometric(8.0, 0.5, 20, 10);
  EXPECT_NEAR(f[20], 0.5, 1e-12);
  EXPECT_EQ(f.back(), 8.0);
  for (std::size_t k = 21; k < f.size(); ++k) EXPECT_GT(f[k] - f[k - 1], f[k - 1] - f[k - 2] - 1e-12);
  EXPECT_THROW(fineThenGeometric(1.0, 2.0, 4, 4), InputError);
  const auto even = geometric(1.0, 0.085, 14);  // the sphere's layers at zone 0.85: 14 x 0.085 > 1
  for (std::size_t k = 1; k < even.size(); ++k) EXPECT_NEAR(even[k] - even[k - 1], 1.0 / 14, 1e-12);
  // fine cells too long for the coarse ones to grow (the sphere's arc at Contact Zone Size 0.85):
  // the coarse cells are shorter, evenly spread, and the positions still increase to the end
  const auto tight = fineThenGeometric(cgcm::kPi / 4, 0.68, 16, 8);
  EXPECT_NEAR(tight[16], 0.68, 1e-12);
  EXPECT_EQ(tight.back(), cgcm::kPi / 4);
  for (std::size_t k = 17; k < tight.size(); ++k) {
    EXPECT_GT(tight[k] - tight[k - 1], 0.0) << k;
    EXPECT_LE(tight[k] - tight[k - 1], 0.68 / 16 + 1e-12) << k;
  }
}

TEST(Benchmark, QuarterDiskDoesNotFoldOverAnyContactZone) {
  // A cell turned inside out would be flipped by the generator and its area counted twice: the cells
  // must tile the quarter disk. What they miss is the chords' segments, the sum of d theta^3 / 12 over
  // the arc's cells: measured 6.9e-3 at zone 0.02 (its coarsest arc cells are the longest), 0.7e-3 to
  // 1.1e-3 from 0.3 to 0.85 (before this was fixed, 0.85 folded and overlapped by 7.6e-2).
  for (double zone : {0.02, 0.3, 0.5, 0.65, 0.66, 0.75, 0.85}) {
    QuarterDiskSpec s;
    s.fineAngle = 0.8 * zone;  // as Geometry/Contact Zone Size sets it
    const auto [area, smallest] = cellMeasures(quarterDisk(s));
    EXPECT_GT(smallest, 0.0) << "zone " << zone;
    EXPECT_NEAR(area, cgcm::kPi / 4, zone < 0.1 ? 8e-3 : 2e-3) << "zone " << zone;
  }
}

// The benchmark's quarter model in 3D: the sphere (centre at height R + gap) and the half-space.
struct QuarterModel {
  QuarterDiskSpec sphere;
  HalfSpaceSpec halfSpace;
  int quarterCells = 8;
  Mesh mesh() const { return sphereOnHalfSpaceQuarter(sphere, halfSpace, quarterCells); }
};

QuarterModel quarterModel(int level, int quarterCells, ElementOrder element = {}) {
  QuarterModel q;
  q.sphere.radius = 1.0;
  q.sphere.centerY = 1.01;
  q.sphere.refinement = q.halfSpace.refinement = level;
  q.sphere.element = q.halfSpace.element = element;
  q.sphere.fineAngle = 0.4;
  q.quarterCells = quarterCells << level;
  return q;
}

// Faces of a body's cells (corner keys) and how many cells use each.
std::map<std::vector<LocalIndex>, int> faceUses(const Mesh& m, int body) {
  std::map<std::vector<LocalIndex>, int> uses;
  for (const auto& b : m.blocks) {
    if (b.body != body) continue;
    const int npc = nodesPerCell(b.type), corners = facetCornerCount(cellTypeInfo(b.type));
    for (LocalIndex c = 0; c < b.numCells(); ++c)
      for (const auto& f : localFacets(b.type)) {
        std::vector<LocalIndex> key;
        for (int a = 0; a < corners; ++a) key.push_back(b.connectivity[std::size_t(c) * npc + f[a]]);
        std::sort(key.begin(), key.end());
        ++uses[key];
      }
  }
  return uses;
}

double distance(const Mesh& m, LocalIndex n, const double (&c)[3]) {
  return std::sqrt(std::pow(m.coord(n, 0) - c[0], 2) + std::pow(m.coord(n, 1) - c[1], 2) +
                   std::pow(m.coord(n, 2) - c[2], 2));
}

TEST(Benchmark, QuarterModelCellsArePositiveAndTheSphereConverges) {
  // The sphere body is a quarter of the lower hemisphere, pi R^3 / 6. Its surface is inscribed
  // (flat facets between nodes on the sphere): the volume misses the caps over the facets, about
  // (surface area) x (2/3 of the chord's sagitta R d^2 / 8) = (pi / 2) x (pi / 16)^2 / 12 = 5.0e-3
  // for the azimuthal cells at 8 over the quarter (the meridian's finer ones add little). Measured:
  // 4.34e-3 at level 0 and 1.09e-3 at level 1 (each level halves every cell: / 4, second order).
  double previous = 1.0;
  for (int level : {0, 1}) {
    SCOPED_TRACE("level " + std::to_string(level));
    const Mesh m = quarterModel(level, 8).mesh();
    for (const auto& b : m.blocks) EXPECT_EQ(b.type, CellType::Hex8);
    const auto measure = testing::isoparametricMeasure(m);  // every Gauss point and node of every cell
    EXPECT_GT(measure.smallestJacobian, 0.0);
    const double error = std::abs(measure.perBody[0] - cgcm::kPi / 6);
    std::printf("[ quarter model ] level %d: %d nodes, %d cells, sphere volume error %.3e\n", level, int(m.numNodes()),
                int(m.numCells()), error);
    EXPECT_LT(error, 5e-3 / (1 << (2 * level)));
    EXPECT_LT(error, 0.3 * previous);
    previous = error;
    // the half-space: a quarter cylinder of radius and depth 8 whose flat faces are the prism over the
    // inscribed polygon of its 8 x 2^level equal sides: its volume exactly
    const int sides = 8 << level;
    EXPECT_NEAR(measure.perBody[1], 8 * sides * 0.5 * 64 * std::sin(cgcm::kPi / 2 / sides), 1e-9 * 512);
    // the model's size without building it (the size check before any work)
    const MeshSize size = sphereOnHalfSpaceQuarterSize(level, 8 << level);
    EXPECT_EQ(size.nodes, m.numNodes());
    EXPECT_EQ(size.cells, m.numCells());
  }
  for (int cells : {2, 4, 16}) {
    const QuarterModel q = quarterModel(0, cells);
    const Mesh m = q.mesh();
    EXPECT_GT(testing::isoparametricMeasure(m).smallestJacobian, 0.0) << cells;
    EXPECT_EQ(sphereOnHalfSpaceQuarterSize(0, cells).nodes, m.numNodes());
  }
  EXPECT_THROW(quarterModel(0, 3).mesh(), InputError);
  EXPECT_THROW(quarterModel(0, 40).mesh(), InputError);  // the core would not turn into circles in the sphere
}

TEST(Benchmark, QuarterModelOfTheWidestContactZoneIsValid) {
  // Contact Zone Size 0.85 (fine angle 0.68): the meridian's coarse cells no longer grow (they are
  // even and shorter than the fine ones), so the swept cells stay positive and tile the quarter sphere
  // as well as the default zone's (volume error 4.34e-3 there, bound 5e-3 as above).
  QuarterModel q = quarterModel(0, 8);
  q.sphere.fineAngle = 0.8 * 0.85;
  const Mesh m = q.mesh();
  const auto measure = testing::isoparametricMeasure(m);
  EXPECT_GT(measure.smallestJacobian, 0.0);
  EXPECT_LT(std::abs(measure.perBody[0] - cgcm::kPi / 6), 5e-3);
}

TEST(Benchmark, QuarterModelIsConformingWithOutwardSurfacesOnTheSphere) {
  const QuarterModel q = quarterModel(0, 8);
  const Mesh m = q.mesh();
  const double centre[3] = {0.0, 0.0, 1.01};
  const auto on = [&](const std::vector<LocalIndex>& f, auto&& test) { return std::all_of(f.begin(), f.end(), test); };
  for (int body : {0, 1}) {
    SCOPED_TRACE("body " + std::to_string(body));
    // every face is shared by two cells, or lies on the body's boundary
    int boundary = 0, curved = 0;
    for (const auto& [face, count] : faceUses(m, body)) {
      EXPECT_LE(count, 2);
      if (count == 2) continue;
      ++boundary;
      const bool plane = on(face, [&](LocalIndex n) { return m.coord(n, 0) == 0.0; }) ||
                         on(face, [&](LocalIndex n) { return m.coord(n, 1) == 0.0; });
      const bool flat =
          body == 0 ? on(face, [&](LocalIndex n) { return std::abs(m.coord(n, 2) - 1.01) < 1e-14; })
                    : on(face, [&](LocalIndex n) { return m.coord(n, 2) == -8.0; }) ||
                          on(face, [&](LocalIndex n) { return std::hypot(m.coord(n, 0), m.coord(n, 1)) > 8 - 1e-12; });
      const bool surface = body == 0
                               ? on(face, [&](LocalIndex n) { return std::abs(distance(m, n, centre) - 1.0) < 1e-14; })
                               : on(face, [&](LocalIndex n) { return m.coord(n, 2) == 0.0; });
      EXPECT_TRUE(plane || flat || surface) << "an inner face used by one cell";
      curved += surface && !plane;
    }
    // the interacting surface: the curved face (the top), all of it, outward
    const Surface& s = m.surfaces[std::size_t(body)];
    ASSERT_EQ(s.nodesPerFacet, 4);
    EXPECT_EQ(s.numFacets(), curved);
    EXPECT_GT(boundary, curved);
    for (LocalIndex f = 0; f < s.numFacets(); ++f) {
      const LocalIndex* n = &s.facets[std::size_t(f) * 4];
      double a[3], b[3], normal[3], mid[3] = {}, cell[3] = {};
      for (int i = 0; i < 3; ++i) {
        a[i] = m.coord(n[1], i) - m.coord(n[0], i);
        b[i] = m.coord(n[3], i) - m.coord(n[0], i);
        for (int k = 0; k < 4; ++k) mid[i] += m.coord(n[k], i) / 4;
      }
      normal[0] = a[1] * b[2] - a[2] * b[1], normal[1] = a[2] * b[0] - a[0] * b[2],
      normal[2] = a[0] * b[1] - a[1] * b[0];
      LocalIndex c = s.facetCells[f];
      std::size_t bi = 0;
      while (c >= m.blocks[bi].numCells()) c -= m.blocks[bi++].numCells();
      for (int k = 0; k < 8; ++k)
        for (int i = 0; i < 3; ++i) cell[i] += m.coord(m.blocks[bi].connectivity[std::size_t(c) * 8 + k], i) / 8;
      double away = 0.0, outward = 0.0;
      for (int i = 0; i < 3; ++i) {
        away += normal[i] * (mid[i] - cell[i]);
        outward += normal[i] * (body == 0 ? mid[i] - centre[i] : (i == 2 ? 1.0 : 0.0));
      }
      EXPECT_GT(away, 0.0);
      EXPECT_GT(outward, 0.0);
      for (int k = 0; k < 4; ++k)
        if (body == 0) {
          EXPECT_NEAR(distance(m, n[k], centre), 1.0, 1e-15);  // on the sphere to round-off
        } else {
          EXPECT_EQ(m.coord(n[k], 2), 0.0);
        }
    }
  }
}

TEST(Benchmark, QuarterModelHasTheGmshNodeSetsAndTheMeridianOnItsPlanes) {
  const QuarterModel q = quarterModel(0, 8);
  const Mesh m = q.mesh();
  std::vector<std::string> names;
  for (const auto& [name, nodes] : m.nodeSets) names.push_back(name);
  EXPECT_EQ(names, (std::vector<std::string>{"apex", "contact:half-space", "contact:sphere", "driven", "driven body",
                                             "fixed", "lower apex", "symmetry x", "symmetry y"}));
  EXPECT_EQ(bodyNames(m), (std::vector<std::string>{"sphere", "half-space"}));
  std::vector<int> bodyOf(std::size_t(m.numNodes()), -1);
  for (const auto& b : m.blocks)
    for (LocalIndex n : b.connectivity) bodyOf[n] = b.body;
  const LocalIndex sphereNodes = LocalIndex(std::count(bodyOf.begin(), bodyOf.end(), 0));
  EXPECT_EQ(m.nodeSet("driven body").size(), std::size_t(sphereNodes));
  for (LocalIndex n : m.nodeSet("driven body")) EXPECT_EQ(bodyOf[n], 0);
  // the symmetry planes: every node on x = 0 (y = 0), and no other
  for (int axis : {0, 1}) {
    const auto& set = m.nodeSet(axis == 0 ? "symmetry x" : "symmetry y");
    std::vector<LocalIndex> onPlane;
    for (LocalIndex n = 0; n < m.numNodes(); ++n)
      if (m.coord(n, axis) == 0.0) onPlane.push_back(n);
    EXPECT_EQ(set, onPlane);
  }
  // driven: the sphere's equator plane; fixed: the half-space's bottom
  std::vector<LocalIndex> equator, bottom;
  for (LocalIndex n = 0; n < m.numNodes(); ++n) {
    if (bodyOf[n] == 0 && std::abs(m.coord(n, 2) - 1.01) < 1e-14) equator.push_back(n);
    if (bodyOf[n] == 1 && m.coord(n, 2) == -8.0) bottom.push_back(n);
  }
  EXPECT_EQ(m.nodeSet("driven"), equator);
  EXPECT_EQ(m.nodeSet("fixed"), bottom);
  const LocalIndex apex = m.nodeSet("apex").at(0), lower = m.nodeSet("lower apex").at(0);
  EXPECT_EQ(m.nodeSet("apex").size(), 1u);
  EXPECT_EQ(m.nodeSet("lower apex").size(), 1u);
  for (int i = 0; i < 2; ++i) {
    EXPECT_EQ(m.coord(apex, i), 0.0);
    EXPECT_EQ(m.coord(lower, i), 0.0);
  }
  EXPECT_NEAR(m.coord(apex, 2), 0.01, 1e-15);
  EXPECT_EQ(m.coord(lower, 2), 0.0);
  // either plane holds the meridian meshes node for node (up to the round-off of putting them on the sphere)
  auto points = [](const Mesh& mm, int from, int to, auto&& pick) {
    std::vector<std::array<double, 2>> p;
    for (LocalIndex n = from; n < to; ++n)
      if (pick(n)) p.push_back({mm.coord(n, 0) + mm.coord(n, 1) * (mm.dim == 3), mm.coord(n, mm.dim - 1)});
    std::sort(p.begin(), p.end());
    return p;
  };
  const Mesh disk = quarterDisk(q.sphere), block = halfSpaceBlock(q.halfSpace);
  for (int axis : {0, 1}) {
    auto onPlane = [&](LocalIndex n) { return m.coord(n, axis) == 0.0; };
    auto all = [](LocalIndex) { return true; };
    for (const auto& [swept, meridian] :
         {std::pair{points(m, 0, sphereNodes, onPlane), points(disk, 0, disk.numNodes(), all)},
          std::pair{points(m, sphereNodes, m.numNodes(), onPlane), points(block, 0, block.numNodes(), all)}}) {
      ASSERT_EQ(swept.size(), meridian.size());
      for (std::size_t k = 0; k < swept.size(); ++k)
        for (int i = 0; i < 2; ++i) EXPECT_NEAR(swept[k][i], meridian[k][i], 1e-15);
    }
  }
}

TEST(Benchmark, QuarterModelIsAsFineAtTheApexAsTheMeridianMesh) {
  // the cells at the apex and under it in the half-space: as long as the meridian mesh's fine cells
  // (0.8 zone / 16 on the sphere, zone / 20 on the half-space) in every direction, across the core too
  for (Real zone : {0.5, 0.1}) {
    QuarterModel q = quarterModel(0, 8);
    q.sphere.fineAngle = 0.8 * zone;
    q.halfSpace.fineLength = zone;
    const Mesh m = q.mesh();
    for (const auto& [set, h] : {std::pair{"apex", 0.8 * zone / 16}, std::pair{"lower apex", zone / 20}}) {
      const LocalIndex tip = m.nodeSet(set).at(0);
      double longest = 0.0, shortest = 1e300;
      for (const auto& b : m.blocks)
        for (LocalIndex c = 0; c < b.numCells(); ++c) {
          const LocalIndex* h8 = &b.connectivity[std::size_t(c) * 8];
          if (std::find(h8, h8 + 8, tip) == h8 + 8) continue;
          for (const auto& e : cellTypeInfo(CellType::Hex8).facets)
            for (int k = 0; k < 4; ++k) {
              double d2 = 0.0;
              for (int i = 0; i < 3; ++i) d2 += std::pow(m.coord(h8[e[k]], i) - m.coord(h8[e[(k + 1) % 4]], i), 2);
              longest = std::max(longest, std::sqrt(d2)), shortest = std::min(shortest, std::sqrt(d2));
            }
        }
      EXPECT_LT(longest, 1.1 * h) << set << ", zone " << zone;
      EXPECT_GT(shortest, 0.9 * h) << set << ", zone " << zone;
    }
  }
}

TEST(Elevate, QuarterModelPutsTheSphereFacesNodesOnTheSphere) {
  const double linear = std::abs(testing::isoparametricMeasure(quarterModel(0, 4).mesh()).perBody[0] - cgcm::kPi / 6);
  const double centre[3] = {0.0, 0.0, 1.01};
  for (bool serendipity : {false, true}) {
    SCOPED_TRACE(serendipity ? "HEX20" : "HEX27");
    const Mesh m = quarterModel(0, 4, {2, serendipity}).mesh();
    for (const auto& b : m.blocks) EXPECT_EQ(b.type, serendipity ? CellType::Hex20 : CellType::Hex27);
    const auto measure = testing::isoparametricMeasure(m);
    EXPECT_GT(measure.smallestJacobian, 0.0);
    const Surface& s = m.surfaces[0];
    ASSERT_EQ(s.nodesPerFacet, serendipity ? 8 : 9);
    for (LocalIndex n : s.facets) EXPECT_NEAR(distance(m, n, centre), 1.0, 1e-15);
    for (LocalIndex n : m.surfaces[1].facets) EXPECT_EQ(m.coord(n, 2), 0.0);
    // curved faces hold the sphere far better than flat ones
    const double error = std::abs(measure.perBody[0] - cgcm::kPi / 6);
    std::printf("[ quarter model ] sphere volume error: linear %.3e, %s %.3e\n", linear,
                serendipity ? "HEX20" : "HEX27", error);
    EXPECT_LT(error, 0.02 * linear);
    for (LocalIndex n : m.nodeSet("symmetry x")) EXPECT_EQ(m.coord(n, 0), 0.0);
    for (LocalIndex n : m.nodeSet("driven")) EXPECT_NEAR(m.coord(n, 2), 1.01, 1e-14);
    for (LocalIndex n : m.nodeSet("fixed")) EXPECT_EQ(m.coord(n, 2), -8.0);
  }
}

// Two bodies: a rectangle and a second one at (x0, y0) with its own size and cells.
Mesh twoRectangles(Real x0, Real y0, Real lx, Real ly, int nx, int ny) {
  RectangleSpec a;
  a.nx = a.ny = 2;
  a.name = "a";
  Mesh m = rectangle(a);
  RectangleSpec b;
  b.x0 = x0, b.y0 = y0, b.lx = lx, b.ly = ly, b.nx = nx, b.ny = ny;
  b.name = "b";
  append(m, rectangle(b), "b ");
  return m;
}

Mesh twoBoxes(Real x0, bool tetrahedra) {
  BoxSpec a;
  a.nx = a.ny = a.nz = 2;
  a.tetrahedra = tetrahedra;
  a.name = "a";
  Mesh m = box(a);
  BoxSpec b = a;
  b.x0 = x0, b.y0 = 0.3, b.z0 = 0.2;
  b.name = "b";
  append(m, box(b), "b ");
  return m;
}

TEST(Overlap, FindsNodesInsideCellsAndCrossingBoundaries) {
  EXPECT_EQ(findBodyOverlap(twoRectangles(0.0, 1.5, 1.0, 1.0, 2, 2)), "");  // apart
  EXPECT_EQ(findBodyOverlap(twoRectangles(1.0, 0.0, 1.0, 1.0, 3, 3)), "");  // touching along x = 1
  const std::string inside = findBodyOverlap(twoRectangles(0.7, 0.7, 1.0, 1.0, 2, 2));
  EXPECT_NE(inside.find("lies inside a cell of body"), std::string::npos) << inside;
  // a cross: no node of either lies inside the other, the boundaries cross
  const std::string cross = findBodyOverlap(twoRectangles(-0.5, 0.6, 2.0, 0.2, 1, 1));
  EXPECT_NE(cross.find("the boundaries of body \"a\" and body \"b\" cross"), std::string::npos) << cross;
  for (bool tets : {false, true}) {
    EXPECT_EQ(findBodyOverlap(twoBoxes(1.0, tets)), "") << tets;
    EXPECT_NE(findBodyOverlap(twoBoxes(0.6, tets)), "") << tets;
  }
  // a thin slab through the first box between its node layers: only the boundaries cross
  BoxSpec a;
  a.nx = a.ny = a.nz = 2;
  Mesh slab = box(a);
  BoxSpec b;
  b.x0 = b.y0 = -0.5, b.z0 = 0.6, b.lx = b.ly = 2.0, b.lz = 0.1;
  append(slab, box(b), "b ");
  const std::string through = findBodyOverlap(slab);
  EXPECT_NE(through.find("cross"), std::string::npos) << through;
}

}  // namespace
}  // namespace cgcm::mesh

namespace cgcm::mesh {
namespace {

TEST(Mirror, JoinsBodiesOnThePlaneAndKeepsOrientation) {
  for (bool tets : {false, true}) {
    BoxSpec spec;
    spec.lx = 1.0, spec.ly = 2.0, spec.lz = 1.5, spec.nx = 3, spec.ny = 2, spec.nz = 2, spec.tetrahedra = tets;
    Mesh m = box(spec);
    m.nodeSets["symmetry x"] = m.nodeSets.at("xmin");
    const LocalIndex nodes = m.numNodes(), onPlane = LocalIndex(m.nodeSet("xmin").size());
    const LocalIndex cells = m.numCells(), facets = m.surfaces[0].numFacets();
    mirror(m, 0);
    EXPECT_EQ(m.numNodes(), 2 * nodes - onPlane);
    EXPECT_EQ(m.numCells(), 2 * cells);
    EXPECT_EQ(m.numBodies, 1);
    EXPECT_EQ(m.nodeSets.count("symmetry x"), 0u);
    // the plane's facets are interior now: 2 (ny nz) of them (x2 for triangles) leave
    const LocalIndex planeFacets = LocalIndex(spec.ny * spec.nz * (tets ? 2 : 1));
    EXPECT_EQ(m.surfaces[0].numFacets(), 2 * (facets - planeFacets));
    const double volume = 2.0 * spec.lx * spec.ly * spec.lz;
    // outward facets of the mirrored surface, and cells that kept their orientation (their own
    // exterior facets, rebuilt from the cells, give the same flux)
    EXPECT_NEAR(surfaceFlux(m, 0), 3.0 * volume, 1e-12);
    Mesh rebuilt = m;
    buildSurfaces(rebuilt);
    EXPECT_EQ(rebuilt.surfaces[0].numFacets(), m.surfaces[0].numFacets());
    EXPECT_NEAR(surfaceFlux(rebuilt, 0), 3.0 * volume, 1e-12);
    if (tets) {
      const auto [total, smallest] = cellMeasures(m);
      EXPECT_NEAR(total, volume, 1e-12);
      EXPECT_GT(smallest, 0.0);
    }
    // node sets hold both halves: xmax and its image
    EXPECT_EQ(m.nodeSet("xmax").size(), 2 * m.nodeSet("xmin").size());
  }
}

TEST(Mirror, QuadraticCellsKeepTheirOrientation) {
  for (CellType type : {CellType::Quad9, CellType::Quad8, CellType::Hex27, CellType::Hex20, CellType::Tet10}) {
    const CellTypeInfo& row = cellTypeInfo(type);
    const bool serendipity = type == CellType::Quad8 || type == CellType::Hex20;
    Mesh m;
    double volume = 0.0;
    if (row.dim == 2) {
      RectangleSpec r;
      r.lx = 1.0, r.ly = 2.0, r.nx = 2, r.ny = 3, r.element = {2, serendipity};
      m = rectangle(r);
      m.nodeSets["symmetry x"] = m.nodeSets.at("left");
      volume = 2.0 * 2.0;
    } else {
      BoxSpec b;
      b.lx = 1.0, b.ly = 2.0, b.lz = 1.5, b.nx = 2, b.ny = 2, b.nz = 1, b.tetrahedra = row.simplex;
      b.element = {2, serendipity};
      m = box(b);
      m.nodeSets["symmetry x"] = m.nodeSets.at("xmin");
      volume = 2.0 * 3.0;
    }
    ASSERT_EQ(m.blocks[0].type, type);
    const LocalIndex nodes = m.numNodes(), onPlane = LocalIndex(m.nodeSet("symmetry x").size());
    mirror(m, 0);
    EXPECT_EQ(m.numNodes(), 2 * nodes - onPlane) << row.name;
    const auto measure = testing::isoparametricMeasure(m);
    EXPECT_NEAR(measure.perBody[0], volume, 1e-12) << row.name;
    EXPECT_GT(measure.smallestJacobian, 0.0) << row.name;
    EXPECT_NEAR(cornerFlux(m, 0, facetCornerCount(row)), row.dim * volume, 1e-12) << row.name;
    Mesh rebuilt = m;
    buildSurfaces(rebuilt);
    // the same facets (each as its set of nodes; their orientation is the flux's)
    auto facetSets = [](const Surface& surface) {
      std::vector<std::vector<LocalIndex>> sets;
      for (LocalIndex f = 0; f < surface.numFacets(); ++f) {
        const auto first = surface.facets.begin() + std::ptrdiff_t(f) * surface.nodesPerFacet;
        sets.emplace_back(first, first + surface.nodesPerFacet);
        std::sort(sets.back().begin(), sets.back().end());
      }
      std::sort(sets.begin(), sets.end());
      return sets;
    };
    EXPECT_EQ(facetSets(rebuilt.surfaces[0]), facetSets(m.surfaces[0])) << row.name;
  }
}

TEST(Mirror, BodiesOffThePlaneGetAnImageBody) {
  BoxSpec spec;
  spec.x0 = 1.0, spec.nx = spec.ny = spec.nz = 2;
  Mesh m = box(spec);
  mirror(m, 0);
  ASSERT_EQ(m.numBodies, 2);
  EXPECT_EQ(m.blocks[1].body, 1);
  EXPECT_EQ(m.blocks[1].name, "block mirrored in x");
  EXPECT_NEAR(surfaceFlux(m, 1), 3.0, 1e-12);
  EXPECT_EQ(m.surfaces[1].numFacets(), m.surfaces[0].numFacets());
  EXPECT_TRUE(findBodyOverlap(m).empty());
  EXPECT_EQ(bodyNames(m), (std::vector<std::string>{"block", "block mirrored in x"}));
  // an image's original, through any number of planes; other names stay
  EXPECT_EQ(unmirroredName("block mirrored in x"), "block");
  EXPECT_EQ(unmirroredName("block mirrored in x mirrored in y"), "block");
  EXPECT_EQ(unmirroredName("mirrored in x"), "mirrored in x");
  EXPECT_EQ(unmirroredName("tip"), "tip");
}

TEST(Mirror, RejectsNodesOnTheNegativeSide) {
  BoxSpec spec;
  spec.x0 = -0.5;
  Mesh m = box(spec);
  EXPECT_THROW(mirror(m, 0), InputError);
}

}  // namespace
// A rank's subdomain holds its cells, the nodes they touch (no others) and the facets of its cells, in
// the whole mesh's order: every facet of the whole surface is on exactly one rank. Node sets are
// restricted.
TEST(Subdomain, HoldsItsCellsTheirNodesAndTheirFacets) {
  BoxSpec spec;
  spec.nx = spec.ny = spec.nz = 4;
  const Mesh whole = box(spec);
  std::vector<int> owner(std::size_t(whole.numCells()));
  for (LocalIndex c = 0; c < whole.numCells(); ++c) {
    Real x = 0.0;
    for (int a = 0; a < 8; ++a) x += whole.coord(whole.blocks[0].connectivity[std::size_t(c) * 8 + a], 0) / 8.0;
    owner[std::size_t(c)] = x < 0.25 ? 0 : (x < 0.75 ? 1 : 2);
  }
  LocalIndex cells = 0;
  std::vector<int> held(std::size_t(whole.surfaces[0].numFacets()), 0);  // per whole facet: the ranks holding it
  for (int rank = 0; rank < 3; ++rank) {
    SCOPED_TRACE(rank);
    const Mesh part = subdomain(whole, owner, rank);
    cells += part.numCells();
    ASSERT_EQ(part.nodeIds.size(), std::size_t(part.numNodes()));
    EXPECT_TRUE(std::is_sorted(part.nodeIds.begin(), part.nodeIds.end()));
    for (LocalIndex n = 0; n < part.numNodes(); ++n)
      for (int i = 0; i < 3; ++i) ASSERT_EQ(part.coord(n, i), whole.coord(LocalIndex(part.nodeIds[n]), i));
    // the planes of nodes its cells touch: 2 of 5 x 5 at the ends, 3 in the middle slab
    EXPECT_EQ(part.numNodes(), rank == 1 ? 75 : 50);
    ASSERT_EQ(part.nodeSets.size(), whole.nodeSets.size());
    for (LocalIndex n : part.nodeSet("xmin")) EXPECT_EQ(whole.coord(LocalIndex(part.nodeIds[n]), 0), 0.0);
    EXPECT_EQ(part.nodeSet("xmin").size(), rank == 0 ? whole.nodeSet("xmin").size() : 0u);
    ASSERT_EQ(part.surfaces.size(), 1u);
    const auto& s = part.surfaces[0];
    const auto& w = whole.surfaces[0];
    ASSERT_EQ(s.facetCells.size(), std::size_t(s.numFacets()));
    LocalIndex f = 0;  // the part's facets, in the whole surface's order
    for (LocalIndex g = 0; g < w.numFacets(); ++g) {
      if (owner[std::size_t(w.facetCells[std::size_t(g)])] != rank) continue;
      ASSERT_LT(f, s.numFacets());
      for (int a = 0; a < s.nodesPerFacet; ++a)
        EXPECT_EQ(part.nodeIds[std::size_t(s.facets[std::size_t(f) * 4 + a])], w.facets[std::size_t(g) * 4 + a]);
      const LocalIndex c = s.facetCells[std::size_t(f)];
      ASSERT_GE(c, 0);
      EXPECT_EQ(part.blocks[0].cellIds[std::size_t(c)], w.facetCells[std::size_t(g)]);
      ++held[std::size_t(g)];
      ++f;
    }
    EXPECT_EQ(f, s.numFacets());
    EXPECT_GT(f, 0);
  }
  EXPECT_EQ(cells, whole.numCells());
  EXPECT_EQ(std::count(held.begin(), held.end(), 1), std::ptrdiff_t(held.size()));
}

// A mesh sent to another rank (toBytes, meshFromBytes) arrives whole: a two-body mesh with node sets,
// and a part with its node ids, cell ids and facets. A cut or padded buffer is
// refused.
TEST(Subdomain, MeshesTravelAsBytesUnchanged) {
  BoxSpec spec;
  spec.x0 = 0.5, spec.nx = 3, spec.ny = 2, spec.nz = 2;
  Mesh whole = box(spec);
  mirror(whole, 0);
  std::vector<int> owner(std::size_t(whole.numCells()));
  for (std::size_t c = 0; c < owner.size(); ++c) owner[c] = int(c % 2);
  for (const Mesh& m : {whole, subdomain(whole, owner, 1)}) {
    const Mesh back = meshFromBytes(toBytes(m));
    EXPECT_EQ(back.dim, m.dim);
    EXPECT_EQ(back.numBodies, m.numBodies);
    EXPECT_EQ(back.coords, m.coords);
    EXPECT_EQ(back.nodeIds, m.nodeIds);
    EXPECT_EQ(back.nodeSets, m.nodeSets);
    ASSERT_EQ(back.blocks.size(), m.blocks.size());
    for (std::size_t b = 0; b < m.blocks.size(); ++b) {
      EXPECT_EQ(back.blocks[b].name, m.blocks[b].name);
      EXPECT_EQ(back.blocks[b].body, m.blocks[b].body);
      EXPECT_EQ(back.blocks[b].type, m.blocks[b].type);
      EXPECT_EQ(back.blocks[b].connectivity, m.blocks[b].connectivity);
      EXPECT_EQ(back.blocks[b].cellIds, m.blocks[b].cellIds);
    }
    ASSERT_EQ(back.surfaces.size(), m.surfaces.size());
    for (std::size_t k = 0; k < m.surfaces.size(); ++k) {
      EXPECT_EQ(back.surfaces[k].body, m.surfaces[k].body);
      EXPECT_EQ(back.surfaces[k].nodesPerFacet, m.surfaces[k].nodesPerFacet);
      EXPECT_EQ(back.surfaces[k].facets, m.surfaces[k].facets);
      EXPECT_EQ(back.surfaces[k].facetCells, m.surfaces[k].facetCells);
    }
  }
  auto bytes = toBytes(whole);
  bytes.push_back(0);
  EXPECT_THROW(meshFromBytes(bytes), std::logic_error);
  bytes.resize(bytes.size() / 2);
  EXPECT_THROW(meshFromBytes(bytes), std::logic_error);
}

}  // namespace cgcm::mesh
