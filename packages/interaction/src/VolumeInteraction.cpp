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

// The measured relative error of the Gauss rule on the r^-12 and r^-6 parts of a pair's force
// (tools/volume_quadrature_error.py: two facing squares, 2D plane-strain law, or cubes of edge h
// at gap g), per order n (rows) and h/g = 0.25 sqrt(2)^k, k = 0 .. 12 (columns), as the envelope
// of the measurements: at each (n, h/g) the largest error at that order or above and that h/g
// or below, rounded up to three digits. Beyond h/g = 4 the error of the r^-12 part no longer falls with n up to 12 (the rule
// does not resolve the peak of width g across cells of 4 g and more: 9e-4 .. 0.3 at n = 12).
constexpr int kTauColumns = 13;
constexpr Real kTauFirst = 0.25, kTauLast = 16.0;
// 2D, r^-12, orders 1 .. 12
constexpr Real kError2D12[12][kTauColumns] = {
    {3.82e-01, 5.62e-01, 7.42e-01, 8.80e-01, 9.58e-01, 9.89e-01, 9.98e-01, 1.00e+00, 1.00e+00, 1.00e+00, 1.00e+00, 1.00e+00, 1.00e+00},
    {2.43e-02, 6.75e-02, 1.63e-01, 3.29e-01, 5.46e-01, 7.53e-01, 8.97e-01, 9.68e-01, 9.93e-01, 9.99e-01, 1.00e+00, 1.00e+00, 1.00e+00},
    {6.03e-04, 3.05e-03, 1.32e-02, 4.72e-02, 1.36e-01, 3.03e-01, 5.29e-01, 7.43e-01, 8.92e-01, 9.67e-01, 9.93e-01, 9.99e-01, 1.00e+00},
    {1.04e-05, 9.39e-05, 7.11e-04, 4.32e-03, 2.04e-02, 7.33e-02, 1.96e-01, 3.91e-01, 6.16e-01, 8.10e-01, 9.31e-01, 9.82e-01, 9.97e-01},
    {1.34e-07, 2.19e-06, 2.90e-05, 3.00e-04, 2.35e-03, 1.34e-02, 5.31e-02, 1.49e-01, 3.10e-01, 5.28e-01, 7.49e-01, 9.03e-01, 9.74e-01},
    {1.43e-09, 4.21e-08, 9.78e-07, 1.72e-05, 2.21e-04, 2.01e-03, 1.20e-02, 4.47e-02, 1.17e-01, 2.54e-01, 4.75e-01, 7.20e-01, 8.93e-01},
    {1.32e-11, 7.02e-10, 2.87e-08, 8.60e-07, 1.82e-05, 2.59e-04, 2.32e-03, 1.13e-02, 3.13e-02, 7.74e-02, 2.11e-01, 4.57e-01, 7.24e-01},
    {1.09e-13, 1.05e-11, 7.51e-10, 3.85e-08, 1.35e-06, 3.02e-05, 4.00e-04, 2.38e-03, 3.36e-03, 2.94e-02, 1.05e-01, 2.36e-01, 4.79e-01},
    {1.12e-15, 1.40e-13, 1.80e-11, 1.58e-09, 9.07e-08, 3.25e-06, 6.30e-05, 3.70e-04, 2.83e-03, 2.94e-02, 1.05e-01, 2.36e-01, 3.42e-01},
    {1.12e-15, 1.89e-15, 4.00e-13, 6.03e-11, 5.73e-09, 3.24e-07, 9.24e-06, 1.74e-05, 2.82e-03, 2.94e-02, 1.05e-01, 2.36e-01, 3.42e-01},
    {1.12e-15, 1.34e-15, 9.33e-15, 2.16e-12, 3.41e-10, 3.05e-08, 1.26e-06, 1.74e-05, 1.76e-03, 2.25e-02, 1.03e-01, 2.36e-01, 3.42e-01},
    {1.12e-15, 1.34e-15, 1.34e-15, 7.19e-14, 1.92e-11, 2.75e-09, 1.56e-07, 1.03e-05, 9.31e-04, 1.52e-02, 8.70e-02, 2.36e-01, 3.42e-01}};
