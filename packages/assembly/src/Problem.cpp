#include "cgcm/assembly/Problem.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Assembly_Helpers.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

namespace cgcm::assembly {

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

/// The message of the lowest rank that has one, on every rank (empty if none
/// has). Collective; only on the failure path.
std::string firstOnAnyRank(const Teuchos::Comm<int>& comm, const std::string& local) {
  const int mine = local.empty() ? comm.getSize() : comm.getRank();
  int root = comm.getSize();
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MIN, 1, &mine, &root);
  if (root == comm.getSize()) return {};
  int length = static_cast<int>(local.size());
  Teuchos::broadcast(comm, root, 1, &length);
  std::string text = comm.getRank() == root ? local : std::string(static_cast<std::size_t>(length), ' ');
  Teuchos::broadcast(comm, root, length, text.data());
  return text;
}

}  // namespace

Problem::Problem(Teuchos::RCP<const DofMap> dofs, std::shared_ptr<const mesh::Mesh> mesh, Formulation formulation,
                 const material::NeoHookean& material)
    : Problem(dofs, mesh, formulation, std::vector<material::NeoHookean>(mesh->numBodies, material)) {}

Problem::Problem(Teuchos::RCP<const DofMap> dofs, std::shared_ptr<const mesh::Mesh> mesh, Formulation formulation,
                 std::vector<material::NeoHookean> bodyMaterials)
    : dofs_(std::move(dofs)), mesh_(std::move(mesh)), formulation_(formulation), dim_(formulationDim(formulation)) {
  if (mesh_->dim != dim_)
    throw InputError(std::string("Problem/Formulation = \"") + formulationName(formulation) + "\" needs a " +
                     std::to_string(dim_) + "D mesh, got a " + std::to_string(mesh_->dim) + "D one");
  if (int(bodyMaterials.size()) != mesh_->numBodies)
    throw std::logic_error("Problem: " + std::to_string(bodyMaterials.size()) + " materials for " +
                           std::to_string(mesh_->numBodies) + " bodies");
  for (int b = 0; b < mesh_->numBodies; ++b) bulk_.emplace_back(*dofs_, *mesh_, b, formulation, bodyMaterials[b]);
  uOverlap_ = Teuchos::rcp(new Vector(dofs_->overlapMap()));
  fOverlap_ = Teuchos::rcp(new Vector(dofs_->overlapMap()));
  exporter_ = Teuchos::rcp(new Export(dofs_->overlapMap(), dofs_->ownedMap()));
}


Teuchos::RCP<const Graph> Problem::graph() {
  if (graph_.is_null()) buildGraph();
  return graph_;
}

Teuchos::RCP<Matrix> Problem::createMatrix() { return Teuchos::rcp(new Matrix(graph())); }

void Problem::findCellNeighbours() {
  const Map& overlap = *dofs_->overlapMap();
  const std::size_t numOverlapNodes = overlap.getNodeNumElements() / dim_;
  cellNeighbours_.assign(numOverlapNodes, {});
  for (const auto& part : bulk_) part.appendCellNeighbours(cellNeighbours_);
  // Other ranks' cells at a shared node add at most the nodes of their cells there: the node's cell-node
  // incidences summed over the ranks that have it, less this rank's (its list before removing repeats).
  std::vector<Real> here(numOverlapNodes);
  for (std::size_t k = 0; k < numOverlapNodes; ++k) here[k] = Real(cellNeighbours_[k].size());
  const std::vector<Real> all = dofs_->sumOverSharers(here);
  remoteCellNodes_.assign(numOverlapNodes, 0);
  for (std::size_t k = 0; k < numOverlapNodes; ++k) {
    auto& list = cellNeighbours_[k];
    remoteCellNodes_[k] = std::max(0LL, (long long)std::llround(all[k] - here[k]));
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
  }
  cellNeighboursFound_ = true;
}

