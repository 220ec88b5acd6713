// The table of cell types (core/CellType.hpp) against the shape functions of
// its elements, and the dispatch from (Formulation, CellType) to the kernels.
// Each row is checked on its own parent cell, so a new row with a wrong
// facet, reflection or corner list fails here before any mesh is read.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>
#include <string>
#include <vector>

#include "cgcm/fem/Dispatch.hpp"

using namespace cgcm;

namespace {

using Point = std::array<Real, 3>;

// The parent coordinates of every node of the element of `type`.
std::vector<Point> parentNodes(CellType type) {
  std::vector<Point> out;
  const bool found = fem::withElement(type, [&](auto element) {
    using E = decltype(element);
    for (int a = 0; a < E::numNodes; ++a) {
      Real xi[E::dim];
      E::parentCoordinates(a, xi);
      Point p{0.0, 0.0, 0.0};
      for (int i = 0; i < E::dim; ++i) p[i] = xi[i];
      out.push_back(p);
    }
  });
  EXPECT_TRUE(found) << cellTypeInfo(type).name << " has no element";
  return out;
}

Point minus(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Point cross(const Point& a, const Point& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Real dot(const Point& a, const Point& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// Jacobian signs at the row's corners of the nodes x: +1 all positive, -1 all negative, 0 mixed.
int orientation(const CellTypeInfo& row, const std::vector<Point>& x) {
  int positive = 0, negative = 0;
  for (int k = 0; k < row.numCorners; ++k) {
    const int* c = row.corners[k];
    const Point a = minus(x[c[1]], x[c[0]]), b = minus(x[c[2]], x[c[0]]);
    const Real j = row.dim == 2 ? a[0] * b[1] - a[1] * b[0] : dot(cross(a, b), minus(x[c[3]], x[c[0]]));
    positive += j > 0.0, negative += j < 0.0;
  }
  return positive == row.numCorners ? 1 : negative == row.numCorners ? -1 : 0;
}

}  // namespace

TEST(CellTypeTable, EveryRowHasItsElementAndAKernel) {
  for (const CellTypeInfo& row : kCellTypes) {
    SCOPED_TRACE(row.name);
    EXPECT_EQ(int(parentNodes(row.type).size()), row.numNodes);
    int kernels = 0;
    for (Formulation f : {Formulation::PlaneStrain, Formulation::Axisymmetric, Formulation::ThreeD})
      kernels += fem::solidKernelTakes(f, row.type);
    EXPECT_EQ(kernels, row.dim == 2 ? 2 : 1);
  }
}

TEST(CellTypeTable, FacetsPointOutOfTheParentCell) {
  for (const CellTypeInfo& row : kCellTypes) {
    SCOPED_TRACE(row.name);
    const auto x = parentNodes(row.type);
    Point centre{0.0, 0.0, 0.0};
    for (const auto& p : x)
      for (int i = 0; i < 3; ++i) centre[i] += p[i] / Real(x.size());
    std::set<std::vector<int>> distinct;
    for (int f = 0; f < row.numFacets; ++f) {
      const int* n = row.facets[f];
      Point facetCentre{0.0, 0.0, 0.0}, normal{0.0, 0.0, 0.0};
      for (int a = 0; a < row.nodesPerFacet; ++a)
        for (int i = 0; i < 3; ++i) facetCentre[i] += x[n[a]][i] / row.nodesPerFacet;
      if (row.dim == 2) {
        const Point t = minus(x[n[1]], x[n[0]]);
        normal = {t[1], -t[0], 0.0};  // the body on the left of n0 -> n1
      } else {
        for (int a = 1; a + 1 < row.nodesPerFacet; ++a) {
          const Point m = cross(minus(x[n[a]], x[n[0]]), minus(x[n[a + 1]], x[n[0]]));
          for (int i = 0; i < 3; ++i) normal[i] += m[i];
        }
      }
      EXPECT_GT(dot(normal, minus(facetCentre, centre)), 0.0) << "facet " << f << " points inward";
      std::vector<int> nodes(n, n + row.nodesPerFacet);
      std::sort(nodes.begin(), nodes.end());
      distinct.insert(nodes);
    }
    EXPECT_EQ(int(distinct.size()), row.numFacets) << "a facet is listed twice";
  }
}

TEST(CellTypeTable, ReflectionKeepsTheOrientationAndTheCornersSeeIt) {
  for (const CellTypeInfo& row : kCellTypes) {
    SCOPED_TRACE(row.name);
    const auto x = parentNodes(row.type);
    EXPECT_EQ(orientation(row, x), 1);
    // mirror in the first coordinate: the image cell in the table's order is positive again
    std::vector<Point> image(x.size()), reordered(x.size());
    for (std::size_t a = 0; a < x.size(); ++a) image[a] = {-x[a][0], x[a][1], x[a][2]};
    EXPECT_EQ(orientation(row, image), -1);
    for (int a = 0; a < row.numNodes; ++a) reordered[a] = image[row.reflected[a]];
    EXPECT_EQ(orientation(row, reordered), 1);
    // the reflected facet order reverses the facet's normal: the mirrored facet 0 points out of the image
    const int* n = row.facets[0];
    Point normal{0.0, 0.0, 0.0}, mirrored{0.0, 0.0, 0.0};
    auto facetNormal = [&](const std::vector<Point>& p, const int* order, Point& out) {
      if (row.dim == 2) {
        const Point t = minus(p[n[order[1]]], p[n[order[0]]]);
        out = {t[1], -t[0], 0.0};
        return;
      }
      for (int a = 1; a + 1 < row.nodesPerFacet; ++a) {
        const Point m = cross(minus(p[n[order[a]]], p[n[order[0]]]), minus(p[n[order[a + 1]]], p[n[order[0]]]));
        for (int i = 0; i < 3; ++i) out[i] += m[i];
      }
    };
    int identity[kMaxFacetNodes];
    for (int a = 0; a < kMaxFacetNodes; ++a) identity[a] = a;
    facetNormal(x, identity, normal);
    facetNormal(image, row.reflectedFacet, mirrored);
    EXPECT_NEAR(mirrored[0], -normal[0], 1e-14);
    EXPECT_NEAR(mirrored[1], normal[1], 1e-14);
    EXPECT_NEAR(mirrored[2], normal[2], 1e-14);
  }
}

TEST(CellTypeTable, EachFacetLiesOnOneFaceOfTheParentCell) {
  for (const CellTypeInfo& row : kCellTypes) {
    SCOPED_TRACE(row.name);
    const auto x = parentNodes(row.type);
    for (int f = 0; f < row.numFacets; ++f) {
      const int* n = row.facets[f];
      auto all = [&](auto on) {
        for (int a = 0; a < row.nodesPerFacet; ++a)
          if (!on(x[n[a]])) return false;
        return true;
      };
      bool onAFace = false;
      for (int i = 0; i < row.dim; ++i)
        for (Real v : row.simplex ? std::vector<Real>{0.0} : std::vector<Real>{-1.0, 1.0})
          onAFace = onAFace || all([&](const Point& p) { return p[i] == v; });
      if (row.simplex) onAFace = onAFace || all([&](const Point& p) { return p[0] + p[1] + p[2] == 1.0; });
      EXPECT_TRUE(onAFace) << "facet " << f;
    }
  }
}

// The rows of the linear cells as the mesh code had them before the table (Exodus side order, the
// mirror's and the gmsh reader's reflections): a change to them changes written side sets and meshes.
TEST(CellTypeTable, TheLinearRowsAreTheExodusOnes) {
  auto facets = [](CellType t) {
    std::vector<std::vector<int>> out;
    const CellTypeInfo& row = cellTypeInfo(t);
    for (int f = 0; f < row.numFacets; ++f) out.emplace_back(row.facets[f], row.facets[f] + row.nodesPerFacet);
    return out;
  };
  auto reflected = [](CellType t) {
    const CellTypeInfo& row = cellTypeInfo(t);
    return std::vector<int>(row.reflected, row.reflected + row.numNodes);
  };
  EXPECT_EQ(facets(CellType::Quad4), (std::vector<std::vector<int>>{{0, 1}, {1, 2}, {2, 3}, {3, 0}}));
  EXPECT_EQ(facets(CellType::Hex8), (std::vector<std::vector<int>>{
                                        {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {0, 4, 7, 3}, {0, 3, 2, 1}, {4, 5, 6, 7}}));
  EXPECT_EQ(facets(CellType::Tet4), (std::vector<std::vector<int>>{{0, 1, 3}, {1, 2, 3}, {0, 3, 2}, {0, 2, 1}}));
  EXPECT_EQ(reflected(CellType::Quad4), (std::vector<int>{0, 3, 2, 1}));
  EXPECT_EQ(reflected(CellType::Hex8), (std::vector<int>{0, 3, 2, 1, 4, 7, 6, 5}));
  EXPECT_EQ(reflected(CellType::Tet4), (std::vector<int>{0, 2, 1, 3}));
  EXPECT_EQ(std::string(cellTypeInfo(CellType::Quad4).name), "QUAD4");
  EXPECT_EQ(std::string(cellTypeInfo(CellType::Hex8).name), "HEX8");
  EXPECT_EQ(std::string(cellTypeInfo(CellType::Tet4).name), "TETRA4");
}

// A facet's nodes after its corners sit where its own element (Line3, Tri6, Quad8, Quad9) has
// them: mid-edge node k halfway between corners k and k + 1, the face centre at the corners'
// mean. Checked on the parent cell, where every facet is flat.
TEST(CellTypeTable, FacetNodesFollowTheirCornersAsInTheFacetElement) {
  for (const CellTypeInfo& row : kCellTypes) {
    SCOPED_TRACE(row.name);
    const auto x = parentNodes(row.type);
    const int corners = facetCornerCount(row);
    for (int f = 0; f < row.numFacets; ++f) {
      const int* n = row.facets[f];
      for (int a = 0; a < corners; ++a) EXPECT_LT(n[a], cornerCount(row)) << "facet " << f << " corner " << a;
      for (int a = corners; a < row.nodesPerFacet; ++a) {
        Point want{0.0, 0.0, 0.0};
        const int k = a - corners;
        if (k < corners) {
          for (int i = 0; i < 3; ++i) want[i] = 0.5 * (x[n[k]][i] + x[n[(k + 1) % corners]][i]);
        } else {
          for (int c = 0; c < corners; ++c)
            for (int i = 0; i < 3; ++i) want[i] += x[n[c]][i] / corners;
        }
        for (int i = 0; i < 3; ++i) EXPECT_EQ(x[n[a]][i], want[i]) << "facet " << f << " node " << a;
      }
    }
  }
}

// The reflected order relabels the whole mirror image, mid-edge and centre nodes included:
// every node of the reordered image sits where the affine map of its corners puts the node
// of the parent cell (the parent cell and its mirror image are affine images of each other).
TEST(CellTypeTable, ReflectionRelabelsEveryNode) {
  for (const CellTypeInfo& row : kCellTypes) {
    SCOPED_TRACE(row.name);
    const auto x = parentNodes(row.type);
    std::vector<Point> image(x.size());
    for (int a = 0; a < row.numNodes; ++a) {
      const Point& p = x[row.reflected[a]];
      image[a] = {-p[0], p[1], p[2]};
    }
    // the affine map xi -> image from corner c0 and its edge neighbours c1 .. c_dim
    const int* c = row.corners[0];
    for (int a = 0; a < row.numNodes; ++a) {
      // xi_a - xi_c0 in the basis of the edges from c0 (they are orthogonal, or the unit simplex's axes)
      Point want = image[c[0]];
      for (int e = 1; e <= row.dim; ++e) {
        const Point edge = minus(x[c[e]], x[c[0]]);
        const Real t = dot(minus(x[a], x[c[0]]), edge) / dot(edge, edge);
        const Point imageEdge = minus(image[c[e]], image[c[0]]);
        for (int i = 0; i < 3; ++i) want[i] += t * imageEdge[i];
      }
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(image[a][i], want[i], 1e-14) << "node " << a;
    }
    // facets: the reflected order relabels the image of facet 0 as a facet element again
    const int* n = row.facets[0];
    const int corners = facetCornerCount(row);
    std::vector<Point> facetImage;
    for (int a = 0; a < row.nodesPerFacet; ++a) {
      const Point& p = x[n[row.reflectedFacet[a]]];
      facetImage.push_back({-p[0], p[1], p[2]});
    }
    for (int a = corners; a < row.nodesPerFacet; ++a) {
      Point want{0.0, 0.0, 0.0};
      const int k = a - corners;
      if (k < corners) {
        for (int i = 0; i < 3; ++i) want[i] = 0.5 * (facetImage[k][i] + facetImage[(k + 1) % corners][i]);
      } else {
        for (int b = 0; b < corners; ++b)
          for (int i = 0; i < 3; ++i) want[i] += facetImage[b][i] / corners;
      }
      for (int i = 0; i < 3; ++i) EXPECT_EQ(facetImage[a][i], want[i]) << "reflected facet node " << a;
    }
  }
}

TEST(CellTypeTable, GmshOrderIsAPermutation) {
  for (const CellTypeInfo& row : kCellTypes) {
    SCOPED_TRACE(row.name);
    std::set<int> from(row.fromGmsh, row.fromGmsh + row.numNodes), reflected(row.reflected, row.reflected + row.numNodes);
    EXPECT_EQ(int(from.size()), row.numNodes);
    EXPECT_EQ(int(reflected.size()), row.numNodes);
  }
}

TEST(SolidKernelDispatch, PicksTheKernelOfTheFormulationAndCell) {
  struct Seen {
    int numNodes, dim;
    bool axisymmetric;
  };
  auto seen = [](Formulation f, CellType t) {
    Seen s{-1, -1, false};
    const bool called = fem::withSolidKernel(f, t, [&](auto kernel) {
      using K = decltype(kernel);
      s = {K::numNodes, K::dim, K::axisymmetric};
    });
    EXPECT_EQ(called, s.numNodes > 0);
    return s;
  };
  EXPECT_EQ(seen(Formulation::PlaneStrain, CellType::Quad4).numNodes, 4);
  EXPECT_FALSE(seen(Formulation::PlaneStrain, CellType::Quad4).axisymmetric);
  EXPECT_TRUE(seen(Formulation::Axisymmetric, CellType::Quad4).axisymmetric);
  EXPECT_EQ(seen(Formulation::ThreeD, CellType::Hex8).numNodes, 8);
  EXPECT_EQ(seen(Formulation::ThreeD, CellType::Tet4).numNodes, 4);
  EXPECT_EQ(seen(Formulation::ThreeD, CellType::Tet4).dim, 3);
  // the pairs no kernel takes call nothing
  EXPECT_EQ(seen(Formulation::ThreeD, CellType::Quad4).numNodes, -1);
  EXPECT_EQ(seen(Formulation::PlaneStrain, CellType::Hex8).numNodes, -1);
  EXPECT_EQ(seen(Formulation::Axisymmetric, CellType::Tet4).numNodes, -1);
  EXPECT_EQ(seen(Formulation::PlaneStrain, CellType::Quad9).numNodes, 9);
  EXPECT_EQ(seen(Formulation::ThreeD, CellType::Hex27).numNodes, 27);
  EXPECT_EQ(seen(Formulation::ThreeD, CellType::Tet10).numNodes, 10);
  EXPECT_EQ(fem::cellTypesTakenBy(Formulation::PlaneStrain), "QUAD4, QUAD8, QUAD9");
  EXPECT_EQ(fem::cellTypesTakenBy(Formulation::ThreeD), "HEX8, TETRA4, TETRA10, HEX20, HEX27");
}
