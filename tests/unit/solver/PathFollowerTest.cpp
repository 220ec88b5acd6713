// Path control as a strategy: every Loading/Control value of the registry is
// a follower the deck can name, the Loading sublist is read and checked by the
// plan (the parameter named in every refusal), and LOCA's step sizes come
// from the plan alone.
#include <gtest/gtest.h>

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include <algorithm>
#include <string>

#include "cgcm/core/Error.hpp"
#include "cgcm/io/Deck.hpp"
#include "cgcm/solver/PathFollower.hpp"

namespace cgcm::solver {
namespace {

const std::vector<std::string> kInteraction{"gammaW", "gammaL"};

PathPlan planOf(Teuchos::ParameterList loading, const std::vector<std::string>& parameters = kInteraction) {
  io::validateDeck(loading, *PathPlan::validParameters(), "Loading/");
  return PathPlan(loading, parameters, 0.02);
}

std::string refusal(const Teuchos::ParameterList& loading, const std::vector<std::string>& parameters = kInteraction) {
  try {
    planOf(loading, parameters);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(PathFollower, EveryRegisteredControlIsADeckChoiceWithItsFollower) {
  const auto& entry = PathPlan::validParameters()->getEntry("Control");
  const auto choices =
      Teuchos::rcp_dynamic_cast<const Teuchos::StringValidator>(entry.validator(), true)->validStringValues();
  ASSERT_EQ(choices->size(), pathControlRegistry().size());
  for (const auto& e : pathControlRegistry()) {
    SCOPED_TRACE(e.deckName);
    EXPECT_NE(std::find(choices->begin(), choices->end(), std::string(e.deckName)), choices->end());
    EXPECT_NE(entry.docString().find(e.description), std::string::npos);
    Teuchos::ParameterList loading;
    loading.set("Control", std::string(e.deckName));
    const auto plan = planOf(loading);
    EXPECT_EQ(plan.follower().name(), e.deckName);
  }
  Teuchos::ParameterList displacement, arcLength;
  arcLength.set("Control", std::string("arc-length"));
  const auto d = planOf(displacement), a = planOf(arcLength);
  EXPECT_FALSE(d.follower().tracesUnstableBranches());
  EXPECT_TRUE(d.follower().restartable());
  EXPECT_FALSE(d.usesContinuation());
  EXPECT_TRUE(a.follower().tracesUnstableBranches());
  EXPECT_FALSE(a.follower().restartable());
  EXPECT_TRUE(a.usesContinuation());
}

TEST(PathFollower, ThePlanRefusesAPathItCannotFollowNamingTheParameter) {
  Teuchos::ParameterList noInteraction;
  noInteraction.set("Continuation Parameter", std::string("gammaW"));
  noInteraction.set("Parameter Path", Teuchos::Array<double>(Teuchos::tuple<double>(100.0, 20.0)));
  EXPECT_NE(refusal(noInteraction, {}).find("Loading/Continuation Parameter = \"gammaW\" needs an interaction"),
            std::string::npos);
  Teuchos::ParameterList noWaypoints;
  noWaypoints.set("Continuation Parameter", std::string("gammaL"));
  EXPECT_NE(refusal(noWaypoints).find("Loading/Parameter Path: give the waypoints of gammaL"), std::string::npos);
  Teuchos::ParameterList pathForU;
  pathForU.set("Parameter Path", Teuchos::Array<double>(1, 100.0));
  EXPECT_NE(refusal(pathForU).find("Loading/Parameter Path: only with a Continuation Parameter other than \"u\""),
            std::string::npos);
  Teuchos::ParameterList negative;
  negative.set("Continuation Parameter", std::string("gammaW"));
  negative.set("Parameter Path", Teuchos::Array<double>(Teuchos::tuple<double>(100.0, -5.0)));
  EXPECT_NE(refusal(negative).find("Loading/Parameter Path: waypoint 1"), std::string::npos) << refusal(negative);
  Teuchos::ParameterList bounds;
  bounds.set("Approach Path", Teuchos::Array<double>(Teuchos::tuple<double>(-0.02, 0.06)));
  bounds.set("Parameter Bounds", Teuchos::Array<double>(Teuchos::tuple<double>(-0.01, 0.1)));
  EXPECT_NE(refusal(bounds).find("Loading/Parameter Bounds: the path value -0.02"), std::string::npos) << refusal(bounds);
  Teuchos::ParameterList control;
  control.set("Control", std::string("force"));
  EXPECT_NE(refusal(control).find("Loading/Control = \"force\": not a choice"), std::string::npos);
}

TEST(PathFollower, LocaStepSizesComeFromThePlanUnlessTheDeckGivesThem) {
  Teuchos::ParameterList loading;
  loading.set("Min Increment", 1e-6);
  loading.set("Max Increment", 0.004);
  loading.set("Initial Increment", 0.002);
  const auto inU = planOf(loading);
  const auto loca = inU.locaParameters(Teuchos::ParameterList("LOCA"));
  EXPECT_EQ(loca.sublist("Step Size").get<double>("Min Step Size"), 1e-6);
  EXPECT_EQ(loca.sublist("Step Size").get<double>("Max Step Size"), 0.004);
  Teuchos::ParameterList deckLoca("LOCA");
  deckLoca.sublist("Step Size").set("Max Step Size", 0.5);
  EXPECT_EQ(inU.locaParameters(deckLoca).sublist("Step Size").get<double>("Max Step Size"), 0.5);
  // in gammaW the step is not a displacement: LOCA's own Max Step Size
  loading.set("Continuation Parameter", std::string("gammaW"));
  loading.set("Parameter Path", Teuchos::Array<double>(1, 100.0));
  const auto inGammaW = planOf(loading).locaParameters(Teuchos::ParameterList("LOCA"));
  EXPECT_EQ(inGammaW.sublist("Step Size").get<double>("Min Step Size"), 1e-6);
  EXPECT_FALSE(inGammaW.sublist("Step Size").isParameter("Max Step Size"));
  // the help says so
  const std::string help = PathPlan::locaHelp();
  EXPECT_NE(help.find("Max Step Size = Loading/Max Increment (continuation in u)"), std::string::npos);
  EXPECT_NE(help.find("Min Step Size = Loading/Min Increment"), std::string::npos);
}

}  // namespace
}  // namespace cgcm::solver
