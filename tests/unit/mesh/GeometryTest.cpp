// The Geometry sublist belongs to the mesh package: each built-in geometry is
// a model with its conditions, responses and force scale; u = 0 puts the
// interacting surfaces the contact distance apart; P is the whole body's force.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "cgcm/core/Error.hpp"
#include "cgcm/io/Deck.hpp"
#include "cgcm/mesh/Geometry.hpp"

namespace cgcm::mesh {
namespace {

Model modelOf(Teuchos::ParameterList g, Formulation f, Real contactDistance = 0.01) {
  io::validateDeck(g, *validParameters(), "Geometry/");
  return buildModel(g, f, [contactDistance] { return contactDistance; });
}

TEST(Geometry, TheBenchmarkIsTwoInteractingBodiesTheContactDistanceApart) {
  for (const Formulation f : {Formulation::Axisymmetric, Formulation::PlaneStrain}) {
    SCOPED_TRACE(formulationName(f));
    const Real rS0 = 0.0137;
    const Model m = modelOf(Teuchos::ParameterList(), f, rS0);
    EXPECT_TRUE(m.interacting);
    EXPECT_EQ(m.mesh->numBodies, 2);
    ASSERT_TRUE(m.contact.has_value());
    const LocalIndex apex = m.mesh->nodeSet(m.contact->upperApex).front();
    const LocalIndex lower = m.mesh->nodeSet(m.contact->lowerApex).front();
    EXPECT_NEAR(m.mesh->coord(apex, 1) - m.mesh->coord(lower, 1), rS0, 1e-14);
    EXPECT_EQ(m.contact->contactDistance, rS0);
    EXPECT_EQ(m.force.nodeSet, "equator");
    EXPECT_EQ(m.force.sign, -1.0);  // P > 0 compressive
    ASSERT_TRUE(m.balance.has_value());
    EXPECT_EQ(m.forceScale(3.0), 3.0);  // Y R0^2 (Y R0 per unit thickness), R0 = 1
    // the whole body: the plane-strain models are halves (their axis a symmetry line)
    EXPECT_EQ(m.force.scale, f == Formulation::PlaneStrain ? 2.0 : 1.0);
    EXPECT_EQ(m.balance->scale, m.force.scale);
  }
  Teuchos::ParameterList big;
  big.set("Sphere Radius", 2.0);
  EXPECT_EQ(modelOf(big, Formulation::Axisymmetric).forceScale(1.0), 4.0);
  EXPECT_EQ(modelOf(big, Formulation::PlaneStrain).forceScale(1.0), 2.0);
  big.set("Type", std::string("sphere on sphere"));
  big.set("Second Sphere Radius", 6.0);
  EXPECT_DOUBLE_EQ(reducedRadius(big), 1.5);
}

// A rigid body: every node of it takes the condition its node sets carry in
// each component, and the forces measured on it sum over all its nodes.
TEST(Geometry, ARigidBodyFollowsItsConditionsWithEveryNode) {
  Model m = modelOf(Teuchos::ParameterList(), Formulation::Axisymmetric);
  const std::size_t before = m.conditions.size();
  const std::string forceSet = m.force.nodeSet, balanceSet = m.balance->nodeSet;
  makeRigid(m, 1, "half-space");  // held at its base, on the axis
  const std::string all = "half-space (all nodes)";
  ASSERT_EQ(m.conditions.size(), before + 2);
  for (int i = 0; i < 2; ++i) {
    const DisplacementCondition& c = m.conditions[before + std::size_t(i)];
    EXPECT_EQ(c.nodeSet, all);
    EXPECT_EQ(c.component, i);
    EXPECT_EQ(c.offset, 0.0);
    EXPECT_EQ(c.scale, 0.0);
  }
  // every node of the half-space's cells, and none of the sphere's
  std::vector<char> inBody(std::size_t(m.mesh->numNodes()), 0);
  for (const auto& b : m.mesh->blocks)
    for (LocalIndex n : b.connectivity) inBody[std::size_t(n)] |= char(b.body == 1 ? 1 : 2);
  const auto& nodes = m.mesh->nodeSet(all);
  EXPECT_EQ(nodes.size(), std::size_t(std::count(inBody.begin(), inBody.end(), 1)));
  for (LocalIndex n : nodes) EXPECT_EQ(inBody[std::size_t(n)], 1);
  EXPECT_EQ(m.force.nodeSet, forceSet);  // measured on the sphere, as before
  EXPECT_EQ(m.balance->nodeSet, all);    // on the half-space: its whole body
  // The driven sphere translates with the approach: its driven y-condition and the axis's x = 0.
  makeRigid(m, 0, "sphere");
  const DisplacementCondition& y = m.conditions.back();
  EXPECT_EQ(y.nodeSet, "sphere (all nodes)");
  EXPECT_EQ(y.component, 1);
  EXPECT_NE(y.scale, 0.0);
  EXPECT_EQ(m.force.nodeSet, "sphere (all nodes)");
  EXPECT_NE(balanceSet, m.balance->nodeSet);

  // measureOnWholeBody alone leaves the conditions as they are.
  Model stiff = modelOf(Teuchos::ParameterList(), Formulation::PlaneStrain);
  const std::size_t n = stiff.conditions.size();
  EXPECT_TRUE(measureOnWholeBody(stiff, 0, "sphere"));
  EXPECT_EQ(stiff.conditions.size(), n);
  EXPECT_EQ(stiff.force.nodeSet, "sphere (all nodes)");

  // A block held at one end and driven at the other cannot be rigid.
  Teuchos::ParameterList g;
  g.set("Type", std::string("block"));
  Model block = modelOf(g, Formulation::ThreeD);
  try {
    makeRigid(block, 0, "block");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("Bodies/block/Rigid: a rigid body moves as a whole, but its node sets"),
              std::string::npos)
        << e.what();
  }
}

TEST(Geometry, ABlockIsStretchedOnRollersAndDoesNotInteract) {
  Teuchos::ParameterList g;
  g.set("Type", std::string("block"));
  g.sublist("Block").set("Length X", 2.0);
  g.sublist("Block").set("Length Y", 3.0);
  const Model box = modelOf(g, Formulation::ThreeD);
  EXPECT_FALSE(box.interacting);
  EXPECT_EQ(box.forceScale(1.0), 6.0);  // the loaded face z = Lz
  EXPECT_EQ(box.force.scale, 1.0);     // a block is whole
  EXPECT_EQ(box.force.nodeSet, "zmax");
  EXPECT_EQ(box.conditions.size(), 4u);
  const Model axi = modelOf(g, Formulation::Axisymmetric);
  EXPECT_NEAR(axi.forceScale(1.0), kPi * 4.0, 1e-14);
  g.sublist("Block").set("Loaded Face", std::string("clamped"));
  EXPECT_EQ(modelOf(g, Formulation::PlaneStrain).conditions.size(), 4u);
  EXPECT_EQ(modelOf(g, Formulation::ThreeD).conditions.size(), 6u);
}

std::string inputErrorOf(Teuchos::ParameterList g, Formulation f) {
  try {
    modelOf(g, f);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no InputError";
}

TEST(Geometry, ABentBlockIsACantileverDrivenAtItsTipEdge) {
  Teuchos::ParameterList g;
  g.set("Type", std::string("block"));
  auto& b = g.sublist("Block");
  b.set("Load", std::string("bend"));
  b.set("Length X", 10.0);
  b.set("Cells X", 5);
  b.set("Cells Y", 2);
  b.set("Cells Z", 2);
  for (const Formulation f : {Formulation::PlaneStrain, Formulation::ThreeD})
    for (int order : {1, 2}) {
      SCOPED_TRACE(std::string(formulationName(f)) + " order " + std::to_string(order));
      g.set("Element Order", order);
      const Model m = modelOf(g, f);
      EXPECT_FALSE(m.interacting);
      const int last = f == Formulation::ThreeD ? 2 : 1;
      EXPECT_EQ(m.force.nodeSet, "tip");
      EXPECT_EQ(m.force.component, last);
      // the clamp: every component of x = 0; the drive: the tip edge across the strip
      int clamped = 0, driven = 0;
      for (const auto& c : m.conditions) {
        if (c.nodeSet == (f == Formulation::ThreeD ? "xmin" : "left") && c.scale == 0.0) ++clamped;
        if (c.nodeSet == "tip" && c.component == last && c.scale == 1.0) ++driven;
      }
      EXPECT_EQ(clamped, m.mesh->dim);
      EXPECT_EQ(driven, 1);
      EXPECT_EQ(m.conditions.size(), std::size_t(m.mesh->dim + 1));
      const auto& tip = m.mesh->nodeSet("tip");
      // 2D: the corner (Lx, 0); 3D: the edge x = Lx, z = 0 with 2 cells across (3 nodes, 5 at order 2)
      EXPECT_EQ(tip.size(), f == Formulation::ThreeD ? std::size_t(order == 1 ? 3 : 5) : 1u);
      for (LocalIndex n : tip) {
        EXPECT_EQ(m.mesh->coord(n, 0), 10.0);
        EXPECT_EQ(m.mesh->coord(n, last), 0.0);
      }
      EXPECT_EQ(cellTypeInfo(m.mesh->blocks[0].type).order, order);
    }
  EXPECT_NE(inputErrorOf(g, Formulation::Axisymmetric).find("Load = \"bend\" is a cantilever in plane strain or 3D"),
            std::string::npos);
  b.set("Loaded Face", std::string("clamped"));
  EXPECT_NE(inputErrorOf(g, Formulation::PlaneStrain).find("Loaded Face = \"clamped\" is for Load = \"stretch\""),
            std::string::npos);
}

TEST(Geometry, ElementOrderMakesQuadraticCellsOfEveryBuiltInGeometry) {
  for (const Formulation f : {Formulation::Axisymmetric, Formulation::PlaneStrain}) {
    Teuchos::ParameterList g;
    g.set("Element Order", 2);
    const Model m = modelOf(g, f);
    for (const auto& b : m.mesh->blocks) EXPECT_EQ(b.type, CellType::Quad9) << b.name;
    EXPECT_EQ(m.mesh->surfaces[0].nodesPerFacet, 3);
    g.set("Serendipity", true);
    const Model serendipity = modelOf(g, f);  // held: a range-for over a temporary's mesh would outlive it
    for (const auto& b : serendipity.mesh->blocks) EXPECT_EQ(b.type, CellType::Quad8) << b.name;
  }
  Teuchos::ParameterList g;
  g.set("Type", std::string("block"));
  g.set("Element Order", 2);
  EXPECT_EQ(modelOf(g, Formulation::ThreeD).mesh->blocks[0].type, CellType::Hex27);
  g.sublist("Block").set("Element", std::string("tet4"));
  EXPECT_EQ(modelOf(g, Formulation::ThreeD).mesh->blocks[0].type, CellType::Tet10);
  g.set("Element Order", 1);
  g.set("Serendipity", true);
  EXPECT_NE(inputErrorOf(g, Formulation::ThreeD).find("Geometry/Serendipity = true needs Geometry/Element Order = 2"),
            std::string::npos);
  g.set("Element Order", 3);
  EXPECT_THROW(io::validateDeck(g, *validParameters(), "Geometry/"), InputError);  // the validator: 1 .. 2
}

TEST(Geometry, TheSphereOnAHalfSpaceIsAHexahedralQuarterModelIn3D) {
  const Real rS0 = 0.0137;
  Teuchos::ParameterList g;
  g.set("Azimuthal Cells", 4);
  const Model m = modelOf(g, Formulation::ThreeD, rS0);
  EXPECT_TRUE(m.interacting);
  EXPECT_EQ(m.mesh->dim, 3);
  EXPECT_EQ(bodyNames(*m.mesh), (std::vector<std::string>{"sphere", "half-space"}));
  for (const auto& b : m.mesh->blocks) EXPECT_EQ(b.type, CellType::Hex8);
  ASSERT_TRUE(m.contact.has_value());
  const LocalIndex apex = m.mesh->nodeSet(m.contact->upperApex).front();
  const LocalIndex lower = m.mesh->nodeSet(m.contact->lowerApex).front();
  EXPECT_NEAR(m.mesh->coord(apex, 2) - m.mesh->coord(lower, 2), rS0, 1e-14);
  // the conventions of a gmsh mesh of the quarter (buildFromGmsh): "driven" moves by -u along z, the
  // sphere starts with it, "fixed" is held, the planes x = 0 and y = 0 are symmetry planes, P is
  // 4 x the resultant on "driven" (the whole sphere)
  EXPECT_EQ(m.force.nodeSet, "driven");
  EXPECT_EQ(m.force.component, 2);
  EXPECT_EQ(m.force.sign, -1.0);
  EXPECT_EQ(m.force.scale, 4.0);
  EXPECT_EQ(m.force.direction, (std::vector<Real>{0.0, 0.0, -1.0}));
  ASSERT_TRUE(m.balance.has_value());
  EXPECT_EQ(m.balance->nodeSet, "fixed");
  EXPECT_EQ(m.balance->scale, 4.0);
  EXPECT_EQ(m.forceScale(3.0), 3.0);
  std::vector<std::string> conditions;
  for (const auto& c : m.conditions)
    conditions.push_back(c.nodeSet + " " + std::to_string(c.component) + " " + std::to_string(c.scale));
  EXPECT_EQ(conditions,
            (std::vector<std::string>{"driven 2 -1.000000", "fixed 0 0.000000", "fixed 1 0.000000", "fixed 2 0.000000",
                                      "symmetry x 0 0.000000", "symmetry y 1 0.000000"}));
  ASSERT_EQ(m.initialMotion.size(), 1u);
  EXPECT_EQ(m.initialMotion[0].nodeSet, "driven body");
  EXPECT_EQ(m.report.size(), 1u);
  // order 2 meshes (the interaction refuses them before the mesh is made: the app's contact distance)
  g.set("Element Order", 2);
  g.set("Serendipity", true);
  const Model quadratic = modelOf(g, Formulation::ThreeD, rS0);
  for (const auto& b : quadratic.mesh->blocks) EXPECT_EQ(b.type, CellType::Hex20);
}

TEST(Geometry, TheBuiltInGeometriesIn3DRefuseWhatTheyCannotBuild) {
  Teuchos::ParameterList g;
  g.set("Type", std::string("sphere on sphere"));
  EXPECT_NE(inputErrorOf(g, Formulation::ThreeD).find("\"sphere on sphere\" is built in plane strain or axisymmetry"),
            std::string::npos);
  Teuchos::ParameterList odd;
  odd.set("Azimuthal Cells", 7);
  EXPECT_NE(inputErrorOf(odd, Formulation::ThreeD).find("Geometry/Azimuthal Cells = 7 is odd"), std::string::npos);
  // the widest zone builds (the meridian mesh's cells end at 45 degrees whatever the zone)
  Teuchos::ParameterList large;
  large.set("Contact Zone Size", 0.85);
  EXPECT_EQ(inputErrorOf(large, Formulation::ThreeD), "no InputError");
  // the core's radius, Azimuthal Cells x Contact Zone Size / 40: 64 x 0.65 / 40 = 1.04 sphere radii
  Teuchos::ParameterList wide;
  wide.set("Azimuthal Cells", 64);
  wide.set("Contact Zone Size", 0.65);
  const std::string error = inputErrorOf(wide, Formulation::ThreeD);
  EXPECT_NE(error.find("Geometry/Azimuthal Cells = 64 with Contact Zone Size = 0.65"), std::string::npos) << error;
  EXPECT_NE(error.find("at most 22 cells fit"), std::string::npos) << error;
  wide.set("Azimuthal Cells", 22);
  EXPECT_EQ(inputErrorOf(wide, Formulation::ThreeD), "no InputError");
}

}  // namespace
}  // namespace cgcm::mesh
