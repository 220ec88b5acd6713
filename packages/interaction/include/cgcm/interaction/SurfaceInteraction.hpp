#pragma once
// Method 3 driver: builds the interaction pair list by closest-point search
// and evaluates all pairs into scatter-friendly element contributions, for
// 2D surfaces (segments; plane strain, axisymmetric) and 3D surfaces
// (triangles and quadrilaterals). Independent of Tpetra: the assembly
// package scatters the outputs.
//
// Every quadrature point of every surface facet of body k is projected
// onto the surface of every other body l; the pair (k, e, q) -> (l, s) is
// kept when the distance is <= the cutoff (pairs beyond it are counted).
// Pairs of bodies whose surfaces' bounding boxes are farther apart than the
// cutoff are skipped without a search. In 3D the target s is a triangle of
// l's surface with every quad4 facet split into two triangles
// (targetSurface(l)); the projection is onto that triangle's face, edge or
// vertex (Method3Kernel3D.hpp). The projection smoothing below applies in
// 3D with rho_s = r_s + o_s^2/delta, o_s the distance from the foot on the
// triangle's plane to the projection (no neighbour exception: triangles
// projecting onto a common edge or vertex give equal contributions), over
// at most kMaxBlendTargets3D triangles.
// Usage per nonlinear-solver evaluation:
//     si.updatePairs(coords);                  // search (once per evaluation)
//     si.evaluate(coords, contributions);      // f and K of every pair
// A matrix graph covering all pairs that can appear while the nodes move
// by less than (radius - cutoff)/2 comes from couplings(coords, radius).
//
// Smoothed projection: with the closest segment alone, rbar jumps by the
// corner angle where x crosses the bisector of a concave corner of l's
// polyline (the closest segment switches between two segments that both
// hold a foot point), so the residual jumps there and Newton can cycle
// between the two sides. With projectionSmoothing delta > 0 a point's
// contribution is the softmin blend over the segments s of l near x,
//     f = sum_s w_s f_s,  w_s = exp(-rho_s/delta) / sum_t exp(-rho_t/delta),
// with f_s the pair contribution on s and rho_s = r_s + delta P_s, r_s the
// clamped distance. Near a concave corner both feet lie inside their
// segments, P = 0, and the blend is the softmin of the distances:
// continuous across the bisector. A projection onto a vertex (the foot of
// the line beyond s's end by o_s) is penalised by
//     P_s = (o_s/delta)^2 exp(-(o_n/delta)^2),
// o_n the same overshoot of the neighbour n holding the vertex: such a
// projection enters only within about delta of the end where the neighbour
// covers the vertex (flat or concave vertex: o_n = 0; there the closest
// segment switches without a jump, both projections being the vertex), and
// fully where both project onto the vertex (o_n > 0: convex vertex, equal
// contributions). Without the penalty a point at distance r would be blended
// with every segment within sqrt(2 r c delta) along a flat surface (many on
// fine meshes), with rbar tilted towards their vertices: a spurious shear.
// The weights are continuously differentiable in the coordinates, so is the
// residual wherever it was before (away from the clamping kinks of f_s), and
// the tangent includes dw_s = (w_s/delta)(-drho_s + sum_t w_t drho_t).
// Candidates are the segments with rho_s <= rho_min + c delta
// (c = kSmoothingRange), at most kMaxBlendTargets of them (lowest rho).
//
// Curved segments (2D, the Line3 facets of quadratic cells): a point of such
// a segment lies on its curve, and a point of any body is projected onto
// such a body's curved segments (Method3CurvedKernel.hpp), with the same
// blend (the overshoot beyond a vertex measured along the segment's tangent
// there). The search runs over the chords a-mid, mid-b of each curved
// segment (targetSurface: segment s -> chords 2s, 2s + 1), whose distance
// differs from the curve's by at most the chord deviation of the body
// (line3ChordDeviation, refreshed at every search); every segment whose
// chords come that close to the nearest is projected onto exactly.
//
// Curved facets (3D, the TRI6, QUAD8 and QUAD9 faces of quadratic cells):
// the same on curved facets (Method3CurvedKernel3D.hpp): a point lies on its
// curved facet, the projection is onto the target's curved facet (inside, an
// edge or a corner), the blend runs over facets (rho = r + o^2/delta, o the
// offset of x from the facet's normal line at the foot). The search runs
// over each facet's cover (its nodes' grid split into 4 or 8 flat
// triangles; the QUAD8 centre evaluated), whose distance from the facet is
// bounded by coverDeviation; every facet whose cover comes within twice the
// body's largest bound of the nearest is projected onto exactly. A body's
// facets are all linear or all curved, and in 3D so are every body's.
#include <Kokkos_Core.hpp>

