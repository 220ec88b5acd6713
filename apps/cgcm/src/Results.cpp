#include "cgcm/app/Results.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

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

}  // namespace

ResultsWriter::ResultsWriter(const std::string& path, const mesh::Mesh* mesh, const solver::Discretization& disc,
                             const std::vector<std::string>& globals, int keptSteps, bool criticalMode)
    : mesh_(mesh),
      disc_(disc),
      globals_(globals),
      root_(disc.dofs->comm()->getRank() == 0),
      criticalMode_(criticalMode),
      gather_(disc.dofs->ownedMap()) {
  io::ExodusVariables vars;
  const int dim = disc.dofs->dofsPerNode();
  for (int i = 0; i < dim; ++i) vars.nodal.push_back(kDisplacement[i]);
  if (disc.problem->hasInteraction()) {  // whichever method: from the interaction force on each node
    for (int i = 0; i < dim; ++i) vars.nodal.push_back(kTraction[i]);
    vars.nodal.push_back("pressure");
    for (int i = 0; i < dim; ++i) vars.nodal.push_back(kInteractionForce[i]);
  }
  if (criticalMode_)
    for (int i = 0; i < dim; ++i) vars.nodal.push_back(kCriticalMode[i]);
  for (const auto& c : stressComponents(disc.problem->formulation())) vars.element.push_back(c.name);
  vars.element.insert(vars.element.end(), {"J", "von_mises"});
  vars.global = globals;
  solver::runOnRoot(*disc.dofs->comm(), [&] {
    if (!mesh_) throw std::logic_error("ResultsWriter: rank 0 needs the whole mesh");
    writer_ = keptSteps >= 0 ? std::make_unique<io::ExodusWriter>(path, *mesh_, vars, keptSteps)
                             : std::make_unique<io::ExodusWriter>(path, "cgcm", *mesh_, vars);
  });
}

void ResultsWriter::write(const assembly::Vector& x, const std::vector<double>& globals, const assembly::Vector* mode) {
  const bool interacting = disc_.problem->hasInteraction();
  // by dof id = global node id * dim + i; the interaction force of the state x, whichever method
  const std::vector<Real> forceByNode =
      interacting ? gather_.gather(*disc_.problem->interactionNodeForces(x)) : std::vector<Real>{};
  const std::vector<Real> modeByNode =
      criticalMode_ && mode ? gather_.gather(*mode) : std::vector<Real>{};
  const std::vector<Real> uByNode = gather_.gather(x);
  if (!root_) return;
  const std::vector<Real> u = inMeshOrder(uByNode);
  io::ExodusWriter::Fields nodal, element;
  displacementAndStress(u, nodal, element);
  if (interacting) interactionFields(u, inMeshOrder(forceByNode), nodal);
  if (criticalMode_) {
    const int dim = mesh_->dim;
    const std::vector<Real> m = inMeshOrder(modeByNode);
    for (int i = 0; i < dim; ++i) {
      auto& field = nodal[kCriticalMode[i]];
      field.assign(std::size_t(mesh_->numNodes()), 0.0);
      for (LocalIndex n = 0; !m.empty() && n < mesh_->numNodes(); ++n) field[std::size_t(n)] = m[std::size_t(n) * dim + i];
    }
  }
  io::ExodusWriter::Scalars scalars;
  for (std::size_t k = 0; k < globals_.size(); ++k) scalars[globals_[k]] = globals[k];
  writer_->writeStep(writer_->numSteps() + 1, nodal, element, scalars);
}

std::vector<Real> ResultsWriter::inMeshOrder(const std::vector<Real>& byGlobalNode) const {
  if (byGlobalNode.empty()) return {};
  const int dim = mesh_->dim;
  std::vector<Real> out(std::size_t(mesh_->numNodes()) * dim);
  for (LocalIndex n = 0; n < mesh_->numNodes(); ++n)
    for (int i = 0; i < dim; ++i) out[std::size_t(n) * dim + i] = byGlobalNode[std::size_t(mesh_->globalNode(n)) * dim + i];
  return out;
}

void ResultsWriter::displacementAndStress(const std::vector<Real>& u, io::ExodusWriter::Fields& nodal,
                                          io::ExodusWriter::Fields& element) const {
  const auto& mesh = *mesh_;
  const int dim = mesh.dim;
  for (int i = 0; i < dim; ++i) {
    auto& d = nodal[kDisplacement[i]];
    d.resize(mesh.numNodes());
    for (LocalIndex n = 0; n < mesh.numNodes(); ++n) d[n] = u[std::size_t(n) * dim + i];
  }
  const auto components = stressComponents(disc_.problem->formulation());
  std::vector<std::vector<double>*> out;
  for (const auto& c : components) out.push_back(&element[c.name]);
  out.push_back(&element["J"]);
  out.push_back(&element["von_mises"]);
  for (auto* o : out) o->reserve(mesh.numCells());
  for (const auto& b : mesh.blocks) {
    const material::NeoHookean& material = disc_.problem->material(b.body);
    const int npc = mesh::nodesPerCell(b.type);
    for (LocalIndex c = 0; c < b.numCells(); ++c) {
      const LocalIndex* nodes = &b.connectivity[std::size_t(c) * npc];
      Mat3 s;
      Real J = 0.0;
      bool ok = false;
      if (!fem::withSolidKernel(disc_.problem->formulation(), b.type, [&](auto kernel) {
            ok = cellStress<decltype(kernel)>(mesh, nodes, u, material, s, J);
          }))
        throw std::logic_error("ResultsWriter: no kernel for block \"" + b.name + "\" (the assembly has one)");
      const Real nan = std::numeric_limits<Real>::quiet_NaN();  // an inverted cell: no stress
      for (std::size_t k = 0; k < components.size(); ++k) out[k]->push_back(ok ? s.a[components[k].i][components[k].j] : nan);
      out[components.size()]->push_back(ok ? J : nan);
      out[components.size() + 1]->push_back(ok ? vonMises(s) : nan);
    }
  }
}

void ResultsWriter::interactionFields(const std::vector<Real>& u, const std::vector<Real>& force,
                                      io::ExodusWriter::Fields& nodal) const {
  const auto& mesh = *mesh_;
  const int d = mesh.dim;
  const LocalIndex nn = mesh.numNodes();
  // the traction on the whole mesh's surfaces: the same formula for Method 3 (the force of the surface
  // pairs) and Method 1 (a body force: the traction leaves out the interior nodes' share)
  const auto t = assembly::surfaceTractions(mesh, disc_.problem->formulation(), u, force);
  for (int i = 0; i < d; ++i) {
    auto& traction = nodal[kTraction[i]];
    auto& f = nodal[kInteractionForce[i]];
    traction.resize(std::size_t(nn));
    f.resize(std::size_t(nn));
    for (LocalIndex n = 0; n < nn; ++n) {
      traction[std::size_t(n)] = t.traction[d * std::size_t(n) + i];
      f[std::size_t(n)] = force[d * std::size_t(n) + i];
    }
  }
  nodal["pressure"] = t.pressure;
}

}  // namespace cgcm::app
