// The parts of the discrete problem: the bulk part per body (its tangent
// against finite differences, a material per body), the interaction part
// (the coupled tangent against finite differences, the force on each body)
// and the Problem as their sum.
#include <gtest/gtest.h>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <memory>
#include <numeric>
#include <random>
#include <tuple>
#include <vector>

#include "cgcm/assembly/GhostedSurfaces.hpp"
#include "cgcm/assembly/Problem.hpp"
#include "cgcm/assembly/SurfaceTraction.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/interaction/PairPotential.hpp"
#include "cgcm/interaction/Quadrature.hpp"
#include "cgcm/mesh/Generators.hpp"
#include "cgcm/mesh/Subdomain.hpp"

namespace cgcm::assembly {
namespace {

// Two boxes along z, a gap apart: body 0 tetrahedra below, body 1 hexahedra above.
std::shared_ptr<mesh::Mesh> twoBoxes(Real gap, int cells = 2) {
  mesh::BoxSpec lower;
  lower.nx = lower.ny = lower.nz = cells;
  lower.tetrahedra = true;
  lower.z0 = -1.0;
  auto m = std::make_shared<mesh::Mesh>(mesh::box(lower));
  mesh::BoxSpec upper;
  upper.nx = upper.ny = upper.nz = cells;
  upper.x0 = 0.1, upper.y0 = -0.05, upper.z0 = gap;
  upper.name = "upper";
  mesh::append(*m, mesh::box(upper), "upper ");
  return m;
}

std::vector<Real> toStd(const Vector& v) {
  auto h = v.getLocalViewHost(Tpetra::Access::ReadOnly);
  std::vector<Real> out(h.extent(0));
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = h(i, 0);
  return out;
}

void fromStd(const std::vector<Real>& x, Vector& v) {
  auto h = v.getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (std::size_t i = 0; i < x.size(); ++i) h(i, 0) = x[i];
}

std::vector<Real> residual(Problem& p, const std::vector<Real>& u) {
  Vector uv(p.dofs().ownedMap()), f(p.dofs().ownedMap());
  fromStd(u, uv);
  p.evaluate(uv, f, nullptr);
  return toStd(f);
}

// max |J - J_fd| / max |J| over every entry, J_fd by central differences with step h.
Real tangentError(Problem& p, const std::vector<Real>& u, Real h) {
  Vector uv(p.dofs().ownedMap()), f(p.dofs().ownedMap());
  fromStd(u, uv);
  auto J = p.createMatrix();
  p.evaluate(uv, f, J.get());
  const std::size_t n = u.size();
  std::vector<Real> dense(n * n, 0.0);
  Real jmax = 0.0;
  for (std::size_t r = 0; r < n; ++r) {
    Matrix::nonconst_local_inds_host_view_type cols("cols", J->getNumEntriesInLocalRow(r));
    Matrix::nonconst_values_host_view_type vals("vals", cols.extent(0));
    std::size_t count = 0;
    J->getLocalRowCopy(LocalIndex(r), cols, vals, count);
    for (std::size_t k = 0; k < count; ++k) {
      dense[r * n + J->getColMap()->getGlobalElement(cols(k))] = vals(k);
      jmax = std::max(jmax, std::abs(vals(k)));
    }
  }
  Real worst = 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    std::vector<Real> up = u, um = u;
    up[j] += h, um[j] -= h;
    const auto fp = residual(p, up), fm = residual(p, um);
    for (std::size_t i = 0; i < n; ++i) worst = std::max(worst, std::abs(dense[i * n + j] - (fp[i] - fm[i]) / (2 * h)));
  }
  return worst / jmax;
}

std::vector<Real> randomDisplacement(std::size_t n, Real amplitude, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> d(-amplitude, amplitude);
  std::vector<Real> u(n);
  for (Real& v : u) v = d(rng);
  return u;
}

// A 12^3 hexahedral box with its cells numbered at random, as a mesh generator may number them.
std::shared_ptr<mesh::Mesh> shuffledBox() {
  mesh::BoxSpec spec;
  spec.nx = spec.ny = spec.nz = 12;
  auto m = std::make_shared<mesh::Mesh>(mesh::box(spec));
  auto& conn = m->blocks[0].connectivity;
  std::vector<LocalIndex> order(std::size_t(m->numCells()));
  for (std::size_t c = 0; c < order.size(); ++c) order[c] = LocalIndex(c);
  std::shuffle(order.begin(), order.end(), std::mt19937(5));
  std::vector<LocalIndex> shuffled;
  for (LocalIndex c : order) shuffled.insert(shuffled.end(), conn.begin() + 8 * c, conn.begin() + 8 * c + 8);
  conn = shuffled;
  return m;
}

// Nodes touched by the cells of more than one part (owner: per cell).
int sharedNodes(const mesh::Mesh& m, const std::vector<int>& owner) {
  const auto& conn = m.blocks[0].connectivity;
  std::vector<int> first(std::size_t(m.numNodes()), -1);
  std::vector<char> counted(std::size_t(m.numNodes()), 0);
  int shared = 0;
  for (std::size_t c = 0; c < owner.size(); ++c)
    for (int a = 0; a < 8; ++a) {
      const auto n = std::size_t(conn[8 * c + std::size_t(a)]);
      if (first[n] < 0) first[n] = owner[c];
      else if (first[n] != owner[c] && !counted[n]) counted[n] = 1, ++shared;
    }
  return shared;
}

std::vector<int> cellOwners(const DofMap& dofs, LocalIndex numCells) {
  std::vector<int> owner(static_cast<std::size_t>(numCells));
  for (LocalIndex c = 0; c < numCells; ++c) owner[std::size_t(c)] = dofs.cellOwner(c);
  return owner;
}

// The box's geometric partition gives every cell one owner (the same list on
// every rank), parts balanced to Zoltan2's 2 % and an interface of about one
// plane of nodes; contiguous ranges of the shuffled numbering share most nodes.
TEST(DofMap, GeometricPartitionIsCompactAndBalanced) {
  auto comm = Tpetra::getDefaultComm();
  const int p = comm->getSize(), rank = comm->getRank();
  const auto m = shuffledBox();
  const LocalIndex numCells = m->numCells();
  DofMap geometric(comm, *m, 3), contiguous(comm, *m, 3, CellPartition::Contiguous);
  std::vector<long long> perRank(p, 0);
  long long ownerSum = 0;
  for (LocalIndex c = 0; c < numCells; ++c) {
    ASSERT_GE(geometric.cellOwner(c), 0);
    ASSERT_LT(geometric.cellOwner(c), p);
    ++perRank[geometric.cellOwner(c)];
    ownerSum += geometric.cellOwner(c) * (c % 17 + 1);
  }
  long long minSum = 0, maxSum = 0;  // the same list on every rank
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MIN, ownerSum, Teuchos::outArg(minSum));
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_MAX, ownerSum, Teuchos::outArg(maxSum));
  EXPECT_EQ(minSum, maxSum);
  EXPECT_EQ(LocalIndex(geometric.localCells(0).size()), perRank[rank]);
  EXPECT_EQ(geometric.ownedMap()->getGlobalNumElements(), std::size_t(3 * m->numNodes()));
  for (int r = 0; r < p; ++r) EXPECT_LE(perRank[r], 1.02 * numCells / p + 1) << "rank " << r;
  const int geometricShared = sharedNodes(*m, cellOwners(geometric, numCells));
  const int contiguousShared = sharedNodes(*m, cellOwners(contiguous, numCells));
  if (p == 1) {
    EXPECT_EQ(geometricShared, 0);
    return;
  }
  const int plane = 13 * 13;
  EXPECT_LE(geometricShared, 2 * plane);
  EXPECT_GT(contiguousShared, 5 * plane);
  std::printf("[partition] %d ranks: shared nodes geometric %d, contiguous %d (one plane %d)\n", p, geometricShared,
              contiguousShared, plane);
  // one process cutting the parts of p ranks (a root that sends them) lists the contiguous ranges alike
  EXPECT_EQ(partitionCells(*m, CellPartition::Contiguous, p), cellOwners(contiguous, numCells));
}

