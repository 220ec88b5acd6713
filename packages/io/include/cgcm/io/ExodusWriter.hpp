#pragma once
// Exodus II results file (Debian libexodusii 6.02, C API): the mesh once, then
// one time step per call, flushed to disk (ex_update) after each step so that
// a run that is killed, even with SIGKILL, leaves a readable file holding
// every step written so far. Serial: in an MPI run rank 0 writes what the
// ranks send it. No Trilinos dependency.
//
// Two ways to write: from a whole mesh::Mesh and whole fields (the first
// constructor and writeStep), or streamed, for a writer that never holds the
// whole mesh: the file's layout (counts, names, types) first, then every
// array in pieces of consecutive entries (put*), and each step as
// beginStep, pieces of its fields, endStep. A streamed file is complete when
// every entry has been put once; the writer counts the entries put and
// endStep/finishMesh refuse a file with a hole.
//
// Contents: coordinates (2D meshes, plane strain or axisymmetric, as 2D
// files); one element block per mesh::ElementBlock, named after it, of the
// Exodus type of its cells (QUAD4, HEX8, TETRA4, QUAD8, QUAD9, TETRA10, HEX20,
// HEX27) with all their nodes; one node set per Mesh::nodeSets entry, with its name; one
// side set per body with a non-empty Surface, named "contact:<body>" (the
// body's name is its first block's name), as (element, Exodus side) pairs
// sorted by element, then side (an order any distribution of the cells gives).
// Variables are declared up front, by name: nodal (one value per node, e.g.
// displacement_x/_y/_z, which ParaView joins into a vector), element (one
// value per cell, on every block, e.g. stress_rr, J, von_mises) and global
// (one value per step, e.g. u, P). Block and set names longer than 64
// characters are truncated by Exodus (with a warning on stderr).
#include <cstdint>
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

/// What a file holds, before any of its arrays: enough to create it.
struct ExodusLayout {
  struct Block {
    std::string name;
    CellType type = CellType::Quad4;
    std::int64_t numCells = 0;
  };
  struct Set {
    std::string name;
    std::int64_t size = 0;  ///< nodes of a node set, (element, side) pairs of a side set
  };
  int dim = 2;
  std::int64_t numNodes = 0;
  std::vector<Block> blocks;  ///< file element ids run block after block
  std::vector<Set> nodeSets, sideSets;
  std::int64_t numCells() const;
};

/// The layout of a whole mesh, as the first constructor writes it (side sets: one per body with facets).
ExodusLayout layoutOf(const mesh::Mesh& mesh);
/// A side set's name: "contact:<first block of the body>" ("contact:body <b>" for a body without blocks).
std::string sideSetName(const std::vector<ExodusLayout::Block>& blocks, const std::vector<int>& blockBodies, int body);
/// The Exodus side (1-based) of `cell` of `block` whose nodes are `facet` (any order), 0 if none.
int exodusSide(const mesh::ElementBlock& block, LocalIndex cell, const LocalIndex* facet, int nodesPerFacet);

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
  /// Creates `path` (replacing it) with `layout` and the variable names; the mesh's arrays follow with
  /// the put* calls, then finishMesh(). The same errors as above.
  ExodusWriter(const std::string& path, const std::string& title, const ExodusLayout& layout,
               const ExodusVariables& variables);
  /// Continues the file `path` written by this class for the mesh of `layout` with
  /// `variables`: the next step written is keptSteps + 1 (later steps already
  /// in the file are overwritten as the run goes on). Throws InputError if the
  /// file cannot be opened or does not match the mesh, the variables or holds
  /// fewer than keptSteps steps.
  ExodusWriter(const std::string& path, const ExodusLayout& layout, const ExodusVariables& variables, int keptSteps);
  ~ExodusWriter();  ///< closes the file; never throws
  ExodusWriter(const ExodusWriter&) = delete;
  ExodusWriter& operator=(const ExodusWriter&) = delete;

  /// Appends one time step and flushes it. Every declared variable must be
  /// given, nodal ones with numNodes values, element ones with numCells
  /// values in mesh-wide cell order (block after block). Throws
  /// std::runtime_error naming the file and the variable otherwise; nothing
  /// is written then.
  void writeStep(double time, const Fields& nodal, const Fields& element, const Scalars& global);

  /// Streamed mesh: `count` consecutive entries from `first` (0-based) of the coordinates (z null in
  /// 2D), of block b's connectivity (the cells' nodes, 0-based file node ids), of node set s (0-based
  /// node ids) or of side set s (0-based element ids, 1-based Exodus sides). Throws std::runtime_error
  /// for a range outside the array.
  void putCoordinates(std::int64_t first, std::int64_t count, const double* x, const double* y, const double* z);
  void putConnectivity(std::size_t block, std::int64_t first, std::int64_t count, const GlobalIndex* nodes);
  void putNodeSet(std::size_t set, std::int64_t first, std::int64_t count, const GlobalIndex* nodes);
  void putSideSet(std::size_t set, std::int64_t first, std::int64_t count, const GlobalIndex* elements,
                  const int* sides);
  /// Ends the streamed mesh: throws std::runtime_error if fewer or more entries were put than the
  /// layout holds (coordinates, connectivity and sets counted together).
  void finishMesh();

  /// Streamed step: beginStep(time), then each field in pieces (variable k of its kind, the step's
  /// `count` values from `first`: nodes, or cells of block b), then endStep with the globals, which
  /// flushes the step; it throws std::runtime_error if the fields' values put are not every node's and
  /// every cell's once (counted together), or a global is missing or unknown.
  void beginStep(double time);
  void putNodal(std::size_t variable, std::int64_t first, std::int64_t count, const double* values);
  void putElement(std::size_t variable, std::size_t block, std::int64_t first, std::int64_t count,
                  const double* values);
  void endStep(const Scalars& global);

  const ExodusLayout& layout() const { return layout_; }

  /// Closes the file (idempotent). Throws std::runtime_error if Exodus fails.
  void close();

  const std::string& path() const { return path_; }
  int numSteps() const { return steps_; }

 private:
  void check(int status, const std::string& what) const;
  void checkFields(const char* kind, const std::vector<std::string>& names, const Fields& values,
                   std::size_t size) const;

  void create(const std::string& title);
  void checkRange(const char* what, std::int64_t first, std::int64_t count, std::int64_t size) const;
  void checkGlobals(const Scalars& global) const;

  std::string path_;
  int exoid_ = -1;
  int steps_ = 0;
  bool inStep_ = false;
  ExodusVariables names_;
  ExodusLayout layout_;
  // entries put so far: of the mesh's arrays (coordinates, blocks, node sets, side sets), of the step's fields
  std::int64_t meshEntries_ = 0, stepEntries_ = 0;
};

}  // namespace cgcm::io
