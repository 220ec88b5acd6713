#include "cgcm/solver/LinearSolver.hpp"

#include <iterator>
#include <string>
#include <vector>

#include <Stratimikos_DefaultLinearSolverBuilder.hpp>
#include <Stratimikos_MueLuHelpers.hpp>
#include <Teuchos_AbstractFactoryStd.hpp>
#include <Teuchos_StandardParameterEntryValidators.hpp>
#include <Thyra_Ifpack2PreconditionerFactory.hpp>

#include "cgcm/assembly/TpetraTypes.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/core/ParameterValidators.hpp"
#include "MumpsSolver.hpp"
#include "PreconditionerReuse.hpp"
#include "SymmetricElimination.hpp"

namespace cgcm::solver {

namespace {
const char* const kTypes[] = {"auto",
                              "MUMPS",
                              "Amesos2 KLU2",
                              "Belos GMRES + Ifpack2",
                              "Belos GMRES + MueLu",
                              "Belos CG + MueLu",
                              "Stratimikos"};

// "auto". 3D: GMRES + MueLu, also for a symmetric tangent: CG with the Dirichlet rows eliminated
// symmetrically took as long on the hex8 Neo-Hookean block (bench/peers, 108k unknowns, 4 interleaved runs:
// 2.9-3.2 s on one rank, 1.9-2.9 s on two, both): its cheaper iterations are paid for by building the
// eliminated copy and a slower first MueLu set-up on it (1.64-1.69 s against 1.33-1.36 s over the three
// set-ups of the Newton solve; doc/performance.md). MueLu against the others, measured on the tetrahedral
// quarter sphere on half-space (5.9k dofs, one rank): 0.32 s per solve against 1.1 s for KLU2 and 4 s for
// GMRES + RILUK(2).
// 2D: MUMPS. Measured on the default deck: on one rank 0.89 s against 1.48 s per Newton iteration for KLU2
// at Mesh Refinement 2 (40k unknowns, side by side on a loaded machine), 2.8 s against 4.0 s of linear
// solves over the level-0 path; on two ranks at level 1 14.5 s against 27.3 s for GMRES + RILUK(2) over
// the path. Load curves identical to 1e-14.
}  // namespace

std::string resolvedLinearSolverType(const Teuchos::ParameterList& settings, int dofsPerNode) {
  const std::string type = settings.get<std::string>("Type");
  if (type != "auto") return type;
  return dofsPerNode == 3 ? "Belos GMRES + MueLu" : "MUMPS";
}

Teuchos::RCP<const Teuchos::ParameterList> linearSolverValidParameters() {
  static Teuchos::RCP<Teuchos::ParameterList> valid;
  if (!valid.is_null()) return valid;
  valid = Teuchos::rcp(new Teuchos::ParameterList("Linear Solver"));
  const auto types = validators::choices(std::vector<std::string>(std::begin(kTypes), std::end(kTypes)));
  valid->set("Type", "auto",
             "auto: MUMPS in 2D, Belos GMRES + MueLu in 3D; or MUMPS (direct, any number of ranks), Amesos2 KLU2 "
             "(direct, one rank only), Belos GMRES + Ifpack2, Belos GMRES + MueLu, Belos CG + MueLu (conjugate "
             "gradients on the Jacobian with its Dirichlet rows eliminated symmetrically; needs a symmetric "
             "tangent, so no interaction: Method 3's is not symmetric), Stratimikos (use the Stratimikos sublist "
             "as is)",
             types);
  using namespace validators;
  // AMD in 2D: the graph follows the spreading contact, so MUMPS analyses again in most steps (69 analyses
  // for 236 factorisations on the default deck at Mesh Refinement 2), and PORD's analysis costs 5 times
  // AMD's: level 2 path 39.0 s against 46.6 s, level 1 8.7 s against 11.4 s; at level 3 (160k) AMD's
  // factorisation is 15 % dearer, its analysis 4.8 times cheaper. PORD in 3D: on the 3D sphere deck at 27k
  // unknowns AMD's factorisation took 1.9 s against 1.0 s. (doc/performance.md)
  valid->set("MUMPS Ordering", "auto",
             "fill-reducing ordering of MUMPS' analysis: auto (AMD in 2D, PORD in 3D), AMD (approximate minimum "
             "degree: cheap analysis, more fill) or PORD (nested dissection: less fill in large and 3D meshes)",
             validators::choices({"auto", "AMD", "PORD"}));
  valid->set("Tolerance", 1e-10, "relative residual tolerance of iterative solvers", atLeast(1e-16));
  valid->set("Max Iterations", 1000, "iteration limit of iterative solvers", intAtLeast(1));
  valid->set("Krylov Space", 200, "GMRES restart length", intAtLeast(1));
  valid->set("ILU Fill Level", 2, "level of fill of the Ifpack2 RILUK preconditioner", intAtLeast(0));
  valid->set("Preconditioner Reuse", 0,
             "Belos types: how many later Jacobians a preconditioner serves, also across load steps, before it is "
             "built again; 0 builds one for every Jacobian. A kept one is built again sooner when a solve with it "
             "fails (the solve is then repeated) or needs more than Preconditioner Growth Limit times the Krylov "
             "iterations of the first solve with it. Every solve still meets Tolerance with the current Jacobian; "
             "a kept preconditioner holds the matrix it was built from (more memory)",
             intAtLeast(0));
  valid->set("Preconditioner Growth Limit", 1.5,
             "with Preconditioner Reuse: the Krylov iterations of a solve with a kept preconditioner, relative to "
             "its first solve, above which it is built again for the next Jacobian (at least 1)",
             atLeast(1.0));
  // Constant by default. Eisenstat-Walker on the 3D sphere deck at 27k unknowns (GMRES + MueLu, 14 states):
  // 577 Krylov iterations against 1440 and 14.5 s of linear solves against 19.2 s, but 39 Newton iterations
  // against 33, so that the path took 40.0 s against 38.0 s. Its Newton iteration counts also depend on the
  // partition, and with them the adaptive step sizes: one and two ranks took different steps on the
  // three-spheres deck.
  valid->set("Forcing Term", "constant",
             "the relative tolerance of iterative solves inside Newton: constant (Tolerance in every iteration) or "
             "Eisenstat-Walker (NOX's Type 2: 0.01 in the first iteration, then following the decrease of the "
             "Newton residual, at least Tolerance and at most 0.9: fewer Krylov iterations, more Newton iterations, "
             "and steps that depend on the number of ranks). States are accepted by the same residual test "
             "either way; direct solvers solve exactly; continuation (LOCA) and relaxation always use Tolerance",
             validators::choices({"constant", "Eisenstat-Walker"}));
  valid->set("MueLu Near Null Space", "translations",
             "near-null space of the MueLu aggregation: translations (one unit vector per displacement component, "
             "MueLu's default) or rigid body modes (translations and rotations of the reference configuration; "
             "3D and plane strain). On the compact bodies measured the rotations cut the Krylov iterations by up "
             "to a half but made a solve 1.45-1.55 times dearer (larger coarse operators); they may pay on "
             "slender ones",
             validators::choices({"translations", "rigid body modes"}));
  valid->sublist("Stratimikos", false, "Stratimikos parameter list, used as is when Type = Stratimikos")
      .disableRecursiveValidation();
  return valid;
}

Teuchos::RCP<Teuchos::ParameterList> stratimikosParameters(
    const Teuchos::ParameterList& settings, int numRanks, int dofsPerNode,
    const Teuchos::RCP<const assembly::MultiVector>& nearNullSpace, bool symmetric) {
  const std::string type = resolvedLinearSolverType(settings, dofsPerNode);
  if (const int reuse = settings.get<int>("Preconditioner Reuse"); reuse > 0 && type.rfind("Belos ", 0) != 0)
    throw InputError("Solver/Linear Solver/Preconditioner Reuse = " + std::to_string(reuse) +
                     " applies to the Belos types, and this run's linear solver is " + type +
                     "; use Preconditioner Reuse = 0 or a Belos type");
  if (type == "Stratimikos") return Teuchos::rcp(new Teuchos::ParameterList(settings.sublist("Stratimikos")));
  if (type == "Belos CG + MueLu" && !symmetric)
    throw InputError(
        "Solver/Linear Solver/Type = \"Belos CG + MueLu\" needs a symmetric tangent, and this problem's "
        "interaction tangent is not symmetric; use \"auto\", \"Belos GMRES + MueLu\" or \"MUMPS\"");
  auto p = Teuchos::rcp(new Teuchos::ParameterList("Stratimikos"));
  if (type == "MUMPS") {
    p->set("Linear Solver Type", "MUMPS");
    std::string ordering = settings.get<std::string>("MUMPS Ordering");
    if (ordering == "auto") ordering = dofsPerNode == 3 ? "PORD" : "AMD";
    p->sublist("Linear Solver Types").sublist("MUMPS").set("Ordering", ordering);
    p->set("Preconditioner Type", "None");
    return p;
  }
  if (type == "Amesos2 KLU2") {
    if (numRanks > 1)
      throw InputError("Solver/Linear Solver/Type = \"Amesos2 KLU2\" runs on one MPI rank only (this run has " +
                       std::to_string(numRanks) +
                       "; Debian's Amesos2 KLU2 returns wrong solutions on several ranks); use \"auto\", "
                       "\"Belos GMRES + Ifpack2\" or \"Belos GMRES + MueLu\"");
    p->set("Linear Solver Type", "Amesos2");
    p->sublist("Linear Solver Types").sublist("Amesos2").set("Solver Type", "KLU2");
    p->set("Preconditioner Type", "None");
    return p;
  }
  p->set("Linear Solver Type", "Belos");
  auto& belos = p->sublist("Linear Solver Types").sublist("Belos");
  if (type == "Belos CG + MueLu") {
    belos.set("Solver Type", "Pseudo Block CG");
    auto& cg = belos.sublist("Solver Types").sublist("Pseudo Block CG");
    cg.set("Convergence Tolerance", settings.get<double>("Tolerance"));
    cg.set("Maximum Iterations", settings.get<int>("Max Iterations"));
  } else {
    belos.set("Solver Type", "Block GMRES");
    auto& gmres = belos.sublist("Solver Types").sublist("Block GMRES");
    gmres.set("Convergence Tolerance", settings.get<double>("Tolerance"));
    gmres.set("Maximum Iterations", settings.get<int>("Max Iterations"));
    gmres.set("Num Blocks", settings.get<int>("Krylov Space"));
  }
  if (type == "Belos GMRES + Ifpack2") {
    p->set("Preconditioner Type", "Ifpack2");
    auto& ifp = p->sublist("Preconditioner Types").sublist("Ifpack2");
    // RILUK on each rank's diagonal block (block Jacobi with incomplete LU).
    ifp.set("Prec Type", "RILUK");
    ifp.sublist("Ifpack2 Settings").set("fact: iluk level-of-fill", settings.get<int>("ILU Fill Level"));
  } else {  // MueLu (GMRES or CG): smoothed aggregation, no direct coarse solve (KLU2 is wrong on several ranks)
    p->set("Preconditioner Type", "MueLu");
    auto& m = p->sublist("Preconditioner Types").sublist("MueLu");
    m.set("verbosity", "none");
    m.set("number of equations", dofsPerNode);  // nodal blocks for aggregation
    // MueLu's factory converts a Tpetra multivector under "Nullspace" itself (non-const by its type check).
    if (!nearNullSpace.is_null())
      m.set("Nullspace", Teuchos::rcp_const_cast<assembly::MultiVector>(nearNullSpace));
    // Chebyshev rather than symmetric Gauss-Seidel: on the hex8 Neo-Hookean box (bench_newton_iteration,
    // one rank) 1.80 s against 3.33 s per solve at 108k unknowns and 6.4 s against 12.5 s at 311k, with
    // 25-33 iterations against 20-26; on the 3D sphere deck at lcContact = 0.02 (27k unknowns, 88 entries
    // per row) 21.2 s against 24.9 s over two states. Load curves the same to 8e-12. (doc/performance.md)
    m.set("smoother: type", "CHEBYSHEV");
    m.sublist("smoother: params").set("chebyshev: degree", 2);
    // Chebyshev smooths up to boost x the largest eigenvalue of D^-1 A estimated by 10 power iterations.
    // On the graded tetrahedral meshes of the 3D sphere deck the estimate falls short, more so the finer
    // the mesh, and the modes above it are amplified: Ifpack2's boost of 1.1 gave 43 Krylov iterations per
    // solve at 27k unknowns, 80 at 170k and 260 at a million, 1.5 gives 39, 55 and 62 (a million on two
    // ranks: 39 s per Newton iteration against 123 s). The hex8 box loses 3 of 55-60. (doc/performance.md)
    m.sublist("smoother: params").set("chebyshev: boost factor", 1.5);
    // Coarsen down to 200 rows rather than MueLu's 2000: there is no direct solve on the coarsest level. The
    // sphere deck above: 259 Krylov iterations against 391, 19.8 s against 21.2 s; the 311k box 22
    // iterations against 33, 5.4 s against 6.4 s; the 108k box is unchanged.
    m.set("coarse: max size", 200);
    // No direct coarse solve (KLU2 is wrong on several ranks), but Chebyshev of degree 10 there rather than
    // one Jacobi sweep; it costs ten products with a matrix of at most a few hundred rows. The 108k box with
    // CG: 53 iterations against 65 on one rank, 61 against 85 on two (the cut splits aggregates, and the
    // coarse space carried the cost), solves 2.55 s against 2.8-3.1 and 1.65-1.77 against 1.93-2.07 s; the
    // 311k box and the sphere deck at 27k on one and two ranks unchanged within noise. (doc/performance.md)
    m.set("coarse: type", "CHEBYSHEV");
    m.sublist("coarse: params").set("chebyshev: degree", 10);
    // A polynomial of degree 10 amplifies what lies above its interval far more than one of degree 2, and
    // with CG an indefinite preconditioner would break the iteration: the bound from 50 power iterations
    // (not 10; cheap on these few rows) and the same boost as above. 59 CG iterations on two ranks at 108k
    // against 61 with Ifpack2's defaults, the same on one rank and on the sphere deck.
    m.sublist("coarse: params").set("chebyshev: eigenvalue max iterations", 50);
    m.sublist("coarse: params").set("chebyshev: boost factor", 1.5);
    // With an interaction (the only source of an unsymmetric tangent here) the aggregation drops entries
    // below 0.02 of their rows' diagonals: the interaction's couplings across the gap are weak, and
    // aggregates built across them coarsen poorly. The 3D sphere deck at 326k unknowns on two ranks: 94
    // Krylov iterations against 221, solves 12.4-12.7 s against 21.7-22.0 s; at 27k (14 states) 687
    // against 1274, 11.2 s against 14.4 s; three spheres 615 against 1130, 8.4 s against 12.2 s; load
    // curves the same to 1e-7. Without an interaction it costs: the 311k box 5.30 s against 4.32 s per
    // solve. (doc/performance.md)
    if (!symmetric) m.set("aggregation: drop tol", 0.02);
  }
  return p;
}

Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> buildLinearSolver(
    const Teuchos::ParameterList& settings, int numRanks, int dofsPerNode,
    const Teuchos::RCP<const assembly::MultiVector>& nearNullSpace, bool symmetric) {
  using namespace assembly;
  Stratimikos::DefaultLinearSolverBuilder builder;
  builder.setPreconditioningStrategyFactory(
      Teuchos::abstractFactoryStd<Thyra::PreconditionerFactoryBase<Real>,
                                  Thyra::Ifpack2PreconditionerFactory<CrsMatrix>>(),
      "Ifpack2");
  Stratimikos::enableMueLu<LocalIndex, GlobalIndex, Node>(builder);
  builder.setLinearSolveStrategyFactory(
      Teuchos::abstractFactoryStd<Thyra::LinearOpWithSolveFactoryBase<Real>, MumpsLinearOpWithSolveFactory>(), "MUMPS");
  auto params = stratimikosParameters(settings, numRanks, dofsPerNode, nearNullSpace, symmetric);
  try {
    builder.setParameterList(params);
  } catch (const std::exception& e) {
    throw InputError(std::string("Solver/Linear Solver: Stratimikos rejected the parameters: ") + e.what());
  }
  auto strategy = builder.createLinearSolveStrategy("");
  const std::string type = resolvedLinearSolverType(settings, dofsPerNode);
  // a Belos type: stratimikosParameters refused the others
  if (const int reuse = settings.get<int>("Preconditioner Reuse"); reuse > 0)
    strategy = Teuchos::rcp(
        new PreconditionerReuseFactory(strategy, reuse, settings.get<double>("Preconditioner Growth Limit")));
  if (type == "Belos CG + MueLu") return Teuchos::rcp(new SymmetricEliminationFactory(strategy));
  return strategy;
}

}  // namespace cgcm::solver
