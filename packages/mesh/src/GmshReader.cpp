#include "cgcm/mesh/GmshReader.hpp"

#include <gmsh.h>
#include <boost/crc.hpp>
#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <unordered_map>
#include <vector>

#include "cgcm/core/Error.hpp"
#include "cgcm/mesh/Generators.hpp"

namespace cgcm::mesh {

namespace {

namespace fs = std::filesystem;

std::mutex gmshMutex;  // gmsh keeps global state: one read at a time

std::string inQuotes(const std::string& s) { return "\"" + s + "\""; }

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// One gmsh session per read. The parser's variables and the ONELAB
// parameters survive gmsh::finalize(); a DefineConstant with a Name option
// would take the value a previous file gave the same ONELAB name. Clear both.
struct GmshSession {
  explicit GmshSession(bool verbose) {
    gmsh::initialize(0, nullptr, /*readConfigFiles=*/false);
    gmsh::option::setNumber("General.Terminal", verbose ? 1 : 0);
    gmsh::clear();
    gmsh::onelab::clear();
  }
  ~GmshSession() {
    gmsh::onelab::clear();
    gmsh::finalize();
  }
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;
};

// A .geo of "name = value;" lines, merged before the user's file so that its
// DefineConstant[] entries keep these values (gmsh's -setnumber semantics;
// -setnumber itself is stored process-wide by gmsh and would leak into every
// later read).
struct OverrideFile {
  std::string path;
  explicit OverrideFile(const std::map<std::string, double>& numbers) {
    std::string tmpl = (fs::temp_directory_path() / "cgcm-setnumber-XXXXXX.geo").string();
    const int fd = mkstemps(tmpl.data(), 4);
    if (fd < 0) throw InputError("cannot create a temporary file for the gmsh number overrides in " + tmpl);
    close(fd);
    path = tmpl;
    std::ofstream out(path);
    char buf[64];
    for (const auto& [name, value] : numbers) {
      std::snprintf(buf, sizeof buf, "%.17g", value);
      out << name << " = " << buf << ";\n";
    }
  }
  ~OverrideFile() { std::remove(path.c_str()); }
};

// Whether `name` is assigned inside one of the DefineConstant[...] blocks of a .geo text.
bool definesConstant(const std::string& text, const std::string& name) {
  const std::regex assignment("\\b" + name + "\\s*=[^=]");
  for (std::size_t pos = text.find("DefineConstant"); pos != std::string::npos;
       pos = text.find("DefineConstant", pos + 1)) {
    const std::size_t open = text.find('[', pos);
    if (open == std::string::npos) break;
    int depth = 0;
    std::size_t end = open;
    for (; end < text.size(); ++end) {
      if (text[end] == '[') ++depth;
      if (text[end] == ']' && --depth == 0) break;
    }
    if (std::regex_search(text.begin() + open, text.begin() + end, assignment)) return true;
  }
  return false;
}

// Checks a .geo's text: the number overrides must name DefineConstant[]
// entries, and the file must end with a newline (gmsh 4.8 silently drops the
// last statement of a final line that holds several and no newline).
void checkGeo(const std::string& path, const std::map<std::string, double>& numbers) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  if (!text.empty() && text.back() != '\n')
    throw InputError(inQuotes(path) + " does not end with a newline; gmsh may skip its last statement: add one");
  const std::regex identifier("[A-Za-z_][A-Za-z0-9_]*");
  for (const auto& [name, value] : numbers) {
    if (!std::isfinite(value)) throw InputError("gmsh number override " + inQuotes(name) + " is not finite");
    if (!std::regex_match(name, identifier))
      throw InputError("gmsh number override " + inQuotes(name) + " is not a .geo variable name");
    if (!definesConstant(text, name))
      throw InputError("gmsh number override " + inQuotes(name) + ": " + inQuotes(path) +
                       " has no DefineConstant[] entry of that name");
  }
}

std::string elementTypeName(int type) {
  std::string name;
  int dim = 0, order = 0, numNodes = 0, numPrimary = 0;
  std::vector<double> local;
  gmsh::model::mesh::getElementProperties(type, name, dim, order, numNodes, local, numPrimary);
  return name;
}

const char* entityKind(int dim) {
  static const char* kinds[] = {"point", "curve", "surface", "volume"};
  return kinds[dim];
}

// gmsh element type -> cell type of a body of dimension `dim` (false if unsupported).
bool cellTypeOf(int gmshType, int dim, CellType& type) {
  for (const CellTypeInfo& row : kCellTypes)
    if (row.dim == dim && row.gmshType == gmshType) return type = row.type, true;
  return false;
}

// "A", "A and B", "A, B and C".
std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t k = 0; k < names.size(); ++k)
    out += (k == 0 ? "" : k + 1 == names.size() ? " and " : ", ") + names[k];
  return out;
}

