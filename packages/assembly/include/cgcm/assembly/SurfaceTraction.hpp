#pragma once
// The interaction traction on the bodies' surfaces, from the interaction
// force on each node (Problem::interactionNodeForces), for output: the force
// of a surface node over its lumped current surface area, and its normal
// part, the pressure. The surfaces are the mesh's (mesh::Mesh::surfaces), so
// the same function serves every interaction method:
//   - Method 3: the interaction force sits on the surface nodes; the
//     traction is the lumped surface traction of its pairs.
//   - Method 1: the interaction force is a body force, on every node of the
//     cells within reach of another body; the traction at a surface node is
//     that node's force over its area (the same formula), so the interior
//     nodes' share is not in it (their forces are in the nodal force itself).
#include <vector>

#include "cgcm/core/Formulation.hpp"
#include "cgcm/core/Types.hpp"
#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::assembly {

/// Per node of a mesh, 0 off its surfaces.
struct SurfaceTractions {
  std::vector<Real> area;      ///< lumped current surface area (ring area in axisymmetry)
  std::vector<Real> traction;  ///< dim per node: the node's interaction force over its area
  std::vector<Real> pressure;  ///< -traction . n, n the node's outward normal (area-weighted over its facets):
                               ///< > 0 pushing into the body, < 0 adhesive
};

/// The tractions of the node forces `force` (dim per node, in the order of
/// `mesh`'s nodes) at the displacement `u` (the same order) on the surfaces
/// of `mesh`. A node's area is its share of its facets' current areas: half
/// a segment's length in plane strain, the integral of its shape function
/// times 2 pi r in axisymmetry, 1/3 of a triangle's and 1/4 of a
/// quadrilateral's area (the sum of its corner triangles' area vectors) in 3D. Quadratic facets:
/// in 2D the integral of the node's shape function over the curved edge (exact for a uniform
/// traction); in 3D the area is that of the straight pieces through the facet's nodes (Tri6: four
/// triangles, Quad8: four corner triangles and the mid-edge quadrilateral, Quad9: four
/// quadrilaterals), lumped as above, and the traction is not force over area (a Tri6's corners
/// carry none of a uniform traction's consistent forces) but the traction whose consistent node
/// forces on the curved facets are the node forces: the solution of M t = force, M_ab = int N_a
/// N_b da over those facets, exact for every traction their shape functions hold.
SurfaceTractions surfaceTractions(const mesh::Mesh& mesh, Formulation formulation, const std::vector<Real>& u,
                                  const std::vector<Real>& force);

}  // namespace cgcm::assembly