// 2D, r^-6, orders 1 .. 12
constexpr Real kError2D6[12][kTauColumns] = {
    {1.12e-01, 1.86e-01, 2.88e-01, 4.17e-01, 5.59e-01, 6.95e-01, 8.08e-01, 8.91e-01, 9.44e-01, 9.74e-01, 9.89e-01, 9.95e-01, 9.98e-01},
    {2.50e-03, 7.46e-03, 2.04e-02, 4.99e-02, 1.08e-01, 2.03e-01, 3.34e-01, 4.88e-01, 6.44e-01, 7.78e-01, 8.75e-01, 9.37e-01, 9.71e-01},
    {2.25e-05, 1.19e-04, 5.61e-04, 2.35e-03, 8.56e-03, 2.69e-02, 6.99e-02, 1.50e-01, 2.70e-01, 4.23e-01, 5.89e-01, 7.40e-01, 8.53e-01},
    {1.79e-07, 1.68e-06, 1.36e-05, 9.37e-05, 5.41e-04, 2.60e-03, 1.01e-02, 3.06e-02, 7.33e-02, 1.50e-01, 2.72e-01, 4.37e-01, 6.15e-01},
    {1.09e-09, 1.81e-08, 2.56e-07, 3.05e-06, 3.00e-05, 2.30e-04, 1.27e-03, 4.73e-03, 1.20e-02, 2.58e-02, 6.34e-02, 1.57e-01, 3.18e-01},
    {6.18e-12, 1.84e-10, 4.47e-09, 8.80e-08, 1.40e-06, 1.77e-05, 1.48e-04, 5.64e-04, 1.37e-03, 1.26e-02, 4.83e-02, 1.19e-01, 2.28e-01},
    {3.05e-14, 1.66e-12, 7.14e-11, 2.46e-09, 6.40e-08, 1.22e-06, 1.48e-05, 2.45e-05, 1.37e-03, 1.26e-02, 4.83e-02, 1.19e-01, 2.28e-01},
    {1.00e-15, 1.44e-14, 1.07e-12, 6.19e-11, 2.77e-09, 8.52e-08, 1.29e-06, 1.55e-05, 7.95e-04, 8.73e-03, 4.29e-02, 1.19e-01, 2.28e-01},
    {1.00e-15, 1.12e-15, 1.43e-14, 1.55e-12, 1.10e-10, 5.59e-09, 1.06e-07, 7.37e-06, 3.62e-04, 5.07e-03, 3.13e-02, 1.07e-01, 2.28e-01},
    {1.00e-15, 1.12e-15, 1.12e-15, 3.72e-14, 4.50e-12, 3.35e-10, 6.26e-09, 2.33e-06, 1.49e-04, 2.73e-03, 2.10e-02, 8.55e-02, 2.17e-01},
    {1.00e-15, 1.12e-15, 1.12e-15, 1.12e-15, 1.73e-13, 2.14e-11, 1.82e-10, 6.52e-07, 5.83e-05, 1.42e-03, 1.35e-02, 6.49e-02, 1.90e-01},
    {1.00e-15, 1.00e-15, 1.00e-15, 1.00e-15, 4.67e-15, 1.31e-12, 1.20e-10, 1.75e-07, 2.23e-05, 7.19e-04, 8.46e-03, 4.77e-02, 1.59e-01}};
// 3D, r^-12, orders 1 .. 6
constexpr Real kError3D12[6][kTauColumns] = {
    {3.99e-01, 5.79e-01, 7.53e-01, 8.84e-01, 9.58e-01, 9.89e-01, 9.98e-01, 1.00e+00, 1.00e+00, 1.00e+00, 1.00e+00, 1.00e+00, 1.00e+00},
    {3.12e-02, 8.37e-02, 1.93e-01, 3.68e-01, 5.79e-01, 7.69e-01, 8.99e-01, 9.66e-01, 9.92e-01, 9.99e-01, 1.00e+00, 1.00e+00, 1.00e+00},
    {8.41e-04, 4.06e-03, 1.65e-02, 5.51e-02, 1.49e-01, 3.19e-01, 5.33e-01, 7.30e-01, 8.74e-01, 9.56e-01, 9.89e-01, 9.98e-01, 1.00e+00},
    {1.59e-05, 1.36e-04, 9.50e-04, 5.28e-03, 2.31e-02, 7.77e-02, 1.96e-01, 3.67e-01, 5.61e-01, 7.50e-01, 8.95e-01, 9.69e-01, 9.94e-01},
    {2.21e-07, 3.36e-06, 4.06e-05, 3.81e-04, 2.74e-03, 1.45e-02, 5.24e-02, 1.29e-01, 2.37e-01, 3.98e-01, 6.21e-01, 8.27e-01, 9.46e-01},
    {2.53e-09, 6.84e-08, 1.43e-06, 2.24e-05, 2.63e-04, 2.22e-03, 1.19e-02, 3.40e-02, 5.39e-02, 8.77e-02, 2.31e-01, 5.05e-01, 7.75e-01}};
