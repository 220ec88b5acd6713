#include "cgcm/interaction/SurfaceInteraction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "cgcm/core/Error.hpp"
#include "cgcm/interaction/Method3CurvedKernel.hpp"
#include "cgcm/interaction/Method3CurvedKernel3D.hpp"
#include "cgcm/interaction/Method3Kernel3D.hpp"

namespace cgcm::interaction {

namespace {

/// The chords a-mid, mid-b of every Line3 segment (s -> 2s, 2s + 1): what the 2D search runs over.
mesh::Surface chords(const mesh::Surface& s) {
  mesh::Surface c{s.body, 2, {}, {}};
  for (LocalIndex e = 0; e < s.numFacets(); ++e) {
    const LocalIndex* n = &s.facets[3 * std::size_t(e)];
    c.facets.insert(c.facets.end(), {n[0], n[2], n[2], n[1]});
    if (!s.facetCells.empty()) c.facetCells.insert(c.facetCells.end(), 2, s.facetCells[e]);
  }
  return c;
}

/// f(std::integral_constant<int, N>) for the nodes N = 6, 8, 9 of a curved 3D facet.
template <class F>
decltype(auto) withCurvedFacet(int nodes, F&& f) {
  switch (nodes) {
    case 6: return f(std::integral_constant<int, 6>{});
    case 8: return f(std::integral_constant<int, 8>{});
    default: return f(std::integral_constant<int, 9>{});
  }
}

/// The triangles of the covers of every curved 3D facet (facet s -> triangles T s .. T s + T - 1 over
/// the points P s .. P s + P - 1 of SurfaceInteraction::cover).
mesh::Surface coverTriangles(const mesh::Surface& s) {
  mesh::Surface c{s.body, 3, {}, {}};
  withCurvedFacet(s.nodesPerFacet, [&](auto n) {
    constexpr int N = decltype(n)::value, P = kCoverPoints<N>, T = kCoverTriangles<N>;
    for (LocalIndex e = 0; e < s.numFacets(); ++e)
      for (int t = 0; t < T; ++t) {
        const int* tri = coverTriangle<N>(t);
        for (int a = 0; a < 3; ++a) c.facets.push_back(LocalIndex(P * e + tri[a]));
        if (!s.facetCells.empty()) c.facetCells.push_back(s.facetCells[e]);
      }
  });
  return c;
}

/// The most a point of a curved facet moves per unit motion of its nodes: max over the facet of
/// sum |N_a| (Line3 5/4, TRI6 5/3, QUAD8 3 at its centre, QUAD9 (5/4)^2).
Real lebesgueConstant(int dim, int nodesPerFacet) {
  if (dim == 2) return nodesPerFacet == 3 ? 1.25 : 1.0;
  switch (nodesPerFacet) {
    case 6: return 5.0 / 3.0;
    case 8: return 3.0;
    case 9: return 25.0 / 16.0;
    default: return 1.0;
  }
}

}  // namespace

SurfaceInteraction::SurfaceInteraction(std::vector<mesh::Surface> surfaces, std::vector<Real> densities,
                                       std::shared_ptr<const PairPotential> potential,
                                       SurfaceInteractionOptions options)
    : surfaces_(std::move(surfaces)),
      densities_(std::move(densities)),
      potential_(std::move(potential)),
      options_(options) {
  if (!potential_) throw InputError("surface interaction: no pair potential given");
  kernel_ = potential_->kernelPotential();
  dim_ = options_.formulation == Formulation::ThreeD ? 3 : 2;
  for (std::size_t k = 0; k < densities_.size(); ++k)
    if (!(densities_[k] > 0.0) || !std::isfinite(densities_[k]))
      throw InputError("surface interaction: density of body " + std::to_string(k) +
                       " must be finite and > 0");
  if (options_.quadraturePoints < 1 || options_.quadraturePoints > 64)
    throw InputError("surface interaction: quadraturePoints must be in [1, 64], got " +
                     std::to_string(options_.quadraturePoints));
  if (std::isnan(options_.cutoff)) throw InputError("surface interaction: cutoff is NaN");
  if (!(options_.cutoffTaper >= 0.0 && options_.cutoffTaper < 1.0))
    throw InputError("surface interaction: cutoffTaper must be in [0, 1), got " +
                     std::to_string(options_.cutoffTaper));
  if (std::isnan(options_.projectionSmoothing) || std::isinf(options_.projectionSmoothing))
    throw InputError("surface interaction: projectionSmoothing must be finite");
  rule_ = gaussLegendreUnit(options_.quadraturePoints);
  cutoff1_ = options_.cutoff > 0.0 ? options_.cutoff : 10.0 * potential_->r0();
  taperStart1_ = std::isfinite(cutoff1_) ? (1.0 - options_.cutoffTaper) * cutoff1_ : cutoff1_;
  smoothing1_ = options_.projectionSmoothing >= 0.0
                    ? options_.projectionSmoothing
                    : SurfaceInteractionOptions::kDefaultProjectionSmoothing * potential_->r0();
  setLengthScale(1.0);

  Real maxProduct = 0.0;
  for (std::size_t k = 0; k < densities_.size(); ++k)
    for (std::size_t l = 0; l < densities_.size(); ++l)
      if (k != l) maxProduct = std::max(maxProduct, densities_[k] * densities_[l]);
  // both invariant under the length scale
  summary_.cutoffTraction =
      std::isfinite(cutoff1_) ? maxProduct * std::abs(potential_->halfSpace(taperStart1_)) : 0.0;
  summary_.neglectedWorkFraction = neglectedWorkFraction(*potential_, taperStart1_, cutoff1_);
  summary_.minDistance = std::numeric_limits<Real>::infinity();
  summary_.resultant.assign(surfaces_.size(), {0.0, 0.0, 0.0});
  search_.resize(surfaces_.size());
  for (auto& s : search_) s = makeClosestPointSearch(dim_, options_.search);
  setSurfaces(std::move(surfaces_));
}

void SurfaceInteraction::setSurfaces(std::vector<mesh::Surface> surfaces) {
  if (surfaces.size() != densities_.size()) {
    std::ostringstream os;
    os << "surface interaction: " << surfaces.size() << " surfaces but " << densities_.size()
       << " densities (one per body)";
    throw InputError(os.str());
  }
  const mesh::Surface* first = nullptr;  // the first body with facets: the 3D kernels pair flat with flat
  for (std::size_t k = 0; k < surfaces.size(); ++k) {
    const int npf = surfaces[k].nodesPerFacet;
    if (surfaces[k].numFacets() == 0) continue;
    if (dim_ == 2 ? npf != 2 && npf != 3 : npf != 3 && npf != 4 && npf != 6 && npf != 8 && npf != 9)
      throw InputError("surface interaction: " +
                       std::string(dim_ == 2 ? "2D surfaces need 2 or 3 nodes per facet"
                                             : "3D surfaces need 3, 4 (flat) or 6, 8, 9 (curved) nodes per facet") +
                       " (body " + std::to_string(k) + " has " + std::to_string(npf) + ")");
    if (!first) first = &surfaces[k];
    if (dim_ == 3 && (npf > 4) != (first->nodesPerFacet > 4))
      throw InputError("surface interaction: in 3D the bodies' facets must be all flat or all curved (body " +
                       std::to_string(first->body) + " has " + std::to_string(first->nodesPerFacet) +
                       " nodes per facet, body " + std::to_string(k) + " has " + std::to_string(npf) + ")");
  }
  surfaces_ = std::move(surfaces);
  surfaceNodes_.clear();
  targets_.clear();
  facetRules_.clear();
  firstPoint_.clear();
  neighbours_.clear();
  pairs_.clear();
  evaluatedFacets_.clear();
  referenceAreas_.clear();
  searchedCoords_.clear();  // the next updatePairs searches anew
  for (const mesh::Surface& sk : surfaces_) surfaceNodes_.insert(surfaceNodes_.end(), sk.facets.begin(), sk.facets.end());
  std::sort(surfaceNodes_.begin(), surfaceNodes_.end());
  surfaceNodes_.erase(std::unique(surfaceNodes_.begin(), surfaceNodes_.end()), surfaceNodes_.end());
  if (dim_ == 3) {
    for (std::size_t k = 0; k < surfaces_.size(); ++k) {
      const mesh::Surface& sk = surfaces_[k];
      targets_.push_back(curved(int(k)) ? coverTriangles(sk) : mesh::triangulated(sk));
      facetRules_.push_back(facetQuadrature(sk.nodesPerFacet, options_.quadraturePoints));
    }
  } else {
    for (const mesh::Surface& sk : surfaces_) targets_.push_back(sk.nodesPerFacet == 3 ? chords(sk) : sk);
  }
  coverDeviation_.assign(surfaces_.size(), 0.0);
  coverPoints_.resize(surfaces_.size());
  std::size_t points = 0;
  for (std::size_t k = 0; k < surfaces_.size(); ++k) {
    firstPoint_.push_back(points);
    points += std::size_t(surfaces_[k].numFacets()) * pointsPerFacet(int(k));
  }
  hints_.assign(points * surfaces_.size(), -1);
  if (dim_ == 3) return;  // the projection blend (and its neighbour table) is 2D only

  // neighbours_[l][2 s + end]: the other segment holding that node of s, if exactly one does
  neighbours_.resize(surfaces_.size());
  for (std::size_t l = 0; l < surfaces_.size(); ++l) {
    const mesh::Surface& sl = surfaces_[l];
    std::vector<std::pair<LocalIndex, LocalIndex>> byNode;  // (node, 2 s + end): the ends, not a Line3's mid node
    for (LocalIndex i = 0; i < 2 * sl.numFacets(); ++i)
      byNode.emplace_back(sl.facets[std::size_t(i / 2) * sl.nodesPerFacet + i % 2], i);
    std::sort(byNode.begin(), byNode.end());
    neighbours_[l].assign(byNode.size(), -1);
    for (std::size_t i = 0; i < byNode.size();) {
      std::size_t j = i;
      while (j < byNode.size() && byNode[j].first == byNode[i].first) ++j;
      if (j - i == 2) {
        neighbours_[l][byNode[i].second] = byNode[i + 1].second / 2;
        neighbours_[l][byNode[i + 1].second] = byNode[i].second / 2;
      }
      i = j;
    }
  }
}

Real neglectedWorkFraction(const PairPotential& potential, Real taperStart, Real cutoff) {
  const Real w = potential.adhesionWorkCoefficient();
  if (!(w > 0.0) || !std::isfinite(cutoff)) return 0.0;
  const KernelPotential kernel = potential.kernelPotential();
  auto removed = [&](Real r) {  // Phi/beta (1 - S)
    Real T, dT, Tc, dTc;
    potential.halfSpaceWithDerivative(r, T, dT);
    std::visit(
        [&](const auto& p) {
          TractionLaw<std::decay_t<decltype(p)>>{p, 1.0, taperStart, cutoff}(r, Tc, dTc);
        },
        kernel);
    return T - Tc;
  };
  // Simpson on the taper, and on [r_c, inf) after r = r_c / t (the integrand vanishes at t = 0).
  const int n = 200;
  const Real h = (cutoff - taperStart) / n;
  Real taper = 0.0, tail = 0.0;
  for (int i = 0; i <= n; ++i) {
    const Real c = (i == 0 || i == n) ? 1.0 : (i % 2 ? 4.0 : 2.0);
    if (h > 0.0) taper += c * removed(taperStart + i * h);
    const Real t = Real(i) / n;
    if (i > 0) tail += c * removed(cutoff / t) * cutoff / (t * t);
  }
  return -(taper * h / 3.0 + tail / (3.0 * n)) / w;
}

void SurfaceInteraction::setStrength(Real strength) {
  if (!(strength > 0.0) || !std::isfinite(strength))
    throw InputError("surface interaction: strength must be finite and > 0, got " + std::to_string(strength));
  strength_ = strength;
}

void SurfaceInteraction::setLengthScale(Real b) {
  if (!(b > 0.0) || !std::isfinite(b))
    throw InputError("surface interaction: length scale must be finite and > 0, got " + std::to_string(b));
  lengthScale_ = b;
  cutoff_ = b * cutoff1_;
  taperStart_ = b * taperStart1_;
  smoothing_ = b * smoothing1_;
  summary_.cutoff = cutoff_;
  summary_.taperStart = taperStart_;
}

// delta P of the projection of x onto segment s of body l (see the header):
// P = (o_s/delta)^2 exp(-(o_n/delta)^2) when s's projection is its vertex
// (region 1, 2), o_s the overshoot of the unclamped foot beyond that vertex
// and o_n the neighbour's beyond the same vertex; 0 for a foot inside s or
// a vertex no other segment holds. With grad (8 entries) also its derivative
// with respect to (x, node a of s, node b of s, far node of the neighbour),
// whose id goes to *far (-1 when not involved).
Real SurfaceInteraction::vertexPenalty(const Real* coords, int l, LocalIndex s, const Real x[2], int region,
                                       Real* grad, LocalIndex* far) const {
  if (grad != nullptr)
    for (int i = 0; i < 8; ++i) grad[i] = 0.0;
  if (far != nullptr) *far = -1;
  const mesh::Surface& sl = surfaces_[l];
  const int end = region - 1;
  const LocalIndex n = end < 0 ? -1 : neighbours_[l][2 * std::size_t(s) + end];
  if (n < 0) return 0.0;
  const Real delta = smoothing_;
  const LocalIndex vertex = sl.facets[2 * s + end];
  const int endN = sl.facets[2 * n] == vertex ? 0 : 1;
  auto at = [&](LocalIndex node) { return coords + 2 * std::size_t(node); };
  Real gs[6], gn[6];
  const Real os = overshootBeyondEnd(x, at(sl.facets[2 * s]), at(sl.facets[2 * s + 1]), end, grad ? gs : nullptr);
  if (os == 0.0) return 0.0;
  const Real on = overshootBeyondEnd(x, at(sl.facets[2 * n]), at(sl.facets[2 * n + 1]), endN, grad ? gn : nullptr);
  const Real ts = os / delta, tn = on / delta;
  const Real phi = std::exp(-tn * tn), P = ts * ts * phi;
  if (grad != nullptr) {
    // d(delta P) = 2 ts phi do_s - 2 ts^2 tn phi do_n
    const Real cs = 2.0 * ts * phi, cn = -2.0 * ts * ts * tn * phi;
    for (int i = 0; i < 2; ++i) {
      grad[i] = cs * gs[i] + cn * gn[i];
      grad[2 + i] = cs * gs[2 + i];
      grad[4 + i] = cs * gs[4 + i];
      grad[2 * (1 + end) + i] += cn * gn[2 * (1 + endN) + i];  // the shared vertex
      grad[6 + i] = cn * gn[2 * (2 - endN) + i];               // the neighbour's other node
    }
    if (far != nullptr) *far = sl.facets[2 * n + 1 - endN];
  }
  return delta * P;
}

// The blend targets of the point x (closest segment at r_min): every segment
// of body l with rho <= rho_min + c delta, sorted by rho (ties by facet id),
// at most kMaxBlendTargets. The closest segment or its neighbour has
// P <= 1/e (both P's of the two projections onto a vertex are
// t_s^2 exp(-t_n^2) and t_n^2 exp(-t_s^2)), so rho_min <= r_min + delta/e
// and every candidate lies within r_min + (c + 1) delta.
void SurfaceInteraction::findTargets(const Real* coords, const Real x[2], int l, Real rmin, InteractionPair& p) {
  const mesh::Surface& sl = surfaces_[l];
  const Real range = kSmoothingRange * smoothing_, limit = rmin + range + smoothing_;
  near_.clear();
  search_[l]->facetsNearPoint(x, limit, near_);
  candidates_.clear();
  Real rhoMin = std::numeric_limits<Real>::infinity();
  for (LocalIndex s : near_) {
    Real xi, xp[2];
    int region;
    const Real d2 = projectOntoSegment(x, coords + 2 * std::size_t(sl.facets[2 * s]),
                                       coords + 2 * std::size_t(sl.facets[2 * s + 1]), xi, xp, region);
    const Real r = std::sqrt(d2);
    if (r > limit) continue;
    const Real rho = r + vertexPenalty(coords, l, s, x, region, nullptr, nullptr);
    rhoMin = std::min(rhoMin, rho);
    candidates_.emplace_back(rho, s);
  }
  keepBlendTargets(rhoMin + range, kMaxBlendTargets, p);
}

int SurfaceInteraction::coverPieces(int l) const {
  return dim_ == 2 ? 2 : surfaces_[l].nodesPerFacet == 6 ? kCoverTriangles<6> : kCoverTriangles<9>;
}

Real SurfaceInteraction::cover(const Real* coords, int l, std::vector<Real>& points) const {
  if (!curved(l)) return 0.0;
  const mesh::Surface& sl = surfaces_[l];
  Real dev = 0.0;
  if (dim_ == 2) {  // the chords are the segments' own nodes
    for (LocalIndex s = 0; s < sl.numFacets(); ++s) {
      const LocalIndex* n = &sl.facets[3 * std::size_t(s)];
      dev = std::max(dev, line3ChordDeviation(coords + 2 * std::size_t(n[0]), coords + 2 * std::size_t(n[1]),
                                              coords + 2 * std::size_t(n[2])));
    }
    return dev;
  }
  withCurvedFacet(sl.nodesPerFacet, [&](auto n) {
    constexpr int N = decltype(n)::value, P = kCoverPoints<N>;
    points.resize(3 * P * std::size_t(sl.numFacets()));
    for (LocalIndex s = 0; s < sl.numFacets(); ++s) {
      Real y[3 * N];
      for (int a = 0; a < N; ++a)
        for (int i = 0; i < 3; ++i) y[3 * a + i] = coords[3 * std::size_t(sl.facets[N * std::size_t(s) + a]) + i];
      coverPoints<N>(y, reinterpret_cast<Real(*)[3]>(&points[3 * P * std::size_t(s)]));
      dev = std::max(dev, coverDeviation<N>(y));
    }
  });
  return dev;
}

void SurfaceInteraction::curvedFacetsNear(const Real* x, int l, Real radius, std::vector<LocalIndex>& out) {
  near_.clear();
  search_[l]->facetsNearPoint(x, radius + coverDeviation_[l], near_);
  out.clear();
  const int pieces = coverPieces(l);
  for (LocalIndex c : near_) out.push_back(c / pieces);
  out.erase(std::unique(out.begin(), out.end()), out.end());  // the pieces of a facet are adjacent
}

Real SurfaceInteraction::curvedBlendDistance(const Real* coords, const Real* x, int l, LocalIndex s, Real* r,
                                             bool withPenalty) const {
  const mesh::Surface& sl = surfaces_[l];
  if (dim_ == 3)
    return withCurvedFacet(sl.nodesPerFacet, [&](auto n) {
      constexpr int N = decltype(n)::value;
      Real y[3 * N];
      for (int a = 0; a < N; ++a)
        for (int i = 0; i < 3; ++i) y[3 * a + i] = coords[3 * std::size_t(sl.facets[N * std::size_t(s) + a]) + i];
      return facetBlendDistance<N>(x, y, withPenalty ? smoothing_ : 0.0, r);
    });
  Real y[6], v[6], eta, p[2];
  int region;
  for (int a = 0; a < 3; ++a)
    for (int i = 0; i < 2; ++i) y[2 * a + i] = coords[2 * std::size_t(sl.facets[3 * std::size_t(s) + a]) + i];
  const Real d = std::sqrt(projectOntoCurve<3>(x, y, eta, p, region));
  if (r != nullptr) *r = d;
  const LocalIndex n = region == 0 ? -1 : neighbours_[l][2 * std::size_t(s) + region - 1];
  if (!withPenalty || smoothing_ <= 0.0 || n < 0) return d;
  const LocalIndex vertex = sl.facets[3 * std::size_t(s) + region - 1];
  for (int a = 0; a < 3; ++a)
    for (int i = 0; i < 2; ++i) v[2 * a + i] = coords[2 * std::size_t(sl.facets[3 * std::size_t(n) + a]) + i];
  const Real os = detail::overshootAlongEnd<3>(x, y, region - 1) / smoothing_;
  const Real on = detail::overshootAlongEnd<3>(x, v, sl.facets[3 * std::size_t(n)] == vertex ? 0 : 1) / smoothing_;
  return d + smoothing_ * os * os * std::exp(-on * on);
}

// The closest curved facet: the cover's nearest lies within the cover
// deviation of the facets, so every facet whose cover comes within twice
// that of x is a candidate.
std::pair<Real, LocalIndex> SurfaceInteraction::closestCurvedFacet(const Real* coords, const Real* x, int l,
                                                                   const Projection& cover) {
  curvedFacetsNear(x, l, cover.distance + coverDeviation_[l], segments_);
  std::pair<Real, LocalIndex> best{std::numeric_limits<Real>::infinity(), -1};
  for (LocalIndex s : segments_) {
    const Real r = curvedBlendDistance(coords, x, l, s, nullptr, false);
    if (r < best.first) best = {r, s};
  }
  if (!(best.first <= cutoff_)) best.second = -1;
  return best;
}

// As findTargets (2D) and findTargets3D on the curved facets of body l.
void SurfaceInteraction::findCurvedTargets(const Real* coords, const Real* x, int l, InteractionPair& p) {
  const Real range = kSmoothingRange * smoothing_;
  const Real rho0 = curvedBlendDistance(coords, x, l, p.targets[0], nullptr);
  curvedFacetsNear(x, l, rho0 + range, segments_);
  candidates_.clear();
  Real rhoMin = std::numeric_limits<Real>::infinity();
  for (LocalIndex s : segments_) {
    const Real rho = curvedBlendDistance(coords, x, l, s, nullptr);
    if (rho > rho0 + range) continue;
    rhoMin = std::min(rhoMin, rho);
    candidates_.emplace_back(rho, s);
  }
  keepBlendTargets(rhoMin + range, dim_ == 3 ? kMaxBlendTargets3D : kMaxBlendTargets, p);
}

// The candidates with rho <= limit, lowest first, at most maxTargets (a
// truncation is counted); the closest projection is always among them.
void SurfaceInteraction::keepBlendTargets(Real limit, int maxTargets, InteractionPair& p) {
  std::sort(candidates_.begin(), candidates_.end());
  int n = 0;
  while (n < int(candidates_.size()) && candidates_[n].first <= limit) ++n;
  if (n == 0) return;  // cannot happen: the closest facet is a candidate
  if (n > maxTargets) {
    ++summary_.numTruncatedBlends;
    n = maxTargets;
  }
  p.numTargets = n;
  for (int i = 0; i < n; ++i) p.targets[i] = candidates_[i].second;
  if (n > 1) ++summary_.numBlended;
}

// The 3D blend targets of x: every triangle of body l with rho <= rho_min +
// c delta (rho = r + o^2/delta, Method3Kernel3D.hpp), lowest rho first, at
// most kMaxBlendTargets3D. rho_min <= rho of the closest triangle and
// r <= rho, so every candidate lies within that rho + c delta of x.
void SurfaceInteraction::findTargets3D(const Real* coords, const Real x[3], int l, LocalIndex closest,
                                       InteractionPair& p) {
  const mesh::Surface& tl = targets_[l];
  const Real delta = smoothing_, range = kSmoothingRange * delta;
  auto rhoOf = [&](LocalIndex s) {
    Real t[9], xi[2], foot[3];
    for (int v = 0; v < 3; ++v)
      for (int k = 0; k < 3; ++k) t[3 * v + k] = coords[3 * std::size_t(tl.facets[3 * std::size_t(s) + v]) + k];
    int region;
    projectOntoTriangle(x, t, t + 3, t + 6, xi, foot, region);
    return detail::blendDistanceAt(x, t, region, delta);
  };
  const Real limit = rhoOf(closest) + range;
  near_.clear();
  search_[l]->facetsNearPoint(x, limit, near_);
  candidates_.clear();
  Real rhoMin = std::numeric_limits<Real>::infinity();
  for (LocalIndex s : near_) {
    const Real rho = rhoOf(s);
    if (rho > limit) continue;
    rhoMin = std::min(rhoMin, rho);
    candidates_.emplace_back(rho, s);
  }
  keepBlendTargets(rhoMin + range, kMaxBlendTargets3D, p);
}

std::vector<char> SurfaceInteraction::bodiesWithin(const Real* coords, Real radius) const {
  const int nb = numBodies();
  std::vector<std::array<Real, 6>> box(nb);
  for (int k = 0; k < nb; ++k) {
    auto& b = box[k];
    for (int i = 0; i < 3; ++i) b[i] = std::numeric_limits<Real>::infinity(), b[3 + i] = -b[i];
    for (LocalIndex n : surfaces_[k].facets)
      for (int i = 0; i < dim_; ++i) {
        const Real v = coords[std::size_t(n) * dim_ + i];
        b[i] = std::min(b[i], v);
        b[3 + i] = std::max(b[3 + i], v);
      }
  }
  std::vector<char> near(std::size_t(nb) * nb, 0);
  for (int k = 0; k < nb; ++k)
    for (int l = 0; l < nb; ++l) {
      if (k == l || surfaces_[k].numFacets() == 0 || surfaces_[l].numFacets() == 0) continue;
      Real gap2 = 0.0;  // squared distance between the boxes
      for (int i = 0; i < dim_; ++i) {
        const Real g = std::max({0.0, box[k][i] - box[l][3 + i], box[l][i] - box[k][3 + i]});
        gap2 += g * g;
      }
      near[std::size_t(k) * nb + l] = gap2 <= radius * radius;
    }
  return near;
}

template <class Visit, class FacetDone>
void SurfaceInteraction::forEachPoint(const Real* coords, Visit&& visit, FacetDone&& facetDone) const {
  for (int k = 0; k < numBodies(); ++k) {
    const mesh::Surface& sk = surfaces_[k];
    const int npf = sk.nodesPerFacet;
    const char* evaluated = evaluatedFacets_.empty() ? nullptr : evaluatedFacets_[k].data();
    for (LocalIndex e = 0; e < sk.numFacets(); ++e) {
      if (evaluated && !evaluated[e]) continue;
      const LocalIndex* nodes = &sk.facets[std::size_t(e) * npf];
      if (dim_ == 3) {
        const auto& rule = facetRules_[k];
        for (int q = 0; q < int(rule.size()); ++q) {
          Real x[3] = {0.0, 0.0, 0.0};
          for (int a = 0; a < npf; ++a)
            for (int i = 0; i < 3; ++i) x[i] += rule[q].N[a] * coords[3 * std::size_t(nodes[a]) + i];
          visit(k, e, q, x);
        }
        facetDone(k, e);
        continue;
      }
      for (int q = 0; q < rule_.size(); ++q) {
        Real N[3], dN[3], x[2] = {0.0, 0.0};
        if (npf == 3) lineShape<3>(rule_.points[q], N, dN);
        else lineShape<2>(rule_.points[q], N, dN);
        for (int a = 0; a < npf; ++a)
          for (int i = 0; i < 2; ++i) x[i] += N[a] * coords[2 * std::size_t(nodes[a]) + i];
        visit(k, e, q, x);
      }
      facetDone(k, e);
    }
  }
}

void SurfaceInteraction::setEvaluatedFacets(std::vector<std::vector<char>> evaluated) {
  if (!evaluated.empty()) {
    bool fits = evaluated.size() == surfaces_.size();
    for (std::size_t k = 0; fits && k < surfaces_.size(); ++k)
      fits = evaluated[k].size() == std::size_t(surfaces_[k].numFacets());
    if (!fits) throw InputError("surface interaction: evaluated facets need one flag per facet of every body");
  }
  evaluatedFacets_ = std::move(evaluated);
  searchedCoords_.clear();  // the next updatePairs searches anew
}

void SurfaceInteraction::updatePairs(const Real* coords) {
  const int nb = numBodies();
  bool same = searchedCutoff_ == cutoff_ && searchedSmoothing_ == smoothing_ &&
              searchedCoords_.size() == surfaceNodes_.size() * dim_;
  for (std::size_t i = 0; same && i < surfaceNodes_.size(); ++i)
    for (int k = 0; k < dim_; ++k)
      same = same && searchedCoords_[dim_ * i + k] == coords[dim_ * std::size_t(surfaceNodes_[i]) + k];
  if (same) return;  // the trees and pairs of this very state
  searchedCoords_.resize(surfaceNodes_.size() * dim_);
  for (std::size_t i = 0; i < surfaceNodes_.size(); ++i)
    for (int k = 0; k < dim_; ++k) searchedCoords_[dim_ * i + k] = coords[dim_ * std::size_t(surfaceNodes_[i]) + k];
  searchedCutoff_ = cutoff_;
  searchedSmoothing_ = smoothing_;
  ++summary_.numSearches;

  Real largestDeviation = 0.0;
  for (int l = 0; l < nb; ++l) {
    coverDeviation_[l] = cover(coords, l, coverPoints_[l]);
    largestDeviation = std::max(largestDeviation, coverDeviation_[l]);
  }
  const std::vector<char> near = bodiesWithin(coords, cutoff_ + largestDeviation);
  for (int l = 0; l < nb; ++l) {
    bool needed = false;
    for (int k = 0; k < nb; ++k) needed = needed || near[std::size_t(k) * nb + l];
    // a body no other comes near is not searched (an empty tree costs nothing)
    search_[l]->build(dim_ == 3 && curved(l) ? coverPoints_[l].data() : coords,
                      needed ? targets_[l] : mesh::Surface{l, dim_, {}, {}});
  }
  pairs_.clear();
  summary_.numQuadraturePoints = 0;
  summary_.numPairs = 0;
  summary_.numBeyondCutoff = 0;
  summary_.numBlended = 0;
  summary_.numTruncatedBlends = 0;
  // every other body near k: the closest point of the quadrature point x of facet e, q
  auto searchFrom = [&](int k, LocalIndex e, int q, const Real* x) {
    for (int l = 0; l < nb; ++l) {
      if (!near[std::size_t(k) * nb + l]) continue;
      ++summary_.numQuadraturePoints;
      const std::size_t point = pointIndex(k, e, q);
      LocalIndex& hint = hints_[point * nb + l];
      const Projection pr = search_[l]->project(x, cutoff_ + coverDeviation_[l], hint);
      hint = pr.facet;
      const auto [r, closest] = !pr.found() ? std::pair<Real, LocalIndex>{0.0, -1}
                                : curved(l)  ? closestCurvedFacet(coords, x, l, pr)
                                             : std::pair<Real, LocalIndex>{pr.distance, pr.facet};
      if (closest < 0) {
        ++summary_.numBeyondCutoff;
        continue;
      }
      InteractionPair p{k, e, q, l};
      p.targets[0] = closest;
      if (smoothing_ > 0.0) {
        if (curved(l)) findCurvedTargets(coords, x, l, p);
        else if (dim_ == 3) findTargets3D(coords, x, l, pr.facet, p);
        else findTargets(coords, x, l, r, p);
      }
      pairs_.push_back(p);
    }
  };
  forEachPoint(coords, searchFrom, [](int, LocalIndex) {});
  summary_.numPairs = LocalIndex(pairs_.size());
}

namespace {

[[noreturn]] void throwContact(const InteractionPair& p, LocalIndex target, Real r, const char* facet = "segment") {
  std::ostringstream os;
  os << "surface interaction: quadrature point " << p.qp << " of " << facet << " " << p.facet << " of body " << p.body
     << " lies on " << facet << " " << target << " of body " << p.otherBody << " (r = " << r
     << "): the surfaces touch or interpenetrate";
  throw NumericalError(os.str());
}

// The softmin weights w_t = exp(-(rho_t - rho_min)/delta) / sum (header) of nt blend targets
// (one target: w = 1), the same for segments, curved segments and triangles.
void blendWeights(const Real* rho, int nt, int closest, Real delta, Real* w) {
  if (nt == 1) {
    w[0] = 1.0;
    return;
  }
  Real sum = 0.0;
  for (int t = 0; t < nt; ++t) sum += (w[t] = std::exp(-(rho[t] - rho[closest]) / delta));
  for (int t = 0; t < nt; ++t) w[t] /= sum;
}

// The blended contribution of nt curved targets (header): out.f = sum_t w_t f_t and, with the
// tangent, out.K = sum_t w_t [K_t + (f - f_t) (x) drho_t / delta] (no cancellation of terms of size
// f/delta) over out's first ncols columns. Target t: f_t at f + t fStride, its K_t rows of nz[t]
// entries at K + t kStride, drho_t at Jrho + t zStride, z entry j in column colOf[t zStride + j].
template <class Contribution>
void blendContributions(Contribution& out, int nt, int nf, int ncols, const Real* rho, int closest, Real delta,
                        const Real* f, int fStride, const Real* K, int kStride, const int* nz, const int* colOf,
                        const Real* Jrho, int zStride, bool withTangent) {
  Real w[kMaxBlendTargets3D];
  blendWeights(rho, nt, closest, delta, w);
  for (int i = 0; i < nf; ++i) {
    out.f[i] = 0.0;
    for (int t = 0; t < nt; ++t) out.f[i] += w[t] * f[t * fStride + i];
  }
  if (!withTangent) return;
  for (int i = 0; i < nf; ++i)
    for (int c = 0; c < ncols; ++c) out.K[i][c] = 0.0;
  for (int t = 0; t < nt; ++t)
    for (int i = 0; i < nf; ++i) {
      const Real g = nt > 1 ? w[t] * (out.f[i] - f[t * fStride + i]) / delta : 0.0;
      for (int j = 0; j < nz[t]; ++j)
        out.K[i][colOf[t * zStride + j]] += w[t] * K[t * kStride + i * nz[t] + j] + g * Jrho[t * zStride + j];
    }
}

bool allFinite(const Real f[4]) {
  return std::isfinite(f[0]) && std::isfinite(f[1]) && std::isfinite(f[2]) && std::isfinite(f[3]);
}

}  // namespace

template <class P>
PairState SurfaceInteraction::evaluatePair3D(const P& potential, const Real* coords, const InteractionPair& p,
                                             PairContribution& out, bool withTangent) const {
  const mesh::Surface& sk = surfaces_[p.body];
  const mesh::Surface& tl = targets_[p.otherBody];
  const int npf = sk.nodesPerFacet, nt = p.numTargets;
  const int nz = 3 * npf + 9;
  out.dim = 3;
  out.numRowNodes = npf;
  int nc = npf;
  for (int a = 0; a < npf; ++a) out.rowNodes[a] = out.colNodes[a] = sk.facets[std::size_t(p.facet) * npf + a];
  // col[t][a]: column node of target t's vertex a (shared vertices merged)
  int col[kMaxBlendTargets3D][3];
  for (int t = 0; t < nt; ++t)
    for (int a = 0; a < 3; ++a) {
      const LocalIndex node = tl.facets[3 * std::size_t(p.targets[t]) + a];
      int c = npf;
      while (c < nc && out.colNodes[c] != node) ++c;
      if (c == nc) out.colNodes[nc++] = node;
      col[t][a] = c;
    }
  out.numColNodes = nc;
  const auto law = this->law(potential, p.body, p.otherBody);
  const FacetPoint& q = facetRules_[p.body][p.qp];
  const Real* dA = referenceAreaOf(p);
  // One target: its contribution. Several: the softmin blend over rho_t
  // (header), K = sum_t w_t [K_t + (f - f_t) (x) drho_t / delta].
  Real f[kMaxBlendTargets3D][12], rho[kMaxBlendTargets3D] = {}, Jrho[kMaxBlendTargets3D][21];
  Real Kt[kMaxBlendTargets3D][12 * 21];  // [t][3 npf x nz]
  PairState st[kMaxBlendTargets3D];
  int closest = 0;
  for (int t = 0; t < nt; ++t) {
    Real z[21];
    for (int a = 0; a < npf; ++a)
      for (int i = 0; i < 3; ++i) z[3 * a + i] = coords[3 * std::size_t(out.colNodes[a]) + i];
    for (int a = 0; a < 3; ++a)
      for (int i = 0; i < 3; ++i) z[3 * npf + 3 * a + i] = coords[3 * std::size_t(out.colNodes[col[t][a]]) + i];
    Real* K = withTangent ? Kt[t] : nullptr;
    st[t] = npf == 4 ? method3Pair3D<4>(z, q, law, f[t], K, dA) : method3Pair3D<3>(z, q, law, f[t], K, dA);
    bool finite = true;
    for (int i = 0; i < 3 * npf; ++i) finite = finite && std::isfinite(f[t][i]);
    if (!(st[t].distance > 0.0) || !finite) {
      std::ostringstream os;
      os << "surface interaction: quadrature point " << p.qp << " of facet " << p.facet << " of body " << p.body
         << " lies on triangle " << p.targets[t] << " of body " << p.otherBody << " (r = " << st[t].distance
         << "): the surfaces touch or interpenetrate";
      throw NumericalError(os.str());
    }
    if (nt == 1) break;
    Real* g = withTangent ? Jrho[t] : nullptr;
    rho[t] = npf == 4 ? method3BlendDistance3D<4>(z, q, st[t].region, smoothing_, g)
                      : method3BlendDistance3D<3>(z, q, st[t].region, smoothing_, g);
    if (rho[t] < rho[closest]) closest = t;
  }
  Real w[kMaxBlendTargets3D];
  blendWeights(rho, nt, closest, smoothing_, w);
  const int nf = 3 * npf;
  for (int i = 0; i < nf; ++i) {
    out.f[i] = 0.0;
    for (int t = 0; t < nt; ++t) out.f[i] += w[t] * f[t][i];
  }
  if (!withTangent) return st[closest];
  const int ncol = 3 * nc;
  for (int i = 0; i < nf; ++i)
    for (int c = 0; c < ncol; ++c) out.K[i][c] = 0.0;
  for (int t = 0; t < nt; ++t) {
    int colOf[21];  // column of the kernel's z entry j
    for (int j = 0; j < nz; ++j) colOf[j] = j < nf ? j : 3 * col[t][(j - nf) / 3] + (j - nf) % 3;
    const Real* K = Kt[t];
    for (int i = 0; i < nf; ++i) {
      for (int j = 0; j < nz; ++j) out.K[i][colOf[j]] += w[t] * K[i * nz + j];
      if (nt == 1) continue;
      const Real g = w[t] * (out.f[i] - f[t][i]) / smoothing_;
      for (int j = 0; j < nz; ++j) out.K[i][colOf[j]] += g * Jrho[t][j];
    }
  }
  return st[closest];
}

PairState SurfaceInteraction::evaluatePair(const Real* coords, const InteractionPair& p, PairContribution& out,
                                           bool withTangent) const {
  if (curvedFacets3D())
    throw std::logic_error("surface interaction: pairs of curved 3D facets fill a CurvedPairContribution");
  return std::visit(
      [&](const auto& potential) {
        return dim_ == 3 ? evaluatePair3D(potential, coords, p, out, withTangent)
                         : evaluatePairWith(potential, coords, p, out, withTangent);
      },
      kernel_);
}

PairState SurfaceInteraction::evaluatePair(const Real* coords, const InteractionPair& p, CurvedPairContribution& out,
                                           bool withTangent) const {
  if (!curvedFacets3D())
    throw std::logic_error("surface interaction: a CurvedPairContribution holds a pair of curved 3D facets");
  return std::visit(
      [&](const auto& potential) { return evaluateCurvedPair3D(potential, coords, p, out, withTangent); }, kernel_);
}

template <class P>
PairState SurfaceInteraction::evaluatePairWith(const P& potential, const Real* coords, const InteractionPair& p,
                                               PairContribution& out, bool withTangent) const {
  if (curved(p.body) || curved(p.otherBody)) return evaluateCurvedPair(potential, coords, p, out, withTangent);
  const mesh::Surface& sk = surfaces_[p.body];
  const mesh::Surface& sl = surfaces_[p.otherBody];
  out.dim = 2;
  out.numRowNodes = 2;
  out.rowNodes[0] = out.colNodes[0] = sk.facets[2 * p.facet];
  out.rowNodes[1] = out.colNodes[1] = sk.facets[2 * p.facet + 1];
  int nc = 2;
  auto column = [&](LocalIndex node) {  // index of node in out.colNodes, appended if new
    int c = 0;
    while (c < nc && out.colNodes[c] != node) ++c;
    if (c == nc) out.colNodes[nc++] = node;
    return c;
  };
  // z of target t: the point's segment (4) then the target's nodes (4);
  // col[t][a]: column of the target's node a
  const int nt = p.numTargets;
  Real z[kMaxBlendTargets][8];
  int col[kMaxBlendTargets][2];
  for (int t = 0; t < nt; ++t)
    for (int a = 0; a < 2; ++a) {
      col[t][a] = column(sl.facets[2 * p.targets[t] + a]);
      for (int i = 0; i < 2; ++i) {
        z[t][2 * a + i] = coords[2 * std::size_t(out.colNodes[a]) + i];
        z[t][4 + 2 * a + i] = coords[2 * std::size_t(out.colNodes[col[t][a]]) + i];
      }
    }
  out.numColNodes = nc;
  if (z[0][0] == z[0][2] && z[0][1] == z[0][3]) {
    std::ostringstream os;
    os << "surface interaction: segment " << p.facet << " of body " << p.body << " has zero length";
    throw NumericalError(os.str());
  }
  const auto law = this->law(potential, p.body, p.otherBody);
  const Real xi = rule_.points[p.qp], w = rule_.weights[p.qp];
  const bool axi = options_.formulation == Formulation::Axisymmetric;
  const Real* dA = referenceAreaOf(p);
  auto kernel = [&](int t, Real f[4], Real (*K)[8], Real* Jr) {
    return axi ? method3Pair<Formulation::Axisymmetric>(z[t], xi, w, law, f, K, Jr, dA)
               : method3Pair<Formulation::PlaneStrain>(z[t], xi, w, law, f, K, Jr, dA);
  };

  if (nt == 1) {  // the closest segment alone (no smoothing, or no other segment near)
    Real K[4][8];
    const PairState st = kernel(0, out.f, withTangent ? K : nullptr, nullptr);
    if (!(st.distance > 0.0) || !allFinite(out.f)) throwContact(p, p.targets[0], st.distance);
    if (withTangent)
      for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 8; ++j) out.K[i][j] = K[i][j];
    return st;
  }