// The gmsh names of the cell types of dimension `dim`, for messages: "A" and "B".
std::string supportedGmshTypes(int dim) {
  std::vector<std::string> names;
  for (const CellTypeInfo& row : kCellTypes)
    if (row.dim == dim) names.push_back(std::string("\"") + row.gmshName + "\"");
  return joined(names);
}

// The gmsh names of the element types allowed in boundary groups of dimension `dim`, for messages.
std::string supportedBoundaryTypes(int dim) {
  std::vector<std::string> names;
  if (dim == 0) names.push_back("\"" + elementTypeName(15) + "\"");
  for (const CellTypeInfo& row : kCellTypes) {
    const std::string name = "\"" + elementTypeName(row.gmshFacetType) + "\"";
    if (dim > 0 && row.dim == dim + 1 && std::find(names.begin(), names.end(), name) == names.end())
      names.push_back(name);
  }
  return joined(names);
}

// Element types allowed in lower-dimensional groups: points, and the facets of the cell types.
bool boundaryTypeAllowed(int gmshType, int dim) {
  if (dim == 0) return gmshType == 15;
  for (const CellTypeInfo& row : kCellTypes)
    if (row.dim == dim + 1 && row.gmshFacetType == gmshType) return true;
  return false;
}

Real det3(const Real a[3], const Real b[3], const Real c[3]) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
}

// +1 if the Jacobian is positive at every corner, -1 if negative at every
// corner (the cell is mirrored), 0 otherwise (tangled or degenerate).
int orientation(const Mesh& m, CellType type, const LocalIndex* c) {
  auto edge = [&](int from, int to, Real e[3]) {
    for (int i = 0; i < 3; ++i) e[i] = i < m.dim ? m.coord(c[to], i) - m.coord(c[from], i) : 0.0;
  };
  const CellTypeInfo& row = cellTypeInfo(type);
  int positive = 0, negative = 0;
  for (int k = 0; k < row.numCorners; ++k) {
    const int* corner = row.corners[k];
    Real a[3], b[3], d[3];
    edge(corner[0], corner[1], a), edge(corner[0], corner[2], b);
    Real jac;
    if (row.dim == 2) {
      jac = a[0] * b[1] - a[1] * b[0];
    } else {
      edge(corner[0], corner[3], d);
      jac = det3(a, b, d);
    }
    positive += jac > 0.0, negative += jac < 0.0;
  }
  if (positive == row.numCorners) return 1;
  if (negative == row.numCorners) return -1;
  return 0;
}

// Mirrors a cell's node order (reverses its orientation).
void mirror(CellType type, LocalIndex* c) {
  const CellTypeInfo& row = cellTypeInfo(type);
  LocalIndex copy[kMaxCellNodes];
  std::copy(c, c + row.numNodes, copy);
  for (int a = 0; a < row.numNodes; ++a) c[a] = copy[row.reflected[a]];
}

struct Group {
  int dim, tag;
  std::string name;
};

struct RawBody {
  std::string name;
  std::string group;  // physical name, for messages
  bool typed = false;
  int gmshType = 0;
  CellType type = CellType::Quad4;
  std::vector<std::size_t> nodeTags, elementTags;
};

class Extractor {
 public:
  Extractor(const std::string& path, int dim) : path_(path), dim_(dim) {}

  Mesh run() {
    readGroups();
    readBodies();
    numberNodes();
    Mesh m;
    m.dim = dim_;
    m.coords = coords_;
    m.numBodies = int(bodies_.size());
    buildCells(m);
    std::map<int, std::vector<std::vector<LocalIndex>>> contactFacets;
    readBoundaryGroups(m, contactFacets);
    buildSurfaces(m);
    for (const auto& [body, facets] : contactFacets) restrictSurface(m, body, facets);
    return m;
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw InputError(inQuotes(path_) + ": " + what); }