// One process cutting the box for 2-4 ranks (a root that sends the parts): every part used, balanced
// to Zoltan2's 2 %, one plane of nodes or so per cut.
TEST(DofMap, OneProcessCutsTheRanksPartsCompactAndBalanced) {
  const auto m = shuffledBox();
  const LocalIndex numCells = m->numCells();
  const int plane = 13 * 13;
  for (int parts = 2; parts <= 4; ++parts) {
    SCOPED_TRACE(parts);
    const auto owner = partitionCells(*m, CellPartition::Geometric, parts);
    ASSERT_EQ(owner.size(), std::size_t(numCells));
    std::vector<LocalIndex> perPart(std::size_t(parts), 0);
    for (int o : owner) {
      ASSERT_GE(o, 0);
      ASSERT_LT(o, parts);
      ++perPart[std::size_t(o)];
    }
    for (LocalIndex n : perPart) {
      EXPECT_GT(n, 0);
      EXPECT_LE(n, 1.02 * numCells / parts + 1);
    }
    EXPECT_LE(sharedNodes(*m, owner), 2 * (parts - 1) * plane);
  }
  EXPECT_EQ(partitionCells(*m, CellPartition::Geometric, 1), std::vector<int>(std::size_t(numCells), 0));
}

TEST(DofMap, PartitionNamesAreChecked) {
  EXPECT_EQ(parseCellPartition("geometric"), CellPartition::Geometric);
  EXPECT_EQ(parseCellPartition("contiguous"), CellPartition::Contiguous);
  EXPECT_THROW(parseCellPartition("metis"), InputError);
}

TEST(BulkPart, TangentAndOneMaterialPerBody) {
  auto comm = Tpetra::getDefaultComm();
  if (comm->getSize() > 1) GTEST_SKIP() << "one rank";
  auto m = twoBoxes(0.5);
  auto dofs = Teuchos::rcp(new DofMap(comm, *m, 3));
  const auto soft = material::NeoHookean::fromYoungPoisson(1.0, 0.3), stiff = material::NeoHookean::fromYoungPoisson(3.0, 0.3);
  Problem same(dofs, m, Formulation::ThreeD, soft), mixed(dofs, m, Formulation::ThreeD, {soft, stiff});
  ASSERT_EQ(mixed.bulkParts().size(), 2u);
  EXPECT_EQ(mixed.bulkParts()[0].numLocalCells() + mixed.bulkParts()[1].numLocalCells(), m->numCells());
  EXPECT_NEAR(mixed.material(1).youngsModulus(), 3.0, 1e-15);
  const auto u = randomDisplacement(3 * std::size_t(m->numNodes()), 0.03, 7);
  const auto f1 = residual(same, u), f3 = residual(mixed, u);
  // Neo-Hookean at fixed nu: the internal force scales with Y, body by body
  std::vector<int> nodeBody(m->numNodes());
  for (const auto& b : m->blocks)
    for (LocalIndex n : b.connectivity) nodeBody[n] = b.body;
  Real fmax = 0.0, worst = 0.0;
  for (std::size_t i = 0; i < f1.size(); ++i) {
    const Real factor = nodeBody[i / 3] == 1 ? 3.0 : 1.0;
    fmax = std::max(fmax, std::abs(f3[i]));
    worst = std::max(worst, std::abs(f3[i] - factor * f1[i]));
  }
  EXPECT_LE(worst, 1e-13 * fmax);
  const Real err = tangentError(mixed, u, 1e-6);
  std::printf("[bulk part] tet4 + hex8 bodies, two materials: max|J - J_fd|/max|J| = %.2e\n", err);
  EXPECT_LT(err, 1e-6);
}

std::shared_ptr<interaction::SurfaceInteraction> methodThree(const mesh::Mesh& m);

// The Jacobian's local entries as (row, column, value), in the order the matrix holds them.
std::vector<std::tuple<LocalIndex, LocalIndex, Real>> localEntries(const Matrix& J) {
  std::vector<std::tuple<LocalIndex, LocalIndex, Real>> out;
  for (std::size_t r = 0; r < J.getNodeNumRows(); ++r) {
    Matrix::nonconst_local_inds_host_view_type cols("cols", J.getNumEntriesInLocalRow(LocalIndex(r)));
    Matrix::nonconst_values_host_view_type vals("vals", cols.extent(0));
    std::size_t count = 0;
    J.getLocalRowCopy(LocalIndex(r), cols, vals, count);
    for (std::size_t k = 0; k < count; ++k) out.emplace_back(LocalIndex(r), cols(k), vals(k));
  }
  return out;
}

// The bulk scatter adds each tangent entry at its cached offset in the row; the Jacobian is, bit for bit,
// the one whose entries are found by bisection: linear and quadratic cells in 3D and 2D, with an
// interaction's couplings in the graph (1 and 2 ranks; the offsets found for every block).
TEST(BulkPart, ScatterAtCachedOffsetsIsTheScatterByBisection) {
  auto comm = Tpetra::getDefaultComm();
  struct Case {
    const char* name;
    std::shared_ptr<mesh::Mesh> mesh;
    Formulation formulation;
    bool interaction;
  };
  std::vector<Case> cases;
  cases.push_back({"tet4 + hex8, Method 3", twoBoxes(0.3), Formulation::ThreeD, true});
  {
    mesh::BoxSpec h, s, t;
    h.nx = h.ny = 3, h.nz = 2, h.name = "hex27", h.element = {2, false};
    s.x0 = 3.0, s.name = "hex20", s.element = {2, true};
    t.x0 = 5.0, t.tetrahedra = true, t.name = "tet10", t.element = {2, false};
    auto m = std::make_shared<mesh::Mesh>(mesh::box(h));
    mesh::append(*m, mesh::box(s), "hex20 ");
    mesh::append(*m, mesh::box(t), "tet10 ");
    cases.push_back({"hex27, hex20, tet10", m, Formulation::ThreeD, false});
  }
  {
    mesh::RectangleSpec a, b;
    a.nx = 6, a.ny = 4, a.name = "quad4";
    b.nx = 4, b.ny = 3, b.y0 = 1.5, b.name = "quad9", b.element = {2, false};
    auto m = std::make_shared<mesh::Mesh>(mesh::rectangle(a));
    mesh::append(*m, mesh::rectangle(b), "quad9 ");
    cases.push_back({"quad4 + quad9, axisymmetric", m, Formulation::Axisymmetric, false});
  }
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const int dim = formulationDim(c.formulation);
    auto dofs = Teuchos::rcp(new DofMap(comm, *c.mesh, dim));
    Problem p(dofs, c.mesh, c.formulation, material::NeoHookean::fromYoungPoisson(1.0, 0.3));
    if (c.interaction) p.setInteraction(methodThree(*c.mesh), 1.5);
    Vector u(dofs->ownedMap()), f(dofs->ownedMap());
    {
      const auto all = randomDisplacement(std::size_t(dim) * std::size_t(c.mesh->numNodes()), 0.02, 11);
      auto h = u.getLocalViewHost(Tpetra::Access::OverwriteAll);
      const auto& map = *dofs->ownedMap();
      for (std::size_t k = 0; k < map.getNodeNumElements(); ++k) h(k, 0) = all[std::size_t(map.getGlobalElement(LocalIndex(k)))];
    }
    if (c.interaction) EXPECT_TRUE(p.updateInteractionGraph(u));  // the couplings at u
    auto J = p.createMatrix();
    p.evaluate(u, f, J.get());
    const auto atOffsets = localEntries(*J);
    for (const auto& part : p.bulkParts())
      if (part.numLocalCells() > 0) EXPECT_GE(part.numBlocksWithOffsets(), 1);  // (a rank may hold no cell of a body)
    p.useScatterOffsets(false);
    p.evaluate(u, f, J.get());
    const auto byBisection = localEntries(*J);
    ASSERT_EQ(atOffsets.size(), byBisection.size());
    std::size_t differing = 0;
    for (std::size_t k = 0; k < atOffsets.size(); ++k) differing += atOffsets[k] != byBisection[k] ? 1 : 0;
    EXPECT_EQ(differing, 0u) << "of " << atOffsets.size() << " entries";
  }
}

