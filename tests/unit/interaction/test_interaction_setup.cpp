// The Interaction sublist belongs to the interaction package: the three
// parameterisations give one interaction, bad combinations are refused with
// the parameter named, the interaction it creates is the method asked for,
// and gammaW and gammaL reach it through the one Interaction interface.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "cgcm/core/Error.hpp"
#include "cgcm/interaction/InteractionSetup.hpp"
#include "cgcm/interaction/VolumeInteraction.hpp"
#include "cgcm/io/Deck.hpp"
#include "cgcm/mesh/Geometry.hpp"

using namespace cgcm;
using namespace cgcm::interaction;

namespace {

const ReferenceScales kScales{1.0, 1.0, 0.2, 1.0};

InteractionSetup setUp(Teuchos::ParameterList list, Formulation f = Formulation::Axisymmetric) {
  io::validateDeck(list, *validParameters(), "Interaction/");
  return fromParameters(list, kScales, f);
}

std::string refusal(const Teuchos::ParameterList& list) {
  try {
    setUp(list);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

mesh::Model benchmark(Formulation f, Real contactDistance, int elementOrder = 1, int level = 0, Real zone = 0.5) {
  Teuchos::ParameterList g;
  g.set("Element Order", elementOrder);
  g.set("Mesh Refinement", level);
  g.set("Contact Zone Size", zone);
  io::validateDeck(g, *mesh::validParameters(), "Geometry/");
  return mesh::buildModel(g, f, [contactDistance] { return contactDistance; });
}

TEST(InteractionSetup, TheThreeParameterisationsGiveOneInteraction) {
  Teuchos::ParameterList plain;
  plain.set("gammaL", 50.0);
  plain.set("gammaW", 200.0);
  const auto a = setUp(plain);
  Teuchos::ParameterList barred;  // the literal reading: gammaL = gammaL bar / (3/4)^(1/6), gammaW = gammaW bar / sqrt 3
  barred.set("gammaL bar", 50.0 * std::pow(0.75, 1.0 / 6.0));
  barred.set("gammaW bar", 200.0 * std::sqrt(3.0));
  const auto b = setUp(barred);
  Teuchos::ParameterList physical;  // r0 = R0 / gammaL, epsilon = Y gammaL^3 / (gammaW R0^3 beta0^2)
  physical.set("r0", 1.0 / 50.0);
  physical.set("epsilon", 50.0 * 50.0 * 50.0 / 200.0);
  const auto c = setUp(physical);
  for (const auto* s : {&b, &c}) {
    EXPECT_NEAR(s->gammaL, 50.0, 1e-12);
    EXPECT_NEAR(s->gammaW, 200.0, 1e-10);
    EXPECT_NEAR(s->potential->r0(), a.potential->r0(), 1e-15);
    EXPECT_NEAR(s->potential->epsilon() / a.potential->epsilon(), 1.0, 1e-13);
  }
  // the defaults: Lennard-Jones, Method 3, cutoff 10 r0 with a 20 % taper
  EXPECT_EQ(a.potential->name(), "lennard-jones");
  EXPECT_EQ(a.method, Method::HalfSpacePoint);
  EXPECT_DOUBLE_EQ(a.surfaceOptions.cutoff, 10.0 * a.potential->r0());
  EXPECT_DOUBLE_EQ(a.surfaceOptions.cutoffTaper, 0.2);
  EXPECT_EQ(a.surfaceOptions.quadraturePoints, 4);
  // 3D: 2 points per direction unless given
  EXPECT_EQ(setUp(plain, Formulation::ThreeD).surfaceOptions.quadraturePoints, 2);
}

TEST(InteractionSetup, BadCombinationsAreRefusedWithTheParameterNamed) {
  Teuchos::ParameterList mixed;
  mixed.set("gammaL", 20.0);
  mixed.set("r0", 0.05);
  mixed.set("epsilon", 1.0);
  EXPECT_NE(refusal(mixed).find("give one of (gammaL, gammaW), (gammaL bar, gammaW bar) or (r0, epsilon)"),
            std::string::npos);
  Teuchos::ParameterList half;
  half.set("r0", 0.05);
  EXPECT_NE(refusal(half).find("set both r0 and epsilon"), std::string::npos);
  Teuchos::ParameterList taper;
  taper.set("Cutoff", 2.5);
  taper.set("Cutoff Taper", 0.5);
  EXPECT_NE(refusal(taper).find("Interaction/Cutoff Taper"), std::string::npos);
  Teuchos::ParameterList orders;
  orders.set("Method", std::string("volume pair"));
  orders.set("Volume Quadrature Order", 4);
  orders.set("Max Volume Quadrature Order", 3);
  EXPECT_NE(refusal(orders).find("Interaction/Max Volume Quadrature Order = 3 is below"), std::string::npos);
  Teuchos::ParameterList potential;
  potential.set("Potential", std::string("coulomb"));
  EXPECT_NE(refusal(potential).find("Interaction/Potential = \"coulomb\": not a choice"), std::string::npos);
}

TEST(InteractionSetup, APotentialDeclaresAndReadsItsOwnParameters) {
  // Morse's Inverse Width (a r0) lives in Interaction/Morse: the default 6 is Lennard-Jones's curvature,
  // another value changes phi as exp(-2a(r - r0)) - 2 exp(-a(r - r0)) with a = Inverse Width / r0 says.
  Teuchos::ParameterList morse;
  morse.set("Potential", std::string("Morse"));
  const InteractionSetup matched = setUp(morse);
  morse.sublist("Morse").set("Inverse Width", 9.0);
  const InteractionSetup narrow = setUp(morse);
  const Real eps = matched.potential->epsilon(), r0 = matched.potential->r0();
  for (Real r : {0.9 * r0, r0, 1.3 * r0}) {
    for (const auto& [s, a] : {std::pair{&matched, 6.0 / r0}, std::pair{&narrow, 9.0 / r0}}) {
      const Real e = std::exp(-a * (r - r0));
      EXPECT_NEAR(s->potential->phi(r), eps * e * (e - 2.0), 1e-13 * eps) << "a r0 = " << a * r0 << ", r = " << r;
    }
  }
  // the parameter of a potential not chosen, and a parameter the potential does not declare, are refused
  Teuchos::ParameterList stray;
  stray.sublist("Morse").set("Inverse Width", 9.0);
  EXPECT_NE(refusal(stray).find("Interaction/Morse/Inverse Width is set, but Interaction/Potential = \"Lennard-Jones\""),
            std::string::npos)
      << refusal(stray);
  Teuchos::ParameterList unknown;
  unknown.set("Potential", std::string("Morse"));
  unknown.sublist("Morse").set("Depth", 2.0);
  EXPECT_NE(refusal(unknown).find("Depth"), std::string::npos) << refusal(unknown);
  Teuchos::ParameterList bad;
  bad.set("Potential", std::string("Morse"));
  bad.sublist("Morse").set("Inverse Width", -1.0);
  EXPECT_NE(refusal(bad).find("Inverse Width"), std::string::npos) << refusal(bad);
  // makePotential, outside a deck, checks the same list
  Teuchos::ParameterList own;
  own.set("Depth", 2.0);
  EXPECT_THROW(makePotential("Morse", 1.0, 1.0, own), InputError);
}

TEST(InteractionSetup, ContactDistanceIsLennardJonesRS0OfTheSameR0ForEveryPotential) {
  for (const char* name : {"Lennard-Jones", "repulsive", "Morse"}) {
    Teuchos::ParameterList list;
    list.set("Potential", std::string(name));  // the deck names
    const auto s = setUp(list);
    EXPECT_DOUBLE_EQ(s.contactDistance(), s.potential->r0() / std::pow(15.0, 1.0 / 6.0)) << name;
  }
}

TEST(InteractionSetup, CreatesTheMethodAskedForAndScalesItThroughItsParameters) {
  for (const char* method : {"half-space point", "volume pair"}) {
    SCOPED_TRACE(method);
    Teuchos::ParameterList list;
    list.set("Method", std::string(method));
    const auto s = setUp(list);
    const auto model = benchmark(Formulation::Axisymmetric, s.contactDistance());
    const auto interaction = s.create(*model.mesh);
    const bool volume = std::string(method) == "volume pair";
    EXPECT_EQ(dynamic_cast<VolumeInteraction*>(interaction.get()) != nullptr, volume);
    EXPECT_EQ(dynamic_cast<SurfaceInteraction*>(interaction.get()) != nullptr, !volume);
    EXPECT_EQ(interaction->numBodies(), 2);
    const Real cutoff = interaction->cutoff();

    const auto parameters = s.scalarParameters(interaction);
    ASSERT_EQ(parameters.size(), 2u);
    EXPECT_EQ(parameters[0].name, "gammaW");
    EXPECT_EQ(parameters[0].nominal, 200.0);
    EXPECT_EQ(parameters[1].name, "gammaL");
    EXPECT_EQ(parameters[1].nominal, 50.0);
    // gammaW = Y / (beta0^2 r0^3 epsilon) at fixed r0: epsilon, the strength, as 1 / gammaW
    parameters[0].apply(50.0);
    EXPECT_DOUBLE_EQ(interaction->strength(), 4.0);
    EXPECT_DOUBLE_EQ(interaction->lengthScale(), 1.0);
    // gammaL = R0 / r0: r0, the length scale and the cutoff with it, as 1 / gammaL
    parameters[1].apply(100.0);
    EXPECT_DOUBLE_EQ(interaction->lengthScale(), 0.5);
    EXPECT_NEAR(interaction->cutoff(), 0.5 * cutoff, 1e-15);
    EXPECT_DOUBLE_EQ(interaction->strength(), 4.0);
    EXPECT_THROW(parameters[0].apply(0.0), NumericalError);
    EXPECT_THROW(parameters[1].apply(-1.0), NumericalError);
  }
}

TEST(InteractionSetup, Method1TakesASymmetricPartThroughItsImages) {
  Teuchos::ParameterList list;
  list.set("Method", std::string("volume pair"));
  list.set("Volume Quadrature Tolerance", 0.0);
  // the built-in half model in plane strain: its axis is a symmetry line, the image is across x = 0
  for (const Formulation f : {Formulation::PlaneStrain, Formulation::Axisymmetric}) {
    auto s = setUp(list);
    s.volumeOptions.formulation = f;
    const auto half = benchmark(f, s.contactDistance());
    EXPECT_NO_THROW(s.checkMesh(*half.mesh, f));
    const auto volume = std::dynamic_pointer_cast<VolumeInteraction>(s.create(*half.mesh));
    ASSERT_TRUE(volume);
    // in axisymmetry the axis is the axis of revolution: the model is whole
    EXPECT_EQ(volume->options().symmetryPlanes, f == Formulation::PlaneStrain ? 1 : 0);
    EXPECT_EQ(volume->options().bodySymmetryPlanes, std::vector<int>(2, f == Formulation::PlaneStrain ? 1 : 0));
  }
}

// Both methods take quadratic cells in every formulation: the set-up's mesh check passes them.
TEST(InteractionSetup, BothMethodsTakeQuadraticCells) {
  for (const char* method : {"half-space point", "volume pair"}) {
    Teuchos::ParameterList list;
    list.set("Method", std::string(method));
    const auto s = setUp(list);
    EXPECT_NO_THROW(s.checkMesh(*benchmark(Formulation::Axisymmetric, s.contactDistance(), 2).mesh,
                                Formulation::Axisymmetric)) << method;
  }
}

// Method 1 refuses, before any work, a mesh whose cells where the bodies meet its quadrature
// cannot integrate to the Volume Quadrature Tolerance in contact, and names the cell size it
// needs: the default deck at gammaL = 200 (cells of 5 r0 at the surfaces: at order 12 the
// estimated error is 0.19 of a pair's force; needed 1.68 r0, measured with the default 1e-4),
// and accepts the same mesh with the Contact Zone Size scaled as the message says. A tolerance
// of 0 (no estimate) accepts anything.
TEST(InteractionSetup, Method1RefusesCellsItsQuadratureCannotIntegrateInContact) {
  Teuchos::ParameterList list;
  list.set("Method", std::string("volume pair"));
  list.set("gammaL", 200.0);
  const auto s = setUp(list);
  std::string message = "no InputError";
  try {
    s.checkMesh(*benchmark(Formulation::Axisymmetric, s.contactDistance()).mesh, Formulation::Axisymmetric);
  } catch (const InputError& e) {
    message = e.what();
  }
  for (const char* part : {"up to 5 r0 long", "Interaction/Volume Quadrature Tolerance = 0.0001",
                           "Cells of at most 1.68 r0", "Geometry/Contact Zone Size", "scale it by 0.336",
                           "Geometry/Mesh Refinement"})
    EXPECT_NE(message.find(part), std::string::npos) << part << " in: " << message;
  EXPECT_NO_THROW(s.checkMesh(*benchmark(Formulation::Axisymmetric, s.contactDistance(), 1, 0, 0.5 * 0.336).mesh,
                              Formulation::Axisymmetric));
  list.set("Volume Quadrature Tolerance", 0.0);
  EXPECT_NO_THROW(setUp(list).checkMesh(*benchmark(Formulation::Axisymmetric, s.contactDistance()).mesh,
                                        Formulation::Axisymmetric));
}

// The same integral with every QUAD4 within 3 r0 of the gap split into 2 x 2 cells (the bilinear
// map of a quarter of the parent square is the bilinear interpolation of its corners: the same
// geometry, the same integral) for a finer quadrature where the kernel's most order binds.
mesh::Mesh splitNearTheGap(const mesh::Mesh& m, Real r0) {
  Real sphereLow = 1e300, halfSpaceHigh = -1e300;
  const std::vector<std::string> names = mesh::bodyNames(m);
  for (const auto& b : m.blocks)
    for (LocalIndex n : b.connectivity) {
      if (names[b.body] == "sphere") sphereLow = std::min(sphereLow, m.coord(n, 1));
      else halfSpaceHigh = std::max(halfSpaceHigh, m.coord(n, 1));
    }
  const Real mid = 0.5 * (sphereLow + halfSpaceHigh);
  mesh::Mesh out;
  out.dim = 2;
  out.numBodies = m.numBodies;
  out.coords = m.coords;
  for (const auto& b : m.blocks) {
    mesh::ElementBlock nb;
    nb.name = b.name;
    nb.body = b.body;
    nb.type = b.type;
    for (LocalIndex c = 0; c < b.numCells(); ++c) {
      const LocalIndex* v = &b.connectivity[std::size_t(c) * 4];
      Real cy = 0.0;
      for (int a = 0; a < 4; ++a) cy += 0.25 * m.coord(v[a], 1);
      if (std::abs(cy - mid) > 3.0 * r0) {
        nb.connectivity.insert(nb.connectivity.end(), v, v + 4);
        continue;
      }
      // nodes at (s, t) in {0, 1/2, 1}^2 of the parent's corners 0 (0,0), 1 (1,0), 2 (1,1), 3 (0,1)
      LocalIndex id[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          const Real S = 0.5 * i, T = 0.5 * j, w[4] = {(1 - S) * (1 - T), S * (1 - T), S * T, (1 - S) * T};
          id[i][j] = out.numNodes();
          for (int d = 0; d < 2; ++d) {
            Real x = 0.0;
            for (int a = 0; a < 4; ++a) x += w[a] * m.coord(v[a], d);
            out.coords.push_back(x);
          }
        }
      for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
          for (LocalIndex n : {id[i][j], id[i + 1][j], id[i + 1][j + 1], id[i][j + 1]}) nb.connectivity.push_back(n);
    }
    out.blocks.push_back(nb);
  }
  return out;
}

// Method 1 on meshes it accepts, as a user gets them: the undeformed sphere at the contact
// distance r_S0 over the half-space (every apex cell pair in contact), gammaL = 50 (cells of
// 1.25 r0 at the surfaces) and gammaL = 200 with the contact zone the refusal above asks for
// (1.68 r0), levels 0 and 1. The force on the sphere with the default Volume Quadrature
// Tolerance 1e-4 against a raised quadrature, two ways:
//  - tolerance 1e-7 on the same mesh (every pair below the kernel's most order gets more
//    points): measured changes 3e-8 .. 8e-7;
//  - tolerance 1e-7 and every cell within 3 r0 of the gap split in four (the pairs in contact,
//    which the first way leaves at the kernel's most order, then have half the size over gap).
//    Splitting also moves the cutoff, which acts on the cells' boxes: at the default 10 r0 that
//    alone moves the force by 4e-4 .. 8e-4 (falling as cutoff^-3), so this comparison runs at
//    25 r0, where the changes are 1.7e-5 .. 4.8e-5 (an upper bound of the quadrature's part).
// Both stay within the tolerance: each pair's error is bounded by the tolerance times the larger
// of its repulsive and attractive parts, and those sum to the order of the force here.
TEST(InteractionSetup, Method1ForceDoesNotMoveWhenItsQuadratureIsRaised) {
  auto sphereForce = [](Real gammaL, Real zone, int level, Real cutoff, Real tolerance, bool split) {
    Teuchos::ParameterList list;
    list.set("Method", std::string("volume pair"));
    list.set("gammaL", gammaL);
    list.set("Cutoff", cutoff);
    list.set("Volume Quadrature Tolerance", tolerance);
    const auto s = setUp(list);
    const auto model = benchmark(Formulation::Axisymmetric, s.contactDistance(), 1, level, zone);
    if (!split && tolerance >= 1e-4) s.checkMesh(*model.mesh, Formulation::Axisymmetric);  // accepted as the user gets it
    const mesh::Mesh m = split ? splitNearTheGap(*model.mesh, s.potential->r0()) : *model.mesh;
    VolumeInteraction vi(m, std::vector<Real>(std::size_t(m.numBodies), s.density), s.potential, s.volumeOptions);
    vi.updatePairs(m.coords.data());
    vi.evaluate(m.coords.data(), [](const auto&, long) {}, false);
    if (tolerance >= 1e-4) {
      EXPECT_EQ(vi.summary().numAboveTolerance, 0);  // the raised runs cap the pairs in contact
    }
    const std::vector<std::string> names = mesh::bodyNames(*model.mesh);
    const auto sphere = std::find(names.begin(), names.end(), "sphere") - names.begin();
    return vi.summary().resultant.at(std::size_t(sphere))[1];
  };
  const Real tolerance = 1e-4;
  for (const auto& [gammaL, zone] : {std::pair{50.0, 0.5}, std::pair{200.0, 0.5 * 0.336}})
    for (int level : {0, 1})
      for (Real cutoff : {10.0, 25.0}) {
        const bool split = cutoff > 10.0;
        const Real f = sphereForce(gammaL, zone, level, cutoff, tolerance, false);
        const Real raised = sphereForce(gammaL, zone, level, cutoff, 1e-7, split);
        const Real change = std::abs(raised / f - 1.0);
        std::printf("[method 1] gammaL = %3.0f level %d cutoff %2.0f r0%s: sphere's force %.8e, raised %.8e: %.1e\n",
                    gammaL, level, cutoff, split ? ", split" : "", f, raised, change);
        EXPECT_LT(change, tolerance) << "gammaL " << gammaL << " level " << level << " cutoff " << cutoff;
      }
}

}  // namespace
