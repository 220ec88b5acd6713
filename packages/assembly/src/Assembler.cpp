#include "cgcm/assembly/Assembler.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Assembly_Helpers.hpp>

#include <algorithm>
#include <chrono>
#include <set>

#include "cgcm/core/Error.hpp"
#include "cgcm/fem/SolidKernel.hpp"

namespace cgcm::assembly {

const char* formulationName(Formulation f) {
  switch (f) {
    case Formulation::PlaneStrain: return "plane strain";
    case Formulation::Axisymmetric: return "axisymmetric";
    case Formulation::ThreeD: return "3D";
  }
  return "?";
}

int formulationDim(Formulation f) { return f == Formulation::ThreeD ? 3 : 2; }

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

using LocalMatrix = Matrix::local_matrix_device_type;
using DofView = Kokkos::View<LocalIndex**, Kokkos::LayoutRight>;
using CoordView = Kokkos::View<Real***, Kokkos::LayoutRight>;
using ConstVecView = Vector::dual_view_type::t_dev::const_type;
using VecView = Vector::dual_view_type::t_dev;

// Evaluates one block with a fixed (formulation, element) kernel; returns the
// number of cells that turned inside out.
template <class Kernel>
int assembleBlock(const DofView& dofLids, const DofView& colLids, const CoordView& Xref,
                  const ConstVecView& u, const VecView& f, const LocalMatrix* J,
                  const material::NeoHookean& mat) {
  constexpr int nn = Kernel::numNodes, dim = Kernel::dim, nd = Kernel::numDofs;
  const LocalIndex numCells = LocalIndex(dofLids.extent(0));
  int failures = 0;
  const bool withTangent = J != nullptr;
  LocalMatrix K = withTangent ? *J : LocalMatrix();
  Kokkos::parallel_reduce(
      "cgcm::assembleBlock", Kokkos::RangePolicy<ExecSpace>(0, numCells),
      [=](const LocalIndex c, int& failed) {
        Real X[nn][dim], x[nn][dim];
        for (int a = 0; a < nn; ++a)
          for (int i = 0; i < dim; ++i) {
            X[a][i] = Xref(c, a, i);
            x[a][i] = X[a][i] + u(dofLids(c, a * dim + i), 0);
          }
        Real fe[nd];
        bool ok;
        if (withTangent) {
          Real ke[nd][nd];
          ok = Kernel::residualAndTangent(X, x, mat, fe, ke);
          if (ok) {
            LocalIndex cols[nd];
            for (int k = 0; k < nd; ++k) cols[k] = colLids(c, k);
            for (int r = 0; r < nd; ++r) K.sumIntoValues(dofLids(c, r), cols, nd, ke[r], false, true);
          }
        } else {
          ok = Kernel::residual(X, x, mat, fe);
        }
        if (!ok) {
          ++failed;
          return;
        }
        for (int r = 0; r < nd; ++r) Kokkos::atomic_add(&f(dofLids(c, r), 0), fe[r]);
      },
      failures);
  return failures;
}

}  // namespace

Assembler::Assembler(Teuchos::RCP<const DofMap> dofs, std::shared_ptr<const mesh::Mesh> mesh,
                     Formulation formulation, const material::NeoHookean& material)
    : dofs_(std::move(dofs)), mesh_(std::move(mesh)), formulation_(formulation), material_(material),
      dim_(formulationDim(formulation)) {
  if (mesh_->dim != dim_)
    throw InputError(std::string("Problem/Formulation = \"") + formulationName(formulation) + "\" needs a " +
                     std::to_string(dim_) + "D mesh, got a " + std::to_string(mesh_->dim) + "D one");
  const Map& overlap = *dofs_->overlapMap();
  for (std::size_t b = 0; b < mesh_->blocks.size(); ++b) {
    const auto& blk = mesh_->blocks[b];
    const bool fits = (dim_ == 2 && blk.type == mesh::CellType::Quad4) ||
                      (dim_ == 3 && (blk.type == mesh::CellType::Hex8 || blk.type == mesh::CellType::Tet4));
    if (!fits)
      throw InputError(std::string("element block \"") + blk.name + "\" has " + mesh::cellTypeName(blk.type) +
                       " cells, which the " + formulationName(formulation) + " formulation does not support");
    const auto& cells = dofs_->localCells(b);
    const int nn = mesh::nodesPerCell(blk.type);
    BlockData d;
    d.type = blk.type;
    d.numNodes = nn;
    d.dofLids = DofView("dofLids", cells.size(), nn * dim_);
    d.X = CoordView("X", cells.size(), nn, dim_);
    for (std::size_t k = 0; k < cells.size(); ++k)
      for (int a = 0; a < nn; ++a) {
        const LocalIndex node = blk.connectivity[std::size_t(cells[k]) * nn + a];
        for (int i = 0; i < dim_; ++i) {
          d.dofLids(k, a * dim_ + i) = overlap.getLocalElement(dofs_->dof(node, i));
          d.X(k, a, i) = mesh_->coord(node, i);
        }
      }
    blocks_.push_back(d);
  }
  uOverlap_ = Teuchos::rcp(new Vector(dofs_->overlapMap()));
  fOverlap_ = Teuchos::rcp(new Vector(dofs_->overlapMap()));
  exporter_ = Teuchos::rcp(new Export(dofs_->overlapMap(), dofs_->ownedMap()));
}

