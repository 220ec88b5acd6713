#pragma once
// Closest-point search from a point onto the discretised surface of a body
// (doc/theory.md#method-3): the closest point over all facets, including their edges and
// vertices (projection with clamping), so that the distance is continuous.
//
// The interface is dimension-neutral: the 2D/axisymmetric implementations
// work on segments (AabbTreeSearch2D through CGAL's AABB tree, the default;
// brute force for reference); a 3D implementation on triangles or
// quadrilaterals implements the same class.
#include <Kokkos_Macros.hpp>
#include <limits>
#include <memory>
#include <vector>

#include "cgcm/core/Types.hpp"
#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::interaction {

/// Result of a closest-point query.
struct Projection {
  LocalIndex facet = -1;    ///< facet index in the surface; -1 when none lies within the cutoff
  Real xi[2] = {0.0, 0.0};  ///< local coordinates of the projection (2D: xi[0] in [0,1] from node a to b)
  Real point[3] = {0.0, 0.0, 0.0};                        ///< the projection point x_P
  Real distance = std::numeric_limits<Real>::infinity();  ///< |x - x_P|
  bool found() const { return facet >= 0; }
};

class ClosestPointSearch {
 public:
  virtual ~ClosestPointSearch() = default;
  /// Spatial dimension of the points and facets.
  virtual int dim() const = 0;
  /// Builds the search structure over the facets of `surface`; `coords` holds
  /// dim() entries per node, indexed by the node indices of the facets. The facet coordinates are copied: rebuild after the nodes move.
  virtual void build(const Real* coords, const mesh::Surface& surface) = 0;
  void build(const std::vector<Real>& coords, const mesh::Surface& surface) { build(coords.data(), surface); }
  /// Number of facets of the last build.
  virtual LocalIndex numFacets() const = 0;
  /// Closest point to x (dim() components) over all facets at distance
  /// <= cutoff (infinity: no cutoff). Ties go to the lowest facet index.
  /// `hint` (optional) is a facet likely to be close, typically the previous
  /// projection's: it bounds the distance before the search starts. The
  /// result does not depend on it.
  virtual Projection project(const Real* x, Real cutoff, LocalIndex hint) const = 0;
  Projection project(const Real* x, Real cutoff) const { return project(x, cutoff, -1); }
  /// Appends to `out`, in facet order, exactly the facets within `radius`
  /// of the point x (to round-off).
  virtual void facetsNearPoint(const Real* x, Real radius, std::vector<LocalIndex>& out) const = 0;
};

/// Point-to-segment projection with clamping, shared by the search and the
/// interaction kernel so that both take the same branch. Returns the squared
/// distance; xi in [0,1] is the local coordinate of p on a->b; region is
/// 0 inside the segment, 1 at vertex a, 2 at vertex b.
KOKKOS_INLINE_FUNCTION Real projectOntoSegment(const Real x[2], const Real a[2], const Real b[2], Real& xi,
                                               Real p[2], int& region) {
  const Real d0 = b[0] - a[0], d1 = b[1] - a[1];
  const Real dd = d0 * d0 + d1 * d1;
  const Real lam = dd > 0.0 ? ((x[0] - a[0]) * d0 + (x[1] - a[1]) * d1) / dd : 0.0;
  if (!(lam > 0.0)) {
    xi = 0.0;
    p[0] = a[0];
    p[1] = a[1];
    region = 1;
  } else if (lam >= 1.0) {
    xi = 1.0;
    p[0] = b[0];
    p[1] = b[1];
    region = 2;
  } else {
    xi = lam;
    p[0] = a[0] + lam * d0;
    p[1] = a[1] + lam * d1;
    region = 0;
  }
  const Real g0 = x[0] - p[0], g1 = x[1] - p[1];
  return g0 * g0 + g1 * g1;
}