  // Softmin blend f = sum_s w_s f_s over rho_s = r_s + delta P_s (see the
  // header). The targets come from the last updatePairs; the weights use the
  // current coordinates. Jrho[t]: d rho_t / dz in columns of out.colNodes.
  constexpr int kCols = 2 * kMaxContributionNodes;
  Real f[kMaxBlendTargets][4], K[kMaxBlendTargets][4][8], rho[kMaxBlendTargets] = {};
  Real Jrho[kMaxBlendTargets][kCols] = {};
  PairState st[kMaxBlendTargets];
  const Real delta = smoothing_;
  int closest = 0;
  for (int t = 0; t < nt; ++t) {
    Real Jr[8], Jp[8];
    st[t] = kernel(t, f[t], withTangent ? K[t] : nullptr, Jr);
    if (!(st[t].distance > 0.0) || !allFinite(f[t])) throwContact(p, p.targets[t], st[t].distance);
    const Real x[2] = {(1.0 - xi) * z[t][0] + xi * z[t][2], (1.0 - xi) * z[t][1] + xi * z[t][3]};
    LocalIndex far;
    rho[t] = st[t].distance + vertexPenalty(coords, p.otherBody, p.targets[t], x, st[t].region,
                                            withTangent ? Jp : nullptr, withTangent ? &far : nullptr);
    if (rho[t] < rho[closest]) closest = t;
    if (!withTangent) continue;
    const int farCol = far >= 0 ? column(far) : -1;
    for (int i = 0; i < 2; ++i) {
      Jrho[t][i] += Jr[i] + (1.0 - xi) * Jp[i];
      Jrho[t][2 + i] += Jr[2 + i] + xi * Jp[i];
      for (int a = 0; a < 2; ++a) Jrho[t][2 * col[t][a] + i] += Jr[4 + 2 * a + i] + Jp[2 + 2 * a + i];
      if (farCol >= 0) Jrho[t][2 * farCol + i] += Jp[6 + i];
    }
  }
  out.numColNodes = nc;
  Real wt[kMaxBlendTargets];
  blendWeights(rho, nt, closest, delta, wt);
  for (int i = 0; i < 4; ++i) {
    out.f[i] = 0.0;
    for (int t = 0; t < nt; ++t) out.f[i] += wt[t] * f[t][i];
  }
  if (!withTangent) return st[closest];

