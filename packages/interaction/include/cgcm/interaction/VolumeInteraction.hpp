#pragma once
// Method 1 (the paper's eq. 16): the interaction energy of two bodies as the
// double volume integral of beta1 beta2 phi(|x1 - x2|) over pairs of their
// elements, evaluated by quadrature over both elements, with its exact
// gradient (the nodal forces) and Hessian (the tangent). The reference for
// Method 3, and the answer where the half-space approximation fails (small
// gammaL). Point-pair laws per formulation: VolumePairLaw.hpp.
//
// Pair list: every (cell of body k, cell of body l) pair whose current
// bounding boxes come within cutoff + skin, found with CGAL's box
// intersection; kept until a node has moved by more than skin / 2 since the
// list was built (quadratic cells: skin / (2 Lambda), see maxPointMotion;
// then no pair within the cutoff can be missing), so the
// energy is one smooth function between rebuilds. Each unordered pair is
// listed twice, once per direction: the directed pair (row cell, column
// cell) gives the forces on the row cell's nodes only, so a rank evaluates
// the pairs of the cells it owns and writes only rows it holds. Both
// directions use the same quadrature: the forces on the two bodies are
// equal and opposite to round-off.
//
// Quadrature: tensor Gauss-Legendre of order n per direction (Quad4, Quad8,
// Quad9, Hex8, Hex20, Hex27; Tet4, Tet10: the same on each of the four hexahedra that split it, one per
// vertex, through the edge midpoints, face centroids and the centroid: a
// rule invariant under every permutation of the vertices, so that mirror
// images of a mesh get mirror images of its points, with positive weights;
// n <= kMaxTetOrder), n chosen per pair when the list is built from an error
// estimate: the lowest order from the base order up whose estimated error
// (volumeQuadratureError) at the closest gap the pair can reach before the next
// rebuild is within the tolerance; see VolumeInteractionOptions. Quadratic cells
// map the same points with their own shape functions (curved cells: det J0
// and the axisymmetric 2 pi R of the quadratic map); their bounding boxes
// are grown to hold the curved cell (VolumeInteraction.cpp, cellBound).
//
// Symmetric models: a mesh that is the part x_i >= 0 of a model symmetric in
// the planes x_i = 0 (VolumeInteractionOptions::symmetryPlanes) is
// integrated over the whole model through image cells: a directed pair's
// column cell may be the mirror image of a cell in any combination of the
// planes (VolumePair::image), its points mirrored and its tangent columns
// times the mirror's signs (d x_image / d x = M). Cells of the same body pair
// only through images across planes that do not cut that body (its distinct
// mirror image in the whole model). The forces on the mesh's nodes and the
// tangent are then those of the whole model restricted to the part, and the
// energy is the whole model's divided by the number of images.
//
// The kernel is a Kokkos functor over the directed pairs (no virtual calls,
// no allocation); it hands each pair's element vector and matrix to a
// scatter functor the caller supplies (assembly: atomic adds into Tpetra's
// local views).
#include <Kokkos_Core.hpp>

#include <array>
#include <chrono>
#include <functional>
#include <limits>
#include <memory>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "cgcm/core/Types.hpp"
#include "cgcm/fem/Dispatch.hpp"
#include "cgcm/interaction/Method3Kernel.hpp"
#include "cgcm/interaction/Interaction.hpp"
#include "cgcm/interaction/PairPotential.hpp"
#include "cgcm/interaction/VolumePairLaw.hpp"
#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::interaction {

/// Highest quadrature order per direction (the kernel's stack arrays hold
/// one cell's points: 12^2 in 2D, 6^3 in 3D).
constexpr int kMaxVolumeOrder2D = 12;
constexpr int kMaxVolumeOrder3D = 6;
constexpr int kMaxTetOrder = 4;
constexpr int kMaxCellPoints = 256;  ///< 6^3 (Hex8), 4 x 4^3 (Tet4)
/// The most nodes of a cell the method takes (Hex27), and of a linear cell (Hex8). The kernel's
/// per-pair buffers are sized by the most nodes of the mesh's cells, one of the two: sized for 27
/// on linear cells they made the plane-strain kernel without tangent 10-15 % slower (zeroing and
/// striding buffers three times as large), so linear meshes keep buffers of 8.
constexpr int kMaxVolumeCellNodes = 27;
constexpr int kMaxLinearCellNodes = 8;

