#pragma once
// Mirror images of meshes: a model drawn on one side of a plane, completed
// by its reflection. The result is exactly symmetric (node for node), which
// an unstructured mesher cannot promise for the two halves of a symmetric
// geometry.
#include <string>

#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::mesh {

/// Adds to `mesh` its reflection in the plane x_axis = 0 (axis 0, 1, 2 <
/// mesh.dim). Every node must lie on the side x_axis >= 0; nodes within
/// `tolerance` (relative to the mesh's extent) of the plane are shared by
/// both halves. A body that touches the plane is joined with its image into
/// one body (its image cells form a new element block of the same body); a
/// body that does not gets an image body of its own, named "<name> mirrored
/// in <x|y|z>". Cells and facets of the image are reordered so that they keep
/// a positive Jacobian and outward normals. Node sets become the union of
/// both halves, except "symmetry <x|y|z>" of the plane, which is removed (it
/// is interior now); surfaces (including restricted "contact:" ones) gain
/// the image facets, less the facets that lie in the plane. Throws
/// InputError for a node on the negative side.
void mirror(Mesh& mesh, int axis, Real tolerance = 1e-9);

/// The body a mirror image body was made of: `name` less its " mirrored in <x|y|z>" endings
/// (`name` itself for a body that is no image).
std::string unmirroredName(std::string name);

}  // namespace cgcm::mesh