// The interaction part's share of f (full - bulk), summed per body, is minus
// the force on the body (to the round-off of the larger of the two).
void expectForcesAreTheInteractionShare(const mesh::Mesh& m, const std::vector<Real>& fb, const std::vector<Real>& ff,
                                        const std::vector<std::array<Real, 3>>& forces) {
  std::vector<int> nodeBody(m.numNodes());
  for (const auto& b : m.blocks)
    for (LocalIndex n : b.connectivity) nodeBody[n] = b.body;
  Real sum[2][3] = {}, scale = 0.0;
  for (std::size_t i = 0; i < ff.size(); ++i) {
    sum[nodeBody[i / 3]][i % 3] += ff[i] - fb[i];
    scale = std::max({scale, std::abs(ff[i]), std::abs(fb[i])});
  }
  for (int b = 0; b < 2; ++b)
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(forces[b][i], -sum[b][i], 1e-12 * scale);
}

std::shared_ptr<interaction::SurfaceInteraction> methodThree(const mesh::Mesh& m) {
  interaction::SurfaceInteractionOptions o;
  o.formulation = Formulation::ThreeD;
  o.quadraturePoints = 2;
  o.cutoff = 2.0;
  return std::make_shared<interaction::SurfaceInteraction>(m.surfaces, std::vector<Real>{1.0, 1.0},
                                                           interaction::makePotential("lennard-jones", 10.0, 0.25), o);
}

// Two boxes 0.3 apart: the bulk alone and the bulk with the interaction, at a random state.
struct TwoBodies {
  std::shared_ptr<mesh::Mesh> m = twoBoxes(0.3);
  Teuchos::RCP<DofMap> dofs = Teuchos::rcp(new DofMap(Tpetra::getDefaultComm(), *m, 3));
  material::NeoHookean mat = material::NeoHookean::fromYoungPoisson(1.0, 0.3);
  Problem bulk{dofs, m, Formulation::ThreeD, mat}, full{dofs, m, Formulation::ThreeD, mat};
  std::shared_ptr<interaction::SurfaceInteraction> si = methodThree(*m);
  std::vector<Real> u;
  explicit TwoBodies(unsigned seed) : u(randomDisplacement(3 * std::size_t(m->numNodes()), 0.02, seed)) {
    full.setInteraction(si, 1.5);
  }
};

TEST(InteractionPart, CoupledTangentAndForcesOnTheBodies) {
  if (Tpetra::getDefaultComm()->getSize() > 1) GTEST_SKIP() << "one rank";
  TwoBodies t(11);
  auto& [m, dofs, mat, bulk, full, si, u] = t;
  Vector uv(dofs->ownedMap());
  fromStd(u, uv);
  EXPECT_FALSE(full.interactionGraphCovers(uv, full.searchRadius()));  // no graph yet
  EXPECT_TRUE(full.updateInteractionGraph(uv));
  EXPECT_TRUE(full.interactionGraphCovers(uv, full.searchRadius()));
  const auto fb = residual(bulk, u), ff = residual(full, u);
  const auto forces = full.interactionForces();
  ASSERT_EQ(forces.size(), 2u);
  expectForcesAreTheInteractionShare(*m, fb, ff, forces);
  EXPECT_GT(forces[0][2], 0.0);  // the bodies attract: the lower one is pulled up
  EXPECT_LT(forces[1][2], 0.0);
  const Real err = tangentError(full, u, 1e-6);
  std::printf("[interaction part] two boxes 0.3 apart: forces %.4e, %.4e; max|J - J_fd|/max|J| = %.2e\n",
              forces[0][2], forces[1][2], err);
  EXPECT_LT(err, 1e-6);
}

// Two boxes 0.3 apart (the same mesh for both problems): `bulk` without interaction, `full` with
// Method 1 (orders 1 .. 2, cutoff 1, skin 0.2, search radius factor 1.5).
struct TwoBoxesMethod1 {
  std::shared_ptr<mesh::Mesh> m = twoBoxes(0.3);
  Teuchos::RCP<DofMap> dofs = Teuchos::rcp(new DofMap(Tpetra::getDefaultComm(), *m, 3));
  material::NeoHookean mat = material::NeoHookean::fromYoungPoisson(1.0, 0.3);
  Problem bulk{dofs, m, Formulation::ThreeD, mat}, full{dofs, m, Formulation::ThreeD, mat};
  TwoBoxesMethod1() {
    interaction::VolumeInteractionOptions o;
    o.formulation = Formulation::ThreeD;
    o.quadratureOrder = 1;
    o.maxQuadratureOrder = 2;
    o.cutoff = 1.0;
    o.skin = 0.2;
    full.setInteraction(std::make_shared<interaction::VolumeInteraction>(
                            *m, std::vector<Real>{1.0, 1.0}, interaction::makePotential("lennard-jones", 10.0, 0.25), o),
                        1.5);
  }
};

TEST(VolumeInteractionPart, CoupledTangentAndBalancedForces) {
  if (Tpetra::getDefaultComm()->getSize() > 1) GTEST_SKIP() << "one rank";
  TwoBoxesMethod1 t;
  auto& [m, dofs, mat, bulk, full] = t;
  EXPECT_NEAR(full.searchRadius(), 1.0 + 1.5 * 0.2, 1e-15);  // cutoff + factor x skin
  ASSERT_NE(full.volumeInteraction(), nullptr);
  const auto u = randomDisplacement(3 * std::size_t(m->numNodes()), 0.02, 17);
  Vector uv(dofs->ownedMap());
  fromStd(u, uv);
  EXPECT_TRUE(full.updateInteractionGraph(uv));
  const auto fb = residual(bulk, u), ff = residual(full, u);
  const auto forces = full.interactionForces();
  ASSERT_EQ(forces.size(), 2u);
  expectForcesAreTheInteractionShare(*m, fb, ff, forces);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(forces[0][i] + forces[1][i], 0.0, 1e-13 * std::abs(forces[0][2]));
  EXPECT_GT(forces[0][2], 0.0);  // the bodies attract
  const Real err = tangentError(full, u, 1e-6);
  std::printf("[volume interaction part] two boxes 0.3 apart: forces %.4e, %.4e; max|J - J_fd|/max|J| = %.2e\n",
              forces[0][2], forces[1][2], err);
  EXPECT_LT(err, 1e-6);
}

