#pragma once
// Kinematic formulations, used as compile-time policies of the element
// kernels (fem/SolidKernel.hpp).
//
//   PlaneStrain   dim 2, coordinates (x, y), F₃₃ = 1, quantities per unit thickness.
//   Axisymmetric  dim 2, coordinates (r, z) = (x[0], x[1]) of a meridian half-plane
//                 (r > 0), hoop stretch F_θθ = r/R, dv = 2π r dA: forces, energies
//                 and stiffnesses are totals over the full ring.
//   ThreeD        dim 3.
#include "cgcm/core/Types.hpp"

namespace cgcm::fem {

struct PlaneStrain {
  static constexpr int dim = 2;
  static constexpr bool axisymmetric = false;
  static constexpr const char* name = "PlaneStrain";
};

struct Axisymmetric {
  static constexpr int dim = 2;
  static constexpr bool axisymmetric = true;
  static constexpr const char* name = "Axisymmetric";
  /// 2π: the ring factor of dv = 2π r dA.
  static constexpr Real ringFactor = 2.0 * kPi;
};

struct ThreeD {
  static constexpr int dim = 3;
  static constexpr bool axisymmetric = false;
  static constexpr const char* name = "ThreeD";
};

}  // namespace cgcm::fem
