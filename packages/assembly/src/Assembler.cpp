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
    : Assembler(dofs, mesh, formulation, std::vector<material::NeoHookean>(mesh->numBodies, material)) {}

Assembler::Assembler(Teuchos::RCP<const DofMap> dofs, std::shared_ptr<const mesh::Mesh> mesh,
                     Formulation formulation, std::vector<material::NeoHookean> bodyMaterials)
    : dofs_(std::move(dofs)), mesh_(std::move(mesh)), formulation_(formulation), materials_(std::move(bodyMaterials)),
      dim_(formulationDim(formulation)) {
  if (int(materials_.size()) != mesh_->numBodies)
    throw std::logic_error("Assembler: " + std::to_string(materials_.size()) + " materials for " +
                           std::to_string(mesh_->numBodies) + " bodies");
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
    d.material = materials_.at(blk.body);
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
          failures += assembleBlock<SolidKernel<PlaneStrain, Quad4>>(b.dofLids, b.colLids, b.X, uv, fv, Jp, b.material);
          break;
        case Formulation::Axisymmetric:
          failures += assembleBlock<SolidKernel<Axisymmetric, Quad4>>(b.dofLids, b.colLids, b.X, uv, fv, Jp, b.material);
          break;
        case Formulation::ThreeD:
          if (b.type == mesh::CellType::Hex8)
            failures += assembleBlock<SolidKernel<ThreeD, Hex8>>(b.dofLids, b.colLids, b.X, uv, fv, Jp, b.material);
          else
            failures += assembleBlock<SolidKernel<ThreeD, Tet4>>(b.dofLids, b.colLids, b.X, uv, fv, Jp, b.material);
          break;
      }
    }
  }
  double interactionSeconds = 0.0;
  int dropped = 0;
  if (interaction_) {
    const auto ti = Clock::now();
    dropped = assembleInteraction(u, fOverlap_->getLocalViewDevice(Tpetra::Access::ReadWrite), J);
    interactionSeconds = secondsSince(ti);
  }
  int counts[2] = {failures, dropped}, globalCounts[2] = {0, 0};
  Teuchos::reduceAll(*dofs_->comm(), Teuchos::REDUCE_SUM, 2, counts, globalCounts);
  if (J) Tpetra::endAssembly(*J);
  f.putScalar(0.0);
  f.doExport(*fOverlap_, *exporter_, Tpetra::ADD);
  timings_.interaction += interactionSeconds;
  if (J) {
    timings_.jacobian += secondsSince(t0) - interactionSeconds;
    ++timings_.jacobianCalls;
  } else {
    timings_.residual += secondsSince(t0) - interactionSeconds;
    ++timings_.residualCalls;
  }
  if (globalCounts[0] > 0)
    throw InvertedElementError(std::to_string(globalCounts[0]) + " element(s) inverted (J <= 0)");
  if (globalCounts[1] > 0) {
    graphOutdated_ = true;
    throw GraphOutdatedError(std::to_string(globalCounts[1]) +
                             " interaction tangent entries fell outside the matrix graph");
  }
}

void Assembler::setInteraction(std::shared_ptr<interaction::SurfaceInteraction> interaction,
                               Real searchRadiusFactor) {
  if (!(searchRadiusFactor > 1.0))
    throw InputError("Interaction/Search Radius Factor = " + std::to_string(searchRadiusFactor) +
                     ": the graph search radius must exceed the interaction cutoff (factor > 1)");
  interaction_ = std::move(interaction);
  searchRadiusFactor_ = searchRadiusFactor;
  ownsFacet_.assign(interaction_->numBodies(), {});
  const int rank = dofs_->comm()->getRank();
  std::set<LocalIndex> nodes;
  for (int b = 0; b < interaction_->numBodies(); ++b) {
    const auto& surf = interaction_->surface(b);
    if (surf.facetCells.size() != std::size_t(surf.numFacets()))
      throw std::logic_error("surface without facet-to-cell map");
    ownsFacet_[b].resize(surf.numFacets());
    for (LocalIndex f = 0; f < surf.numFacets(); ++f)
      ownsFacet_[b][f] = dofs_->cellOwner(surf.facetCells[f]) == rank;
    nodes.insert(surf.facets.begin(), surf.facets.end());
  }
  std::vector<GlobalIndex> gids;
  for (LocalIndex n : nodes)
    for (int i = 0; i < dim_; ++i) gids.push_back(dofs_->dof(n, i));
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  surfaceMap_ = Teuchos::rcp(new Map(invalid, gids.data(), gids.size(), 0, dofs_->comm()));
  surfaceImport_ = Teuchos::rcp(new Import(dofs_->ownedMap(), surfaceMap_));
  uSurface_ = Teuchos::rcp(new Vector(surfaceMap_));
  coords_ = mesh_->coords;
}

const std::vector<Real>& Assembler::surfaceCoordinates(const Vector& u) {
  uSurface_->doImport(u, *surfaceImport_, Tpetra::INSERT);
  auto v = uSurface_->getLocalViewHost(Tpetra::Access::ReadOnly);
  const Map& map = *surfaceMap_;
  for (std::size_t lid = 0; lid < map.getNodeNumElements(); ++lid) {
    const GlobalIndex gid = map.getGlobalElement(LocalIndex(lid));
    coords_[gid] = mesh_->coords[gid] + v(lid, 0);  // dof gid = node * dim + i = coordinate index
  }
  return coords_;
}