TEST(Problem, IsTheSumOfItsParts) {
  if (Tpetra::getDefaultComm()->getSize() > 1) GTEST_SKIP() << "one rank";
  TwoBodies t(13);
  auto& [m, dofs, mat, bulk, full, si, u] = t;
  const auto fb = residual(bulk, u), ff = residual(full, u);
  // the interaction evaluated alone, outside Tpetra, on the mesh's surfaces and numbering (the problem's
  // holds its surfaces in a numbering of its own)
  const auto alone = methodThree(*m);
  std::vector<Real> x(m->coords);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] += u[i];
  std::vector<interaction::PairContribution> c;
  alone->updatePairs(x);
  alone->evaluate(x, c, false);
  std::vector<Real> fi(x.size(), 0.0);
  for (const auto& p : c)
    for (int a = 0; a < p.numRowNodes; ++a)
      for (int i = 0; i < 3; ++i) fi[3 * std::size_t(p.rowNodes[a]) + i] += p.f[3 * a + i];
  Real fmax = 0.0, scale = 0.0, worst = 0.0;
  for (std::size_t i = 0; i < ff.size(); ++i) {
    fmax = std::max(fmax, std::abs(fi[i]));
    scale = std::max({scale, std::abs(ff[i]), std::abs(fb[i])});
    worst = std::max(worst, std::abs(ff[i] - fb[i] - fi[i]));
  }
  ASSERT_GT(fmax, 1e-3 * scale);  // an interaction that matters next to the bulk
  EXPECT_LE(worst, 1e-13 * scale);
  // a problem without interaction has none of its parts
  EXPECT_FALSE(bulk.hasInteraction());
  EXPECT_EQ(bulk.volumeInteraction(), nullptr);
  EXPECT_TRUE(bulk.interactionForces().empty());
  EXPECT_EQ(bulk.searchRadius(), 0.0);
  Vector uv(dofs->ownedMap());
  fromStd(u, uv);
  EXPECT_EQ(bulk.interactionNodeForces(uv)->normInf(), 0.0);  // zero, on the owned map
}

// A dof's index by its mesh node: node * 3 + i (every rank holding the whole mesh).
std::size_t meshIndex(const DofMap& dofs, GlobalIndex dof) {
  return std::size_t(dofs.meshNodeOfDof(dof)) * 3 + std::size_t(dof % 3);
}

// A vector on the owned map gathered by mesh node on every rank.
std::vector<Real> gatherByMeshNode(const DofMap& dofs, const Vector& v) {
  const Map& owned = *dofs.ownedMap();
  std::vector<Real> local(owned.getGlobalNumElements(), 0.0), all(local.size(), 0.0);
  auto h = v.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (std::size_t lid = 0; lid < owned.getNodeNumElements(); ++lid)
    local[meshIndex(dofs, owned.getGlobalElement(LocalIndex(lid)))] = h(lid, 0);
  Teuchos::reduceAll(*dofs.comm(), Teuchos::REDUCE_SUM, int(local.size()), local.data(), all.data());
  return all;
}

Vector ownedByMeshNode(const DofMap& dofs, const std::vector<Real>& u) {
  Vector v(dofs.ownedMap());
  const Map& owned = *dofs.ownedMap();
  auto h = v.getLocalViewHost(Tpetra::Access::OverwriteAll);
  for (std::size_t lid = 0; lid < owned.getNodeNumElements(); ++lid)
    h(lid, 0) = u[meshIndex(dofs, owned.getGlobalElement(LocalIndex(lid)))];
  return v;
}

// Per body, the sum of the node forces over its nodes, against interactionForces() (relative to the
// largest component); returns the largest relative difference.
Real expectBodySumsAreTheInteractionForces(const mesh::Mesh& m, const std::vector<Real>& nodeForces,
                                           const std::vector<std::array<Real, 3>>& forces) {
  std::vector<int> nodeBody(std::size_t(m.numNodes()), -1);
  for (const auto& b : m.blocks)
    for (LocalIndex n : b.connectivity) nodeBody[std::size_t(n)] = b.body;
  std::vector<std::array<Real, 3>> sum(forces.size(), {0.0, 0.0, 0.0});
  for (std::size_t k = 0; k < nodeForces.size(); ++k) sum[std::size_t(nodeBody[k / 3])][k % 3] += nodeForces[k];
  Real scale = 0.0, worst = 0.0;
  for (const auto& f : forces)
    for (Real c : f) scale = std::max(scale, std::abs(c));
  EXPECT_GT(scale, 0.0);
  for (std::size_t b = 0; b < forces.size(); ++b)
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(sum[b][std::size_t(i)], forces[b][std::size_t(i)], 1e-10 * scale) << "body " << b << " component " << i;
      worst = std::max(worst, std::abs(sum[b][std::size_t(i)] - forces[b][std::size_t(i)]) / scale);
    }
  return worst;
}

// Method 3: the node forces of the part's residual are those of its pairs, evaluated one by one at the
// state of the last evaluation (what results.e wrote before; 1e-12), summed per body the forces on the
// bodies (1e-10), and the forces on the bodies are left as the evaluation gave them. 1 and 2 ranks.
TEST(InteractionPart, NodeForcesAreThoseOfThePairs) {
  auto m = twoBoxes(0.3);
  auto dofs = Teuchos::rcp(new DofMap(Tpetra::getDefaultComm(), *m, 3));
  Problem p(dofs, m, Formulation::ThreeD, material::NeoHookean::fromYoungPoisson(1.0, 0.3));
  const auto si = methodThree(*m);
  p.setInteraction(si, 1.5);
  const auto u = randomDisplacement(3 * std::size_t(m->numNodes()), 0.02, 29);
  Vector uv = ownedByMeshNode(*dofs, u), f(dofs->ownedMap());
  p.updateInteractionGraph(uv);
  p.evaluate(uv, f, nullptr);
  const auto evaluated = p.interactionForces();
  // the pairs of this rank's facets from the last evaluation, one by one, summed over the ranks
  // (the pairs' nodes are numbered as the surfaces the rank holds: their global ids are the mesh's nodes)
  const std::vector<Real>& x = *p.heldSurfaces(uv).coords;
  const GhostedSurfaces& held = p.surfaceInteractionPart()->held();
  std::vector<Real> local(3 * std::size_t(m->numNodes()), 0.0), pairs(local.size(), 0.0);
  interaction::PairContribution c;
  for (const auto& pair : si->pairs()) {
    si->evaluatePair(x.data(), pair, c, false);
    for (int a = 0; a < c.numRowNodes; ++a)
      for (int i = 0; i < 3; ++i)
        local[3 * std::size_t(held.globalNode(c.rowNodes[a])) + std::size_t(i)] -= c.f[3 * a + i];
  }
  Teuchos::reduceAll(*dofs->comm(), Teuchos::REDUCE_SUM, int(local.size()), local.data(), pairs.data());
  const std::vector<Real> nodeForces = gatherByMeshNode(*dofs, *p.interactionNodeForces(uv));
  Real scale = 0.0, worst = 0.0;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    scale = std::max(scale, std::abs(pairs[k]));
    worst = std::max(worst, std::abs(nodeForces[k] - pairs[k]));
  }
  ASSERT_GT(scale, 0.0);
  // one rank: the same sums in the same order, so bit for bit (results.e's fields unchanged); on several
  // ranks the export adds the shared nodes' shares in another order than the reduction
  if (dofs->comm()->getSize() == 1)
    EXPECT_EQ(worst, 0.0);
  else
    EXPECT_LE(worst, 1e-12 * scale);
  const auto after = p.interactionForces();
  ASSERT_EQ(after.size(), 2u);
  for (int b = 0; b < 2; ++b)
    for (int i = 0; i < 3; ++i) EXPECT_EQ(after[b][i], evaluated[b][i]);
  const Real sums = expectBodySumsAreTheInteractionForces(*m, nodeForces, after);
  std::printf("[node forces, Method 3] against the pairs: max|df|/max|f| = %.1e; body sums against the forces "
              "on the bodies: %.1e; %d rank(s)\n",
              worst / scale, sums, dofs->comm()->getSize());
}

