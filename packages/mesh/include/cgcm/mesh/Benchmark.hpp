#pragma once
// Meshes of the sphere-on-half-space benchmark (the paper's Fig. 3-4) in the
// meridian half-plane (x = radial coordinate >= 0, y = axis), usable both
// axisymmetrically (spheres) and in plane strain (cylinders, with x = 0 a
// symmetry line). Cells are graded towards the contact zone at x = 0.
#include "cgcm/mesh/Generators.hpp"

namespace cgcm::mesh {

/// One-dimensional node distribution on [0, length]: `fineCells` cells of
/// equal size up to `fineLength`, then `coarseCells` cells growing
/// geometrically to `length`. Returns the fineCells + coarseCells + 1 node positions.
std::vector<Real> fineThenGeometric(Real length, Real fineLength, int fineCells, int coarseCells);
/// Node distribution on [0, length] whose first cell has size `first` and whose
/// cells then grow geometrically (cells + 1 positions).
std::vector<Real> geometric(Real length, Real first, int cells);

struct QuarterDiskSpec {
  Real radius = 1.0;
  Real centerY = 0.0;     ///< centre on the axis x = 0
  bool lowerHalf = true;  ///< true: the quarter below the centre (apex pointing down)
  int refinement = 0;     ///< each level halves every cell
  Real fineAngle = 0.4;   ///< polar angle from the apex over which cells are finest (16 cells at level 0,
                          ///< also the thickness of the first layer under the surface)
  int body = 0;
  std::string name = "sphere";
  ElementOrder element;
};

/// Quarter disk as an O-grid (a core rectangle and two curved patches).
/// Node sets: "axis" (x = 0), "equator" (the flat side through the centre),
/// "apex" (the node on the axis on the curved side). Order 2: the nodes of
/// the edges on the arc lie on the circle (elevate), the other edges are straight.
Mesh quarterDisk(const QuarterDiskSpec& spec);

struct HalfSpaceSpec {
  Real width = 8.0;       ///< radial extent
  Real depth = 8.0;       ///< below the surface y = topY
  Real topY = 0.0;
  int refinement = 0;
  Real fineLength = 0.5;  ///< radial extent of the finest surface cells (20 at level 0, also the
                          ///< thickness of the first layer under the surface)
  int body = 0;
  std::string name = "half-space";
  ElementOrder element;
};

/// Rectangle [0, width] x [topY - depth, topY], graded towards (0, topY).
/// Node sets: "axis", "bottom", "top", "side", "apex" (the node at (0, topY)).
Mesh halfSpaceBlock(const HalfSpaceSpec& spec);

}  // namespace cgcm::mesh
