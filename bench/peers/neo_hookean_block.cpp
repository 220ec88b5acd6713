// cgcm's half of the peer comparison (bench/peers/compare_dolfinx.py): the
// compressible Neo-Hookean unit cube, n^3 hex8 cells, Y = 1, nu = 0.3, bottom
// clamped, top pressed down 10 % (u_z = -0.1, free laterally), 2x2x2 Gauss,
// solved by full Newton from u = 0 (the first iteration is the linear-elastic
// solution). The dolfinx worker
// (neo_hookean_block_dolfinx.py) solves the same problem the same way.
//
//   bench_peer_block N [SOLVER] [RTOL]
//   SOLVER: a "Solver/Linear Solver/Type" value (default: auto, which is Belos GMRES + MueLu;
//           compare_dolfinx.py asks for Belos CG + MueLu, the method of dolfinx's side)
//   RTOL:   relative tolerance |b - A x| / |b| of every linear solve (default 1e-8)
//
// Prints one JSON line on rank 0: sizes, Newton and Krylov counts, the top
// reaction force and the wall time over the whole Newton solve of residual
// assembly, Jacobian assembly (cgcm's includes the residual: one fused pass)
// and linear solves (solve_s, preconditioner set-up included; setup_s alone).
#include <Thyra_LinearOpWithSolveFactoryHelpers.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Tpetra_Core.hpp>

#include <cstdio>
#include <string>

#include "cgcm/assembly/Dirichlet.hpp"
#include "cgcm/assembly/Problem.hpp"
#include "cgcm/core/MallocTunables.hpp"
#include "cgcm/mesh/Generators.hpp"
#include "cgcm/solver/LinearSolver.hpp"
#include "../BenchSupport.hpp"

using namespace cgcm;
using bench::Clock;
using bench::secondsSince;

