// Whole runs of block decks (app::runSimulation) and the deck's own checks:
// uniaxial compression against the closed-form Neo-Hookean solution, a
// verbatim Stratimikos list against the default solver, bad decks stopped with
// messages naming the parameter.
#include <gtest/gtest.h>

#include <Tpetra_Core.hpp>

#include <cmath>
#include <sstream>

#include "ClosedForm.hpp"
#include "cgcm/app/Setup.hpp"
#include "cgcm/app/Simulation.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/io/Deck.hpp"
#include "cgcm/solver/LoadStepper.hpp"

namespace cgcm {
namespace {

using Teuchos::ParameterList;
using Teuchos::RCP;
using test::lateralDirections;
using test::loadedArea;

// A block deck with the given overrides.
RCP<ParameterList> deck(const std::vector<std::string>& overrides) {
  auto d = Teuchos::rcp(new ParameterList("cgcm"));
  io::applyOverrides(*d, *app::validParameters(), {"Geometry/Type=block"});
  io::applyOverrides(*d, *app::validParameters(), overrides);
  io::validateDeck(*d, *app::validParameters());
  return d;
}

const char* kFormulations[] = {"plane strain", "axisymmetric", "3D"};

TEST(LoadStepping, UniaxialCompressionMatchesClosedFormNeoHookean) {
  // 30 % compression, roller faces: homogeneous state; P = sigma_zz * current area.
  for (std::string form : kFormulations) {
    for (std::string element : {"hex8", "tet4"}) {
      if (form != "3D" && element == "tet4") continue;
      for (std::string law : {"(Lambda/2)(ln J)^2", "(Lambda/4)(J^2-1-2 ln J)"}) {
        SCOPED_TRACE(form + " " + element + " " + law);
        auto d = deck({"Problem/Formulation=" + form, "Geometry/Block/Element=" + element,
                       "Geometry/Block/Cells X=2", "Geometry/Block/Cells Y=3", "Geometry/Block/Cells Z=2",
                       "Material/Poisson's Ratio=0.3", "Material/Volumetric Energy=" + law,
                       "Loading/Approach Path={0, -0.3}", "Loading/Initial Increment=0.1",
                       "Loading/Max Increment=0.1", "Output/Print Steps=false",
                       "Output/Directory=" + std::string(CGCM_TEST_OUTPUT) + "/uniaxial"});
        std::ostringstream log;
        const auto run = app::runSimulation(Tpetra::getDefaultComm(), *d, log);
        ASSERT_TRUE(run.completed) << run.failure;
        ASSERT_EQ(run.curve.size(), 4u);
        const auto setup = app::buildProblem(*d);
        for (const auto& pt : run.curve) {
          double lateral = 1.0;
          const double sigma = test::uniaxialCauchyStress(setup.material, 1.0 + pt.u, lateralDirections(form), lateral);
          const double expected = sigma * loadedArea(form, lateral);
          EXPECT_NEAR(pt.P, expected, 1e-9 * (1.0 + std::abs(expected))) << "u = " << pt.u;
        }
        EXPECT_LT(run.curve.back().P, -0.2);  // really compressed
      }
    }
  }
}

TEST(Input, BadDecksStopWithMessagesNamingTheParameter) {
  auto expectError = [](const std::vector<std::string>& overrides, const std::string& fragment) {
    try {
      auto d = deck(overrides);
      app::buildProblem(*d);
      solver::LoadPathSettings::fromParameters(d->sublist("Loading"));
      ADD_FAILURE() << "no error for " << overrides.front();
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
  };
  expectError({"Material/Poisson's Ratio=0.5"}, "Poisson's Ratio");
  expectError({"Material/Young's Modulus=-1"}, "Young's Modulus");
  expectError({"Problem/Formulation=2D"}, "Formulation");
  expectError({"Geometry/Block/Cells X=0"}, "Cells X");
  expectError({"Loading/Approach Path={0.1}"}, "Approach Path");
  expectError({"Loading/Approach Path={0, 0.1, 0.2}"}, "Approach Path");
  expectError({"Material/Youngs Modulus=1"}, "Youngs Modulus");
  expectError({"Solver/Newton/Line Search=trust region"}, "Line Search");
}

TEST(LinearSolver, VerbatimStratimikosListIsUsedAndValidated) {
  // Type = Stratimikos hands the sublist to Stratimikos as is: a Belos GMRES
  // with an Ifpack2 ILUT preconditioner must solve the clamped block like the default.
  auto d = deck({"Geometry/Type=block", "Problem/Formulation=3D", "Geometry/Block/Loaded Face=clamped",
                 "Loading/Approach Path={0, -0.1}", "Loading/Initial Increment=0.05", "Loading/Max Increment=0.05",
                 "Output/Print Steps=false",
                 "Output/Directory=" + std::string(CGCM_TEST_OUTPUT) + "/stratimikos",
                 "Solver/Linear Solver/Type=Stratimikos"});
  auto& s = d->sublist("Solver").sublist("Linear Solver").sublist("Stratimikos");
  s.set("Linear Solver Type", "Belos");
  auto& gmres = s.sublist("Linear Solver Types").sublist("Belos");
  gmres.set("Solver Type", "Block GMRES");
  gmres.sublist("Solver Types").sublist("Block GMRES").set("Convergence Tolerance", 1e-12);
  s.set("Preconditioner Type", "Ifpack2");
  s.sublist("Preconditioner Types").sublist("Ifpack2").set("Prec Type", "ILUT");
  std::ostringstream log;
  const auto custom = app::runSimulation(Tpetra::getDefaultComm(), *d, log);
  ASSERT_TRUE(custom.completed) << custom.failure;
  auto reference = deck({"Geometry/Type=block", "Problem/Formulation=3D", "Geometry/Block/Loaded Face=clamped",
                         "Loading/Approach Path={0, -0.1}", "Loading/Initial Increment=0.05", "Loading/Max Increment=0.05",
                         "Output/Print Steps=false",
                         "Output/Directory=" + std::string(CGCM_TEST_OUTPUT) + "/stratimikos-reference"});
  const auto ref = app::runSimulation(Tpetra::getDefaultComm(), *reference, log);
  ASSERT_EQ(custom.curve.size(), ref.curve.size());
  EXPECT_NEAR(custom.curve.back().P, ref.curve.back().P, 1e-8 * std::abs(ref.curve.back().P));

  s.set("Linear Solver Type", "Magic");  // an unknown solver: a clear error before any work
  EXPECT_THROW(app::runSimulation(Tpetra::getDefaultComm(), *d, log), InputError);
}

}  // namespace
}  // namespace cgcm
