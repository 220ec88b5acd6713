#include "cgcm/io/ExodusWriter.hpp"

#include <exodusII.h>

#include <algorithm>
#include <limits>
#include <set>
#include <stdexcept>

#include "cgcm/core/Error.hpp"

namespace cgcm::io {

namespace {

constexpr int kMaxNameLength = 64;  // Exodus' default is 32; ParaView reads longer names
constexpr std::int64_t kMaxId = std::numeric_limits<int>::max();  // the file stores 32-bit ids

std::string exodusMessage() {
  const char *msg = nullptr, *func = nullptr;
  int code = 0;
  ex_get_err(&msg, &func, &code);
  return msg && *msg ? std::string(msg) : "Exodus error " + std::to_string(code);
}

// 1-based 32-bit ids of 0-based ones
std::vector<int> exodusIds(const GlobalIndex* ids, std::int64_t count) {
  std::vector<int> out(static_cast<std::size_t>(count));
  for (std::int64_t k = 0; k < count; ++k) out[std::size_t(k)] = int(ids[k] + 1);
  return out;
}

}  // namespace

std::int64_t ExodusLayout::numCells() const {
  std::int64_t n = 0;
  for (const auto& b : blocks) n += b.numCells;
  return n;
}

int exodusSide(const mesh::ElementBlock& block, LocalIndex cell, const LocalIndex* facet, int nodesPerFacet) {
  const int npc = mesh::nodesPerCell(block.type);
  const LocalIndex* nodes = &block.connectivity[std::size_t(cell) * npc];
  std::vector<LocalIndex> want(facet, facet + nodesPerFacet);
  std::sort(want.begin(), want.end());
  const auto& sides = mesh::localFacets(block.type);
  for (std::size_t s = 0; s < sides.size(); ++s) {
    std::vector<LocalIndex> have;
    for (int a : sides[s]) have.push_back(nodes[a]);
    std::sort(have.begin(), have.end());
    if (have == want) return int(s) + 1;
  }
  return 0;
}

std::string sideSetName(const std::vector<ExodusLayout::Block>& blocks, const std::vector<int>& blockBodies, int body) {
  for (std::size_t b = 0; b < blocks.size(); ++b)
    if (blockBodies[b] == body) return "contact:" + blocks[b].name;
  return "contact:body " + std::to_string(body);
}

ExodusLayout layoutOf(const mesh::Mesh& mesh) {
  ExodusLayout layout;
  layout.dim = mesh.dim;
  layout.numNodes = mesh.numNodes();
  std::vector<int> bodies;
  for (const auto& b : mesh.blocks) {
    layout.blocks.push_back({b.name, b.type, b.numCells()});
    bodies.push_back(b.body);
  }
  for (const auto& [name, nodes] : mesh.nodeSets) layout.nodeSets.push_back({name, std::int64_t(nodes.size())});
  for (const auto& s : mesh.surfaces)
    if (s.numFacets() > 0) layout.sideSets.push_back({sideSetName(layout.blocks, bodies, s.body), s.numFacets()});
  return layout;
}

ExodusWriter::ExodusWriter(const std::string& path, const std::string& title, const ExodusLayout& layout,
                           const ExodusVariables& variables)
    : path_(path), names_(variables), layout_(layout) {
  create(title);
}

ExodusWriter::ExodusWriter(const std::string& path, const std::string& title, const mesh::Mesh& mesh,
                           const ExodusVariables& variables)
    : path_(path), names_(variables), layout_(layoutOf(mesh)) {
  create(title);
  try {
    std::vector<double> xyz[3];
    for (int i = 0; i < mesh.dim; ++i) {
      xyz[i].resize(std::size_t(mesh.numNodes()));
      for (LocalIndex n = 0; n < mesh.numNodes(); ++n) xyz[i][std::size_t(n)] = mesh.coord(n, i);
    }
    putCoordinates(0, mesh.numNodes(), xyz[0].data(), xyz[1].data(), mesh.dim == 3 ? xyz[2].data() : nullptr);
    for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
      const auto& c = mesh.blocks[b].connectivity;
      const std::vector<GlobalIndex> nodes(c.begin(), c.end());
      putConnectivity(b, 0, mesh.blocks[b].numCells(), nodes.data());
    }
    std::size_t set = 0;
    for (const auto& [name, nodes] : mesh.nodeSets) {
      const std::vector<GlobalIndex> ids(nodes.begin(), nodes.end());
      putNodeSet(set++, 0, std::int64_t(ids.size()), ids.data());
    }
    // side sets: the bodies' surfaces, as (element, side) pairs sorted by element, then side
    std::vector<LocalIndex> blockStart;
    for (std::size_t b = 0; b < mesh.blocks.size(); ++b) blockStart.push_back(mesh.firstCellOfBlock(b));
    set = 0;
    for (const auto& s : mesh.surfaces) {
      if (s.numFacets() == 0) continue;
      std::vector<std::pair<GlobalIndex, int>> pairs;
      for (LocalIndex f = 0; f < s.numFacets(); ++f) {
        const LocalIndex cell = s.facetCells[f];
        const std::size_t b = std::upper_bound(blockStart.begin(), blockStart.end(), cell) - blockStart.begin() - 1;
        const int side = exodusSide(mesh.blocks[b], cell - blockStart[b], &s.facets[std::size_t(f) * s.nodesPerFacet],
                                    s.nodesPerFacet);
        if (side == 0)
          throw std::runtime_error("Exodus file \"" + path + "\": facet " + std::to_string(f) + " of body " +
                                   std::to_string(s.body) + " is no side of its cell " + std::to_string(cell));
        pairs.emplace_back(cell, side);
      }
      std::sort(pairs.begin(), pairs.end());
      std::vector<GlobalIndex> elements;
      std::vector<int> sides;
      for (const auto& [e, side] : pairs) elements.push_back(e), sides.push_back(side);
      putSideSet(set++, 0, std::int64_t(pairs.size()), elements.data(), sides.data());
    }
    finishMesh();
  } catch (...) {
    ex_close(exoid_);
    exoid_ = -1;
    throw;
  }
}

