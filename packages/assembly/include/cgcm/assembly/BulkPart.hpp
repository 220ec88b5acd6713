#pragma once
// The bulk of one body as a part of the discrete problem: the internal force
// and tangent of its cells on this rank (updated Lagrangian Neo-Hookean,
// package fem), in Kokkos element loops that scatter into the overlap
// (owned + shared) rows with atomic adds. It knows its cells, their dofs and
// its material; the maps, the graph and the sum over parts belong to the
// Problem.
#include <cstdint>
#include <string>
#include <vector>

#include <Kokkos_Core.hpp>

#include "cgcm/assembly/DofMap.hpp"
#include "cgcm/core/Formulation.hpp"
#include "cgcm/material/NeoHookean.hpp"
#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::assembly {

class BulkPart {
 public:
  using LocalMatrix = Matrix::local_matrix_device_type;
  using ConstVectorView = Vector::dual_view_type::t_dev::const_type;
  using VectorView = Vector::dual_view_type::t_dev;

  /// The cells of body `body` that this rank evaluates. Throws InputError for
  /// a cell type the formulation does not support.
  BulkPart(const DofMap& dofs, const mesh::Mesh& mesh, int body, Formulation formulation,
           const material::NeoHookean& material);

  const material::NeoHookean& material() const { return material_; }
  LocalIndex numLocalCells() const;

  /// Appends, for each node of this rank's cells (index = overlap local dof /
  /// dim), the nodes it shares a cell with (overlap node indices, itself
  /// included, repeated): the element cliques of the matrix graph.
  void appendCellNeighbours(std::vector<std::vector<LocalIndex>>& neighbours) const;
  /// Caches, for the matrix J (after every new graph, J in assembly mode), the column ids of the
  /// cells' dofs and where each cell's entries lie in J's rows: per cell and pair of its nodes (a, b),
  /// the offset of b's columns in the rows of a's dofs, so that the scatter adds each entry at a
  /// known place instead of finding its column by bisection in the row (38 % of the Jacobian's time
  /// on a hex8 box). A block whose rows do not hold each node's columns side by side, the same in
  /// the rows of every dof of a node (or more than 65535 entries in), keeps the bisection. sortedRows:
  /// J's rows hold their column ids in ascending order (searched by bisection here too).
  void setMatrixGraph(const Map& columns, const LocalMatrix& J, bool sortedRows);
  /// Whether the scatter uses the offsets (true, the default, where setMatrixGraph found them) or
  /// finds every entry by bisection (false; a test compares the two).
  void useScatterOffsets(bool use) { useOffsets_ = use; }
  /// Blocks whose scatter uses offsets (of those with cells), after setMatrixGraph.
  int numBlocksWithOffsets() const;

  /// Cells that turned inside out (J <= 0); their contributions are left out.
  struct CellFailures {
    int count = 0;
    std::string first;  ///< "cell 12 of block \"b\" (its first node 40 at X = (...))", empty if none
  };
  /// f += f_int of the cells, and J += their tangent if J is given (J's
  /// column ids must be those of setColumnMap). sortedRows: J's rows hold
  /// their column ids in ascending order (Tpetra's after fillComplete), so
  /// each entry is found by bisection instead of a scan of its row.
  CellFailures assemble(const ConstVectorView& u, const VectorView& f, const LocalMatrix* J, bool sortedRows) const;

 private:
  struct Block {
    CellType type;
    int numNodes;
    Kokkos::View<LocalIndex**, Kokkos::LayoutRight> dofLids;  // [cell][a*dim+i], overlap local ids
    Kokkos::View<LocalIndex**, Kokkos::LayoutRight> colLids;  // [cell][a*dim+i], matrix column ids
    Kokkos::View<std::uint16_t**, Kokkos::LayoutRight> offsets;  // [cell][a*nn+b] (setMatrixGraph); empty: none
    Kokkos::View<Real***, Kokkos::LayoutRight> X;             // [cell][a][i], reference coordinates
    std::string name;                                         // the mesh block's
    std::vector<LocalIndex> cellIds;                          // block-local cell index in the whole mesh
  };
  const Map* overlap_;
  Formulation formulation_;
  int dim_;
  material::NeoHookean material_;
  std::vector<Block> blocks_;
  bool useOffsets_ = true;
};

}  // namespace cgcm::assembly