  // K = sum_s w_s K_s + sum_s f_s (x) dw_s with dw_s = (w_s/delta)(-drho_s + sum_t w_t drho_t), i.e.
  // K = sum_s w_s [K_s + (f - f_s) (x) drho_s / delta]  (no cancellation of terms of size f/delta)
  const int ncol = 2 * nc;
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < ncol; ++c) out.K[i][c] = 0.0;
  for (int t = 0; t < nt; ++t) {
    for (int j = 0; j < 8; ++j) {
      const int c = j < 4 ? j : 2 * col[t][(j - 4) / 2] + j % 2;
      for (int i = 0; i < 4; ++i) out.K[i][c] += wt[t] * K[t][i][j];
    }
    for (int i = 0; i < 4; ++i) {
      const Real g = wt[t] * (out.f[i] - f[t][i]) / delta;
      for (int c = 0; c < ncol; ++c) out.K[i][c] += g * Jrho[t][c];
    }
  }
  return st[closest];
}

template <class P>
PairState SurfaceInteraction::evaluateCurvedPair(const P& potential, const Real* coords, const InteractionPair& p,
                                                 PairContribution& out, bool withTangent) const {
  const mesh::Surface& sk = surfaces_[p.body];
  const mesh::Surface& sl = surfaces_[p.otherBody];
  const int ne = sk.nodesPerFacet, ns = sl.nodesPerFacet, nf = 2 * ne, nt = p.numTargets;
  out.dim = 2;
  out.numRowNodes = ne;
  int nc = ne;
  for (int a = 0; a < ne; ++a) out.rowNodes[a] = out.colNodes[a] = sk.facets[std::size_t(p.facet) * ne + a];
  auto column = [&](LocalIndex node) {  // index of node in out.colNodes, appended if new
    int c = 0;
    while (c < nc && out.colNodes[c] != node) ++c;
    if (c == nc) out.colNodes[nc++] = node;
    return c;
  };
  const auto law = this->law(potential, p.body, p.otherBody);
  const Real xi = rule_.points[p.qp], w = rule_.weights[p.qp];
  const bool axi = options_.formulation == Formulation::Axisymmetric;
  const Real* dA = referenceAreaOf(p);
  const Real delta = nt > 1 ? smoothing_ : 0.0;
  Real x[2] = {0.0, 0.0};
  {
    Real N[3], dN[3];
    if (ne == 3) lineShape<3>(xi, N, dN);
    else lineShape<2>(xi, N, dN);
    for (int a = 0; a < ne; ++a)
      for (int i = 0; i < 2; ++i) x[i] += N[a] * coords[2 * std::size_t(out.rowNodes[a]) + i];
  }
  constexpr int kz = 18;  // the most z entries: 2 (3 + 2 * 3)
  Real f[kMaxBlendTargets][6], rho[kMaxBlendTargets] = {}, K[kMaxBlendTargets][6 * kz], Jrho[kMaxBlendTargets][kz];
  int colOf[kMaxBlendTargets][kz];  // column of z entry j
  int nz[kMaxBlendTargets];          // z entries of target t: without the neighbour when it plays no part
  PairState st[kMaxBlendTargets];
  int closest = 0;
  for (int t = 0; t < nt; ++t) {
    // z: the point's segment, the target, and the target's neighbour at the vertex x projects onto
    Real z[kz], eta, foot[2];
    int region;
    const LocalIndex* target = &sl.facets[std::size_t(p.targets[t]) * ns];
    for (int a = 0; a < ne; ++a)
      for (int i = 0; i < 2; ++i) z[2 * a + i] = coords[2 * std::size_t(out.rowNodes[a]) + i], colOf[t][2 * a + i] = 2 * a + i;
    for (int a = 0; a < ns; ++a) {
      const int c = column(target[a]);
      for (int i = 0; i < 2; ++i) z[nf + 2 * a + i] = coords[2 * std::size_t(target[a]) + i], colOf[t][nf + 2 * a + i] = 2 * c + i;
    }
    if (ns == 3) projectOntoCurve<3>(x, z + nf, eta, foot, region);
    else projectOntoCurve<2>(x, z + nf, eta, foot, region);
    const CurveFoot projection{eta, region};  // the kernel takes it: one projection per target
    const LocalIndex n = delta > 0.0 && region != 0 ? neighbours_[p.otherBody][2 * std::size_t(p.targets[t]) + region - 1] : -1;
    int neighbourEnd = -1;
    nz[t] = nf + 2 * ns * (n >= 0 ? 2 : 1);
    for (int a = 0; n >= 0 && a < ns; ++a) {  // the neighbour's nodes
      const LocalIndex node = sl.facets[std::size_t(n) * ns + a];
      const int c = column(node);
      for (int i = 0; i < 2; ++i) z[nf + 2 * ns + 2 * a + i] = coords[2 * std::size_t(node) + i], colOf[t][nf + 2 * ns + 2 * a + i] = 2 * c + i;
      if (a < 2 && node == target[region - 1]) neighbourEnd = a;
    }
    Real* Kt = withTangent ? K[t] : nullptr;
    auto run = [&](auto form, auto e, auto s) {
      constexpr Formulation F = decltype(form)::value;
      constexpr int NE = decltype(e)::value, NS = decltype(s)::value;
      return n >= 0 ? method3CurvedPair<F, NE, NS, true>(z, xi, w, law, projection, neighbourEnd, delta, dA, f[t],
                                                         rho[t], Kt, Jrho[t])
                    : method3CurvedPair<F, NE, NS, false>(z, xi, w, law, projection, -1, delta, dA, f[t], rho[t], Kt,
                                                          Jrho[t]);
    };
    using Axi = std::integral_constant<Formulation, Formulation::Axisymmetric>;
    using Plane = std::integral_constant<Formulation, Formulation::PlaneStrain>;
    using Two = std::integral_constant<int, 2>;
    using Three = std::integral_constant<int, 3>;
    auto byTarget = [&](auto form, auto e) { return ns == 3 ? run(form, e, Three{}) : run(form, e, Two{}); };
    auto byPoint = [&](auto form) { return ne == 3 ? byTarget(form, Three{}) : byTarget(form, Two{}); };
    st[t] = axi ? byPoint(Axi{}) : byPoint(Plane{});
    bool finite = true;
    for (int i = 0; i < nf; ++i) finite = finite && std::isfinite(f[t][i]);
    if (!(st[t].distance > 0.0) || !finite) throwContact(p, p.targets[t], st[t].distance);
    if (rho[t] < rho[closest]) closest = t;
  }
  out.numColNodes = nc;
  blendContributions(out, nt, nf, 2 * nc, rho, closest, delta, &f[0][0], 6, &K[0][0], 6 * kz, nz, &colOf[0][0],
                     &Jrho[0][0], kz, withTangent);
  return st[closest];
}

