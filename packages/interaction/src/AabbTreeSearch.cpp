// Closest point on 2D segments and 3D triangles through CGAL's AABB tree (ClosestPointSearch.hpp).
#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <iterator>

#include "SearchDetail.hpp"
#include "cgcm/interaction/ClosestPointSearch.hpp"

namespace cgcm::interaction {

namespace {

using Kernel = CGAL::Simple_cartesian<double>;
using Point3 = Kernel::Point_3;

// CGAL's tree over the facets of one surface: Datum is Segment_3 (Dim = 2,
// the points in the plane z = 0) or Triangle_3 (Dim = 3), kept in facet
// order so that a primitive's position is its facet index.
template <class Datum, template <class...> class PrimitiveOf, int Dim>
struct FacetTree {
  using Iterator = typename std::vector<Datum>::const_iterator;
  using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, PrimitiveOf<Kernel, Iterator>>>;

  std::vector<Datum> facets;
  Tree tree;

  static Point3 point(const Real* x) { return Point3(x[0], x[1], Dim == 3 ? x[2] : 0.0); }
  static CGAL::Bbox_3 box(const Real* lo, const Real* hi, Real r) {
    return CGAL::Bbox_3(lo[0] - r, lo[1] - r, (Dim == 3 ? lo[2] : 0.0) - r, hi[0] + r, hi[1] + r,
                        (Dim == 3 ? hi[2] : 0.0) + r);
  }

  // CGAL has no refit: a moved surface is a new tree.
  void build() {
    if (facets.empty()) return;
    tree.insert(facets.cbegin(), facets.cend());
    tree.build();
    tree.accelerate_distance_queries();
  }

  // Facets whose geometry meets the box [lo - r, hi + r], appended unsorted.
  void intersecting(const Real* lo, const Real* hi, Real r, std::vector<LocalIndex>& out) const {
    std::vector<Iterator> hits;
    tree.all_intersected_primitives(box(lo, hi, r), std::back_inserter(hits));
    for (const auto& it : hits) out.push_back(LocalIndex(it - facets.cbegin()));
  }

  // The facets that can hold the closest point to x within the cutoff: every
  // facet as close as the one CGAL finds, to round-off (the caller decides
  // among them with the common projection arithmetic and tie rule). False if
  // none lies within the cutoff.
  bool candidates(const Real* x, Real cutoff, std::vector<LocalIndex>& out) const {
    if (facets.empty()) return false;
    // Nothing within the cutoff: one box test instead of a distance query.
    if (std::isfinite(cutoff) && !tree.do_intersect(box(x, x, cutoff))) return false;
    const Real d = std::sqrt(tree.squared_distance(point(x)));
    if (d > cutoff * (1.0 + 1e-12)) return false;
    intersecting(x, x, d * (1.0 + 1e-9) + 1e-300, out);
    return true;
  }

  void facetsNear(const Real* lo, const Real* hi, Real radius, std::vector<LocalIndex>& out) const {
    if (facets.empty()) return;
    const std::size_t first = out.size();
    intersecting(lo, hi, radius, out);
    std::sort(out.begin() + first, out.end());
    out.erase(std::unique(out.begin() + first, out.end()), out.end());
  }
};

using SegmentTree = FacetTree<Kernel::Segment_3, CGAL::AABB_segment_primitive, 2>;
using TriangleTree = FacetTree<Kernel::Triangle_3, CGAL::AABB_triangle_primitive, 3>;

}  // namespace

// ---------------------------------------------------------------------------
// AabbTreeSearch2D

struct AabbTreeSearch2D::Tree : SegmentTree {};

AabbTreeSearch2D::AabbTreeSearch2D() : tree_(std::make_unique<Tree>()) {}
AabbTreeSearch2D::~AabbTreeSearch2D() = default;

void AabbTreeSearch2D::build(const Real* coords, const mesh::Surface& surface) {
  detail::copySegments(coords, surface, seg_);
  auto t = std::make_unique<Tree>();
  t->facets.reserve(numFacets());
  for (LocalIndex e = 0; e < numFacets(); ++e) {
    const Real* s = &seg_[4 * std::size_t(e)];
    t->facets.emplace_back(Point3(s[0], s[1], 0.0), Point3(s[2], s[3], 0.0));
  }
  t->build();
  tree_ = std::move(t);
}

Projection AabbTreeSearch2D::project(const Real* x, Real cutoff) const {
  std::vector<LocalIndex> candidates;
  if (!tree_->candidates(x, cutoff, candidates)) return {};
  detail::Best best;
  for (LocalIndex e : candidates) best.consider(&seg_[4 * std::size_t(e)], e, x, cutoff * cutoff);
  return best.result();
}

void AabbTreeSearch2D::facetsNear(const Real* lo, const Real* hi, Real radius, std::vector<LocalIndex>& out) const {
  tree_->facetsNear(lo, hi, radius, out);
}

// ---------------------------------------------------------------------------
// AabbTreeSearch3D

struct AabbTreeSearch3D::Tree : TriangleTree {};

AabbTreeSearch3D::AabbTreeSearch3D() : tree_(std::make_unique<Tree>()) {}
AabbTreeSearch3D::~AabbTreeSearch3D() = default;

void AabbTreeSearch3D::build(const Real* coords, const mesh::Surface& surface) {
  detail::copyTriangles(coords, surface, tri_);
  auto t = std::make_unique<Tree>();
  t->facets.reserve(numFacets());
  for (LocalIndex e = 0; e < numFacets(); ++e) {
    const Real* v = &tri_[9 * std::size_t(e)];
    t->facets.emplace_back(Point3(v[0], v[1], v[2]), Point3(v[3], v[4], v[5]), Point3(v[6], v[7], v[8]));
  }
  t->build();
  tree_ = std::move(t);
}

Projection AabbTreeSearch3D::project(const Real* x, Real cutoff) const {
  std::vector<LocalIndex> candidates;
  if (!tree_->candidates(x, cutoff, candidates)) return {};
  detail::BestTriangle best;
  for (LocalIndex e : candidates) best.consider(&tri_[9 * std::size_t(e)], e, x, cutoff * cutoff);
  return best.result();
}

void AabbTreeSearch3D::facetsNear(const Real* lo, const Real* hi, Real radius, std::vector<LocalIndex>& out) const {
  tree_->facetsNear(lo, hi, radius, out);
}

}  // namespace cgcm::interaction
