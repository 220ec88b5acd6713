#pragma once
// Linear solvers through Stratimikos, with Ifpack2 and MueLu registered.
//
// Deck sublist "Linear Solver":
//   Type = "auto" (default): MUMPS in 2D, Belos GMRES + MueLu in 3D;
//          "MUMPS": direct, any number of ranks (MumpsSolver.hpp);
//          "Amesos2 KLU2": direct, one rank only (Debian's KLU2 is wrong on several ranks);
//          "Belos GMRES + Ifpack2", "Belos GMRES + MueLu": iterative;
//          "Belos CG + MueLu": CG with the Dirichlet rows eliminated symmetrically
//          (SymmetricElimination.hpp), for symmetric tangents only;
//          "Stratimikos": the sublist "Stratimikos" is handed to Stratimikos unchanged.
#include <Teuchos_ParameterList.hpp>
#include <Thyra_LinearOpWithSolveFactoryBase.hpp>

#include <string>

#include "cgcm/assembly/TpetraTypes.hpp"
#include "cgcm/core/Types.hpp"

namespace cgcm::solver {

/// Valid parameters (with defaults and documentation) of the "Linear Solver" sublist.
Teuchos::RCP<const Teuchos::ParameterList> linearSolverValidParameters();

/// The type the settings' "Type" stands for ("auto" resolved).
std::string resolvedLinearSolverType(const Teuchos::ParameterList& settings, int dofsPerNode);

/// The Stratimikos parameter list the settings stand for on `numRanks` ranks.
/// Throws InputError for KLU2 on more than one rank, and for CG when the
/// tangent is not `symmetric` (true when the Jacobian is symmetric apart from
/// its Dirichlet rows: no interaction), and for Preconditioner Reuse with a
/// type other than Belos. MueLu gets `nearNullSpace` (assembly::rigidBodyModes)
/// when it is given, and drops couplings below 0.02 of the diagonal in its
/// aggregation when the tangent is not `symmetric` (bodies interact).
Teuchos::RCP<Teuchos::ParameterList> stratimikosParameters(
    const Teuchos::ParameterList& settings, int numRanks, int dofsPerNode,
    const Teuchos::RCP<const assembly::MultiVector>& nearNullSpace = Teuchos::null, bool symmetric = false);

/// Builds the solver factory from validated settings (Preconditioner Reuse > 0:
/// the Belos strategy wrapped in the reuse of its preconditioner; CG: wrapped in
/// the symmetric elimination of the Dirichlet rows).
Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> buildLinearSolver(
    const Teuchos::ParameterList& settings, int numRanks, int dofsPerNode,
    const Teuchos::RCP<const assembly::MultiVector>& nearNullSpace = Teuchos::null, bool symmetric = false);

}  // namespace cgcm::solver