struct VolumeInteractionOptions {
  Formulation formulation = Formulation::PlaneStrain;
  /// Gauss points per direction of a cell for pairs far apart (>= 1).
  int quadratureOrder = 2;
  /// Most points per direction for close pairs; 0: the largest the kernel
  /// holds (kMaxVolumeOrder2D, kMaxVolumeOrder3D).
  int maxQuadratureOrder = 0;
  /// Each pair gets the lowest order (>= quadratureOrder) whose estimated relative error of the
  /// pair's force (volumeQuadratureError) at the closest gap it can reach before the next list rebuild,
  /// max(box gap - skin, kContactGapFloor r0), is at most this; pairs the maximum order cannot
  /// bring within it keep the maximum and are counted (summary). 0: no estimate, every pair
  /// takes quadratureOrder.
  Real quadratureTolerance = 1e-4;
  /// Absolute cutoff: pairs of cells whose bounding boxes are farther apart
  /// are skipped. <= 0 selects 10 r0 (the traction between flat blocks is then
  /// within 0.2 % of sigma_max; 5 r0: 1 %).
  Real cutoff = 0.0;
  /// Verlet skin (absolute): the pair list covers cutoff + skin and is rebuilt
  /// when a node has moved by more than skin / 2. <= 0 selects r0.
  Real skin = 0.0;
  /// Bit i: the mesh is the part x_i >= 0 of a model symmetric in the plane x_i = 0, whose other
  /// part acts through image cells. 0: the mesh is the whole model.
  int symmetryPlanes = 0;
  /// Per body (empty: none): the symmetry planes that cut it, across which its image is the body
  /// itself; across the others its image is another body of the whole model, which it interacts with.
  std::vector<int> bodySymmetryPlanes;
};

/// One directed pair: the forces on rowCell's nodes from colCell (mesh-wide
/// cell indices), `order` Gauss points per direction in both cells.
struct VolumePair {
  LocalIndex rowCell = 0;
  LocalIndex colCell = 0;
  int order = 2;
  int image = 0;  ///< bit i: the column cell mirrored in x_i = 0 (VolumeInteractionOptions::symmetryPlanes)
};

/// The contribution of a directed pair, ready to scatter: node-major dofs,
/// f[dim a + i] for rowNodes[a]; K[dim a + i][dim b + j] = d f / d x_j(colNodes[b]),
/// colNodes = the row cell's nodes, then the column cell's. MaxNodes: the buffers' size
/// (kMaxLinearCellNodes or kMaxVolumeCellNodes); a scatter takes either (a generic callable).
template <int MaxNodes>
struct VolumeContributionOf {
  static constexpr int maxNodes = MaxNodes;
  int dim = 2;
  int rowBody = 0;
  int numRowNodes = 0;
  int numColNodes = 0;
  LocalIndex rowNodes[MaxNodes];
  LocalIndex colNodes[2 * MaxNodes];
  Real energy = 0.0;  ///< half the pair's energy (the reverse direction adds the other half)
  Real f[3 * MaxNodes];
  Real K[3 * MaxNodes][6 * MaxNodes];
};

/// Counts of the last updatePairs / evaluate.
struct VolumeInteractionSummary {
  Real cutoff = 0.0;
  Real skin = 0.0;
  long numListBuilds = 0;          ///< pair lists built so far
  LocalIndex numPairs = 0;         ///< directed pairs in the list (of the row cells set)
  long numPointPairs = 0;          ///< quadrature-point pairs of the last evaluate (this rank)
  int maxOrderUsed = 0;            ///< highest quadrature order of every list built so far
  LocalIndex numAtMaxOrder = 0;    ///< most directed pairs at the maximum order in a list built so far
  /// most directed pairs of a list built so far whose estimate exceeds the tolerance at the maximum order
  LocalIndex numAboveTolerance = 0;
  Real maxErrorEstimate = 0.0;     ///< largest estimated pair error of every list built so far
  Real minCellGap = 0.0;           ///< smallest bounding-box gap between paired cells at the last build
  Real energy = 0.0;               ///< interaction energy of the pairs evaluated (last evaluate)
  long totalPointPairs = 0;        ///< quadrature-point pairs of every evaluate so far (this rank)
  double kernelSeconds = 0.0;      ///< wall time of the kernel (with the scatter) so far
  /// Per body: resultant of the interaction forces on it (last evaluate, pairs evaluated here).
  std::vector<std::array<Real, 3>> resultant;
};