  void readGroups() {
    gmsh::vectorpair tags;
    gmsh::model::getPhysicalGroups(tags);
    if (tags.empty()) fail("no physical groups; bodies are physical groups named \"body:<name>\" (meshes/README.md)");
    int top = 0;
    for (const auto& [dim, tag] : tags) top = std::max(top, dim);
    if (top != dim_)
      fail("a " + std::to_string(dim_) + "D mesh was expected but the physical groups are " +
           (top < dim_ ? "at most " : "") + std::to_string(top) + "D");
    for (const auto& [dim, tag] : tags) {
      std::string name;
      gmsh::model::getPhysicalName(dim, tag, name);
      const std::string what = "physical " + std::string(entityKind(dim)) + " " + std::to_string(tag);
      if (name.empty()) fail(what + " has no name; every physical group needs one (meshes/README.md)");
      if (dim == dim_ && (!startsWith(name, "body:") || name.size() == 5))
        fail(what + " " + inQuotes(name) + ": groups of the mesh's dimension name bodies, as \"body:<name>\"");
      if (dim < dim_ && startsWith(name, "body:"))
        fail(what + " " + inQuotes(name) + " is " + std::to_string(dim) + "D; a body is a " + std::to_string(dim_) +
             "D group");
      if (startsWith(name, "contact:") && dim != dim_ - 1)
        fail(what + " " + inQuotes(name) + ": a contact surface is a " + std::to_string(dim_ - 1) + "D group");
      groups_.push_back({dim, tag, name});
    }
  }

  void readBodies() {
    std::map<int, std::string> entityBody;  // entity tag -> body group name
    for (const auto& g : groups_) {
      if (g.dim != dim_) continue;
      const std::string bodyName = g.name.substr(5);
      auto it = std::find_if(bodies_.begin(), bodies_.end(), [&](const RawBody& b) { return b.name == bodyName; });
      if (it == bodies_.end()) {
        RawBody fresh;
        fresh.name = bodyName, fresh.group = g.name;
        bodies_.push_back(std::move(fresh));
        it = bodies_.end() - 1;
      }
      RawBody& body = *it;
      std::vector<int> entities;
      gmsh::model::getEntitiesForPhysicalGroup(g.dim, g.tag, entities);
      for (int e : entities) {
        auto [owner, fresh] = entityBody.try_emplace(e, g.name);
        if (!fresh) {
          if (owner->second == g.name) continue;
          fail(std::string(entityKind(dim_)) + " " + std::to_string(e) + " is in two bodies, " +
               inQuotes(owner->second) + " and " + inQuotes(g.name));
        }
        std::vector<int> types;
        std::vector<std::vector<std::size_t>> elementTags, nodeTags;
        gmsh::model::mesh::getElements(types, elementTags, nodeTags, dim_, e);
        for (std::size_t t = 0; t < types.size(); ++t) {
          CellType type;
          if (!cellTypeOf(types[t], dim_, type))
            fail("physical group " + inQuotes(g.name) + " has elements of type " + inQuotes(elementTypeName(types[t])) +
                 "; supported are " + supportedGmshTypes(dim_));
          if (body.typed && type != body.type)
            fail("body " + inQuotes(g.name) + " mixes " + inQuotes(elementTypeName(body.gmshType)) + " and " +
                 inQuotes(elementTypeName(types[t])) + " elements; one element type per body");
          body.typed = true, body.type = type, body.gmshType = types[t];
          body.elementTags.insert(body.elementTags.end(), elementTags[t].begin(), elementTags[t].end());
          body.nodeTags.insert(body.nodeTags.end(), nodeTags[t].begin(), nodeTags[t].end());
        }
      }
      if (body.elementTags.empty()) fail("body " + inQuotes(g.name) + " has no elements");
    }
    // Cells outside every body would silently disappear from the model.
    gmsh::vectorpair entities;
    gmsh::model::getEntities(entities, dim_);
    for (const auto& [d, e] : entities) {
      if (entityBody.count(e)) continue;
      std::vector<int> types;
      std::vector<std::vector<std::size_t>> elementTags, nodeTags;
      gmsh::model::mesh::getElements(types, elementTags, nodeTags, d, e);
      if (!types.empty())
        fail(std::string(entityKind(d)) + " " + std::to_string(e) + " is meshed but in no \"body:<name>\" group");
    }
  }