#include <array>
#include <memory>
#include <utility>
#include <vector>

#include "cgcm/core/Types.hpp"
#include "cgcm/interaction/ClosestPointSearch.hpp"
#include "cgcm/interaction/Interaction.hpp"
#include "cgcm/interaction/Method3Kernel.hpp"
#include "cgcm/interaction/PairPotential.hpp"
#include "cgcm/interaction/Quadrature.hpp"
#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::interaction {

/// How Method 3 counts the particles of a body's surface layer (doc/theory.md#method-3).
enum class SurfaceDensity {
  /// beta0 over the current area element da: eq. (21) of the paper. Where the surface
  /// stretches (J_s = da/dA > 1, at an opening contact edge) the layer's particles are
  /// counted J_s times.
  CurrentArea,
  /// beta0 over the reference area element dA: the particles beta0 dA of the undeformed
  /// layer, conserved however the surface stretches (Method 1 conserves them exactly).
  ReferenceArea,
};

struct SurfaceInteractionOptions {
  Formulation formulation = Formulation::PlaneStrain;
  /// ReferenceArea needs SurfaceInteraction::setReferenceConfiguration before the first evaluation.
  SurfaceDensity surfaceDensity = SurfaceDensity::CurrentArea;
  /// Gauss points per segment (2D) or per direction of a facet (3D: n^2 per
  /// facet, the collapsed rule on triangles), >= 1.
  int quadraturePoints = 4;
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
  /// Default projection smoothing, as a fraction of the potential's r0.
  static constexpr Real kDefaultProjectionSmoothing = 1e-3;
  /// Width delta (absolute length) of the softmin blend of the projections
  /// onto the segments near the closest one (see above). 0: closest segment
  /// only (the residual jumps at concave corners); < 0 selects the default
  /// kDefaultProjectionSmoothing * r0. Like the cutoff it scales with
  /// SurfaceInteraction::setLengthScale. Search radii of the matrix graph
  /// must exceed cutoff + (kSmoothingRange + 1) delta.
  Real projectionSmoothing = -1.0;
};

/// Most segments one quadrature point is blended over; when more have
/// rho <= rho_min + c delta, those with the lowest rho are kept (counted in
/// InteractionSummary::numTruncatedBlends).
constexpr int kMaxBlendTargets = 4;
/// The same in 3D: the fan of triangles around a vertex of a flat surface
/// (typically 6) all hold the foot of a point above the vertex.
constexpr int kMaxBlendTargets3D = 8;
/// c: candidates of the blend have rho_s <= rho_min + c delta. A segment
/// entering the set has weight <= exp(-30) = 9.4e-14 of the largest one,
/// below the rounding of the assembled residual, so the (discrete) set can
/// change between evaluations without a visible jump; a larger c only adds
/// candidates.
constexpr Real kSmoothingRange = 30.0;
/// Column nodes of one blended contribution: in 2D the point's segment
/// nodes, the nodes of each target segment and the other nodes of a target's
/// neighbour when the target projects onto their common vertex; in 3D the point's
/// facet nodes and three per target triangle (shared nodes are merged).
constexpr int kMaxContributionNodes = 4 + 3 * kMaxBlendTargets3D;
/// The same on curved 3D facets: the point's facet nodes and up to nine per target facet.
constexpr int kMaxCurvedContributionNodes = 9 + 9 * kMaxBlendTargets3D;

/// One interaction pair: quadrature point `qp` of segment `facet` of body
/// `body` and the segments `targets[0 .. numTargets)` of body `otherBody` it
/// is blended over, lowest rho first (one target without smoothing: the
/// closest segment, or when no other segment is near). Segment ids index the
/// facets of the bodies' surfaces.
struct InteractionPair {
  int body = 0;
  LocalIndex facet = 0;
  int qp = 0;
  int otherBody = 0;
  int numTargets = 1;
  LocalIndex targets[kMaxBlendTargets3D] = {};
  /// The closest segment (the one of largest weight).
  LocalIndex target() const { return targets[0]; }
};

