#include "cgcm/interaction/ClosestPointSearch.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "cgcm/core/Error.hpp"

namespace cgcm::interaction {

namespace {

void copySegments(const Real* coords, const mesh::Surface& surface, std::vector<Real>& seg) {
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

void segmentBox(const Real* s, Real lo[2], Real hi[2]) {
  lo[0] = std::min(s[0], s[2]);
  hi[0] = std::max(s[0], s[2]);
  lo[1] = std::min(s[1], s[3]);
  hi[1] = std::max(s[1], s[3]);
}

bool boxesOverlap(const Real alo[2], const Real ahi[2], const Real blo[2], const Real bhi[2]) {
  return alo[0] <= bhi[0] && blo[0] <= ahi[0] && alo[1] <= bhi[1] && blo[1] <= ahi[1];
}

}  // namespace

// ---------------------------------------------------------------------------
// SegmentSearch2D

void SegmentSearch2D::build(const Real* coords, const mesh::Surface& surface) {
  copySegments(coords, surface, seg_);
  const LocalIndex n = numFacets();
  cellStart_.clear();
  cellItems_.clear();
  if (n == 0) {
    nx_ = ny_ = 0;
    return;
  }
  lo_[0] = lo_[1] = std::numeric_limits<Real>::infinity();
  hi_[0] = hi_[1] = -std::numeric_limits<Real>::infinity();
  Real totalLength = 0.0;
  for (LocalIndex e = 0; e < n; ++e) {
    const Real* s = &seg_[4 * e];
    for (int k = 0; k < 2; ++k) {
      lo_[k] = std::min({lo_[k], s[k], s[2 + k]});
      hi_[k] = std::max({hi_[k], s[k], s[2 + k]});
    }
    totalLength += std::hypot(s[2] - s[0], s[3] - s[1]);
  }
  for (int k = 0; k < 2; ++k)
    if (!std::isfinite(lo_[k]) || !std::isfinite(hi_[k]))
      throw NumericalError("2D closest-point search: non-finite surface coordinates");

  // Bin size: the mean segment length, enlarged until there are at most
  // about 4 bins per segment (a closed curve would otherwise need ~N^2 bins).
  const Real ex = hi_[0] - lo_[0], ey = hi_[1] - lo_[1];
  h_ = totalLength / n;
  if (!(h_ > 0.0)) h_ = std::max({ex, ey, Real(1.0)});
  const double maxBins = 4.0 * n + 64.0;
  for (;;) {
    const double bx = std::max(1.0, std::ceil(ex / h_)), by = std::max(1.0, std::ceil(ey / h_));
    if (bx * by <= maxBins) {
      nx_ = int(bx);
      ny_ = int(by);
      break;
    }
    h_ *= 1.5;
  }

  // CSR bins: a segment goes into every bin its bounding box overlaps.
  const std::size_t nb = std::size_t(nx_) * ny_;
  std::vector<LocalIndex> count(nb + 1, 0);
  auto forBins = [&](LocalIndex e, auto&& fn) {
    Real blo[2], bhi[2];
    segmentBox(&seg_[4 * e], blo, bhi);
    int i0, j0, i1, j1;
    cellOf(blo[0], blo[1], i0, j0);
    cellOf(bhi[0], bhi[1], i1, j1);
    for (int j = j0; j <= j1; ++j)
      for (int i = i0; i <= i1; ++i) fn(std::size_t(j) * nx_ + i);
  };
  for (LocalIndex e = 0; e < n; ++e) forBins(e, [&](std::size_t c) { ++count[c + 1]; });
  cellStart_.assign(nb + 1, 0);
  for (std::size_t c = 0; c < nb; ++c) cellStart_[c + 1] = cellStart_[c] + count[c + 1];
  cellItems_.resize(cellStart_[nb]);
  std::vector<LocalIndex> fill(cellStart_.begin(), cellStart_.end() - 1);
  for (LocalIndex e = 0; e < n; ++e) forBins(e, [&](std::size_t c) { cellItems_[fill[c]++] = e; });
}

void SegmentSearch2D::cellOf(Real x, Real y, int& i, int& j) const {
  const Real fx = std::floor((x - lo_[0]) / h_), fy = std::floor((y - lo_[1]) / h_);
  i = int(std::clamp(fx, Real(0), Real(nx_ - 1)));
  j = int(std::clamp(fy, Real(0), Real(ny_ - 1)));
}

Projection SegmentSearch2D::project(const Real* x, Real cutoff) const {
  Best best;
  if (numFacets() == 0) return best.result();
  // Distance from x to the grid box (0 inside); the clamped point p lies in
  // the box and |x - y| >= |p - y| for every y in the box.
  const Real p0 = std::clamp(x[0], lo_[0], hi_[0]), p1 = std::clamp(x[1], lo_[1], hi_[1]);
  const Real distBox = std::hypot(x[0] - p0, x[1] - p1);
  if (distBox > cutoff) return best.result();
  const Real limit2 = cutoff * cutoff;
  int ci, cj;
  cellOf(p0, p1, ci, cj);
  const int maxRing = std::max({ci, nx_ - 1 - ci, cj, ny_ - 1 - cj});
  auto visitCell = [&](int i, int j) {
    const std::size_t c = std::size_t(j) * nx_ + i;
    for (LocalIndex k = cellStart_[c]; k < cellStart_[c + 1]; ++k)
      best.consider(&seg_[4 * std::size_t(cellItems_[k])], cellItems_[k], x, limit2);
  };
  for (int ring = 0; ring <= maxRing; ++ring) {
    // Every bin of this ring is at least (ring - 1) bins away from p's bin,
    // and |x - y|^2 >= |x - p|^2 + |p - y|^2 for y in the box.
    const Real gap = std::max(ring - 1, 0) * h_;
    const Real lower2 = distBox * distBox + gap * gap;
    const Real bound = std::min(std::sqrt(best.d2), cutoff);
    if (lower2 > bound * bound) break;
    if (ring == 0) {
      visitCell(ci, cj);
      continue;
    }
    // the ring's rows (j = cj -+ ring) and columns (i = ci -+ ring), clipped to the grid
    const int i0 = std::max(ci - ring, 0), i1 = std::min(ci + ring, nx_ - 1);
    const int j0 = std::max(cj - ring + 1, 0), j1 = std::min(cj + ring - 1, ny_ - 1);
    if (cj - ring >= 0)
      for (int i = i0; i <= i1; ++i) visitCell(i, cj - ring);
    if (cj + ring < ny_)
      for (int i = i0; i <= i1; ++i) visitCell(i, cj + ring);
    if (ci - ring >= 0)
      for (int j = j0; j <= j1; ++j) visitCell(ci - ring, j);
    if (ci + ring < nx_)
      for (int j = j0; j <= j1; ++j) visitCell(ci + ring, j);
  }
  return best.result();
}

void SegmentSearch2D::facetsNear(const Real* lo, const Real* hi, Real radius,
                                 std::vector<LocalIndex>& out) const {
  if (numFacets() == 0) return;
  const Real qlo[2] = {lo[0] - radius, lo[1] - radius}, qhi[2] = {hi[0] + radius, hi[1] + radius};
  if (!boxesOverlap(qlo, qhi, lo_, hi_)) return;
  int i0, j0, i1, j1;
  cellOf(qlo[0], qlo[1], i0, j0);
  cellOf(qhi[0], qhi[1], i1, j1);
  const std::size_t start = out.size();
  for (int j = j0; j <= j1; ++j)
    for (int i = i0; i <= i1; ++i) {
      const std::size_t c = std::size_t(j) * nx_ + i;
      for (LocalIndex k = cellStart_[c]; k < cellStart_[c + 1]; ++k) {
        const LocalIndex e = cellItems_[k];
        Real blo[2], bhi[2];
        segmentBox(&seg_[4 * e], blo, bhi);
        if (boxesOverlap(qlo, qhi, blo, bhi)) out.push_back(e);
      }
    }
  std::sort(out.begin() + start, out.end());
  out.erase(std::unique(out.begin() + start, out.end()), out.end());
}

// ---------------------------------------------------------------------------
// SegmentTreeSearch2D

namespace {
constexpr int kLeafSize = 4;

Real boxDistance2(const Real* x, const Real lo[2], const Real hi[2]) {
  Real d2 = 0.0;
  for (int k = 0; k < 2; ++k) {
    const Real d = x[k] < lo[k] ? lo[k] - x[k] : (x[k] > hi[k] ? x[k] - hi[k] : 0.0);
    d2 += d * d;
  }
  return d2;
}
}  // namespace

void SegmentTreeSearch2D::build(const Real* coords, const mesh::Surface& surface) {
  std::vector<Real> seg;
  copySegments(coords, surface, seg);
  const LocalIndex n = LocalIndex(seg.size() / 4);
  ids_.resize(n);
  std::vector<Real> centroids(2 * std::size_t(n));
  for (LocalIndex e = 0; e < n; ++e) {
    ids_[e] = e;
    centroids[2 * e] = 0.5 * (seg[4 * e] + seg[4 * e + 2]);
    centroids[2 * e + 1] = 0.5 * (seg[4 * e + 1] + seg[4 * e + 3]);
    for (int k = 0; k < 4; ++k)
      if (!std::isfinite(seg[4 * e + k]))
        throw NumericalError("2D closest-point search: non-finite surface coordinates");
  }
  nodes_.clear();
  nodes_.reserve(std::size_t(2 * (n / kLeafSize + 1)));
  if (n > 0) {
    // nodes store boxes of their segments; seg_ is filled in leaf order
    seg_.swap(seg);
    buildNode(0, n, centroids, 0);
    std::vector<Real> ordered(seg_.size());
    for (LocalIndex k = 0; k < n; ++k)
      for (int c = 0; c < 4; ++c) ordered[4 * k + c] = seg_[4 * std::size_t(ids_[k]) + c];
    seg_.swap(ordered);
  } else {
    seg_.clear();
  }
}

int SegmentTreeSearch2D::buildNode(int begin, int end, std::vector<Real>& centroids, int depth) {
  // seg_ is still in facet order here; ids_[begin, end) are the node's facets
  const int index = int(nodes_.size());
  nodes_.emplace_back();
  Node node;
  node.lo[0] = node.lo[1] = std::numeric_limits<Real>::infinity();
  node.hi[0] = node.hi[1] = -std::numeric_limits<Real>::infinity();
  Real clo[2] = {node.lo[0], node.lo[1]}, chi[2] = {node.hi[0], node.hi[1]};
  for (int k = begin; k < end; ++k) {
    const Real* s = &seg_[4 * std::size_t(ids_[k])];
    for (int c = 0; c < 2; ++c) {
      node.lo[c] = std::min({node.lo[c], s[c], s[2 + c]});
      node.hi[c] = std::max({node.hi[c], s[c], s[2 + c]});
      clo[c] = std::min(clo[c], centroids[2 * std::size_t(ids_[k]) + c]);
      chi[c] = std::max(chi[c], centroids[2 * std::size_t(ids_[k]) + c]);
    }
  }
  if (end - begin <= kLeafSize || depth > 60) {
    node.begin = begin;
    node.end = end;
    nodes_[index] = node;
    return index;
  }
  const int axis = (chi[0] - clo[0]) >= (chi[1] - clo[1]) ? 0 : 1;
  const int mid = begin + (end - begin) / 2;
  std::nth_element(
      ids_.begin() + begin, ids_.begin() + mid, ids_.begin() + end, [&](LocalIndex a, LocalIndex b) {
        const Real ca = centroids[2 * std::size_t(a) + axis], cb = centroids[2 * std::size_t(b) + axis];
        return ca < cb || (ca == cb && a < b);
      });
  node.left = buildNode(begin, mid, centroids, depth + 1);
  node.right = buildNode(mid, end, centroids, depth + 1);
  nodes_[index] = node;
  return index;
}

Projection SegmentTreeSearch2D::project(const Real* x, Real cutoff) const {
  Best best;
  if (nodes_.empty()) return best.result();
  const Real limit2 = cutoff * cutoff;
  int stack[128];
  int top = 0;
  if (boxDistance2(x, nodes_[0].lo, nodes_[0].hi) > limit2) return best.result();
  stack[top++] = 0;
  while (top > 0) {
    const Node& nd = nodes_[stack[--top]];
    // prune: nothing in this box can beat the best (ties still visited)
    if (boxDistance2(x, nd.lo, nd.hi) > std::min(best.d2, limit2)) continue;
    if (nd.left < 0) {
      for (int k = nd.begin; k < nd.end; ++k) best.consider(&seg_[4 * std::size_t(k)], ids_[k], x, limit2);
      continue;
    }
    const Real dl = boxDistance2(x, nodes_[nd.left].lo, nodes_[nd.left].hi);
    const Real dr = boxDistance2(x, nodes_[nd.right].lo, nodes_[nd.right].hi);
    // push the farther child first so that the nearer one is visited first
    if (dl <= dr) {
      stack[top++] = nd.right;
      stack[top++] = nd.left;
    } else {
      stack[top++] = nd.left;
      stack[top++] = nd.right;
    }
  }
  return best.result();
}

void SegmentTreeSearch2D::facetsNear(const Real* lo, const Real* hi, Real radius,
                                     std::vector<LocalIndex>& out) const {
  if (nodes_.empty()) return;
  const Real qlo[2] = {lo[0] - radius, lo[1] - radius}, qhi[2] = {hi[0] + radius, hi[1] + radius};
  const std::size_t start = out.size();
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& nd = nodes_[stack[--top]];
    if (!boxesOverlap(qlo, qhi, nd.lo, nd.hi)) continue;
    if (nd.left < 0) {
      for (int k = nd.begin; k < nd.end; ++k) {
        Real blo[2], bhi[2];
        segmentBox(&seg_[4 * std::size_t(k)], blo, bhi);
        if (boxesOverlap(qlo, qhi, blo, bhi)) out.push_back(ids_[k]);
      }
      continue;
    }
    stack[top++] = nd.left;
    stack[top++] = nd.right;
  }
  std::sort(out.begin() + start, out.end());
}

void SegmentTreeSearch2D::facetsNearPoint(const Real* x, Real radius, std::vector<LocalIndex>& out) const {
  if (nodes_.empty()) return;
  const Real limit2 = radius * radius;
  int stack[128];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& nd = nodes_[stack[--top]];
    if (boxDistance2(x, nd.lo, nd.hi) > limit2) continue;
    if (nd.left < 0) {
      for (int k = nd.begin; k < nd.end; ++k) {
        const Real* s = &seg_[4 * std::size_t(k)];
        Real xi, p[2];
        int region;
        if (projectOntoSegment(x, s, s + 2, xi, p, region) <= limit2) out.push_back(ids_[k]);
      }
      continue;
    }
    stack[top++] = nd.left;
    stack[top++] = nd.right;
  }
}

