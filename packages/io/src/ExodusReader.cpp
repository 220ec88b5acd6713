#include "cgcm/io/ExodusReader.hpp"

#include <exodusII.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "cgcm/core/Error.hpp"

namespace cgcm::io {

namespace {

std::vector<std::string> readNames(int exoid, ex_entity_type type, int count, bool variables) {
  if (count <= 0) return {};
  const int length = std::max<int>(MAX_STR_LENGTH, int(ex_inquire_int(exoid, EX_INQ_DB_MAX_USED_NAME_LENGTH)));
  std::vector<std::vector<char>> buffers(count, std::vector<char>(length + 1, '\0'));
  std::vector<char*> ptrs;
  for (auto& b : buffers) ptrs.push_back(b.data());
  const int status =
      variables ? ex_get_variable_names(exoid, type, count, ptrs.data()) : ex_get_names(exoid, type, ptrs.data());
  if (status < 0) return std::vector<std::string>(count);
  std::vector<std::string> names;
  for (auto& b : buffers) names.emplace_back(b.data());
  return names;
}

}  // namespace

ExodusReader::ExodusReader(const std::string& path) : path_(path) {
  int cpuWordSize = sizeof(double), ioWordSize = 0;
  float version = 0.0f;
  exoid_ = ex_open(path.c_str(), EX_READ, &cpuWordSize, &ioWordSize, &version);
  if (exoid_ < 0) throw InputError("cannot open Exodus file \"" + path + "\"");
  const int used = int(ex_inquire_int(exoid_, EX_INQ_DB_MAX_USED_NAME_LENGTH));
  if (used > MAX_STR_LENGTH) ex_set_max_name_length(exoid_, used);

  char title[MAX_LINE_LENGTH + 1] = {0};
  int dim = 0, nodes = 0, elems = 0, numBlocks = 0, numNodeSets = 0, numSideSets = 0;
  if (ex_get_init(exoid_, title, &dim, &nodes, &elems, &numBlocks, &numNodeSets, &numSideSets) < 0) {
    ex_close(exoid_);
    throw InputError("cannot read the header of Exodus file \"" + path + "\"");
  }
  title_ = title, dim_ = dim, numNodes_ = nodes, numElements_ = elems;

  const std::vector<std::string> blockNames = readNames(exoid_, EX_ELEM_BLOCK, numBlocks, false);
  blockIds_.resize(numBlocks);
  if (numBlocks > 0) ex_get_ids(exoid_, EX_ELEM_BLOCK, blockIds_.data());
  for (int b = 0; b < numBlocks; ++b) {
    char type[MAX_STR_LENGTH + 1] = {0};
    int n = 0, perEntry = 0, edges = 0, faces = 0, attributes = 0;
    ex_get_block(exoid_, EX_ELEM_BLOCK, blockIds_[b], type, &n, &perEntry, &edges, &faces, &attributes);
    blocks_.push_back({blockNames[b], type, n});
  }
  const std::pair<ex_entity_type, int> setKinds[] = {{EX_NODE_SET, numNodeSets}, {EX_SIDE_SET, numSideSets}};
  for (const auto& [type, count] : setKinds) {
    auto& sets = type == EX_NODE_SET ? nodeSets_ : sideSets_;
    const std::vector<std::string> names = readNames(exoid_, type, count, false);
    std::vector<int>& ids = type == EX_NODE_SET ? nodeSetIds_ : sideSetIds_;
    ids.resize(std::size_t(count));
    if (count > 0) ex_get_ids(exoid_, type, ids.data());
    for (int s = 0; s < count; ++s) {
      int n = 0, factors = 0;
      ex_get_set_param(exoid_, type, ids[s], &n, &factors);
      sets.push_back({names[s], "", n});
    }
  }
  const std::pair<ex_entity_type, std::vector<std::string>*> varKinds[] = {
      {EX_NODAL, &nodalNames_}, {EX_ELEM_BLOCK, &elementNames_}, {EX_GLOBAL, &globalNames_}};
  for (const auto& [type, names] : varKinds) {
    int count = 0;
    ex_get_variable_param(exoid_, type, &count);
    *names = readNames(exoid_, type, count, true);
  }
  times_.resize(std::size_t(ex_inquire_int(exoid_, EX_INQ_TIME)));
  if (!times_.empty()) ex_get_all_times(exoid_, times_.data());
}

ExodusReader::~ExodusReader() {
  if (exoid_ >= 0) ex_close(exoid_);
}

int ExodusReader::index(const std::vector<std::string>& names, const std::string& name, const char* kind,
                        int step) const {
  if (step < 1 || step > numSteps())
    throw std::runtime_error("Exodus file \"" + path_ + "\": no step " + std::to_string(step) + " (it has " +
                             std::to_string(numSteps()) + ")");
  auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end())
    throw std::runtime_error("Exodus file \"" + path_ + "\" has no " + kind + " variable \"" + name + "\"");
  return int(it - names.begin()) + 1;
}

