#include "cgcm/app/Results.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>

#include <Teuchos_CommHelpers.hpp>

#include "cgcm/assembly/GhostedSurfaces.hpp"
#include "cgcm/assembly/SurfaceTraction.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/fem/Dispatch.hpp"

namespace cgcm::app {

namespace {

const char* const kDisplacement[] = {"displacement_x", "displacement_y", "displacement_z"};
const char* const kTraction[] = {"traction_x", "traction_y", "traction_z"};
const char* const kInteractionForce[] = {"interaction_force_x", "interaction_force_y", "interaction_force_z"};
const char* const kCriticalMode[] = {"critical_mode_x", "critical_mode_y", "critical_mode_z"};

// Stress components written per formulation, as (name, i, j) of the 3x3 Cauchy stress.
struct Component {
  const char* name;
  int i, j;
};
std::vector<Component> stressComponents(Formulation f) {
  switch (f) {
    case Formulation::Axisymmetric:
      return {{"stress_rr", 0, 0}, {"stress_zz", 1, 1}, {"stress_tt", 2, 2}, {"stress_rz", 0, 1}};
    case Formulation::PlaneStrain:
      return {{"stress_xx", 0, 0}, {"stress_yy", 1, 1}, {"stress_zz", 2, 2}, {"stress_xy", 0, 1}};
    case Formulation::ThreeD:
      break;
  }
  return {{"stress_xx", 0, 0}, {"stress_yy", 1, 1}, {"stress_zz", 2, 2},
          {"stress_xy", 0, 1}, {"stress_yz", 1, 2}, {"stress_xz", 0, 2}};
}

Real vonMises(const Mat3& s) {
  const Real d = (s.a[0][0] - s.a[1][1]) * (s.a[0][0] - s.a[1][1]) + (s.a[1][1] - s.a[2][2]) * (s.a[1][1] - s.a[2][2]) +
                 (s.a[2][2] - s.a[0][0]) * (s.a[2][2] - s.a[0][0]);
  const Real t = s.a[0][1] * s.a[0][1] + s.a[1][2] * s.a[1][2] + s.a[0][2] * s.a[0][2];
  return std::sqrt(0.5 * d + 3.0 * t);
}

// Mean Cauchy stress and J of one cell with the kernel of its (formulation, element); false if inverted.
template <class Kernel>
bool cellStress(const mesh::Mesh& m, const LocalIndex* nodes, const std::vector<Real>& u,
                const material::NeoHookean& mat, Mat3& sigma, Real& J) {
  Real X[Kernel::numNodes][Kernel::dim], ue[Kernel::numNodes][Kernel::dim], x[Kernel::numNodes][Kernel::dim];
  for (int a = 0; a < Kernel::numNodes; ++a)
    for (int i = 0; i < Kernel::dim; ++i) {
      X[a][i] = m.coord(nodes[a], i);
      ue[a][i] = u[std::size_t(nodes[a]) * Kernel::dim + i];
      x[a][i] = X[a][i] + ue[a][i];
    }
  return Kernel::averageStress(X, x, ue, mat, sigma, J);
}

// The entries of a window of a dense array: consecutive from the first. A gap is a bug of the sender.
void expectConsecutive(const std::vector<GlobalIndex>& at, const char* what) {
  for (std::size_t k = 1; k < at.size(); ++k)
    if (at[k] != at[0] + GlobalIndex(k))
      throw std::logic_error(std::string("ResultsWriter: ") + what + " " + std::to_string(at[0] + GlobalIndex(k)) +
                             " sent by no rank");
}

// Summed over the ranks.
std::vector<long long> sumOverRanks(const assembly::Comm& comm, const std::vector<long long>& mine) {
  std::vector<long long> all(mine.size(), 0);
  if (!mine.empty()) Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, int(mine.size()), mine.data(), all.data());
  return all;
}

}  // namespace

