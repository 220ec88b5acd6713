#pragma once
// What the benchmarks share: wall-clock intervals and one linear solve
// through a Thyra solver with its Krylov iteration count.
#include <Thyra_LinearOpWithSolveBase.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>

#include <chrono>

#include "cgcm/assembly/TpetraTypes.hpp"

namespace cgcm::bench {

using Clock = std::chrono::steady_clock;

inline double secondsSince(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

struct LinearSolve {
  bool converged = true;
  int iterations = 0;  ///< Krylov iterations; 0 for direct solvers
};

/// Solves A x = b with `lows` (A's operator on `space`), starting from x = 0.
inline LinearSolve solve(const Thyra::LinearOpWithSolveBase<Real>& lows,
                         const Teuchos::RCP<const Thyra::VectorSpaceBase<Real>>& space, const assembly::Vector& b,
                         assembly::Vector& x) {
  using assembly::Node;
  x.putScalar(0.0);
  auto bT = Thyra::createConstVector<Real, LocalIndex, GlobalIndex, Node>(Teuchos::rcpFromRef(b), space);
  auto xT = Thyra::createVector<Real, LocalIndex, GlobalIndex, Node>(Teuchos::rcpFromRef(x), space);
  const auto status = lows.solve(Thyra::NOTRANS, *bT, xT.ptr());
  LinearSolve out;
  out.converged = status.solveStatus != Thyra::SOLVE_STATUS_UNCONVERGED;
  if (!status.extraParameters.is_null() && status.extraParameters->isType<int>("Iteration Count"))
    out.iterations = status.extraParameters->get<int>("Iteration Count");
  return out;
}

}  // namespace cgcm::bench
