#pragma once
// Reading Exodus II results back: what tests and tools/exo_compare need
// (Debian has no SEACAS exodiff). Variables are looked up by name.
#include <map>
#include <utility>
#include <string>
#include <vector>

namespace cgcm::io {

class ExodusReader {
 public:
  /// A block or set: name, element type (blocks only) and number of entries.
  struct Entity {
    std::string name, type;
    long long size = 0;
  };

  /// Opens `path` read-only and reads its header. Throws InputError if it cannot.
  explicit ExodusReader(const std::string& path);
  ~ExodusReader();
  ExodusReader(const ExodusReader&) = delete;
  ExodusReader& operator=(const ExodusReader&) = delete;

  const std::string& path() const { return path_; }
  const std::string& title() const { return title_; }
  int dim() const { return dim_; }
  long long numNodes() const { return numNodes_; }
  long long numElements() const { return numElements_; }
  const std::vector<Entity>& blocks() const { return blocks_; }
  const std::vector<Entity>& nodeSets() const { return nodeSets_; }
  const std::vector<Entity>& sideSets() const { return sideSets_; }
  const std::vector<std::string>& nodalNames() const { return nodalNames_; }
  const std::vector<std::string>& elementNames() const { return elementNames_; }
  const std::vector<std::string>& globalNames() const { return globalNames_; }
  /// Time values, one per step.
  const std::vector<double>& times() const { return times_; }
  int numSteps() const { return int(times_.size()); }

  /// The mesh: coordinate i of every node; the 1-based node ids of block b's cells; the 1-based node
  /// ids of node set s; the (1-based element, side) pairs of side set s. Throws std::runtime_error
  /// naming the file if Exodus cannot read them.
  std::vector<double> coordinates(int i) const;
  std::vector<long long> connectivity(std::size_t block) const;
  std::vector<long long> nodeSet(std::size_t set) const;
  std::vector<std::pair<long long, int>> sideSet(std::size_t set) const;

  /// Values at `step` (1-based, as Exodus counts). Throws std::runtime_error
  /// naming the file and the variable if the name or the step is unknown.
  std::vector<double> globals(int step) const;  ///< in globalNames() order
  std::vector<double> nodal(const std::string& name, int step) const;
  std::vector<double> element(const std::string& name, int step) const;  ///< all blocks, in block order

 private:
  int index(const std::vector<std::string>& names, const std::string& name, const char* kind, int step) const;

  std::string path_, title_;
  int exoid_ = -1;
  int dim_ = 0;
  long long numNodes_ = 0, numElements_ = 0;
  std::vector<Entity> blocks_, nodeSets_, sideSets_;
  std::vector<int> blockIds_, nodeSetIds_, sideSetIds_;
  std::vector<std::string> nodalNames_, elementNames_, globalNames_;
  std::vector<double> times_;
};

/// Tolerances of compareExodus: |a - b| <= abs + rel * max(|a|, |b|).
struct ExodusTolerance {
  double abs = 1e-12;
  double rel = 1e-9;
  std::map<std::string, double> absFor;  ///< a variable's own absolute tolerance, in place of abs
  /// The tolerance of variable `name`.
  ExodusTolerance of(const std::string& name) const {
    ExodusTolerance t{abs, rel, {}};
    if (const auto it = absFor.find(name); it != absFor.end()) t.abs = it->second;
    return t;
  }
};

/// Compares two Exodus files: dimension, number of nodes and elements; the
/// mesh (coordinates within the tolerance; blocks, their connectivity, node
/// and side sets exactly); number of steps, time values, and every global,
/// nodal and element variable by name at every step. Returns one line per difference (the worst entry of
/// each variable); empty if the files agree. Throws InputError if a file
/// cannot be read.
std::vector<std::string> compareExodus(const std::string& a, const std::string& b, const ExodusTolerance& tol);

}  // namespace cgcm::io
