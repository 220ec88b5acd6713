#pragma once
// Structured mesh generators for tests, benchmarks and the built-in geometries.
#include <functional>

#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::mesh {

/// Maps a parameter s in [0, 1] to [0, 1], monotonically (mesh grading).
using Grading = std::function<Real(Real)>;
/// Uniform spacing.
Real uniformGrading(Real s);
/// Spacing that is fine near s = 0: s -> s^power (power > 1 concentrates nodes at 0).
Grading powerGrading(Real power);

struct RectangleSpec {
  Real x0 = 0.0, y0 = 0.0;      ///< lower-left corner
  Real lx = 1.0, ly = 1.0;      ///< side lengths
  int nx = 1, ny = 1;           ///< cells per direction
  Grading gradeX = uniformGrading, gradeY = uniformGrading;
  int body = 0;
  std::string name = "block";
  ElementOrder element;
};

/// Quad4 (order 2: Quad9 or Quad8) mesh of a rectangle. Node sets: left, right, bottom, top
/// (x = x0, x = x0 + lx, y = y0, y = y0 + ly). Its surface is filled in. The corner nodes come
/// first, numbered as at order 1.
Mesh rectangle(const RectangleSpec& spec);

struct BoxSpec {
  Real x0 = 0.0, y0 = 0.0, z0 = 0.0;
  Real lx = 1.0, ly = 1.0, lz = 1.0;
  int nx = 1, ny = 1, nz = 1;
  bool tetrahedra = false;      ///< split every hexahedron into 6 tetrahedra
  int body = 0;
  std::string name = "block";
  ElementOrder element;
};

/// Hex8 or Tet4 (order 2: Hex27, Hex20 or Tet10) mesh of a box. Node sets: xmin, xmax, ymin,
/// ymax, zmin, zmax.
Mesh box(const BoxSpec& spec);

/// Where elevate puts the node of the edge between nodes a and b: x (dim entries) holds the
/// edge's midpoint and may be moved, e.g. onto the curved boundary the edge stands for.
using EdgeNodePlacement = std::function<void(LocalIndex a, LocalIndex b, Real* x)>;

/// Where elevate puts the node of a hexahedron's face with corners `corners` (4, sorted): x holds the
/// transfinite blend of the face's edge nodes and may be moved, e.g. onto the curved surface the face
/// stands for.
using FaceNodePlacement = std::function<void(const std::vector<LocalIndex>& corners, Real* x)>;

/// Makes a mesh of linear cells quadratic, in place: Quad4 -> Quad9 (serendipity: Quad8), Hex8
/// -> Hex27 (Hex20), Tet4 -> Tet10. Each edge gets one node, shared by its cells, at its
/// midpoint or where `place` moves it; each quadrilateral face and each quadrilateral or
/// hexahedral cell of the complete (Lagrange) types one node, at the transfinite (Coons) blend
/// of its corners and edge nodes (the centre of a straight cell). The existing nodes keep their
/// indices; the new ones follow. A new node joins every node set that holds all the corners of
/// its edge, face or cell. The surfaces are rebuilt (buildSurfaces): elevate before trimming them.
/// `placeFace` (3D) may move the face nodes after the blend; a cell's node then moves by half the
/// sum of its faces' moves (the transfinite blend of the cell's faces).
void elevate(Mesh& mesh, bool serendipity, const EdgeNodePlacement& place = {},
             const FaceNodePlacement& placeFace = {});

/// Appends `other` to `mesh` as new bodies (body ids shifted by mesh.numBodies);
/// node-set names of `other` get `prefix` prepended. Dimensions must agree.
void append(Mesh& mesh, const Mesh& other, const std::string& prefix);

/// Recomputes mesh.surfaces from the element blocks: one surface per body,
/// all facets used by exactly one cell, oriented outward.
void buildSurfaces(Mesh& mesh);

/// Removes from the surface of `body` every facet whose nodes all belong to
/// `nodes` (sorted): symmetry lines and loaded faces that are not physical
/// surfaces of the interaction.
void removeFacetsOn(Mesh& mesh, int body, const std::vector<LocalIndex>& nodes);

/// Moves every node not in a boundary node set by a random amount up to
/// `fraction` of the smallest cell size (deterministic for a given seed):
/// distorted meshes for patch tests.
void perturbInteriorNodes(Mesh& mesh, Real fraction, unsigned seed);

}  // namespace cgcm::mesh