void Assembler::setExtraCouplings(std::vector<std::pair<LocalIndex, LocalIndex>> nodePairs) {
  std::sort(nodePairs.begin(), nodePairs.end());
  nodePairs.erase(std::unique(nodePairs.begin(), nodePairs.end()), nodePairs.end());
  if (nodePairs == extraCouplings_ && !graph_.is_null()) return;
  extraCouplings_ = std::move(nodePairs);
  graph_ = Teuchos::null;
}

Teuchos::RCP<const Graph> Assembler::graph() {
  if (graph_.is_null()) buildGraph();
  return graph_;
}

Teuchos::RCP<Matrix> Assembler::createMatrix() { return Teuchos::rcp(new Matrix(graph())); }

void Assembler::buildGraph() {
  // Row lengths: a generous bound from the cell cliques plus extra couplings per row node.
  const Map& overlap = *dofs_->overlapMap();
  std::vector<std::set<GlobalIndex>> rowCols;  // only used for the bound; cheap at these sizes
  std::size_t maxCliques = 0;
  {
    std::vector<int> cellsPerNode(overlap.getNodeNumElements() / dim_ + 1, 0);
    for (const auto& b : blocks_)
      for (std::size_t c = 0; c < b.dofLids.extent(0); ++c)
        for (int a = 0; a < b.numNodes; ++a) ++cellsPerNode[b.dofLids(c, a * dim_) / dim_];
    int maxCells = 0;
    for (int n : cellsPerNode) maxCells = std::max(maxCells, n);
    int maxNodes = 0;
    for (const auto& b : blocks_) maxNodes = std::max(maxNodes, b.numNodes);
    maxCliques = std::size_t(maxCells) * maxNodes * dim_;
  }
  std::vector<int> extraPerRow(mesh_->numNodes(), 0);
  int maxExtra = 0;
  for (const auto& [r, c] : extraCouplings_) maxExtra = std::max(maxExtra, ++extraPerRow[r]);
  const std::size_t maxPerRow = maxCliques + std::size_t(maxExtra) * dim_;

  graph_ = Teuchos::rcp(new Graph(dofs_->ownedMap(), dofs_->overlapMap(), maxPerRow));
  Tpetra::beginAssembly(*graph_);
  for (const auto& b : blocks_) {
    const int nd = b.numNodes * dim_;
    std::vector<GlobalIndex> gids(nd);
    for (std::size_t c = 0; c < b.dofLids.extent(0); ++c) {
      for (int k = 0; k < nd; ++k) gids[k] = overlap.getGlobalElement(b.dofLids(c, k));
      for (int k = 0; k < nd; ++k) graph_->insertGlobalIndices(gids[k], nd, gids.data());
    }
  }
  std::vector<GlobalIndex> cols(dim_);
  for (const auto& [r, c] : extraCouplings_) {
    for (int j = 0; j < dim_; ++j) cols[j] = dofs_->dof(c, j);
    for (int i = 0; i < dim_; ++i) {
      const GlobalIndex row = dofs_->dof(r, i);
      if (overlap.getLocalElement(row) == Teuchos::OrdinalTraits<LocalIndex>::invalid())
        throw std::logic_error("interaction coupling row node " + std::to_string(r) + " is not on this rank");
      graph_->insertGlobalIndices(row, dim_, cols.data());
    }
  }
  Tpetra::endAssembly(*graph_);
  ++graphVersion_;
}

