#pragma once
// One run of the solver app: set up from a validated deck, follow the path
// (displacement control or arc-length continuation), write the load curve
// and a summary.
#include <Teuchos_Comm.hpp>
#include <Teuchos_ParameterList.hpp>

#include <array>
#include <ostream>
#include <string>
#include <vector>

#include "cgcm/core/Types.hpp"
#include "cgcm/solver/LoadPoint.hpp"

namespace cgcm::app {


struct RunResult {
  std::vector<solver::LoadPoint> curve;
  bool completed = false;           ///< the whole path was traversed
  std::string failure;              ///< why not
  double assemblySeconds = 0.0;     ///< bulk residual + tangent evaluations
  double interactionSeconds = 0.0;  ///< interaction: search, kernel, scatter
  double searchSeconds = 0.0;       ///< of which the closest-point search
  double graphSeconds = 0.0;        ///< the interaction couplings of the matrix graph
  double pathSeconds = 0.0;         ///< the whole path, failed attempts included
  double meshSeconds = 0.0;         ///< building the problem: the mesh (gmsh, generators) and its checks
  double distributionSeconds = 0.0;  ///< partition, each rank's subdomain, dofs, problem and solver set-up
  double resultsMeshSeconds = 0.0;   ///< results.e: writing its mesh (before the path)
  double resultsSeconds = 0.0;       ///< results.e: writing its steps (in the path)
  std::string meshSource;            ///< how the mesh was obtained (mesh::Model::meshSource)
  int continuationSteps = 0;        ///< arc-length steps (arc-length control, jumps, parameter continuation)
  int graphRestarts = 0;            ///< continuation restarts after graph rebuilds
  std::vector<std::string> pathNotes;  ///< what the path could not do and went on without (solver::PathCost::notes)
  long linearSolves = 0;            ///< linear solves of Newton and relaxation (LOCA's not counted)
  long krylovIterations = 0;        ///< their Krylov iterations (0 with a direct solver)
  std::string linearSolver;         ///< Solver/Linear Solver/Type, "auto" resolved
  std::size_t matrixRows = 0, matrixEntries = 0;  ///< size of the Jacobian at the end
  std::vector<double> peakMemoryMB;                 ///< per rank: the process's peak resident memory
  /// Per rank: cells and nodes of the mesh it holds, its own surface facets and the ghost facets it holds.
  std::vector<std::array<long, 4>> meshHeld;
  long surfaceGathers = 0;  ///< times the ghost facets were gathered (Method 3 on several ranks)
  std::string volumePairs;  ///< Method 1: its pair list and quadrature at the end (empty for Method 3)
  std::size_t numNodes = 0, numCells = 0, numDofs = 0;  ///< the problem's size
  std::size_t numSurfaceFacets = 0;                     ///< of the interacting surfaces, whole model (rank 0)
};

enum class RunMode {
  Run,      ///< the whole load path
  Restart,  ///< continue the run of Output/Directory from its checkpoint.bin (displacement control only)
  Check     ///< every check and the problem's set-up, no file written, nothing solved (result.completed = true)
};

/// Runs the deck (validated, defaults filled). Writes Output/Directory/{load_curve.csv,
/// body_forces.csv, results.e (unless Output/Exodus is false), checkpoint.bin (unless
/// Output/Checkpoint is false), summary.txt, parameters.xml}; prints progress on rank 0
/// to `log`. Throws InputError for inconsistent input before any work; a run the solver
/// stops returns completed = false with the reason. Collective.
RunResult runSimulation(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const Teuchos::ParameterList& deck,
                        std::ostream& log, RunMode mode = RunMode::Run);

}  // namespace cgcm::app
