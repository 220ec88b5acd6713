// System-level tests of assembly + Newton + load stepping on homogeneous and
// inhomogeneous large-deformation problems with closed-form or FD references.
#include <gtest/gtest.h>

#include <Teuchos_CommHelpers.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Tpetra_Core.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <regex>

#include "ClosedForm.hpp"
#include "TestSystem.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/io/Deck.hpp"
#include "cgcm/solver/Convergence.hpp"
#include "cgcm/solver/LinearSolver.hpp"
#include "cgcm/solver/LoadStepper.hpp"
#include "cgcm/solver/PseudoTransientModel.hpp"

namespace cgcm {
namespace {

using Teuchos::ParameterList;
using Teuchos::RCP;

/// `call` must throw E with a message in which `pattern` is found (std::regex_search).
template <class E, class F>
void expectThrowMatching(F&& call, const std::string& pattern) {
  try {
    call();
    ADD_FAILURE() << "no exception";
  } catch (const E& e) {
    EXPECT_TRUE(std::regex_search(e.what(), std::regex(pattern))) << e.what();
  }
}

// A block deck (the bulk problems of these tests) with the given overrides.
RCP<ParameterList> deck(const std::vector<std::string>& overrides) {
  auto d = Teuchos::rcp(new ParameterList("cgcm"));
  io::applyOverrides(*d, *test::deckParameters(), {"Geometry/Type=block"});
  io::applyOverrides(*d, *test::deckParameters(), overrides);
  io::validateDeck(*d, *test::deckParameters());
  return d;
}

// The assembled problem of a deck, ready for Newton.
struct System {
  solver::ProblemSetup setup;
  std::shared_ptr<const mesh::Mesh> mesh;  ///< the mesh this rank assembles (its part on several ranks)
  RCP<assembly::DofMap> dofs;
  std::shared_ptr<assembly::Problem> problem;
  std::shared_ptr<assembly::DirichletConditions> dirichlet;
  RCP<solver::ModelEvaluator> model;

