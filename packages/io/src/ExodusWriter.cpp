#include "cgcm/io/ExodusWriter.hpp"

#include <exodusII.h>

#include <algorithm>
#include <set>
#include <stdexcept>

#include "cgcm/core/Error.hpp"

namespace cgcm::io {

namespace {

constexpr int kMaxNameLength = 64;  // Exodus' default is 32; ParaView reads longer names

std::string exodusMessage() {
  const char *msg = nullptr, *func = nullptr;
  int code = 0;
  ex_get_err(&msg, &func, &code);
  return msg && *msg ? std::string(msg) : "Exodus error " + std::to_string(code);
}

// Exodus side (1-based) of `cell` whose nodes are `facet`, 0 if none.
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

}  // namespace

ExodusWriter::ExodusWriter(const std::string& path, const std::string& title, const mesh::Mesh& mesh,
                           const ExodusVariables& variables)
    : path_(path), names_(variables), numNodes_(std::size_t(mesh.numNodes())), numCells_(std::size_t(mesh.numCells())) {
  for (const auto* kind : {&names_.nodal, &names_.element, &names_.global}) {
    std::set<std::string> seen;
    for (const auto& n : *kind) {
      if (n.empty() || int(n.size()) > kMaxNameLength)
        throw std::runtime_error("Exodus file \"" + path + "\": variable name \"" + n + "\" must have 1 to " +
                                 std::to_string(kMaxNameLength) + " characters");
      if (!seen.insert(n).second)
        throw std::runtime_error("Exodus file \"" + path + "\": variable \"" + n + "\" declared twice");
    }
  }
  if (mesh.blocks.empty()) throw std::runtime_error("Exodus file \"" + path + "\": the mesh has no element blocks");
  if (mesh.dim != 2 && mesh.dim != 3)
    throw std::runtime_error("Exodus file \"" + path + "\": mesh dimension " + std::to_string(mesh.dim));

  int cpuWordSize = sizeof(double), ioWordSize = sizeof(double);
  exoid_ = ex_create(path.c_str(), EX_CLOBBER, &cpuWordSize, &ioWordSize);
  if (exoid_ < 0) throw InputError("cannot create Exodus file \"" + path + "\": " + exodusMessage());
  try {
    auto putNames = [this](ex_entity_type type, const std::vector<std::string>& names) {
      std::vector<char*> ptrs;  // Exodus 6.02 takes char*[]
      for (const auto& n : names) ptrs.push_back(const_cast<char*>(n.c_str()));
      if (!ptrs.empty()) check(ex_put_names(exoid_, type, ptrs.data()), "names");
    };
    check(ex_set_max_name_length(exoid_, kMaxNameLength), "name length");

    // Side sets: the bodies' surfaces, as (element, side) pairs.
    std::vector<std::string> sideSetNames;
    std::vector<std::vector<int>> sideElems, sideSides;
    std::vector<LocalIndex> blockStart;
    for (std::size_t b = 0; b < mesh.blocks.size(); ++b) blockStart.push_back(mesh.firstCellOfBlock(b));
    for (const auto& s : mesh.surfaces) {
      if (s.numFacets() == 0) continue;
      auto named =
          std::find_if(mesh.blocks.begin(), mesh.blocks.end(), [&](const auto& b) { return b.body == s.body; });
      sideSetNames.push_back("contact:" +
                             (named != mesh.blocks.end() ? named->name : "body " + std::to_string(s.body)));
      std::vector<int> elems, sides;
      for (LocalIndex f = 0; f < s.numFacets(); ++f) {
        const LocalIndex cell = s.facetCells[f];
        const std::size_t b = std::upper_bound(blockStart.begin(), blockStart.end(), cell) - blockStart.begin() - 1;
        const int side = exodusSide(mesh.blocks[b], cell - blockStart[b], &s.facets[std::size_t(f) * s.nodesPerFacet],
                                    s.nodesPerFacet);
        if (side == 0)
          throw std::runtime_error("Exodus file \"" + path + "\": facet " + std::to_string(f) + " of body " +
                                   std::to_string(s.body) + " is no side of its cell " + std::to_string(cell));
        elems.push_back(cell + 1);
        sides.push_back(side);
      }
      sideElems.push_back(std::move(elems));
      sideSides.push_back(std::move(sides));
    }

    check(ex_put_init(exoid_, title.c_str(), mesh.dim, mesh.numNodes(), mesh.numCells(), int(mesh.blocks.size()),
                      int(mesh.nodeSets.size()), int(sideSetNames.size())),
          "ex_put_init");

    std::vector<double> xyz[3];
    for (int i = 0; i < mesh.dim; ++i) {
      xyz[i].resize(numNodes_);
      for (LocalIndex n = 0; n < mesh.numNodes(); ++n) xyz[i][n] = mesh.coord(n, i);
    }
    check(ex_put_coord(exoid_, xyz[0].data(), xyz[1].data(), mesh.dim == 3 ? xyz[2].data() : nullptr), "coordinates");
    const char* coordNames[] = {"x", "y", "z"};
    check(ex_put_coord_names(exoid_, const_cast<char**>(coordNames)), "coordinate names");

    std::vector<std::string> blockNames;
    for (std::size_t b = 0; b < mesh.blocks.size(); ++b) {
      const auto& block = mesh.blocks[b];
      const int npc = mesh::nodesPerCell(block.type);
      check(ex_put_block(exoid_, EX_ELEM_BLOCK, b + 1, mesh::cellTypeName(block.type), block.numCells(), npc, 0, 0, 0),
            "element block " + block.name);
      std::vector<int> conn(block.connectivity.begin(), block.connectivity.end());
      for (int& n : conn) ++n;
      if (!conn.empty())
        check(ex_put_conn(exoid_, EX_ELEM_BLOCK, b + 1, conn.data(), nullptr, nullptr), "connectivity");
      blockNames.push_back(block.name);
      blockCells_.push_back(std::size_t(block.numCells()));
    }
    putNames(EX_ELEM_BLOCK, blockNames);

    std::vector<std::string> nodeSetNames;
    int id = 0;
    for (const auto& [name, nodes] : mesh.nodeSets) {
      ++id;
      check(ex_put_set_param(exoid_, EX_NODE_SET, id, int(nodes.size()), 0), "node set " + name);
      std::vector<int> ones(nodes.begin(), nodes.end());
      for (int& n : ones) ++n;
      if (!ones.empty()) check(ex_put_set(exoid_, EX_NODE_SET, id, ones.data(), nullptr), "node set " + name);
      nodeSetNames.push_back(name);
    }
    putNames(EX_NODE_SET, nodeSetNames);

    for (std::size_t s = 0; s < sideSetNames.size(); ++s) {
      check(ex_put_set_param(exoid_, EX_SIDE_SET, int(s) + 1, int(sideElems[s].size()), 0), "side set");
      check(ex_put_set(exoid_, EX_SIDE_SET, int(s) + 1, sideElems[s].data(), sideSides[s].data()), "side set");
    }
    putNames(EX_SIDE_SET, sideSetNames);

    const std::pair<ex_entity_type, const std::vector<std::string>*> kinds[] = {
        {EX_NODAL, &names_.nodal}, {EX_ELEM_BLOCK, &names_.element}, {EX_GLOBAL, &names_.global}};
    for (const auto& [type, names] : kinds) {
      if (names->empty()) continue;
      check(ex_put_variable_param(exoid_, type, int(names->size())), "variable count");
      std::vector<char*> ptrs;
      for (const auto& n : *names) ptrs.push_back(const_cast<char*>(n.c_str()));
      check(ex_put_variable_names(exoid_, type, int(names->size()), ptrs.data()), "variable names");
    }
    check(ex_update(exoid_), "ex_update");
  } catch (...) {
    ex_close(exoid_);
    exoid_ = -1;
    throw;
  }
}

ExodusWriter::ExodusWriter(const std::string& path, const mesh::Mesh& mesh, const ExodusVariables& variables,
                           int keptSteps)
    : path_(path), steps_(keptSteps), names_(variables), numNodes_(std::size_t(mesh.numNodes())),
      numCells_(std::size_t(mesh.numCells())) {
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
  if (init.num_dim != mesh.dim || std::size_t(init.num_nodes) != numNodes_ || std::size_t(init.num_elem) != numCells_ ||
      std::size_t(init.num_elem_blk) != mesh.blocks.size())
    refuse("it holds another mesh");
  for (const auto& b : mesh.blocks) blockCells_.push_back(std::size_t(b.numCells()));
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
  checkFields("nodal", names_.nodal, nodal, numNodes_);
  checkFields("element", names_.element, element, numCells_);
  Fields globals;
  for (const auto& [name, v] : global) globals[name] = {v};
  checkFields("global", names_.global, globals, 1);

  const int step = steps_ + 1;
  check(ex_put_time(exoid_, step, &time), "time");
  for (std::size_t k = 0; k < names_.nodal.size(); ++k)
    check(ex_put_var(exoid_, step, EX_NODAL, int(k) + 1, 1, numNodes_, nodal.at(names_.nodal[k]).data()),
          names_.nodal[k]);
  for (std::size_t k = 0; k < names_.element.size(); ++k) {
    const double* values = element.at(names_.element[k]).data();
    for (std::size_t b = 0; b < blockCells_.size(); values += blockCells_[b], ++b)
      if (blockCells_[b] > 0)
        check(ex_put_var(exoid_, step, EX_ELEM_BLOCK, int(k) + 1, b + 1, blockCells_[b], values), names_.element[k]);
  }
  if (!names_.global.empty()) {
    std::vector<double> values;
    for (const auto& name : names_.global) values.push_back(global.at(name));
    check(ex_put_var(exoid_, step, EX_GLOBAL, 1, 1, values.size(), values.data()), "global variables");
  }
  check(ex_update(exoid_), "ex_update");
  steps_ = step;
}

void ExodusWriter::close() {
  if (exoid_ < 0) return;
  const int status = ex_close(exoid_);
  exoid_ = -1;
  check(status, "ex_close");
}

}  // namespace cgcm::io