void ExodusWriter::create(const std::string& title) {
  for (const auto* kind : {&names_.nodal, &names_.element, &names_.global}) {
    std::set<std::string> seen;
    for (const auto& n : *kind) {
      if (n.empty() || int(n.size()) > kMaxNameLength)
        throw std::runtime_error("Exodus file \"" + path_ + "\": variable name \"" + n + "\" must have 1 to " +
                                 std::to_string(kMaxNameLength) + " characters");
      if (!seen.insert(n).second)
        throw std::runtime_error("Exodus file \"" + path_ + "\": variable \"" + n + "\" declared twice");
    }
  }
  const ExodusLayout& l = layout_;
  if (l.blocks.empty()) throw std::runtime_error("Exodus file \"" + path_ + "\": the mesh has no element blocks");
  if (l.dim != 2 && l.dim != 3)
    throw std::runtime_error("Exodus file \"" + path_ + "\": mesh dimension " + std::to_string(l.dim));
  if (l.numNodes > kMaxId || l.numCells() > kMaxId)
    throw std::runtime_error("Exodus file \"" + path_ + "\": " + std::to_string(l.numNodes) + " nodes and " +
                             std::to_string(l.numCells()) + " cells; a file of 32-bit ids holds at most " +
                             std::to_string(kMaxId) + " of each");

  int cpuWordSize = sizeof(double), ioWordSize = sizeof(double);
  exoid_ = ex_create(path_.c_str(), EX_CLOBBER, &cpuWordSize, &ioWordSize);
  if (exoid_ < 0) throw InputError("cannot create Exodus file \"" + path_ + "\": " + exodusMessage());
  try {
    auto putNames = [this](ex_entity_type type, const std::vector<std::string>& names) {
      std::vector<char*> ptrs;  // Exodus 6.02 takes char*[]
      for (const auto& n : names) ptrs.push_back(const_cast<char*>(n.c_str()));
      if (!ptrs.empty()) check(ex_put_names(exoid_, type, ptrs.data()), "names");
    };
    check(ex_set_max_name_length(exoid_, kMaxNameLength), "name length");
    check(ex_put_init(exoid_, title.c_str(), l.dim, l.numNodes, l.numCells(), int(l.blocks.size()),
                      int(l.nodeSets.size()), int(l.sideSets.size())),
          "ex_put_init");
    const char* coordNames[] = {"x", "y", "z"};
    check(ex_put_coord_names(exoid_, const_cast<char**>(coordNames)), "coordinate names");
    std::vector<std::string> names;
    for (std::size_t b = 0; b < l.blocks.size(); ++b) {
      const auto& block = l.blocks[b];
      check(ex_put_block(exoid_, EX_ELEM_BLOCK, b + 1, mesh::cellTypeName(block.type), block.numCells,
                         mesh::nodesPerCell(block.type), 0, 0, 0),
            "element block " + block.name);
      names.push_back(block.name);
    }
    putNames(EX_ELEM_BLOCK, names);
    names.clear();
    for (std::size_t s = 0; s < l.nodeSets.size(); ++s) {
      check(ex_put_set_param(exoid_, EX_NODE_SET, int(s) + 1, l.nodeSets[s].size, 0), "node set " + l.nodeSets[s].name);
      names.push_back(l.nodeSets[s].name);
    }
    putNames(EX_NODE_SET, names);
    names.clear();
    for (std::size_t s = 0; s < l.sideSets.size(); ++s) {
      check(ex_put_set_param(exoid_, EX_SIDE_SET, int(s) + 1, l.sideSets[s].size, 0), "side set " + l.sideSets[s].name);
      names.push_back(l.sideSets[s].name);
    }
    putNames(EX_SIDE_SET, names);

    const std::pair<ex_entity_type, const std::vector<std::string>*> kinds[] = {
        {EX_NODAL, &names_.nodal}, {EX_ELEM_BLOCK, &names_.element}, {EX_GLOBAL, &names_.global}};
    for (const auto& [type, vars] : kinds) {
      if (vars->empty()) continue;
      check(ex_put_variable_param(exoid_, type, int(vars->size())), "variable count");
      std::vector<char*> ptrs;
      for (const auto& n : *vars) ptrs.push_back(const_cast<char*>(n.c_str()));
      check(ex_put_variable_names(exoid_, type, int(vars->size()), ptrs.data()), "variable names");
    }
    check(ex_update(exoid_), "ex_update");
  } catch (...) {
    ex_close(exoid_);
    exoid_ = -1;
    throw;
  }
}

