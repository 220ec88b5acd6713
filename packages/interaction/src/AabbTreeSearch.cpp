// Closest point on 2D segments through CGAL's AABB tree (ClosestPointSearch.hpp).
#include <CGAL/AABB_segment_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Simple_cartesian.h>

#include <iterator>

#include "SegmentSearchDetail.hpp"
#include "cgcm/interaction/ClosestPointSearch.hpp"

namespace cgcm::interaction {

namespace {
using Kernel = CGAL::Simple_cartesian<double>;
using Point3 = Kernel::Point_3;
using Segment3 = Kernel::Segment_3;
using SegmentIterator = std::vector<Segment3>::const_iterator;
using Primitive = CGAL::AABB_segment_primitive<Kernel, SegmentIterator>;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
}  // namespace

struct AabbTreeSearch2D::Tree {
  std::vector<Segment3> segments;  ///< the facets in the plane z = 0, in facet order
  AabbTree tree;
  LocalIndex facetOf(SegmentIterator it) const { return LocalIndex(it - segments.cbegin()); }
  // Facets whose segment meets the box [lo - r, hi + r] (z in [-r, r]), appended unsorted.
  void intersecting(const Real* lo, const Real* hi, Real r, std::vector<LocalIndex>& out) const {
    const CGAL::Bbox_3 box(lo[0] - r, lo[1] - r, -r, hi[0] + r, hi[1] + r, r);
    std::vector<SegmentIterator> hits;
    tree.all_intersected_primitives(box, std::back_inserter(hits));
    for (const auto& it : hits) out.push_back(facetOf(it));
  }
};

AabbTreeSearch2D::AabbTreeSearch2D() : tree_(std::make_unique<Tree>()) {}
AabbTreeSearch2D::~AabbTreeSearch2D() = default;

void AabbTreeSearch2D::build(const Real* coords, const mesh::Surface& surface) {
  detail::copySegments(coords, surface, seg_);
  // CGAL has no refit: a moved surface is a new tree.
  auto t = std::make_unique<Tree>();
  const LocalIndex n = numFacets();
  t->segments.reserve(n);
  for (LocalIndex e = 0; e < n; ++e) {
    const Real* s = &seg_[4 * std::size_t(e)];
    t->segments.emplace_back(Point3(s[0], s[1], 0.0), Point3(s[2], s[3], 0.0));
  }
  if (n > 0) {
    t->tree.insert(t->segments.cbegin(), t->segments.cend());
    t->tree.build();
    t->tree.accelerate_distance_queries();
  }
  tree_ = std::move(t);
}

Projection AabbTreeSearch2D::project(const Real* x, Real cutoff) const {
  if (numFacets() == 0) return {};
  if (std::isfinite(cutoff)) {
    // Nothing within the cutoff: one box test instead of a distance query.
    const CGAL::Bbox_3 box(x[0] - cutoff, x[1] - cutoff, -cutoff, x[0] + cutoff, x[1] + cutoff, cutoff);
    if (!tree_->tree.do_intersect(box)) return {};
  }
  const Point3 q(x[0], x[1], 0.0);
  const Real d = std::sqrt(tree_->tree.squared_distance(q));
  if (d > cutoff * (1.0 + 1e-12)) return {};
  // Every facet as close as CGAL's (to round-off) competes under the common
  // arithmetic and tie rule.
  std::vector<LocalIndex> candidates;
  const Real r = d * (1.0 + 1e-9) + 1e-300;
  tree_->intersecting(x, x, r, candidates);
  detail::Best best;
  const Real limit2 = cutoff * cutoff;
  for (LocalIndex e : candidates) best.consider(&seg_[4 * std::size_t(e)], e, x, limit2);
  return best.result();
}

void AabbTreeSearch2D::facetsNear(const Real* lo, const Real* hi, Real radius, std::vector<LocalIndex>& out) const {
  if (numFacets() == 0) return;
  const std::size_t first = out.size();
  tree_->intersecting(lo, hi, radius, out);
  std::sort(out.begin() + first, out.end());
  out.erase(std::unique(out.begin() + first, out.end()), out.end());
}

}  // namespace cgcm::interaction