template <class P>
PairState SurfaceInteraction::evaluateCurvedPair3D(const P& potential, const Real* coords, const InteractionPair& p,
                                                   CurvedPairContribution& out, bool withTangent) const {
  const mesh::Surface& sk = surfaces_[p.body];
  const mesh::Surface& sl = surfaces_[p.otherBody];
  const int ne = sk.nodesPerFacet, ns = sl.nodesPerFacet, nf = 3 * ne, nt = p.numTargets, nz = 3 * (ne + ns);
  out.dim = 3;
  out.numRowNodes = ne;
  int nc = ne;
  for (int a = 0; a < ne; ++a) out.rowNodes[a] = out.colNodes[a] = sk.facets[std::size_t(p.facet) * ne + a];
  auto column = [&](LocalIndex node) {  // index of node in out.colNodes, appended if new
    int c = 0;
    while (c < nc && out.colNodes[c] != node) ++c;
    if (c == nc) out.colNodes[nc++] = node;
    return c;
  };
  const auto law = this->law(potential, p.body, p.otherBody);
  const FacetPoint& q = facetRules_[p.body][p.qp];
  const Real* dA = referenceAreaOf(p);
  const Real delta = nt > 1 ? smoothing_ : 0.0;
  constexpr int kz = 54;  // the most z entries: 3 (9 + 9)
  Real f[kMaxBlendTargets3D][27], rho[kMaxBlendTargets3D] = {}, Jrho[kMaxBlendTargets3D][kz];
  Real K[kMaxBlendTargets3D][27 * kz];
  int colOf[kMaxBlendTargets3D][kz];  // column of z entry j
  PairState st[kMaxBlendTargets3D];
  int closest = 0;
  for (int t = 0; t < nt; ++t) {
    Real z[kz];
    const LocalIndex* target = &sl.facets[std::size_t(p.targets[t]) * ns];
    for (int a = 0; a < ne; ++a)
      for (int i = 0; i < 3; ++i) z[3 * a + i] = coords[3 * std::size_t(out.rowNodes[a]) + i], colOf[t][3 * a + i] = 3 * a + i;
    for (int a = 0; a < ns; ++a) {
      const int c = column(target[a]);
      for (int i = 0; i < 3; ++i) z[nf + 3 * a + i] = coords[3 * std::size_t(target[a]) + i], colOf[t][nf + 3 * a + i] = 3 * c + i;
    }
    Real* Kt = withTangent ? K[t] : nullptr;
    auto run = [&](auto e, auto s) {
      constexpr int NF = decltype(e)::value, NS = decltype(s)::value;
      const PatchFoot foot = facetFootOnTarget<NF, NS>(z, q);  // one projection per target
      return method3CurvedPair3D<NF, NS>(z, q, law, foot, delta, dA, f[t], rho[t], Kt, Jrho[t]);
    };
    st[t] = withCurvedFacet(ne, [&](auto e) { return withCurvedFacet(ns, [&](auto s) { return run(e, s); }); });
    bool finite = true;
    for (int i = 0; i < nf; ++i) finite = finite && std::isfinite(f[t][i]);
    if (!(st[t].distance > 0.0) || !finite) throwContact(p, p.targets[t], st[t].distance, "facet");
    if (rho[t] < rho[closest]) closest = t;
  }
  out.numColNodes = nc;
  int nzOf[kMaxBlendTargets3D];
  for (int t = 0; t < nt; ++t) nzOf[t] = nz;
  blendContributions(out, nt, nf, 3 * nc, rho, closest, delta, &f[0][0], 27, &K[0][0], 27 * kz, nzOf,
                     &colOf[0][0], &Jrho[0][0], kz, withTangent);
  return st[closest];
}