void ExodusWriter::checkRange(const char* what, std::int64_t first, std::int64_t count, std::int64_t size) const {
  if (exoid_ < 0) throw std::runtime_error("Exodus file \"" + path_ + "\": written after close()");
  if (first < 0 || count < 0 || first + count > size)
    throw std::runtime_error("Exodus file \"" + path_ + "\": " + what + " entries " + std::to_string(first) + " .. " +
                             std::to_string(first + count - 1) + " outside 0 .. " + std::to_string(size - 1));
}

void ExodusWriter::putCoordinates(std::int64_t first, std::int64_t count, const double* x, const double* y,
                                  const double* z) {
  checkRange("coordinate", first, count, layout_.numNodes);
  if (count == 0) return;
  if (!x || !y || (layout_.dim == 3) != (z != nullptr))
    throw std::logic_error("ExodusWriter::putCoordinates: " + std::to_string(layout_.dim) + " components needed");
  check(ex_put_partial_coord(exoid_, first + 1, count, x, y, z), "coordinates");
  meshEntries_ += count;
}

void ExodusWriter::putConnectivity(std::size_t block, std::int64_t first, std::int64_t count, const GlobalIndex* nodes) {
  if (block >= layout_.blocks.size()) throw std::logic_error("ExodusWriter::putConnectivity: no block " + std::to_string(block));
  const auto& b = layout_.blocks[block];
  checkRange(("connectivity of block " + b.name).c_str(), first, count, b.numCells);
  if (count == 0) return;
  const int npc = mesh::nodesPerCell(b.type);
  for (std::int64_t k = 0; k < count * npc; ++k)
    if (nodes[k] < 0 || nodes[k] >= layout_.numNodes)
      throw std::runtime_error("Exodus file \"" + path_ + "\": block " + b.name + " has node " +
                               std::to_string(nodes[k]) + " of " + std::to_string(layout_.numNodes));
  const std::vector<int> ids = exodusIds(nodes, count * npc);
  check(ex_put_partial_elem_conn(exoid_, block + 1, first + 1, count, ids.data()), "connectivity of " + b.name);
  meshEntries_ += count;
}

void ExodusWriter::putNodeSet(std::size_t set, std::int64_t first, std::int64_t count, const GlobalIndex* nodes) {
  if (set >= layout_.nodeSets.size()) throw std::logic_error("ExodusWriter::putNodeSet: no set " + std::to_string(set));
  checkRange(("node set " + layout_.nodeSets[set].name).c_str(), first, count, layout_.nodeSets[set].size);
  if (count == 0) return;
  const std::vector<int> ids = exodusIds(nodes, count);
  check(ex_put_partial_set(exoid_, EX_NODE_SET, int(set) + 1, first + 1, count, ids.data(), nullptr),
        "node set " + layout_.nodeSets[set].name);
  meshEntries_ += count;
}