  void numberNodes() {
    std::vector<std::size_t> used;
    for (const auto& b : bodies_) used.insert(used.end(), b.nodeTags.begin(), b.nodeTags.end());
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    std::vector<std::size_t> tags;
    std::vector<double> xyz, uvw;
    gmsh::model::mesh::getNodes(tags, xyz, uvw, -1, -1, false, false);
    std::unordered_map<std::size_t, std::size_t> position;
    for (std::size_t i = 0; i < tags.size(); ++i) position[tags[i]] = i;
    Real extent = 0.0;
    for (double v : xyz) extent = std::max(extent, std::abs(v));
    coords_.reserve(used.size() * dim_);
    for (std::size_t n = 0; n < used.size(); ++n) {
      index_[used[n]] = LocalIndex(n);
      const double* x = &xyz[3 * position.at(used[n])];
      if (dim_ == 2 && std::abs(x[2]) > 1e-12 * std::max(extent, 1.0))
        fail("node " + std::to_string(used[n]) + " has z = " + std::to_string(x[2]) +
             "; a 2D mesh must lie in the plane z = 0");
      coords_.insert(coords_.end(), x, x + dim_);
    }
  }

  void buildCells(Mesh& m) {
    std::vector<int> owner(coords_.size() / dim_, -1);
    for (std::size_t bi = 0; bi < bodies_.size(); ++bi) {
      const RawBody& raw = bodies_[bi];
      ElementBlock b;
      b.name = raw.name;
      b.body = int(bi);
      b.type = raw.type;
      const int npc = nodesPerCell(raw.type);
      b.connectivity.reserve(raw.nodeTags.size());
      for (std::size_t t : raw.nodeTags) {
        const LocalIndex n = index_.at(t);
        if (owner[n] >= 0 && owner[n] != b.body) {
          std::ostringstream at;
          for (int i = 0; i < dim_; ++i) at << (i ? ", " : "") << coords_[std::size_t(n) * dim_ + i];
          fail("bodies " + inQuotes(bodies_[owner[n]].group) + " and " + inQuotes(raw.group) + " share the node at (" +
               at.str() + "); bodies must be separate meshes (do not fragment them)");
        }
        owner[n] = b.body;
        b.connectivity.push_back(n);
      }
      const CellTypeInfo& row = cellTypeInfo(raw.type);
      for (LocalIndex c = 0; c < b.numCells(); ++c) {
        LocalIndex* cell = &b.connectivity[std::size_t(c) * npc];
        LocalIndex inGmshOrder[kMaxCellNodes];
        std::copy(cell, cell + npc, inGmshOrder);
        for (int a = 0; a < npc; ++a) cell[a] = inGmshOrder[row.fromGmsh[a]];
        const int sign = orientation(m, raw.type, cell);
        if (sign < 0) mirror(raw.type, cell);
        if (sign == 0)
          fail("element " + std::to_string(raw.elementTags[c]) + " of " + inQuotes(raw.group) +
               " is inverted or degenerate (its Jacobian changes sign)");
      }
      m.blocks.push_back(std::move(b));
    }
  }