// 3D, r^-6, orders 1 .. 6
constexpr Real kError3D6[6][kTauColumns] = {
    {1.26e-01, 2.05e-01, 3.13e-01, 4.43e-01, 5.81e-01, 7.10e-01, 8.17e-01, 8.95e-01, 9.45e-01, 9.74e-01, 9.89e-01, 9.95e-01, 9.98e-01},
    {4.15e-03, 1.21e-02, 3.16e-02, 7.25e-02, 1.45e-01, 2.49e-01, 3.78e-01, 5.18e-01, 6.56e-01, 7.77e-01, 8.70e-01, 9.32e-01, 9.68e-01},
    {4.19e-05, 2.11e-04, 9.34e-04, 3.59e-03, 1.21e-02, 3.47e-02, 8.22e-02, 1.59e-01, 2.59e-01, 3.83e-01, 5.30e-01, 6.81e-01, 8.09e-01},
    {3.89e-07, 3.44e-06, 2.57e-05, 1.59e-04, 8.01e-04, 3.36e-03, 1.14e-02, 2.83e-02, 5.13e-02, 8.01e-02, 1.70e-01, 3.34e-01, 4.47e-01},
    {2.61e-09, 4.03e-08, 5.14e-07, 5.43e-06, 4.72e-05, 3.16e-04, 1.40e-03, 2.87e-03, 8.43e-03, 5.34e-02, 1.70e-01, 3.34e-01, 4.33e-01},
    {1.64e-11, 4.43e-10, 9.50e-09, 1.61e-07, 2.21e-06, 2.48e-05, 1.64e-04, 1.64e-04, 8.43e-03, 5.34e-02, 1.70e-01, 3.34e-01, 4.33e-01}};

// log-log interpolation between the measured columns (h/g a factor sqrt 2 apart)
Real tableError(const Real (*rows)[kTauColumns], int order, Real tau) {
  if (tau > kTauLast) return 1.0;
  const Real k = std::max(0.0, 2.0 * std::log2(tau / kTauFirst));
  const int j = std::min(int(k), kTauColumns - 2);
  const Real t = std::min(1.0, k - j);
  const Real* row = rows[order - 1];
  return std::exp((1.0 - t) * std::log(row[j]) + t * std::log(row[j + 1]));
}

}  // namespace

Real volumeQuadratureError(int dim, int order, Real size, Real gap, Real r0) {
  const int rows = dim == 2 ? kMaxVolumeOrder2D : kMaxVolumeOrder3D;
  if (order < 1 || order > rows || !(gap > 0.0)) return 1.0e300;
  const Real tau = size / gap, x = r0 / gap;
  const Real e12 = dim == 2 ? tableError(kError2D12, order, tau) : tableError(kError3D12, order, tau);
  const Real e6 = dim == 2 ? tableError(kError2D6, order, tau) : tableError(kError3D6, order, tau);
  // error <= E12 |F12| + E6 |F6|; over the larger part, |F6| counts at most 1 and |F12| at most
  // (r0/g)^6 (no point pair of the cells is closer than g, and the ratio of the parts' point
  // forces is (r0/r)^6 in 3D, 0.72 (r0/r)^6 for the line laws of plane strain)
  const Real q = std::pow(x, 6);
  return e12 * std::min(1.0, q) + e6;
}

