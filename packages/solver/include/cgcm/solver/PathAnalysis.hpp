#pragma once
// What a load curve says about displacement control: the path a rigid
// loading device would follow (stable branches joined by jumps at folds),
// the jumps, and the energy the hysteresis loop dissipates.
#include <vector>

#include "cgcm/solver/LoadPoint.hpp"

namespace cgcm::solver {

struct Jump {
  LoadPoint from;  ///< the fold where the stable branch ends
  LoadPoint to;    ///< the state on the far stable branch at the same u
};

/// The displacement-controlled path of a curve in u: rows of stable branches
/// in order; at a fold that ends a stable branch, a jump to where the curve
/// (later, on a stable branch) returns to the fold's u moving the same way,
/// with the landing state interpolated linearly. A displacement-controlled
/// run's curve is returned as it is.
std::vector<LoadPoint> displacementControlPath(const std::vector<LoadPoint>& curve);

/// The jumps of a displacement-controlled path: fold row -> landing row.
std::vector<Jump> jumpsOf(const std::vector<LoadPoint>& path);

/// Energy dissipated by the approach-retraction loop of a displacement-
/// controlled path: the integral of P du along the approach (up to the
/// largest u) minus the same integral along the retraction, over the u range
/// both cover. 0 for a path without retraction or without hysteresis.
Real hysteresisEnergy(const std::vector<LoadPoint>& path);

}  // namespace cgcm::solver