  explicit System(const ParameterList& d) : setup(test::setupOf(d)) {
    auto comm = Tpetra::getDefaultComm();
    auto disc = solver::discretize(comm, setup, d.sublist("Solver").sublist("Linear Solver"));
    mesh = disc.mesh;
    dofs = disc.dofs;
    problem = disc.problem;
    dirichlet = disc.dirichlet;
    model = disc.model;
  }
};

// One Newton solve from rest at load `load` (the Dirichlet values imposed first).
solver::NewtonResult solveFromRest(System& sys, const solver::NewtonSettings& settings, Real load) {
  solver::NewtonSolver newton(sys.model, settings);
  assembly::Vector u(sys.model->map());
  sys.model->setDisplacement(load);
  sys.dirichlet->impose(load, u);
  return newton.solve(u);
}

const char* kFormulations[] = {"plane strain", "axisymmetric", "3D"};

using test::lateralDirections;

TEST(LoadStepping, PatchTestOnDistortedMeshesReproducesHomogeneousDeformation) {
  for (std::string form : kFormulations) {
    for (std::string element : {"hex8", "tet4"}) {
      if (form != "3D" && element == "tet4") continue;
      SCOPED_TRACE(form + " " + element);
      auto d = deck({"Problem/Formulation=" + form, "Geometry/Block/Element=" + element,
                     "Geometry/Block/Cells X=3", "Geometry/Block/Cells Y=3", "Geometry/Block/Cells Z=3",
                     "Geometry/Block/Distortion=0.3", "Loading/Approach Path={0, -0.25}",
                     "Loading/Initial Increment=0.125", "Loading/Max Increment=0.125"});
      System sys(*d);
      solver::NewtonSettings exact;
      exact.residualTolerance = 1e-13;  // a patch test: to round-off
      solver::NewtonSolver newton(sys.model, exact);
      solver::LoadStepper stepper(sys.model, newton, solver::LoadPathSettings::fromParameters(d->sublist("Loading")));
      assembly::Vector u(sys.model->map());
      stepper.run(u, [](const solver::StepInfo&, const assembly::Vector&) {});

      const int dim = sys.setup.model.mesh->dim;
      double lateral = 1.0;
      test::uniaxialCauchyStress(sys.setup.material, 0.75, lateralDirections(form), lateral);
      auto uv = u.getLocalViewHost(Tpetra::Access::ReadOnly);
      const auto& map = *u.getMap();
      double maxError = 0.0;
      for (std::size_t lid = 0; lid < map.getNodeNumElements(); ++lid) {
        const auto gid = map.getGlobalElement(LocalIndex(lid));
        const LocalIndex node = LocalIndex(gid / dim);
        const int i = int(gid % dim);
        const double stretch = (i == dim - 1) ? 0.75 : lateral;
        const double exact = (stretch - 1.0) * sys.setup.model.mesh->coord(node, i);
        maxError = std::max(maxError, std::abs(uv(lid, 0) - exact));
      }
      double globalError = 0.0;
      Teuchos::reduceAll(*map.getComm(), Teuchos::REDUCE_MAX, maxError, Teuchos::outArg(globalError));
      EXPECT_LT(globalError, 1e-10);
    }
  }
}

TEST(Newton, ConvergesQuadraticallyOnLargeInhomogeneousDeformation) {
  // Clamped loaded face: inhomogeneous state; one 20 % step from rest.
  for (std::string form : kFormulations) {
    SCOPED_TRACE(form);
    auto d = deck({"Problem/Formulation=" + form, "Geometry/Block/Loaded Face=clamped", "Geometry/Block/Cells X=3",
                   "Geometry/Block/Cells Y=3", "Geometry/Block/Cells Z=3", "Loading/Approach Path={0, -0.2}",
                   "Loading/Initial Increment=0.2", "Loading/Max Increment=0.2"});
    System sys(*d);
    solver::NewtonSettings settings;
    settings.residualTolerance = 1e-14;
    solver::NewtonSolver newton(sys.model, settings);
    assembly::Vector u(sys.model->map());
    sys.model->setDisplacement(-0.2);
    sys.dirichlet->impose(-0.2, u);
    const auto r = newton.solve(u);
    ASSERT_TRUE(r.converged) << r.failure;
    EXPECT_LE(r.iterations, 8);
    const auto& n = r.residualNorms;
    int quadraticPairs = 0;
    for (std::size_t k = 1; k + 1 < n.size(); ++k) {
      const double rk = n[k] / n[0], rk1 = n[k + 1] / n[0];
      if (rk > 1e-2 || rk1 < 1e-12) continue;  // pre-asymptotic or at round-off
      EXPECT_LT(rk1, 10.0 * rk * rk) << "iteration " << k << ": " << rk << " -> " << rk1;
      ++quadraticPairs;
    }
    EXPECT_GE(quadraticPairs, 1);
  }
}

// A state needs one Newton update unless its starting point is exact: from
// rest with nothing loaded (f = 0) none is taken; from the solution perturbed
// by 1e-12 (|f| inside the tolerance, far above 1e-6 of it) one is.
TEST(Newton, AStartingPointInsideTheToleranceStillTakesOneUpdate) {
  auto d = deck({"Geometry/Block/Cells X=2", "Geometry/Block/Cells Y=2", "Geometry/Block/Cells Z=2"});
  System sys(*d);
  const solver::NewtonSettings settings;  // Residual Tolerance 1e-10
  const auto atRest = solveFromRest(sys, settings, 0.0);
  ASSERT_TRUE(atRest.converged) << atRest.failure;
  EXPECT_EQ(atRest.iterations, 0);
  solver::NewtonSolver newton(sys.model, settings);
  assembly::Vector u(sys.model->map());
  sys.model->setDisplacement(-0.05);
  sys.dirichlet->impose(-0.05, u);
  ASSERT_TRUE(newton.solve(u).converged);
  {  // a non-uniform perturbation of 1e-12 (a uniform one is a translation: no force)
    auto v = u.getLocalViewHost(Tpetra::Access::ReadWrite);
    for (std::size_t i = 0; i < v.extent(0); ++i) v(i, 0) += 1e-12 * std::sin(1.7 * double(i) + 0.3);
  }
  assembly::Vector f(sys.model->map());
  sys.model->evaluateUnconstrained(u, sys.model->parameters(), f);
  sys.dirichlet->applyToResidual(u, -0.05, f);
  EXPECT_LT(f.norm2(), settings.tolerance());
  EXPECT_GT(f.norm2(), solver::kStartingPointFraction * settings.tolerance());
  const auto again = newton.solve(u);
  ASSERT_TRUE(again.converged) << again.failure;
  EXPECT_EQ(again.iterations, 1);
}

TEST(ModelEvaluator, JacobianMatchesFiniteDifferencesOfResidual) {
  for (std::string form : kFormulations) {
    SCOPED_TRACE(form);
    auto d = deck({"Problem/Formulation=" + form, "Geometry/Block/Loaded Face=clamped", "Geometry/Block/Cells X=2",
                   "Geometry/Block/Cells Y=2", "Geometry/Block/Cells Z=2", "Geometry/Block/Distortion=0.2"});
    System sys(*d);
    const auto& map = sys.model->map();
    assembly::Vector u(map), v(map), Jv(map), fp(map), fm(map), up(map), um(map);
    u.randomize(-0.05, 0.05);
    v.randomize(-1.0, 1.0);
    sys.model->setDisplacement(-0.03);
    auto W = sys.problem->createMatrix();
    sys.problem->evaluate(u, fp, W.get());
    sys.dirichlet->applyToJacobian(*W);
    W->apply(v, Jv);
    const double h = 1e-6;
    up.update(1.0, u, h, v, 0.0);
    um.update(1.0, u, -h, v, 0.0);
    sys.problem->evaluate(up, fp, nullptr);
    sys.dirichlet->applyToResidual(up, -0.03, fp);
    sys.problem->evaluate(um, fm, nullptr);
    sys.dirichlet->applyToResidual(um, -0.03, fm);
    fp.update(-1.0 / (2 * h), fm, 1.0 / (2 * h));  // (f+ - f-)/2h
    fp.update(-1.0, Jv, 1.0);
    EXPECT_LT(fp.norm2(), 1e-6 * Jv.norm2());
  }
}

TEST(PseudoTransientModel, ResidualAndShiftedJacobianAreMxdotPlusFAndAlphaMPlusJ) {
  auto d = deck({"Problem/Formulation=plane strain", "Geometry/Block/Loaded Face=clamped", "Geometry/Block/Cells X=2",
                 "Geometry/Block/Cells Y=2", "Geometry/Block/Distortion=0.2"});
  System sys(*d);
  const auto& map = sys.model->map();
  assembly::Vector u(map), xDot(map), v(map);
  u.randomize(-0.05, 0.05);
  xDot.randomize(-1.0, 1.0);
  v.randomize(-1.0, 1.0);
  sys.model->setDisplacement(-0.03);
  sys.dirichlet->impose(-0.03, u);
  solver::PseudoTransientModel transient(sys.model);
  transient.setMassFromJacobian(u);
  // M: |diag J| on free rows, 0 on constrained ones.
  auto J = sys.problem->createMatrix();
  assembly::Vector f(map), diag(map);
  sys.problem->evaluate(u, f, J.get());
  sys.dirichlet->applyToResidual(u, -0.03, f);
  J->getLocalDiagCopy(diag);
  diag.abs(diag);
  sys.dirichlet->zeroConstrained(diag);
  assembly::Vector diff(map);
  diff.update(1.0, transient.mass(), -1.0, diag, 0.0);
  EXPECT_LT(diff.normInf(), 1e-14 * diag.normInf());
  EXPECT_GT(transient.mass().normInf(), 0.0);

  const double alpha = 3.7;
  auto in = transient.createInArgs();
  auto uc = Teuchos::rcp(new assembly::Vector(u, Teuchos::Copy));
  auto xc = Teuchos::rcp(new assembly::Vector(xDot, Teuchos::Copy));
  using TV = Tpetra::Vector<Real, LocalIndex, GlobalIndex, assembly::Node>;
  in.set_x(Thyra::createConstVector(Teuchos::rcp_implicit_cast<const TV>(uc)));
  in.set_x_dot(Thyra::createConstVector(Teuchos::rcp_implicit_cast<const TV>(xc)));
  in.set_p(0, sys.model->getNominalValues().get_p(0));
  in.set_alpha(alpha);
  in.set_beta(1.0);
  auto out = transient.createOutArgs();
  auto fT = Teuchos::rcp(new assembly::Vector(map));
  out.set_f(Thyra::createVector(Teuchos::rcp_implicit_cast<TV>(fT)));
  const auto W = transient.create_W_op();
  out.set_W_op(W);
  transient.evalModel(in, out);
  // f_t = f + M x_dot
  assembly::Vector expected(map);
  expected.elementWiseMultiply(1.0, transient.mass(), xDot, 0.0);
  expected.update(1.0, f, 1.0);
  diff.update(1.0, *fT, -1.0, expected, 0.0);
  EXPECT_LT(diff.norm2(), 1e-12 * expected.norm2());
  // W v = J v + alpha M v (J with the constrained rows as unit rows)
  sys.dirichlet->applyToJacobian(*J);
  assembly::Vector Wv(map), Jv(map);
  using Extract = Thyra::TpetraOperatorVectorExtraction<Real, LocalIndex, GlobalIndex, assembly::Node>;
  Extract::getTpetraOperator(W)->apply(v, Wv);
  J->apply(v, Jv);
  expected.elementWiseMultiply(alpha, transient.mass(), v, 0.0);
  expected.update(1.0, Jv, 1.0);
  diff.update(1.0, Wv, -1.0, expected, 0.0);
  EXPECT_LT(diff.norm2(), 1e-12 * expected.norm2());
}

TEST(Newton, RelaxationEndsOnTheNewtonSolution) {
  // The clamped 20 % compression in one step: pseudo-transient relaxation
  // from rest reaches the state Newton reaches, with Newton's test.
  for (std::string form : {"plane strain", "axisymmetric"}) {
    SCOPED_TRACE(form);
    auto d = deck({"Problem/Formulation=" + form, "Geometry/Block/Loaded Face=clamped", "Geometry/Block/Cells X=3",
                   "Geometry/Block/Cells Y=3", "Loading/Approach Path={0, -0.2}"});
    System sys(*d);
    solver::NewtonSettings settings;
    settings.residualTolerance = 1e-12;
    settings.forceScale = sys.setup.forceScale;
    solver::NewtonSolver newton(sys.model, settings);
    assembly::Vector byNewton(sys.model->map()), byRelaxation(sys.model->map());
    sys.model->setDisplacement(-0.2);
    sys.dirichlet->impose(-0.2, byNewton);
    sys.dirichlet->impose(-0.2, byRelaxation);
    const auto rn = newton.solve(byNewton);
    ASSERT_TRUE(rn.converged) << rn.failure;
    solver::RelaxationSettings relax;
    relax.initialStep = 0.1;
    relax.maxIncrement = 0.05;
    const auto rr = newton.relax(byRelaxation, relax);
    ASSERT_TRUE(rr.converged) << rr.failure;
    EXPECT_LE(rr.residualNorms.back(), settings.tolerance());
    EXPECT_GT(rr.iterations, rn.iterations);  // it relaxed, with capped moves
    EXPECT_FALSE(rr.fell);                    // a stable state straight ahead: no snap
    byRelaxation.update(-1.0, byNewton, 1.0);
    EXPECT_LT(byRelaxation.normInf(), 1e-9);
  }
}

TEST(RuntimeFaults, InvertedCellsAndNonFiniteResidualsAreReportedWithWhere) {
  auto d = Teuchos::rcp(new ParameterList("cgcm"));
  io::validateDeck(*d, *test::deckParameters());
  System sys(*d);
  const auto& dofs = sys.dofs;
  const auto& problem = sys.problem;
  const auto& mesh = *sys.setup.model.mesh;
  // Node 0's first cell turned inside out: node 0 pushed far through it.
  assembly::Vector u(dofs->ownedMap()), f(dofs->ownedMap());
  const auto lid = dofs->ownedMap()->getLocalElement(GlobalIndex(0));  // node 0, x (global ids)
  if (lid != Teuchos::OrdinalTraits<LocalIndex>::invalid()) {
    u.replaceLocalValue(lid, 100.0 * mesh.coord(mesh.numNodes() - 1, 0) + 100.0);
  }
  expectThrowMatching<InvertedElementError>([&] { problem->evaluate(u, f, nullptr); },
                                            "[0-9]+ element\\(s\\) inverted \\(J <= 0\\), the first cell [0-9]+ of block "
                                            "\"[^\"]+\" \\(its first node [0-9]+ at X = \\(");
  // A NaN in a residual names its node and component.
  assembly::Vector g(dofs->ownedMap());
  const GlobalIndex dof = 3 * dofs->dofsPerNode() + 1;  // node 3, component 1
  const auto k = dofs->ownedMap()->getLocalElement(dof);
  const bool owner = k != Teuchos::OrdinalTraits<LocalIndex>::invalid();
  if (owner) g.replaceLocalValue(k, std::nan(""));
  // the scan is local: the owning rank names the node, the others see nothing
  if (owner)
    EXPECT_NE(problem->firstNonFinite(g).find("node 3, component 1"), std::string::npos) << problem->firstNonFinite(g);
  else
    EXPECT_TRUE(problem->firstNonFinite(g).empty()) << problem->firstNonFinite(g);
  g.putScalar(1.0);
  EXPECT_TRUE(problem->firstNonFinite(g).empty());
}

}  // namespace
}  // namespace cgcm

