#include "cgcm/solver/Convergence.hpp"

#include <LOCA_MultiContinuation_ExtendedVector.H>
#include <NOX_Abstract_Group.H>
#include <NOX_Solver_Generic.H>
#include <NOX_StatusTest_Combo.H>
#include <NOX_StatusTest_FiniteValue.H>
#include <NOX_StatusTest_MaxIters.H>

#include <algorithm>
#include <cmath>
#include <limits>
#include <ostream>

namespace cgcm::solver {

Real residualNorm(const NOX::Abstract::Group& group, const Teuchos::RCP<const NOX::Abstract::Vector>& weights) {
  const NOX::Abstract::Vector* F = &group.getF();
  if (const auto* ext = dynamic_cast<const LOCA::MultiContinuation::ExtendedVector*>(F)) F = ext->getXVec().get();
  return weights.is_null() ? F->norm(NOX::Abstract::Vector::TwoNorm) : F->norm(*weights);
}

NOX::StatusTest::StatusType ResidualNormTest::checkStatus(const NOX::Solver::Generic& solver,
                                                          NOX::StatusTest::CheckType type) {
  if (type == NOX::StatusTest::None) {
    status_ = NOX::StatusTest::Unevaluated;
    return status_;
  }
  const NOX::Abstract::Group& group = solver.getSolutionGroup();
  norm_ = residualNorm(group, weights_);
  // The starting point (a predictor) passes only if it is exact: one that
  // merely meets a loose tolerance can be off by a percent in the load, which
  // one Newton update (quadratic near the solution) removes.
  const Real needed = solver.getNumIterations() == 0 ? kStartingPointFraction * tolerance_ : tolerance_;
  bool constraintsHold = true;
  if (const auto* ext = dynamic_cast<const LOCA::MultiContinuation::ExtendedVector*>(&group.getF())) {
    const auto& g = *ext->getScalars();
    for (int i = 0; i < g.numRows(); ++i)
      for (int j = 0; j < g.numCols(); ++j) constraintsHold = constraintsHold && std::abs(g(i, j)) <= constraintTolerance_;
  }
  status_ = (norm_ <= needed && constraintsHold) ? NOX::StatusTest::Converged : NOX::StatusTest::Unconverged;
  return status_;
}

std::ostream& ResidualNormTest::print(std::ostream& stream, int indent) const {
  for (int i = 0; i < indent; ++i) stream << ' ';
  return stream << status_ << "|f|_2 = " << norm_ << " <= " << tolerance_ << " (force units; "
                << kStartingPointFraction << " of it before the first Newton update)\n";
}

NOX::StatusTest::StatusType ProgressTest::checkStatus(const NOX::Solver::Generic& solver,
                                                      NOX::StatusTest::CheckType type) {
  const int k = solver.getNumIterations();
  if (k == 0) history_.clear();
  if (type == NOX::StatusTest::None) {
    status_ = NOX::StatusTest::Unevaluated;
    return status_;
  }
  history_.resize(k + 1, std::numeric_limits<Real>::infinity());
  history_[k] = residualNorm(solver.getSolutionGroup(), weights_);
  status_ = NOX::StatusTest::Unconverged;
  if (k >= window_) {
    const Real earlier = *std::min_element(history_.begin(), history_.begin() + (k - window_ + 1));
    if (history_[k] > earlier) status_ = NOX::StatusTest::Failed;
  }
  return status_;
}

std::ostream& ProgressTest::print(std::ostream& stream, int indent) const {
  for (int i = 0; i < indent; ++i) stream << ' ';
  return stream << status_ << "progress: |f| below its value " << window_ << " iterations earlier\n";
}

Teuchos::RCP<NOX::StatusTest::Generic> convergenceTests(Real tolerance, int maxIterations,
                                                        Teuchos::RCP<const NOX::Abstract::Vector> weights) {
  using namespace NOX::StatusTest;
  auto tests = Teuchos::rcp(new Combo(Combo::OR));
  tests->addStatusTest(Teuchos::rcp(new FiniteValue));
  tests->addStatusTest(Teuchos::rcp(new ResidualNormTest(tolerance, weights)));
  tests->addStatusTest(Teuchos::rcp(new ProgressTest(weights)));
  tests->addStatusTest(Teuchos::rcp(new MaxIters(maxIterations)));
  return tests;
}

}  // namespace cgcm::solver
