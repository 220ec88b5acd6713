#include "cgcm/app/Results.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "cgcm/core/Error.hpp"
#include "cgcm/fem/Dispatch.hpp"

namespace cgcm::app {

namespace {

const char* const kDisplacement[] = {"displacement_x", "displacement_y", "displacement_z"};

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
  Real X[Kernel::numNodes][Kernel::dim], x[Kernel::numNodes][Kernel::dim];
  for (int a = 0; a < Kernel::numNodes; ++a)
    for (int i = 0; i < Kernel::dim; ++i) {
      X[a][i] = m.coord(nodes[a], i);
      x[a][i] = X[a][i] + u[std::size_t(nodes[a]) * Kernel::dim + i];
    }
  return Kernel::averageStress(X, x, mat, sigma, J);
}

}  // namespace

ResultsWriter::ResultsWriter(const std::string& path, const mesh::Mesh* mesh, const Discretization& disc,
                             const std::vector<std::string>& globals, int keptSteps)
    : mesh_(mesh),
      disc_(disc),
      globals_(globals),
      root_(disc.dofs->comm()->getRank() == 0),
      gather_(disc.dofs->ownedMap()) {
  io::ExodusVariables vars;
  const int dim = disc.dofs->dofsPerNode();
  for (int i = 0; i < dim; ++i) vars.nodal.push_back(kDisplacement[i]);
  if (disc.problem->interaction()) {  // Method 3: the traction of its pairs
    vars.nodal.insert(vars.nodal.end(), {"traction_x", "traction_y"});
    if (dim == 3) vars.nodal.push_back("traction_z");
    vars.nodal.push_back("pressure");
  }
  for (const auto& c : stressComponents(disc.problem->formulation())) vars.element.push_back(c.name);
  vars.element.insert(vars.element.end(), {"J", "von_mises"});
  vars.global = globals;
  runOnRoot(*disc.dofs->comm(), [&] {
    if (!mesh_) throw std::logic_error("ResultsWriter: rank 0 needs the whole mesh");
    writer_ = keptSteps >= 0 ? std::make_unique<io::ExodusWriter>(path, *mesh_, vars, keptSteps)
                             : std::make_unique<io::ExodusWriter>(path, "cgcm", *mesh_, vars);
  });
}

void ResultsWriter::write(const assembly::Vector& x, const std::vector<double>& globals) {
  const std::vector<Real> forceByNode = disc_.problem->interaction() ? interactionNodeForces(x) : std::vector<Real>{};
  const std::vector<Real> uByNode = gather_.gather(x);  // by dof id = global node id * dim + i
  if (!root_) return;
  const std::vector<Real> u = inMeshOrder(uByNode), force = inMeshOrder(forceByNode);
  io::ExodusWriter::Fields nodal, element;
  displacementAndStress(u, nodal, element);
  if (disc_.problem->interaction()) traction(u, force, nodal);
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
      fem::withSolidKernel(disc_.problem->formulation(), b.type, [&](auto kernel) {
        ok = cellStress<decltype(kernel)>(mesh, nodes, u, material, s, J);
      });
      const Real nan = std::numeric_limits<Real>::quiet_NaN();  // an inverted cell: no stress
      for (std::size_t k = 0; k < components.size(); ++k) out[k]->push_back(ok ? s.a[components[k].i][components[k].j] : nan);
      out[components.size()]->push_back(ok ? J : nan);
      out[components.size() + 1]->push_back(ok ? vonMises(s) : nan);
    }
  }
}

std::vector<Real> ResultsWriter::interactionNodeForces(const assembly::Vector& x) const {
  // Each rank holds the pairs of its own facets, from the last evaluation, at this state.
  const auto& in = *disc_.problem->interaction();
  const int d = in.dim();
  const std::vector<Real>& coords = disc_.problem->currentCoordinates(x);  // every surface node
  const auto& dofs = *disc_.dofs;
  // by global node id: the ranks' meshes number their nodes each their own way
  std::vector<Real> local(dofs.ownedMap()->getGlobalNumElements(), 0.0), force(local.size(), 0.0);
  interaction::PairContribution c;
  for (const auto& p : in.pairs()) {
    in.evaluatePair(coords.data(), p, c, false);
    for (int a = 0; a < c.numRowNodes; ++a)
      for (int i = 0; i < d; ++i)
        local[d * std::size_t(dofs.globalNode(c.rowNodes[a])) + i] -= c.f[d * a + i];  // on the body: -f_C
  }
  Teuchos::reduce(local.data(), force.data(), int(local.size()), Teuchos::REDUCE_SUM, 0, *disc_.dofs->comm());
  return force;
}

