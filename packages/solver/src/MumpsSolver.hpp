#pragma once
// The sparse direct solver MUMPS (Debian's libmumps, double precision, MPI)
// as a Stratimikos linear solve strategy, "MUMPS": the forward operator's
// Tpetra CrsMatrix is handed over as distributed coordinates (each rank its
// owned rows), the right-hand sides are gathered on rank 0 and the solutions
// scattered back. The analysis (ordering, symbolic factorisation) is kept
// while the matrix's sparsity pattern is unchanged; each new matrix value
// set is factorised again.
//
// Why not Amesos2: Debian's Amesos2 has only KLU2 and Tacho; KLU2 is slow on
// finite-element matrices (no supernodes) and wrong on several ranks.
#include "OperatorSolveBase.hpp"

namespace cgcm::solver {

/// A direct solve needs no preconditioner: none is accepted.
class MumpsLinearOpWithSolveFactory : public OperatorSolveFactoryBase {
 public:
  bool isCompatible(const Thyra::LinearOpSourceBase<Real>& fwdOpSrc) const override;
  Teuchos::RCP<Thyra::LinearOpWithSolveBase<Real>> createOp() const override;
  void initializeOp(const Teuchos::RCP<const Thyra::LinearOpSourceBase<Real>>& fwdOpSrc,
                    Thyra::LinearOpWithSolveBase<Real>* Op, const Thyra::ESupportSolveUse supportSolveUse) const override;

  void setParameterList(const Teuchos::RCP<Teuchos::ParameterList>& paramList) override;
  Teuchos::RCP<Teuchos::ParameterList> getNonconstParameterList() override { return params_; }
  Teuchos::RCP<Teuchos::ParameterList> unsetParameterList() override;
  Teuchos::RCP<const Teuchos::ParameterList> getParameterList() const override { return params_; }
  Teuchos::RCP<const Teuchos::ParameterList> getValidParameters() const override;

 private:
  Teuchos::RCP<Teuchos::ParameterList> params_;
};

}  // namespace cgcm::solver
