#pragma once
// Do the bodies of a mesh overlap in the reference configuration?
#include <string>

#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::mesh {

/// Looks for two bodies that overlap: a node of one strictly inside a cell of
/// the other, or the boundaries of two bodies crossing (an edge of one
/// body's boundary through a boundary facet of the other: segments in 2D,
/// the facets' triangles in 3D). Together these find every overlap of
/// bodies with straight-sided cells; bodies that only touch do not overlap.
/// Cells count as convex: quadrilaterals with positive corner Jacobians and
/// tetrahedra are; a hexahedron is taken as the intersection of the
/// half-spaces of its facets' triangles. Returns a description of the first
/// overlap found (bodies, node or place), "" if there is none.
std::string findBodyOverlap(const Mesh& mesh);

}  // namespace cgcm::mesh
