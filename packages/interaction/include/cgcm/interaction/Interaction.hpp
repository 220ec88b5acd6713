#pragma once
// What every interaction method offers its callers, whichever integral it
// evaluates (Method 3, SurfaceInteraction; Method 1, VolumeInteraction): the
// potential, the cutoff, and the two scalings that continuation in gammaW
// and gammaL moves.
#include "cgcm/core/Types.hpp"
#include "cgcm/interaction/PairPotential.hpp"

namespace cgcm::interaction {

class Interaction {
 public:
  virtual ~Interaction() = default;

  virtual const PairPotential& potential() const = 0;
  virtual int numBodies() const = 0;
  /// Absolute cutoff in use (scaled by the length scale).
  virtual Real cutoff() const = 0;

  /// Scales the potential's epsilon, hence every traction, by `strength` > 0
  /// (w and sigma_max scale with it, r_S0 does not). Default 1.
  virtual void setStrength(Real strength) = 0;
  virtual Real strength() const = 0;

  /// Stretches the law by the length b > 0 (default 1): T(r) = strength T_1(r/b),
  /// T_1 the law at b = 1 with its taper, so the cutoff (and Method 3's
  /// projection smoothing, Method 1's skin) scale with b. For Lennard-Jones
  /// this is the potential with r0 b and epsilon / b^3.
  virtual void setLengthScale(Real b) = 0;
  virtual Real lengthScale() const = 0;
};

}  // namespace cgcm::interaction
