#pragma once
// Meshes from gmsh: a .msh file, or a .geo file meshed in memory through the
// gmsh C++ API (libgmsh 4.8).
//
// Physical-group convention (also in meshes/README.md):
//
//   * Bodies are the physical groups of the mesh's dimension (surfaces in 2D,
//     volumes in 3D) named "body:<name>". Each group is one body and one
//     element block named <name>; groups with the same name are one body.
//     Body ids follow the order in which the groups appear (ascending physical
//     tag, which in a .geo is the order of definition). Every cell of that
//     dimension must belong to exactly one body, and bodies share no node
//     (do not fragment bodies that are meant to come into contact).
//   * Every lower-dimensional physical group (curves and points in 2D;
//     surfaces, curves and points in 3D) becomes a node set with the group's
//     name: fixed supports, the driven boundary, symmetry planes, single
//     points ("fixed", "driven", "symmetry x", "apex", ...). The meaning of a
//     name is the deck's business, not the reader's.
//   * Groups of dimension - 1 named "contact:<body>" are in addition the
//     interacting surface of that body: its Surface is exactly those facets
//     (which must lie on the body's boundary). A body with no contact group
//     gets all its exterior facets.
//   * Every group needs a name.
//
// Supported elements: 4-node quadrilaterals in 2D; 8-node hexahedra or 4-node
// tetrahedra in 3D (one kind per body); points, 2-node lines, 3-node
// triangles and 4-node quadrilaterals on the boundary groups. Anything else
// (triangles in 2D, quadratic elements, prisms, pyramids) is an InputError
// naming the file, the group and the gmsh element type.
//
// Node indices are 0-based and contiguous, in ascending gmsh node tag, over
// the nodes that belong to a body's cells. Cells are reordered where needed so
// that their Jacobian is positive (gmsh orients 2D cells with the surface
// normal, which may be -z); a cell whose Jacobian changes sign is an error.
#include <map>
#include <string>

#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::mesh {

struct GmshOptions {
  int dim = 2;  ///< the spatial dimension the mesh must have (2 or 3)
  /// Overrides of numbers defined with DefineConstant[] in a .geo (gmsh's
  /// -setnumber semantics): each name must be one of the file's
  /// DefineConstant entries. Not allowed for a .msh.
  std::map<std::string, double> numbers;
  bool verbose = false;  ///< let gmsh print its progress (General.Terminal = 1)
};

/// Reads `path` (.geo or .msh) into a Mesh of dimension options.dim following
/// the convention above. Throws InputError naming the file on any problem.
/// Serialised internally: gmsh holds global state and is not reentrant.
Mesh readGmsh(const std::string& path, const GmshOptions& options);

}  // namespace cgcm::mesh