int main(int argc, char** argv) {
  cgcm::core::tuneMalloc(argv);
  Tpetra::ScopeGuard scope(&argc, &argv);
  auto comm = Tpetra::getDefaultComm();
  const bool root = comm->getRank() == 0;
  if (argc < 2 || argc > 4) {
    if (root) std::fprintf(stderr, "usage: bench_peer_block N [SOLVER] [RTOL]\n");
    return 2;
  }
  int n = 0;
  double rtol = 1e-8;
  try {
    n = std::stoi(argv[1]);
    if (argc > 3) rtol = std::stod(argv[3]);
  } catch (const std::exception&) {
  }
  if (n < 1 || !(rtol > 0)) {
    if (root) std::fprintf(stderr, "bench_peer_block: N must be a positive integer and RTOL a positive number\n");
    return 2;
  }
  const std::string solverType = argc > 2 ? argv[2] : "auto";
  const double press = -0.1, newtonTolerance = 1e-9;  // on |f|_2, as the dolfinx worker

  mesh::BoxSpec spec;
  spec.nx = spec.ny = spec.nz = n;
  auto mesh = std::make_shared<mesh::Mesh>(mesh::box(spec));
  const int dim = 3;
  auto dofs = Teuchos::rcp(new assembly::DofMap(comm, *mesh, dim));
  assembly::Problem problem(dofs, mesh, Formulation::ThreeD,
                            material::NeoHookean::fromYoungPoisson(1.0, 0.3));
  assembly::DirichletConditions bc(dofs);
  for (int c = 0; c < dim; ++c) bc.add(mesh->nodeSet("zmin"), c, 0.0, 0.0);
  bc.add(mesh->nodeSet("zmax"), 2, 0.0, 1.0);

  Teuchos::ParameterList settings;
  settings.set("Type", solverType);
  settings.set("Tolerance", rtol);
  try {
    settings.validateParametersAndSetDefaults(*solver::linearSolverValidParameters());
  } catch (const std::exception& e) {
    if (root) std::fprintf(stderr, "bench_peer_block: SOLVER = \"%s\": %s\n", solverType.c_str(), e.what());
    return 2;
  }
  auto factory = solver::buildLinearSolver(settings, comm->getSize(), dim, Teuchos::null, /*symmetric=*/true);

  const auto& map = *dofs->ownedMap();
  assembly::Vector u(dofs->ownedMap()), f(dofs->ownedMap()), du(dofs->ownedMap()), r(dofs->ownedMap());
  auto J = problem.createMatrix();
  auto space = Thyra::createVectorSpace<Real>(dofs->ownedMap());

  // One solver object re-initialised with each new Jacobian, as NOX does.
  Teuchos::RCP<const Thyra::LinearOpBase<Real>> op = Thyra::tpetraLinearOp<Real, LocalIndex, GlobalIndex, assembly::Node>(
      space, space, Teuchos::rcp_implicit_cast<assembly::Operator>(J));
  auto lows = factory->createOp();
  double tResidual = 0, tJacobian = 0, tSetup = 0, tSolve = 0, worstLinearResidual = 0;
  int newton = 0, krylov = 0, unconvergedSolves = 0;
  bool converged = false;
  for (; newton <= 20; ++newton) {
    comm->barrier();
    auto t = Clock::now();
    problem.evaluate(u, f, nullptr);
    bc.applyToResidual(u, press, f);
    comm->barrier();
    tResidual += secondsSince(t);
    if (f.norm2() < newtonTolerance) {
      converged = true;
      break;
    }
    t = Clock::now();
    problem.evaluate(u, f, J.get());
    bc.applyToResidual(u, press, f);
    bc.applyToJacobian(*J);
    comm->barrier();
    tJacobian += secondsSince(t);

    t = Clock::now();
    Thyra::initializeOp(*factory, op, lows.ptr());
    comm->barrier();
    tSetup += secondsSince(t);
    t = Clock::now();
    const auto solved = bench::solve(*lows, space, f, du);
    comm->barrier();
    tSolve += secondsSince(t);
    if (!solved.converged) ++unconvergedSolves;
    krylov += solved.iterations;
    J->apply(du, r);
    r.update(-1.0, f, 1.0);
    worstLinearResidual = std::max(worstLinearResidual, r.norm2() / f.norm2());
    u.update(-1.0, du, 1.0);
  }

  // Top reaction: the internal force on the pressed face, before boundary conditions.
  problem.evaluate(u, f, nullptr);
  double ownReaction = 0, reaction = 0;
  {
    auto fv = f.getLocalViewHost(Tpetra::Access::ReadOnly);
    for (const auto node : mesh->nodeSet("zmax")) {
      const auto lid = map.getLocalElement(GlobalIndex(node) * dim + 2);
      if (lid != Teuchos::OrdinalTraits<LocalIndex>::invalid()) ownReaction += fv(lid, 0);
    }
  }
  Teuchos::reduceAll(*comm, Teuchos::REDUCE_SUM, 1, &ownReaction, &reaction);
  if (root)
    std::printf("{\"code\": \"cgcm\", \"n\": %d, \"cells\": %lld, \"dofs\": %lld, \"ranks\": %d, \"solver\": \"%s\", "
                "\"rtol\": %g, \"converged\": %s, \"newton\": %d, \"krylov\": %d, \"unconverged_solves\": %d, \"worst_linear_residual\": %.2e, "
                "\"reaction\": %.12f, \"residual_s\": %.4f, \"residual_evaluations\": %d, \"jacobian_s\": %.4f, "
                "\"setup_s\": %.4f, \"solve_s\": %.4f}\n",
                n, (long long)mesh->numCells(), (long long)map.getGlobalNumElements(), comm->getSize(),
                solverType.c_str(), rtol, converged ? "true" : "false", newton, krylov, unconvergedSolves, worstLinearResidual, reaction,
                tResidual, newton + 1, tJacobian, tSetup, tSetup + tSolve);
  return converged ? 0 : 1;
}