namespace cgcm {
namespace {

using Teuchos::ParameterList;

TEST(Interaction, UndeformedBenchmarkMeshGivesDerjaguinForceOnBothBodies) {
  // Undeformed sphere over the half-space at the equilibrium gap: the force on
  // each body is the rigid-sphere (Derjaguin) value, 2 pi w R up to the
  // curvature correction of a polygonal sphere at R/r0 = 50 (-0.9837, computed
  // independently by quadrature of T(h(rho)) 2 pi rho over the same polyline).
  auto d = Teuchos::rcp(new ParameterList("cgcm"));
  io::validateDeck(*d, *test::deckParameters());
  const auto s = test::setupOf(*d);
  const auto& in = *s.interaction;
  const auto created = in.create(*s.model.mesh);
  auto& si = dynamic_cast<interaction::SurfaceInteraction&>(*created);
  si.updatePairs(s.model.mesh->coords);
  std::vector<interaction::PairContribution> out;
  si.evaluate(s.model.mesh->coords, out, false);
  const double twoPiWR = 2 * cgcm::kPi * in.potential->workOfAdhesion(1.0, 1.0);
  const auto& r = si.summary().resultant;
  std::printf("resultants / 2 pi w R: sphere %.6f, half-space %.6f\n", r[0][1] / twoPiWR, r[1][1] / twoPiWR);
  EXPECT_NEAR(r[0][1] / twoPiWR, -0.9837, 0.005);
  EXPECT_NEAR(-r[1][1] / twoPiWR, -0.9837, 0.02);
}

}  // namespace
}  // namespace cgcm