// Method 1: the node forces are a body force (interior nodes within reach carry some), minus the part's
// share of the residual, and summed per body the forces on the bodies (1e-10). 1 and 2 ranks.
TEST(VolumeInteractionPart, NodeForcesAreABodyForceSummingToTheForcesOnTheBodies) {
  TwoBoxesMethod1 t;
  auto& [m, dofs, mat, bulk, full] = t;
  const auto u = randomDisplacement(3 * std::size_t(m->numNodes()), 0.02, 31);
  Vector uv = ownedByMeshNode(*dofs, u), fb(dofs->ownedMap()), ff(dofs->ownedMap());
  full.updateInteractionGraph(uv);
  bulk.evaluate(uv, fb, nullptr);
  full.evaluate(uv, ff, nullptr);
  const std::vector<Real> nodeForces = gatherByMeshNode(*dofs, *full.interactionNodeForces(uv));
  const std::vector<Real> share = [&] {
    const auto b = gatherByMeshNode(*dofs, fb), f = gatherByMeshNode(*dofs, ff);
    std::vector<Real> d(f.size());
    for (std::size_t k = 0; k < d.size(); ++k) d[k] = f[k] - b[k];
    return d;
  }();
  Real scale = 0.0, worst = 0.0;
  for (std::size_t k = 0; k < share.size(); ++k) {
    scale = std::max(scale, std::abs(nodeForces[k]));
    worst = std::max(worst, std::abs(nodeForces[k] + share[k]));
  }
  ASSERT_GT(scale, 0.0);
  EXPECT_LE(worst, 1e-10 * scale);  // the difference of two residuals: the bulk's round-off
  // on the interior nodes too: the centre node of each 2 x 2 x 2 box, 0.5 from its surface
  std::vector<char> onSurface(std::size_t(m->numNodes()), 0);
  for (const auto& s : m->surfaces)
    for (LocalIndex n : s.facets) onSurface[std::size_t(n)] = 1;
  int interiorLoaded = 0;
  for (LocalIndex n = 0; n < m->numNodes(); ++n)
    if (!onSurface[std::size_t(n)] && std::abs(nodeForces[3 * std::size_t(n) + 2]) > 1e-6 * scale) ++interiorLoaded;
  EXPECT_EQ(interiorLoaded, 2);
  const Real sums = expectBodySumsAreTheInteractionForces(*m, nodeForces, full.interactionForces());
  std::printf("[node forces, Method 1] against minus the part's share of f: max|df|/max|f| = %.1e; body sums "
              "against the forces on the bodies: %.1e; %d interior nodes loaded; %d rank(s)\n",
              worst / scale, sums, interiorLoaded, dofs->comm()->getSize());
}

// The lumped surface areas of a whole boundary add up to its area (ring areas in axisymmetry), a uniform
// traction t given as t times each node's area reads back as t on every surface node, with the pressure
// -t . n on a face, and nothing off the surfaces.
TEST(SurfaceTraction, LumpedAreasAndAUniformTraction) {
  struct Case {
    const char* name;
    mesh::Mesh mesh;
    Formulation formulation;
    Real area;          // of the whole boundary
    LocalIndex face;    // a node inside the top face (normal +y in 2D, +z in 3D)
  };
  mesh::RectangleSpec r;
  r.x0 = 1.0, r.lx = 1.0, r.ly = 2.0, r.nx = 2, r.ny = 4;  // node (i, j): j * 3 + i
  mesh::BoxSpec b;
  b.lx = 1.0, b.ly = 2.0, b.lz = 3.0, b.nx = 2, b.ny = 2, b.nz = 3;  // node (i, j, k): (k * 3 + j) * 3 + i
  mesh::BoxSpec t = b;
  t.tetrahedra = true;
  const LocalIndex top3 = (3 * 3 + 1) * 3 + 1;
  const Case cases[] = {
      {"plane strain", mesh::rectangle(r), Formulation::PlaneStrain, 6.0, 4 * 3 + 1},
      // inner and outer cylinders, two annuli
      {"axisymmetric", mesh::rectangle(r), Formulation::Axisymmetric, 2.0 * kPi * (1.0 * 2 + 2.0 * 2) + 2.0 * kPi * 3.0,
       4 * 3 + 1},
      {"3D hexahedra", mesh::box(b), Formulation::ThreeD, 2.0 * (1 * 2 + 2 * 3 + 1 * 3), top3},
      {"3D tetrahedra", mesh::box(t), Formulation::ThreeD, 2.0 * (1 * 2 + 2 * 3 + 1 * 3), top3}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const mesh::Mesh& m = c.mesh;
    const int d = m.dim;
    const std::vector<Real> zero(m.coords.size(), 0.0);
    const auto areas = surfaceTractions(m, c.formulation, zero, zero).area;
    Real total = 0.0;
    for (Real a : areas) total += a;
    EXPECT_NEAR(total, c.area, 1e-12 * c.area);
    const Real traction[3] = {0.3, -0.7, 0.2};
    std::vector<Real> force(m.coords.size());
    for (std::size_t k = 0; k < force.size(); ++k) force[k] = traction[k % std::size_t(d)] * areas[k / std::size_t(d)];
    const auto s = surfaceTractions(m, c.formulation, zero, force);
    std::vector<char> onSurface(std::size_t(m.numNodes()), 0);
    for (const auto& surface : m.surfaces)
      for (LocalIndex n : surface.facets) onSurface[std::size_t(n)] = 1;
    int interior = 0;
    for (LocalIndex n = 0; n < m.numNodes(); ++n) {
      if (!onSurface[std::size_t(n)]) {
        ++interior;
        EXPECT_EQ(areas[std::size_t(n)], 0.0);
        EXPECT_EQ(s.pressure[std::size_t(n)], 0.0);
        for (int i = 0; i < d; ++i) EXPECT_EQ(s.traction[d * std::size_t(n) + std::size_t(i)], 0.0);
        continue;
      }
      for (int i = 0; i < d; ++i) EXPECT_NEAR(s.traction[d * std::size_t(n) + std::size_t(i)], traction[i], 1e-14);
    }
    EXPECT_GT(interior, 0);
    ASSERT_TRUE(onSurface[std::size_t(c.face)]);
    ASSERT_EQ(m.coord(c.face, d - 1), d == 2 ? 2.0 : 3.0);  // on the top face
    EXPECT_NEAR(s.pressure[std::size_t(c.face)], -traction[d - 1], 1e-14);
  }
}

