#include "cgcm/app/SizeEstimate.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include "cgcm/core/Error.hpp"
#include "cgcm/mesh/Benchmark.hpp"

namespace cgcm::app {

namespace {

// Peak resident memory (MB) measured with the default solver settings:
//   axisymmetric benchmark, Mesh Refinement 0..3: 2676, 10308, 40452, 160260 dofs ->
//     127, 142, 259, 1527 MB;
//   3D hex8 block, 10^3, 15^3, 20^3, 25^3 cells: 3993, 12288, 27783, 52728 dofs ->
//     146, 182, 243, 337 MB.
// base + scale (dofs / reference)^exponent runs through the largest of each
// and above the smaller ones by at most 10 MB.
constexpr double kBaseMegabytes = 120.0;
struct MemoryLaw {
  double referenceDofs, megabytesAtReference, exponent;
};
constexpr MemoryLaw k2D{160260.0, 1407.0, 1.7};
constexpr MemoryLaw k3D{52728.0, 217.0, 1.2};

// The built-in sphere meshes: level 0 has 1338 nodes and 1240 cells, and each
// level about four times as many (5154, 20226, 80130 nodes at levels 1..3).
constexpr double kSphereNodes = 1338.0, kSphereCells = 1240.0;

std::string megabytes(double mb) {
  char buf[64];
  if (mb >= 1024.0)
    std::snprintf(buf, sizeof buf, "%.3g GB", mb / 1024.0);
  else
    std::snprintf(buf, sizeof buf, "%.0f MB", mb);
  return buf;
}

}  // namespace

SizeEstimate estimateSize(double nodes, double cells, Formulation formulation) {
  SizeEstimate e;
  e.nodes = nodes;
  e.cells = cells;
  e.dofs = nodes * formulationDim(formulation);
  const MemoryLaw& law = formulation == Formulation::ThreeD ? k3D : k2D;
  e.megabytes = kBaseMegabytes + law.megabytesAtReference * std::pow(e.dofs / law.referenceDofs, law.exponent);
  return e;
}

std::optional<SizeEstimate> estimateBuiltInMesh(const Teuchos::ParameterList& deck, Formulation formulation) {
  const auto& g = deck.sublist("Geometry");
  const std::string type = g.get<std::string>("Type");
  if (type == "gmsh") return std::nullopt;
  if (type == "block") {
    const auto& b = g.sublist("Block");
    const double nx = b.get<int>("Cells X"), ny = b.get<int>("Cells Y");
    if (formulation == Formulation::ThreeD) {
      const double nz = b.get<int>("Cells Z");
      const double cells = nx * ny * nz * (b.get<std::string>("Element") == "tet4" ? 6.0 : 1.0);
      return estimateSize((nx + 1) * (ny + 1) * (nz + 1), cells, formulation);
    }
    return estimateSize((nx + 1) * (ny + 1), nx * ny, formulation);
  }
  if (formulation == Formulation::ThreeD && type == "sphere on half-space") {  // the swept quarter model
    const int level = g.get<int>("Mesh Refinement");
    const mesh::MeshSize size = mesh::sphereOnHalfSpaceQuarterSize(level, mesh::cellsAtLevel(g.get<int>("Azimuthal Cells"), level));
    return estimateSize(size.nodes, size.cells, formulation);
  }
  const double grow = std::pow(4.0, g.get<int>("Mesh Refinement"));
  return estimateSize(kSphereNodes * grow, kSphereCells * grow, formulation);
}

MemoryLimit memoryLimit(const Teuchos::ParameterList& output) {
  const double given = output.get<double>("Max Memory");
  if (given > 0.0) return {given, true};
  std::ifstream meminfo("/proc/meminfo");
  std::string line;
  while (std::getline(meminfo, line))
    if (line.rfind("MemAvailable:", 0) == 0) {
      std::istringstream in(line.substr(13));
      double kb = 0.0;
      if (in >> kb && kb > 0.0) return {kb / 1024.0, false};
    }
  return {std::numeric_limits<double>::infinity(), false};
}

std::string MemoryLimit::describe() const {
  return given ? "Output/Max Memory = " + app::megabytes(this->megabytes)
               : "the " + app::megabytes(this->megabytes) +
                     " this machine has available (Output/Max Memory sets the limit, in MB)";
}

void checkSize(const SizeEstimate& e, const MemoryLimit& limit, const std::string& what) {
  char counts[160];
  std::snprintf(counts, sizeof counts, "%.3g nodes, %.3g cells, %.3g unknowns", e.nodes, e.cells, e.dofs);
  const double maxIndex = double(std::numeric_limits<int>::max());
  if (e.nodes > maxIndex || e.dofs > maxIndex)
    throw InputError(what + ": the mesh would have " + counts + ", beyond the 2^31 - 1 this code can index");
  if (e.megabytes > limit.megabytes)
    throw InputError(what + ": the mesh would have " + counts + " and need about " + megabytes(e.megabytes) +
                     " of memory, more than " + limit.describe());
}

}  // namespace cgcm::app
