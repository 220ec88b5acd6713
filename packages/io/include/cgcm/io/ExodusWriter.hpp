#pragma once
// Exodus II results file (Debian libexodusii 6.02, C API): the mesh once, then
// one time step per call, flushed to disk (ex_update) after each step so that
// a run that is killed, even with SIGKILL, leaves a readable file holding
// every step written so far. Serial: in an MPI run rank 0 writes after
// gathering. No Trilinos dependency.
//
// Contents: coordinates (2D meshes, plane strain or axisymmetric, as 2D
// files); one element block per mesh::ElementBlock, named after it, of the
// Exodus type of its cells (QUAD4, HEX8, TETRA4, QUAD8, QUAD9, TETRA10, HEX20,
// HEX27) with all their nodes; one node set per Mesh::nodeSets entry, with its name; one
// side set per body with a non-empty Surface, named "contact:<body>" (the
// body's name is its first block's name), as (element, Exodus side) pairs.
// Variables are declared up front, by name: nodal (one value per node, e.g.
// displacement_x/_y/_z, which ParaView joins into a vector), element (one
// value per cell, on every block, e.g. stress_rr, J, von_mises) and global
// (one value per step, e.g. u, P). Block and set names longer than 64
// characters are truncated by Exodus (with a warning on stderr).
#include <map>
#include <string>
#include <vector>

#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::io {

struct ExodusVariables {
  std::vector<std::string> nodal;
  std::vector<std::string> element;
  std::vector<std::string> global;
};

class ExodusWriter {
 public:
  /// Values by variable name.
  using Fields = std::map<std::string, std::vector<double>>;
  using Scalars = std::map<std::string, double>;

  /// Creates `path` (replacing it) and writes the mesh and the variable
  /// names. Throws InputError if the file cannot be created, and
  /// std::runtime_error for invalid variable names (empty, repeated, longer
  /// than 64 characters) or a mesh Exodus cannot hold.
  ExodusWriter(const std::string& path, const std::string& title, const mesh::Mesh& mesh,
               const ExodusVariables& variables);
  /// Continues the file `path` written by this class for `mesh` with
  /// `variables`: the next step written is keptSteps + 1 (later steps already
  /// in the file are overwritten as the run goes on). Throws InputError if the
  /// file cannot be opened or does not match the mesh, the variables or holds
  /// fewer than keptSteps steps.
  ExodusWriter(const std::string& path, const mesh::Mesh& mesh, const ExodusVariables& variables, int keptSteps);
  ~ExodusWriter();  ///< closes the file; never throws
  ExodusWriter(const ExodusWriter&) = delete;
  ExodusWriter& operator=(const ExodusWriter&) = delete;

  /// Appends one time step and flushes it. Every declared variable must be
  /// given, nodal ones with numNodes values, element ones with numCells
  /// values in mesh-wide cell order (block after block). Throws
  /// std::runtime_error naming the file and the variable otherwise; nothing
  /// is written then.
  void writeStep(double time, const Fields& nodal, const Fields& element, const Scalars& global);

  /// Closes the file (idempotent). Throws std::runtime_error if Exodus fails.
  void close();

  const std::string& path() const { return path_; }
  int numSteps() const { return steps_; }

 private:
  void check(int status, const std::string& what) const;
  void checkFields(const char* kind, const std::vector<std::string>& names, const Fields& values,
                   std::size_t size) const;

  std::string path_;
  int exoid_ = -1;
  int steps_ = 0;
  ExodusVariables names_;
  std::size_t numNodes_ = 0, numCells_ = 0;
  std::vector<std::size_t> blockCells_;  // cells per element block
};

}  // namespace cgcm::io