void Problem::buildGraph() {
  const auto t0 = Clock::now();
  // Node by node: the nodes each overlap node couples with (its cells' nodes, found once, and its
  // interaction partners), then one insertion per row. Inserting cell by cell and pair by pair, into rows
  // all as long as the longest, cost 2-3 s per build of a 27k-unknown tetrahedral graph (doc/performance.md).
  if (!cellNeighboursFound_) findCellNeighbours();
  const Map& overlap = *dofs_->overlapMap();
  const std::size_t numOverlapNodes = cellNeighbours_.size();
  std::vector<std::vector<GlobalIndex>> partners(numOverlapNodes);  // global node ids
  std::vector<Real> partnersHere(numOverlapNodes, 0.0);
  for (const auto& [r, c] : extraCouplings_) {
    const LocalIndex row = overlap.getLocalElement(dofs_->dof(r, 0));
    if (row == Teuchos::OrdinalTraits<LocalIndex>::invalid())
      throw std::logic_error("interaction coupling row node " + std::to_string(dofs_->globalNode(r)) +
                             " is not on this rank");
    partners[row / dim_].push_back(c);
    partnersHere[row / dim_] += 1.0;
  }
  // Row lengths: this rank's couplings exactly, plus a bound on what other ranks add to a shared row at the
  // end of assembly: their cells' nodes and their interaction partners of the node.
  const std::vector<Real> partnersAll = dofs_->sumOverSharers(partnersHere);
  const auto numDofs = (long long)dofs_->ownedMap()->getGlobalNumElements();
  Kokkos::DualView<std::size_t*, Graph::device_type> rowLengths("rowLengths", overlap.getNodeNumElements());
  std::vector<std::vector<GlobalIndex>> columns(numOverlapNodes);
  {
    auto lengths = rowLengths.view_host();
    for (std::size_t k = 0; k < numOverlapNodes; ++k) {
      auto& cols = columns[k];
      cols.reserve((cellNeighbours_[k].size() + partners[k].size()) * dim_);
      for (LocalIndex m : cellNeighbours_[k])
        for (int j = 0; j < dim_; ++j) cols.push_back(overlap.getGlobalElement(LocalIndex(m * dim_ + j)));
      for (GlobalIndex c : partners[k])
        for (int j = 0; j < dim_; ++j) cols.push_back(c * dim_ + j);
      std::sort(cols.begin(), cols.end());
      cols.erase(std::unique(cols.begin(), cols.end()), cols.end());
      const long long remote = remoteCellNodes_[k] + std::llround(partnersAll[k] - partnersHere[k]);
      const auto length = std::size_t(std::min<long long>((long long)cols.size() + remote * dim_, numDofs));
      for (int i = 0; i < dim_; ++i) lengths(k * dim_ + i) = length;
    }
    rowLengths.modify_host();
    rowLengths.sync_device();
  }
  graph_ = Teuchos::rcp(new Graph(dofs_->ownedMap(), dofs_->overlapMap(),
                                  Kokkos::DualView<const std::size_t*, Graph::device_type>(rowLengths)));
  Tpetra::beginAssembly(*graph_);
  for (std::size_t k = 0; k < numOverlapNodes; ++k) {
    const auto& cols = columns[k];
    if (cols.empty()) continue;
    for (int i = 0; i < dim_; ++i)
      graph_->insertGlobalIndices(overlap.getGlobalElement(LocalIndex(k * dim_ + i)), LocalIndex(cols.size()),
                                  cols.data());
  }
  Tpetra::endAssembly(*graph_);
  ++graphVersion_;
  timings_.graph += secondsSince(t0);
}