std::vector<double> ExodusReader::coordinates(int i) const {
  if (i < 0 || i >= dim_) throw std::runtime_error("Exodus file \"" + path_ + "\": no coordinate " + std::to_string(i));
  std::vector<double> c[3];
  for (int k = 0; k < 3; ++k) c[k].resize(k == i ? std::size_t(numNodes_) : 0);
  if (numNodes_ > 0 && ex_get_coord(exoid_, i == 0 ? c[0].data() : nullptr, i == 1 ? c[1].data() : nullptr,
                                    i == 2 ? c[2].data() : nullptr) < 0)
    throw std::runtime_error("Exodus file \"" + path_ + "\": cannot read the coordinates");
  return c[i];
}

std::vector<long long> ExodusReader::connectivity(std::size_t block) const {
  char type[MAX_STR_LENGTH + 1] = {0};
  int n = 0, perEntry = 0, edges = 0, faces = 0, attributes = 0;
  if (block >= blocks_.size() ||
      ex_get_block(exoid_, EX_ELEM_BLOCK, blockIds_[block], type, &n, &perEntry, &edges, &faces, &attributes) < 0)
    throw std::runtime_error("Exodus file \"" + path_ + "\": cannot read block " + std::to_string(block + 1));
  std::vector<int> ids(std::size_t(n) * std::size_t(perEntry));
  if (!ids.empty() && ex_get_conn(exoid_, EX_ELEM_BLOCK, blockIds_[block], ids.data(), nullptr, nullptr) < 0)
    throw std::runtime_error("Exodus file \"" + path_ + "\": cannot read the connectivity of block " +
                             blocks_[block].name);
  return std::vector<long long>(ids.begin(), ids.end());
}

std::vector<long long> ExodusReader::nodeSet(std::size_t set) const {
  if (set >= nodeSets_.size()) throw std::runtime_error("Exodus file \"" + path_ + "\": no node set " + std::to_string(set + 1));
  std::vector<int> ids(std::size_t(nodeSets_[set].size));
  if (!ids.empty() && ex_get_set(exoid_, EX_NODE_SET, nodeSetIds_[set], ids.data(), nullptr) < 0)
    throw std::runtime_error("Exodus file \"" + path_ + "\": cannot read node set " + nodeSets_[set].name);
  return std::vector<long long>(ids.begin(), ids.end());
}

std::vector<std::pair<long long, int>> ExodusReader::sideSet(std::size_t set) const {
  if (set >= sideSets_.size()) throw std::runtime_error("Exodus file \"" + path_ + "\": no side set " + std::to_string(set + 1));
  std::vector<int> elements(std::size_t(sideSets_[set].size)), sides(elements.size());
  if (!elements.empty() && ex_get_set(exoid_, EX_SIDE_SET, sideSetIds_[set], elements.data(), sides.data()) < 0)
    throw std::runtime_error("Exodus file \"" + path_ + "\": cannot read side set " + sideSets_[set].name);
  std::vector<std::pair<long long, int>> out;
  for (std::size_t k = 0; k < elements.size(); ++k) out.emplace_back(elements[k], sides[k]);
  return out;
}