/// The gap, in r0, below which the order of a pair is not raised further: surfaces in adhesive
/// contact are about r_S0 = 0.64 r0 apart, and r0 / 2 under a compressive traction of about
/// 17 sigma_max (Lennard-Jones half-spaces), beyond any load of the decks.
constexpr Real kContactGapFloor = 0.5;

/// Estimated quadrature error of the force of one cell pair, order n per direction in both cells
/// (dim 2: plane strain and axisymmetric; dim 3), relative to the larger of the pair's repulsive
/// and attractive parts: size = the longest edge of the larger cell (a tetrahedron's
/// sub-hexahedra: half its longest edge), gap = the distance of the cells, r0 of the potential.
/// The Gauss rule's relative errors of the r^-12 and r^-6 parts of the force, E12 and E6, are a
/// table measured on two facing squares or cubes of edge size at that gap
/// (tools/volume_quadrature_error.py; they depend on size/gap and n alone). Relative to the
/// larger part, the attractive part counts at most 1 and the repulsive part at most (r0/g)^6 (the
/// ratio of the parts' point forces at the closest distance g): E12 min(1, (r0/g)^6) + E6. Far
/// pairs are held to E6 (their repulsion is negligible), pairs in contact to E12 + E6. Summed over
/// the pairs, the error of the force on a body is at most the tolerance times the sum of the
/// pairs' larger parts.
/// size/gap beyond 16, the table's end: E = 1.
Real volumeQuadratureError(int dim, int order, Real size, Real gap, Real r0);

namespace detail {

/// Quadrature points of one cell at the current coordinates.
template <int MaxNodes>
struct CellPoints {
  int count = 0;
  int numNodes = 0;
  Real N[kMaxCellPoints][MaxNodes];
  Real x[kMaxCellPoints][3];
  Real W[kMaxCellPoints];  ///< beta0 w det J0 (x 2 pi R axisymmetric)
};

struct VolumeMeshView {
  Kokkos::View<const LocalIndex* [kMaxVolumeCellNodes]> cellNodes;
  Kokkos::View<const int*> cellType;  ///< CellType as int
  Kokkos::View<const int*> cellBody;
  Kokkos::View<const Real*> density;  ///< per body
  Kokkos::View<const Real*> refCoords;
  Kokkos::View<const Real**> gaussPoints;   ///< [order][i] on [0, 1]
  Kokkos::View<const Real**> gaussWeights;  ///< [order][i], sum 1
};

/// Parent coordinates xi of the point (s, t, u) in [0, 1]^3 of the
/// hexahedron of vertex v of the parent tetrahedron (corners: the vertex,
/// the midpoints of its edges, the centroids of its faces, the centroid;
/// axes towards the other vertices in increasing order), and det(d xi / d stu).
KOKKOS_INLINE_FUNCTION void tetSubHexPoint(int v, Real s, Real t, Real u, Real (&xi)[3], Real& det) {
  Real V[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  int o[3], k = 0;
  for (int w = 0; w < 4; ++w)
    if (w != v) o[k++] = w;
  Real corner[8][3];  // index i + 2 j + 4 k for the corner (i, j, k)
  for (int c = 0; c < 8; ++c) {
    const int bits[3] = {c & 1, (c >> 1) & 1, (c >> 2) & 1};
    Real count = 1.0;
    for (int d = 0; d < 3; ++d) corner[c][d] = V[v][d];
    for (int a = 0; a < 3; ++a)
      if (bits[a]) {
        count += 1.0;
        for (int d = 0; d < 3; ++d) corner[c][d] += V[o[a]][d];
      }
    for (int d = 0; d < 3; ++d) corner[c][d] /= count;
  }
  const Real p[3] = {s, t, u};
  Real J[3][3] = {};
  for (int d = 0; d < 3; ++d) xi[d] = 0.0;
  for (int c = 0; c < 8; ++c) {
    const int bits[3] = {c & 1, (c >> 1) & 1, (c >> 2) & 1};
    Real f[3], df[3];
    for (int a = 0; a < 3; ++a) {
      f[a] = bits[a] ? p[a] : 1.0 - p[a];
      df[a] = bits[a] ? 1.0 : -1.0;
    }
    const Real w = f[0] * f[1] * f[2];
    const Real dw[3] = {df[0] * f[1] * f[2], f[0] * df[1] * f[2], f[0] * f[1] * df[2]};
    for (int d = 0; d < 3; ++d) {
      xi[d] += w * corner[c][d];
      for (int a = 0; a < 3; ++a) J[d][a] += dw[a] * corner[c][d];
    }
  }
  det = std::abs(J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                 J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]));
}