void Problem::evaluate(const Vector& u, Vector& f, Matrix* J) {
  const auto t0 = Clock::now();
  uOverlap_->doImport(u, *dofs_->ownedToOverlap(), Tpetra::INSERT);
  fOverlap_->putScalar(0.0);
  if (J) {
    Tpetra::beginAssembly(*J);
    J->setAllToScalar(0.0);
    if (columnsVersion_ != graphVersion_) {
      // column ids and row offsets of the owned+shared matrix; valid while J is in assembly mode
      const auto local = J->getLocalMatrixDevice();
      const bool sorted = J->getCrsGraph()->isSorted();
      for (auto& part : bulk_) part.setMatrixGraph(*J->getColMap(), local, sorted);
      columnsVersion_ = graphVersion_;
    }
  }
  int failures = 0;
  std::string firstInverted;
  {
    auto uv = uOverlap_->getLocalViewDevice(Tpetra::Access::ReadOnly);
    auto fv = fOverlap_->getLocalViewDevice(Tpetra::Access::ReadWrite);
    BulkPart::LocalMatrix lclJ;
    if (J) lclJ = J->getLocalMatrixDevice();
    const bool sortedRows = J && J->getCrsGraph()->isSorted();
    for (const auto& part : bulk_) {
      const auto cells = part.assemble(uv, fv, J ? &lclJ : nullptr, sortedRows);
      failures += cells.count;
      if (firstInverted.empty()) firstInverted = cells.first;
    }
  }
  double interactionSeconds = 0.0;
  InteractionPart::Outcome interaction;
  if (interactionPart_) {
    const auto ti = Clock::now();
    interaction = interactionPart_->assemble(u, fOverlap_->getLocalViewDevice(Tpetra::Access::ReadWrite), J);
    interactionSeconds = secondsSince(ti);
    timings_.search += interactionPart_->lastSearchSeconds();
  }
  // A NaN or Inf among this rank's contributions reaches f in the export below.
  const std::string firstNaN = firstNonFinite(*fOverlap_);
  // every rank learns of every failure here, in one reduction, before the collective end of assembly
  const Teuchos::Comm<int>& comm = *dofs_->comm();
  int counts[4] = {failures, interaction.dropped, interaction.failure.empty() ? 0 : 1, firstNaN.empty() ? 0 : 1};
  int globalCounts[4] = {0, 0, 0, 0};
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, 4, counts, globalCounts);
  if (J) Tpetra::endAssembly(*J);
  f.putScalar(0.0);
  f.doExport(*fOverlap_, *exporter_, Tpetra::ADD);
  timings_.interaction += interactionSeconds;
  if (J) {
    timings_.jacobian += secondsSince(t0) - interactionSeconds;
  } else {
    timings_.residual += secondsSince(t0) - interactionSeconds;
  }
  if (globalCounts[2] > 0) throw NumericalError(firstOnAnyRank(comm, interaction.failure));
  if (globalCounts[0] > 0)
    throw InvertedElementError(std::to_string(globalCounts[0]) + " element(s) inverted (J <= 0), the first " +
                               firstOnAnyRank(comm, firstInverted));
  if (globalCounts[1] > 0) {
    graphOutdated_ = true;
    throw GraphOutdatedError(std::to_string(globalCounts[1]) +
                             " interaction tangent entries fell outside the matrix graph (the first at " +
                             firstOnAnyRank(comm, interaction.firstDropped) + ")");
  }
  if (globalCounts[3] > 0) throw NumericalError("the residual is not finite at " + firstOnAnyRank(comm, firstNaN));
}

std::string Problem::firstNonFinite(const Vector& v) const {
  const auto values = v.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (std::size_t k = 0; k < values.extent(0); ++k) {
    if (std::isfinite(values(k, 0))) continue;
    const GlobalIndex dof = v.getMap()->getGlobalElement(LocalIndex(k));
    const int perNode = dofs_->dofsPerNode();
    return "node " + std::to_string(dof / perNode) + ", component " + std::to_string(dof % perNode) + " (" +
           std::to_string(values(k, 0)) + ")";
  }
  return {};
}

void Problem::setInteraction(std::shared_ptr<interaction::Interaction> interaction, Real searchRadiusFactor) {
  // the one place that knows which part assembles which method
  if (auto surface = std::dynamic_pointer_cast<interaction::SurfaceInteraction>(interaction))
    interactionPart_ = std::make_unique<SurfaceInteractionPart>(dofs_, *mesh_, std::move(surface), searchRadiusFactor);
  else if (auto volume = std::dynamic_pointer_cast<interaction::VolumeInteraction>(interaction))
    interactionPart_ = std::make_unique<VolumeInteractionPart>(dofs_, *mesh_, std::move(volume), searchRadiusFactor);
  else
    throw std::logic_error("Problem::setInteraction: no assembly part for this interaction method");
}

std::vector<std::array<Real, 3>> Problem::interactionForces() const {
  return interactionPart_ ? interactionPart_->forces() : std::vector<std::array<Real, 3>>{};
}

