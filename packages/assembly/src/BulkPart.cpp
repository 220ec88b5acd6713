#include "cgcm/assembly/BulkPart.hpp"

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>

#include "cgcm/core/Error.hpp"
#include "cgcm/fem/Dispatch.hpp"

namespace cgcm::assembly {

namespace {

using DofView = Kokkos::View<LocalIndex**, Kokkos::LayoutRight>;
using CoordView = Kokkos::View<Real***, Kokkos::LayoutRight>;
using OffsetView = Kokkos::View<std::uint16_t**, Kokkos::LayoutRight>;

struct BlockFailures {
  int count = 0;
  LocalIndex first = 0;  ///< the lowest failed cell of the block, if count > 0
};

// Reference coordinates, displacements and current coordinates of cell c.
template <int nn, int dim>
KOKKOS_INLINE_FUNCTION void gatherCell(const LocalIndex c, const DofView& dofLids, const CoordView& Xref,
                                       const BulkPart::ConstVectorView& u, Real (&X)[nn][dim], Real (&ue)[nn][dim],
                                       Real (&x)[nn][dim]) {
  for (int a = 0; a < nn; ++a)
    for (int i = 0; i < dim; ++i) {
      X[a][i] = Xref(c, a, i);
      ue[a][i] = u(dofLids(c, a * dim + i), 0);
      x[a][i] = X[a][i] + ue[a][i];
    }
}

// Evaluates one block with a fixed (formulation, element) kernel; returns the
// number of cells that turned inside out and the first of them.
template <class Kernel>
BlockFailures assembleBlock(const DofView& dofLids, const DofView& colLids, const OffsetView& offsets,
                  const CoordView& Xref, const BulkPart::ConstVectorView& u, const BulkPart::VectorView& f,
                  const BulkPart::LocalMatrix* J, bool sortedRows, const material::NeoHookean& mat) {
  constexpr int nn = Kernel::numNodes, dim = Kernel::dim, nd = Kernel::numDofs;
  const LocalIndex numCells = LocalIndex(dofLids.extent(0));
  int failures = 0;
  const bool withTangent = J != nullptr;
  BulkPart::LocalMatrix K = withTangent ? *J : BulkPart::LocalMatrix();
  const bool byOffsets = withTangent && offsets.extent(0) == std::size_t(numCells) && numCells > 0;
  Kokkos::parallel_reduce(
      "cgcm::assembleBlock", Kokkos::RangePolicy<ExecSpace>(0, numCells),
      [=](const LocalIndex c, int& failed) {
        Real X[nn][dim], ue[nn][dim], x[nn][dim];
        gatherCell(c, dofLids, Xref, u, X, ue, x);
        Real fe[nd];
        bool ok;
        if (withTangent) {
          Real ke[nd][nd];
          ok = Kernel::residualAndTangent(X, x, ue, mat, fe, ke);
          if (ok && byOffsets) {  // row r of node a: node b's columns start at offsets(c, a nn + b) in it
            for (int r = 0; r < nd; ++r) {
              const auto start = K.graph.row_map(dofLids(c, r));
              const int a = r / dim;
              for (int b = 0; b < nn; ++b) {
                const auto at = start + offsets(c, a * nn + b);
                for (int j = 0; j < dim; ++j) Kokkos::atomic_add(&K.values(at + j), ke[r][b * dim + j]);
              }
            }
          } else if (ok) {
            LocalIndex cols[nd];
            for (int k = 0; k < nd; ++k) cols[k] = colLids(c, k);
            for (int r = 0; r < nd; ++r) K.sumIntoValues(dofLids(c, r), cols, nd, ke[r], sortedRows, true);
          }
        } else {
          ok = Kernel::residual(X, x, ue, mat, fe);
        }
        if (!ok) {
          ++failed;
          return;
        }
        for (int r = 0; r < nd; ++r) Kokkos::atomic_add(&f(dofLids(c, r), 0), fe[r]);
      },
      failures);
  if (failures == 0) return {};
  // Only on failure: a second pass finds the first inverted cell for the message.
  LocalIndex first = numCells;
  Kokkos::parallel_reduce(
      "cgcm::firstInvertedCell", Kokkos::RangePolicy<ExecSpace>(0, numCells),
      [=](const LocalIndex c, LocalIndex& lowest) {
        Real X[nn][dim], ue[nn][dim], x[nn][dim], fe[nd];
        gatherCell(c, dofLids, Xref, u, X, ue, x);
        if (!Kernel::residual(X, x, ue, mat, fe) && c < lowest) lowest = c;
      },
      Kokkos::Min<LocalIndex>(first));
  return {failures, first};
}

}  // namespace

BulkPart::BulkPart(const DofMap& dofs, const mesh::Mesh& mesh, int body, Formulation formulation,
                   const material::NeoHookean& material)
    : overlap_(dofs.overlapMap().get()), formulation_(formulation), dim_(formulationDim(formulation)),
      material_(material) {
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
    const auto& blk = mesh.blocks[b];
    if (blk.body != body) continue;
    if (!fem::solidKernelTakes(formulation, blk.type))
      throw InputError(std::string("element block \"") + blk.name + "\" has " + mesh::cellTypeName(blk.type) +
                       " cells, which the " + formulationName(formulation) + " formulation does not support (it takes " +
                       fem::cellTypesTakenBy(formulation) + ")");
    const auto& cells = dofs.localCells(b);
    const int nn = mesh::nodesPerCell(blk.type);
    Block d;
    d.type = blk.type;
    d.numNodes = nn;
    d.name = blk.name;
    for (LocalIndex c : cells) d.cellIds.push_back(blk.cellId(c));
    d.dofLids = DofView("dofLids", cells.size(), nn * dim_);
    d.X = CoordView("X", cells.size(), nn, dim_);
    for (std::size_t k = 0; k < cells.size(); ++k)
      for (int a = 0; a < nn; ++a) {
        const LocalIndex node = blk.connectivity[std::size_t(cells[k]) * nn + a];
        for (int i = 0; i < dim_; ++i) {
          d.dofLids(k, a * dim_ + i) = overlap_->getLocalElement(dofs.dof(node, i));
          d.X(k, a, i) = mesh.coord(node, i);
        }
      }
    blocks_.push_back(d);
  }
}