namespace cgcm {
namespace {

using Teuchos::ParameterList;

TEST(Newton, BacktrackingLineSearchConverges) {
  auto d = deck({"Problem/Formulation=3D", "Geometry/Block/Loaded Face=clamped", "Solver/Newton/Line Search=backtrack"});
  System sys(*d);
  auto& model = sys.model;
  auto& bc = sys.dirichlet;
  auto settings = solver::NewtonSettings::fromParameters(d->sublist("Solver").sublist("Newton"),
                                                          d->sublist("Solver").sublist("Linear Solver"));
  settings.residualTolerance = 1e-12;
  solver::NewtonSolver newton(model, settings);
  assembly::Vector u(model->map());
  model->setDisplacement(-0.2);  // 20 % in one step from rest: the top cells start at J = 0.2
  bc->impose(-0.2, u);
  const auto r = newton.solve(u);
  ASSERT_TRUE(r.converged) << r.failure;
  EXPECT_LE(r.iterations, 10);
  EXPECT_LT(r.residualNorms.back(), 1e-9 * r.residualNorms.front());
}

TEST(LoadPath, AnEmptyLoadingListGetsTheDocumentedDefaultPath) {
  // Teuchos::Array has no initializer-list constructor: Array<double>{0.0, 0.1}
  // was an empty array, and a deck without an Approach Path was refused.
  ParameterList loading("Loading");
  loading.validateParametersAndSetDefaults(*solver::LoadPathSettings::validParameters());
  const auto s = solver::LoadPathSettings::fromParameters(loading);
  EXPECT_EQ(s.path, (std::vector<Real>{0.0, 0.1}));
}

TEST(Newton, AnUnconvergedLinearSolveIsNamedInTheFailure) {
  // Two GMRES iterations cannot solve the 3D block's Newton systems to 1e-12:
  // NOX goes on with the poor directions, fails, and the message says why.
  auto d = deck({"Problem/Formulation=3D", "Geometry/Block/Loaded Face=clamped",
                 "Solver/Linear Solver/Type=Belos GMRES + Ifpack2", "Solver/Linear Solver/Max Iterations=2",
                 "Solver/Linear Solver/Tolerance=1e-12"});
  System sys(*d);
  auto settings = solver::NewtonSettings::fromParameters(d->sublist("Solver").sublist("Newton"),
                                                          d->sublist("Solver").sublist("Linear Solver"));
  settings.maxIterations = 4;
  const auto r = solveFromRest(sys, settings, -0.2);
  ASSERT_FALSE(r.converged);
  EXPECT_TRUE(std::regex_search(r.failure, std::regex("the linear solve of Newton iteration [0-9]+ did not converge "
                                                      "\\(2 iterations, relative residual [-+.e0-9]+\\)")))
      << r.failure;
}

TEST(Newton, TheDecksLinearToleranceAndForcingTermReachEveryKrylovSolve) {
  // NOX hands its own tolerance to every linear solve; the deck's must be the one used. A loose constant
  // tolerance (1e-1) turns Newton's quadratic convergence linear (more iterations); Eisenstat-Walker from
  // the same minimum keeps it fast. Before the deck's value reached NOX, all three counts were equal.
  auto iterationsWith = [](const std::vector<std::string>& linear) {
    std::vector<std::string> o = {"Problem/Formulation=3D", "Geometry/Block/Loaded Face=clamped",
                                  "Solver/Linear Solver/Type=Belos GMRES + MueLu"};
    o.insert(o.end(), linear.begin(), linear.end());
    auto d = deck(o);
    System sys(*d);
    auto settings = solver::NewtonSettings::fromParameters(d->sublist("Solver").sublist("Newton"),
                                                          d->sublist("Solver").sublist("Linear Solver"));
    settings.residualTolerance = 1e-12;
    settings.maxIterations = 40;
    const auto r = solveFromRest(sys, settings, -0.2);
    EXPECT_TRUE(r.converged) << r.failure;
    return r.iterations;
  };
  const int tight = iterationsWith({"Solver/Linear Solver/Tolerance=1e-12"});
  const int loose = iterationsWith({"Solver/Linear Solver/Tolerance=1e-1"});
  const int adaptive = iterationsWith({"Solver/Linear Solver/Tolerance=1e-12", "Solver/Linear Solver/Forcing Term=Eisenstat-Walker"});
  std::printf("Newton iterations: linear tolerance 1e-12 %d, 1e-1 %d, Eisenstat-Walker %d\n", tight, loose, adaptive);
  EXPECT_LE(tight, 8);
  EXPECT_GE(loose, tight + 3) << "a 1e-1 linear tolerance cannot keep Newton quadratic";
  EXPECT_LE(adaptive, tight + 4);
}

TEST(LinearSolver, RigidBodyModesAreTheNullSpaceOfTheReferenceTangent) {
  // At x = X the tangent is the linear elasticity operator (no stress, no geometric term): translations and
  // rotations of the reference configuration give zero force, in 3D and plane strain; axisymmetry has none.
  for (std::string form : {"3D", "plane strain"}) {
    SCOPED_TRACE(form);
    auto d = deck({"Problem/Formulation=" + form, "Geometry/Block/Cells X=3", "Geometry/Block/Cells Y=2",
                   "Geometry/Block/Cells Z=2", "Solver/Linear Solver/Type=Belos GMRES + MueLu",
                   "Solver/Linear Solver/MueLu Near Null Space=rigid body modes"});
    System sys(*d);
    const auto modes = assembly::rigidBodyModes(*sys.dofs, *sys.mesh, sys.setup.formulation);
    ASSERT_FALSE(modes.is_null());
    const std::size_t expected = form == "3D" ? 6 : 3;
    ASSERT_EQ(modes->getNumVectors(), expected);
    assembly::Vector u(sys.dofs->ownedMap()), f(sys.dofs->ownedMap());
    auto J = sys.problem->createMatrix();
    sys.problem->evaluate(u, f, J.get());
    assembly::MultiVector Jm(sys.dofs->ownedMap(), modes->getNumVectors());
    J->apply(*modes, Jm);
    std::vector<Real> force(expected), size(expected);
    Jm.norm2(force);
    modes->norm2(size);
    for (std::size_t m = 0; m < expected; ++m) EXPECT_LT(force[m], 1e-12 * size[m]) << "mode " << m;
    // and MueLu takes them: a Newton step of the compressed block converges
    const auto r = solveFromRest(sys, solver::NewtonSettings{}, -0.1);
    EXPECT_TRUE(r.converged) << r.failure;
  }
  auto axi = deck({"Problem/Formulation=axisymmetric"});
  System sys(*axi);
  EXPECT_TRUE(assembly::rigidBodyModes(*sys.dofs, *sys.mesh, sys.setup.formulation).is_null());
}

TEST(Interaction, EntriesOutsideTheGraphAreDetectedAndTheGraphRebuilt) {
  // Graph built with the sphere far away (no interaction couplings), Jacobian
  // evaluated with the sphere at the equilibrium gap: the interaction entries
  // would be dropped, so the evaluation must fail until the graph is refreshed.
  auto d = Teuchos::rcp(new ParameterList("cgcm"));
  io::validateDeck(*d, *test::deckParameters());
  System sys(*d);
  const auto& dofs = sys.dofs;
  const auto& problem = sys.problem;
  assembly::Vector far(dofs->ownedMap()), near(dofs->ownedMap()), f(dofs->ownedMap());
  assembly::DirichletConditions lift(dofs);
  lift.add(sys.mesh->nodeSet("upper body"), 1, 0.0, 1.0);
  lift.impose(1.0, far);  // the sphere one radius higher
  EXPECT_TRUE(problem->updateInteractionGraph(far));
  auto J = problem->createMatrix();
  // says where: a row node and the column node it lacks
  expectThrowMatching<assembly::GraphOutdatedError>(
      [&] { problem->evaluate(near, f, J.get()); },
      "outside the matrix graph \\(the first at row node [0-9]+, column node [0-9]+\\)");
  EXPECT_TRUE(problem->updateInteractionGraph(near));
  EXPECT_FALSE(problem->updateInteractionGraph(near));  // nothing new
  J = problem->createMatrix();
  EXPECT_NO_THROW(problem->evaluate(near, f, J.get()));
}

}  // namespace
}  // namespace cgcm

