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
  // Scratch of the queries (one per quadrature point and Newton iteration):
  // kept so that a query allocates nothing once they have grown.
  mutable std::vector<Iterator> hits;
  mutable std::vector<LocalIndex> candidateScratch;

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
    hits.clear();
    tree.all_intersected_primitives(box(lo, hi, r), std::back_inserter(hits));
    for (const auto& it : hits) out.push_back(LocalIndex(it - facets.cbegin()));
  }

  // The facets that can hold the closest point to x within the cutoff: the
  // one CGAL finds and every facet through its closest point p (to
  // round-off), i.e. those sharing the vertex or edge p lies on, which are
  // as close; the caller decides among them with the common projection
  // arithmetic and tie rule. (Facets equally close at other points, an exact
  // tie between separate parts of the surface, are not searched for: CGAL's
  // choice stands.) False if none lies within the cutoff.
  // `hint`: a facet index and its closest point to x, within the cutoff, or -1.
  bool candidates(const Real* x, Real cutoff, LocalIndex hint, const Real* hintPoint,
                  std::vector<LocalIndex>& out) const {
    if (facets.empty()) return false;
    // Nothing within the cutoff: one box test instead of a distance query.
    if (hint < 0 && std::isfinite(cutoff) && !tree.do_intersect(box(x, x, cutoff))) return false;
    const auto [closest, primitive] =
        hint < 0 ? tree.closest_point_and_primitive(point(x))
                 : tree.closest_point_and_primitive(point(x), {point(hintPoint), facets.cbegin() + hint});
    const Real p[3] = {closest.x(), closest.y(), closest.z()};
    const Real d2 = CGAL::squared_distance(point(x), closest);
    if (d2 > cutoff * cutoff * (1.0 + 1e-12)) return false;
    out.push_back(LocalIndex(primitive - facets.cbegin()));
    const Real scale = std::sqrt(d2) + std::abs(p[0]) + std::abs(p[1]) + std::abs(p[2]);
    intersecting(p, p, 1e-12 * scale + 1e-300, out);
    return true;
  }

  // Facets within the radius of x (widened by round-off), in facet order: a
  // traversal that prunes every node whose box lies farther.
  void facetsNearPoint(const Real* x, Real radius, std::vector<LocalIndex>& out) const {
    if (facets.empty()) return;
    const Real r = radius * (1.0 + 1e-12) + 1e-300;
    BallCollector collect{point(x), r * r, &out, &facets};
    const std::size_t first = out.size();
    tree.traversal(collect.centre, collect);
    std::sort(out.begin() + first, out.end());
  }

  // CGAL traversal traits: the facets within sqrt(r2) of the centre.
  struct BallCollector {
    Point3 centre;
    Real r2;
    std::vector<LocalIndex>* out;
    const std::vector<Datum>* all;
    bool go_further() const { return true; }
    template <class Primitive>
    void intersection(const Point3&, const Primitive& primitive) {
      if (CGAL::squared_distance(centre, primitive.datum()) <= r2)
        out->push_back(LocalIndex(primitive.id() - all->cbegin()));
    }
    template <class Node>
    bool do_intersect(const Point3&, const Node& node) const {
      const CGAL::Bbox_3& b = node.bbox();
      Real d2 = 0.0;
      for (int k = 0; k < 3; ++k) {
        const Real v = std::max({b.min(k) - centre[k], 0.0, centre[k] - b.max(k)});
        d2 += v * v;
      }
      return d2 <= r2;
    }
  };
};

// The CGAL tree and datum of a facet, per dimension.
template <int Dim>
struct CgalFacets;
template <>
struct CgalFacets<2> {
  using Tree = FacetTree<Kernel::Segment_3, CGAL::AABB_segment_primitive, 2>;
  static Kernel::Segment_3 datum(const Real* v) { return {Point3(v[0], v[1], 0.0), Point3(v[2], v[3], 0.0)}; }
};
template <>
struct CgalFacets<3> {
  using Tree = FacetTree<Kernel::Triangle_3, CGAL::AABB_triangle_primitive, 3>;
  static Kernel::Triangle_3 datum(const Real* v) {
    return {Point3(v[0], v[1], v[2]), Point3(v[3], v[4], v[5]), Point3(v[6], v[7], v[8])};
  }
};

}  // namespace

template <int Dim>
struct AabbTreeSearch<Dim>::Tree : CgalFacets<Dim>::Tree {};

template <int Dim>
AabbTreeSearch<Dim>::AabbTreeSearch() : tree_(std::make_unique<Tree>()) {}
template <int Dim>
AabbTreeSearch<Dim>::~AabbTreeSearch() = default;

template <int Dim>
void AabbTreeSearch<Dim>::build(const Real* coords, const mesh::Surface& surface) {
  detail::Facets<Dim>::copy(coords, surface, vertices_);
  auto t = std::make_unique<Tree>();
  t->facets.reserve(numFacets());
  for (LocalIndex e = 0; e < numFacets(); ++e) t->facets.push_back(CgalFacets<Dim>::datum(&vertices_[kStride * e]));
  t->build();
  tree_ = std::move(t);
}

template <int Dim>
Projection AabbTreeSearch<Dim>::project(const Real* x, Real cutoff, LocalIndex hint) const {
  std::vector<LocalIndex>& candidates = tree_->candidateScratch;
  candidates.clear();
  Real hintPoint[3] = {0.0, 0.0, 0.0};
  if (hint >= 0 && hint < numFacets()) {
    typename detail::Facets<Dim>::Best h;
    h.consider(&vertices_[kStride * hint], hint, x, cutoff * cutoff);
    if (h.facet < 0) hint = -1;  // beyond the cutoff: no bound to start from
    for (int k = 0; k < Dim; ++k) hintPoint[k] = h.p[k];
  } else {
    hint = -1;
  }
  if (!tree_->candidates(x, cutoff, hint, hintPoint, candidates)) return {};
  typename detail::Facets<Dim>::Best best;
  for (LocalIndex e : candidates) best.consider(&vertices_[kStride * e], e, x, cutoff * cutoff);
  return best.result();
}

template <int Dim>
void AabbTreeSearch<Dim>::facetsNearPoint(const Real* x, Real radius, std::vector<LocalIndex>& out) const {
  tree_->facetsNearPoint(x, radius, out);
}

template class AabbTreeSearch<2>;
template class AabbTreeSearch<3>;

}  // namespace cgcm::interaction
