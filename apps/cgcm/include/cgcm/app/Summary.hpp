#pragma once
// summary.txt: what a run found and what it cost, in a few lines.
#include <ostream>
#include <string>

#include "cgcm/app/Simulation.hpp"
#include "cgcm/solver/PathFollower.hpp"

namespace cgcm::app {

/// Writes `path`: completed or stopped (with the reason), P_min, the folds,
/// the jumps and the hysteresis energy of the displacement-controlled path
/// (continuation parameter u), the states, Newton iterations and
/// continuation steps, the Jacobian's size and the wall time split into bulk
/// assembly, interaction (closest-point search) and linear solves. Each line
/// also goes to `echo` (if not null) prefixed with "cgcm: ".
void writeSummary(const std::string& path, const RunResult& result, const solver::PathPlan& plan,
                  std::ostream* echo);

}  // namespace cgcm::app