namespace cgcm {
namespace {

TEST(ModelEvaluator, ParameterDerivativeMatchesFiniteDifferences) {
  // DfDp (used by continuation) against FD of the residual in the load parameter.
  using MEB = Thyra::ModelEvaluatorBase;
  using Extract = Thyra::TpetraOperatorVectorExtraction<Real, LocalIndex, GlobalIndex, assembly::Node>;
  auto d = Teuchos::rcp(new Teuchos::ParameterList("cgcm"));
  io::applyOverrides(*d, *test::deckParameters(), {"Geometry/Type=block", "Problem/Formulation=plane strain"});
  io::validateDeck(*d, *test::deckParameters());
  System sys(*d);
  auto x = Thyra::createMember(sys.model->get_x_space());
  Extract::getTpetraVector(x)->randomize(-0.01, 0.01);
  auto evalF = [&](double p, const Teuchos::RCP<Thyra::VectorBase<Real>>& f,
                   const Teuchos::RCP<Thyra::MultiVectorBase<Real>>& dfdp) {
    auto in = sys.model->createInArgs();
    in.set_x(x);
    auto pv = Thyra::createMember(sys.model->get_p_space(0));
    Thyra::set_ele(0, p, pv.ptr());
    in.set_p(0, pv);
    auto out = sys.model->createOutArgs();
    out.set_f(f);
    if (!dfdp.is_null()) out.set_DfDp(0, MEB::Derivative<Real>(dfdp, MEB::DERIV_MV_BY_COL));
    sys.model->evalModel(in, out);
  };
  auto fp = Thyra::createMember(sys.model->get_f_space()), fm = Thyra::createMember(sys.model->get_f_space());
  auto dfdp = Thyra::createMembers(sys.model->get_f_space(), 1);
  evalF(-0.05 + 1e-6, fp, Teuchos::null);
  evalF(-0.05 - 1e-6, fm, Teuchos::null);
  evalF(-0.05, Thyra::createMember(sys.model->get_f_space()), dfdp);
  Thyra::Vp_StV(fp.ptr(), -1.0, *fm);
  Thyra::Vt_S(fp.ptr(), 1.0 / 2e-6);
  Thyra::Vp_StV(fp.ptr(), -1.0, *dfdp->col(0));
  EXPECT_LT(Thyra::norm_2(*fp), 1e-8 * Thyra::norm_2(*dfdp->col(0)));
  EXPECT_GT(Thyra::norm_2(*dfdp->col(0)), 1.0);  // one unit entry per loaded dof
}

}  // namespace
}  // namespace cgcm

