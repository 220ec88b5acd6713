#pragma once
// One row of a load curve: a converged state of the path, as the load curve,
// the checkpoint and the path analysis see it.
#include "cgcm/core/Types.hpp"

namespace cgcm::solver {

/// One row of the load curve: a converged state.
struct LoadPoint {
  int step = 0;
  Real u = 0.0, P = 0.0;
  Real parameter = 0.0;                   ///< value of the continuation parameter (u, gammaW or gammaL)
  Real gap = 0.0, contactRadius = 0.0;    ///< two-body contact only
  Real Plower = 0.0;                      ///< the same resultant at the lower body's support
  int newtonIterations = 0;
  bool stable = true;                     ///< under control of the continuation parameter
  bool fold = false;                      ///< a located fold (turning point of the path)
  bool branchPoint = false;               ///< a located branch point (Output/Eigenvalues)
  bool jump = false;                      ///< reached by a jump from a fold (displacement control)
  Real residual = 0.0;                    ///< |f|_2 of the accepted state (force units)
  int cutbacks = 0;
};

}  // namespace cgcm::solver
