#pragma once
// One run of the solver app: set up from a validated deck, step the load
// path, write the load curve and a summary.
#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>

#include <ostream>
#include <vector>

#include "cgcm/core/Types.hpp"

namespace cgcm::app {

struct LoadPoint {
  int step;
  Real u, P;
  Real gap, contactRadius;  ///< two-body contact only
  int newtonIterations;
  bool jump;                ///< reached by a jump to another branch
  Real residual;
};

struct RunResult {
  std::vector<LoadPoint> curve;
  bool completed = false;        ///< the whole load path was traversed
  std::string failure;           ///< why not
  double assemblySeconds = 0.0;  ///< bulk residual + tangent evaluations
  double interactionSeconds = 0.0;  ///< interaction: search, kernel, scatter
  double newtonSeconds = 0.0;    ///< the whole load path, failed attempts included
  int stalledSteps = 0;          ///< steps accepted at a Newton stall (see Solver/Newton/Stall Tolerance)
};

/// Runs the deck (validated, defaults filled). Writes Output/Directory/{load_curve.csv,
/// parameters.xml}; prints progress on rank 0 to `log`. Collective.
RunResult runSimulation(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const Teuchos::ParameterList& deck,
                        std::ostream& log);

}  // namespace cgcm::app