namespace {

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
  if (!(options_.quadratureTolerance >= 0.0) || !std::isfinite(options_.quadratureTolerance))
    throw InputError(where() + "the quadrature tolerance must be finite and >= 0, got " +
                     std::to_string(options_.quadratureTolerance));
  if (std::isnan(options_.cutoff) || std::isnan(options_.skin) || std::isinf(options_.skin))
    throw InputError(where() + "cutoff and skin must be numbers (the skin finite)");
  const int allPlanes = (1 << dim_) - 1;
  if (options_.symmetryPlanes & ~allPlanes)
    throw InputError(where() + "symmetry planes beyond the mesh's " + std::to_string(dim_) + " axes");
  if (options_.formulation == Formulation::Axisymmetric && (options_.symmetryPlanes & 1))
    throw InputError(where() + "x = 0 is the axis of an axisymmetric model, not a symmetry plane");
  if (!options_.bodySymmetryPlanes.empty() && int(options_.bodySymmetryPlanes.size()) != numBodies_)
    throw InputError(where() + std::to_string(options_.bodySymmetryPlanes.size()) +
                     " bodies' symmetry planes for " + std::to_string(numBodies_) + " bodies");
  for (int planes : options_.bodySymmetryPlanes)
    if (planes & ~options_.symmetryPlanes)
      throw InputError(where() + "a body is cut by a plane that is not a symmetry plane of the model");
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
  std::vector<Candidate> out;
  forEachCandidate(coords, radius, [&](const Candidate& c) { out.push_back(c); });
  std::sort(out.begin(), out.end(), [](const Candidate& a, const Candidate& b) {
    return a.rowCell != b.rowCell ? a.rowCell < b.rowCell
                                  : a.colCell != b.colCell ? a.colCell < b.colCell : a.image < b.image;
  });
  return out;
}

VolumeInteraction::PairListSize VolumeInteraction::pairListSize(const Real* coords, double stopAboveMegabytes) const {
  PairListSize size;
  // the candidates (listed, then sorted), the kernel's list, and the graph's (row node, column node) couplings
  const auto megabytes = [&] {
    return (size.pairs * double(sizeof(Candidate) + 2 * sizeof(VolumePair)) +
            size.couplings * double(sizeof(std::pair<LocalIndex, LocalIndex>))) / (1024.0 * 1024.0);
  };
  struct Stop {};
  try {
    forEachCandidate(coords, cutoff() + skin(), [&](const Candidate& c) {
      size.pairs += 1.0;
      size.couplings += double(mesh::nodesPerCell(CellType(view_.cellType(c.rowCell)))) *
                        mesh::nodesPerCell(CellType(view_.cellType(c.colCell)));
      // checked every 2^20 pairs: the count stops once past the limit
      if (std::fmod(size.pairs, 1048576.0) == 0.0 && megabytes() > stopAboveMegabytes) throw Stop{};
    });
  } catch (const Stop&) {
    size.stopped = true;
  }
  size.megabytes = megabytes();
  return size;
}

void VolumeInteraction::forEachCandidate(const Real* coords, Real radius,
                                         const std::function<void(const Candidate&)>& visit) const {
  using Box = CGAL::Box_intersection_d::Box_with_info_d<double, 3, LocalIndex>;
  // per body: each cell's current bounding box (holding the curved cell), grown by radius / 2 on
  // every side; its size for the error estimate (volumeQuadratureError): the longest edge
  // between corners (the tensor rule resolves each parametric direction along its edges), on a
  // tetrahedron half of it (its sub-hexahedra's edges run from a vertex to an edge midpoint, from
  // there to a face centroid, and on to the centroid: at most half the longest edge)
  std::vector<std::vector<Box>> boxes(numBodies_);
  std::vector<std::array<Real, 6>> bounds(view_.cellBody.extent(0));
  std::vector<Real> sizes(view_.cellBody.extent(0));
  for (int b = 0; b < numBodies_; ++b)
    for (LocalIndex c : cellsOfBody_[b]) {
      std::array<Real, 6>& bb = bounds[c];
      Real lo0[3], hi0[3];
      cellBox(c, coords, lo0, hi0);
      for (int i = 0; i < 3; ++i) bb[i] = lo0[i], bb[3 + i] = hi0[i];
      sizes[c] = cellSize(c, coords);
      double lo[3], hi[3];
      for (int i = 0; i < 3; ++i) {
        lo[i] = bb[i] - 0.5 * radius;
        hi[i] = bb[3 + i] + 0.5 * radius;
      }
      boxes[b].emplace_back(lo, hi, c);
    }
  const int planes = options_.symmetryPlanes;
  for (int k = 0; k < numBodies_; ++k)
    for (int l = k; l < numBodies_; ++l)
      for (int image = 0; image <= planes; ++image) {
        if ((image & ~planes) || boxes[k].empty() || boxes[l].empty()) continue;  // images: subsets of the planes
        // a body meets its image only where that is another body of the whole model
        const int cutting = options_.bodySymmetryPlanes.empty() ? 0 : options_.bodySymmetryPlanes[k];
        if (k == l && !(image & ~cutting)) continue;
        auto mirrored = [&](std::array<Real, 6> b) {
          for (int i = 0; i < 3; ++i)
            if (image & (1 << i)) {
              const Real lo = b[i];
              b[i] = -b[3 + i];
              b[3 + i] = -lo;
            }
          return b;
        };
        auto report = [&](const Box& p, const Box& q) {
          const std::array<Real, 6>& bp = bounds[p.info()];
          const std::array<Real, 6> bq = mirrored(bounds[q.info()]);
          Real gap2 = 0.0;
          for (int i = 0; i < 3; ++i) {
            const Real g = std::max({0.0, bp[i] - bq[3 + i], bq[i] - bp[3 + i]});
            gap2 += g * g;
          }
          if (gap2 > radius * radius) return;  // the boxes' corners are farther apart
          const Real gap = std::sqrt(gap2), size = std::max(sizes[p.info()], sizes[q.info()]);
          const bool tet = cellTypeInfo(CellType(view_.cellType(p.info()))).simplex ||
                           cellTypeInfo(CellType(view_.cellType(q.info()))).simplex;
          visit({p.info(), q.info(), image, gap, size, tet});
          // the reverse direction (the mirror is its own inverse: the same gap); a body and its own
          // image: intersecting both ways round, reported both ways round
          if (k != l) visit({q.info(), p.info(), image, gap, size, tet});
        };
        // box_intersection_d reorders its inputs: work on copies (of body l: its image, new boxes)
        std::vector<Box> bk = boxes[k], bl;
        bl.reserve(boxes[l].size());
        for (const Box& b : boxes[l]) {
          double lo[3], hi[3];
          for (int i = 0; i < 3; ++i) {
            const bool flip = image & (1 << i);
            lo[i] = flip ? -b.max_coord(i) : b.min_coord(i);
            hi[i] = flip ? -b.min_coord(i) : b.max_coord(i);
          }
          bl.emplace_back(lo, hi, b.info());
        }
        CGAL::box_intersection_d(bk.begin(), bk.end(), bl.begin(), bl.end(), report);
      }
}

