#pragma once
// Helpers shared by the closest-point searches (internal to the package):
// the segments (2D) and triangles (3D) of a surface, the running best
// projection with the tie rule of ClosestPointSearch, bounding boxes.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "cgcm/core/Error.hpp"
#include "cgcm/interaction/ClosestPointSearch.hpp"

namespace cgcm::interaction::detail {

inline void copySegments(const Real* coords, const mesh::Surface& surface, std::vector<Real>& seg) {
  if (surface.nodesPerFacet != 2)
    throw InputError("2D closest-point search: surface facets must be segments (2 nodes), got " +
                     std::to_string(surface.nodesPerFacet) + " nodes per facet");
  const LocalIndex n = surface.numFacets();
  seg.resize(std::size_t(4) * n);
  for (LocalIndex e = 0; e < n; ++e) {
    const LocalIndex a = surface.facets[2 * e], b = surface.facets[2 * e + 1];
    seg[4 * e + 0] = coords[2 * std::size_t(a)];
    seg[4 * e + 1] = coords[2 * std::size_t(a) + 1];
    seg[4 * e + 2] = coords[2 * std::size_t(b)];
    seg[4 * e + 3] = coords[2 * std::size_t(b) + 1];
  }
}

// Keeps the lexicographically smallest (squared distance, facet index).
struct Best {
  Real d2 = std::numeric_limits<Real>::infinity();
  LocalIndex facet = -1;
  Real xi = 0.0;
  Real p[2] = {0.0, 0.0};

  // s: the segment's ax, ay, bx, by; e: its facet id
  void consider(const Real* s, LocalIndex e, const Real* x, Real limit2) {
    Real xi_, p_[2];
    int region;
    const Real d2_ = projectOntoSegment(x, s, s + 2, xi_, p_, region);
    if (d2_ > limit2) return;
    if (d2_ < d2 || (d2_ == d2 && e < facet)) {
      d2 = d2_;
      facet = e;
      xi = xi_;
      p[0] = p_[0];
      p[1] = p_[1];
    }
  }

  Projection result() const {
    Projection pr;
    if (facet < 0) return pr;
    pr.facet = facet;
    pr.xi[0] = xi;
    pr.point[0] = p[0];
    pr.point[1] = p[1];
    pr.distance = std::sqrt(d2);
    return pr;
  }
};

inline void copyTriangles(const Real* coords, const mesh::Surface& surface, std::vector<Real>& tri) {
  if (surface.nodesPerFacet != 3)
    throw InputError("3D closest-point search: surface facets must be triangles (3 nodes), got " +
                     std::to_string(surface.nodesPerFacet) + " nodes per facet");
  const LocalIndex n = surface.numFacets();
  tri.resize(std::size_t(9) * n);
  for (LocalIndex e = 0; e < n; ++e)
    for (int v = 0; v < 3; ++v)
      for (int k = 0; k < 3; ++k) tri[9 * std::size_t(e) + 3 * v + k] = coords[3 * std::size_t(surface.facets[3 * e + v]) + k];
}

// Keeps the lexicographically smallest (squared distance, facet index) over triangles.
struct BestTriangle {
  Real d2 = std::numeric_limits<Real>::infinity();
  LocalIndex facet = -1;
  Real xi[2] = {0.0, 0.0};
  Real p[3] = {0.0, 0.0, 0.0};

  // t: the triangle's a, b, c; e: its facet id
  void consider(const Real* t, LocalIndex e, const Real* x, Real limit2) {
    Real xi_[2], p_[3];
    int region;
    const Real d2_ = projectOntoTriangle(x, t, t + 3, t + 6, xi_, p_, region);
    if (d2_ > limit2) return;
    if (d2_ < d2 || (d2_ == d2 && e < facet)) {
      d2 = d2_;
      facet = e;
      xi[0] = xi_[0];
      xi[1] = xi_[1];
      for (int k = 0; k < 3; ++k) p[k] = p_[k];
    }
  }

  Projection result() const {
    Projection pr;
    if (facet < 0) return pr;
    pr.facet = facet;
    pr.xi[0] = xi[0];
    pr.xi[1] = xi[1];
    for (int k = 0; k < 3; ++k) pr.point[k] = p[k];
    pr.distance = std::sqrt(d2);
    return pr;
  }
};

// What differs between the dimensions of the searches: how the facets'
// coordinates are copied and the projection that decides.
template <int Dim>
struct Facets;
template <>
struct Facets<2> {
  using Best = detail::Best;
  static void copy(const Real* coords, const mesh::Surface& s, std::vector<Real>& v) { copySegments(coords, s, v); }
};
template <>
struct Facets<3> {
  using Best = BestTriangle;
  static void copy(const Real* coords, const mesh::Surface& s, std::vector<Real>& v) { copyTriangles(coords, s, v); }
};

}  // namespace cgcm::interaction::detail