// ---------------------------------------------------------------------------
// BruteForceSegmentSearch2D

void BruteForceSegmentSearch2D::build(const Real* coords, const mesh::Surface& surface) {
  copySegments(coords, surface, seg_);
}

Projection BruteForceSegmentSearch2D::project(const Real* x, Real cutoff) const {
  Best best;
  const Real limit2 = cutoff * cutoff;
  for (LocalIndex e = 0; e < numFacets(); ++e) best.consider(&seg_[4 * std::size_t(e)], e, x, limit2);
  return best.result();
}

void BruteForceSegmentSearch2D::facetsNear(const Real* lo, const Real* hi, Real radius,
                                           std::vector<LocalIndex>& out) const {
  const Real qlo[2] = {lo[0] - radius, lo[1] - radius}, qhi[2] = {hi[0] + radius, hi[1] + radius};
  for (LocalIndex e = 0; e < numFacets(); ++e) {
    Real blo[2], bhi[2];
    segmentBox(&seg_[4 * e], blo, bhi);
    if (boxesOverlap(qlo, qhi, blo, bhi)) out.push_back(e);
  }
}

// ---------------------------------------------------------------------------

std::unique_ptr<ClosestPointSearch> makeClosestPointSearch(int dim, SearchMethod method) {
  if (dim == 2) {
    switch (method) {
      case SearchMethod::Bins:
        return std::make_unique<SegmentSearch2D>();
      case SearchMethod::BruteForce:
        return std::make_unique<BruteForceSegmentSearch2D>();
      case SearchMethod::Tree:
        break;
    }
    return std::make_unique<SegmentTreeSearch2D>();
  }
  if (dim == 3)
    throw InputError("closest-point search: 3D surfaces (triangles/quadrilaterals) are not available yet");
  throw InputError("closest-point search: dimension must be 2 or 3, got " + std::to_string(dim));
}

}  // namespace cgcm::interaction