Teuchos::RCP<Vector> Problem::interactionNodeForces(const Vector& u) {
  auto forces = Teuchos::rcp(new Vector(dofs_->ownedMap()));
  if (!interactionPart_) return forces;
  // Evaluating again at the last evaluated state leaves the interaction's search state (hints, pair
  // lists) as it was; at another state it would move them, and the path would depend on the output.
  Vector state(dofs_->overlapMap());
  state.doImport(u, *dofs_->ownedToOverlap(), Tpetra::INSERT);
  state.update(-1.0, *uOverlap_, 1.0);
  if (state.normInf() != 0.0)
    throw std::logic_error("Problem::interactionNodeForces: u is not the state of the last evaluation");
  const auto t0 = Clock::now();
  const std::string failure = interactionPart_->nodeForces(u, *forces);
  timings_.interaction += secondsSince(t0);  // an evaluation of the interaction, as the others
  timings_.search += interactionPart_->lastSearchSeconds();
  const std::string first = firstOnAnyRank(*dofs_->comm(), failure);
  if (!first.empty()) throw NumericalError(first);
  return forces;
}

std::vector<std::pair<LocalIndex, GlobalIndex>> Problem::interactionCouplings(const Vector& u, Real radius) {
  const auto t0 = Clock::now();
  auto wanted = interactionPart_->couplings(u, radius);
  timings_.graph += secondsSince(t0);
  return wanted;
}

bool Problem::graphHoldsEverywhere(const std::vector<std::pair<LocalIndex, GlobalIndex>>& wanted) const {
  const int missing = graph_.is_null() || !std::includes(extraCouplings_.begin(), extraCouplings_.end(),
                                                         wanted.begin(), wanted.end());
  int anyMissing = 0;
  Teuchos::reduceAll(*dofs_->comm(), Teuchos::REDUCE_MAX, missing, Teuchos::outArg(anyMissing));
  return anyMissing == 0;
}

bool Problem::interactionGraphCovers(const Vector& u, Real radius) {
  return !interactionPart_ || graphHoldsEverywhere(interactionCouplings(u, radius));
}

bool Problem::updateInteractionGraph(const Vector& u, bool keepExisting, Real radiusFactor) {
  if (!interactionPart_) return false;
  auto wanted = interactionCouplings(u, searchRadius() * radiusFactor);
  if (graphHoldsEverywhere(wanted)) return false;
  // every rank rebuilds (the fill is collective), also one whose couplings did not change
  if (keepExisting) wanted.insert(wanted.end(), extraCouplings_.begin(), extraCouplings_.end());
  std::sort(wanted.begin(), wanted.end());
  wanted.erase(std::unique(wanted.begin(), wanted.end()), wanted.end());
  extraCouplings_ = std::move(wanted);
  graph_ = Teuchos::null;
  graph();
  return true;
}

Real Problem::nodeValue(const Vector& v, LocalIndex node, int component) const {
  return sumOverNodes(v, {node}, component);
}

Teuchos::RCP<Vector> Problem::residualWeights(Real referenceModulus) const {
  std::vector<Real> scale(bulk_.size());
  bool stiffer = false;
  for (std::size_t b = 0; b < bulk_.size(); ++b) {
    scale[b] = std::max(1.0, bulk_[b].material().youngsModulus() / referenceModulus);
    stiffer = stiffer || scale[b] > 1.0;
  }
  if (!stiffer) return Teuchos::null;
  auto weights = Teuchos::rcp(new Vector(dofs_->ownedMap()));
  weights->putScalar(1.0);
  auto w = weights->getLocalViewHost(Tpetra::Access::ReadWrite);
  const Map& owned = *dofs_->ownedMap();
  for (const auto& block : mesh_->blocks) {
    const Real s = scale[std::size_t(block.body)];
    if (s == 1.0) continue;
    for (LocalIndex n : block.connectivity) {
      if (!dofs_->ownsNode(n)) continue;
      for (int i = 0; i < dim_; ++i) w(owned.getLocalElement(dofs_->dof(n, i)), 0) = 1.0 / (s * s);
    }
  }
  return weights;
}

Real Problem::sumOverNodes(const Vector& f, const std::vector<LocalIndex>& nodes, int component) const {
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