std::vector<double> ExodusReader::globals(int step) const {
  if (step < 1 || step > numSteps())
    throw std::runtime_error("Exodus file \"" + path_ + "\": no step " + std::to_string(step));
  std::vector<double> values(globalNames_.size());
  if (!values.empty() && ex_get_var(exoid_, step, EX_GLOBAL, 1, 1, int(values.size()), values.data()) < 0)
    throw std::runtime_error("Exodus file \"" + path_ + "\": cannot read the global variables of step " +
                             std::to_string(step));
  return values;
}

std::vector<double> ExodusReader::nodal(const std::string& name, int step) const {
  const int k = index(nodalNames_, name, "nodal", step);
  std::vector<double> values(static_cast<std::size_t>(numNodes_));
  if (ex_get_var(exoid_, step, EX_NODAL, k, 1, numNodes_, values.data()) < 0)
    throw std::runtime_error("Exodus file \"" + path_ + "\": cannot read nodal variable \"" + name + "\"");
  return values;
}

std::vector<double> ExodusReader::element(const std::string& name, int step) const {
  const int k = index(elementNames_, name, "element", step);
  std::vector<double> values;
  for (std::size_t b = 0; b < blocks_.size(); ++b) {
    std::vector<double> block(static_cast<std::size_t>(blocks_[b].size));
    if (!block.empty() && ex_get_var(exoid_, step, EX_ELEM_BLOCK, k, blockIds_[b], blocks_[b].size, block.data()) < 0)
      throw std::runtime_error("Exodus file \"" + path_ + "\": cannot read element variable \"" + name + "\"");
    values.insert(values.end(), block.begin(), block.end());
  }
  return values;
}

namespace {

// Appends a line for the worst entry of `a` vs `b` if it exceeds the tolerance.
void compareValues(const std::string& what, const std::vector<double>& a, const std::vector<double>& b,
                   const ExodusTolerance& tol, std::vector<std::string>& out) {
  if (a.size() != b.size()) {
    out.push_back(what + ": " + std::to_string(a.size()) + " vs " + std::to_string(b.size()) + " values");
    return;
  }
  double worst = 0.0;
  std::size_t at = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i] == b[i] || (std::isnan(a[i]) && std::isnan(b[i]))) continue;
    const double excess = std::isfinite(a[i]) && std::isfinite(b[i])
                              ? std::abs(a[i] - b[i]) - (tol.abs + tol.rel * std::max(std::abs(a[i]), std::abs(b[i])))
                              : INFINITY;  // one is NaN or infinite
    if (excess > worst) worst = excess, at = i;
  }
  if (worst > 0.0) {
    char line[512];
    std::snprintf(line, sizeof line, "%s: %.17g vs %.17g at entry %zu (|a-b| = %.3g)", what.c_str(), a[at], b[at],
                  at + 1, std::abs(a[at] - b[at]));
    out.push_back(line);
  }
}

// Names in either list, with a line for each name only one file has.
std::vector<std::string> commonNames(const char* kind, const std::vector<std::string>& a,
                                     const std::vector<std::string>& b, const ExodusReader& ra, const ExodusReader& rb,
                                     std::vector<std::string>& out) {
  std::vector<std::string> common;
  for (const auto& n : a)
    if (std::find(b.begin(), b.end(), n) != b.end())
      common.push_back(n);
    else
      out.push_back(std::string(kind) + " variable \"" + n + "\" only in " + ra.path());
  for (const auto& n : b)
    if (std::find(a.begin(), a.end(), n) == a.end())
      out.push_back(std::string(kind) + " variable \"" + n + "\" only in " + rb.path());
  return common;
}