LocalIndex BulkPart::numLocalCells() const {
  LocalIndex n = 0;
  for (const auto& b : blocks_) n += LocalIndex(b.dofLids.extent(0));
  return n;
}

void BulkPart::appendCellNeighbours(std::vector<std::vector<LocalIndex>>& neighbours) const {
  for (const auto& b : blocks_)
    for (std::size_t c = 0; c < b.dofLids.extent(0); ++c)
      for (int a = 0; a < b.numNodes; ++a) {
        auto& list = neighbours[b.dofLids(c, a * dim_) / dim_];
        for (int k = 0; k < b.numNodes; ++k) list.push_back(b.dofLids(c, k * dim_) / dim_);
      }
}

void BulkPart::setMatrixGraph(const Map& columns, const LocalMatrix& J, bool sortedRows) {
  const auto rowMap = J.graph.row_map;
  const auto entries = J.graph.entries;
  for (auto& b : blocks_) {
    const std::size_t numCells = b.dofLids.extent(0), nd = b.dofLids.extent(1);
    const int nn = b.numNodes;
    b.colLids = DofView("colLids", numCells, nd);
    for (std::size_t c = 0; c < numCells; ++c)
      for (std::size_t k = 0; k < nd; ++k)
        b.colLids(c, k) = columns.getLocalElement(overlap_->getGlobalElement(b.dofLids(c, k)));
    // where node b's columns start in the rows of node a's dofs: the same offset in each of them, and
    // b's dofs side by side from there (the graph is built node by node, so they are)
    b.offsets = OffsetView("offsets", numCells, std::size_t(nn) * nn);
    bool found = true;
    for (std::size_t c = 0; c < numCells && found; ++c)
      for (int a = 0; a < nn && found; ++a) {
        const auto first = rowMap(b.dofLids(c, a * dim_)), end = rowMap(b.dofLids(c, a * dim_) + 1);
        for (int k = 0; k < nn && found; ++k) {
          const LocalIndex col = b.colLids(c, k * dim_);
          const LocalIndex *row = entries.data() + first, *rowEnd = entries.data() + end;
          const LocalIndex* at = sortedRows ? std::lower_bound(row, rowEnd, col) : std::find(row, rowEnd, col);
          const auto offset = std::size_t(at - row);
          found = at != rowEnd && *at == col && offset <= 65535;
          for (int i = 0; i < dim_ && found; ++i) {
            const auto row = b.dofLids(c, a * dim_ + i);
            const auto start = rowMap(row);
            for (int j = 0; j < dim_ && found; ++j)
              found = start + offset + j < rowMap(row + 1) && entries(start + offset + j) == b.colLids(c, k * dim_ + j);
          }
          if (found) b.offsets(c, std::size_t(a) * nn + k) = std::uint16_t(offset);
        }
      }
    if (!found) b.offsets = OffsetView();
  }
}

int BulkPart::numBlocksWithOffsets() const {
  int n = 0;
  for (const auto& b : blocks_) n += b.dofLids.extent(0) > 0 && b.offsets.extent(0) == b.dofLids.extent(0) ? 1 : 0;
  return n;
}

BulkPart::CellFailures BulkPart::assemble(const ConstVectorView& u, const VectorView& f, const LocalMatrix* J,
                                          bool sortedRows) const {
  CellFailures out;
  for (const auto& b : blocks_) {
    BlockFailures bf;
    const bool assembled = fem::withSolidKernel(formulation_, b.type, [&](auto kernel) {
      bf = assembleBlock<decltype(kernel)>(b.dofLids, b.colLids, useOffsets_ ? b.offsets : OffsetView(), b.X, u, f, J,
                                           sortedRows, material_);
    });
    if (!assembled) throw std::logic_error("BulkPart: no kernel for block \"" + b.name + "\" (checked at construction)");
    if (bf.count > 0 && out.first.empty()) {
      const LocalIndex c = bf.first;
      std::ostringstream where;
      where << "cell " << b.cellIds[c] << " of block \"" << b.name << "\" (its first node "
            << overlap_->getGlobalElement(b.dofLids(c, 0)) / dim_ << " at X = (";
      for (int i = 0; i < dim_; ++i) where << (i ? ", " : "") << b.X(c, 0, i);
      where << "))";
      out.first = where.str();
    }
    out.count += bf.count;
  }
  return out;
}

}  // namespace cgcm::assembly