void Assembler::cacheColumnIndices(const Matrix& J) {
  // Column ids of the owned+shared matrix; valid while J is in assembly mode.
  const Map& overlap = *dofs_->overlapMap();
  const Map& colMap = *J.getColMap();
  for (auto& b : blocks_) {
    b.colLids = DofView("colLids", b.dofLids.extent(0), b.dofLids.extent(1));
    for (std::size_t c = 0; c < b.dofLids.extent(0); ++c)
      for (std::size_t k = 0; k < b.dofLids.extent(1); ++k)
        b.colLids(c, k) = colMap.getLocalElement(overlap.getGlobalElement(b.dofLids(c, k)));
  }
  colLidsVersion_ = graphVersion_;
}

void Assembler::evaluate(const Vector& u, Vector& f, Matrix* J) {
  const auto t0 = Clock::now();
  uOverlap_->doImport(u, *dofs_->ownedToOverlap(), Tpetra::INSERT);
  fOverlap_->putScalar(0.0);
  if (J) {
    Tpetra::beginAssembly(*J);
    J->setAllToScalar(0.0);
    if (colLidsVersion_ != graphVersion_) cacheColumnIndices(*J);
  }
  int failures = 0;
  {
    auto uv = uOverlap_->getLocalViewDevice(Tpetra::Access::ReadOnly);
    auto fv = fOverlap_->getLocalViewDevice(Tpetra::Access::ReadWrite);
    LocalMatrix lclJ;
    if (J) lclJ = J->getLocalMatrixDevice();
    const LocalMatrix* Jp = J ? &lclJ : nullptr;
    using namespace fem;
    for (const auto& b : blocks_) {
      switch (formulation_) {
        case Formulation::PlaneStrain:
          failures += assembleBlock<SolidKernel<PlaneStrain, Quad4>>(b.dofLids, b.colLids, b.X, uv, fv, Jp, material_);
          break;
        case Formulation::Axisymmetric:
          failures += assembleBlock<SolidKernel<Axisymmetric, Quad4>>(b.dofLids, b.colLids, b.X, uv, fv, Jp, material_);
          break;
        case Formulation::ThreeD:
          if (b.type == mesh::CellType::Hex8)
            failures += assembleBlock<SolidKernel<ThreeD, Hex8>>(b.dofLids, b.colLids, b.X, uv, fv, Jp, material_);
          else
            failures += assembleBlock<SolidKernel<ThreeD, Tet4>>(b.dofLids, b.colLids, b.X, uv, fv, Jp, material_);
          break;
      }
    }
  }
  int globalFailures = 0;
  Teuchos::reduceAll(*dofs_->comm(), Teuchos::REDUCE_SUM, failures, Teuchos::outArg(globalFailures));
  if (J) Tpetra::endAssembly(*J);
  f.putScalar(0.0);
  f.doExport(*fOverlap_, *exporter_, Tpetra::ADD);
  if (J) {
    timings_.jacobian += secondsSince(t0);
    ++timings_.jacobianCalls;
  } else {
    timings_.residual += secondsSince(t0);
    ++timings_.residualCalls;
  }
  if (globalFailures > 0)
    throw InvertedElementError(std::to_string(globalFailures) + " element(s) inverted (J <= 0)");
}

Real Assembler::sumOverNodes(const Vector& f, const std::vector<LocalIndex>& nodes, int component) const {
  auto fv = f.getLocalViewHost(Tpetra::Access::ReadOnly);
  const Map& owned = *dofs_->ownedMap();
  Real local = 0.0;
  for (LocalIndex n : nodes) {
    if (!dofs_->ownsNode(n)) continue;
    local += fv(owned.getLocalElement(dofs_->dof(n, component)), 0);
  }
  Real global = 0.0;
  Teuchos::reduceAll(*dofs_->comm(), Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
  return global;
}

}  // namespace cgcm::assembly
