#pragma once
// The convergence test every accepted state passes, for Newton at a fixed
// prescribed displacement and for the corrector of arc-length continuation alike: the
// 2-norm of the residual f (force units: the internal force plus the
// interaction force; constrained rows hold u_i - u_prescribed, which Newton
// zeroes in one step) at or below an absolute force tolerance, with the rows
// of a body stiffer than the reference material weighted by (Y/Y_body)²
// (ParameterizedModel::residualWeights; assembly::Problem::residualWeights
// says why). The starting
// point of a solve (the predictor) is accepted without a Newton update only
// when it is exact: |f| at most kStartingPointFraction of the tolerance.
#include <NOX_StatusTest_Generic.H>
#include <Teuchos_RCP.hpp>

#include <vector>

#include "cgcm/core/Types.hpp"

namespace NOX::Abstract {
class Group;
class Vector;
}

namespace cgcm::solver {

/// The 2-norm of the residual of a NOX group (its F must be current),
/// weighted, sqrt(Σ w_i f_i²), when `weights` is not null
/// (ParameterizedModel::residualWeights). For a LOCA continuation group, the
/// norm of the physical part of its extended residual.
Real residualNorm(const NOX::Abstract::Group& group, const Teuchos::RCP<const NOX::Abstract::Vector>& weights = Teuchos::null);

/// Before the first Newton update a state must meet this fraction of the
/// tolerance: in practice only an exact predictor passes (a state with no
/// force at all, such as the bodies out of each other's range).
inline constexpr Real kStartingPointFraction = 1e-6;

/// NOX status test: converged when residualNorm <= tolerance (after at least
/// one Newton update; kStartingPointFraction of it before) and, for a
/// continuation group, the continuation constraints hold to round-off
/// (|g| <= constraintTolerance, in the constraint's own units).
class ResidualNormTest : public NOX::StatusTest::Generic {
 public:
  explicit ResidualNormTest(Real tolerance, Teuchos::RCP<const NOX::Abstract::Vector> weights = Teuchos::null,
                            Real constraintTolerance = 1e-10)
      : tolerance_(tolerance), constraintTolerance_(constraintTolerance), weights_(std::move(weights)) {}
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic& solver,
                                          NOX::StatusTest::CheckType type) override;
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream& print(std::ostream& stream, int indent = 0) const override;
  Real lastNorm() const { return norm_; }

 private:
  Real tolerance_, constraintTolerance_;
  Teuchos::RCP<const NOX::Abstract::Vector> weights_;
  Real norm_ = -1.0;
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
};

/// NOX status test: failed when Newton makes no progress, i.e. after
/// iteration k >= window the residual norm is above the lowest one of
/// iterations 0 .. k - window. A converging Newton iteration (quadratic near
/// the solution, damped far from it) passes; one that wanders past a fold or
/// around the snap of a contact ring is stopped after a few iterations
/// instead of at the iteration limit.
class ProgressTest : public NOX::StatusTest::Generic {
 public:
  explicit ProgressTest(Teuchos::RCP<const NOX::Abstract::Vector> weights = Teuchos::null, int window = 5)
      : window_(window), weights_(std::move(weights)) {}
  NOX::StatusTest::StatusType checkStatus(const NOX::Solver::Generic& solver,
                                          NOX::StatusTest::CheckType type) override;
  NOX::StatusTest::StatusType getStatus() const override { return status_; }
  std::ostream& print(std::ostream& stream, int indent = 0) const override;

 private:
  int window_;
  Teuchos::RCP<const NOX::Abstract::Vector> weights_;
  std::vector<Real> history_;
  NOX::StatusTest::StatusType status_ = NOX::StatusTest::Unevaluated;
};

/// The complete test of a nonlinear solve: failed on a non-finite residual,
/// without progress (ProgressTest) or after `maxIterations`, converged on
/// ResidualNormTest(tolerance); both norms weighted by `weights` if not null.
Teuchos::RCP<NOX::StatusTest::Generic> convergenceTests(Real tolerance, int maxIterations,
                                                        Teuchos::RCP<const NOX::Abstract::Vector> weights = Teuchos::null);

}  // namespace cgcm::solver