void SurfaceInteraction::setReferenceConfiguration(const Real* coords) {
  std::vector<Real> areas(surfaces_.empty() ? 0 : pointIndex(numBodies() - 1, surfaces_.back().numFacets(), 0));
  for (int k = 0; k < numBodies(); ++k) {
    const mesh::Surface& sk = surfaces_[k];
    const int npf = sk.nodesPerFacet;
    for (LocalIndex e = 0; e < sk.numFacets(); ++e) {
      const LocalIndex* nodes = &sk.facets[std::size_t(e) * npf];
      for (int q = 0; q < int(pointsPerFacet(k)); ++q) {
        Real dA;
        if (dim_ == 3) {  // |G1 x G2| w, as da of Method3Kernel3D.hpp in the undeformed facet
          const FacetPoint& fq = facetRules_[k][q];
          Real g[2][3] = {};
          for (int a = 0; a < npf; ++a)
            for (int i = 0; i < 3; ++i)
              for (int d = 0; d < 2; ++d) g[d][i] += fq.dN[d][a] * coords[3 * std::size_t(nodes[a]) + i];
          const Real m[3] = {g[0][1] * g[1][2] - g[0][2] * g[1][1], g[0][2] * g[1][0] - g[0][0] * g[1][2],
                             g[0][0] * g[1][1] - g[0][1] * g[1][0]};
          dA = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]) * fq.weight;
        } else {  // |T| w, times 2 pi X_0 in axisymmetry, as da of Method3Kernel.hpp (T = dX/dxi)
          Real N[3], dN[3], X[2] = {0.0, 0.0}, T[2] = {0.0, 0.0};
          if (npf == 3) lineShape<3>(rule_.points[q], N, dN);
          else lineShape<2>(rule_.points[q], N, dN);
          for (int a = 0; a < npf; ++a)
            for (int i = 0; i < 2; ++i) {
              X[i] += N[a] * coords[2 * std::size_t(nodes[a]) + i];
              T[i] += dN[a] * coords[2 * std::size_t(nodes[a]) + i];
            }
          dA = std::hypot(T[0], T[1]) * rule_.weights[q];
          if (options_.formulation == Formulation::Axisymmetric) dA *= 2.0 * kPi * X[0];
        }
        if (!(dA > 0.0) || !std::isfinite(dA))
          throw InputError("surface interaction: facet " + std::to_string(e) + " of body " + std::to_string(k) +
                           " has reference area element " + std::to_string(dA) + " at its point " +
                           std::to_string(q) + " (a degenerate facet, or on the axis)");
        areas[pointIndex(k, e, q)] = dA;
      }
    }
  }
  referenceAreas_ = std::move(areas);
}

