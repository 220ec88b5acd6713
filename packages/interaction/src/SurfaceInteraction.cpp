#include "cgcm/interaction/SurfaceInteraction.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "cgcm/core/Error.hpp"

namespace cgcm::interaction {

SurfaceInteraction::SurfaceInteraction(std::vector<mesh::Surface> surfaces, std::vector<Real> densities,
                                       std::shared_ptr<const PairPotential> potential,
                                       SurfaceInteractionOptions options)
    : surfaces_(std::move(surfaces)),
      densities_(std::move(densities)),
      potential_(std::move(potential)),
      options_(options) {
  if (!potential_) throw InputError("surface interaction: no pair potential given");
  if (surfaces_.size() != densities_.size()) {
    std::ostringstream os;
    os << "surface interaction: " << surfaces_.size() << " surfaces but " << densities_.size()
       << " densities (one per body)";
    throw InputError(os.str());
  }
  for (std::size_t k = 0; k < surfaces_.size(); ++k) {
    if (surfaces_[k].nodesPerFacet != 2 && surfaces_[k].numFacets() > 0)
      throw InputError("surface interaction: 2D surfaces need 2 nodes per facet (body " + std::to_string(k) +
                       " has " + std::to_string(surfaces_[k].nodesPerFacet) + ")");
    if (!(densities_[k] > 0.0) || !std::isfinite(densities_[k]))
      throw InputError("surface interaction: density of body " + std::to_string(k) +
                       " must be finite and > 0");
  }
  if (options_.quadraturePoints < 1 || options_.quadraturePoints > 64)
    throw InputError("surface interaction: quadraturePoints must be in [1, 64], got " +
                     std::to_string(options_.quadraturePoints));
  if (std::isnan(options_.cutoff)) throw InputError("surface interaction: cutoff is NaN");
  if (!(options_.cutoffTaper >= 0.0 && options_.cutoffTaper < 1.0))
    throw InputError("surface interaction: cutoffTaper must be in [0, 1), got " +
                     std::to_string(options_.cutoffTaper));
  rule_ = gaussLegendreUnit(options_.quadraturePoints);
  cutoff_ = options_.cutoff > 0.0 ? options_.cutoff : 10.0 * potential_->r0();
  taperStart_ = std::isfinite(cutoff_) ? (1.0 - options_.cutoffTaper) * cutoff_ : cutoff_;

  summary_.cutoff = cutoff_;
  summary_.taperStart = taperStart_;
  Real maxProduct = 0.0;
  for (std::size_t k = 0; k < densities_.size(); ++k)
    for (std::size_t l = 0; l < densities_.size(); ++l)
      if (k != l) maxProduct = std::max(maxProduct, densities_[k] * densities_[l]);
  summary_.cutoffTraction =
      std::isfinite(cutoff_) ? maxProduct * std::abs(potential_->halfSpace(taperStart_)) : 0.0;
  summary_.neglectedWorkFraction = neglectedWorkFraction(*potential_, taperStart_, cutoff_);
  summary_.resultant.assign(surfaces_.size(), {0.0, 0.0});
  summary_.minDistance = std::numeric_limits<Real>::infinity();
  search_.resize(surfaces_.size());
  for (auto& s : search_) s = makeClosestPointSearch(2, options_.search);
}

Real neglectedWorkFraction(const PairPotential& potential, Real taperStart, Real cutoff) {
  const Real w = potential.adhesionWorkCoefficient();
  if (!(w > 0.0) || !std::isfinite(cutoff)) return 0.0;
  const SurfaceInteraction::Law unit{&potential, 1.0, taperStart, cutoff};
  auto removed = [&](Real r) {  // Phi/beta (1 - S)
    Real T, dT, Tc, dTc;
    potential.halfSpaceWithDerivative(r, T, dT);
    unit(r, Tc, dTc);
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

void SurfaceInteraction::updatePairs(const Real* coords) {
  const int nb = numBodies();
  for (int l = 0; l < nb; ++l) search_[l]->build(coords, surfaces_[l]);
  pairs_.clear();
  summary_.numQuadraturePoints = 0;
  summary_.numPairs = 0;
  summary_.numBeyondCutoff = 0;
  const int nq = rule_.size();
  for (int k = 0; k < nb; ++k) {
    const mesh::Surface& sk = surfaces_[k];
    for (LocalIndex e = 0; e < sk.numFacets(); ++e) {
      const LocalIndex a = sk.facets[2 * e], b = sk.facets[2 * e + 1];
      for (int q = 0; q < nq; ++q) {
        const Real xi = rule_.points[q];
        const Real x[2] = {(1.0 - xi) * coords[2 * std::size_t(a)] + xi * coords[2 * std::size_t(b)],
                           (1.0 - xi) * coords[2 * std::size_t(a) + 1] + xi * coords[2 * std::size_t(b) + 1]};
        for (int l = 0; l < nb; ++l) {
          if (l == k || search_[l]->numFacets() == 0) continue;
          ++summary_.numQuadraturePoints;
          const Projection pr = search_[l]->project(x, cutoff_);
          if (!pr.found()) {
            ++summary_.numBeyondCutoff;
            continue;
          }
          pairs_.push_back(InteractionPair{k, e, q, l, pr.facet});
        }
      }
    }
  }
  summary_.numPairs = LocalIndex(pairs_.size());
}

PairState SurfaceInteraction::evaluatePair(const Real* coords, const InteractionPair& p,
                                           PairContribution& out, bool withTangent) const {
  const mesh::Surface& sk = surfaces_[p.body];
  const mesh::Surface& sl = surfaces_[p.otherBody];
  out.rowNodes[0] = out.colNodes[0] = sk.facets[2 * p.facet];
  out.rowNodes[1] = out.colNodes[1] = sk.facets[2 * p.facet + 1];
  out.colNodes[2] = sl.facets[2 * p.target];
  out.colNodes[3] = sl.facets[2 * p.target + 1];
  Real z[8];
  for (int a = 0; a < 4; ++a) {
    z[2 * a] = coords[2 * std::size_t(out.colNodes[a])];
    z[2 * a + 1] = coords[2 * std::size_t(out.colNodes[a]) + 1];
  }
  if (z[0] == z[2] && z[1] == z[3]) {
    std::ostringstream os;
    os << "surface interaction: segment " << p.facet << " of body " << p.body << " has zero length";
    throw NumericalError(os.str());
  }
  const Law law = this->law(p.body, p.otherBody);
  const Real xi = rule_.points[p.qp], w = rule_.weights[p.qp];
  Real(*K)[8] = withTangent ? out.K : nullptr;
  const PairState st = options_.formulation == Formulation::Axisymmetric
                           ? method3Pair<Formulation::Axisymmetric>(z, xi, w, law, out.f, K)
                           : method3Pair<Formulation::PlaneStrain>(z, xi, w, law, out.f, K);
  const bool finite = std::isfinite(out.f[0]) && std::isfinite(out.f[1]) && std::isfinite(out.f[2]) &&
                      std::isfinite(out.f[3]);
  if (!(st.distance > 0.0) || !finite) {
    std::ostringstream os;
    os << "surface interaction: quadrature point " << p.qp << " of segment " << p.facet << " of body "
       << p.body << " lies on segment " << p.target << " of body " << p.otherBody << " (r = " << st.distance
       << "): the surfaces touch or interpenetrate";
    throw NumericalError(os.str());
  }
  return st;
}

void SurfaceInteraction::beginEvaluation() {
  summary_.resultant.assign(surfaces_.size(), {0.0, 0.0});
  summary_.minDistance = std::numeric_limits<Real>::infinity();
  summary_.numVertexProjections = 0;
}

void SurfaceInteraction::accumulate(const InteractionPair& p, const PairState& st,
                                    const PairContribution& c) {
  auto& R = summary_.resultant[p.body];
  R[0] -= c.f[0] + c.f[2];
  R[1] -= c.f[1] + c.f[3];
  summary_.minDistance = std::min(summary_.minDistance, st.distance);
  if (st.region != 0) ++summary_.numVertexProjections;
}

void SurfaceInteraction::evaluate(const Real* coords, std::vector<PairContribution>& out, bool withTangent) {
  out.resize(pairs_.size());
  beginEvaluation();
  for (std::size_t i = 0; i < pairs_.size(); ++i) {
    const PairState st = evaluatePair(coords, pairs_[i], out[i], withTangent);
    accumulate(pairs_[i], st, out[i]);
  }
}

std::vector<std::pair<LocalIndex, LocalIndex>> SurfaceInteraction::couplings(const Real* coords,
                                                                             Real radius) const {
  const int nb = numBodies();
  std::vector<std::unique_ptr<ClosestPointSearch>> search(nb);
  for (int l = 0; l < nb; ++l) {
    search[l] = makeClosestPointSearch(2, options_.search);
    search[l]->build(coords, surfaces_[l]);
  }
  std::vector<std::pair<LocalIndex, LocalIndex>> out;
  std::vector<LocalIndex> near;
  for (int k = 0; k < nb; ++k) {
    const mesh::Surface& sk = surfaces_[k];
    for (LocalIndex e = 0; e < sk.numFacets(); ++e) {
      const LocalIndex a = sk.facets[2 * e], b = sk.facets[2 * e + 1];
      const Real lo[2] = {std::min(coords[2 * std::size_t(a)], coords[2 * std::size_t(b)]),
                          std::min(coords[2 * std::size_t(a) + 1], coords[2 * std::size_t(b) + 1])};
      const Real hi[2] = {std::max(coords[2 * std::size_t(a)], coords[2 * std::size_t(b)]),
                          std::max(coords[2 * std::size_t(a) + 1], coords[2 * std::size_t(b) + 1])};
      bool any = false;
      for (int l = 0; l < nb; ++l) {
        if (l == k) continue;
        near.clear();
        search[l]->facetsNear(lo, hi, radius, near);
        const mesh::Surface& sl = surfaces_[l];
        for (LocalIndex s : near) {
          any = true;
          for (LocalIndex row : {a, b})
            for (int j = 0; j < 2; ++j) out.emplace_back(row, sl.facets[2 * s + j]);
        }
      }
      if (any)
        for (LocalIndex row : {a, b})
          for (LocalIndex col : {a, b}) out.emplace_back(row, col);
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace cgcm::interaction