template <int Dim, class Element, int MaxNodes>
KOKKOS_INLINE_FUNCTION void tensorPoints(const VolumeMeshView& m, LocalIndex cell, int order, const Real* x,
                                         bool axisymmetric, CellPoints<MaxNodes>& out) {
  constexpr int nn = Element::numNodes;
  constexpr bool tet = cellTypeInfo(Element::cellType).simplex;  // pairs with a tetrahedron have order <= kMaxTetOrder
  out.numNodes = nn;
  out.count = 0;
  const Real beta0 = m.density(m.cellBody(cell));
  const int perBlock = Dim == 2 ? order * order : order * order * order;
  const int total = tet ? 4 * perBlock : perBlock;
  for (int q = 0; q < total; ++q) {
    const int r = q % perBlock;
    const int idx[3] = {r % order, (r / order) % order, r / (order * order)};
    Real xi[3], w = 1.0;
    for (int d = 0; d < Dim; ++d) {
      xi[d] = m.gaussPoints(order, idx[d]);
      w *= m.gaussWeights(order, idx[d]);
    }
    Real jacobianScale = 1.0;
    if constexpr (tet) {
      const Real s = xi[0], t = xi[1], u = xi[2];
      tetSubHexPoint(q / perBlock, s, t, u, xi, jacobianScale);
    } else {
      for (int d = 0; d < Dim; ++d) xi[d] = 2.0 * xi[d] - 1.0;  // [0, 1] -> [-1, 1]
      jacobianScale = Dim == 2 ? 4.0 : 8.0;
    }
    Real N[nn], dN[nn][Dim];
    Real xiDim[Dim];
    for (int d = 0; d < Dim; ++d) xiDim[d] = xi[d];
    Element::shape(xiDim, N, dN);
    Real J0[Dim][Dim] = {}, X[Dim] = {}, xc[Dim] = {};
    for (int a = 0; a < nn; ++a) {
      const LocalIndex node = m.cellNodes(cell, a);
      for (int i = 0; i < Dim; ++i) {
        const Real Xi = m.refCoords(Dim * node + i);
        X[i] += N[a] * Xi;
        xc[i] += N[a] * x[Dim * node + i];
        for (int j = 0; j < Dim; ++j) J0[i][j] += Xi * dN[a][j];
      }
    }
    Real det;
    if constexpr (Dim == 2)
      det = J0[0][0] * J0[1][1] - J0[0][1] * J0[1][0];
    else
      det = J0[0][0] * (J0[1][1] * J0[2][2] - J0[1][2] * J0[2][1]) -
            J0[0][1] * (J0[1][0] * J0[2][2] - J0[1][2] * J0[2][0]) +
            J0[0][2] * (J0[1][0] * J0[2][1] - J0[1][1] * J0[2][0]);
    constexpr Real twoPi = 2.0 * kPi;
    const int k = out.count++;
    out.W[k] = beta0 * w * jacobianScale * det * (axisymmetric ? twoPi * X[0] : 1.0);
    for (int a = 0; a < nn; ++a) out.N[k][a] = N[a];
    for (int i = 0; i < Dim; ++i) out.x[k][i] = xc[i];
  }
}

template <int Dim, int MaxNodes>
KOKKOS_INLINE_FUNCTION void cellPoints(const VolumeMeshView& m, LocalIndex cell, int order, const Real* x,
                                       bool axisymmetric, CellPoints<MaxNodes>& out) {
  out.count = 0;  // a cell type without points (refused by the constructor) contributes nothing
  fem::withElement(CellType(m.cellType(cell)), [&](auto element) {
    using E = decltype(element);
    if constexpr (E::dim == Dim && E::numNodes <= MaxNodes)
      tensorPoints<Dim, E>(m, cell, order, x, Dim == 2 && axisymmetric, out);
  });
}

