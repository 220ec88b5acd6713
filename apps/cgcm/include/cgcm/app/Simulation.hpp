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
  int newtonIterations;
  Real residual;
};

struct RunResult {
  std::vector<LoadPoint> curve;
  bool completed = false;        ///< the whole load path was traversed
  std::string failure;           ///< why not
  double assemblySeconds = 0.0;  ///< bulk residual + tangent evaluations
  double newtonSeconds = 0.0;    ///< all Newton solves (assembly + linear solves + NOX)
};

/// Runs the deck (validated, defaults filled). Writes Output/Directory/{load_curve.csv,
/// parameters.xml}; prints progress on rank 0 to `log`. Collective.
RunResult runSimulation(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const Teuchos::ParameterList& deck,
                        std::ostream& log);

}  // namespace cgcm::app
