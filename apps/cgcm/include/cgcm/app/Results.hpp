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
// global variables.
//
// Written in parallel, through rank 0: each rank evaluates the fields of its
// own cells and nodes (a node's values come from its owner) and rank 0 writes
// what the ranks send it a window of entries at a time (solver::streamToRoot),
// so no rank holds the whole mesh or a whole field; only the traction, whose
// lumped areas and surface mass matrix couple the facets of every rank, is
// evaluated on rank 0 from the surfaces the ranks send it (O(surface)). The
// file numbers the nodes by global id (file node = id + 1) and the cells block
// after block in the whole mesh's order, whatever the number of ranks.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "cgcm/io/ExodusWriter.hpp"
#include "cgcm/solver/Discretization.hpp"
#include "cgcm/solver/RootStream.hpp"

namespace cgcm::app {

class ResultsWriter {
 public:
  /// Creates `path` on rank 0 with the mesh `disc` assembles (its cells are spread over the ranks) and
  /// the global variables `globals` (stresses with the problem's material of each body); keptSteps >= 0:
  /// continues the existing file after that many steps (a restart). Throws InputError on every rank if
  /// it cannot be created or continued. `windowBytes`: what rank 0 receives at a time (tests make it
  /// small). Collective.
  ResultsWriter(const std::string& path, const solver::Discretization& disc, const std::vector<std::string>& globals,
                int keptSteps = -1, bool criticalMode = false,
                std::size_t windowBytes = solver::kRootStreamWindowBytes);

  /// Wall time of writing the mesh (the constructor) and of writing the steps so far: evaluating the
  /// fields, sending them and writing them, not the interaction force (timed by the problem).
  double meshSeconds() const { return meshSeconds_; }
  double stepSeconds() const { return stepSeconds_; }

  /// Steps written to the file so far (rank 0; 0 elsewhere).
  int numSteps() const { return writer_ ? writer_->numSteps() : 0; }

  /// Appends the state x with the globals' values (in the constructor's
  /// order) and, when the file has the field, the critical mode (null: zero)
  /// as step time = number of the step, flushed. Throws on every rank if
  /// rank 0 cannot write. Collective.
  void write(const assembly::Vector& x, const std::vector<double>& globals, const assembly::Vector* mode = nullptr);

 private:
  /// The file's layout: the counts summed over the ranks. Collective.
  io::ExodusLayout layout() const;
  /// Coordinates, connectivity, node and side sets of the file laid out as `layout`. Collective.
  void writeMesh(const io::ExodusLayout& layout);
  /// Displacement, interaction force and critical mode of the owned nodes. Collective.
  void writeOwnedNodeFields(const assembly::Vector& x, const assembly::Vector* force, const assembly::Vector* mode);
  /// Traction and pressure: rank 0 evaluates them on the surfaces the ranks send it. Collective.
  void writeTraction(const std::vector<Real>& u, const std::vector<Real>& force);
  /// Stresses, J and von Mises of this rank's cells. Collective.
  void writeCellFields(const std::vector<Real>& u);
  /// Values of an owned-map vector at this rank's mesh nodes (dim per node; NaN at a node no cell of
  /// this rank touches). Collective.
  std::vector<Real> atMeshNodes(const assembly::Vector& v);
  /// Runs `work` on rank 0 (with writer_); what it throws is thrown on every rank. Collective.
  void onRoot(const std::function<void()>& work);

  const mesh::Mesh& mesh_;  ///< the mesh this rank assembles: its subdomain, or the whole mesh
  const solver::Discretization& disc_;
  std::vector<std::string> globals_;
  bool criticalMode_;
  std::size_t windowBytes_;
  io::ExodusVariables variables_;
  std::vector<LocalIndex> ownedNodes_;                ///< this rank's owned mesh nodes, ascending global id
  std::vector<LocalIndex> ownedDofs_;                 ///< their dofs' local indices in the owned map, dim per node
  std::vector<std::vector<LocalIndex>> ownCells_;     ///< per block, the cells this rank evaluates (by cell id)
  std::vector<LocalIndex> overlapIndex_;              ///< per mesh node: its overlap node, -1 if none
  Teuchos::RCP<assembly::Vector> overlap_;
  std::unique_ptr<io::ExodusWriter> writer_;           ///< rank 0
  double meshSeconds_ = 0.0, stepSeconds_ = 0.0;
};

}  // namespace cgcm::app
