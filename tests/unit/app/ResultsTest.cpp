// results.e of a run read back (ExodusReader): element blocks, variable
// names, one step per load-curve row with the row's values, and the fields
// against the homogeneous solution of uniaxial compression; on the sphere
// benchmark the interaction traction where the bodies touch and, with either
// method, the nodal interaction force summed per body (body_forces.csv).
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "ClosedForm.hpp"
#include "cgcm/app/Setup.hpp"
#include "cgcm/app/Results.hpp"
#include "cgcm/app/Simulation.hpp"
#include "cgcm/io/Deck.hpp"
#include "cgcm/io/ExodusReader.hpp"
#include "cgcm/solver/Discretization.hpp"
#include "cgcm/solver/ModelEvaluator.hpp"

namespace cgcm {
namespace {

Teuchos::RCP<Teuchos::ParameterList> deck(const std::vector<std::string>& overrides) {
  auto d = Teuchos::rcp(new Teuchos::ParameterList("cgcm"));
  io::applyOverrides(*d, *app::validParameters(), overrides);
  io::validateDeck(*d, *app::validParameters());
  return d;
}

std::vector<std::string> csvHeader(const std::string& path) {
  std::ifstream in(path);
  std::string line, name;
  std::getline(in, line);
  std::vector<std::string> names;
  for (std::stringstream s(line); std::getline(s, name, ',');) names.push_back(name);
  return names;
}

double global(const io::ExodusReader& r, const std::string& name, int step) {
  const auto& names = r.globalNames();
  return r.globals(step).at(std::size_t(std::find(names.begin(), names.end(), name) - names.begin()));
}

// Per state of results.e, interaction_force_x/_y summed over each body's nodes against the body's row of
// body_forces.csv (relative to the largest component of the state: the file's 12 digits); returns the
// largest relative difference.
double expectBodySumsAreTheBodyForces(const io::ExodusReader& r, const mesh::Mesh& mesh, const std::string& dir) {
  std::vector<int> nodeBody(std::size_t(mesh.numNodes()), -1);
  for (const auto& b : mesh.blocks)
    for (LocalIndex n : b.connectivity) nodeBody[std::size_t(n)] = b.body;
  std::ifstream in(dir + "/body_forces.csv");
  std::string line;
  std::getline(in, line);  // step,u,body,Fx,Fy,Fz
  std::vector<std::array<double, 3>> rows;
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::string value;
    std::vector<double> v;
    while (std::getline(row, value, ',')) v.push_back(std::stod(value));
    rows.push_back({v.at(3), v.at(4), v.at(5)});
  }
  const int bodies = mesh.numBodies;
  EXPECT_EQ(rows.size(), std::size_t(r.numSteps() * bodies));
  double worst = 0.0;
  for (int s = 1; s <= r.numSteps() && rows.size() >= std::size_t(s * bodies); ++s) {
    const auto fx = r.nodal("interaction_force_x", s), fy = r.nodal("interaction_force_y", s);
    std::vector<std::array<double, 2>> sum(std::size_t(bodies), {0.0, 0.0});
    for (LocalIndex n = 0; n < mesh.numNodes(); ++n) {
      sum[std::size_t(nodeBody[std::size_t(n)])][0] += fx[std::size_t(n)];
      sum[std::size_t(nodeBody[std::size_t(n)])][1] += fy[std::size_t(n)];
    }
    double scale = 0.0;
    for (int b = 0; b < bodies; ++b)
      for (int i = 0; i < 2; ++i) scale = std::max(scale, std::abs(rows[std::size_t((s - 1) * bodies + b)][i]));
    EXPECT_GT(scale, 0.0);
    for (int b = 0; b < bodies; ++b)
      for (int i = 0; i < 2; ++i) {
        const double expected = rows[std::size_t((s - 1) * bodies + b)][std::size_t(i)];
        EXPECT_NEAR(sum[std::size_t(b)][std::size_t(i)], expected, 1e-10 * scale) << "step " << s << " body " << b;
        worst = std::max(worst, std::abs(sum[std::size_t(b)][std::size_t(i)] - expected) / scale);
      }
  }
  return worst;
}

TEST(Results, UniaxialCompressionFieldsAreTheHomogeneousSolution) {
  struct Case {
    std::string formulation, type;
    std::vector<std::string> stresses;
    int lateral;  // free lateral directions
  };
  const Case cases[] = {
      {"plane strain", "QUAD4", {"stress_xx", "stress_yy", "stress_zz", "stress_xy"}, 1},
      {"axisymmetric", "QUAD4", {"stress_rr", "stress_zz", "stress_tt", "stress_rz"}, 2},
      {"3D", "HEX8", {"stress_xx", "stress_yy", "stress_zz", "stress_xy", "stress_yz", "stress_xz"}, 2}};
  for (const auto& c : cases) {
    SCOPED_TRACE(c.formulation);
    const std::string dir = std::string(CGCM_TEST_OUTPUT) + "/results-" + c.formulation;
    auto d = deck({"Problem/Formulation=" + c.formulation, "Geometry/Type=block", "Geometry/Block/Cells X=2",
                   "Geometry/Block/Cells Y=3", "Geometry/Block/Cells Z=2", "Material/Poisson's Ratio=0.3",
                   "Loading/Approach Path={0, -0.3}", "Loading/Initial Increment=0.1", "Loading/Max Increment=0.1",
                   "Output/Print Steps=false", "Output/Directory=" + dir});
    std::ostringstream log;
    const auto run = app::runSimulation(Tpetra::getDefaultComm(), *d, log);
    ASSERT_TRUE(run.completed) << run.failure;
    if (Tpetra::getDefaultComm()->getRank() != 0) continue;

    const io::ExodusReader r(dir + "/results.e");
    const auto setup = app::buildProblem(*d);
    const auto& mesh = *setup.model.mesh;
    const int dim = mesh.dim, axis = dim - 1;
    ASSERT_EQ(r.blocks().size(), 1u);
    EXPECT_EQ(r.blocks()[0].name, "block");
    EXPECT_EQ(r.blocks()[0].type, c.type);
    EXPECT_EQ(r.numNodes(), mesh.numNodes());
    std::vector<std::string> nodal{"displacement_x", "displacement_y", "displacement_z"};
    nodal.resize(std::size_t(dim));
    EXPECT_EQ(r.nodalNames(), nodal);
    auto element = c.stresses;
    element.insert(element.end(), {"J", "von_mises"});
    EXPECT_EQ(r.elementNames(), element);
    EXPECT_EQ(r.globalNames(), csvHeader(dir + "/load_curve.csv"));
    ASSERT_EQ(r.numSteps(), int(run.curve.size()));

    for (int s = 1; s <= r.numSteps(); ++s) {
      const auto& row = run.curve[std::size_t(s - 1)];
      EXPECT_EQ(r.times()[std::size_t(s - 1)], s);
      EXPECT_EQ(global(r, "u", s), row.u);
      EXPECT_EQ(global(r, "P", s), row.P);
      // homogeneous: u_axis = u X_axis / L, u_lateral = (lateral stretch - 1) X
      double lateral = 1.0;
      const double sigma = test::uniaxialCauchyStress(setup.material, 1.0 + row.u, c.lateral, lateral);
      for (int i = 0; i < dim; ++i) {
        const auto u = r.nodal(nodal[std::size_t(i)], s);
        const bool loaded = i == axis;
        const bool free = !loaded && (c.formulation != "plane strain" || i == 0);
        for (LocalIndex n = 0; n < mesh.numNodes(); ++n) {
          const double expected = loaded ? row.u * mesh.coord(n, i) : (free ? (lateral - 1.0) : 0.0) * mesh.coord(n, i);
          ASSERT_NEAR(u[std::size_t(n)], expected, 1e-9) << nodal[std::size_t(i)] << " node " << n << " step " << s;
        }
      }
      const auto axial = r.element(c.formulation == "plane strain" ? "stress_yy" : "stress_zz", s);
      const auto J = r.element("J", s), mises = r.element("von_mises", s);
      const double expectedJ = (1.0 + row.u) * std::pow(lateral, c.lateral);
      for (std::size_t e = 0; e < J.size(); ++e) {
        EXPECT_NEAR(axial[e], sigma, 1e-9);
        EXPECT_NEAR(J[e], expectedJ, 1e-12);
        if (c.formulation != "plane strain") {
          EXPECT_NEAR(mises[e], std::abs(sigma), 1e-9);  // uniaxial stress
        }
      }
    }
  }
}

TEST(Results, InteractionTractionPressesWhereTheBodiesTouch) {
  const std::string dir = std::string(CGCM_TEST_OUTPUT) + "/results-sphere";
  auto d = io::readDeck(CGCM_DECK);
  io::applyOverrides(*d, *app::validParameters(),
                     {"Loading/Approach Path={-0.005, 0.02}", "Loading/Initial Increment=0.005",
                      "Loading/Max Increment=0.005", "Output/Print Steps=false", "Output/Directory=" + dir});
  io::validateDeck(*d, *app::validParameters());
  std::ostringstream log;
  const auto run = app::runSimulation(Tpetra::getDefaultComm(), *d, log);
  ASSERT_TRUE(run.completed) << run.failure;
  if (Tpetra::getDefaultComm()->getRank() != 0) return;
  ASSERT_GT(run.curve.back().P, 0.0);  // compressed at the end

  const io::ExodusReader r(dir + "/results.e");
  ASSERT_EQ(r.blocks().size(), 2u);
  EXPECT_EQ(r.blocks()[0].name, "sphere");
  EXPECT_EQ(r.blocks()[1].name, "half-space");
  ASSERT_EQ(r.sideSets().size(), 2u);
  EXPECT_EQ(r.sideSets()[0].name, "contact:sphere");
  EXPECT_EQ(r.nodalNames(), (std::vector<std::string>{"displacement_x", "displacement_y", "traction_x", "traction_y",
                                                      "pressure", "interaction_force_x", "interaction_force_y"}));
  const auto mesh = app::buildProblem(*d).model.mesh;
  const double sums = expectBodySumsAreTheBodyForces(r, *mesh, dir);
  std::printf("[results, Method 3] interaction_force summed per body against body_forces.csv: %.1e\n", sums);
  const int last = r.numSteps();
  const auto p = r.nodal("pressure", last), ty = r.nodal("traction_y", last);
  const LocalIndex apex = mesh->nodeSet("apex").front(), lowerApex = mesh->nodeSet("lower apex").front();
  EXPECT_GT(p[std::size_t(apex)], 0.0);
  EXPECT_GT(p[std::size_t(lowerApex)], 0.0);
  EXPECT_GT(ty[std::size_t(apex)], 0.0);        // the sphere is pushed up
  EXPECT_LT(ty[std::size_t(lowerApex)], 0.0);   // the half-space down
  for (LocalIndex n : mesh->nodeSet("lower bottom")) EXPECT_EQ(p[std::size_t(n)], 0.0);  // off the surfaces
  // the displacement of the driven equator is -u (the sphere's equator plane moves down by u)
  const auto uy = r.nodal("displacement_y", last);
  for (LocalIndex n : mesh->nodeSet("equator")) EXPECT_NEAR(uy[std::size_t(n)], -run.curve.back().u, 1e-14);
}

// Method 1 writes the same interaction fields: the nodal interaction force (a body force: interior nodes
// carry some; summed per body, body_forces.csv) and, from its surface nodes' share, the traction and
// pressure, finite, 0 off the surfaces, and adhesive (< 0) at the apices of the sphere near the half-space.
TEST(Results, MethodOneWritesTheInteractionTractionAndForce) {
  const std::string dir = std::string(CGCM_TEST_OUTPUT) + "/results-method1";
  auto d = io::readDeck(CGCM_DECK);
  io::applyOverrides(*d, *app::validParameters(),
                     {"Interaction/Method=volume pair", "Loading/Approach Path={-0.02, -0.016}",
                      "Output/Print Steps=false", "Output/Directory=" + dir});
  io::validateDeck(*d, *app::validParameters());
  std::ostringstream log;
  const auto run = app::runSimulation(Tpetra::getDefaultComm(), *d, log);
  ASSERT_TRUE(run.completed) << run.failure;
  if (Tpetra::getDefaultComm()->getRank() != 0) return;
  ASSERT_LT(run.curve.back().P, 0.0);  // apart, attracting

  const io::ExodusReader r(dir + "/results.e");
  EXPECT_EQ(r.nodalNames(), (std::vector<std::string>{"displacement_x", "displacement_y", "traction_x", "traction_y",
                                                      "pressure", "interaction_force_x", "interaction_force_y"}));
  const auto mesh = app::buildProblem(*d).model.mesh;
  std::vector<char> onSurface(std::size_t(mesh->numNodes()), 0);
  for (const auto& surface : mesh->surfaces)
    for (LocalIndex n : surface.facets) onSurface[std::size_t(n)] = 1;
  const int last = r.numSteps();
  const auto p = r.nodal("pressure", last), tx = r.nodal("traction_x", last), ty = r.nodal("traction_y", last);
  const auto fy = r.nodal("interaction_force_y", last);
  int interiorLoaded = 0;
  double fmax = 0.0;
  for (double f : fy) fmax = std::max(fmax, std::abs(f));
  ASSERT_GT(fmax, 0.0);
  for (LocalIndex n = 0; n < mesh->numNodes(); ++n) {
    const auto k = std::size_t(n);
    ASSERT_TRUE(std::isfinite(p[k]) && std::isfinite(tx[k]) && std::isfinite(ty[k]) && std::isfinite(fy[k]))
        << "node " << n;
    if (onSurface[k]) continue;
    EXPECT_EQ(p[k], 0.0) << "node " << n;
    EXPECT_EQ(tx[k], 0.0) << "node " << n;
    EXPECT_EQ(ty[k], 0.0) << "node " << n;
    interiorLoaded += std::abs(fy[k]) > 1e-6 * fmax;
  }
  EXPECT_GT(interiorLoaded, 0);  // a body force
  const LocalIndex apex = mesh->nodeSet("apex").front(), lowerApex = mesh->nodeSet("lower apex").front();
  EXPECT_LT(p[std::size_t(apex)], 0.0);  // adhesive
  EXPECT_LT(p[std::size_t(lowerApex)], 0.0);
  EXPECT_LT(ty[std::size_t(apex)], 0.0);       // the sphere is pulled down
  EXPECT_GT(ty[std::size_t(lowerApex)], 0.0);  // the half-space up
  const double sums = expectBodySumsAreTheBodyForces(r, *mesh, dir);
  std::printf("[results, Method 1] pressure at the apices %.4e, %.4e; %d interior nodes loaded; interaction_force "
              "summed per body against body_forces.csv: %.1e\n",
              p[std::size_t(apex)], p[std::size_t(lowerApex)], interiorLoaded, sums);
}

// Rank 0 receives the fields a window at a time: with windows of 1 kB (18 nodes or cells with their
// fields, dozens of windows per array of this mesh) the file is the one written with the default window
// (8 MiB: one window),
// mesh and fields entry by entry, on one rank or two (mpi_app_tests_np2; mpi_*_results_np1_vs_np2
// compare the files of one and two ranks).
TEST(Results, FileIsTheSameWhateverTheWindowRankZeroReceives) {
  const auto comm = Tpetra::getDefaultComm();
  const std::string dir = std::string(CGCM_TEST_OUTPUT) + "/results-window";
  auto d = io::readDeck(CGCM_DECK);
  io::applyOverrides(*d, *app::validParameters(), {"Output/Directory=" + dir});
  io::validateDeck(*d, *app::validParameters());
  auto setup = app::buildProblem(*comm, *d);
  const auto disc = solver::discretize(comm, setup, d->sublist("Solver").sublist("Linear Solver"));
  // a smooth displacement field, the interaction evaluated at it (traction, force), a critical mode
  assembly::Vector x(disc.dofs->ownedMap()), f(disc.dofs->ownedMap()), mode(disc.dofs->ownedMap());
  {
    auto hx = x.getLocalViewHost(Tpetra::Access::OverwriteAll);
    auto hm = mode.getLocalViewHost(Tpetra::Access::OverwriteAll);
    const auto& map = *disc.dofs->ownedMap();
    for (std::size_t lid = 0; lid < map.getNodeNumElements(); ++lid) {
      const GlobalIndex dof = map.getGlobalElement(LocalIndex(lid));
      const LocalIndex n = disc.dofs->meshNodeOfDof(dof);
      const int i = int(dof % 2);
      hx(lid, 0) = 1e-3 * std::sin(3.0 * disc.mesh->coord(n, 0) + i) * std::cos(2.0 * disc.mesh->coord(n, 1));
      hm(lid, 0) = std::cos(double(dof));
    }
  }
  std::vector<Real> p = disc.model->parameters();
  disc.model->evaluateUnconstrained(x, p, f);
  std::filesystem::create_directories(dir);
  for (const std::size_t bytes : {std::size_t(1024), solver::kRootStreamWindowBytes}) {
    app::ResultsWriter writer(dir + "/window-" + std::to_string(bytes) + ".e", disc, {"u"}, -1, true, bytes);
    writer.write(x, {0.5}, &mode);
    writer.write(x, {0.75}, nullptr);  // no mode: zero
  }
  if (comm->getRank() != 0) return;
  const std::string small = dir + "/window-1024.e", whole = dir + "/window-" + std::to_string(solver::kRootStreamWindowBytes) + ".e";
  const auto differences = io::compareExodus(small, whole, {0.0, 0.0, {}});
  EXPECT_TRUE(differences.empty()) << differences.front();
  const io::ExodusReader r(small);
  ASSERT_EQ(r.numSteps(), 2);
  EXPECT_EQ(r.numNodes(), long(setup.numNodes));
  EXPECT_EQ(r.numElements(), long(setup.numCells));
  double largest = 0.0;  // the pressure is not all zero: the interaction was written
  for (double v : r.nodal("pressure", 1)) largest = std::max(largest, std::abs(v));
  EXPECT_GT(largest, 0.0);
  for (double v : r.nodal("critical_mode_x", 2)) EXPECT_EQ(v, 0.0);
}

// The file numbers the nodes by global id (file node = id + 1), whatever the mesh's own order: a
// homogeneous stretch of a block whose nodes carry reversed ids reads back node by node at the ids, the
// coordinates and the cells relabelled with them, with the homogeneous J in every cell.
TEST(Results, FieldsFollowTheMeshNodesWhateverTheirIds) {
  // relabelled ids on a mesh every rank holds whole: one rank (several ranks assemble on parts, whose ids
  // are the whole mesh's)
  if (Tpetra::getDefaultComm()->getSize() > 1) GTEST_SKIP() << "one rank";
  const std::string dir = std::string(CGCM_TEST_OUTPUT) + "/results-node-ids";
  auto d = deck({"Problem/Formulation=3D", "Geometry/Type=block", "Geometry/Block/Cells X=2",
                 "Geometry/Block/Cells Y=3", "Geometry/Block/Cells Z=2", "Output/Directory=" + dir});
  auto setup = app::buildProblem(*d);
  auto& mesh = *setup.model.mesh;
  mesh.nodeIds.resize(std::size_t(mesh.numNodes()));
  for (LocalIndex n = 0; n < mesh.numNodes(); ++n) mesh.nodeIds[std::size_t(n)] = mesh.numNodes() - 1 - n;
  const auto disc = solver::discretize(Tpetra::getDefaultComm(), setup, d->sublist("Solver").sublist("Linear Solver"));
  const double stretch[3] = {0.01, 0.02, -0.03};
  assembly::Vector x(disc.dofs->ownedMap());
  {
    auto h = x.getLocalViewHost(Tpetra::Access::OverwriteAll);
    const auto& map = *disc.dofs->ownedMap();
    for (std::size_t lid = 0; lid < map.getNodeNumElements(); ++lid) {
      const GlobalIndex dof = map.getGlobalElement(LocalIndex(lid));
      const int i = int(dof % 3);
      h(lid, 0) = stretch[i] * mesh.coord(disc.dofs->meshNodeOfDof(dof), i);
    }
  }
  std::filesystem::create_directories(dir);
  {
    app::ResultsWriter writer(dir + "/results.e", disc, {"u"});
    writer.write(x, {0.0});
  }
  if (Tpetra::getDefaultComm()->getRank() != 0) return;
  const io::ExodusReader r(dir + "/results.e");
  ASSERT_EQ(r.numSteps(), 1);
  const char* names[3] = {"displacement_x", "displacement_y", "displacement_z"};
  for (int i = 0; i < 3; ++i) {
    const auto u = r.nodal(names[i], 1);
    const auto x = r.coordinates(i);
    for (LocalIndex n = 0; n < mesh.numNodes(); ++n) {
      const auto id = std::size_t(mesh.globalNode(n));
      ASSERT_EQ(x[id], mesh.coord(n, i)) << "node " << n;
      ASSERT_NEAR(u[id], stretch[i] * mesh.coord(n, i), 1e-15) << names[i] << " node " << n;
    }
  }
  const auto cells = r.connectivity(0);
  ASSERT_EQ(cells.size(), mesh.blocks[0].connectivity.size());
  for (std::size_t k = 0; k < cells.size(); ++k)
    ASSERT_EQ(cells[k], mesh.globalNode(mesh.blocks[0].connectivity[k]) + 1) << "entry " << k;
  for (double J : r.element("J", 1)) EXPECT_NEAR(J, 1.01 * 1.02 * 0.97, 1e-13);
}

}  // namespace
}  // namespace cgcm
