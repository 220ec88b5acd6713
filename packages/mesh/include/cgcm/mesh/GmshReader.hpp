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
// Supported elements: the cell types of core/CellType.hpp, one kind per body:
// quadrilaterals of 4, 8 or 9 nodes in 2D; hexahedra of 8, 20 or 27 nodes and
// tetrahedra of 4 or 10 nodes in 3D; on the boundary groups points and the
// facets of those cells (lines of 2 or 3 nodes, triangles of 3 or 6,
// quadrilaterals of 4, 8 or 9). Anything else (triangles in 2D, prisms,
// pyramids, third order) is an InputError naming the file, the group and the
// gmsh element type. A .geo is meshed with the cells of GmshOptions::element
// (gmsh's Mesh.ElementOrder and Mesh.SecondOrderIncomplete, the deck's
// choice over the file's), the nodes of quadratic cells on the curved
// geometry; a .msh is read with the cells it holds.
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
  /// gmsh's own number options for meshing a .geo, e.g. Mesh.Algorithm3D = 10
  /// (HXT, the parallel 3D mesher) or General.NumThreads = 2, set after the
  /// file is merged (the caller's choice over the file's). Each name must be a
  /// gmsh number option. Not allowed for a .msh.
  std::map<std::string, double> gmshOptions;
  /// A folder in which a meshed .geo is kept as a binary .msh, named by a
  /// CRC-64 of everything the mesh depends on (the .geo and the files it
  /// Includes, numbers, gmsh options, element order, dimension, gmsh's
  /// version); a later read with the same key reads the .msh instead of
  /// meshing. Empty: no cache. A cached file whose checksum does not match is
  /// meshed again and replaced.
  std::string cache;
  bool verbose = false;  ///< let gmsh print its progress (General.Terminal = 1)
  ElementOrder element;  ///< the cells a .geo is meshed with (a .msh: ignored)
};

/// How a mesh was obtained: one line for the run's summary, e.g. "meshed by
/// gmsh in 18.2 s, kept in cache/x-0123.msh" or "read from cache/x-0123.msh
/// in 2.1 s".
struct GmshProvenance {
  std::string line;
};

/// Whether `name` (e.g. "Mesh.Algorithm3D") is a number option of the gmsh library.
bool isGmshNumberOption(const std::string& name);

/// Reads `path` (.geo or .msh) into a Mesh of dimension options.dim following
/// the convention above. Throws InputError naming the file on any problem.
/// Serialised internally: gmsh holds global state and is not reentrant.
Mesh readGmsh(const std::string& path, const GmshOptions& options, GmshProvenance* provenance = nullptr);

}  // namespace cgcm::mesh