template <Formulation F, class P>
KOKKOS_INLINE_FUNCTION void pointPairLaw(const P& c, const Real* x1, const Real* x2, Real& psi, Real* g, Real (*H11)[3],
                                         Real (*H12)[3]) {
  if constexpr (F == Formulation::ThreeD)
    pairLaw3D(c, x1, x2, psi, g, H11, H12);
  else if constexpr (F == Formulation::PlaneStrain)
    pairLawPlaneStrain(c, x1, x2, psi, g, H11, H12);
  else
    pairLawAxisymmetric(c, x1, x2, psi, g, H11, H12);
}

/// The kernel: one directed pair per index, every cell of at most MaxNodes nodes.
template <Formulation F, class P, class Scatter, int MaxNodes>
struct VolumePairFunctor {
  static constexpr int Dim = F == Formulation::ThreeD ? 3 : 2;
  VolumeMeshView mesh;
  Kokkos::View<const VolumePair*> pairs;
  Kokkos::View<const Real*, Kokkos::MemoryTraits<Kokkos::Unmanaged>> x;
  P law;  ///< kernel potential (KernelPotential.hpp)
  bool withTangent;
  Scatter scatter;

  KOKKOS_INLINE_FUNCTION void operator()(const int k) const {
    const VolumePair p = pairs(k);
    CellPoints<MaxNodes> a, b;
    cellPoints<Dim>(mesh, p.rowCell, p.order, x.data(), F == Formulation::Axisymmetric, a);
    cellPoints<Dim>(mesh, p.colCell, p.order, x.data(), F == Formulation::Axisymmetric, b);
    Real sign[3] = {1.0, 1.0, 1.0};  // the image's mirror M = diag(sign)
    for (int t = 0; t < Dim; ++t)
      if (p.image & (1 << t)) {
        sign[t] = -1.0;
        for (int j = 0; j < b.count; ++j) b.x[j][t] = -b.x[j][t];
      }
    VolumeContributionOf<MaxNodes> c;
    c.dim = Dim;
    c.rowBody = mesh.cellBody(p.rowCell);
    c.numRowNodes = a.numNodes;
    c.numColNodes = a.numNodes + b.numNodes;
    for (int n = 0; n < a.numNodes; ++n) c.colNodes[n] = c.rowNodes[n] = mesh.cellNodes(p.rowCell, n);
    for (int n = 0; n < b.numNodes; ++n) c.colNodes[a.numNodes + n] = mesh.cellNodes(p.colCell, n);
    const int nr = Dim * c.numRowNodes, nc = Dim * c.numColNodes;
    for (int r = 0; r < nr; ++r) {
      c.f[r] = 0.0;
      if (withTangent)
        for (int s = 0; s < nc; ++s) c.K[r][s] = 0.0;
    }
    Real energy = 0.0;
    for (int i = 0; i < a.count; ++i) {
      // sums over the column cell's points, weighted by W2: psi, d psi/dx1,
      // d2 psi/dx1 dx1 and, per column node, N2 d2 psi/dx1 dx2
      Real e = 0.0, g[3] = {}, H[3][3] = {}, C[MaxNodes][3][3] = {};
      for (int j = 0; j < b.count; ++j) {
        Real psi, gj[3], H11[3][3] = {}, H12[3][3] = {};
        pointPairLaw<F>(law, a.x[i], b.x[j], psi, gj, withTangent ? H11 : nullptr, H12);
        const Real w = b.W[j];
        e += w * psi;
        for (int s = 0; s < Dim; ++s) g[s] += w * gj[s];
        if (!withTangent) continue;
        for (int s = 0; s < Dim; ++s)
          for (int t = 0; t < Dim; ++t) H[s][t] += w * H11[s][t];
        for (int n = 0; n < b.numNodes; ++n) {
          const Real wn = w * b.N[j][n];
          for (int s = 0; s < Dim; ++s)
            for (int t = 0; t < Dim; ++t) C[n][s][t] += wn * H12[s][t];
        }
      }
      const Real wi = a.W[i];
      energy += wi * e;
      for (int m = 0; m < a.numNodes; ++m) {
        const Real wm = wi * a.N[i][m];
        for (int s = 0; s < Dim; ++s) c.f[Dim * m + s] += wm * g[s];
        if (!withTangent) continue;
        for (int n = 0; n < a.numNodes; ++n) {
          const Real wmn = wm * a.N[i][n];
          for (int s = 0; s < Dim; ++s)
            for (int t = 0; t < Dim; ++t) c.K[Dim * m + s][Dim * n + t] += wmn * H[s][t];
        }
        for (int n = 0; n < b.numNodes; ++n)
          for (int s = 0; s < Dim; ++s)
            for (int t = 0; t < Dim; ++t) c.K[Dim * m + s][Dim * (a.numNodes + n) + t] += wm * C[n][s][t] * sign[t];
      }
    }
    c.energy = 0.5 * energy;
    scatter(static_cast<const VolumeContributionOf<MaxNodes>&>(c), a.count * b.count);
  }
};

}  // namespace detail

