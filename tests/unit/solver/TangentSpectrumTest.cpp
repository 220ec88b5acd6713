// The tangent's spectrum (TangentSpectrum): Anasazi's Krylov-Schur against
// LAPACK on the spring chain (ChainModel.hpp), the count of negative
// eigenvalues against the closed-form stability of the chain's branches, and
// the constrained dofs of a finite-element tangent left out.
#include <gtest/gtest.h>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Core.hpp>

#include <cmath>
#include <cstdio>

#include "ChainModel.hpp"
#include "TestSystem.hpp"
#include "cgcm/io/Deck.hpp"
#include "cgcm/solver/LinearSolver.hpp"
#include "cgcm/solver/TangentSpectrum.hpp"

namespace cgcm {
namespace {

using test::ChainModel;
using test::LennardJonesWall;

Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> directSolver() {
  Teuchos::ParameterList settings("Linear Solver");
  settings.setParameters(*solver::linearSolverValidParameters());
  return solver::buildLinearSolver(settings, Tpetra::getDefaultComm()->getSize(), 1);
}

Real maxAbsDifference(const assembly::Vector& a, const assembly::Vector& b) {
  assembly::Vector d(a, Teuchos::Copy);
  d.update(-1.0, b, 1.0);
  return d.normInf();
}

// 300 springs: more free dofs than the dense bound, so that the default path is Anasazi's.
TEST(TangentSpectrum, KrylovSchurAgreesWithLapackAndTheNegativeCountWithTheChainsBranches) {
  LennardJonesWall wall;
  auto model = Teuchos::rcp(new ChainModel(Tpetra::getDefaultComm(), 300, 300.0, 1.0, wall, directSolver()));
  solver::TangentSpectrum krylov(model, 4), dense(model, 4, 1000);
  // K = k/n = 1: the folds where phi''(g) = -1; the loop's unstable branch lies between them
  int unstableStates = 0;
  for (double g : {2.0, 1.4, 1.3, 1.2, 1.15, 1.1, 1.02}) {
    SCOPED_TRACE("tip gap " + std::to_string(g));
    const auto x = model->stateOf(g);
    const std::vector<Real> p{model->lambdaOf(g)};
    const auto a = krylov.compute(*x, p), b = dense.compute(*x, p);
    ASSERT_EQ(a.eigenvalues.size(), 4u);
    ASSERT_EQ(b.eigenvalues.size(), 4u);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(a.eigenvalues[k], b.eigenvalues[k], 1e-9 * std::abs(b.eigenvalues[k]) + 1e-11);
    EXPECT_EQ(a.negative, b.negative);
    // the branch between the folds has one negative eigenvalue, the tip's mode: with the chain's stiffness K = k/n
    // condensed onto the tip, J is positive definite exactly where K + phi''(g) > 0
    const bool stable = model->K() + wall.ddphi(g) > 0.0;
    EXPECT_EQ(a.negative, stable ? 0 : 1);
    EXPECT_EQ(a.stable(), stable);
    unstableStates += stable ? 0 : 1;
    EXPECT_LT(maxAbsDifference(*a.mode(), *b.mode()), 1e-6);
    EXPECT_NEAR(a.mode()->normInf(), 1.0, 1e-14);
  }
  EXPECT_GE(unstableStates, 2);
}

// On a finite-element tangent the constrained dofs (unit rows) are not part of the spectrum: the mode is 0 on
// them and an eigenvector of the free block, K_FF v = lambda v, checked with the matrix's own apply.
TEST(TangentSpectrum, TheConstrainedDofsOfAFiniteElementTangentAreLeftOut) {
  auto d = Teuchos::rcp(new Teuchos::ParameterList("cgcm"));
  io::applyOverrides(*d, *test::deckParameters(),
                     {"Geometry/Type=block", "Problem/Formulation=plane strain", "Geometry/Block/Cells X=8",
                      "Geometry/Block/Cells Y=8", "Geometry/Block/Distortion=0.2"});
  io::validateDeck(*d, *test::deckParameters());
  const auto setup = test::setupOf(*d);
  auto disc = solver::discretize(Tpetra::getDefaultComm(), setup, d->sublist("Solver").sublist("Linear Solver"));
  assembly::Vector x(disc.model->map());
  disc.model->setDisplacement(-0.1);
  disc.dirichlet->impose(-0.1, x);  // a state off equilibrium (the interior at rest: an indefinite tangent) is as good as any for the algebra
  const std::vector<Real> p{-0.1};
  solver::TangentSpectrum krylov(disc.model, 3, 0), dense(disc.model, 3, 100000);
  const auto a = krylov.compute(x, p), b = dense.compute(x, p);
  ASSERT_EQ(a.eigenvalues.size(), 3u);
  // Anasazi converges to a relative residual of 1e-10 of the inverse problem: eigenvalues to about 1e-9
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(a.eigenvalues[k], b.eigenvalues[k], 1e-8 * std::abs(b.eigenvalues[k]));
  EXPECT_EQ(a.negative, b.negative);
  // K v on the free rows = lambda v; v = 0 on the constrained dofs
  auto W = disc.model->create_W_op();
  {
    auto in = disc.model->createInArgs();
    in.set_x(Thyra::createConstVector<Real, LocalIndex, GlobalIndex, assembly::Node>(
        Teuchos::rcp(new assembly::Vector(x, Teuchos::Copy)), disc.model->get_x_space()));
    auto out = disc.model->createOutArgs();
    out.set_W_op(W);
    disc.model->evalModel(in, out);
  }
  using Extract = Thyra::TpetraOperatorVectorExtraction<Real, LocalIndex, GlobalIndex, assembly::Node>;
  auto K = Extract::getConstTpetraOperator(W);
  assembly::Vector Kv(disc.model->map());
  K->apply(*a.mode(), Kv);
  Real worstFree = 0.0, worstConstrained = 0.0;
  {
    auto A = Teuchos::rcp_dynamic_cast<const assembly::CrsMatrix>(K, true);
    auto kv = Kv.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto v = a.mode()->getLocalViewHost(Tpetra::Access::ReadOnly);
    typename assembly::CrsMatrix::local_inds_host_view_type cols;
    typename assembly::CrsMatrix::values_host_view_type vals;
    for (LocalIndex r = 0; r < LocalIndex(A->getNodeNumRows()); ++r) {
      A->getLocalRowView(r, cols, vals);
      const bool unit = cols.extent(0) > 0 && [&] {
        for (std::size_t k = 0; k < cols.extent(0); ++k) {
          const bool diagonal = A->getColMap()->getGlobalElement(cols(k)) == A->getRowMap()->getGlobalElement(r);
          if (vals(k) != (diagonal ? 1.0 : 0.0)) return false;
        }
        return true;
      }();
      if (unit)
        worstConstrained = std::max(worstConstrained, std::abs(v(r, 0)));
      else
        worstFree = std::max(worstFree, std::abs(kv(r, 0) - a.eigenvalues[0] * v(r, 0)));
    }
  }
  Real free = 0.0, constrained = 0.0;
  const auto& comm = *disc.model->map()->getComm();
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, worstFree, Teuchos::outArg(free));
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, worstConstrained, Teuchos::outArg(constrained));
  EXPECT_LT(constrained, 1e-12);  // round-off of the dense solver; Anasazi's are exact zeros
  EXPECT_LT(free, 1e-8 * Kv.normInf());
  EXPECT_LT(maxAbsDifference(*a.mode(), *b.mode()), 1e-6);
}

