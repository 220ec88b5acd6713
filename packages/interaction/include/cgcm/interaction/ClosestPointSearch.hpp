#pragma once
// Closest-point search from a point onto the discretised surface of a body
// (THEORY §2): the closest point over all facets, including their edges and
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
  /// dim() entries per node, indexed by the global node numbers of the
  /// facets. The facet coordinates are copied: rebuild after the nodes move.
  virtual void build(const Real* coords, const mesh::Surface& surface) = 0;
  void build(const std::vector<Real>& coords, const mesh::Surface& surface) { build(coords.data(), surface); }
  /// Number of facets of the last build.
  virtual LocalIndex numFacets() const = 0;
  /// Closest point to x (dim() components) over all facets at distance
  /// <= cutoff (infinity: no cutoff). Ties go to the lowest facet index.
  virtual Projection project(const Real* x, Real cutoff) const = 0;
  /// Appends to `out` (sorted, unique) every facet whose bounding box
  /// overlaps the box [lo - radius, hi + radius]: a superset of the facets
  /// within `radius` of any point of the box [lo, hi].
  virtual void facetsNear(const Real* lo, const Real* hi, Real radius,
                          std::vector<LocalIndex>& out) const = 0;
  /// Appends to `out` every facet within `radius` of the point x, and
  /// possibly a few farther ones (the default: facetsNear of the box [x, x]).
  virtual void facetsNearPoint(const Real* x, Real radius, std::vector<LocalIndex>& out) const {
    facetsNear(x, x, radius, out);
  }
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

/// Reference implementation: loops over all segments (tests, tiny surfaces).
class BruteForceSegmentSearch2D final : public ClosestPointSearch {
 public:
  int dim() const override { return 2; }
  using ClosestPointSearch::build;
  void build(const Real* coords, const mesh::Surface& surface) override;
  LocalIndex numFacets() const override { return LocalIndex(seg_.size() / 4); }
  Projection project(const Real* x, Real cutoff) const override;
  void facetsNear(const Real* lo, const Real* hi, Real radius, std::vector<LocalIndex>& out) const override;

 private:
  std::vector<Real> seg_;
};

/// 2D segments through CGAL's AABB tree (the segments embedded in the plane
/// z = 0, CGAL::AABB_tree with its kd-tree for distance queries). The
/// closest primitive CGAL returns is confirmed among every facet whose
/// geometry meets the box of that distance around the point, with the same
/// projection arithmetic and tie rule as the other implementations, so all
/// of them return the same projection. facetsNear lists the facets whose
/// segment meets the widened box (a subset of the bounding-box overlaps,
/// still a superset of the facets within the radius).
class AabbTreeSearch2D final : public ClosestPointSearch {
 public:
  AabbTreeSearch2D();
  ~AabbTreeSearch2D() override;
  int dim() const override { return 2; }
  using ClosestPointSearch::build;
  void build(const Real* coords, const mesh::Surface& surface) override;
  LocalIndex numFacets() const override { return LocalIndex(seg_.size() / 4); }
  Projection project(const Real* x, Real cutoff) const override;
  void facetsNear(const Real* lo, const Real* hi, Real radius, std::vector<LocalIndex>& out) const override;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
  std::vector<Real> seg_;  ///< ax, ay, bx, by per segment
};

/// Choice of search structure.
enum class SearchMethod {
  Tree,       ///< CGAL's AABB tree (default)
  BruteForce  ///< every facet (reference)
};

/// The search for a spatial dimension: 2 -> AabbTreeSearch2D (Tree) or
/// BruteForceSegmentSearch2D. Throws InputError for 3 (not available yet)
/// and other values.
std::unique_ptr<ClosestPointSearch> makeClosestPointSearch(int dim, SearchMethod method = SearchMethod::Tree);

}  // namespace cgcm::interaction
