#pragma once
// The kinematics of the bulk: plane strain, axisymmetric or 3D.
namespace cgcm::assembly {

enum class Formulation { PlaneStrain, Axisymmetric, ThreeD };

const char* formulationName(Formulation f);
/// Spatial dimension of the unknowns of a formulation.
int formulationDim(Formulation f);

}  // namespace cgcm::assembly
