#include "cgcm/app/Summary.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>

#include "cgcm/core/MallocTunables.hpp"
#include "cgcm/solver/PathAnalysis.hpp"

namespace cgcm::app {

void writeSummary(const std::string& path, const RunResult& result, const solver::PathPlan& plan,
                  std::ostream* echo) {
  const std::string& parameter = plan.parameter();
  std::ofstream sum(path);
  auto both = [&](const char* text) {
    sum << text;
    if (echo) *echo << "cgcm: " << text;
  };
  char buf[400];
  both(result.completed ? "completed\n" : ("stopped: " + result.failure + "\n").c_str());
  const auto& c = result.curve;
  if (!c.empty()) {
    const auto minIt = std::min_element(
        c.begin(), c.end(), [](const solver::LoadPoint& a, const solver::LoadPoint& b) { return a.P < b.P; });
    std::snprintf(buf, sizeof buf, "P_min = %.10g at u = %.10g (step %d)\n", minIt->P, minIt->u, minIt->step);
    both(buf);
  }
  for (const auto& pt : c)
    if (pt.fold || pt.branchPoint) {
      const std::string other =
          parameter == "u" ? "" : ", " + parameter + " = " + std::to_string(pt.parameter);
      std::snprintf(buf, sizeof buf, "%s at step %d: u = %.10g%s, P = %.10g, gap = %.6g, contact radius = %.6g\n",
                    pt.fold ? "fold" : "branch point", pt.step, pt.u, other.c_str(), pt.P, pt.gap, pt.contactRadius);
      both(buf);
    }
  if (parameter == "u") {
    const auto path = plan.follower().tracesUnstableBranches() ? solver::displacementControlPath(c) : c;
    for (const auto& j : solver::jumpsOf(path)) {
      std::snprintf(buf, sizeof buf, "jump under displacement control at u = %.10g: P %.10g -> %.10g, gap %.6g -> %.6g\n",
                    j.from.u, j.from.P, j.to.P, j.from.gap, j.to.gap);
      both(buf);
    }
    std::snprintf(buf, sizeof buf, "hysteresis energy (loop of the displacement-controlled path) = %.10g\n",
                  solver::hysteresisEnergy(path));
    both(buf);
  }
  for (const auto& note : result.pathNotes) both(("note: " + note + "\n").c_str());
  int iterations = 0, unstable = 0;
  for (const auto& pt : c) iterations += pt.newtonIterations, unstable += pt.stable ? 0 : 1;
  std::snprintf(buf, sizeof buf,
                "states = %zu (%d unstable), Newton iterations = %d (%.2f per state), continuation steps = %d, "
                "graph restarts = %d\n",
                c.size(), unstable, iterations, double(iterations) / std::max<std::size_t>(1, c.size()),
                result.continuationSteps, result.graphRestarts);
  both(buf);
  const char* which = result.continuationSteps > 0 ? "linear solves outside continuation" : "linear solves";
  if (result.linearSolver == "MUMPS" || result.linearSolver == "Amesos2 KLU2")
    std::snprintf(buf, sizeof buf, "%s = %ld (direct solver %s)\n", which, result.linearSolves,
                  result.linearSolver.c_str());
  else
    std::snprintf(buf, sizeof buf, "%s = %ld, Krylov iterations = %ld (%.1f per solve), %s\n", which,
                  result.linearSolves, result.krylovIterations,
                  double(result.krylovIterations) / double(std::max(1L, result.linearSolves)),
                  result.linearSolver.c_str());
  both(buf);
  std::snprintf(buf, sizeof buf, "Jacobian at the end: %zu rows, %zu entries (%.1f per row)\n",
                result.matrixRows, result.matrixEntries,
                double(result.matrixEntries) / std::max<std::size_t>(1, result.matrixRows));
  both(buf);
  std::snprintf(buf, sizeof buf,
                "wall time of the path %.3f s = bulk assembly %.3f s + interaction %.3f s (%s %.3f s) + matrix "
                "graph (couplings and build) %.3f s + linear solves, NOX and LOCA %.3f s + results.e %.3f s\n",
                result.pathSeconds, result.assemblySeconds, result.interactionSeconds,
                result.volumePairs.empty() ? "closest-point search" : "pair lists", result.searchSeconds,
                result.graphSeconds,
                result.pathSeconds - result.assemblySeconds - result.interactionSeconds - result.graphSeconds -
                    result.resultsSeconds,
                result.resultsSeconds);
  both(buf);
  std::snprintf(buf, sizeof buf,
                "before the path: mesh and its checks %.3f s, distribution and set-up %.3f s, results.e's mesh %.3f s\n",
                result.meshSeconds, result.distributionSeconds, result.resultsMeshSeconds);
  both(buf);
  if (!result.meshSource.empty()) both((result.meshSource + "\n").c_str());
  if (!result.peakMemoryMB.empty()) {
    std::string line = "peak memory per rank:";
    for (std::size_t r = 0; r < result.peakMemoryMB.size(); ++r) {
      std::snprintf(buf, sizeof buf, "%s %.0f MB", r == 0 ? "" : ",", result.peakMemoryMB[r]);
      line += buf;
    }
    line += " (malloc in " + core::mallocDescription() + ")";
    both((line + "\n").c_str());
  }
  if (result.meshHeld.size() > 1) {
    std::string line = "mesh held per rank (cells, nodes, surface facets own + ghost):";
    for (std::size_t r = 0; r < result.meshHeld.size(); ++r) {
      std::snprintf(buf, sizeof buf, "%s %ld, %ld, %ld + %ld", r == 0 ? "" : ";", result.meshHeld[r][0],
                    result.meshHeld[r][1], result.meshHeld[r][2], result.meshHeld[r][3]);
      line += buf;
    }
    std::snprintf(buf, sizeof buf, " of %zu, %zu, %zu", result.numCells, result.numNodes, result.numSurfaceFacets);
    line += buf;
    if (!result.volumePairs.empty()) {
      line += " (Method 1 reads the whole mesh)";
    } else if (result.surfaceGathers > 0) {
      std::snprintf(buf, sizeof buf, "; ghosts gathered %ld times", result.surfaceGathers);
      line += buf;
    }
    both((line + "\n").c_str());
  }
  if (!result.volumePairs.empty()) both((result.volumePairs + "\n").c_str());
}

}  // namespace cgcm::app