int Assembler::assembleInteraction(const Vector& u, Vector::dual_view_type::t_dev fv, Matrix* J) {
  const std::vector<Real>& x = surfaceCoordinates(u);
  interaction_->updatePairs(x.data());
  const Map& overlap = *dofs_->overlapMap();
  LocalMatrix lclJ;
  Teuchos::RCP<const Map> colMap;
  if (J) {
    lclJ = J->getLocalMatrixDevice();
    colMap = J->getColMap();
  }
  const auto& pairs = interaction_->pairs();
  bodyForces_.assign(3 * std::size_t(interaction_->numBodies()), 0.0);
  int dropped = 0;
  interaction::PairContribution c;
  for (const auto& p : pairs) {
    if (!ownsFacet_[p.body][p.facet]) continue;  // each pair is evaluated by exactly one rank
    interaction_->evaluatePair(x.data(), p, c, J != nullptr);
    LocalIndex rows[12], cols[interaction::kMaxContributionColumns];
    const int nrows = dim_ * c.numRowNodes;
    for (int a = 0; a < c.numRowNodes; ++a)
      for (int i = 0; i < dim_; ++i) rows[dim_ * a + i] = overlap.getLocalElement(dofs_->dof(c.rowNodes[a], i));
    for (int r = 0; r < nrows; ++r) Kokkos::atomic_add(&fv(rows[r], 0), c.f[r]);
    for (int r = 0; r < nrows; ++r) bodyForces_[3 * std::size_t(p.body) + r % dim_] -= c.f[r];  // on the body: -f_C
    if (!J) continue;
    // the point's facet and every facet its projection is blended over
    const int ncols = dim_ * c.numColNodes;
    for (int b = 0; b < c.numColNodes; ++b)
      for (int j = 0; j < dim_; ++j) cols[dim_ * b + j] = colMap->getLocalElement(dofs_->dof(c.colNodes[b], j));
    // sumIntoValues skips columns missing from the row and returns how many it found
    for (int r = 0; r < nrows; ++r)
      dropped += ncols - lclJ.sumIntoValues(rows[r], cols, ncols, c.K[r], false, true);
  }
  return dropped;
}

std::vector<std::array<Real, 3>> Assembler::interactionForces() const {
  if (!interaction_) return {};
  std::vector<Real> local = bodyForces_, global(3 * std::size_t(interaction_->numBodies()), 0.0);
  local.resize(global.size(), 0.0);
  Teuchos::reduceAll(*dofs_->comm(), Teuchos::REDUCE_SUM, int(local.size()), local.data(), global.data());
  std::vector<std::array<Real, 3>> out(interaction_->numBodies());
  for (std::size_t b = 0; b < out.size(); ++b) out[b] = {global[3 * b], global[3 * b + 1], global[3 * b + 2]};
  return out;
}

Real Assembler::searchRadius() const { return interaction_ ? searchRadiusFactor_ * interaction_->cutoff() : 0.0; }

std::vector<std::pair<LocalIndex, LocalIndex>> Assembler::interactionCouplings(const Vector& u, Real radius) {
  const std::vector<Real>& x = surfaceCoordinates(u);
  const Map& overlap = *dofs_->overlapMap();
  std::vector<std::pair<LocalIndex, LocalIndex>> wanted;
  for (const auto& rc : interaction_->couplings(x.data(), radius))
    if (overlap.getLocalElement(dofs_->dof(rc.first, 0)) != Teuchos::OrdinalTraits<LocalIndex>::invalid())
      wanted.push_back(rc);
  return wanted;
}

bool Assembler::interactionGraphCovers(const Vector& u, Real radius) {
  if (!interaction_) return true;
  const auto wanted = interactionCouplings(u, radius);
  const int missing = graph_.is_null() || !std::includes(extraCouplings_.begin(), extraCouplings_.end(),
                                                         wanted.begin(), wanted.end());
  int anyMissing = 0;
  Teuchos::reduceAll(*dofs_->comm(), Teuchos::REDUCE_MAX, missing, Teuchos::outArg(anyMissing));
  return anyMissing == 0;
}

bool Assembler::updateInteractionGraph(const Vector& u, bool keepExisting, Real radiusFactor) {
  if (!interaction_) return false;
  auto wanted = interactionCouplings(u, searchRadius() * radiusFactor);
  const int missing = std::includes(extraCouplings_.begin(), extraCouplings_.end(), wanted.begin(), wanted.end())
                          ? 0 : 1;
  int anyMissing = 0;
  Teuchos::reduceAll(*dofs_->comm(), Teuchos::REDUCE_MAX, missing, Teuchos::outArg(anyMissing));
  if (!anyMissing && !graph_.is_null()) return false;
  if (keepExisting) wanted.insert(wanted.end(), extraCouplings_.begin(), extraCouplings_.end());
  extraCouplings_.clear();
  setExtraCouplings(std::move(wanted));
  graph();
  return true;
}

Real Assembler::nodeValue(const Vector& v, LocalIndex node, int component) const {
  return sumOverNodes(v, {node}, component);
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