void ExodusWriter::putSideSet(std::size_t set, std::int64_t first, std::int64_t count, const GlobalIndex* elements,
                              const int* sides) {
  if (set >= layout_.sideSets.size()) throw std::logic_error("ExodusWriter::putSideSet: no set " + std::to_string(set));
  checkRange(("side set " + layout_.sideSets[set].name).c_str(), first, count, layout_.sideSets[set].size);
  if (count == 0) return;
  const std::vector<int> ids = exodusIds(elements, count);
  check(ex_put_partial_set(exoid_, EX_SIDE_SET, int(set) + 1, first + 1, count, ids.data(), sides),
        "side set " + layout_.sideSets[set].name);
  meshEntries_ += count;
}

void ExodusWriter::finishMesh() {
  std::int64_t expected = layout_.numNodes + layout_.numCells();
  for (const auto& s : layout_.nodeSets) expected += s.size;
  for (const auto& s : layout_.sideSets) expected += s.size;
  if (meshEntries_ != expected)
    throw std::runtime_error("Exodus file \"" + path_ + "\": " + std::to_string(meshEntries_) + " mesh entries put of " +
                             std::to_string(expected) + " (coordinates, connectivity and sets)");
  check(ex_update(exoid_), "ex_update");
}

ExodusWriter::ExodusWriter(const std::string& path, const ExodusLayout& layout, const ExodusVariables& variables,
                           int keptSteps)
    : path_(path), steps_(keptSteps), names_(variables), layout_(layout) {
  int cpuWordSize = sizeof(double), ioWordSize = 0;
  float version = 0.0f;
  exoid_ = ex_open(path.c_str(), EX_WRITE, &cpuWordSize, &ioWordSize, &version);
  if (exoid_ < 0) throw InputError("cannot continue Exodus file \"" + path + "\": " + exodusMessage());
  auto refuse = [&](const std::string& why) {
    ex_close(exoid_);
    exoid_ = -1;
    throw InputError("cannot continue Exodus file \"" + path + "\": " + why);
  };
  ex_set_max_name_length(exoid_, kMaxNameLength);
  ex_init_params init{};
  if (ex_get_init_ext(exoid_, &init) < 0) refuse(exodusMessage());
  if (init.num_dim != layout.dim || init.num_nodes != layout.numNodes || init.num_elem != layout.numCells() ||
      std::size_t(init.num_elem_blk) != layout.blocks.size())
    refuse("it holds another mesh");
  for (std::size_t b = 0; b < layout.blocks.size(); ++b) {
    char type[MAX_STR_LENGTH + 1] = {};
    int64_t cells = 0, perCell = 0, edges = 0, faces = 0, attributes = 0;
    if (ex_get_block(exoid_, EX_ELEM_BLOCK, b + 1, type, &cells, &perCell, &edges, &faces, &attributes) < 0 ||
        cells != layout.blocks[b].numCells || std::string(type) != mesh::cellTypeName(layout.blocks[b].type))
      refuse("it holds another mesh");
  }
  const std::pair<ex_entity_type, const std::vector<std::string>*> kinds[] = {
      {EX_NODAL, &names_.nodal}, {EX_ELEM_BLOCK, &names_.element}, {EX_GLOBAL, &names_.global}};
  for (const auto& [type, names] : kinds) {
    int count = 0;
    if (ex_get_variable_param(exoid_, type, &count) < 0 || std::size_t(count) != names->size())
      refuse("it holds other variables");
    for (int k = 0; k < count; ++k) {
      char name[kMaxNameLength + 1] = {};
      if (ex_get_variable_name(exoid_, type, k + 1, name) < 0 || (*names)[std::size_t(k)] != name)
        refuse("it holds other variables");
    }
  }
  const int stored = int(ex_inquire_int(exoid_, EX_INQ_TIME));
  if (stored < keptSteps)
    refuse("it holds " + std::to_string(stored) + " steps, the checkpoint " + std::to_string(keptSteps));
}

ExodusWriter::~ExodusWriter() {
  if (exoid_ >= 0) ex_close(exoid_);
}

void ExodusWriter::check(int status, const std::string& what) const {
  if (status < 0) throw std::runtime_error("Exodus file \"" + path_ + "\": " + what + ": " + exodusMessage());
}