namespace cgcm {
namespace {

// An unsymmetric tridiagonal matrix (a convection-diffusion stencil) on every
// rank's rows, with values scaled by `scale` and one more coupling in the rows
// below `widenBelow` (a new sparsity pattern; on two ranks, rows 0-9 are rank 0's only).
RCP<assembly::CrsMatrix> stencil(const RCP<const assembly::Map>& map, double scale, GlobalIndex widenBelow) {
  auto A = Teuchos::rcp(new assembly::CrsMatrix(map, 4));
  const GlobalIndex n = GlobalIndex(map->getGlobalNumElements());
  for (std::size_t k = 0; k < map->getNodeNumElements(); ++k) {
    const GlobalIndex i = map->getGlobalElement(LocalIndex(k));
    std::vector<GlobalIndex> cols{i};
    std::vector<double> vals{4.0 * scale};
    if (i > 0) cols.push_back(i - 1), vals.push_back(-1.5 * scale);
    if (i + 1 < n) cols.push_back(i + 1), vals.push_back(-0.5 * scale);
    if (i < widenBelow && i + 7 < n) cols.push_back(i + 7), vals.push_back(0.25 * scale);
    A->insertGlobalValues(i, Teuchos::ArrayView<const GlobalIndex>(cols), Teuchos::ArrayView<const double>(vals));
  }
  A->fillComplete();
  return A;
}

// MUMPS solves to round-off on any number of ranks, with either ordering and
// several right-hand sides, after new values on the same pattern and after a
// new pattern (also one that changes on one rank only, and one with more
// fill); a singular matrix is an error that says so.
TEST(LinearSolver, MumpsSolvesExactlyOnAnyNumberOfRanks) {
  auto comm = Tpetra::getDefaultComm();
  auto map = Teuchos::rcp(new assembly::Map(Tpetra::global_size_t(101), 0, comm));
  ParameterList settings("Linear Solver");
  settings.set("Type", "MUMPS");
  settings.validateParametersAndSetDefaults(*solver::linearSolverValidParameters());
  for (const char* ordering : {"AMD", "PORD"}) {
    SCOPED_TRACE(std::string("ordering ") + ordering);
    settings.set("MUMPS Ordering", ordering);
    const auto factory = solver::buildLinearSolver(settings, comm->getSize(), 1);
    const auto lows = factory->createOp();
    for (const auto& [scale, widenBelow] :
         {std::pair<double, GlobalIndex>{1.0, 0}, {3.0, 0}, {1.0, 10}, {1.0, 101}, {2.0, 101}}) {
      SCOPED_TRACE("scale " + std::to_string(scale) + ", extra couplings in rows below " + std::to_string(widenBelow));
      const auto A = stencil(map, scale, widenBelow);
      const auto op = Thyra::createConstLinearOp(Teuchos::rcp_implicit_cast<const assembly::Operator>(A));
      Thyra::initializeOp(*factory, op, lows.ptr());
      assembly::MultiVector exact(map, 2), b(map, 2), x(map, 2);
      exact.randomize();
      A->apply(exact, b);
      Thyra::solve(*lows, Thyra::NOTRANS, *Thyra::createConstMultiVector(Teuchos::rcp_implicit_cast<const assembly::MultiVector>(Teuchos::rcpFromRef(b))),
                   Thyra::createMultiVector(Teuchos::rcpFromRef(x)).ptr());
      x.update(-1.0, exact, 1.0);
      std::vector<double> err(2), size(2);
      x.normInf(err);
      exact.normInf(size);
      for (int k = 0; k < 2; ++k) EXPECT_LT(err[k], 1e-13 * size[k]) << "right-hand side " << k;
    }
  }
  const auto factory = solver::buildLinearSolver(settings, comm->getSize(), 1);

  // the stencil with an empty last row is singular
  auto singular = Teuchos::rcp(new assembly::CrsMatrix(map, 3));
  for (std::size_t k = 0; k < map->getNodeNumElements(); ++k) {
    const GlobalIndex i = map->getGlobalElement(LocalIndex(k));
    const double d = i == 100 ? 0.0 : 1.0;
    singular->insertGlobalValues(i, Teuchos::tuple<GlobalIndex>(i), Teuchos::tuple<double>(d));
  }
  singular->fillComplete();
  const auto op = Thyra::createConstLinearOp(Teuchos::rcp_implicit_cast<const assembly::Operator>(singular));
  const auto fresh = factory->createOp();
  expectThrowMatching<std::runtime_error>([&] { Thyra::initializeOp(*factory, op, fresh.ptr()); },
                                          "MUMPS factorisation failed .*singular");
}

// A symmetric positive definite stencil whose rows in `unitRows` are unit
// rows, their other entries kept in the pattern as zeros: a stiffness matrix
// with its Dirichlet rows replaced, symmetric no more.
RCP<assembly::CrsMatrix> withUnitRows(const RCP<const assembly::Map>& map, const std::vector<GlobalIndex>& unitRows) {
  auto A = Teuchos::rcp(new assembly::CrsMatrix(map, 3));
  const GlobalIndex n = GlobalIndex(map->getGlobalNumElements());
  for (std::size_t k = 0; k < map->getNodeNumElements(); ++k) {
    const GlobalIndex i = map->getGlobalElement(LocalIndex(k));
    const bool unit = std::find(unitRows.begin(), unitRows.end(), i) != unitRows.end();
    std::vector<GlobalIndex> cols{i};
    std::vector<double> vals{unit ? 1.0 : 2.5};
    for (const GlobalIndex j : {i - 1, i + 1})
      if (j >= 0 && j < n) cols.push_back(j), vals.push_back(unit ? 0.0 : -1.0);
    A->insertGlobalValues(i, Teuchos::ArrayView<const GlobalIndex>(cols), Teuchos::ArrayView<const double>(vals));
  }
  A->fillComplete();
  return A;
}

// CG with the unit rows eliminated symmetrically solves the unsymmetric
// system itself: large prescribed values on the unit rows, two right-hand
// sides, the tolerance asked for relative to |b| (the lifted right-hand side
// is larger), a new pattern, new values that make one more row a unit row
// on the same pattern, on any number of ranks. Its forward operator is the
// matrix with its unit rows.
TEST(LinearSolver, ConjugateGradientsSolveSystemsWithUnitRowsExactly) {
  auto comm = Tpetra::getDefaultComm();
  auto map = Teuchos::rcp(new assembly::Map(Tpetra::global_size_t(101), 0, comm));
  ParameterList settings("Linear Solver");
  settings.set("Type", "Belos CG + MueLu");
  settings.validateParametersAndSetDefaults(*solver::linearSolverValidParameters());
  const auto factory = solver::buildLinearSolver(settings, comm->getSize(), 1, Teuchos::null, true);
  const auto lows = factory->createOp();
  RCP<assembly::CrsMatrix> A;
  // new matrices; then the last one's values changed so that row 20 becomes a unit row (same graph)
  for (const auto& unitRows : {std::vector<GlobalIndex>{0, 37, 100}, std::vector<GlobalIndex>{0, 49, 50, 51, 100},
                               std::vector<GlobalIndex>{0, 20, 49, 50, 51, 100}}) {
    SCOPED_TRACE("unit rows " + std::to_string(unitRows.size()));
    if (unitRows.size() < 6) {
      A = withUnitRows(map, unitRows);
    } else {
      A->resumeFill();
      if (map->isNodeGlobalElement(20))
        A->replaceGlobalValues(20, Teuchos::tuple<GlobalIndex>(19, 20, 21), Teuchos::tuple<double>(0.0, 1.0, 0.0));
      A->fillComplete();
    }
    const auto op = Thyra::createConstLinearOp(Teuchos::rcp_implicit_cast<const assembly::Operator>(A));
    Thyra::initializeOp(*factory, op, lows.ptr());
    assembly::MultiVector exact(map, 2), b(map, 2), x(map, 2), Ax(map, 2);
    exact.randomize();
    for (const GlobalIndex i : unitRows)
      if (map->isNodeGlobalElement(i)) exact.replaceGlobalValue(i, 0, 100.0), exact.replaceGlobalValue(i, 1, -40.0);
    A->apply(exact, b);
    const auto bT = Thyra::createConstMultiVector(Teuchos::rcp_implicit_cast<const assembly::MultiVector>(Teuchos::rcpFromRef(b)));
    const auto xT = Thyra::createMultiVector(Teuchos::rcpFromRef(x));
    const Thyra::SolveCriteria<double> criteria(
        Thyra::SolveMeasureType(Thyra::SOLVE_MEASURE_NORM_RESIDUAL, Thyra::SOLVE_MEASURE_NORM_RHS), 1e-10);
    x.putScalar(0.0);
    const auto status = lows->solve(Thyra::NOTRANS, *bT, xT.ptr(), Teuchos::ptrFromRef(criteria));
    EXPECT_EQ(status.solveStatus, Thyra::SOLVE_STATUS_CONVERGED);
    A->apply(x, Ax);
    Ax.update(-1.0, b, 1.0);
    std::vector<double> residual(2), size(2), err(2), exactSize(2);
    Ax.norm2(residual);
    b.norm2(size);
    x.update(-1.0, exact, 1.0);
    x.normInf(err);
    exact.normInf(exactSize);
    for (int k = 0; k < 2; ++k) {
      EXPECT_LE(residual[k], 1e-10 * size[k]) << "right-hand side " << k;
      EXPECT_LT(err[k], 1e-8 * exactSize[k]) << "right-hand side " << k;
    }
    // the unit rows hold their values exactly
    x.update(1.0, exact, 1.0);
    for (const GlobalIndex i : unitRows)
      if (map->isNodeGlobalElement(i)) {
        const LocalIndex lid = map->getLocalElement(i);
        EXPECT_EQ(x.getData(0)[lid], 100.0);
        EXPECT_EQ(x.getData(1)[lid], -40.0);
      }
    // the forward operator is A
    Thyra::apply(*lows, Thyra::NOTRANS, *Thyra::createConstMultiVector(Teuchos::rcp_implicit_cast<const assembly::MultiVector>(Teuchos::rcpFromRef(exact))),
                 Thyra::createMultiVector(Teuchos::rcpFromRef(Ax)).ptr());
    Ax.update(-1.0, b, 1.0);
    Ax.normInf(err);
    for (int k = 0; k < 2; ++k) EXPECT_EQ(err[k], 0.0);
  }
}

// A tridiagonal stencil on `map`: `diagonal` on the diagonal, -1 beside it (a 1D Laplacian shifted by
// diagonal - 2). Given A, its values are replaced on its own graph.
RCP<assembly::CrsMatrix> tridiagonal(const RCP<const assembly::Map>& map, double diagonal,
                                     RCP<assembly::CrsMatrix> A = Teuchos::null) {
  const bool fill = A.is_null();
  if (fill) A = Teuchos::rcp(new assembly::CrsMatrix(map, 3));
  else A->resumeFill();
  const GlobalIndex n = GlobalIndex(map->getGlobalNumElements());
  for (std::size_t k = 0; k < map->getNodeNumElements(); ++k) {
    const GlobalIndex i = map->getGlobalElement(LocalIndex(k));
    std::vector<GlobalIndex> cols{i};
    std::vector<double> vals{diagonal};
    for (const GlobalIndex j : {i - 1, i + 1})
      if (j >= 0 && j < n) cols.push_back(j), vals.push_back(-1.0);
    if (fill) A->insertGlobalValues(i, Teuchos::ArrayView<const GlobalIndex>(cols), Teuchos::ArrayView<const double>(vals));
    else A->replaceGlobalValues(i, Teuchos::ArrayView<const GlobalIndex>(cols), Teuchos::ArrayView<const double>(vals));
  }
  A->fillComplete();
  return A;
}

struct KrylovSolve {
  Thyra::ESolveStatus status;
  int iterations;           ///< Belos' count
  double relativeResidual;  ///< |b - A x| / |b| with A as it is now
};

// Initialises `lows` with A (through `factory`) and solves A x = 1 from x = 0 to 1e-10.
KrylovSolve initializeAndSolve(const Thyra::LinearOpWithSolveFactoryBase<double>& factory,
                               Thyra::LinearOpWithSolveBase<double>& lows, const RCP<assembly::CrsMatrix>& A) {
  const auto op = Thyra::createConstLinearOp(Teuchos::rcp_implicit_cast<const assembly::Operator>(A));
  Thyra::initializeOp(factory, op, Teuchos::ptrFromRef(lows));
  assembly::Vector b(A->getRowMap()), x(A->getRowMap()), r(A->getRowMap());
  b.putScalar(1.0);
  const auto bT = Thyra::createConstMultiVector(Teuchos::rcp_implicit_cast<const assembly::MultiVector>(Teuchos::rcpFromRef(b)));
  const auto xT = Thyra::createMultiVector(Teuchos::rcp_implicit_cast<assembly::MultiVector>(Teuchos::rcpFromRef(x)));
  const Thyra::SolveCriteria<double> criteria(
      Thyra::SolveMeasureType(Thyra::SOLVE_MEASURE_NORM_RESIDUAL, Thyra::SOLVE_MEASURE_NORM_RHS), 1e-10);
  const auto status = lows.solve(Thyra::NOTRANS, *bT, xT.ptr(), Teuchos::ptrFromRef(criteria));
  A->apply(x, r);
  r.update(1.0, b, -1.0);
  const auto& extra = status.extraParameters;
  return {status.solveStatus, extra.is_null() ? -1 : extra->get<int>("Belos/Iteration Count"), r.norm2() / b.norm2()};
}

// With Preconditioner Reuse the preconditioner of one Jacobian serves the next ones, and
// every solve still meets its tolerance with the current matrix. On shifted 1D Laplacians (diagonals E =
// 2.5, N = 4 and H = 2.01: MueLu's preconditioner of E serves N in 17 Krylov iterations against 13 fresh,
// N's serves H in 72 against 15): E's is kept for N while within the growth limit (1.5) until its age is up
// (3 later Jacobians); N's kept for H exceeds the limit, so the next Jacobian gets a fresh one; a
// preconditioner serves another matrix (graph) and another solve object of the same factory too (the
// interaction's graph changes from step to step); a kept one under which the solve fails (Max Iterations)
// is built anew and the solve repeated from where it stopped, its count the sum of both. Counts of a fresh
// preconditioner are compared with a solver without reuse to within 2 (MueLu's Chebyshev estimates its
// eigenvalue bound from a random vector), counts of the same preconditioner on the same matrix exactly.
TEST(LinearSolver, AKeptPreconditionerServesLaterJacobiansUntilItNoLongerPays) {
  auto comm = Tpetra::getDefaultComm();
  auto map = Teuchos::rcp(new assembly::Map(Tpetra::global_size_t(20000), 0, comm));
  auto factoryWith = [&](int reuse, int maxIterations) {
    ParameterList settings("Linear Solver");
    settings.set("Type", "Belos GMRES + MueLu");
    settings.set("Preconditioner Reuse", reuse);
    settings.set("Max Iterations", maxIterations);
    settings.validateParametersAndSetDefaults(*solver::linearSolverValidParameters());
    return solver::buildLinearSolver(settings, comm->getSize(), 1, Teuchos::null, false);
  };
  const double E = 2.5, N = 4.0, H = 2.01;
  const auto fresh = factoryWith(0, 1000);
  const auto freshLows = fresh->createOp();
  const int freshE = initializeAndSolve(*fresh, *freshLows, tridiagonal(map, E)).iterations;
  const int freshN = initializeAndSolve(*fresh, *freshLows, tridiagonal(map, N)).iterations;
  const int freshH = initializeAndSolve(*fresh, *freshLows, tridiagonal(map, H)).iterations;

  const auto reusing = factoryWith(3, 1000);
  const auto lows = reusing->createOp();
  auto A = tridiagonal(map, E);
  EXPECT_NEAR(initializeAndSolve(*reusing, *lows, A).iterations, freshE, 2) << "the first Jacobian builds one";
  int keptOnN = 0;
  for (int later = 1; later <= 3; ++later) {
    SCOPED_TRACE("later Jacobian " + std::to_string(later));
    A = tridiagonal(map, N, A);
    const KrylovSolve s = initializeAndSolve(*reusing, *lows, A);
    EXPECT_EQ(s.status, Thyra::SOLVE_STATUS_CONVERGED);
    EXPECT_LE(s.relativeResidual, 1e-10) << "the solve is with the current matrix";
    if (later == 1) keptOnN = s.iterations;
    EXPECT_EQ(s.iterations, keptOnN);
  }
  EXPECT_GT(keptOnN, freshN) << "E's preconditioner serves N, less well than N's own";
  EXPECT_LE(keptOnN, 1.5 * freshE) << "within the growth limit";
  A = tridiagonal(map, N, A);  // its age is up
  EXPECT_NEAR(initializeAndSolve(*reusing, *lows, A).iterations, freshN, 2);
  A = tridiagonal(map, H, A);  // N's kept for H: past the growth limit
  KrylovSolve s = initializeAndSolve(*reusing, *lows, A);
  EXPECT_LE(s.relativeResidual, 1e-10);
  const int keptOnH = s.iterations;
  EXPECT_GT(keptOnH, 1.5 * freshN);
  A = tridiagonal(map, H, A);  // so built anew
  EXPECT_NEAR(initializeAndSolve(*reusing, *lows, A).iterations, freshH, 2);
  // a new matrix (another graph) and another solve object of the same factory: H's is kept, and built on
  // the matrix it came from, it serves N in more iterations than N's own would need
  A = tridiagonal(map, N);
  const auto otherLows = reusing->createOp();
  s = initializeAndSolve(*reusing, *otherLows, A);
  EXPECT_LE(s.relativeResidual, 1e-10);
  EXPECT_GT(s.iterations, 1.5 * freshH);
  A = tridiagonal(map, N, A);  // past the growth limit: built anew
  EXPECT_NEAR(initializeAndSolve(*reusing, *otherLows, A).iterations, freshN, 2);

  // A limit on the Krylov iterations that only a fresh preconditioner meets
  ASSERT_GT(keptOnH, freshH + 4);
  const auto strict = factoryWith(3, freshH + 4);
  const auto strictLows = strict->createOp();
  A = tridiagonal(map, N);
  initializeAndSolve(*strict, *strictLows, A);
  A = tridiagonal(map, H, A);
  s = initializeAndSolve(*strict, *strictLows, A);
  EXPECT_EQ(s.status, Thyra::SOLVE_STATUS_CONVERGED);
  EXPECT_LE(s.relativeResidual, 1e-10);
  EXPECT_GT(s.iterations, freshH + 4) << "the failed attempt's iterations and the fresh solve's";
  EXPECT_LE(s.iterations, freshH + 4 + freshH + 2);
}

// MueLu's aggregation drops the weak couplings (below 0.02 of the diagonal) where bodies interact (the
// tangent is not symmetric) and keeps every coupling without an interaction, where dropping costs.
TEST(LinearSolver, MueLuDropsWeakCouplingsOnlyWhereBodiesInteract) {
  for (const std::string type : {"Belos GMRES + MueLu", "Belos CG + MueLu"})
    for (const bool symmetric : {false, true}) {
      if (type == "Belos CG + MueLu" && !symmetric) continue;  // refused (below)
      SCOPED_TRACE(type + (symmetric ? ", no interaction" : ", interaction"));
      ParameterList settings("Linear Solver");
      settings.set("Type", type);
      settings.validateParametersAndSetDefaults(*solver::linearSolverValidParameters());
      const auto p = solver::stratimikosParameters(settings, 1, 3, Teuchos::null, symmetric);
      const auto& muelu = p->sublist("Preconditioner Types").sublist("MueLu");
      if (symmetric) EXPECT_FALSE(muelu.isParameter("aggregation: drop tol"));
      else EXPECT_EQ(muelu.get<double>("aggregation: drop tol"), 0.02);
    }
}

TEST(LinearSolver, ConjugateGradientsAreRefusedForAnUnsymmetricTangent) {
  ParameterList settings("Linear Solver");
  settings.set("Type", "Belos CG + MueLu");
  settings.validateParametersAndSetDefaults(*solver::linearSolverValidParameters());
  expectThrowMatching<InputError>([&] { solver::buildLinearSolver(settings, 1, 3, Teuchos::null, false); },
                                  "Solver/Linear Solver/Type = \"Belos CG \\+ MueLu\" needs a symmetric tangent");
}

TEST(LinearSolver, AnUnknownMumpsOrderingIsRejectedByName) {
  ParameterList settings("Linear Solver");
  settings.set("MUMPS Ordering", "METIS");  // not in Debian's MUMPS
  expectThrowMatching<std::exception>(
      [&] { settings.validateParametersAndSetDefaults(*solver::linearSolverValidParameters()); },
      "\"MUMPS Ordering\" parameter");
}

}  // namespace
}  // namespace cgcm