// On quadratic 3D facets the traction is the one whose consistent node forces are the given ones:
// forces int N_a t(x) da of a linear traction field t(x) over the facets of a distorted box (curved
// facets) read back as t at every surface node (TETRA10, HEX27, HEX20). The forces are integrated with
// the projection's rule (4 points per direction): with 5 the two differ by the quadrature error of the
// curved area element, 4e-11 .. 7e-10 of t here. The facets' lumped areas still add up to the
// boundary's area.
TEST(SurfaceTraction, QuadraticFacetsReadBackALinearTraction) {
  for (const auto& [tets, serendipity] : {std::pair{true, false}, std::pair{false, false}, std::pair{false, true}}) {
    mesh::BoxSpec b;
    b.lx = 1.0, b.ly = 2.0, b.lz = 3.0, b.nx = 2, b.ny = 2, b.nz = 3;
    b.tetrahedra = tets;
    b.element.order = 2;
    b.element.serendipity = serendipity;
    mesh::Mesh m = mesh::box(b);
    SCOPED_TRACE(mesh::cellTypeName(m.blocks.at(0).type));
    std::vector<Real> u(m.coords.size(), 0.0);
    for (LocalIndex n = 0; n < m.numNodes(); ++n) {  // a smooth bulge: the facets curve
      const Real x = m.coord(n, 0), y = m.coord(n, 1), z = m.coord(n, 2);
      u[3 * std::size_t(n)] = 0.05 * std::sin(1.3 * y + 0.7 * z);
      u[3 * std::size_t(n) + 1] = 0.04 * std::cos(0.9 * x + 0.5 * z);
      u[3 * std::size_t(n) + 2] = 0.03 * std::sin(1.1 * x + 0.8 * y);
    }
    auto t = [](const Real* x, int i) {  // a linear traction field
      const Real t0[3] = {0.3, -0.7, 0.2}, G[3][3] = {{0.1, -0.2, 0.05}, {0.0, 0.3, -0.1}, {0.2, 0.1, -0.15}};
      return t0[i] + G[i][0] * x[0] + G[i][1] * x[1] + G[i][2] * x[2];
    };
    std::vector<Real> force(m.coords.size(), 0.0);
    for (const auto& surface : m.surfaces) {
      const int npf = surface.nodesPerFacet;
      ASSERT_GT(npf, 4);
      for (LocalIndex f = 0; f < surface.numFacets(); ++f) {
        const LocalIndex* n = &surface.facets[std::size_t(f) * npf];
        for (const interaction::FacetPoint& q : interaction::facetQuadrature(npf, 4)) {
          Real x[3] = {}, g[2][3] = {};
          for (int a = 0; a < npf; ++a)
            for (int i = 0; i < 3; ++i) {
              const Real xa = m.coord(n[a], i) + u[3 * std::size_t(n[a]) + i];
              x[i] += q.N[a] * xa;
              g[0][i] += q.dN[0][a] * xa;
              g[1][i] += q.dN[1][a] * xa;
            }
          const Real c[3] = {g[0][1] * g[1][2] - g[0][2] * g[1][1], g[0][2] * g[1][0] - g[0][0] * g[1][2],
                             g[0][0] * g[1][1] - g[0][1] * g[1][0]};
          const Real da = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) * q.weight;
          for (int a = 0; a < npf; ++a)
            for (int i = 0; i < 3; ++i) force[3 * std::size_t(n[a]) + i] += q.N[a] * t(x, i) * da;
        }
      }
    }
    const auto s = surfaceTractions(m, Formulation::ThreeD, u, force);
    Real worst = 0.0;
    for (const auto& surface : m.surfaces)
      for (LocalIndex n : surface.facets) {
        Real x[3];
        for (int i = 0; i < 3; ++i) x[i] = m.coord(n, i) + u[3 * std::size_t(n) + i];
        for (int i = 0; i < 3; ++i) worst = std::max(worst, std::abs(s.traction[3 * std::size_t(n) + i] - t(x, i)));
      }
    EXPECT_LT(worst, 1e-12);  // the CG solve's tolerance, 1e-14 of the forces, times the mass matrix's condition
    Real total = 0.0;
    for (Real a : surfaceTractions(m, Formulation::ThreeD, std::vector<Real>(m.coords.size(), 0.0), force).area) total += a;
    EXPECT_NEAR(total, 2.0 * (1 * 2 + 2 * 3 + 1 * 3), 1e-12 * 22.0);
  }
}

// What one evaluation of the two boxes with Method 3 gives, gathered over the ranks: the residual, the
// tangent (dense), the rigid-body modes and the forces on the bodies. Entries are indexed by `index` of a
// dof, u given the same way.
struct Gathered {
  std::vector<Real> f, J, modes;
  std::vector<std::array<Real, 3>> forces;
};

using DofIndex = std::function<std::size_t(const DofMap&, GlobalIndex)>;
// node * 3 + i by the node's index in the mesh
const DofIndex byMeshNode = [](const DofMap& dofs, GlobalIndex dof) {
  return std::size_t(dofs.meshNodeOfDof(dof)) * 3 + std::size_t(dof % 3);
};
// the dof's global index: the whole mesh's node * 3 + i, also in a rank's part
const DofIndex byGlobalId = [](const DofMap&, GlobalIndex dof) { return std::size_t(dof); };

Gathered evaluateGathered(const std::shared_ptr<mesh::Mesh>& m, Teuchos::RCP<DofMap> dofs, const std::vector<Real>& u,
                          const DofIndex& dofIndex) {
  auto comm = Tpetra::getDefaultComm();
  Problem p(dofs, m, Formulation::ThreeD, material::NeoHookean::fromYoungPoisson(1.0, 0.3));
  p.setInteraction(methodThree(*m), 1.5);
  const Map& owned = *dofs->ownedMap();
  const std::size_t n = u.size(), numOwned = owned.getNodeNumElements();
  auto index = [&](GlobalIndex dof) { return dofIndex(*dofs, dof); };
  Vector uv(dofs->ownedMap()), fv(dofs->ownedMap());
  {
    auto h = uv.getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (std::size_t lid = 0; lid < numOwned; ++lid) h(lid, 0) = u[index(owned.getGlobalElement(LocalIndex(lid)))];
  }
  EXPECT_TRUE(p.updateInteractionGraph(uv));
  auto J = p.createMatrix();
  p.evaluate(uv, fv, J.get());
  const auto modes = rigidBodyModes(*dofs, *m, Formulation::ThreeD);
  std::vector<Real> f(n, 0.0), K(n * n, 0.0), R(6 * n, 0.0);
  auto fh = fv.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto mh = modes->getLocalViewHost(Tpetra::Access::ReadOnly);
  for (std::size_t lid = 0; lid < numOwned; ++lid) {
    const std::size_t row = index(owned.getGlobalElement(LocalIndex(lid)));
    f[row] = fh(lid, 0);
    for (int k = 0; k < 6; ++k) R[6 * row + k] = mh(lid, k);
    Matrix::nonconst_local_inds_host_view_type cols("cols", J->getNumEntriesInLocalRow(LocalIndex(lid)));
    Matrix::nonconst_values_host_view_type vals("vals", cols.extent(0));
    std::size_t count = 0;
    J->getLocalRowCopy(LocalIndex(lid), cols, vals, count);
    for (std::size_t k = 0; k < count; ++k) K[row * n + index(J->getColMap()->getGlobalElement(cols(k)))] += vals(k);
  }
  Gathered out{std::vector<Real>(n), std::vector<Real>(n * n), std::vector<Real>(6 * n), p.interactionForces()};
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, int(n), f.data(), out.f.data());
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, int(n * n), K.data(), out.J.data());
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, int(6 * n), R.data(), out.modes.data());
  return out;
}

Real maxAbsDifference(const std::vector<Real>& a, const std::vector<Real>& b, Real& scale) {
  Real worst = 0.0;
  scale = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    worst = std::max(worst, std::abs(a[i] - b[i]));
    scale = std::max(scale, std::abs(a[i]));
  }
  return worst;
}

// b gives what a gives: residual, tangent and forces to 1e-13, rigid-body modes to 1e-14, with an
// interaction that is there. Returns max |df| and max |dJ|.
std::pair<Real, Real> expectSameEvaluation(const Gathered& a, const Gathered& b) {
  Real fScale = 0.0, jScale = 0.0, modeScale = 0.0;
  const Real fDiff = maxAbsDifference(a.f, b.f, fScale), jDiff = maxAbsDifference(a.J, b.J, jScale),
             modeDiff = maxAbsDifference(a.modes, b.modes, modeScale);
  EXPECT_LE(fDiff, 1e-13 * fScale);
  EXPECT_LE(jDiff, 1e-13 * jScale);
  EXPECT_LE(modeDiff, 1e-14 * modeScale);
  EXPECT_EQ(a.forces.size(), 2u);
  EXPECT_EQ(b.forces.size(), 2u);
  if (a.forces.size() != 2u || b.forces.size() != 2u) return {fDiff, jDiff};
  EXPECT_GT(a.forces[0][2], 0.0);  // the interaction is there
  for (int body = 0; body < 2; ++body)
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(b.forces[body][i], a.forces[body][i], 1e-13 * std::abs(a.forces[0][2]));
  return {fDiff, jDiff};
}

