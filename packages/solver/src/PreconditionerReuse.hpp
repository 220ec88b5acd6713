#pragma once
// A Krylov solver's preconditioner kept across Jacobians, as a decorator of a
// Stratimikos Belos strategy with a preconditioner factory (MueLu, Ifpack2).
//
// MueLu's set-up is a large share of a 3D linear solve, and the Jacobians of
// successive Newton iterations and load steps differ little. The decorator
// builds a preconditioner from one Jacobian and hands it to the Krylov solves
// of up to `maxReuse` later Jacobians, also on a new matrix graph (the
// interaction's couplings change from step to step; the preconditioner keeps
// the matrix it was built from). The Krylov method always solves with the
// current Jacobian to the same tolerance, so only the Krylov count changes,
// and the Newton steps within that tolerance. A kept preconditioner is built
// again from the current Jacobian when a solve with it fails (the solve is
// then repeated from where it stopped) or, for the next Jacobian, when a
// solve with it needs more than `growthLimit` times the Krylov iterations of
// the first solve with it.
#include "OperatorSolveBase.hpp"

namespace cgcm::solver {

class ReusingSolve;

class PreconditionerReuseFactory : public DecoratingSolveFactory {
 public:
  /// `inner`: a Belos strategy with a preconditioner factory (throws std::logic_error without one). One
  /// preconditioner serves every solve object this factory initialises.
  PreconditionerReuseFactory(Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> inner, int maxReuse,
                             Real growthLimit);

  Teuchos::RCP<Thyra::LinearOpWithSolveBase<Real>> createOp() const override;
  void initializeOp(const Teuchos::RCP<const Thyra::LinearOpSourceBase<Real>>& fwdOpSrc,
                    Thyra::LinearOpWithSolveBase<Real>* Op, const Thyra::ESupportSolveUse supportSolveUse) const override;

 private:
  friend class ReusingSolve;
  struct Kept;  ///< the preconditioner and what its solves learnt, shared by the solve objects

  Teuchos::RCP<Kept> kept_;
};

}  // namespace cgcm::solver
