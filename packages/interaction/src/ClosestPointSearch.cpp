#include "cgcm/interaction/ClosestPointSearch.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "cgcm/core/Error.hpp"
#include "SearchDetail.hpp"

namespace cgcm::interaction {

using namespace detail;

// ---------------------------------------------------------------------------
// BruteForceSearch

template <int Dim>
void BruteForceSearch<Dim>::build(const Real* coords, const mesh::Surface& surface) {
  Facets<Dim>::copy(coords, surface, vertices_);
}

template <int Dim>
Projection BruteForceSearch<Dim>::project(const Real* x, Real cutoff, LocalIndex) const {
  typename Facets<Dim>::Best best;
  for (LocalIndex e = 0; e < numFacets(); ++e) best.consider(&vertices_[kStride * e], e, x, cutoff * cutoff);
  return best.result();
}

template <int Dim>
void BruteForceSearch<Dim>::facetsNearPoint(const Real* x, Real radius, std::vector<LocalIndex>& out) const {
  const Real r = radius * (1.0 + 1e-12) + 1e-300;
  for (LocalIndex e = 0; e < numFacets(); ++e) {
    typename Facets<Dim>::Best one;
    one.consider(&vertices_[kStride * e], e, x, r * r);
    if (one.facet >= 0) out.push_back(e);
  }
}

template class BruteForceSearch<2>;
template class BruteForceSearch<3>;

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
