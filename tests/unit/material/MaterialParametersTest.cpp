// The Material sublist belongs to the material package: its defaults give the
// paper's solid, and a body's overrides are checked as the sublist is.
#include <gtest/gtest.h>

#include <string>

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

TEST(MaterialParameters, DefaultsAreThePapersSolid) {
  const NeoHookean m = fromParameters(validated(Teuchos::ParameterList()));
  EXPECT_NEAR(m.youngsModulus(), 1.0, 1e-14);
  EXPECT_NEAR(m.poissonRatio(), 0.2, 1e-14);
  EXPECT_EQ(m.law, VolumetricLaw::LogSquared);
  EXPECT_EQ(m.kinematics, Kinematics::FiniteStrain);
}

TEST(MaterialParameters, EveryParameterReachesTheLaw) {
  Teuchos::ParameterList list;
  list.set("Young's Modulus", 3.5);
  list.set("Poisson's Ratio", 0.3);
  list.set("Volumetric Energy", std::string("(Lambda/4)(J^2-1-2 ln J)"));
  list.set("Kinematics", std::string("small strain"));
  const NeoHookean m = fromParameters(validated(list));
  EXPECT_NEAR(m.youngsModulus(), 3.5, 1e-13);
  EXPECT_NEAR(m.poissonRatio(), 0.3, 1e-14);
  EXPECT_EQ(m.law, VolumetricLaw::QuadraticJ);
  EXPECT_EQ(m.kinematics, Kinematics::SmallStrain);
}

TEST(MaterialParameters, ABodyOverridesOnlyWhatItGives) {
  Teuchos::ParameterList base;
  base.set("Young's Modulus", 2.0);
  base.set("Kinematics", std::string("small strain"));
  Teuchos::ParameterList overrides;
  overrides.set("Poisson's Ratio", std::string("0.35"));  // a number as text, as the command line gives it
  const NeoHookean m = fromParameters(validated(base), overrides, "Bodies/tip/");
  EXPECT_NEAR(m.youngsModulus(), 2.0, 1e-14);
  EXPECT_NEAR(m.poissonRatio(), 0.35, 1e-14);
  EXPECT_EQ(m.kinematics, Kinematics::SmallStrain);
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
  EXPECT_NE(notANumber.find("Bodies/tip/Young's Modulus"), std::string::npos) << notANumber;
  Teuchos::ParameterList choice;
  choice.set("Kinematics", std::string("large strain"));
  const std::string notAChoice = refusal(choice);
  EXPECT_NE(notAChoice.find("Bodies/tip/Kinematics = \"large strain\": not a choice"), std::string::npos) << notAChoice;
}

}  // namespace
}  // namespace cgcm::material
