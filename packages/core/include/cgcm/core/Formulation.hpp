#pragma once
// The kinematics of a model, one enum for every package: the bulk assembly,
// the interaction kernels and the outputs. The element kernels take the
// matching compile-time tags of fem/Formulation.hpp.
//
//   PlaneStrain   dim 2, (x, y), quantities per unit thickness.
//   Axisymmetric  dim 2, (r, z) of a meridian half-plane; totals over the full ring.
//   ThreeD        dim 3.
#include <string>

#include "cgcm/core/Error.hpp"

namespace cgcm {

enum class Formulation { PlaneStrain, Axisymmetric, ThreeD };

/// The deck's spelling (Problem/Formulation).
inline const char* formulationName(Formulation f) {
  switch (f) {
    case Formulation::PlaneStrain: return "plane strain";
    case Formulation::Axisymmetric: return "axisymmetric";
    case Formulation::ThreeD: return "3D";
  }
  return "unknown";
}

/// Spatial dimension of the unknowns.
inline int formulationDim(Formulation f) { return f == Formulation::ThreeD ? 3 : 2; }

/// The formulation of a Problem/Formulation value. Throws InputError naming the allowed values.
inline Formulation parseFormulation(const std::string& name) {
  for (Formulation f : {Formulation::PlaneStrain, Formulation::Axisymmetric, Formulation::ThreeD})
    if (name == formulationName(f)) return f;
  throw InputError("Problem/Formulation = \"" + name + "\"; allowed: \"plane strain\", \"axisymmetric\", \"3D\"");
}

}  // namespace cgcm