void SurfaceInteraction::beginEvaluation() {
  if (options_.surfaceDensity == SurfaceDensity::ReferenceArea && referenceAreas_.empty())
    throw std::logic_error("surface interaction: the reference surface density needs setReferenceConfiguration "
                           "before the first evaluation");
  summary_.resultant.assign(surfaces_.size(), {0.0, 0.0, 0.0});
  summary_.minDistance = std::numeric_limits<Real>::infinity();
  summary_.numVertexProjections = 0;
}

void SurfaceInteraction::accumulate(const InteractionPair& p, const PairState& st, const Real* f, int rows,
                                    int dim) {
  auto& R = summary_.resultant[p.body];
  for (int r = 0; r < rows; ++r) R[r % dim] -= f[r];
  summary_.minDistance = std::min(summary_.minDistance, st.distance);
  if (st.region != 0) ++summary_.numVertexProjections;
}

Real SurfaceInteraction::lebesgue() const {
  Real most = 1.0;
  for (int l = 0; l < numBodies(); ++l)
    if (curved(l)) most = std::max(most, lebesgueConstant(dim_, surfaces_[l].nodesPerFacet));
  return most;
}

Real SurfaceInteraction::blendReach() const {
  bool anyCurved = false;
  for (int l = 0; l < numBodies(); ++l) anyCurved = anyCurved || curved(l);
  return dim_ == 2 || anyCurved ? (kSmoothingRange + 1.0) * smoothing_ : 0.0;
}