  void readBoundaryGroups(Mesh& m, std::map<int, std::vector<std::vector<LocalIndex>>>& contactFacets) {
    for (const auto& g : groups_) {
      if (g.dim == dim_) continue;
      int contactBody = -1;
      if (startsWith(g.name, "contact:")) {
        const std::string bodyName = g.name.substr(8);
        auto it = std::find_if(bodies_.begin(), bodies_.end(), [&](const RawBody& b) { return b.name == bodyName; });
        if (it == bodies_.end()) {
          std::string names;
          for (const auto& b : bodies_) names += (names.empty() ? "" : ", ") + inQuotes(b.name);
          fail("physical group " + inQuotes(g.name) + " names no body; the bodies are " + names);
        }
        contactBody = int(it - bodies_.begin());
      }
      std::vector<int> entities;
      gmsh::model::getEntitiesForPhysicalGroup(g.dim, g.tag, entities);
      for (int e : entities) {
        std::vector<int> types;
        std::vector<std::vector<std::size_t>> elementTags, nodeTags;
        gmsh::model::mesh::getElements(types, elementTags, nodeTags, g.dim, e);
        for (std::size_t t = 0; t < types.size(); ++t) {
          if (!boundaryTypeAllowed(types[t], g.dim))
            fail("physical group " + inQuotes(g.name) + " has elements of type " + inQuotes(elementTypeName(types[t])) +
                 "; supported on " + std::to_string(g.dim) + "D boundary groups are " + supportedBoundaryTypes(g.dim));
          if (contactBody < 0) continue;
          const std::size_t npe = nodeTags[t].size() / elementTags[t].size();
          for (std::size_t k = 0; k < elementTags[t].size(); ++k) {
            std::vector<LocalIndex> key;
            for (std::size_t a = 0; a < npe; ++a) key.push_back(nodeIndex(nodeTags[t][k * npe + a], g.name));
            std::sort(key.begin(), key.end());
            contactFacets[contactBody].push_back(std::move(key));
          }
        }
      }
      if (contactBody >= 0 && contactFacets[contactBody].empty())
        fail("physical group " + inQuotes(g.name) + " is empty");
      std::vector<std::size_t> tags;
      std::vector<double> xyz;
      gmsh::model::mesh::getNodesForPhysicalGroup(g.dim, g.tag, tags, xyz);
      if (tags.empty()) fail("physical group " + inQuotes(g.name) + " has no nodes");
      auto& nodes = m.nodeSets[g.name];
      for (std::size_t t : tags) nodes.push_back(nodeIndex(t, g.name));
      std::sort(nodes.begin(), nodes.end());
      nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    }
  }

  LocalIndex nodeIndex(std::size_t tag, const std::string& group) const {
    auto it = index_.find(tag);
    if (it == index_.end())
      fail("physical group " + inQuotes(group) + " has node " + std::to_string(tag) +
           ", which belongs to no body's cell");
    return it->second;
  }

  // Keeps only the facets of the body's boundary listed in its contact groups.
  void restrictSurface(Mesh& m, int body, std::vector<std::vector<LocalIndex>> keys) const {
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    Surface& s = m.surfaces.at(body);
    Surface kept;
    kept.body = s.body;
    kept.nodesPerFacet = s.nodesPerFacet;
    for (LocalIndex f = 0; f < s.numFacets(); ++f) {
      const LocalIndex* n = &s.facets[std::size_t(f) * s.nodesPerFacet];
      std::vector<LocalIndex> key(n, n + s.nodesPerFacet);
      std::sort(key.begin(), key.end());
      if (!std::binary_search(keys.begin(), keys.end(), key)) continue;
      kept.facets.insert(kept.facets.end(), n, n + s.nodesPerFacet);
      kept.facetCells.push_back(s.facetCells[f]);
    }
    if (kept.numFacets() != LocalIndex(keys.size()))
      fail(std::to_string(keys.size() - kept.numFacets()) + " of the " + std::to_string(keys.size()) +
           " elements of \"contact:" + bodies_[body].name + "\" are not on the boundary of body " +
           inQuotes(bodies_[body].group));
    s = std::move(kept);
  }

  std::string path_;
  int dim_;
  std::vector<Group> groups_;
  std::vector<RawBody> bodies_;
  std::unordered_map<std::size_t, LocalIndex> index_;  // gmsh node tag -> node index
  std::vector<Real> coords_;
};

// The mesh cache: a meshed .geo kept as a binary .msh (exact coordinates) with
// a checksum beside it, both named by a CRC-64 of what the mesh depends on.
using Crc64 = boost::crc_optimal<64, 0x42F0E1EBA9EA3693ULL, ~0ULL, ~0ULL, true, true>;  // CRC-64/XZ

std::string hex64(std::uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", (unsigned long long)v);
  return buf;
}

