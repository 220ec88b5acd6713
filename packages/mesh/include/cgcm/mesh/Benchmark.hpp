#pragma once
// Meshes of the sphere-on-half-space benchmark (the paper's Fig. 3-4) in the
// meridian half-plane (x = radial coordinate >= 0, y = axis), usable both
// axisymmetrically (spheres) and in plane strain (cylinders, with x = 0 a
// symmetry line). Cells are graded towards the contact zone at x = 0.
// In 3D the same meridian meshes are swept about the axis over a quarter
// (sweepQuarter, sphereOnHalfSpaceQuarter).
#include "cgcm/mesh/Generators.hpp"

namespace cgcm::mesh {

/// One-dimensional node distribution on [0, length]: `fineCells` cells of
/// equal size up to `fineLength`, then `coarseCells` cells growing
/// geometrically to `length` (of equal size, shorter than the fine ones, where
/// `length` leaves them no room to grow). Returns the fineCells + coarseCells + 1
/// increasing node positions.
std::vector<Real> fineThenGeometric(Real length, Real fineLength, int fineCells, int coarseCells);
/// Node distribution on [0, length] whose first cell has size `first` and whose
/// cells then grow geometrically (cells + 1 positions); even cells, shorter than
/// `first`, where `cells` cells of `first` would already pass `length`.
std::vector<Real> geometric(Real length, Real first, int cells);

/// The built-in meshes' levels: Geometry/Mesh Refinement -1 .. 6. Level -1 doubles every cell of
/// level 0: with quadratic cells it has as many nodes as the linear level 0.
inline constexpr int kCoarsestLevel = -1, kFinestLevel = 6;

/// n cells at level 0 at `level` (doubled per level; halved at level -1, rounded down).
inline int cellsAtLevel(int n, int level) { return level >= 0 ? n << level : n >> -level; }

struct QuarterDiskSpec {
  Real radius = 1.0;
  Real centerY = 0.0;     ///< centre on the axis x = 0
  bool lowerHalf = true;  ///< true: the quarter below the centre (apex pointing down)
  int refinement = 0;     ///< each level halves every cell (kCoarsestLevel .. kFinestLevel)
  Real fineAngle = 0.4;   ///< polar angle from the apex over which cells are finest (16 cells at level 0,
                          ///< also the thickness of the first layer under the surface)
  int body = 0;
  std::string name = "sphere";
  ElementOrder element;
};

/// Lines of nodes of a meridian mesh, each from its node on the axis (x = 0) outwards, x
/// increasing, ordered along the axis; consecutive rows bound the cells next to the axis
/// (what sweepQuarter's core is built on).
using MeridianRows = std::vector<std::vector<LocalIndex>>;

/// Quarter disk as an O-grid (a core rectangle and two curved patches).
/// Node sets: "axis" (x = 0), "equator" (the flat side through the centre),
/// "apex" (the node on the axis on the curved side). Order 2: the nodes of
/// the edges on the arc lie on the circle (elevate), the other edges are straight.
/// `rows` (order 1 only): the core rectangle's rows from the equator, then the curved
/// patch's layers up to the arc.
Mesh quarterDisk(const QuarterDiskSpec& spec, MeridianRows* rows = nullptr);

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
/// `rows` (order 1 only): its rows of nodes, bottom to top.
Mesh halfSpaceBlock(const HalfSpaceSpec& spec, MeridianRows* rows = nullptr);

/// The largest core sweepQuarter can build on these rows: every row must reach
/// twice the radius of its node `coreCells` from the axis, where the rings have
/// turned from the core's kite into circles. 0 if none fits.
int largestSweepCore(const Mesh& meridian, const MeridianRows& rows);

/// A Quad4 meridian mesh (x >= 0 the radius, y the axis) swept about its axis over the
/// quarter x, y >= 0 into Hex8 cells: the meridian point (r, y) goes to (r cos phi, r sin phi, y).
/// Near the axis a butterfly core replaces the wedges a plain sweep would collapse there: in
/// every row, the nodes 0 .. coreCells span a coreCells x coreCells grid whose sides on the
/// planes x = 0 and y = 0 are the row itself and whose outer sides are a kite; outward, the
/// rings of 2 coreCells cells turn from that kite into circles by twice its radius. The planes
/// y = 0 and x = 0 hold the meridian mesh node for node. Each node set of the meridian mesh
/// becomes the set of its nodes' images (and of the core's inner nodes of rows it holds whole);
/// "symmetry x" and "symmetry y" are the nodes on x = 0 and y = 0. Blocks keep their names and
/// bodies. Throws InputError if coreCells is not in 1 .. largestSweepCore.
Mesh sweepQuarter(const Mesh& meridian, const MeridianRows& rows, int coreCells);

/// The benchmark in 3D as a quarter model of Hex8 (order 2: Hex27 or Hex20) cells, the meridian
/// meshes of `sphere` and `halfSpace` (a quarter cylinder of radius halfSpace.width) swept by
/// sweepQuarter with `quarterCells` / 2 core cells (quarterCells cells over the quarter's 90
/// degrees), the vertical axis z. The sphere's surface nodes (order 2: its edge and face nodes
/// too) lie on the sphere. Bodies "sphere" (0) and "half-space" (1); node sets as a gmsh mesh of
/// the benchmark has them (meshes/README.md): "driven" (the sphere's equator plane), "fixed"
/// (the half-space's bottom), "symmetry x", "symmetry y", "apex", "lower apex", and "driven body"
/// (every node of the sphere), "contact:sphere" and "contact:half-space" (the nodes of the surfaces:
/// the sphere's curved face, the half-space's top).
Mesh sphereOnHalfSpaceQuarter(const QuarterDiskSpec& sphere, const HalfSpaceSpec& halfSpace, int quarterCells);

/// The most cells over the quarter's 90 degrees sphereOnHalfSpaceQuarter can take with these
/// meridian meshes (2 x largestSweepCore of either).
int largestQuarterCells(const QuarterDiskSpec& sphere, const HalfSpaceSpec& halfSpace);

/// Nodes and cells of sphereOnHalfSpaceQuarter at order 1, without building it (the size check).
struct MeshSize {
  double nodes = 0.0, cells = 0.0;
};
MeshSize sphereOnHalfSpaceQuarterSize(int refinement, int quarterCells);

}  // namespace cgcm::mesh