class VolumeInteraction final : public Interaction {
 public:
  /// mesh: every body's cells (Quad4, Quad8, Quad9 in 2D; Hex8, Tet4, Hex20, Hex27, Tet10 in
  /// 3D); densities:
  /// beta0 per body. Throws InputError for inconsistent arguments or cell
  /// types the method does not handle.
  VolumeInteraction(const mesh::Mesh& mesh, std::vector<Real> densities,
                    std::shared_ptr<const PairPotential> potential, VolumeInteractionOptions options = {});

  const VolumeInteractionOptions& options() const { return options_; }
  const PairPotential& potential() const override { return *potential_; }
  int numBodies() const override { return numBodies_; }
  int dim() const { return dim_; }
  Real density(int body) const { return densities_[body]; }
  /// Absolute cutoff and skin in use (scaled by the length scale).
  Real cutoff() const override { return cutoff1_ * lengthScale_; }
  Real skin() const { return skin1_ * lengthScale_; }
  int maxQuadratureOrder() const { return maxOrder_; }
  /// Lambda of updatePairs: the largest sum of |N_a| over a cell of the mesh.
  Real maxPointMotion() const { return maxPointMotion_; }
  /// The box of `cell` at `coords` that holds the whole (curved) cell: lo[0..2], hi[0..2] (2D: z = 0).
  void cellBox(LocalIndex cell, const Real* coords, Real (&lo)[3], Real (&hi)[3]) const;
  /// The point-pair coefficients in use (strength and length scale applied).
  KernelPotential law() const;

  /// Builds the pair list at `coords` (dim entries per node, mesh-wide) if
  /// none exists, a node moved by more than skin / (2 Lambda) since it was
  /// built (Lambda: the most a point of a cell moves per node motion, 1 on
  /// linear cells, see maxPointMotion), or the cutoff changed; returns whether it did.
  bool updatePairs(const Real* coords);
  /// Forgets the pair list (the next updatePairs builds one).
  void invalidatePairs() { built_ = false; }
  const std::vector<VolumePair>& pairs() const { return pairs_; }

  /// The order a pair of cells at box gap `gap` gets (size: see volumeQuadratureError; tet: a
  /// tetrahedron in the pair, whose cap is kMaxTetOrder) and its error estimate, at the closest
  /// gap it can reach before the list is rebuilt: max(gap - skin, kContactGapFloor r0).
  struct OrderChoice {
    int order;
    Real estimate;
    bool withinTolerance;
  };
  OrderChoice chooseOrder(Real size, Real gap, bool tet) const;

  /// The pairs of cells that come into contact: pairs of surface cells (surfaceCells[cell] != 0;
  /// empty: every cell) whose box gap at `coords` is within the skin of the smallest gap
  /// between the bodies (where they first touch), and the order each needs at the contact gap kContactGapFloor r0. largestSize: the
  /// largest cell size (volumeQuadratureError) among them; neededSize: the largest size whose
  /// estimate at the maximum order meets the tolerance (infinite if all meet it).
  struct ContactQuadrature {
    Real largestSize = 0.0;
    Real neededSize = 0.0;
    int order = 0;          ///< the order the largest cells get there
    Real estimate = 0.0;    ///< their estimate at that order
    bool withinTolerance = true;
    int maxOrder = 0;       ///< the cap those pairs have (kMaxTetOrder with a tetrahedron)
  };
  ContactQuadrature contactQuadrature(const Real* coords, const std::vector<char>& surfaceCells = {}) const;

