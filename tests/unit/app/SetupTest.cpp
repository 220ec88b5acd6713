// A problem built on rank 0 and sent to the other ranks (app::buildProblem(comm, deck)) is, field by
// field, the problem each rank builds from the deck itself, without the mesh; what rank 0's build
// throws stops every rank with the same message. Meaningful on two ranks (mpi_app_tests_np2); on one
// it checks that the single rank keeps the mesh.
#include <gtest/gtest.h>

#include <regex>

#include <Tpetra_Core.hpp>

#include "cgcm/app/Setup.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/io/Deck.hpp"

namespace cgcm {
namespace {

Teuchos::RCP<Teuchos::ParameterList> deckFrom(const std::string& file, const std::vector<std::string>& overrides) {
  auto d = io::readDeck(file);
  app::resolveMeshFile(*d, file);
  io::applyOverrides(*d, *app::validParameters(), overrides);
  io::validateDeck(*d, *app::validParameters());
  return d;
}

// The report with its wall-clock times ("meshed by gmsh in 0.1 s") blanked: two builds of one deck
// say the same, but not in the same time.
std::vector<std::string> withoutTimes(std::vector<std::string> report) {
  static const std::regex time(" in [0-9.]+ s");
  for (auto& line : report) line = std::regex_replace(line, time, " in ... s");
  return report;
}

void expectSame(const mesh::DisplacementCondition& a, const mesh::DisplacementCondition& b) {
  EXPECT_EQ(a.nodeSet, b.nodeSet);
  EXPECT_EQ(a.component, b.component);
  EXPECT_EQ(a.offset, b.offset);
  EXPECT_EQ(a.scale, b.scale);
}

void expectSame(const std::vector<mesh::DisplacementCondition>& a, const std::vector<mesh::DisplacementCondition>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) expectSame(a[k], b[k]);
}

void expectSame(const mesh::ForceResponse& a, const mesh::ForceResponse& b) {
  EXPECT_EQ(a.nodeSet, b.nodeSet);
  EXPECT_EQ(a.component, b.component);
  EXPECT_EQ(a.sign, b.sign);
  EXPECT_EQ(a.scale, b.scale);
  EXPECT_EQ(a.direction, b.direction);
}

void expectSame(const material::NeoHookean& a, const material::NeoHookean& b) {
  EXPECT_EQ(a.lambda, b.lambda);
  EXPECT_EQ(a.mu, b.mu);
  EXPECT_EQ(a.law, b.law);
  EXPECT_EQ(a.kinematics, b.kinematics);
}

// `sent` (received from rank 0, or rank 0's own) against `own` (built by this rank from the deck).
void expectSameSetUp(const solver::ProblemSetup& sent, const solver::ProblemSetup& own) {
  EXPECT_EQ(sent.formulation, own.formulation);
  expectSame(sent.material, own.material);
  ASSERT_EQ(sent.bodyMaterials.size(), own.bodyMaterials.size());
  for (std::size_t b = 0; b < own.bodyMaterials.size(); ++b) expectSame(sent.bodyMaterials[b], own.bodyMaterials[b]);
  expectSame(sent.model.conditions, own.model.conditions);
  expectSame(sent.model.force, own.model.force);
  expectSame(sent.model.initialMotion, own.model.initialMotion);
  ASSERT_EQ(sent.model.balance.has_value(), own.model.balance.has_value());
  if (own.model.balance) expectSame(*sent.model.balance, *own.model.balance);
  EXPECT_EQ(sent.model.interacting, own.model.interacting);
  EXPECT_EQ(sent.model.areaFactors, own.model.areaFactors);
  ASSERT_EQ(sent.interaction.has_value(), own.interaction.has_value());
  if (own.interaction) {
    const auto &a = *sent.interaction, &b = *own.interaction;
    EXPECT_EQ(a.potential->name(), b.potential->name());
    EXPECT_EQ(a.potential->epsilon(), b.potential->epsilon());
    EXPECT_EQ(a.potential->r0(), b.potential->r0());
    for (const Real r : {0.9, 1.0, 1.7, 4.0}) {
      EXPECT_EQ(a.potential->phi(r * b.potential->r0()), b.potential->phi(r * b.potential->r0()));
      EXPECT_EQ(a.potential->halfSpace(r * b.potential->r0()), b.potential->halfSpace(r * b.potential->r0()));
    }
    // every rank reads the Interaction sublist itself (interaction::fromParameters): the same deck, the same set-up
    EXPECT_EQ(a.density, b.density);
    EXPECT_EQ(a.method, b.method);
    EXPECT_EQ(a.surfaceOptions.cutoff, b.surfaceOptions.cutoff);
    EXPECT_EQ(a.volumeOptions.skin, b.volumeOptions.skin);
    EXPECT_EQ(a.gammaL, b.gammaL);
    EXPECT_EQ(a.gammaW, b.gammaW);
  }
  ASSERT_EQ(sent.model.contact.has_value(), own.model.contact.has_value());
  if (const auto& c = own.model.contact) {
    EXPECT_EQ(sent.model.contact->upperApex, c->upperApex);
    EXPECT_EQ(sent.model.contact->lowerApex, c->lowerApex);
    EXPECT_EQ(sent.model.contact->upperBody, c->upperBody);
    EXPECT_EQ(sent.model.contact->lowerBody, c->lowerBody);
    EXPECT_EQ(sent.model.contact->contactDistance, c->contactDistance);
  }
  EXPECT_EQ(withoutTimes(sent.report), withoutTimes(own.report));
  EXPECT_EQ(sent.partition, own.partition);
  EXPECT_EQ(sent.forceScale, own.forceScale);
  EXPECT_EQ(sent.numNodes, std::size_t(own.model.mesh->numNodes()));
  EXPECT_EQ(sent.numCells, std::size_t(own.model.mesh->numCells()));
}

TEST(Setup, RankZeroBuildsTheProblemAndTheOtherRanksReceiveItWithoutTheMesh) {
  const auto comm = Tpetra::getDefaultComm();
  const std::string inputs = CGCM_INPUTS;
  struct Case {
    std::string name, file;
    std::vector<std::string> overrides;
  };
  const Case cases[] = {
      // axisymmetric benchmark: interaction, contact probe, balance, initial motion; another potential
      {"benchmark, Morse", inputs + "/sphere-on-half-space.xml",
       {"Interaction/Potential=Morse", "Solver/Partition=contiguous"}},
      // 3D gmsh, mirrored: many bodies, a material of their own, drive vector components, symmetric load scale
      {"three spheres",
       inputs + "/3d/three-spheres.xml",
       {"Geometry/Mesh Numbers/lcContact=0.2", "Geometry/Mesh Numbers/lcSphere=0.4", "Geometry/Mesh Numbers/lcFar=2.0",
        "Bodies/outer sphere/Young's Modulus=2"}},
      // no interaction
      {"block", inputs + "/sphere-on-half-space.xml",
       {"Geometry/Type=block", "Problem/Formulation=plane strain", "Loading/Approach Path={0, -0.1}"}},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const auto deck = deckFrom(c.file, c.overrides);
    const auto sent = app::buildProblem(*comm, *deck);
    const auto own = app::buildProblem(*deck);
    // EXPECT, not ASSERT: a rank leaving the loop alone would leave the others in buildProblem's collectives
    EXPECT_EQ(sent.model.mesh != nullptr, comm->getRank() == 0) << "only rank 0 holds the whole mesh";
    if (sent.model.mesh) {
      EXPECT_EQ(sent.model.mesh->numNodes(), own.model.mesh->numNodes());
      EXPECT_EQ(sent.model.mesh->coords, own.model.mesh->coords);
    }
    expectSameSetUp(sent, own);
  }
}

TEST(Setup, WhatRankZerosBuildThrowsEveryRankThrows) {
  const auto comm = Tpetra::getDefaultComm();
  const auto deck = deckFrom(std::string(CGCM_INPUTS) + "/3d/three-spheres.xml", {"Geometry/File=no-such-mesh.geo"});
  std::string message;
  try {
    app::buildProblem(*comm, *deck);
    ADD_FAILURE() << "a missing mesh file was accepted";
  } catch (const InputError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("no-such-mesh.geo"), std::string::npos) << message;

  // the kinds of error keep their types on every rank
  EXPECT_THROW(solver::runOnRoot(*comm, [] { throw NumericalError("a failed evaluation"); }), NumericalError);
  try {
    solver::runOnRoot(*comm, [] { throw std::logic_error("a broken invariant"); });
    ADD_FAILURE() << "nothing thrown";
  } catch (const InputError&) {
    ADD_FAILURE() << "a logic error became bad input";
  } catch (const NumericalError&) {
    ADD_FAILURE() << "a logic error became a numerical error";
  } catch (const std::exception& e) {
    EXPECT_STREQ(e.what(), "a broken invariant");
  }
  int calls = 0;
  solver::runOnRoot(*comm, [&] { ++calls; });
  EXPECT_EQ(calls, comm->getRank() == 0 ? 1 : 0);
}

// A part that rank 0 cannot cut (a node of no cell) stops every rank with its message.
TEST(Setup, APartRankZeroCannotCutStopsEveryRank) {
  const auto comm = Tpetra::getDefaultComm();
  if (comm->getSize() == 1) GTEST_SKIP() << "several ranks";
  const auto deck = deckFrom(std::string(CGCM_INPUTS) + "/sphere-on-half-space.xml",
                             {"Geometry/Type=block", "Problem/Formulation=plane strain"});
  auto setup = app::buildProblem(*comm, *deck);
  if (setup.model.mesh) setup.model.mesh->coords.insert(setup.model.mesh->coords.end(), {9.0, 9.0});
  try {
    solver::discretize(comm, setup, deck->sublist("Solver").sublist("Linear Solver"));
    ADD_FAILURE() << "a node of no cell was distributed";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("belongs to no cell"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace cgcm
