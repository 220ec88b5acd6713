#include "cgcm/interaction/ClosestPointSearch.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "cgcm/core/Error.hpp"
#include "SearchDetail.hpp"

namespace cgcm::interaction {

using namespace detail;

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
// BruteForceTriangleSearch3D

void BruteForceTriangleSearch3D::build(const Real* coords, const mesh::Surface& surface) {
  copyTriangles(coords, surface, tri_);
}

Projection BruteForceTriangleSearch3D::project(const Real* x, Real cutoff) const {
  BestTriangle best;
  const Real limit2 = cutoff * cutoff;
  for (LocalIndex e = 0; e < numFacets(); ++e) best.consider(&tri_[9 * std::size_t(e)], e, x, limit2);
  return best.result();
}

void BruteForceTriangleSearch3D::facetsNear(const Real* lo, const Real* hi, Real radius,
                                            std::vector<LocalIndex>& out) const {
  const Real qlo[3] = {lo[0] - radius, lo[1] - radius, lo[2] - radius};
  const Real qhi[3] = {hi[0] + radius, hi[1] + radius, hi[2] + radius};
  for (LocalIndex e = 0; e < numFacets(); ++e)
    if (triangleBoxOverlaps(&tri_[9 * std::size_t(e)], qlo, qhi)) out.push_back(e);
}

// ---------------------------------------------------------------------------

std::unique_ptr<ClosestPointSearch> makeClosestPointSearch(int dim, SearchMethod method) {
  if (dim == 2) {
    if (method == SearchMethod::BruteForce) return std::make_unique<BruteForceSegmentSearch2D>();
    return std::make_unique<AabbTreeSearch2D>();
  }
  if (dim == 3) {
    if (method == SearchMethod::BruteForce) return std::make_unique<BruteForceTriangleSearch3D>();
    return std::make_unique<AabbTreeSearch3D>();
  }
  throw InputError("closest-point search: dimension must be 2 or 3, got " + std::to_string(dim));
}

}  // namespace cgcm::interaction