// A node's global id only labels its dofs: the two boxes with their nodes given shuffled ids give, node by
// node, the residual, tangent, interaction forces and rigid-body modes of the plain numbering (1 and 2 ranks).
TEST(DofMap, NodeIdsOnlyLabelTheDofs) {
  auto plain = twoBoxes(0.3);
  auto shuffled = std::make_shared<mesh::Mesh>(*plain);
  shuffled->nodeIds.resize(plain->numNodes());
  std::iota(shuffled->nodeIds.begin(), shuffled->nodeIds.end(), GlobalIndex(0));
  std::shuffle(shuffled->nodeIds.begin(), shuffled->nodeIds.end(), std::mt19937(3));
  ASSERT_NE(shuffled->nodeIds.front(), 0);
  const auto u = randomDisplacement(3 * std::size_t(plain->numNodes()), 0.02, 19);
  auto comm = Tpetra::getDefaultComm();
  const Gathered a = evaluateGathered(plain, Teuchos::rcp(new DofMap(comm, *plain, 3)), u, byMeshNode),
                 b = evaluateGathered(shuffled, Teuchos::rcp(new DofMap(comm, *shuffled, 3)), u, byMeshNode);
  const auto [fDiff, jDiff] = expectSameEvaluation(a, b);
  std::printf("[node ids] shuffled against plain: |df| %.1e, |dJ| %.1e, %d rank(s)\n", fDiff, jDiff,
              Tpetra::getDefaultComm()->getSize());
}

// Each rank holding only its part of the mesh (its cells, the nodes they touch and their facets; the
// other ranks' facets near them as ghosts) assembles what the ranks holding it whole assemble: the same
// dof distribution, residual, tangent, interaction forces and rigid-body modes, on 1 and 2 ranks.
TEST(DofMap, RanksHoldingTheirPartsAssembleWhatTheWholeMeshGives) {
  auto comm = Tpetra::getDefaultComm();
  auto whole = twoBoxes(0.3, 4);  // interior nodes: a rank's part leaves out those of the other's cells
  auto wholeDofs = Teuchos::rcp(new DofMap(comm, *whole, 3));
  const auto owners = partitionCells(*comm, *whole, CellPartition::Geometric);
  auto part = std::make_shared<mesh::Mesh>(mesh::subdomain(*whole, owners, comm->getRank()));
  auto partDofs = Teuchos::rcp(new DofMap(comm, *part, 3, CellPartition::Subdomain));
  EXPECT_TRUE(partDofs->ownedMap()->isSameAs(*wholeDofs->ownedMap()));
  EXPECT_TRUE(partDofs->overlapMap()->isSameAs(*wholeDofs->overlapMap()));
  LocalIndex partCells = 0;
  for (std::size_t b = 0; b < part->blocks.size(); ++b) partCells += LocalIndex(partDofs->localCells(b).size());
  EXPECT_EQ(partCells, part->numCells());
  if (comm->getSize() > 1) {
    EXPECT_LT(part->numCells(), whole->numCells());
    EXPECT_LT(part->numNodes(), whole->numNodes());
  }
  ASSERT_EQ(part->surfaces.size(), whole->surfaces.size());
  for (std::size_t s = 0; s < part->surfaces.size(); ++s) {  // each facet on one rank: its cell's
    int facets = int(part->surfaces[s].numFacets()), all = 0;
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, facets, Teuchos::outArg(all));
    EXPECT_EQ(all, whole->surfaces[s].numFacets());
  }

  const auto u = randomDisplacement(3 * std::size_t(whole->numNodes()), 0.02, 23);
  const Gathered a = evaluateGathered(whole, wholeDofs, u, byGlobalId), b = evaluateGathered(part, partDofs, u, byGlobalId);
  const auto [fDiff, jDiff] = expectSameEvaluation(a, b);
  std::printf("[local part] rank %d holds %d of %d cells, %d of %d nodes: |df| %.1e, |dJ| %.1e\n", comm->getRank(),
              part->numCells(), whole->numCells(), part->numNodes(), whole->numNodes(), fDiff, jDiff);
}

// The residual and tangent of a problem on the owned rows, gathered on every rank by the dof's global
// index (dense).
std::pair<std::vector<Real>, std::vector<Real>> gatherResidualAndTangent(Problem& p, const Vector& u, std::size_t n) {
  const Map& owned = *p.dofs().ownedMap();
  Vector f(p.dofs().ownedMap());
  auto J = p.createMatrix();
  p.evaluate(u, f, J.get());
  std::vector<Real> fl(n, 0.0), Kl(n * n, 0.0), fa(n, 0.0), Ka(n * n, 0.0);
  auto fh = f.getLocalViewHost(Tpetra::Access::ReadOnly);
  for (std::size_t lid = 0; lid < owned.getNodeNumElements(); ++lid) {
    const auto row = std::size_t(owned.getGlobalElement(LocalIndex(lid)));
    fl[row] = fh(lid, 0);
    Matrix::nonconst_local_inds_host_view_type cols("cols", J->getNumEntriesInLocalRow(LocalIndex(lid)));
    Matrix::nonconst_values_host_view_type vals("vals", cols.extent(0));
    std::size_t count = 0;
    J->getLocalRowCopy(LocalIndex(lid), cols, vals, count);
    for (std::size_t k = 0; k < count; ++k)
      Kl[row * n + std::size_t(J->getColMap()->getGlobalElement(cols(k)))] += vals(k);
  }
  const Teuchos::Comm<int>& comm = *p.dofs().comm();
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, int(n), fl.data(), fa.data());
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, int(n * n), Kl.data(), Ka.data());
  return {fa, Ka};
}