void ExodusWriter::checkFields(const char* kind, const std::vector<std::string>& names, const Fields& values,
                               std::size_t size) const {
  for (const auto& [name, v] : values) {
    if (std::find(names.begin(), names.end(), name) == names.end())
      throw std::runtime_error("Exodus file \"" + path_ + "\": " + kind + " variable \"" + name +
                               "\" was not declared");
    if (v.size() != size)
      throw std::runtime_error("Exodus file \"" + path_ + "\": " + kind + " variable \"" + name + "\" has " +
                               std::to_string(v.size()) + " values, expected " + std::to_string(size));
  }
  for (const auto& name : names)
    if (!values.count(name))
      throw std::runtime_error("Exodus file \"" + path_ + "\": " + kind + " variable \"" + name +
                               "\" missing in step " + std::to_string(steps_ + 1));
}

void ExodusWriter::writeStep(double time, const Fields& nodal, const Fields& element, const Scalars& global) {
  if (exoid_ < 0) throw std::runtime_error("Exodus file \"" + path_ + "\": written after close()");
  checkFields("nodal", names_.nodal, nodal, std::size_t(layout_.numNodes));
  checkFields("element", names_.element, element, std::size_t(layout_.numCells()));
  checkGlobals(global);
  beginStep(time);
  for (std::size_t k = 0; k < names_.nodal.size(); ++k)
    putNodal(k, 0, layout_.numNodes, nodal.at(names_.nodal[k]).data());
  for (std::size_t k = 0; k < names_.element.size(); ++k) {
    const double* values = element.at(names_.element[k]).data();
    for (std::size_t b = 0; b < layout_.blocks.size(); values += layout_.blocks[b].numCells, ++b)
      putElement(k, b, 0, layout_.blocks[b].numCells, values);
  }
  endStep(global);
}

void ExodusWriter::checkGlobals(const Scalars& global) const {
  Fields globals;
  for (const auto& [name, v] : global) globals[name] = {v};
  checkFields("global", names_.global, globals, 1);
}

void ExodusWriter::beginStep(double time) {
  if (exoid_ < 0) throw std::runtime_error("Exodus file \"" + path_ + "\": written after close()");
  if (inStep_) throw std::logic_error("ExodusWriter::beginStep: step " + std::to_string(steps_ + 1) + " not ended");
  check(ex_put_time(exoid_, steps_ + 1, &time), "time");
  inStep_ = true;
  stepEntries_ = 0;
}

void ExodusWriter::putNodal(std::size_t variable, std::int64_t first, std::int64_t count, const double* values) {
  if (!inStep_ || variable >= names_.nodal.size())
    throw std::logic_error("ExodusWriter::putNodal: variable " + std::to_string(variable) + " outside a step");
  checkRange(names_.nodal[variable].c_str(), first, count, layout_.numNodes);
  if (count == 0) return;
  check(ex_put_partial_var(exoid_, steps_ + 1, EX_NODAL, int(variable) + 1, 1, first + 1, count, values),
        names_.nodal[variable]);
  stepEntries_ += count;
}

void ExodusWriter::putElement(std::size_t variable, std::size_t block, std::int64_t first, std::int64_t count,
                              const double* values) {
  if (!inStep_ || variable >= names_.element.size() || block >= layout_.blocks.size())
    throw std::logic_error("ExodusWriter::putElement: variable " + std::to_string(variable) + " of block " +
                           std::to_string(block) + " outside a step");
  checkRange(names_.element[variable].c_str(), first, count, layout_.blocks[block].numCells);
  if (count == 0) return;
  check(ex_put_partial_var(exoid_, steps_ + 1, EX_ELEM_BLOCK, int(variable) + 1, block + 1, first + 1, count, values),
        names_.element[variable]);
  stepEntries_ += count;
}

void ExodusWriter::endStep(const Scalars& global) {
  if (!inStep_) throw std::logic_error("ExodusWriter::endStep: no step begun");
  checkGlobals(global);
  const std::int64_t expected =
      layout_.numNodes * std::int64_t(names_.nodal.size()) + layout_.numCells() * std::int64_t(names_.element.size());
  if (stepEntries_ != expected)
    throw std::runtime_error("Exodus file \"" + path_ + "\": step " + std::to_string(steps_ + 1) + " has " +
                             std::to_string(stepEntries_) + " field values of " + std::to_string(expected));
  if (!names_.global.empty()) {
    std::vector<double> values;
    for (const auto& name : names_.global) values.push_back(global.at(name));
    check(ex_put_var(exoid_, steps_ + 1, EX_GLOBAL, 1, 1, values.size(), values.data()), "global variables");
  }
  check(ex_update(exoid_), "ex_update");
  inStep_ = false;
  ++steps_;
}

void ExodusWriter::close() {
  if (exoid_ < 0) return;
  const int status = ex_close(exoid_);
  exoid_ = -1;
  check(status, "ex_close");
}

}  // namespace cgcm::io
