#pragma once
// Method 3 driver for 2D surfaces (plane strain, axisymmetric): builds the
// interaction pair list by closest-point search and evaluates all pairs
// into scatter-friendly element contributions. Independent of Tpetra: the
// assembly package scatters the outputs.
//
// Every quadrature point of every surface segment of body k is projected
// onto the surface of every other body l; the pair (k, e, q) -> (l, s) is
// kept when the distance is <= the cutoff (pairs beyond it are counted).
// Usage per nonlinear-solver evaluation:
//     si.updatePairs(coords);                  // search (once per evaluation)
//     si.evaluate(coords, contributions);      // f and K of every pair
// A matrix graph covering all pairs that can appear while the nodes move
// by less than (radius - cutoff)/2 comes from couplings(coords, radius).
#include <array>
#include <memory>
#include <utility>
#include <vector>

#include "cgcm/core/Types.hpp"
#include "cgcm/interaction/ClosestPointSearch.hpp"
#include "cgcm/interaction/Method3Kernel.hpp"
#include "cgcm/interaction/PairPotential.hpp"
#include "cgcm/interaction/Quadrature.hpp"
#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::interaction {

struct SurfaceInteractionOptions {
  Formulation formulation = Formulation::PlaneStrain;
  int quadraturePoints = 4;  ///< Gauss points per segment (>= 1)
  /// Absolute cutoff distance r_c: quadrature points farther than r_c from
  /// the other body are skipped. <= 0 selects the default 10 r0; infinity
  /// disables pruning.
  Real cutoff = 0.0;
  /// Fraction of the cutoff over which the traction is blended to zero:
  /// T is multiplied by a C1 smoothstep on [(1 - taper) r_c, r_c], so the
  /// residual and its tangent stay continuous when a point crosses r_c (a
  /// sharp cutoff makes the residual jump by T(r_c) da there, and Newton
  /// stalls at that level in wide adhesive contacts). 0: sharp cutoff.
  Real cutoffTaper = 0.2;
  SearchMethod search = SearchMethod::Tree;  ///< closest-point search structure
};

/// One interaction pair: quadrature point `qp` of segment `facet` of body
/// `body` projects onto segment `target` of body `otherBody`. Segment ids
/// index the facets of the bodies' surfaces.
struct InteractionPair {
  int body = 0;
  LocalIndex facet = 0;
  int qp = 0;
  int otherBody = 0;
  LocalIndex target = 0;
};

/// Contribution of one pair, ready to scatter. Dof ordering is node-major,
/// 2 components per node: f[2a + i] belongs to rowNodes[a], component i;
/// K[2a + i][2b + j] = d f[2a + i] / d x_j(colNodes[b]).
/// colNodes = {rowNodes[0], rowNodes[1], target node a, target node b}.
struct PairContribution {
  LocalIndex rowNodes[2];
  LocalIndex colNodes[4];
  Real f[4];
  Real K[4][8];
};

/// Counts and diagnostics of the last updatePairs / evaluate.
struct InteractionSummary {
  Real cutoff = 0.0;          ///< absolute cutoff used
  Real taperStart = 0.0;      ///< distance where the taper starts, (1 - cutoffTaper) r_c
  Real cutoffTraction = 0.0;  ///< |T| at the taper start for the pair of bodies with the largest density
                              ///< product: the largest traction the cutoff changes
  /// Part of the work of adhesion that the taper and cutoff remove,
  /// -integral of T (1 - S) dr from r_S0 to infinity, over w (0 without adhesion).
  Real neglectedWorkFraction = 0.0;
  LocalIndex numQuadraturePoints = 0;   ///< (point, other body) combinations searched
  LocalIndex numPairs = 0;              ///< within the cutoff (evaluated)
  LocalIndex numBeyondCutoff = 0;       ///< skipped by the cutoff
  LocalIndex numVertexProjections = 0;  ///< pairs whose projection is a vertex (last evaluate)
  Real minDistance = 0.0;               ///< smallest r over the pairs (last evaluate; inf if none)
  /// Per body (index = body id): resultant of the interaction forces applied
  /// to it, sum over its nodes of -f_C (last evaluate; components x, y).
  std::vector<std::array<Real, 2>> resultant;
};

/// Part of the work of adhesion w that a cutoff r_c with a taper from
/// taperStart removes: -integral of Phi/beta (1 - S) dr over w (0 when the
/// potential has no adhesion or r_c is infinite).
Real neglectedWorkFraction(const PairPotential& potential, Real taperStart, Real cutoff);

class SurfaceInteraction {
 public:
  /// surfaces: one per body, index = body id (mesh::Mesh::surfaces); segments
  /// only (2D). densities: reference density beta0 per body (same size).
  /// Throws InputError for inconsistent arguments.
  SurfaceInteraction(std::vector<mesh::Surface> surfaces, std::vector<Real> densities,
                     std::shared_ptr<const PairPotential> potential, SurfaceInteractionOptions options = {});