void ResultsWriter::traction(const std::vector<Real>& u, const std::vector<Real>& force,
                             io::ExodusWriter::Fields& nodal) const {
  const auto& mesh = *mesh_;
  const auto& in = *disc_.problem->interaction();
  const int d = in.dim();
  const LocalIndex nn = mesh.numNodes();
  // the interaction's surfaces name the nodes of the mesh this rank assembles; the fields are on mesh_
  std::vector<LocalIndex> nodeOfId(std::size_t(nn), -1);
  for (LocalIndex n = 0; n < nn; ++n) nodeOfId[std::size_t(mesh.globalNode(n))] = n;
  std::vector<Real> x(mesh.coords);
  for (std::size_t k = 0; k < x.size(); ++k) x[k] += u[k];
  std::vector<Real> area(nn, 0.0), normal(d * std::size_t(nn), 0.0);
  const bool axisymmetric = disc_.problem->formulation() == Formulation::Axisymmetric;
  for (int b = 0; b < in.numBodies(); ++b) {
    const auto& s = in.surface(b);
    const int npf = s.nodesPerFacet;
    for (LocalIndex f = 0; f < s.numFacets(); ++f) {
      LocalIndex n[4];
      for (int a = 0; a < npf; ++a) n[a] = nodeOfId[std::size_t(disc_.dofs->globalNode(s.facets[std::size_t(f) * npf + a]))];
      if (d == 2) {
        const Real tx = x[2 * n[1]] - x[2 * n[0]], ty = x[2 * n[1] + 1] - x[2 * n[0] + 1];
        const Real length = std::hypot(tx, ty);
        // share of each node: integral of N_a (times 2 pi r in axisymmetry)
        const Real a0 = axisymmetric ? 2.0 * kPi * length * (2.0 * x[2 * n[0]] + x[2 * n[1]]) / 6.0 : 0.5 * length;
        const Real a1 = axisymmetric ? 2.0 * kPi * length * (x[2 * n[0]] + 2.0 * x[2 * n[1]]) / 6.0 : 0.5 * length;
        area[n[0]] += a0, area[n[1]] += a1;
        for (int a = 0; a < 2; ++a) normal[2 * n[a]] += ty, normal[2 * n[a] + 1] -= tx;  // outward, length-weighted
        continue;
      }
      // 3D: the facet's area vector (sum of its corner triangles' for a quad), shared equally by its nodes
      Real m[3] = {0.0, 0.0, 0.0};
      for (int a = 1; a + 1 < npf; ++a) {
        const Real* x0 = &x[3 * n[0]];
        const Real* x1 = &x[3 * n[a]];
        const Real* x2 = &x[3 * n[a + 1]];
        const Real e1[3] = {x1[0] - x0[0], x1[1] - x0[1], x1[2] - x0[2]};
        const Real e2[3] = {x2[0] - x0[0], x2[1] - x0[1], x2[2] - x0[2]};
        m[0] += 0.5 * (e1[1] * e2[2] - e1[2] * e2[1]);
        m[1] += 0.5 * (e1[2] * e2[0] - e1[0] * e2[2]);
        m[2] += 0.5 * (e1[0] * e2[1] - e1[1] * e2[0]);
      }
      const Real A = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
      for (int a = 0; a < npf; ++a) {
        area[n[a]] += A / npf;
        for (int i = 0; i < 3; ++i) normal[3 * std::size_t(n[a]) + i] += m[i];
      }
    }
  }
  const char* names[3] = {"traction_x", "traction_y", "traction_z"};
  auto& pressure = nodal["pressure"];
  pressure.assign(nn, 0.0);
  for (int i = 0; i < d; ++i) nodal[names[i]].assign(nn, 0.0);
  for (LocalIndex n = 0; n < nn; ++n) {
    if (!(area[n] > 0.0)) continue;
    Real tn = 0.0, len2 = 0.0;
    for (int i = 0; i < d; ++i) {
      const Real t = force[d * std::size_t(n) + i] / area[n], m = normal[d * std::size_t(n) + i];
      nodal[names[i]][n] = t;
      tn += t * m;
      len2 += m * m;
    }
    if (len2 > 0.0) pressure[n] = -tn / std::sqrt(len2);
  }
}

}  // namespace cgcm::app