/// Point-to-triangle projection (Ericson, Real-Time Collision Detection
/// 5.1.5): the closest point of triangle abc to x by its Voronoi regions.
/// Returns the squared distance; xi = (s, t) with p = a + s (b - a) + t (c - a);
/// region 0 inside the face, 1..3 at vertex a, b, c, 4..6 on edge ab, bc, ca.
KOKKOS_INLINE_FUNCTION Real projectOntoTriangle(const Real x[3], const Real a[3], const Real b[3], const Real c[3],
                                                Real xi[2], Real p[3], int& region) {
  Real ab[3], ac[3], ap[3];
  for (int k = 0; k < 3; ++k) {
    ab[k] = b[k] - a[k];
    ac[k] = c[k] - a[k];
    ap[k] = x[k] - a[k];
  }
  auto dot = [](const Real* u, const Real* v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
  auto finish = [&](Real s, Real t, int r) {
    xi[0] = s;
    xi[1] = t;
    region = r;
    Real d2 = 0.0;
    for (int k = 0; k < 3; ++k) {
      p[k] = a[k] + s * ab[k] + t * ac[k];
      d2 += (x[k] - p[k]) * (x[k] - p[k]);
    }
    return d2;
  };
  const Real d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return finish(0.0, 0.0, 1);
  Real bp[3], cp[3];
  for (int k = 0; k < 3; ++k) {
    bp[k] = x[k] - b[k];
    cp[k] = x[k] - c[k];
  }
  const Real d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return finish(1.0, 0.0, 2);
  const Real vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return finish(d1 / (d1 - d3), 0.0, 4);
  const Real d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return finish(0.0, 1.0, 3);
  const Real vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return finish(0.0, d2 / (d2 - d6), 6);
  const Real va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    const Real w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return finish(1.0 - w, w, 5);
  }
  const Real denom = 1.0 / (va + vb + vc);
  return finish(vb * denom, vc * denom, 0);
}

/// Reference implementation: loops over all facets (tests, tiny surfaces);
/// Dim = 2 segments, Dim = 3 triangles.
template <int Dim>
class BruteForceSearch final : public ClosestPointSearch {
 public:
  int dim() const override { return Dim; }
  using ClosestPointSearch::build;
  void build(const Real* coords, const mesh::Surface& surface) override;
  LocalIndex numFacets() const override { return LocalIndex(vertices_.size() / kStride); }
  using ClosestPointSearch::project;
  Projection project(const Real* x, Real cutoff, LocalIndex hint) const override;
  void facetsNearPoint(const Real* x, Real radius, std::vector<LocalIndex>& out) const override;

 private:
  static constexpr std::size_t kStride = Dim == 2 ? 4 : 9;  ///< coordinates per facet
  std::vector<Real> vertices_;
};
using BruteForceSegmentSearch2D = BruteForceSearch<2>;
using BruteForceTriangleSearch3D = BruteForceSearch<3>;

/// Facets through CGAL's AABB tree: Dim = 2, segments (embedded in the plane
/// z = 0); Dim = 3, triangles. The closest primitive CGAL returns competes
/// with every facet through its closest point (those sharing the vertex or
/// edge it lies on) under the same projection arithmetic and tie rule as
/// brute force, so the result is brute force's (facet, point, local
/// coordinates), except at an exact tie between separate parts of the
/// surface, where CGAL's choice stands. The tree is rebuilt by build(): CGAL
/// has no refit.
template <int Dim>
class AabbTreeSearch final : public ClosestPointSearch {
 public:
  AabbTreeSearch();
  ~AabbTreeSearch() override;
  int dim() const override { return Dim; }
  using ClosestPointSearch::build;
  void build(const Real* coords, const mesh::Surface& surface) override;
  LocalIndex numFacets() const override { return LocalIndex(vertices_.size() / kStride); }
  using ClosestPointSearch::project;
  /// A hint within the cutoff replaces the box test and starts CGAL's
  /// traversal at the hint's distance, pruning every farther node.
  Projection project(const Real* x, Real cutoff, LocalIndex hint) const override;
  /// A traversal pruned by distance.
  void facetsNearPoint(const Real* x, Real radius, std::vector<LocalIndex>& out) const override;

 private:
  static constexpr std::size_t kStride = Dim == 2 ? 4 : 9;  ///< coordinates per facet
  struct Tree;
  std::unique_ptr<Tree> tree_;
  std::vector<Real> vertices_;  ///< the facets' vertex coordinates, kStride per facet
};
using AabbTreeSearch2D = AabbTreeSearch<2>;
using AabbTreeSearch3D = AabbTreeSearch<3>;

/// Choice of search structure.
enum class SearchMethod {
  Tree,       ///< CGAL's AABB tree (default)
  BruteForce  ///< every facet (reference)
};

/// The search for a spatial dimension: 2 -> AabbTreeSearch2D (Tree) or
/// BruteForceSegmentSearch2D; 3 -> AabbTreeSearch3D or
/// BruteForceTriangleSearch3D (triangles). Throws InputError for other values.
std::unique_ptr<ClosestPointSearch> makeClosestPointSearch(int dim, SearchMethod method = SearchMethod::Tree);

}  // namespace cgcm::interaction