// Each rank holds its own facets and the other ranks' facets near them: two boxes approaching each
// other (the upper one moved down rigidly, with a small random field on top) from beyond the ghosts'
// radius to within 2.5 r0. At every state the interaction's residual and tangent assembled from the ranks'
// parts are those of the whole surfaces evaluated alone on the mesh's numbering (1e-12 of the largest
// entry: the same pairs summed in another order), the ghosts are gathered anew as the gap closes, and a
// rank holds no ghosts while the bodies are far apart and never the whole other surface. 1 and 2 ranks.
TEST(GhostedSurfaces, AnApproachGathersAnewAndAssemblesWhatTheWholeSurfacesGive) {
  auto comm = Tpetra::getDefaultComm();
  const auto whole = twoBoxes(0.5, 4);
  const auto owners = partitionCells(*comm, *whole, CellPartition::Geometric);
  auto part = std::make_shared<mesh::Mesh>(mesh::subdomain(*whole, owners, comm->getRank()));
  auto dofs = Teuchos::rcp(new DofMap(comm, *part, 3, CellPartition::Subdomain));
  interaction::SurfaceInteractionOptions o;
  o.formulation = Formulation::ThreeD;
  o.quadraturePoints = 2;
  o.cutoff = 0.1;  // 5 r0; the search radius 0.15, the ghosts' radius about 0.3
  // the closest triangle alone: the boxes' sharp edges put points beyond a convex edge, where the 3D blend's
  // offset penalty (o^2/delta, o up to the cells' size) would favour a triangle beyond the cutoff
  o.projectionSmoothing = 0.0;
  const auto potential = interaction::makePotential("lennard-jones", 1e5, 0.02);  // forces as large as the bulk's
  auto make = [&](const mesh::Mesh& m) {
    return std::make_shared<interaction::SurfaceInteraction>(m.surfaces, std::vector<Real>{1.0, 1.0}, potential, o);
  };
  const auto mat = material::NeoHookean::fromYoungPoisson(1.0, 0.3);
  Problem bulk(dofs, part, Formulation::ThreeD, mat), full(dofs, part, Formulation::ThreeD, mat);
  full.setInteraction(make(*part), 1.5);
  const GhostedSurfaces& held = full.surfaceInteractionPart()->held();
  const auto alone = make(*whole);  // every facet, on every rank

  const std::size_t n = 3 * std::size_t(whole->numNodes());
  const auto wiggle = randomDisplacement(n, 0.002, 41);
  long upperFacets = whole->surfaces[1].numFacets(), lowerFacets = whole->surfaces[0].numFacets();
  Real largest = 0.0;
  for (const Real drop : {0.0, 0.1, 0.2, 0.3, 0.38, 0.42, 0.44, 0.45}) {
    SCOPED_TRACE(drop);
    std::vector<Real> u(wiggle);
    for (const auto& b : whole->blocks)
      if (b.body == 1)
        for (LocalIndex node : b.connectivity) u[3 * std::size_t(node) + 2] = wiggle[3 * std::size_t(node) + 2] - drop;
    Vector uv(dofs->ownedMap());
    {
      auto h = uv.getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (std::size_t lid = 0; lid < uv.getMap()->getNodeNumElements(); ++lid)
        h(lid, 0) = u[std::size_t(uv.getMap()->getGlobalElement(LocalIndex(lid)))];
    }
    // the whole surfaces alone, scattered by mesh node (= global id)
    std::vector<Real> x(whole->coords), fr(n, 0.0), Kr(n * n, 0.0);
    for (std::size_t i = 0; i < n; ++i) x[i] += u[i];
    std::vector<interaction::PairContribution> c;
    alone->updatePairs(x);
    alone->evaluate(x, c, true);
    for (const auto& pc : c)
      for (int a = 0; a < pc.numRowNodes; ++a)
        for (int i = 0; i < 3; ++i) {
          const std::size_t row = 3 * std::size_t(pc.rowNodes[a]) + std::size_t(i);
          fr[row] += pc.f[3 * a + i];
          for (int b = 0; b < pc.numColNodes; ++b)
            for (int j = 0; j < 3; ++j)
              Kr[row * n + 3 * std::size_t(pc.colNodes[b]) + std::size_t(j)] += pc.K[3 * a + i][3 * b + j];
        }
    full.updateInteractionGraph(uv);
    const auto [fb, Kb] = gatherResidualAndTangent(bulk, uv, n);
    const auto [ff, Kf] = gatherResidualAndTangent(full, uv, n);  // throws if the tangent left the graph
    // against the largest entry of either part (the difference full - bulk rounds at the bulk's size)
    Real fScale = 0.0, kScale = 0.0, fWorst = 0.0, kWorst = 0.0, fInteraction = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      fInteraction = std::max(fInteraction, std::abs(fr[i]));
      fScale = std::max({fScale, std::abs(fr[i]), std::abs(fb[i])});
      fWorst = std::max(fWorst, std::abs(ff[i] - fb[i] - fr[i]));
    }
    for (std::size_t k = 0; k < n * n; ++k) {
      kScale = std::max({kScale, std::abs(Kr[k]), std::abs(Kb[k])});
      kWorst = std::max(kWorst, std::abs(Kf[k] - Kb[k] - Kr[k]));
    }
    EXPECT_LE(fWorst, 1e-12 * fScale);
    EXPECT_LE(kWorst, 1e-12 * kScale);
    largest = std::max(largest, fInteraction / fScale);
    long ghosts = held.numGhostFacets(), all = 0, gathers = held.numGathers();
    Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, ghosts, Teuchos::outArg(all));
    if (comm->getSize() == 1) {
      EXPECT_EQ(all, 0);
      EXPECT_EQ(gathers, 0);
    } else if (drop == 0.0) {
      EXPECT_EQ(all, 0);  // 0.5 apart: no facet of the other body within the ghosts' radius
      EXPECT_EQ(gathers, 1);
    } else if (drop == 0.45) {
      EXPECT_GT(ghosts, 0);
      EXPECT_LT(ghosts, (upperFacets + lowerFacets) / 2);  // the facing sides and the sides' lower rows
      EXPECT_GE(gathers, 3);
    }
    std::printf("[ghosts] gap %.2f: rank %d holds %ld ghost facets (%ld on all ranks), gathered %ld times; "
                "interaction %.1e, |df| %.1e of %.1e, |dK| %.1e of %.1e\n",
                0.5 - drop, comm->getRank(), ghosts, all, gathers, fInteraction, fWorst, fScale, kWorst, kScale);
  }
  EXPECT_GT(largest, 0.1);  // the bodies did interact at the end, with forces that matter beside the bulk's
}

// The surfaces a rank holds cover a reach only while the bodies have moved less than half of what the
// ghosts' radius leaves beyond it; on one rank every facet is its own and they always do.
TEST(GhostedSurfaces, CoverAReachUntilTheBodiesMoveTooFar) {
  auto comm = Tpetra::getDefaultComm();
  const auto whole = twoBoxes(0.3, 2);
  const auto owners = partitionCells(*comm, *whole, CellPartition::Geometric);
  const mesh::Mesh part = mesh::subdomain(*whole, owners, comm->getRank());
  auto dofs = Teuchos::rcp(new DofMap(comm, part, 3, CellPartition::Subdomain));
  GhostedSurfaces held(dofs, part, 1.0);
  Vector u(dofs->ownedMap());
  held.update(u);
  const bool oneRank = comm->getSize() == 1;
  EXPECT_EQ(held.covers(0.1), oneRank);  // no ghosts gathered yet
  held.gather(u, comm->getRank() == 0 ? 0.4 : 0.3);  // the ranks ask for different radii: all hold the largest
  EXPECT_EQ(held.radius(), oneRank ? std::numeric_limits<Real>::infinity() : 0.4);
  EXPECT_TRUE(held.covers(0.4));
  u.putScalar(0.03);  // every node moves by 0.03 sqrt(3) = 0.052
  held.update(u);
  EXPECT_TRUE(held.covers(0.29));
  EXPECT_EQ(held.covers(0.3), oneRank);  // 0.3 + 2 x 0.052 > 0.4
  EXPECT_THROW(held.gather(u, -1.0), std::logic_error) << "a negative radius";
}

TEST(DofMap, NodeIdsAreCheckedForRepeatsAndGaps) {
  auto comm = Tpetra::getDefaultComm();
  auto m = twoBoxes(0.3);
  m->nodeIds.resize(m->numNodes());
  std::iota(m->nodeIds.begin(), m->nodeIds.end(), GlobalIndex(0));
  m->nodeIds[5] = m->nodeIds[4];  // repeated
  EXPECT_THROW(DofMap(comm, *m, 3), std::logic_error);
  std::iota(m->nodeIds.begin(), m->nodeIds.end(), GlobalIndex(0));
  m->nodeIds.back() += 10;  // a gap: output gathers by id
  EXPECT_THROW(DofMap(comm, *m, 3), std::logic_error);
  m->nodeIds.pop_back();  // not one per node
  EXPECT_THROW(DofMap(comm, *m, 3), std::logic_error);
}

}  // namespace
}  // namespace cgcm::assembly
