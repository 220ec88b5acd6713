// One Newton iteration of the bulk problem, timed in parts: residual
// assembly, Jacobian assembly (residual + tangent + matrix fill), Dirichlet
// rows, linear solve (set-up + solve). Prints one line per case.
//
//   bench_newton_iteration [3D NX NY NZ | axisymmetric NX NY] [SOLVER] [REPEATS] [NULL SPACE]
//   SOLVER: a "Solver/Linear Solver/Type" value (default: auto)
//   NULL SPACE (MueLu): "translations" (default, as cgcm runs by default: one unit
//   vector per component) or "rigid" (translations and rotations, "MueLu Near
//   Null Space = rigid body modes")
#include <Teuchos_CommHelpers.hpp>
#include <Thyra_LinearOpWithSolveFactoryHelpers.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Tpetra_Core.hpp>

#include <cstdio>
#include <iostream>
#include <string>

#include "cgcm/assembly/Problem.hpp"
#include "cgcm/assembly/Dirichlet.hpp"
#include "cgcm/core/MallocTunables.hpp"
#include "cgcm/mesh/Generators.hpp"
#include "cgcm/solver/LinearSolver.hpp"
#include "BenchSupport.hpp"

using namespace cgcm;
using bench::Clock;
using bench::secondsSince;

int main(int argc, char** argv) {
  cgcm::core::tuneMalloc(argv);
  Tpetra::ScopeGuard scope(&argc, &argv);
  auto comm = Tpetra::getDefaultComm();
  const bool root = comm->getRank() == 0;
  std::vector<std::string> a(argv + 1, argv + argc);
  if (a.empty()) a = {"3D", "32", "32", "32"};
  const bool threeD = a[0] == "3D";
  std::size_t k = 1;
  const int nx = std::stoi(a.at(k++)), ny = std::stoi(a.at(k++)), nz = threeD ? std::stoi(a.at(k++)) : 0;
  const std::string solverType = k < a.size() ? a[k++] : "auto";
  const int repeats = k < a.size() ? std::stoi(a[k++]) : 3;
  const std::string nullSpace = k < a.size() ? a[k++] : "translations";
  if (nullSpace != "rigid" && nullSpace != "translations") {
    if (root) std::fprintf(stderr, "NULL SPACE = \"%s\": expected \"rigid\" or \"translations\"\n", nullSpace.c_str());
    return 2;
  }

  auto mesh = std::make_shared<mesh::Mesh>();
  Formulation form;
  std::vector<std::pair<std::string, int>> fixed;
  std::string loaded;
  if (threeD) {
    mesh::BoxSpec s;
    s.nx = nx, s.ny = ny, s.nz = nz;
    *mesh = mesh::box(s);
    form = Formulation::ThreeD;
    fixed = {{"xmin", 0}, {"ymin", 1}, {"zmin", 2}, {"zmax", 0}, {"zmax", 1}};
    loaded = "zmax";
  } else {
    mesh::RectangleSpec s;
    s.nx = nx, s.ny = ny;
    *mesh = mesh::rectangle(s);
    form = Formulation::Axisymmetric;
    fixed = {{"left", 0}, {"bottom", 1}, {"top", 0}};
    loaded = "top";
  }
  const int dim = formulationDim(form);
  auto dofs = Teuchos::rcp(new assembly::DofMap(comm, *mesh, dim));
  assembly::Problem problem(dofs, mesh, form, material::NeoHookean::fromYoungPoisson(1.0, 0.3));
  assembly::DirichletConditions bc(dofs);
  for (const auto& [set, c] : fixed) bc.add(mesh->nodeSet(set), c, 0.0, 0.0);
  bc.add(mesh->nodeSet(loaded), dim - 1, 0.0, 1.0);

  Teuchos::ParameterList settings;
  settings.set("Type", solverType);
  settings.validateParametersAndSetDefaults(*solver::linearSolverValidParameters());
  auto factory = solver::buildLinearSolver(
      settings, comm->getSize(), dim,
      nullSpace == "rigid" ? assembly::rigidBodyModes(*dofs, *mesh, form) : Teuchos::null,
      /*symmetric=*/true);  // no interaction

  assembly::Vector u(dofs->ownedMap()), f(dofs->ownedMap()), du(dofs->ownedMap());
  const double load = -0.05;
  {
    // first Newton iteration of a 5 % compression step, from a smooth guess
    auto uv = u.getLocalViewHost(Tpetra::Access::ReadWrite);
    const auto& map = *dofs->ownedMap();
    for (std::size_t lid = 0; lid < map.getNodeNumElements(); ++lid) {
      const auto gid = map.getGlobalElement(LocalIndex(lid));
      if (gid % dim == dim - 1) uv(lid, 0) = load * 0.9 * mesh->coord(LocalIndex(gid / dim), dim - 1);
    }
  }
  bc.impose(load, u);
  auto J = problem.createMatrix();

  double tRes = 1e30, tJac = 1e30, tBc = 1e30, tSolve = 1e30;
  int krylovIterations = 0;
  for (int r = 0; r < repeats; ++r) {
    comm->barrier();
    auto t = Clock::now();
    problem.evaluate(u, f, nullptr);
    comm->barrier();
    tRes = std::min(tRes, secondsSince(t));
    t = Clock::now();
    problem.evaluate(u, f, J.get());
    comm->barrier();
    tJac = std::min(tJac, secondsSince(t));
    t = Clock::now();
    bc.applyToResidual(u, load, f);
    bc.applyToJacobian(*J);
    comm->barrier();
    tBc = std::min(tBc, secondsSince(t));
    t = Clock::now();
    auto space = Thyra::createVectorSpace<Real>(dofs->ownedMap());
    Teuchos::RCP<const Thyra::LinearOpBase<Real>> op = Thyra::tpetraLinearOp<Real, LocalIndex, GlobalIndex, assembly::Node>(
        space, space, Teuchos::rcp_implicit_cast<assembly::Operator>(J));
    auto lows = Thyra::linearOpWithSolve(*factory, op);
    const auto solved = bench::solve(*lows, space, f, du);
    comm->barrier();
    tSolve = std::min(tSolve, secondsSince(t));
    if (!solved.converged && root) std::printf("  (linear solve unconverged)\n");
    krylovIterations = solved.iterations;
  }
  // residual of the linear solve, as a check that the numbers are for a real solve
  assembly::Vector r(dofs->ownedMap());
  J->apply(du, r);
  r.update(-1.0, f, 1.0);
  const double rel = r.norm2() / f.norm2();
  const long long cells = mesh->numCells();
  if (root)
    std::printf("%-13s %7lld cells %9lld dofs  np=%d  residual %8.4f s  jacobian %8.4f s (%6.2f us/cell/rank)  "
                "bc %7.4f s  solve[%s, %s] %8.3f s (%d iterations)  |J du - f|/|f| = %.1e\n",
                formulationName(form), cells, (long long)dofs->ownedMap()->getGlobalNumElements(),
                comm->getSize(), tRes, tJac, 1e6 * tJac * comm->getSize() / cells, tBc, solverType.c_str(),
                nullSpace.c_str(), tSolve, krylovIterations, rel);
  return 0;
}