  /// The size of the pair list at `coords` (cutoff + skin), counted without building it: directed
  /// pairs, (row node, column node) couplings before merging, and the memory the list and the
  /// graph's couplings take while built (every rank builds the whole list before keeping its rows).
  /// The count stops (stopped: a lower bound) once the memory passes `stopAboveMegabytes`.
  struct PairListSize {
    double pairs = 0.0;
    double couplings = 0.0;
    double megabytes = 0.0;
    bool stopped = false;
  };
  PairListSize pairListSize(const Real* coords,
                            double stopAboveMegabytes = std::numeric_limits<double>::infinity()) const;

  /// Keeps only the directed pairs whose row cell has rowCells[cell] != 0 in
  /// the pair lists built from now on (a rank's own cells: it writes only
  /// their rows); empty (the default): every pair.
  void setRowCells(std::vector<char> rowCells);

  /// Evaluates every directed pair of the list at `coords` and calls
  /// scatter(const VolumeContributionOf<n>&, long pointPairs) for each (n =
  /// kMaxLinearCellNodes on linear meshes, else kMaxVolumeCellNodes), inside a
  /// Kokkos::parallel_for. Fills summary().energy and the resultants.
  template <class Scatter>
  void evaluate(const Real* coords, Scatter scatter, bool withTangent);

  /// The interaction energy of the current pair list at `coords` (all pairs).
  Real energy(const Real* coords);

  /// Sorted, unique (row node, column node) couplings of every directed pair
  /// whose cells' bounding boxes are within `radius` at `coords`.
  std::vector<std::pair<LocalIndex, LocalIndex>> couplings(const Real* coords, Real radius) const;

  const VolumeInteractionSummary& summary() const { return summary_; }

  /// Interaction: the skin scales with the length scale too.
  void setStrength(Real strength) override;
  Real strength() const override { return strength_; }
  void setLengthScale(Real b) override;
  Real lengthScale() const override { return lengthScale_; }

 private:
  /// Directed pairs of cells whose bounding boxes at `coords` are within
  /// `radius` (with each pair's box gap and size).
  struct Candidate {
    LocalIndex rowCell, colCell;
    int image;    ///< the column cell's mirror (VolumePair::image)
    Real gap, size;  ///< box gap; the larger cell's size (volumeQuadratureError)
    bool tet;        ///< a tetrahedron in the pair
  };
  std::vector<Candidate> candidates(const Real* coords, Real radius) const;
  void forEachCandidate(const Real* coords, Real radius, const std::function<void(const Candidate&)>& visit) const;
  /// The size of volumeQuadratureError: the longest corner-to-corner edge (tetrahedra: half of it).
  Real cellSize(LocalIndex cell, const Real* coords) const;
  template <Formulation F, int MaxNodes, class Scatter>
  void run(const Kokkos::View<const VolumePair*>& pairs, const Real* coords, Scatter scatter, bool withTangent);
  template <Formulation F, class Scatter>
  void run(const Kokkos::View<const VolumePair*>& pairs, const Real* coords, Scatter scatter, bool withTangent) {
    if (maxCellNodes_ <= kMaxLinearCellNodes)
      run<F, kMaxLinearCellNodes>(pairs, coords, scatter, withTangent);
    else
      run<F, kMaxVolumeCellNodes>(pairs, coords, scatter, withTangent);
  }