Real VolumeInteraction::cellSize(LocalIndex cell, const Real* coords) const {
  const CellTypeInfo& row = cellTypeInfo(CellType(view_.cellType(cell)));
  const int corners = cornerCount(row);
  auto distance = [&](int a, int b) {
    Real d2 = 0.0;
    for (int i = 0; i < dim_; ++i) {
      const Real d = coords[std::size_t(dim_) * view_.cellNodes(cell, a) + i] -
                     coords[std::size_t(dim_) * view_.cellNodes(cell, b) + i];
      d2 += d * d;
    }
    return std::sqrt(d2);
  };
  Real longest = 0.0;
  if (row.simplex) {
    for (int a = 0; a < corners; ++a)
      for (int b = a + 1; b < corners; ++b) longest = std::max(longest, distance(a, b));
    return 0.5 * longest;
  }
  // quadrilateral corners 0-1-2-3 around; hexahedron: 0-3 and 4-7 around, 0-4 .. 3-7 between
  const int ring = corners == 8 ? 4 : corners;
  for (int a = 0; a < ring; ++a) {
    longest = std::max(longest, distance(a, (a + 1) % ring));
    if (corners == 8) {
      longest = std::max(longest, distance(4 + a, 4 + (a + 1) % ring));
      longest = std::max(longest, distance(a, 4 + a));
    }
  }
  return longest;
}

VolumeInteraction::OrderChoice VolumeInteraction::chooseOrder(Real size, Real gap, bool tet) const {
  // a tetrahedron's rule holds kMaxTetOrder^3 points on each of its four hexahedra: the base order too is capped
  const int cap = tet ? std::min(maxOrder_, kMaxTetOrder) : maxOrder_;
  const int base = std::min(options_.quadratureOrder, cap);
  const Real tolerance = options_.quadratureTolerance;
  if (tolerance <= 0.0) return {base, 0.0, true};
  const Real r0 = potential_->r0() * lengthScale_;
  // the closest the cells come before the next rebuild: each point moves by at most skin / 2
  const Real closest = std::max(gap - skin(), kContactGapFloor * r0);
  Real estimate = 0.0;
  for (int n = base; n <= cap; ++n) {
    estimate = volumeQuadratureError(dim_, n, size, closest, r0);
    if (estimate <= tolerance) return {n, estimate, true};
  }
  return {cap, estimate, false};
}

