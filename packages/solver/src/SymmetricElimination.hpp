#pragma once
// Symmetric elimination of the unit rows of a Jacobian, as a decorator of a
// Stratimikos linear solve strategy ("Belos CG + MueLu").
//
// The Dirichlet rows of cgcm's Jacobians are unit rows (x_i = b_i), which
// makes a symmetric tangent unsymmetric: K_FD stays, K_DF is gone. For a
// solve A x = b the decorator hands the inner solver the matrix A_s with the
// columns of the unit rows zeroed outside them, and the lifted right-hand
// side b_s = b - A z + z, z = b on the unit rows and 0 elsewhere; after the
// inner solve x = b on the unit rows exactly. This is exact for any b (also
// LOCA's bordered solves, where the prescribed values move), so the forward
// operator, its apply and the Newton steps are those of A; only the inner
// Krylov method sees the symmetric A_s, and CG can be used.
//
// A unit row is recognised from the values (diagonal 1, all other entries 0):
// the elimination of such a row is exact whatever put it there. A_s shares
// A's graph; its values are a copy (8 bytes per entry) refreshed at every
// initialisation.
#include "OperatorSolveBase.hpp"

namespace cgcm::solver {

/// The inner strategy builds its own preconditioner from A_s: none is accepted.
class SymmetricEliminationFactory : public DecoratingSolveFactory {
 public:
  using DecoratingSolveFactory::DecoratingSolveFactory;

  bool isCompatible(const Thyra::LinearOpSourceBase<Real>& fwdOpSrc) const override;
  Teuchos::RCP<Thyra::LinearOpWithSolveBase<Real>> createOp() const override;
  void initializeOp(const Teuchos::RCP<const Thyra::LinearOpSourceBase<Real>>& fwdOpSrc,
                    Thyra::LinearOpWithSolveBase<Real>* Op, const Thyra::ESupportSolveUse supportSolveUse) const override;
};

}  // namespace cgcm::solver
