#include "cgcm/interaction/VolumeInteraction.hpp"

#include <CGAL/box_intersection_d.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "cgcm/core/Error.hpp"
#include "cgcm/interaction/Quadrature.hpp"

namespace cgcm::interaction {

namespace {

std::string where() { return "volume pair interaction: "; }

// The cells whose points the quadrature places: those with shape functions, tensor-product cells
// in 2D and 3D, simplices in 3D (split into four hexahedra; see tetSubHexPoint), linear and
// quadratic (their boxes: cellBound).
bool volumeQuadratureTakes(CellType type, int dim) {
  const CellTypeInfo& row = cellTypeInfo(type);
  return row.dim == dim && (!row.simplex || dim == 3) && row.numNodes <= kMaxVolumeCellNodes &&
         fem::withElement(type, [](auto) {});
}

// Where a (curved) quadratic cell can be, from its nodes. Its map reproduces the (multi)linear
// interpolation x_lin of its corners exactly, so x(xi) = x_lin(xi) + sum over the non-corner
// nodes a of N_a(xi) d_a, d_a = x_a - x_lin(xi_a) the node's deviation from the position the
// corners give it. x_lin lies in the box of the corners (a convex combination), so per
// coordinate the cell lies in that box grown by grow max_a |d_a,i|, grow = max over the cell of
// sum_a |N_a| over the non-corner nodes:
//   - serendipity (Quad8, Hex20): the mid-edge N_a >= 0 sum to sum_k (1 - xi_k^2) <= dim;
//   - Lagrange (Quad9, Hex27): at most the sum of every |N_a|, (5/4)^dim (the 1D Lebesgue
//     constant of the nodes -1, 0, 1 is max |xi| + 1 - xi^2 = 5/4; the non-corner part alone
//     is 1.38 and 1.85 on a grid);
//   - Tet10: the mid-edge 4 l_a l_b sum to 2 (1 - sum l_a^2) <= 3/2.
// (One edge alone: x_lin + 4 t (1 - t) d, within d of its chord, grow 1.) motion: max sum_a |N_a|,
// the most a point of the cell moves per largest node motion (the pair list's Verlet test):
// 1 on linear cells, 3 (Quad8) and 5 (Hex20) at the centre, (5/4)^dim (Lagrange), 2 (Tet10, at
// the centroid: the corners' l (2 l - 1) = -1/8, the mid-edge nodes 1/4); checked by sampling in
// test_volume_interaction.cpp.
struct CellBound {
  Real grow, motion;
};
CellBound cellBound(CellType type) {
  switch (type) {
    case CellType::Quad8: return {2.0, 3.0};
    case CellType::Quad9: return {25.0 / 16.0, 25.0 / 16.0};
    case CellType::Hex20: return {3.0, 5.0};
    case CellType::Hex27: return {125.0 / 64.0, 125.0 / 64.0};
    case CellType::Tet10: return {1.5, 2.0};
    default: return {0.0, 1.0};  // linear: the box of the corners
  }
}

std::string cellTypesTaken(int dim) {
  std::string out;
  for (const CellTypeInfo& row : kCellTypes)
    if (volumeQuadratureTakes(row.type, dim)) out += (out.empty() ? "" : ", ") + std::string(row.name);
  return out;
}

}  // namespace

VolumeInteraction::VolumeInteraction(const mesh::Mesh& mesh, std::vector<Real> densities,
                                     std::shared_ptr<const PairPotential> potential, VolumeInteractionOptions options)
    : dim_(mesh.dim), numBodies_(mesh.numBodies), numNodes_(mesh.numNodes()), densities_(std::move(densities)),
      potential_(std::move(potential)), options_(options) {
  if (!potential_) throw InputError(where() + "no potential");
  law1_ = potential_->kernelPotential();
  if ((dim_ == 3) != (options_.formulation == Formulation::ThreeD))
    throw InputError(where() + "a " + std::to_string(dim_) + "D mesh with the " +
                     formulationName(options_.formulation) + " formulation");
  if (int(densities_.size()) != numBodies_)
    throw InputError(where() + std::to_string(densities_.size()) + " densities for " + std::to_string(numBodies_) +
                     " bodies");
  for (Real b : densities_)
    if (!(b > 0.0) || !std::isfinite(b)) throw InputError(where() + "densities must be finite and > 0");
  const int kernelMax = dim_ == 2 ? kMaxVolumeOrder2D : kMaxVolumeOrder3D;
  maxOrder_ = options_.maxQuadratureOrder > 0 ? options_.maxQuadratureOrder : kernelMax;
  if (options_.quadratureOrder < 1 || options_.quadratureOrder > maxOrder_ || maxOrder_ > kernelMax)
    throw InputError(where() + "quadrature orders must satisfy 1 <= order (" +
                     std::to_string(options_.quadratureOrder) + ") <= maximum order (" + std::to_string(maxOrder_) +
                     ") <= " + std::to_string(kernelMax) + " in " + std::to_string(dim_) + "D");
  if (std::isnan(options_.cutoff) || std::isnan(options_.skin) || std::isinf(options_.skin))
    throw InputError(where() + "cutoff and skin must be numbers (the skin finite)");
  cutoff1_ = options_.cutoff > 0.0 ? options_.cutoff : 10.0 * potential_->r0();
  skin1_ = options_.skin > 0.0 ? options_.skin : potential_->r0();

  // cells as plain arrays for the kernel
  const LocalIndex numCells = mesh.numCells();
  for (const auto& block : mesh.blocks) {
    maxCellNodes_ = std::max(maxCellNodes_, mesh::nodesPerCell(block.type));
    maxPointMotion_ = std::max(maxPointMotion_, cellBound(block.type).motion);
  }
  Kokkos::View<LocalIndex* [kMaxVolumeCellNodes]> cellNodes("cgcm::volume_cell_nodes", numCells);
  Kokkos::View<int*> cellType("cgcm::volume_cell_type", numCells), cellBody("cgcm::volume_cell_body", numCells);
  cellsOfBody_.assign(numBodies_, {});
  std::vector<char> used(numNodes_, 0);
  LocalIndex cell = 0;
  for (const auto& block : mesh.blocks) {
    if (!volumeQuadratureTakes(block.type, dim_))
      throw InputError(where() + "block \"" + block.name + "\" has " + mesh::cellTypeName(block.type) +
                       " cells; the method takes " + cellTypesTaken(dim_) + " in " + std::to_string(dim_) + "D");
    const int nn = mesh::nodesPerCell(block.type);
    for (LocalIndex c = 0; c < block.numCells(); ++c, ++cell) {
      for (int a = 0; a < kMaxVolumeCellNodes; ++a) cellNodes(cell, a) = a < nn ? block.connectivity[std::size_t(c) * nn + a] : -1;
      for (int a = 0; a < nn; ++a) used[cellNodes(cell, a)] = 1;
      cellType(cell) = int(block.type);
      cellBody(cell) = block.body;
      cellsOfBody_.at(block.body).push_back(cell);
    }
  }
  for (LocalIndex n = 0; n < numNodes_; ++n)
    if (used[n]) interactingNodes_.push_back(n);
  Kokkos::View<Real*> density("cgcm::volume_density", numBodies_);
  for (int b = 0; b < numBodies_; ++b) density(b) = densities_[b];
  Kokkos::View<Real*> ref("cgcm::volume_reference_coords", mesh.coords.size());
  for (std::size_t i = 0; i < mesh.coords.size(); ++i) ref(i) = mesh.coords[i];
  Kokkos::View<Real**> gp("cgcm::gauss_points", maxOrder_ + 1, maxOrder_), gw("cgcm::gauss_weights", maxOrder_ + 1,
                                                                                maxOrder_);
  for (int n = 1; n <= maxOrder_; ++n) {
    const GaussRule rule = gaussLegendreUnit(n);
    for (int i = 0; i < n; ++i) {
      gp(n, i) = rule.points[i];
      gw(n, i) = rule.weights[i];
    }
  }
  view_ = detail::VolumeMeshView{cellNodes, cellType, cellBody, density, ref, gp, gw};
  summary_.resultant.assign(numBodies_, {0.0, 0.0, 0.0});
}

KernelPotential VolumeInteraction::law() const { return scaled(law1_, strength_, lengthScale_); }

void VolumeInteraction::setStrength(Real strength) {
  if (!(strength > 0.0) || !std::isfinite(strength))
    throw InputError(where() + "strength must be finite and > 0, got " + std::to_string(strength));
  strength_ = strength;
}

void VolumeInteraction::setLengthScale(Real b) {
  if (!(b > 0.0) || !std::isfinite(b))
    throw InputError(where() + "length scale must be finite and > 0, got " + std::to_string(b));
  lengthScale_ = b;
}

std::vector<VolumeInteraction::Candidate> VolumeInteraction::candidates(const Real* coords, Real radius) const {
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, LocalIndex>;
  // per body: each cell's current bounding box (holding the curved cell), grown by radius / 2 on
  // every side; its size: the diagonal of its nodes' box (the cell's diameter)
  std::vector<std::vector<Box>> boxes(numBodies_);
  std::vector<std::array<Real, 6>> bounds(view_.cellBody.extent(0));
  std::vector<Real> sizes(view_.cellBody.extent(0));
  for (int b = 0; b < numBodies_; ++b)
    for (LocalIndex c : cellsOfBody_[b]) {
      std::array<Real, 6>& bb = bounds[c];
      Real lo0[3], hi0[3];
      cellBox(c, coords, lo0, hi0);
      for (int i = 0; i < 3; ++i) bb[i] = lo0[i], bb[3 + i] = hi0[i];
      Real nlo[3] = {0.0, 0.0, 0.0}, nhi[3] = {0.0, 0.0, 0.0};
      for (int i = 0; i < dim_; ++i) nlo[i] = std::numeric_limits<Real>::max(), nhi[i] = -nlo[i];
      for (int a = 0; a < kMaxVolumeCellNodes && view_.cellNodes(c, a) >= 0; ++a)
        for (int i = 0; i < dim_; ++i) {
          const Real v = coords[std::size_t(dim_) * view_.cellNodes(c, a) + i];
          nlo[i] = std::min(nlo[i], v);
          nhi[i] = std::max(nhi[i], v);
        }
      sizes[c] = std::sqrt((nhi[0] - nlo[0]) * (nhi[0] - nlo[0]) + (nhi[1] - nlo[1]) * (nhi[1] - nlo[1]) +
                           (nhi[2] - nlo[2]) * (nhi[2] - nlo[2]));
      double lo[3], hi[3];
      for (int i = 0; i < 3; ++i) {
        lo[i] = bb[i] - 0.5 * radius;
        hi[i] = bb[3 + i] + 0.5 * radius;
      }
      boxes[b].emplace_back(lo, hi, c);
    }
  std::vector<Candidate> out;
  for (int k = 0; k < numBodies_; ++k)
    for (int l = k + 1; l < numBodies_; ++l) {
      if (boxes[k].empty() || boxes[l].empty()) continue;
      auto report = [&](const Box& p, const Box& q) {
        const std::array<Real, 6>&bp = bounds[p.info()], &bq = bounds[q.info()];
        Real gap2 = 0.0;
        for (int i = 0; i < 3; ++i) {
          const Real g = std::max({0.0, bp[i] - bq[3 + i], bq[i] - bp[3 + i]});
          gap2 += g * g;
        }
        if (gap2 > radius * radius) return;  // the boxes' corners are farther apart
        const Real gap = std::sqrt(gap2), size = std::max(sizes[p.info()], sizes[q.info()]);
        out.push_back({p.info(), q.info(), gap, size});
        out.push_back({q.info(), p.info(), gap, size});
      };
      // box_intersection_d reorders its inputs: work on copies
      std::vector<Box> bk = boxes[k], bl = boxes[l];
      CGAL::box_intersection_d(bk.begin(), bk.end(), bl.begin(), bl.end(), report);
    }
  std::sort(out.begin(), out.end(), [](const Candidate& a, const Candidate& b) {
    return a.rowCell != b.rowCell ? a.rowCell < b.rowCell : a.colCell < b.colCell;
  });
  return out;
}

void VolumeInteraction::cellBox(LocalIndex cell, const Real* coords, Real (&lo)[3], Real (&hi)[3]) const {
  const CellType type = CellType(view_.cellType(cell));
  const CellTypeInfo& row = cellTypeInfo(type);
  const int corners = cornerCount(row);
  auto X = [&](int a, int i) { return coords[std::size_t(dim_) * view_.cellNodes(cell, a) + i]; };
  for (int i = 0; i < 3; ++i) lo[i] = hi[i] = 0.0;
  for (int i = 0; i < dim_; ++i) {
    lo[i] = std::numeric_limits<Real>::max();
    hi[i] = -std::numeric_limits<Real>::max();
    for (int a = 0; a < corners; ++a) {
      lo[i] = std::min(lo[i], X(a, i));
      hi[i] = std::max(hi[i], X(a, i));
    }
  }
  if (row.order == 1) return;
  Real dev[3] = {0.0, 0.0, 0.0};  // max |d_a,i| over the non-corner nodes
  fem::withElement(type, [&](auto element) {
    using E = decltype(element);
    constexpr bool quadratic = cellTypeInfo(E::cellType).order == 2, simplex = cellTypeInfo(E::cellType).simplex;
    if constexpr (quadratic) {
      // the linear cell of the corners: its shape functions at the node give x_lin(xi_a)
      using Linear =
          std::conditional_t<simplex, fem::Tet4, std::conditional_t<E::dim == 2, fem::Quad4, fem::Hex8>>;
      for (int a = Linear::numNodes; a < E::numNodes; ++a) {
        Real xi[E::dim], N[Linear::numNodes], dN[Linear::numNodes][E::dim];
        E::parentCoordinates(a, xi);
        Linear::shape(xi, N, dN);
        for (int i = 0; i < dim_; ++i) {
          Real lin = 0.0;
          for (int c = 0; c < Linear::numNodes; ++c) lin += N[c] * X(c, i);
          dev[i] = std::max(dev[i], std::abs(X(a, i) - lin));
        }
      }
    }
  });
  const Real grow = cellBound(type).grow;
  for (int i = 0; i < dim_; ++i) {
    lo[i] -= grow * dev[i];
    hi[i] += grow * dev[i];
  }
}

void VolumeInteraction::setRowCells(std::vector<char> rowCells) {
  if (!rowCells.empty() && rowCells.size() != view_.cellBody.extent(0))
    throw std::logic_error("volume pair interaction: a row-cell mask of the wrong size");
  rowCells_ = std::move(rowCells);
  built_ = false;
}

bool VolumeInteraction::updatePairs(const Real* coords) {
  const Real cutoff = this->cutoff(), skin = this->skin();
  if (built_ && builtCutoff_ == cutoff) {
    Real moved2 = 0.0;
    for (std::size_t k = 0; k < interactingNodes_.size(); ++k) {
      Real d2 = 0.0;
      for (int i = 0; i < dim_; ++i) {
        const Real d = coords[std::size_t(dim_) * interactingNodes_[k] + i] - builtCoords_[dim_ * k + i];
        d2 += d * d;
      }
      moved2 = std::max(moved2, d2);
    }
    // a point of a quadratic cell moves by up to maxPointMotion_ times its nodes' largest motion
    if (std::sqrt(moved2) * maxPointMotion_ <= 0.5 * skin) return false;
  }
  const Real r0 = potential_->r0() * lengthScale_;
  pairs_.clear();
  summary_.maxOrderUsed = 0;
  summary_.numAtMaxOrder = 0;
  summary_.minCellGap = std::numeric_limits<Real>::infinity();
  for (const Candidate& c : candidates(coords, cutoff + skin)) {
    if (!rowCells_.empty() && !rowCells_[c.rowCell]) continue;
    const int extra = int(std::ceil(kCloseOrderFactor * c.size / std::max(c.gap, 0.5 * r0)));
    // a tetrahedron's rule holds kMaxTetOrder^3 points on each of its four hexahedra
    const int cap = cellTypeInfo(CellType(view_.cellType(c.rowCell))).simplex ||
                            cellTypeInfo(CellType(view_.cellType(c.colCell))).simplex
                        ? std::min(maxOrder_, kMaxTetOrder)
                        : maxOrder_;
    const int order = std::min(cap, options_.quadratureOrder + extra);
    pairs_.push_back({c.rowCell, c.colCell, order});
    summary_.maxOrderUsed = std::max(summary_.maxOrderUsed, order);
    summary_.numAtMaxOrder += order == cap;
    summary_.minCellGap = std::min(summary_.minCellGap, c.gap);
  }
  pairsView_ = Kokkos::View<VolumePair*>("cgcm::volume_pairs", pairs_.size());
  for (std::size_t k = 0; k < pairs_.size(); ++k) pairsView_(k) = pairs_[k];
  builtCoords_.resize(interactingNodes_.size() * dim_);
  for (std::size_t k = 0; k < interactingNodes_.size(); ++k)
    for (int i = 0; i < dim_; ++i) builtCoords_[dim_ * k + i] = coords[std::size_t(dim_) * interactingNodes_[k] + i];
  built_ = true;
  builtCutoff_ = cutoff;
  summary_.cutoff = cutoff;
  summary_.skin = skin;
  summary_.numPairs = LocalIndex(pairs_.size());
  ++summary_.numListBuilds;
  return true;
}

Real VolumeInteraction::energy(const Real* coords) {
  evaluate(coords, [](const auto&, long) {}, false);  // the listed pairs: all without row cells set
  return summary_.energy;
}

std::vector<std::pair<LocalIndex, LocalIndex>> VolumeInteraction::couplings(const Real* coords, Real radius) const {
  std::vector<std::pair<LocalIndex, LocalIndex>> out;
  for (const Candidate& c : candidates(coords, radius))
    for (int a = 0; a < kMaxVolumeCellNodes && view_.cellNodes(c.rowCell, a) >= 0; ++a)
      for (int b = 0; b < kMaxVolumeCellNodes && view_.cellNodes(c.colCell, b) >= 0; ++b)
        out.emplace_back(view_.cellNodes(c.rowCell, a), view_.cellNodes(c.colCell, b));
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

Real pairCutoffWorkFraction(const PairPotential& potential, Real cutoff) {
  const Real w = potential.adhesionWorkCoefficient();
  const auto gap = potential.surfaceEquilibriumDistance();
  if (!(w > 0.0) || !gap || !std::isfinite(cutoff)) return 0.0;
  // The pairs at distance r >= r_c between the half-spaces at gap g: 2 pi r dr per point of one
  // body at height h above the other's surface, and (r - g)^2 / 2 of such point pairs per unit area
  // summed over h in [g, r]. Simpson after r = r_c / t (the integrand vanishes at t = 0).
  const int n = 400;
  Real sum = 0.0;
  for (int i = 1; i <= n; ++i) {
    const Real t = Real(i) / n, r = cutoff / t, c = i == n ? 1.0 : (i % 2 ? 4.0 : 2.0);
    sum += c * r * (r - *gap) * (r - *gap) * potential.phi(r) * cutoff / (t * t);
  }
  return -kPi * sum / (3.0 * n) / w;
}

}  // namespace cgcm::interaction