std::string fileBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::uint64_t crcOfFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  Crc64 crc;
  std::vector<char> chunk(1 << 20);
  while (in) {
    in.read(chunk.data(), std::streamsize(chunk.size()));
    crc.process_bytes(chunk.data(), std::size_t(in.gcount()));
  }
  return crc.checksum();
}

// The contents of a .geo and of the files it Includes or Merges, recursively
// (not their paths: a moved project keeps its cache).
void addSources(const fs::path& file, std::set<fs::path>& seen, std::string& key) {
  std::error_code ec;
  const fs::path canonical = fs::weakly_canonical(file, ec);
  if (!seen.insert(ec ? file : canonical).second) return;
  const std::string text = fileBytes(file);  // a missing file adds nothing; gmsh reports it
  key += "source " + std::to_string(text.size()) + "\n" + text + "\n";
  static const std::regex reference("\\b(?:Include|Merge)\\s*\"([^\"]+)\"");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), reference); it != std::sregex_iterator(); ++it)
    addSources(file.parent_path() / (*it)[1].str(), seen, key);
}

std::string cacheKey(const std::string& path, const GmshOptions& options) {
  char buf[64];
  std::string key = "cgcm mesh cache 1\ngmsh " GMSH_API_VERSION "\ndim " + std::to_string(options.dim) +
                    "\norder " + std::to_string(options.element.order) + " serendipity " +
                    std::to_string(int(options.element.serendipity)) + "\n";
  for (const auto* values : {&options.numbers, &options.gmshOptions}) {
    key += "values\n";
    for (const auto& [name, value] : *values) {
      std::snprintf(buf, sizeof buf, "%.17g", value);
      key += name + " = " + buf + "\n";
    }
  }
  std::set<fs::path> seen;
  addSources(path, seen, key);
  Crc64 crc;
  crc.process_bytes(key.data(), key.size());
  return fs::path(path).stem().string() + "-" + hex64(crc.checksum());
}

// Inside a session.
bool knownNumberOption(const std::string& name) {
  if (name.find('.') == std::string::npos) return false;
  try {
    double current = 0.0;
    gmsh::option::getNumber(name, current);
    return true;
  } catch (...) {
    return false;
  }
}

// Each caller-given gmsh option must be a number option of this gmsh.
void checkGmshOptions(const std::map<std::string, double>& gmshOptions) {
  for (const auto& [name, value] : gmshOptions) {
    if (!knownNumberOption(name))
      throw InputError("gmsh option " + inQuotes(name) + ": not a number option of gmsh " GMSH_API_VERSION
                       " (e.g. Mesh.Algorithm3D, General.NumThreads, Mesh.Optimize; gmsh -help lists them)");
    if (!std::isfinite(value)) throw InputError("gmsh option " + inQuotes(name) + " is not finite");
  }
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string seconds(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f s", s);
  return buf;
}

// Keeps the meshed model in the cache: written beside its final name, then
// renamed, the checksum last (a killed run leaves no file that looks valid).
// A failure to write is reported, not fatal: the run has its mesh.
std::string keepInCache(const fs::path& msh, const fs::path& sum) {
  const std::string part = ".part-" + std::to_string(getpid());
  // gmsh picks the format by the extension: .msh last
  const fs::path mshPart = msh.parent_path() / (msh.stem().string() + part + ".msh"), sumPart = sum.string() + part;
  try {
    gmsh::option::setNumber("Mesh.Binary", 1);   // exact coordinates, fast to read
    gmsh::option::setNumber("Mesh.SaveAll", 1);  // every cell, in a physical group or not
    gmsh::write(mshPart.string());
    if (!fs::is_regular_file(mshPart)) throw std::runtime_error("not written");
    std::ofstream(sumPart) << hex64(crcOfFile(mshPart)) << "\n";
    fs::rename(mshPart, msh);
    fs::rename(sumPart, sum);
    return ", kept in " + msh.string();
  } catch (...) {
    std::error_code ec;
    fs::remove(mshPart, ec);
    fs::remove(sumPart, ec);
    return "; could not be kept in " + msh.string() + " (is the folder writable?)";
  }
}

bool cacheValid(const fs::path& msh, const fs::path& sum) {
  std::error_code ec;
  if (!fs::is_regular_file(msh, ec) || !fs::is_regular_file(sum, ec)) return false;
  std::string expected;
  std::ifstream(sum) >> expected;
  return expected == hex64(crcOfFile(msh));
}

}  // namespace