ResultsWriter::ResultsWriter(const std::string& path, const solver::Discretization& disc,
                             const std::vector<std::string>& globals, int keptSteps, bool criticalMode,
                             std::size_t windowBytes)
    : mesh_(*disc.mesh), disc_(disc), globals_(globals), criticalMode_(criticalMode), windowBytes_(windowBytes) {
  const int dim = disc.dofs->dofsPerNode();
  for (int i = 0; i < dim; ++i) variables_.nodal.push_back(kDisplacement[i]);
  if (disc.problem->hasInteraction()) {  // whichever method: from the interaction force on each node
    for (int i = 0; i < dim; ++i) variables_.nodal.push_back(kTraction[i]);
    variables_.nodal.push_back("pressure");
    for (int i = 0; i < dim; ++i) variables_.nodal.push_back(kInteractionForce[i]);
  }
  if (criticalMode_)
    for (int i = 0; i < dim; ++i) variables_.nodal.push_back(kCriticalMode[i]);
  for (const auto& c : stressComponents(disc.problem->formulation())) variables_.element.push_back(c.name);
  variables_.element.insert(variables_.element.end(), {"J", "von_mises"});
  variables_.global = globals;

  const assembly::DofMap& dofs = *disc.dofs;
  for (LocalIndex n = 0; n < mesh_.numNodes(); ++n)
    if (dofs.ownsNode(n)) ownedNodes_.push_back(n);
  std::sort(ownedNodes_.begin(), ownedNodes_.end(),
            [&](LocalIndex a, LocalIndex b) { return mesh_.globalNode(a) < mesh_.globalNode(b); });
  for (std::size_t b = 0; b < mesh_.blocks.size(); ++b) {
    std::vector<LocalIndex> cells = dofs.localCells(b);
    const auto& block = mesh_.blocks[b];
    std::sort(cells.begin(), cells.end(), [&](LocalIndex x, LocalIndex y) { return block.cellId(x) < block.cellId(y); });
    ownCells_.push_back(std::move(cells));
  }
  for (LocalIndex n : ownedNodes_)
    for (int i = 0; i < dim; ++i) ownedDofs_.push_back(dofs.ownedMap()->getLocalElement(dofs.dof(n, i)));
  const auto& overlapNodes = *dofs.overlapNodeMap();
  overlapIndex_.resize(std::size_t(mesh_.numNodes()));
  for (LocalIndex n = 0; n < mesh_.numNodes(); ++n) {
    const LocalIndex k = overlapNodes.getLocalElement(mesh_.globalNode(n));
    overlapIndex_[std::size_t(n)] = k == Teuchos::OrdinalTraits<LocalIndex>::invalid() ? -1 : k;
  }
  overlap_ = Teuchos::rcp(new assembly::Vector(dofs.overlapMap()));

  const auto start = std::chrono::steady_clock::now();
  const io::ExodusLayout l = layout();
  onRoot([&] {
    writer_ = keptSteps >= 0 ? std::make_unique<io::ExodusWriter>(path, l, variables_, keptSteps)
                             : std::make_unique<io::ExodusWriter>(path, "cgcm", l, variables_);
  });
  if (keptSteps < 0) {
    writeMesh(l);
    onRoot([&] { writer_->finishMesh(); });
  }
  meshSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void ResultsWriter::onRoot(const std::function<void()>& work) { solver::runOnRoot(*disc_.dofs->comm(), work); }

io::ExodusLayout ResultsWriter::layout() const {
  const auto& comm = *disc_.dofs->comm();
  io::ExodusLayout l;
  l.dim = mesh_.dim;
  l.numNodes = std::int64_t(disc_.dofs->ownedNodeMap()->getGlobalNumElements());
  // per block its cells, per node set its owned members, per body its facets of own cells
  std::vector<long long> counts;
  for (const auto& cells : ownCells_) counts.push_back((long long)cells.size());
  for (const auto& [name, nodes] : mesh_.nodeSets)
    counts.push_back(std::count_if(nodes.begin(), nodes.end(), [&](LocalIndex n) { return disc_.dofs->ownsNode(n); }));
  for (const auto& s : mesh_.surfaces)
    counts.push_back(std::count_if(s.facetCells.begin(), s.facetCells.end(),
                                   [&](LocalIndex c) { return disc_.dofs->evaluatesCell(c); }));
  const std::vector<long long> total = sumOverRanks(comm, counts);
  std::size_t k = 0;
  std::vector<int> bodies;
  for (const auto& b : mesh_.blocks) {
    l.blocks.push_back({b.name, b.type, total[k++]});
    bodies.push_back(b.body);
  }
  for (const auto& [name, nodes] : mesh_.nodeSets) l.nodeSets.push_back({name, total[k++]});
  for (const auto& s : mesh_.surfaces) {
    const long long facets = total[k++];
    if (facets > 0) l.sideSets.push_back({io::sideSetName(l.blocks, bodies, s.body), facets});
  }
  return l;
}

void ResultsWriter::writeMesh(const io::ExodusLayout& l) {
  const auto& comm = *disc_.dofs->comm();
  const int dim = mesh_.dim;
  // coordinates by global id
  std::vector<GlobalIndex> ids;
  std::vector<Real> xyz;
  for (LocalIndex n : ownedNodes_) {
    ids.push_back(mesh_.globalNode(n));
    for (int i = 0; i < dim; ++i) xyz.push_back(mesh_.coord(n, i));
  }
  solver::streamToRoot<Real>(
      comm, ids, xyz, dim,
      [&](const std::vector<GlobalIndex>& at, const std::vector<Real>& v) {
        expectConsecutive(at, "node");
        std::vector<double> c[3];
        for (int i = 0; i < dim; ++i)
          for (std::size_t k = 0; k < at.size(); ++k) c[i].push_back(v[k * dim + i]);
        writer_->putCoordinates(at[0], std::int64_t(at.size()), c[0].data(), c[1].data(), dim == 3 ? c[2].data() : nullptr);
      },
      windowBytes_);
  // connectivity by cell id within each block, in global node ids
  std::vector<GlobalIndex> blockStart;  // of the whole mesh: the file's element ids
  GlobalIndex first = 0;
  for (const auto& b : l.blocks) blockStart.push_back(first), first += b.numCells;
  for (std::size_t b = 0; b < mesh_.blocks.size(); ++b) {
    const auto& block = mesh_.blocks[b];
    const int npc = mesh::nodesPerCell(block.type);
    std::vector<GlobalIndex> cellIds, nodes;
    for (LocalIndex c : ownCells_[b]) {
      cellIds.push_back(block.cellId(c));
      for (int a = 0; a < npc; ++a) nodes.push_back(mesh_.globalNode(block.connectivity[std::size_t(c) * npc + a]));
    }
    solver::streamToRoot<GlobalIndex>(
        comm, cellIds, nodes, npc,
        [&](const std::vector<GlobalIndex>& at, const std::vector<GlobalIndex>& v) {
          expectConsecutive(at, ("cell of block " + block.name).c_str());
          writer_->putConnectivity(b, at[0], std::int64_t(at.size()), v.data());
        },
        windowBytes_);
  }
  // node sets: their owned members by global id
  std::size_t set = 0;
  for (const auto& [name, nodes] : mesh_.nodeSets) {
    std::vector<GlobalIndex> members;
    for (LocalIndex n : nodes)
      if (disc_.dofs->ownsNode(n)) members.push_back(mesh_.globalNode(n));
    std::sort(members.begin(), members.end());
    std::int64_t written = 0;
    solver::streamToRoot<GlobalIndex>(
        comm, members, members, 1,
        [&](const std::vector<GlobalIndex>& at, const std::vector<GlobalIndex>&) {
          writer_->putNodeSet(set, written, std::int64_t(at.size()), at.data());
          written += std::int64_t(at.size());
        },
        windowBytes_);
    ++set;
  }
  // side sets: (element, side) of the facets of own cells, keyed by element * 8 + side - 1 (at most 6 sides)
  std::vector<GlobalIndex> partBlockStart;  // of this rank's mesh
  for (std::size_t b = 0; b < mesh_.blocks.size(); ++b) partBlockStart.push_back(mesh_.firstCellOfBlock(b));
  set = 0;
  for (const auto& s : mesh_.surfaces) {
    std::vector<GlobalIndex> keys;
    long long mine = 0;
    for (LocalIndex f = 0; f < s.numFacets(); ++f) {
      const LocalIndex cell = s.facetCells[f];
      if (!disc_.dofs->evaluatesCell(cell)) continue;
      const std::size_t b =
          std::upper_bound(partBlockStart.begin(), partBlockStart.end(), GlobalIndex(cell)) - partBlockStart.begin() - 1;
      const auto& block = mesh_.blocks[b];
      const LocalIndex c = LocalIndex(cell - partBlockStart[b]);
      const int side = io::exodusSide(block, c, &s.facets[std::size_t(f) * s.nodesPerFacet], s.nodesPerFacet);
      if (side == 0)
        throw std::logic_error("ResultsWriter: facet " + std::to_string(f) + " of body " + std::to_string(s.body) +
                               " is no side of its cell");
      keys.push_back((blockStart[b] + block.cellId(c)) * 8 + side - 1);
      ++mine;
    }
    if (sumOverRanks(comm, {mine})[0] == 0) continue;  // no side set (layout())
    std::sort(keys.begin(), keys.end());
    std::int64_t written = 0;
    solver::streamToRoot<GlobalIndex>(
        comm, keys, keys, 1,
        [&](const std::vector<GlobalIndex>& at, const std::vector<GlobalIndex>&) {
          std::vector<GlobalIndex> elements;
          std::vector<int> sides;
          for (GlobalIndex key : at) elements.push_back(key / 8), sides.push_back(int(key % 8) + 1);
          writer_->putSideSet(set, written, std::int64_t(at.size()), elements.data(), sides.data());
          written += std::int64_t(at.size());
        },
        windowBytes_);
    ++set;
  }
}

std::vector<Real> ResultsWriter::atMeshNodes(const assembly::Vector& v) {
  overlap_->doImport(v, *disc_.dofs->ownedToOverlap(), Tpetra::INSERT);
  const auto h = overlap_->getLocalViewHost(Tpetra::Access::ReadOnly);
  const int dim = mesh_.dim;
  std::vector<Real> out(std::size_t(mesh_.numNodes()) * dim, std::numeric_limits<Real>::quiet_NaN());
  for (LocalIndex n = 0; n < mesh_.numNodes(); ++n) {
    const LocalIndex k = overlapIndex_[std::size_t(n)];
    if (k >= 0)
      for (int i = 0; i < dim; ++i) out[std::size_t(n) * dim + i] = h(std::size_t(k) * dim + i, 0);
  }
  return out;
}

void ResultsWriter::write(const assembly::Vector& x, const std::vector<double>& globals, const assembly::Vector* mode) {
  const bool interacting = disc_.problem->hasInteraction();
  // the interaction force of the state x, whichever method
  const Teuchos::RCP<assembly::Vector> force = interacting ? disc_.problem->interactionNodeForces(x) : Teuchos::null;
  const auto start = std::chrono::steady_clock::now();
  onRoot([&] { writer_->beginStep(double(writer_->numSteps() + 1)); });
  writeOwnedNodeFields(x, force.get(), mode);
  const std::vector<Real> u = atMeshNodes(x);
  if (interacting) writeTraction(u, atMeshNodes(*force));
  writeCellFields(u);
  io::ExodusWriter::Scalars scalars;
  for (std::size_t k = 0; k < globals_.size(); ++k) scalars[globals_[k]] = globals[k];
  onRoot([&] { writer_->endStep(scalars); });
  stepSeconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void ResultsWriter::writeOwnedNodeFields(const assembly::Vector& x, const assembly::Vector* force,
                                         const assembly::Vector* mode) {
  const int dim = mesh_.dim;
  std::vector<const assembly::Vector*> fields = {&x};  // displacement, interaction force, critical mode
  std::vector<const char* const*> names = {kDisplacement};
  if (force) fields.push_back(force), names.push_back(kInteractionForce);
  if (criticalMode_) fields.push_back(mode), names.push_back(kCriticalMode);  // no mode: zero
  const int width = int(fields.size()) * dim;
  std::vector<GlobalIndex> ids;
  for (LocalIndex n : ownedNodes_) ids.push_back(mesh_.globalNode(n));
  std::vector<Real> values(ownedNodes_.size() * std::size_t(width), 0.0);  // per node: each field's components
  for (std::size_t k = 0; k < fields.size(); ++k) {
    if (!fields[k]) continue;
    const auto view = fields[k]->getLocalViewHost(Tpetra::Access::ReadOnly);
    for (std::size_t e = 0; e < ownedNodes_.size(); ++e)
      for (int i = 0; i < dim; ++i)
        values[e * width + k * dim + std::size_t(i)] = view(std::size_t(ownedDofs_[e * dim + std::size_t(i)]), 0);
  }
  solver::streamToRoot<Real>(
      *disc_.dofs->comm(), ids, values, width,
      [&](const std::vector<GlobalIndex>& at, const std::vector<Real>& v) {
        expectConsecutive(at, "node");
        std::vector<double> column(at.size());
        for (std::size_t k = 0; k < fields.size(); ++k)
          for (int i = 0; i < dim; ++i) {
            for (std::size_t e = 0; e < at.size(); ++e) column[e] = v[e * width + k * dim + i];
            const auto name = std::find(variables_.nodal.begin(), variables_.nodal.end(), names[k][i]);
            writer_->putNodal(std::size_t(name - variables_.nodal.begin()), at[0], std::int64_t(at.size()), column.data());
          }
      },
      windowBytes_);
}

void ResultsWriter::writeTraction(const std::vector<Real>& u, const std::vector<Real>& force) {
  // each rank sends rank 0 its facets (of own cells) with their nodes' ids, reference coordinates, u and force
  const int dim = mesh_.dim;
  const int p = disc_.dofs->comm()->getSize();
  core::ByteWriter out;
  for (const auto& s : mesh_.surfaces) {
    for (LocalIndex f = 0; f < s.numFacets(); ++f) {
      if (!disc_.dofs->evaluatesCell(s.facetCells[f])) continue;
      out.put(s.body);
      for (int a = 0; a < s.nodesPerFacet; ++a) {
        const LocalIndex n = s.facets[std::size_t(f) * s.nodesPerFacet + a];
        out.put(mesh_.globalNode(n));
        for (int i = 0; i < dim; ++i) out.put(mesh_.coord(n, i));
        for (int i = 0; i < dim; ++i) out.put(u[std::size_t(n) * dim + i]);
        for (int i = 0; i < dim; ++i) out.put(force[std::size_t(n) * dim + i]);
      }
    }
  }
  std::vector<std::vector<char>> toRank(static_cast<std::size_t>(p));
  toRank[0] = out.take();
  const auto fromRank = assembly::exchangeBytes(*disc_.dofs->comm(), toRank);
  onRoot([&] {
    io::ExodusWriter& w = *writer_;
    // the surfaces as a mesh of their own: nodes in order of first appearance (rank 0's facets first)
    mesh::Mesh surfaces;
    surfaces.dim = dim;
    surfaces.numBodies = int(mesh_.surfaces.size());
    surfaces.surfaces.resize(mesh_.surfaces.size());
    for (std::size_t b = 0; b < mesh_.surfaces.size(); ++b) {
      surfaces.surfaces[b].body = mesh_.surfaces[b].body;
      surfaces.surfaces[b].nodesPerFacet = mesh_.surfaces[b].nodesPerFacet;
    }
    std::vector<Real> su, sf;
    std::map<GlobalIndex, LocalIndex> index;
    for (const auto& bytes : fromRank) {
      core::ByteReader in(bytes);
      while (!in.atEnd()) {
        const int body = in.get<int>();
        mesh::Surface& s = surfaces.surfaces.at(std::size_t(body));
        for (int a = 0; a < s.nodesPerFacet; ++a) {
          const auto id = in.get<GlobalIndex>();
          Real x[3], uu[3], ff[3];
          for (int i = 0; i < dim; ++i) x[i] = in.get<Real>();
          for (int i = 0; i < dim; ++i) uu[i] = in.get<Real>();
          for (int i = 0; i < dim; ++i) ff[i] = in.get<Real>();
          const auto [it, added] = index.emplace(id, surfaces.numNodes());
          if (added) {
            surfaces.nodeIds.push_back(id);
            surfaces.coords.insert(surfaces.coords.end(), x, x + dim);
            su.insert(su.end(), uu, uu + dim);
            sf.insert(sf.end(), ff, ff + dim);
          }
          s.facets.push_back(it->second);
        }
        s.facetCells.push_back(-1);
      }
    }
    const auto t = assembly::surfaceTractions(surfaces, disc_.problem->formulation(), su, sf);
    // zero off the surfaces; a window of nodes at a time
    const std::int64_t numNodes = w.layout().numNodes;
    const std::int64_t window = std::max<std::int64_t>(1, std::int64_t(windowBytes_ / sizeof(double)));
    std::vector<double> column;
    auto fieldIndex = [&](const char* name) {
      return std::size_t(std::find(variables_.nodal.begin(), variables_.nodal.end(), name) - variables_.nodal.begin());
    };
    for (int k = 0; k <= dim; ++k) {  // traction components, then pressure
      const std::size_t variable = fieldIndex(k < dim ? kTraction[k] : "pressure");
      auto it = index.begin();
      for (std::int64_t first = 0; first < numNodes; first += window) {
        const std::int64_t count = std::min(window, numNodes - first);
        column.assign(std::size_t(count), 0.0);
        for (; it != index.end() && it->first < first + count; ++it)
          column[std::size_t(it->first - first)] =
              k < dim ? t.traction[std::size_t(it->second) * dim + k] : t.pressure[std::size_t(it->second)];
        w.putNodal(variable, first, count, column.data());
      }
    }
  });
}

void ResultsWriter::writeCellFields(const std::vector<Real>& u) {
  const auto components = stressComponents(disc_.problem->formulation());
  const int width = int(components.size()) + 2;  // the stresses, J, von Mises
  const Real nan = std::numeric_limits<Real>::quiet_NaN();  // an inverted cell: no stress
  for (std::size_t b = 0; b < mesh_.blocks.size(); ++b) {
    const auto& block = mesh_.blocks[b];
    const material::NeoHookean& material = disc_.problem->material(block.body);
    const int npc = mesh::nodesPerCell(block.type);
    std::vector<GlobalIndex> ids;
    std::vector<Real> values;
    for (LocalIndex c : ownCells_[b]) {
      const LocalIndex* nodes = &block.connectivity[std::size_t(c) * npc];
      Mat3 s;
      Real J = 0.0;
      bool ok = false;
      if (!fem::withSolidKernel(disc_.problem->formulation(), block.type, [&](auto kernel) {
            ok = cellStress<decltype(kernel)>(mesh_, nodes, u, material, s, J);
          }))
        throw std::logic_error("ResultsWriter: no kernel for block \"" + block.name + "\" (the assembly has one)");
      ids.push_back(block.cellId(c));
      for (const auto& k : components) values.push_back(ok ? s.a[k.i][k.j] : nan);
      values.push_back(ok ? J : nan);
      values.push_back(ok ? vonMises(s) : nan);
    }
    solver::streamToRoot<Real>(
        *disc_.dofs->comm(), ids, values, width,
        [&](const std::vector<GlobalIndex>& at, const std::vector<Real>& v) {
          expectConsecutive(at, ("cell of block " + block.name).c_str());
          std::vector<double> column(at.size());
          for (int k = 0; k < width; ++k) {
            for (std::size_t e = 0; e < at.size(); ++e) column[e] = v[e * width + k];
            writer_->putElement(std::size_t(k), b, at[0], std::int64_t(at.size()), column.data());
          }
        },
        windowBytes_);
  }
}

}  // namespace cgcm::app