  int dim_ = 2;
  int numBodies_ = 0;
  LocalIndex numNodes_ = 0;
  std::vector<Real> densities_;
  std::shared_ptr<const PairPotential> potential_;
  KernelPotential law1_;  ///< at strength 1, length scale 1
  VolumeInteractionOptions options_;
  int maxOrder_ = 0;
  int maxCellNodes_ = 0;        ///< the most nodes of a cell of the mesh
  Real maxPointMotion_ = 1.0;  ///< see maxPointMotion()
  Real cutoff1_ = 0.0, skin1_ = 0.0;
  Real strength_ = 1.0, lengthScale_ = 1.0;
  std::vector<std::vector<LocalIndex>> cellsOfBody_;
  std::vector<LocalIndex> interactingNodes_;  ///< nodes of cells of bodies that interact (sorted)
  detail::VolumeMeshView view_;
  std::vector<char> rowCells_;  ///< [cell]: pairs with this row cell are listed (empty: all)
  std::vector<VolumePair> pairs_;
  Kokkos::View<VolumePair*> pairsView_;
  bool built_ = false;
  Real builtCutoff_ = 0.0;
  std::vector<Real> builtCoords_;  ///< coordinates of interactingNodes_ at the last build
  VolumeInteractionSummary summary_;
};

template <Formulation F, int MaxNodes, class Scatter>
void VolumeInteraction::run(const Kokkos::View<const VolumePair*>& pairs, const Real* coords, Scatter scatter,
                            bool withTangent) {
  // one kernel per potential type, chosen once per evaluation
  std::visit(
      [&](const auto& law) {
        detail::VolumePairFunctor<F, std::decay_t<decltype(law)>, Scatter, MaxNodes> functor{
            view_,
            pairs,
            Kokkos::View<const Real*, Kokkos::MemoryTraits<Kokkos::Unmanaged>>(coords, std::size_t(dim_) * numNodes_),
            law,
            withTangent,
            scatter};
        Kokkos::parallel_for("cgcm::volume_pairs",
                             Kokkos::RangePolicy<Kokkos::DefaultHostExecutionSpace>(0, pairs.extent(0)), functor);
      },
      law());
  Kokkos::fence();
}

template <class Scatter>
void VolumeInteraction::evaluate(const Real* coords, Scatter scatter, bool withTangent) {
  // energy, resultants and point-pair counts, accumulated atomically next to the caller's scatter
  Kokkos::View<Real* [3]> resultant("cgcm::volume_resultant", numBodies_);
  Kokkos::View<Real[1]> energy("cgcm::volume_energy");
  Kokkos::View<long[1]> pointPairs("cgcm::volume_point_pairs");
  const int dim = dim_;
  auto wrapped = [=](const auto& c, long np) {
    Kokkos::atomic_add(&energy(0), c.energy);
    Kokkos::atomic_add(&pointPairs(0), np);
    for (int a = 0; a < c.numRowNodes; ++a)
      for (int i = 0; i < dim; ++i) Kokkos::atomic_add(&resultant(c.rowBody, i), -c.f[dim * a + i]);
    scatter(c, np);
  };
  const auto t0 = std::chrono::steady_clock::now();
  if (options_.formulation == Formulation::ThreeD)
    run<Formulation::ThreeD>(pairsView_, coords, wrapped, withTangent);
  else if (options_.formulation == Formulation::PlaneStrain)
    run<Formulation::PlaneStrain>(pairsView_, coords, wrapped, withTangent);
  else
    run<Formulation::Axisymmetric>(pairsView_, coords, wrapped, withTangent);
  summary_.energy = energy(0);
  summary_.numPointPairs = pointPairs(0);
  summary_.totalPointPairs += pointPairs(0);
  summary_.kernelSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  summary_.resultant.assign(numBodies_, {0.0, 0.0, 0.0});
  for (int b = 0; b < numBodies_; ++b)
    for (int i = 0; i < dim; ++i) summary_.resultant[b][i] = resultant(b, i);
}

/// Part of the work of adhesion w that Method 1 loses by leaving out point pairs farther apart
/// than the cutoff r_c, between two flat half-spaces: pi integral_{r_c}^inf r (r - g)^2 phi(r) dr
/// removed from the energy at the gap g = r_S0, over w (first order: the truncated law's
/// equilibrium gap moves by O(r_c^-3)). Lennard-Jones: about pi r0^6 / r_c^2 over w, 3.0 % at
/// 10 r0, 0.8 % at 20 r0 (five to six times the half-space law's own cutoff loss, which drops only gaps
/// beyond r_c). An upper bound for the method: it integrates every point pair within r_c and
/// also the farther ones of the cell pairs it lists. 0 without adhesion or cutoff.
Real pairCutoffWorkFraction(const PairPotential& potential, Real cutoff);

}  // namespace cgcm::interaction