bool isGmshNumberOption(const std::string& name) {
  std::lock_guard<std::mutex> lock(gmshMutex);
  GmshSession session(false);
  return knownNumberOption(name);
}

Mesh readGmsh(const std::string& path, const GmshOptions& options, GmshProvenance* provenance) {
  if (options.dim != 2 && options.dim != 3)
    throw InputError("readGmsh: the mesh dimension must be 2 or 3, got " + std::to_string(options.dim));
  if (options.element.order != 1 && options.element.order != 2)
    throw InputError("readGmsh: the element order must be 1 or 2, got " + std::to_string(options.element.order));
  std::error_code ec;
  if (!fs::is_regular_file(path, ec))
    throw InputError("mesh file " + inQuotes(path) + " does not exist or is not a file");
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext != ".geo" && ext != ".msh")
    throw InputError("mesh file " + inQuotes(path) + ": expected a gmsh .geo or .msh file");
  const bool geo = ext == ".geo";
  if (!geo && !options.numbers.empty())
    throw InputError("mesh file " + inQuotes(path) + ": number overrides apply to .geo files only");
  if (!geo && !options.gmshOptions.empty())
    throw InputError("mesh file " + inQuotes(path) + ": gmsh options apply to meshing a .geo only");
  if (!geo && !options.cache.empty())
    throw InputError("mesh file " + inQuotes(path) + ": a mesh cache applies to meshing a .geo only");
  if (geo) checkGeo(path, options.numbers);

  std::lock_guard<std::mutex> lock(gmshMutex);
  GmshSession session(options.verbose);
  const auto start = std::chrono::steady_clock::now();
  try {
    checkGmshOptions(options.gmshOptions);
    std::string line;
    fs::path cachedMsh, cachedSum;
    if (geo && !options.cache.empty()) {
      const std::string key = cacheKey(path, options);
      cachedMsh = fs::path(options.cache) / (key + ".msh");
      cachedSum = fs::path(options.cache) / (key + ".crc64");
      if (cacheValid(cachedMsh, cachedSum)) {
        gmsh::merge(cachedMsh.string());
        Mesh m = Extractor(path, options.dim).run();
        if (provenance) provenance->line = "mesh read from " + cachedMsh.string() + " in " + seconds(secondsSince(start));
        return m;
      }
      std::error_code ec;
      if (fs::exists(cachedMsh, ec)) line = " (" + cachedMsh.string() + " failed its checksum: meshed again)";
    }
    if (!options.numbers.empty()) {
      OverrideFile overrides(options.numbers);
      gmsh::merge(overrides.path);
    }
    gmsh::merge(path);
    if (geo) {
      // the deck's cells over any the file sets; quadratic: the nodes on the curved geometry
      gmsh::option::setNumber("Mesh.ElementOrder", options.element.order);
      gmsh::option::setNumber("Mesh.SecondOrderIncomplete", options.element.serendipity ? 1 : 0);
      gmsh::option::setNumber("Mesh.SecondOrderLinear", 0);
      for (const auto& [name, value] : options.gmshOptions) gmsh::option::setNumber(name, value);
      gmsh::model::mesh::generate(options.dim);
      line = "meshed by gmsh in " + seconds(secondsSince(start)) + line;
      if (!cachedMsh.empty()) line += keepInCache(cachedMsh, cachedSum);
    }
    Mesh m = Extractor(path, options.dim).run();
    if (provenance) provenance->line = geo ? line : "mesh read from " + path + " in " + seconds(secondsSince(start));
    return m;
  } catch (const InputError&) {
    throw;
  } catch (const std::string& message) {  // gmsh reports errors by throwing their text
    throw InputError(inQuotes(path) + ": gmsh: " + message);
  } catch (const std::exception& e) {
    throw InputError(inQuotes(path) + ": " + e.what());
  } catch (...) {
    std::string message;
    gmsh::logger::getLastError(message);
    throw InputError(inQuotes(path) + ": gmsh: " + (message.empty() ? std::string("unknown error") : message));
  }
}

}  // namespace cgcm::mesh
