// The Geometry sublist belongs to the mesh package: each built-in geometry is
// a model with its conditions, responses and force scale; u = 0 puts the
// interacting surfaces the contact distance apart; P is the whole body's force.
#include <gtest/gtest.h>

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

TEST(Geometry, ElementOrderMakesQuadraticCellsOfEveryBuiltInGeometry) {
  for (const Formulation f : {Formulation::Axisymmetric, Formulation::PlaneStrain}) {
    Teuchos::ParameterList g;
    g.set("Element Order", 2);
    const Model m = modelOf(g, f);
    for (const auto& b : m.mesh->blocks) EXPECT_EQ(b.type, CellType::Quad9) << b.name;
    EXPECT_EQ(m.mesh->surfaces[0].nodesPerFacet, 3);
    g.set("Serendipity", true);
    for (const auto& b : modelOf(g, f).mesh->blocks) EXPECT_EQ(b.type, CellType::Quad8) << b.name;
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

TEST(Geometry, TheBuiltInContactGeometriesAreRefusedIn3D) {
  try {
    modelOf(Teuchos::ParameterList(), Formulation::ThreeD);
    ADD_FAILURE() << "a 3D sphere geometry was built";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("needs a mesh file"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cgcm::mesh