  const SurfaceInteractionOptions& options() const { return options_; }
  const PairPotential& potential() const { return *potential_; }
  const GaussRule& quadrature() const { return rule_; }
  int numBodies() const { return int(surfaces_.size()); }
  const mesh::Surface& surface(int body) const { return surfaces_[body]; }
  Real density(int body) const { return densities_[body]; }
  /// Absolute cutoff in use.
  Real cutoff() const { return cutoff_; }

  /// Rebuilds the search structures at `coords` (2 entries per node, global
  /// node ids) and the pair list. Call once per evaluation.
  void updatePairs(const Real* coords);
  void updatePairs(const std::vector<Real>& coords) { updatePairs(coords.data()); }
  const std::vector<InteractionPair>& pairs() const { return pairs_; }

  /// Evaluates one pair at `coords` (thread-safe: usable inside a parallel
  /// loop over pairs()). Without tangent K is left untouched. Returns the
  /// pair's state; throws NumericalError if r = 0 or the result is not finite.
  PairState evaluatePair(const Real* coords, const InteractionPair& pair, PairContribution& out,
                         bool withTangent = true) const;

  /// Evaluates all pairs of the current list at `coords` (which may differ
  /// from the coordinates of updatePairs: the list is kept, each projection
  /// is recomputed on its stored target segment). Fills out (resized to
  /// pairs().size()) and the resultants and counts of summary().
  void evaluate(const Real* coords, std::vector<PairContribution>& out, bool withTangent = true);
  void evaluate(const std::vector<Real>& coords, std::vector<PairContribution>& out,
                bool withTangent = true) {
    evaluate(coords.data(), out, withTangent);
  }

  /// Scatter form: calls scatter(const PairContribution&) for every pair.
  template <class Scatter>
  void evaluate(const Real* coords, Scatter&& scatter, bool withTangent = true) {
    beginEvaluation();
    PairContribution c;
    for (const InteractionPair& p : pairs_) {
      const PairState st = evaluatePair(coords, p, c, withTangent);
      accumulate(p, st, c);
      scatter(static_cast<const PairContribution&>(c));
    }
  }

  /// Sorted, unique (row node, column node) couplings of every pair that can
  /// occur for quadrature points within `radius` of another body: for each
  /// segment e and each segment s of another body whose bounding box comes
  /// within `radius` of e's, the couplings of e's nodes with e's and s's
  /// nodes. Use radius > cutoff so that the graph survives small motions.
  std::vector<std::pair<LocalIndex, LocalIndex>> couplings(const Real* coords, Real radius) const;
  std::vector<std::pair<LocalIndex, LocalIndex>> couplings(const std::vector<Real>& coords,
                                                           Real radius) const {
    return couplings(coords.data(), radius);
  }

  const InteractionSummary& summary() const { return summary_; }

  /// Traction law of the bodies k, l: T(r) = beta_k beta_l Phi(r)/beta S(r),
  /// with the cutoff taper S = 1 below taperStart, 1 - 3 s^2 + 2 s^3 with
  /// s = (r - taperStart)/(cutoff - taperStart) up to the cutoff, 0 beyond.
  struct Law {
    const PairPotential* potential;
    Real betaProduct;
    Real taperStart;
    Real cutoff;
    void operator()(Real r, Real& T, Real& dT) const {
      potential->halfSpaceWithDerivative(r, T, dT);
      T *= betaProduct;
      dT *= betaProduct;
      if (r >= cutoff) {
        T = dT = 0.0;
        return;
      }
      if (r <= taperStart) return;
      const Real width = cutoff - taperStart, s = (r - taperStart) / width;
      const Real S = 1.0 - s * s * (3.0 - 2.0 * s), dS = -6.0 * s * (1.0 - s) / width;
      dT = dT * S + T * dS;
      T *= S;
    }
  };
  /// The law between bodies k and l.
  Law law(int k, int l) const {
    return Law{potential_.get(), strength_ * densities_[k] * densities_[l], taperStart_, cutoff_};
  }

  /// Scales every traction by `strength` > 0 (the potential's epsilon times
  /// strength: w and sigma_max scale with it, r_S0 does not). Default 1.
  void setStrength(Real strength);
  Real strength() const { return strength_; }

 private:
  void beginEvaluation();
  void accumulate(const InteractionPair& p, const PairState& st, const PairContribution& c);

  std::vector<mesh::Surface> surfaces_;
  std::vector<Real> densities_;
  std::shared_ptr<const PairPotential> potential_;
  SurfaceInteractionOptions options_;
  GaussRule rule_;
  Real cutoff_ = 0.0;
  Real taperStart_ = 0.0;
  Real strength_ = 1.0;
  std::vector<std::unique_ptr<ClosestPointSearch>> search_;
  std::vector<InteractionPair> pairs_;
  InteractionSummary summary_;
};

}  // namespace cgcm::interaction
