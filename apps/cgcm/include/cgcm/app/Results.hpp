#pragma once
// The Exodus II results of a run (results.e): one step per load-curve row.
//
// Fields: nodal displacement_x/_y(/_z); per element the Cauchy stress
// averaged over its quadrature points (stress_rr, stress_zz, stress_tt,
// stress_rz in axisymmetry; stress_xx, stress_yy, stress_zz, stress_xy in
// plane strain; the six components in 3D), J and von_mises; with an
// interaction, whichever method, the nodal interaction traction
// (traction_x/_y(/_z): the interaction force on a surface node over its
// current tributary area, ring area in axisymmetry) and its normal part,
// pressure (> 0 pushing into the body, < 0 adhesive), 0 off the surfaces, and
// the interaction force on every node, interaction_force_x/_y(/_z)
// (Problem::interactionNodeForces: Method 1's is a body force, on the
// interior nodes too, whose share the traction leaves out; summed over a
// body it is the body's row of body_forces.csv); with Output/Eigenvalues the
// critical mode of the tangent (critical_mode_x/_y(/_z), largest entry 1,
// TangentSpectrum); the load-curve columns as
// global variables. The state is gathered to rank 0, which evaluates the
// fields on the whole mesh (the set-up's, of which a rank may assemble only a
// subdomain) and writes the file.
#include <memory>
#include <string>
#include <vector>

#include "cgcm/app/Setup.hpp"
#include "cgcm/io/ExodusWriter.hpp"
#include "cgcm/solver/Checkpoint.hpp"

namespace cgcm::app {

class ResultsWriter {
 public:
  /// Creates `path` on rank 0 with `mesh` (the whole mesh that `disc` assembles, whole or a subdomain of it; read on
  /// rank 0 only, null elsewhere allowed) and the global
  /// variables `globals` (stresses with the problem's material of each
  /// body); keptSteps >= 0: continues the existing file after that many
  /// steps (a restart). Throws InputError (rank 0) if it cannot be created
  /// or continued. Collective.
  ResultsWriter(const std::string& path, const mesh::Mesh* mesh, const solver::Discretization& disc,
                const std::vector<std::string>& globals, int keptSteps = -1, bool criticalMode = false);

  /// Steps written to the file so far (rank 0; 0 elsewhere).
  int numSteps() const { return writer_ ? writer_->numSteps() : 0; }

  /// Appends the state x with the globals' values (in the constructor's
  /// order) and, when the file has the field, the critical mode (null: zero)
  /// as step time = number of the step, flushed. Collective.
  void write(const assembly::Vector& x, const std::vector<double>& globals, const assembly::Vector* mode = nullptr);

 private:
  void displacementAndStress(const std::vector<Real>& u, io::ExodusWriter::Fields& nodal,
                             io::ExodusWriter::Fields& element) const;
  /// traction_*, pressure and interaction_force_* of the interaction force
  /// on each node `force` at u (both in mesh_'s node order).
  void interactionFields(const std::vector<Real>& u, const std::vector<Real>& force,
                         io::ExodusWriter::Fields& nodal) const;

  /// A state by global node id (id * dim + i) in the order of mesh_'s nodes.
  std::vector<Real> inMeshOrder(const std::vector<Real>& byGlobalNode) const;

  const mesh::Mesh* mesh_;  ///< the whole mesh (rank 0)
  const solver::Discretization& disc_;
  std::vector<std::string> globals_;
  bool root_, criticalMode_;
  solver::RootGather gather_;
  std::unique_ptr<io::ExodusWriter> writer_;
};

}  // namespace cgcm::app