// Method 3's tangent is not symmetric: its eigenvalues by Anasazi's non-Hermitian Krylov-Schur against LAPACK's
// dgeev, on the benchmark (plane strain, coarse) at the undeformed state, the bodies at the equilibrium gap.
TEST(TangentSpectrum, TheUnsymmetricTangentOfMethod3) {
  auto d = Teuchos::rcp(new Teuchos::ParameterList("cgcm"));
  io::applyOverrides(*d, *test::deckParameters(), {"Problem/Formulation=plane strain", "Geometry/Mesh Refinement=-1"});
  io::validateDeck(*d, *test::deckParameters());
  const auto setup = test::setupOf(*d);
  auto disc = solver::discretize(Tpetra::getDefaultComm(), setup, d->sublist("Solver").sublist("Linear Solver"));
  assembly::Vector x(disc.model->map());
  const auto p = disc.model->parameters();
  solver::TangentSpectrum krylov(disc.model, 4, 0), dense(disc.model, 4, 100000);
  const auto a = krylov.compute(x, p), b = dense.compute(x, p);
  EXPECT_FALSE(a.symmetric);
  EXPECT_FALSE(b.symmetric);
  ASSERT_EQ(a.eigenvalues.size(), 4u);
  ASSERT_EQ(b.eigenvalues.size(), 4u);
  for (int k = 0; k < 4; ++k) {
    EXPECT_NEAR(a.eigenvalues[k], b.eigenvalues[k], 1e-8 * std::abs(b.eigenvalues[k]));
    EXPECT_NEAR(a.imaginaryParts[k], b.imaginaryParts[k], 1e-8 * std::abs(b.eigenvalues[k]));
  }
  EXPECT_EQ(a.negative, b.negative);
  EXPECT_TRUE(a.complete);  // the sign of det K_FF agrees with the negative real eigenvalues found
  if (b.imaginaryParts[0] == 0.0) {
    EXPECT_LT(maxAbsDifference(*a.mode(), *b.mode()), 1e-6);
  }
  std::printf("Method 3 tangent at the equilibrium gap: eigenvalues %.6e %.6e %.6e %.6e, %d negative\n",
              b.eigenvalues[0], b.eigenvalues[1], b.eigenvalues[2], b.eigenvalues[3], b.negative);
}

}  // namespace
}  // namespace cgcm