/// Columns of a contribution's tangent (dim per column node).
constexpr int kMaxContributionColumns = 3 * kMaxContributionNodes;

/// Contribution of one pair, ready to scatter. Dof ordering is node-major,
/// dim components per node: f[dim a + i] belongs to rowNodes[a], component i;
/// K[dim a + i][dim b + j] = d f[dim a + i] / d x_j(colNodes[b]), b < numColNodes.
/// colNodes = {rowNodes..., nodes of the targets in order, each once}: in 2D
/// {rowNodes, target node a, target node b} for one target; in 3D the facet's
/// nodes, then the target triangle's three. Sized by the most row and column
/// nodes: PairContribution for segments and flat facets, CurvedPairContribution
/// (six times larger) for curved 3D facets.
template <int MaxRowNodes, int MaxColNodes>
struct BasicPairContribution {
  static constexpr int kMaxRows = 3 * MaxRowNodes;
  static constexpr int kMaxColumns = 3 * MaxColNodes;
  int dim = 2;
  int numRowNodes = 2;  ///< nodes of the point's facet: 2 or 3 (segment), 3, 4 (flat facet), 6, 8, 9 (curved)
  LocalIndex rowNodes[MaxRowNodes];
  int numColNodes = 4;
  LocalIndex colNodes[MaxColNodes];
  Real f[kMaxRows];
  Real K[kMaxRows][kMaxColumns];
};
using PairContribution = BasicPairContribution<4, kMaxContributionNodes>;
using CurvedPairContribution = BasicPairContribution<9, kMaxCurvedContributionNodes>;

/// Counts and diagnostics of the last updatePairs / evaluate.
struct InteractionSummary {
  Real cutoff = 0.0;          ///< absolute cutoff used
  Real taperStart = 0.0;      ///< distance where the taper starts, (1 - cutoffTaper) r_c
  Real cutoffTraction = 0.0;  ///< |T| at the taper start for the pair of bodies with the largest density
                              ///< product: the largest traction the cutoff changes
  /// Part of the work of adhesion that the taper and cutoff remove,
  /// -integral of T (1 - S) dr from r_S0 to infinity, over w (0 without adhesion).
  Real neglectedWorkFraction = 0.0;
  long numSearches = 0;  ///< updatePairs calls that searched (one at the last call's coordinates does not)
  LocalIndex numQuadraturePoints = 0;   ///< (point, other body) combinations searched
  LocalIndex numPairs = 0;              ///< within the cutoff (evaluated)
  LocalIndex numBeyondCutoff = 0;       ///< skipped by the cutoff
  LocalIndex numBlended = 0;            ///< pairs blended over more than one segment
  LocalIndex numTruncatedBlends = 0;    ///< pairs with more than kMaxBlendTargets candidates
  LocalIndex numVertexProjections = 0;  ///< pairs whose closest projection is a vertex (last evaluate)
  Real minDistance = 0.0;               ///< smallest r over the pairs (last evaluate; inf if none)
  /// Per body (index = body id): resultant of the interaction forces applied
  /// to it, sum over its nodes of -f_C (last evaluate; components x, y, z;
  /// z = 0 in 2D). Only the pairs evaluated here: sum over ranks.
  std::vector<std::array<Real, 3>> resultant;
};

/// Part of the work of adhesion w that a cutoff r_c with a taper from
/// taperStart removes: -integral of Phi/beta (1 - S) dr over w (0 when the
/// potential has no adhesion or r_c is infinite).
Real neglectedWorkFraction(const PairPotential& potential, Real taperStart, Real cutoff);