Real SurfaceInteraction::largestCoverDeviation(const Real* coords) const {
  Real most = 0.0;
  std::vector<Real> points;
  for (int l = 0; l < numBodies(); ++l) most = std::max(most, cover(coords, l, points));
  return most;
}

Real SurfaceInteraction::readingReach(Real radius, Real deviation) const {
  // couplings: the nearest facet within cutoff + skin + blend + 2 deviation, then every facet within
  // that distance + 2 skin + blend + 4 deviation (updatePairs reads less: radius = cutoff, skin 0)
  const Real skin = std::max(radius - cutoff_, 0.0) * lebesgue();
  return cutoff_ + 3.0 * skin + 2.0 * blendReach() + 6.0 * deviation;
}

std::vector<std::pair<LocalIndex, LocalIndex>> SurfaceInteraction::couplings(const Real* coords,
                                                                             Real radius) const {
  const int nb = numBodies();
  // A point at distance d from body l pairs, after every node moved by less
  // than m, with a facet within d + 4 m of its present position; m < skin/2
  // with skin = radius - cutoff, and a point farther than the radius stays
  // beyond the cutoff. 2D blends reach (kSmoothingRange + 1) delta farther.
  // Curved facets: their covers are searched (within the cover deviation of
  // the facets), and a node moving by m moves a facet by up to its Lebesgue
  // constant times m (lebesgueConstant).
  const Real blend = blendReach();
  std::vector<Real> deviation(nb, 0.0);
  std::vector<std::vector<Real>> coverPoints(nb);
  Real margin = 0.0;
  for (int l = 0; l < nb; ++l) {
    deviation[l] = cover(coords, l, coverPoints[l]);
    margin = std::max(margin, 2.0 * deviation[l]);
  }
  const Real skin = std::max(radius - cutoff_, 0.0) * lebesgue();
  const std::vector<char> bodies = bodiesWithin(coords, cutoff_ + skin + blend + margin);
  std::vector<std::unique_ptr<ClosestPointSearch>> search(nb);
  for (int l = 0; l < nb; ++l) {
    search[l] = makeClosestPointSearch(dim_, options_.search);
    search[l]->build(dim_ == 3 && curved(l) ? coverPoints[l].data() : coords, targets_[l]);
  }
  std::vector<std::pair<LocalIndex, LocalIndex>> out;
  std::vector<LocalIndex> near, reach;  // reach: the target nodes the current facet's points can pair with
  auto visit = [&](int k, LocalIndex, int, const Real* x) {
    for (int l = 0; l < nb; ++l) {
      if (!bodies[std::size_t(k) * nb + l]) continue;
      const Real dev = 2.0 * deviation[l];
      const Projection pr = search[l]->project(x, cutoff_ + skin + blend + dev);
      if (!pr.found()) continue;
      near.clear();
      search[l]->facetsNearPoint(x, pr.distance + 2.0 * skin + blend + 2.0 * dev, near);
      // a curved facet (the pieces of its cover) brings its nodes, and a curved segment those of its neighbours
      const mesh::Surface& tl = curved(l) ? surfaces_[l] : targets_[l];
      const int pieces = curved(l) ? coverPieces(l) : 1;
      for (LocalIndex c : near) {
        const LocalIndex s = c / pieces;
        for (int j = 0; j < tl.nodesPerFacet; ++j) reach.push_back(tl.facets[std::size_t(s) * tl.nodesPerFacet + j]);
        if (!curved(l) || dim_ == 3) continue;
        for (int end = 0; end < 2; ++end)
          if (const LocalIndex n = neighbours_[l][2 * std::size_t(s) + end]; n >= 0)
            for (int j = 0; j < 3; ++j) reach.push_back(tl.facets[3 * std::size_t(n) + j]);
      }
    }
  };
  // once per facet: its nodes with its own and with every node it can reach (each pair once)
  auto facetDone = [&](int k, LocalIndex e) {
    if (reach.empty()) return;
    const mesh::Surface& sk = surfaces_[k];
    const int npf = sk.nodesPerFacet;
    const LocalIndex* nodes = &sk.facets[std::size_t(e) * npf];
    reach.insert(reach.end(), nodes, nodes + npf);
    std::sort(reach.begin(), reach.end());
    reach.erase(std::unique(reach.begin(), reach.end()), reach.end());
    for (int a = 0; a < npf; ++a)
      for (LocalIndex n : reach) out.emplace_back(nodes[a], n);
    reach.clear();
  };
  forEachPoint(coords, visit, facetDone);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace cgcm::interaction
