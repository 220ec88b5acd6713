#pragma once
// The size of a problem before it is built, and the memory it will need, so
// that a deck asking for more than the machine has is refused with the
// estimate in the message instead of failing in an allocation minutes later.
//
// Memory model (peak resident set of a displacement-controlled run with the
// default direct solver, measured on this code): the benchmark deck at Mesh
// Refinement 0..3 (2.7k .. 160k dofs, axisymmetric) took 127, 142, 259 and
// 1527 MB; 3D blocks of hex8 at 10^3 .. 25^3 cells likewise (numbers in
// SizeEstimate.cpp). Above a base of about 120 MB the memory grows like
// dofs^1.7 (the direct factor's fill), which the model follows; it is an
// estimate for refusing absurd sizes, not a prediction to the megabyte.
#include <Teuchos_ParameterList.hpp>

#include <optional>
#include <string>

#include "cgcm/core/Formulation.hpp"

namespace cgcm::app {

struct SizeEstimate {
  double nodes = 0.0, cells = 0.0, dofs = 0.0;
  double megabytes = 0.0;  ///< peak memory of a run
};

/// From the node and cell counts and the formulation.
SizeEstimate estimateSize(double nodes, double cells, Formulation formulation);

/// For a built-in mesh (Geometry/Type sphere on half-space, sphere on sphere,
/// block), from the deck's parameters alone; empty for a mesh file.
std::optional<SizeEstimate> estimateBuiltInMesh(const Teuchos::ParameterList& deck, Formulation formulation);

struct MemoryLimit {
  double megabytes;
  bool given;  ///< Output/Max Memory, not the machine's
  /// "Output/Max Memory = 2000 MB" or "the 20000 MB this machine has available (...)", for messages.
  std::string describe() const;
};

/// Output/Max Memory in MB, or (0, the default) the memory this machine has
/// available now (MemAvailable of /proc/meminfo; no limit where that cannot be read).
MemoryLimit memoryLimit(const Teuchos::ParameterList& output);

/// Throws InputError naming `what` (the parameters that set the size), the
/// estimate and the limit when the estimate exceeds the limit, or when the
/// mesh would exceed the index range of the code (2^31 - 1 nodes or dofs).
void checkSize(const SizeEstimate& estimate, const MemoryLimit& limit, const std::string& what);

}  // namespace cgcm::app