/// Traction law of the bodies k, l: T(r) = beta_k beta_l Phi(r/b)/beta S(r),
/// with the cutoff taper S = 1 below taperStart, 1 - 3 s^2 + 2 s^3 with
/// s = (r - taperStart)/(cutoff - taperStart) up to the cutoff, 0 beyond
/// (taperStart and cutoff are absolute, i.e. already scaled by b). P: a
/// kernel potential (KernelPotential.hpp).
template <class P>
struct TractionLaw {
  P potential;  ///< at length scale 1 (plain data: no virtual call per pair)
  Real betaProduct;
  Real taperStart;
  Real cutoff;
  Real lengthScale = 1.0;  ///< b
  KOKKOS_INLINE_FUNCTION void operator()(Real r, Real& T, Real& dT) const {
    potential.halfSpace(r / lengthScale, T, dT);
    T *= betaProduct;
    dT *= betaProduct / lengthScale;
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

class SurfaceInteraction final : public Interaction {
 public:
  /// surfaces: one per body, index = body id (mesh::Mesh::surfaces); segments
  /// in 2D, triangles or quadrilaterals in 3D. densities: reference density beta0 per body (same size).
  /// Throws InputError for inconsistent arguments.
  SurfaceInteraction(std::vector<mesh::Surface> surfaces, std::vector<Real> densities,
                     std::shared_ptr<const PairPotential> potential, SurfaceInteractionOptions options = {});

  const SurfaceInteractionOptions& options() const { return options_; }
  const PairPotential& potential() const override { return *potential_; }
  const GaussRule& quadrature() const { return rule_; }
  int numBodies() const override { return int(surfaces_.size()); }
  const mesh::Surface& surface(int body) const { return surfaces_[body]; }
  /// Spatial dimension (2 or 3): coordinates per node.
  int dim() const { return dim_; }
  /// The facets the closest-point search runs over: the surface itself in 2D
  /// (the chords of curved segments: s -> 2s, 2s + 1), its triangles in 3D
  /// (quad4 facet f -> triangles 2f, 2f + 1; curved facet f -> its cover's
  /// triangles, whose points are not mesh nodes: cover()).
  const mesh::Surface& targetSurface(int body) const { return targets_[body]; }
  Real density(int body) const { return densities_[body]; }
  /// Absolute cutoff in use (scaled by the length scale).
  Real cutoff() const override { return cutoff_; }
  /// Absolute width delta of the projection blend in use (scaled by the
  /// length scale; 0: closest segment only).
  Real projectionSmoothing() const { return smoothing_; }

  /// Replaces the surfaces (one per body, as for the constructor; a body may
  /// have none): the facets this rank holds changed (assembly::GhostedSurfaces).
  /// Evaluated facets, reference configuration and pairs are reset; the next
  /// updatePairs searches anew. Throws InputError as the constructor.
  void setSurfaces(std::vector<mesh::Surface> surfaces);
  /// How far from an evaluated quadrature point couplings(coords, radius)
  /// reads the other bodies' facets (updatePairs and evaluate read less: the
  /// same with radius = cutoff()), `deviation` the largest distance of a
  /// curved facet from its search cover (largestCoverDeviation; 0 for flat
  /// facets). A rank that holds every facet within this distance of its own
  /// points gets the pairs and couplings of the whole surfaces.
  Real readingReach(Real radius, Real deviation) const;
  /// The most a point of a facet moves per unit motion of its nodes (1 for
  /// flat facets; curved: the largest Lebesgue constant of the bodies' kinds).
  Real lebesgue() const;
  /// The largest distance of a curved facet from its search cover at `coords` (0: flat facets).
  Real largestCoverDeviation(const Real* coords) const;

  /// Restricts the quadrature points searched by updatePairs and couplings to
  /// the facets f of body k with evaluated[k][f] != 0 (e.g. the facets whose
  /// cells this MPI rank owns: each rank then searches and pairs only its own
  /// points, against every facet it holds). Empty (the default): every
  /// facet. Throws InputError unless there is one flag per facet of each body.
  void setEvaluatedFacets(std::vector<std::vector<char>> evaluated);

  /// The undeformed coordinates (dim() entries per node, indexed by the mesh's
  /// node indices): the reference area element dA of every quadrature point,
  /// which SurfaceDensity::ReferenceArea integrates over. Throws InputError for
  /// a degenerate facet (dA <= 0 or not finite).
  void setReferenceConfiguration(const Real* coords);
  void setReferenceConfiguration(const std::vector<Real>& coords) { setReferenceConfiguration(coords.data()); }

  /// Rebuilds the search structures at `coords` (dim() entries per node,
  /// indexed by the mesh's node indices) and the pair list. Call once per evaluation: at the
  /// surface coordinates (and cutoff) of the last call it returns at once
  /// (a residual and a Jacobian at one state share one search); otherwise
  /// each point's search starts from its previous projection.
  void updatePairs(const Real* coords);
  void updatePairs(const std::vector<Real>& coords) { updatePairs(coords.data()); }
  const std::vector<InteractionPair>& pairs() const { return pairs_; }

  /// Whether the surfaces are curved 3D facets (every body's, or none's): their contributions are
  /// CurvedPairContribution.
  bool curvedFacets3D() const {
    for (int k = 0; dim_ == 3 && k < numBodies(); ++k)
      if (surfaces_[k].numFacets() > 0) return curved(k);
    return false;
  }

  /// Evaluates one pair at `coords` (thread-safe: usable inside a parallel
  /// loop over pairs()): the blend over its targets, or the single target's
  /// contribution. Without tangent K is left untouched. Returns the state of
  /// the target of largest weight; throws NumericalError if r = 0 or the
  /// result is not finite. The contribution type must be the surfaces'
  /// (curvedFacets3D()), else std::logic_error.
  PairState evaluatePair(const Real* coords, const InteractionPair& pair, PairContribution& out,
                         bool withTangent = true) const;
  PairState evaluatePair(const Real* coords, const InteractionPair& pair, CurvedPairContribution& out,
                         bool withTangent = true) const;

  /// Evaluates all pairs of the current list at `coords` (which may differ
  /// from the coordinates of updatePairs: the list is kept, each projection
  /// is recomputed on its stored target segment). Fills out (resized to
  /// pairs().size()) and the resultants and counts of summary().
  template <class Contribution>
  void evaluate(const Real* coords, std::vector<Contribution>& out, bool withTangent = true) {
    out.resize(pairs_.size());
    beginEvaluation();
    for (std::size_t i = 0; i < pairs_.size(); ++i) {
      const PairState st = evaluatePair(coords, pairs_[i], out[i], withTangent);
      accumulate(pairs_[i], st, out[i].f, out[i].numRowNodes * out[i].dim, out[i].dim);
    }
  }
  template <class Contribution>
  void evaluate(const std::vector<Real>& coords, std::vector<Contribution>& out, bool withTangent = true) {
    evaluate(coords.data(), out, withTangent);
  }

  /// Scatter form: calls scatter(contribution) for every pair p with
  /// include(p) (e.g. the pairs this rank owns), inside a
  /// Kokkos::parallel_for over the pairs (scatter must be safe to call
  /// concurrently where Kokkos runs threads: atomic adds, and take either
  /// contribution type); the summary's resultants and counts are those of
  /// these pairs.
  template <class Scatter, class Include>
  void evaluate(const Real* coords, Scatter&& scatter, bool withTangent, Include&& include) {
    if (curvedFacets3D()) evaluateWith<CurvedPairContribution>(coords, scatter, withTangent, include);
    else evaluateWith<PairContribution>(coords, scatter, withTangent, include);
  }
  template <class Scatter>
  void evaluate(const Real* coords, Scatter&& scatter, bool withTangent = true) {
    evaluate(coords, scatter, withTangent, [](const InteractionPair&) { return true; });
  }


  /// Sorted, unique (row node, column node) couplings of every pair that can
  /// occur while the nodes move by less than (radius - cutoff)/2: for each
  /// quadrature point x of facet e within `radius` of another body, at
  /// distance d from it, the couplings of e's nodes with e's and with those
  /// of every facet within d + 2 (radius - cutoff) of x (plus the reach of
  /// the 2D projection blend). A facet couples only with what its points can
  /// pair with, not with everything within the radius: a much sparser
  /// Jacobian on fine 3D surfaces.
  std::vector<std::pair<LocalIndex, LocalIndex>> couplings(const Real* coords, Real radius) const;
  std::vector<std::pair<LocalIndex, LocalIndex>> couplings(const std::vector<Real>& coords,
                                                           Real radius) const {
    return couplings(coords.data(), radius);
  }

  const InteractionSummary& summary() const { return summary_; }

  /// The potential's plain-data form, at strength 1 and length scale 1.
  const KernelPotential& kernelPotential() const { return kernel_; }
  /// The law between bodies k and l for the kernel potential `potential` (at length scale 1).
  template <class P>
  TractionLaw<P> law(const P& potential, int k, int l) const {
    return TractionLaw<P>{potential, strength_ * densities_[k] * densities_[l], taperStart_, cutoff_, lengthScale_};
  }

  /// Interaction: the next updatePairs uses the new cutoff.
  void setStrength(Real strength) override;
  Real strength() const override { return strength_; }
  void setLengthScale(Real b) override;
  Real lengthScale() const override { return lengthScale_; }

 private:
  template <class Contribution, class Scatter, class Include>
  void evaluateWith(const Real* coords, Scatter& scatter, bool withTangent, Include& include) {
    beginEvaluation();
    Kokkos::View<Real* [3], Kokkos::HostSpace> resultant("cgcm::surface_resultant", surfaces_.size());
    Kokkos::View<Real[1], Kokkos::HostSpace> minDistance("cgcm::surface_min_distance");
    Kokkos::View<LocalIndex[1], Kokkos::HostSpace> vertices("cgcm::surface_vertex_projections");
    minDistance(0) = summary_.minDistance;
    Kokkos::parallel_for(
        "cgcm::method3_pairs", Kokkos::RangePolicy<Kokkos::DefaultHostExecutionSpace>(0, pairs_.size()),
        [&](const std::size_t k) {
          const InteractionPair& p = pairs_[k];
          if (!include(p)) return;
          Contribution c;
          const PairState st = evaluatePair(coords, p, c, withTangent);
          for (int a = 0; a < c.numRowNodes; ++a)
            for (int i = 0; i < c.dim; ++i) Kokkos::atomic_add(&resultant(p.body, i), -c.f[c.dim * a + i]);
          Kokkos::atomic_fetch_min(&minDistance(0), st.distance);
          if (st.region != 0) Kokkos::atomic_add(&vertices(0), LocalIndex(1));
          scatter(static_cast<const Contribution&>(c));
        });
    Kokkos::fence();
    for (std::size_t b = 0; b < surfaces_.size(); ++b)
      for (int i = 0; i < 3; ++i) summary_.resultant[b][i] = resultant(b, i);
    summary_.minDistance = minDistance(0);
    summary_.numVertexProjections = vertices(0);
  }
  void beginEvaluation();
  /// How far beyond the nearest facet the projection blend and the curved candidates reach.
  Real blendReach() const;
  /// Adds pair p's f (rows entries, dim per node) to the resultants, its state to the counts.
  void accumulate(const InteractionPair& p, const PairState& st, const Real* f, int rows, int dim);
  void findTargets(const Real* coords, const Real x[2], int l, Real rmin, InteractionPair& p);
  /// The facets of body l are curved: Line3 segments (2D), TRI6, QUAD8, QUAD9 (3D).
  bool curved(int l) const { return dim_ == 2 ? surfaces_[l].nodesPerFacet == 3 : surfaces_[l].nodesPerFacet > 4; }
  /// Pieces of the search cover per curved facet of body l: 2 chords (2D), 4 or 8 triangles (3D).
  int coverPieces(int l) const;
  /// The search cover of body l at coords: the points of the 3D cover into `points` (3 per point),
  /// and the largest distance of a curved facet from its cover (0 for a body of flat facets).
  Real cover(const Real* coords, int l, std::vector<Real>& points) const;
  /// The curved facets of body l whose cover comes within `radius` of x (sorted, unique).
  void curvedFacetsNear(const Real* x, int l, Real radius, std::vector<LocalIndex>& out);
  /// The blend distance rho (r without smoothing or withPenalty = false) of the
  /// projection of x onto curved facet s of body l, the distance r into *r (may be null).
  Real curvedBlendDistance(const Real* coords, const Real* x, int l, LocalIndex s, Real* r,
                           bool withPenalty = true) const;
  /// The closest curved facet of body l to x within the cutoff: (distance, facet), or facet -1.
  std::pair<Real, LocalIndex> closestCurvedFacet(const Real* coords, const Real* x, int l, const Projection& cover);
  void findCurvedTargets(const Real* coords, const Real* x, int l, InteractionPair& p);
  template <class P>
  PairState evaluateCurvedPair(const P& potential, const Real* coords, const InteractionPair& p,
                               PairContribution& out, bool withTangent) const;
  template <class P>
  PairState evaluateCurvedPair3D(const P& potential, const Real* coords, const InteractionPair& p,
                                 CurvedPairContribution& out, bool withTangent) const;
  void findTargets3D(const Real* coords, const Real x[3], int l, LocalIndex closest, InteractionPair& p);
  void keepBlendTargets(Real limit, int maxTargets, InteractionPair& p);
  template <class P>
  PairState evaluatePairWith(const P& potential, const Real* coords, const InteractionPair& p, PairContribution& out,
                             bool withTangent) const;
  template <class P>
  PairState evaluatePair3D(const P& potential, const Real* coords, const InteractionPair& p, PairContribution& out,
                           bool withTangent) const;
  /// Calls visit(body, facet, quadrature point, x) for every quadrature
  /// point of every evaluated facet at `coords`, and facetDone(body, facet)
  /// after the points of each facet.
  template <class Visit, class FacetDone>
  void forEachPoint(const Real* coords, Visit&& visit, FacetDone&& facetDone) const;
  std::size_t pointsPerFacet(int k) const { return dim_ == 3 ? facetRules_[k].size() : std::size_t(rule_.size()); }
  /// Index of quadrature point q of facet e of body k among every body's points.
  std::size_t pointIndex(int k, LocalIndex e, int q) const {
    return firstPoint_[k] + std::size_t(e) * pointsPerFacet(k) + q;
  }
  /// The dA the kernels integrate over at pair p's point (ReferenceArea), or null (CurrentArea).
  const Real* referenceAreaOf(const InteractionPair& p) const {
    return options_.surfaceDensity == SurfaceDensity::ReferenceArea ? &referenceAreas_[pointIndex(p.body, p.facet, p.qp)]
                                                                    : nullptr;
  }
  /// Pairs of bodies (k, l) whose surfaces come within `radius` (bounding boxes).
  std::vector<char> bodiesWithin(const Real* coords, Real radius) const;
  Real vertexPenalty(const Real* coords, int l, LocalIndex s, const Real x[2], int region, Real* grad,
                     LocalIndex* far) const;

  std::vector<mesh::Surface> surfaces_;
  std::vector<mesh::Surface> targets_;                ///< searched facets (3D: triangles; curved: the cover)
  std::vector<std::vector<Real>> coverPoints_;        ///< [body]: the 3D cover's points (last search)
  std::vector<std::vector<FacetPoint>> facetRules_;   ///< 3D: quadrature per body's facet kind
  int dim_ = 2;
  std::vector<Real> densities_;
  std::shared_ptr<const PairPotential> potential_;
  KernelPotential kernel_;  ///< potential_'s plain-data form
  SurfaceInteractionOptions options_;
  GaussRule rule_;
  Real cutoff1_ = 0.0, taperStart1_ = 0.0, smoothing1_ = 0.0;  ///< at length scale 1
  Real cutoff_ = 0.0;
  Real taperStart_ = 0.0;
  Real smoothing_ = 0.0;
  Real strength_ = 1.0;
  Real lengthScale_ = 1.0;
  std::vector<std::unique_ptr<ClosestPointSearch>> search_;
  std::vector<LocalIndex> surfaceNodes_;  ///< every node of every surface, sorted
  std::vector<Real> searchedCoords_;      ///< their coordinates at the last updatePairs
  Real searchedCutoff_ = -1.0, searchedSmoothing_ = -1.0;
  std::vector<std::size_t> firstPoint_;  ///< [body]: index of its first (facet, quadrature point)
  std::vector<LocalIndex> hints_;        ///< [point * numBodies + other body]: last projection's facet, or -1
  std::vector<Real> referenceAreas_;     ///< [point]: dA (setReferenceConfiguration), empty until set
  std::vector<std::vector<LocalIndex>> neighbours_;  ///< [body][2 s + end]: segment sharing that node, or -1
  std::vector<Real> coverDeviation_;  ///< [body]: largest distance of a curved facet from its cover (last search)
  std::vector<InteractionPair> pairs_;
  std::vector<std::vector<char>> evaluatedFacets_;  ///< [body][facet], empty: all (setEvaluatedFacets)
  std::vector<LocalIndex> near_;                        ///< scratch of findTargets
  std::vector<LocalIndex> segments_;                    ///< scratch of the curved searches
  std::vector<std::pair<Real, LocalIndex>> candidates_;  ///< scratch of findTargets: (rho, segment)
  InteractionSummary summary_;
};

}  // namespace cgcm::interaction