// The meshes of two files with equal counts: coordinates within `tol`, the rest exactly.
void compareMeshes(const ExodusReader& a, const ExodusReader& b, const ExodusTolerance& tol,
                   std::vector<std::string>& out) {
  for (int i = 0; i < a.dim(); ++i)
    compareValues(std::string("coordinate ") + "xyz"[i], a.coordinates(i), b.coordinates(i), tol, out);
  auto entities = [&](const char* kind, const std::vector<ExodusReader::Entity>& ea,
                      const std::vector<ExodusReader::Entity>& eb) {
    bool same = ea.size() == eb.size();
    for (std::size_t k = 0; same && k < ea.size(); ++k)
      same = ea[k].name == eb[k].name && ea[k].type == eb[k].type && ea[k].size == eb[k].size;
    if (!same) out.push_back(std::string(kind) + " differ (names, types or sizes)");
    return same;
  };
  if (entities("element blocks", a.blocks(), b.blocks()))
    for (std::size_t k = 0; k < a.blocks().size(); ++k)
      if (a.connectivity(k) != b.connectivity(k)) out.push_back("connectivity of block \"" + a.blocks()[k].name + "\" differs");
  if (entities("node sets", a.nodeSets(), b.nodeSets()))
    for (std::size_t k = 0; k < a.nodeSets().size(); ++k)
      if (a.nodeSet(k) != b.nodeSet(k)) out.push_back("node set \"" + a.nodeSets()[k].name + "\" differs");
  if (entities("side sets", a.sideSets(), b.sideSets()))
    for (std::size_t k = 0; k < a.sideSets().size(); ++k)
      if (a.sideSet(k) != b.sideSet(k)) out.push_back("side set \"" + a.sideSets()[k].name + "\" differs");
}

}  // namespace

std::vector<std::string> compareExodus(const std::string& pathA, const std::string& pathB, const ExodusTolerance& tol) {
  const ExodusReader a(pathA), b(pathB);
  std::vector<std::string> out;
  if (a.dim() != b.dim() || a.numNodes() != b.numNodes() || a.numElements() != b.numElements()) {
    out.push_back("meshes differ: dimension " + std::to_string(a.dim()) + " vs " + std::to_string(b.dim()) +
                  ", nodes " + std::to_string(a.numNodes()) + " vs " + std::to_string(b.numNodes()) + ", elements " +
                  std::to_string(a.numElements()) + " vs " + std::to_string(b.numElements()));
    return out;
  }
  compareMeshes(a, b, tol, out);
  if (a.numSteps() != b.numSteps())
    out.push_back("number of steps: " + std::to_string(a.numSteps()) + " vs " + std::to_string(b.numSteps()));
  const int steps = std::min(a.numSteps(), b.numSteps());
  compareValues("time", std::vector<double>(a.times().begin(), a.times().begin() + steps),
                std::vector<double>(b.times().begin(), b.times().begin() + steps), tol, out);
  const auto globals = commonNames("global", a.globalNames(), b.globalNames(), a, b, out);
  const auto nodals = commonNames("nodal", a.nodalNames(), b.nodalNames(), a, b, out);
  const auto elements = commonNames("element", a.elementNames(), b.elementNames(), a, b, out);
  for (int step = 1; step <= steps; ++step) {
    const std::string at = " at step " + std::to_string(step);
    const auto ga = a.globals(step), gb = b.globals(step);
    for (const auto& name : globals) {
      const auto ia = std::find(a.globalNames().begin(), a.globalNames().end(), name) - a.globalNames().begin();
      const auto ib = std::find(b.globalNames().begin(), b.globalNames().end(), name) - b.globalNames().begin();
      compareValues("global \"" + name + "\"" + at, {ga[ia]}, {gb[ib]}, tol.of(name), out);
    }
    for (const auto& name : nodals)
      compareValues("nodal \"" + name + "\"" + at, a.nodal(name, step), b.nodal(name, step), tol.of(name), out);
    for (const auto& name : elements)
      compareValues("element \"" + name + "\"" + at, a.element(name, step), b.element(name, step), tol.of(name),
                    out);
  }
  return out;
}

}  // namespace cgcm::io
