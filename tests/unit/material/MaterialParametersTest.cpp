// The Material sublist belongs to the material package: its defaults give the
// paper's solid, and a body's overrides are checked as the sublist is.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "cgcm/core/Error.hpp"
#include "cgcm/io/Deck.hpp"
#include "cgcm/material/MaterialParameters.hpp"

namespace cgcm::material {
namespace {

Teuchos::ParameterList validated(Teuchos::ParameterList list) {
  io::validateDeck(list, *validParameters(), "Material/");
  return list;
}

std::string refusal(const Teuchos::ParameterList& overrides) {
  try {
    fromParameters(validated(Teuchos::ParameterList()), overrides, "Bodies/tip/");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void expectLaw(const NeoHookean& m, Real Y, Real nu, VolumetricLaw law, Kinematics kinematics) {
  EXPECT_NEAR(m.youngsModulus(), Y, 1e-13 * Y);
  EXPECT_NEAR(m.poissonRatio(), nu, 1e-14);
  EXPECT_EQ(m.law, law);
  EXPECT_EQ(m.kinematics, kinematics);
}

TEST(MaterialParameters, DefaultsAreThePapersSolid) {
  expectLaw(fromParameters(validated(Teuchos::ParameterList())), 1.0, 0.2, VolumetricLaw::LogSquared,
            Kinematics::FiniteStrain);
}

TEST(MaterialParameters, EveryParameterReachesTheLaw) {
  Teuchos::ParameterList list;
  list.set("Young's Modulus", 3.5);
  list.set("Poisson's Ratio", 0.3);
  list.set("Volumetric Energy", std::string("(Lambda/4)(J^2-1-2 ln J)"));
  list.set("Kinematics", std::string("small strain"));
  expectLaw(fromParameters(validated(list)), 3.5, 0.3, VolumetricLaw::QuadraticJ, Kinematics::SmallStrain);
}

TEST(MaterialParameters, ABodyOverridesOnlyWhatItGives) {
  Teuchos::ParameterList base;
  base.set("Young's Modulus", 2.0);
  base.set("Kinematics", std::string("small strain"));
  Teuchos::ParameterList overrides;
  overrides.set("Poisson's Ratio", std::string("0.35"));  // a number as text, as the command line gives it
  expectLaw(fromParameters(validated(base), overrides, "Bodies/tip/"), 2.0, 0.35, VolumetricLaw::LogSquared,
            Kinematics::SmallStrain);
}

TEST(MaterialParameters, ABodysBadOverrideIsNamedWithItsPath) {
  Teuchos::ParameterList range;
  range.set("Poisson's Ratio", 0.7);
  const std::string outOfRange = refusal(range);
  EXPECT_NE(outOfRange.find("Bodies/tip/Poisson's Ratio = 0.7: out of range"), std::string::npos) << outOfRange;
  Teuchos::ParameterList unknown;
  unknown.set("Youngs Modulus", 2.0);
  const std::string misspelt = refusal(unknown);
  EXPECT_NE(misspelt.find("Bodies/tip/Youngs Modulus: unknown parameter (did you mean \"Young's Modulus\"?)"),
            std::string::npos)
      << misspelt;
  Teuchos::ParameterList text;
  text.set("Young's Modulus", std::string("stiff"));
  const std::string notANumber = refusal(text);
  EXPECT_NE(notANumber.find("Bodies/tip/Young's Modulus: \"stiff\" is not a number"), std::string::npos) << notANumber;
  Teuchos::ParameterList choice;
  choice.set("Kinematics", std::string("large strain"));
  const std::string notAChoice = refusal(choice);
  EXPECT_NE(notAChoice.find("Bodies/tip/Kinematics = \"large strain\": not a choice"), std::string::npos) << notAChoice;
}

// Bodies/<name>/Rigid: read by rigidBodies (a mirror image follows its
// original), ignored by bodyMaterials, refused when not true or false.
TEST(MaterialParameters, RigidBodiesAreReadAndMirrorImagesFollow) {
  const Teuchos::ParameterList material = validated(Teuchos::ParameterList());
  Teuchos::ParameterList bodies;
  bodies.sublist("tip").set("Rigid", true);
  bodies.sublist("substrate").set("Young's Modulus", 3.0);
  const std::vector<std::string> names = {"substrate", "tip", "tip mirrored in x"};
  const std::vector<std::string> originals = {"substrate", "tip", "tip"};
  std::vector<std::string> report;
  const auto m = bodyMaterials(material, bodies, names, originals, report);  // Rigid is not a material entry
  expectLaw(m[0], 3.0, 0.2, VolumetricLaw::LogSquared, Kinematics::FiniteStrain);
  report.clear();
  EXPECT_EQ(rigidBodies(bodies, names, originals, report), (std::vector<char>{0, 1, 1}));
  ASSERT_EQ(report.size(), 2u);
  EXPECT_EQ(report[0], "body \"tip\": rigid (moved as a whole by its conditions)");
  bodies.sublist("tip mirrored in x").set("Rigid", false);  // an image's own entry wins
  EXPECT_EQ(rigidBodies(bodies, names, originals, report), (std::vector<char>{0, 1, 0}));
  Teuchos::ParameterList words;
  words.sublist("tip").set("Rigid", std::string("yes"));
  EXPECT_THROW(rigidBodies(words, names, originals, report), InputError);
  Teuchos::ParameterList number;
  number.sublist("tip").set("Rigid", 1);
  try {
    rigidBodies(number, names, originals, report);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "Bodies/tip/Rigid: a bool is expected (true or false)");
  }
}

TEST(MaterialParameters, BodiesGetTheirOwnAndMirrorImagesTheirOriginals) {
  const Teuchos::ParameterList material = validated(Teuchos::ParameterList());
  Teuchos::ParameterList bodies;
  bodies.sublist("tip").set("Young's Modulus", 5.0);
  const std::vector<std::string> names = {"substrate", "tip", "tip mirrored in x", "substrate mirrored in x"};
  const std::vector<std::string> originals = {"substrate", "tip", "tip", "substrate"};
  std::vector<std::string> report;
  const auto m = bodyMaterials(material, bodies, names, originals, report);
  ASSERT_EQ(m.size(), 4u);
  expectLaw(m[0], 1.0, 0.2, VolumetricLaw::LogSquared, Kinematics::FiniteStrain);
  expectLaw(m[1], 5.0, 0.2, VolumetricLaw::LogSquared, Kinematics::FiniteStrain);
  expectLaw(m[2], 5.0, 0.2, VolumetricLaw::LogSquared, Kinematics::FiniteStrain);  // the image of "tip"
  expectLaw(m[3], 1.0, 0.2, VolumetricLaw::LogSquared, Kinematics::FiniteStrain);
  ASSERT_EQ(report.size(), 2u);
  EXPECT_EQ(report[0], "body \"tip\": Young's modulus 5, Poisson's ratio 0.2");
  EXPECT_EQ(report[1], "body \"tip mirrored in x\": the material of \"tip\" (its mirror image)");

  auto refusalOf = [&](const Teuchos::ParameterList& b) {
    try {
      bodyMaterials(material, b, names, originals, report);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  Teuchos::ParameterList unknown;
  unknown.sublist("probe").set("Young's Modulus", 2.0);
  EXPECT_EQ(refusalOf(unknown), "Bodies/probe: the mesh has no body of that name; its bodies are \"substrate\", "
                                "\"tip\", \"tip mirrored in x\", \"substrate mirrored in x\"");
  Teuchos::ParameterList notAList;
  notAList.set("tip", 2.0);
  EXPECT_NE(refusalOf(notAList).find("Bodies/tip: a sublist named after a body is expected"), std::string::npos);
}

}  // namespace
}  // namespace cgcm::material