VolumeInteraction::ContactQuadrature VolumeInteraction::contactQuadrature(const Real* coords,
                                                                        const std::vector<char>& surfaceCells) const {
  ContactQuadrature out;
  // the smallest gap between the bodies: a search radius doubled from cutoff + skin until a pair
  // is found (bodies may start farther apart), at most the extent of the mesh
  Real extent = 0.0;
  for (int i = 0; i < dim_; ++i) {
    Real lo = std::numeric_limits<Real>::max(), hi = -lo;
    for (LocalIndex n : interactingNodes_) {
      lo = std::min(lo, coords[std::size_t(dim_) * n + i]);
      hi = std::max(hi, coords[std::size_t(dim_) * n + i]);
    }
    if (!interactingNodes_.empty()) extent += (hi - lo) * (hi - lo);
  }
  extent = std::sqrt(extent);
  std::vector<Candidate> pairs;
  for (Real radius = cutoff() + skin(); pairs.empty() && radius <= 2.0 * extent + cutoff() + skin(); radius *= 2.0)
    pairs = candidates(coords, radius);
  Real closest = std::numeric_limits<Real>::infinity();
  for (const Candidate& c : pairs) closest = std::min(closest, c.gap);
  const Real r0 = potential_->r0() * lengthScale_, contactGap = kContactGapFloor * r0;
  out.neededSize = std::numeric_limits<Real>::infinity();
  for (const Candidate& c : pairs) {
    // the surface cells where the bodies first touch (within the skin of the smallest gap): the
    // cells farther out come as close only as the contact grows; the run's summary counts the
    // pairs the maximum order leaves above the tolerance then
    if (c.gap > closest + skin()) continue;
    if (!surfaceCells.empty() && (!surfaceCells[c.rowCell] || !surfaceCells[c.colCell])) continue;
    const int cap = c.tet ? std::min(maxOrder_, kMaxTetOrder) : maxOrder_;
    // the order the pair gets in contact: chooseOrder at a box gap that leaves contactGap
    const OrderChoice choice = chooseOrder(c.size, contactGap + skin(), c.tet);
    out.largestSize = std::max(out.largestSize, c.size);
    // the worst pair: one that misses the tolerance before one that meets it, then the larger estimate
    const bool worse = out.maxOrder == 0 || (out.withinTolerance && !choice.withinTolerance) ||
                       (out.withinTolerance == choice.withinTolerance && choice.estimate > out.estimate);
    if (worse) {
      out.order = choice.order;
      out.estimate = choice.estimate;
      out.withinTolerance = choice.withinTolerance;
      out.maxOrder = cap;
    }
    if (options_.quadratureTolerance > 0.0) {
      // the largest size the cap brings within the tolerance at the contact gap (the estimate grows with size)
      Real lo = 0.0, hi = c.size;
      if (volumeQuadratureError(dim_, cap, hi, contactGap, r0) > options_.quadratureTolerance) {
        for (int it = 0; it < 60; ++it) {
          const Real mid = 0.5 * (lo + hi);
          (volumeQuadratureError(dim_, cap, mid, contactGap, r0) <= options_.quadratureTolerance ? lo : hi) = mid;
        }
        out.neededSize = std::min(out.neededSize, lo);
      }
    }
  }
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
  pairs_.clear();
  LocalIndex atMax = 0, above = 0;
  summary_.minCellGap = std::numeric_limits<Real>::infinity();
  for (const Candidate& c : candidates(coords, cutoff + skin)) {
    if (!rowCells_.empty() && !rowCells_[c.rowCell]) continue;
    const OrderChoice choice = chooseOrder(c.size, c.gap, c.tet);
    pairs_.push_back({c.rowCell, c.colCell, choice.order, c.image});
    const int cap = c.tet ? std::min(maxOrder_, kMaxTetOrder) : maxOrder_;
    summary_.maxOrderUsed = std::max(summary_.maxOrderUsed, choice.order);
    summary_.maxErrorEstimate = std::max(summary_.maxErrorEstimate, choice.estimate);
    atMax += choice.order == cap;
    above += !choice.withinTolerance;
    summary_.minCellGap = std::min(summary_.minCellGap, c.gap);
  }
  summary_.numAtMaxOrder = std::max(summary_.numAtMaxOrder, atMax);
  summary_.numAboveTolerance = std::max(summary_.numAboveTolerance, above);
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
