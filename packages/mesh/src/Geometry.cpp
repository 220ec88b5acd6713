#include "cgcm/mesh/Geometry.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <map>
#include <sstream>

#include "cgcm/core/Error.hpp"
#include "cgcm/core/ParameterValidators.hpp"
#include "cgcm/mesh/Benchmark.hpp"
#include "cgcm/mesh/Generators.hpp"
#include "cgcm/mesh/GmshReader.hpp"
#include "cgcm/mesh/Mirror.hpp"
#include "cgcm/mesh/Overlap.hpp"

namespace cgcm::mesh {

using Teuchos::ParameterList;

namespace {

void put(core::ByteWriter& out, const DisplacementCondition& c) {
  out.put(c.nodeSet);
  out.put(c.component);
  out.put(c.offset);
  out.put(c.scale);
}

DisplacementCondition getCondition(core::ByteReader& in) {
  DisplacementCondition c;
  c.nodeSet = in.getString();
  c.component = in.get<int>();
  c.offset = in.get<Real>();
  c.scale = in.get<Real>();
  return c;
}

void put(core::ByteWriter& out, const std::vector<DisplacementCondition>& conditions) {
  out.put(std::uint64_t(conditions.size()));
  for (const auto& c : conditions) put(out, c);
}

std::vector<DisplacementCondition> getConditions(core::ByteReader& in) {
  std::vector<DisplacementCondition> conditions(in.getCount(1));
  for (auto& c : conditions) c = getCondition(in);
  return conditions;
}

void put(core::ByteWriter& out, const ForceResponse& f) {
  out.put(f.nodeSet);
  out.put(f.component);
  out.put(f.sign);
  out.put(f.scale);
  out.put(f.direction);
}

ForceResponse getForceResponse(core::ByteReader& in) {
  ForceResponse f;
  f.nodeSet = in.getString();
  f.component = in.get<int>();
  f.sign = in.get<Real>();
  f.scale = in.get<Real>();
  f.direction = in.getVector<Real>();
  return f;
}

}  // namespace

void put(core::ByteWriter& out, const Model& m) {
  put(out, m.conditions);
  put(out, m.force);
  put(out, m.initialMotion);
  out.put(char(m.balance.has_value()));
  if (m.balance) put(out, *m.balance);
  out.put(char(m.contact.has_value()));
  if (const auto& c = m.contact) {
    out.put(c->upperApex);
    out.put(c->lowerApex);
    out.put(c->upperBody);
    out.put(c->lowerBody);
    out.put(c->contactDistance);
  }
  out.put(m.interacting);
  out.put(m.areaFactors);
  out.put(std::uint64_t(m.report.size()));
  for (const auto& line : m.report) out.put(line);
  out.put(m.meshSource);
}

Model getModel(core::ByteReader& in) {
  Model m;
  m.conditions = getConditions(in);
  m.force = getForceResponse(in);
  m.initialMotion = getConditions(in);
  if (in.get<char>()) m.balance = getForceResponse(in);
  if (in.get<char>()) {
    ContactGeometry c;
    c.upperApex = in.getString();
    c.lowerApex = in.getString();
    c.upperBody = in.get<int>();
    c.lowerBody = in.get<int>();
    c.contactDistance = in.get<Real>();
    m.contact = std::move(c);
  }
  m.interacting = in.get<bool>();
  m.areaFactors = in.getVector<Real>();
  m.report.resize(in.getCount(sizeof(std::uint64_t)));
  for (auto& line : m.report) line = in.getString();
  m.meshSource = in.getString();
  return m;
}

Teuchos::RCP<const ParameterList> validParameters() {
  using namespace validators;
  static const Teuchos::RCP<const ParameterList> valid = [] {
    auto g = Teuchos::rcp(new ParameterList("Geometry"));
    g->set("Type", "sphere on half-space",
                 "\"sphere on half-space\" (the paper's benchmark; cylinder on half-space in plane strain; in 3D a "
                 "quarter model of hexahedra, Azimuthal Cells), \"sphere on sphere\", \"block\" (a rectangle or box "
                 "stretched along its last axis), or \"gmsh\" (the mesh of Geometry/File; meshes/README.md)",
                 choices({"sphere on half-space", "sphere on sphere", "block", "gmsh"}));
    g->set("File", "",
                 "Type = gmsh: a gmsh .geo (meshed when read) or .msh file; a relative path is taken from the "
                 "deck's folder. Node sets (physical groups) used: \"driven\" (its last displacement component is "
                 "-u, the rest of its body starts translated with it), \"fixed\" (all components 0), \"axis\" and "
                 "\"symmetry x|y|z\" (that component 0), \"apex\" and \"lower apex\" (one node each: the gap and "
                 "contact radius columns, and u = 0 where they are r_S0 apart)");
    g->set("Drive Direction", "down",
                 "Type = gmsh: the node set \"driven\" moves by u \"down\" (-y in 2D, -z in 3D) or \"up\" (+y, +z) "
                 "along the last axis; the approach closes the gap either way",
                 choices({"down", "up"}));
    g->set("Drive Vector", Teuchos::Array<double>{},
                 "Type = gmsh: a direction d (one entry per dimension, normalised) along which \"driven\" moves by "
                 "u d, every component prescribed, e.g. {1, 0, -1} for an oblique approach; P is the resultant along d. "
                 "Replaces Drive Direction and Driven Components; u is the plain displacement (no apex offset). "
                 "Empty: along the last axis (Drive Direction)");
    g->set("Driven Components", "vertical",
                 "Type = gmsh: which displacement components of \"driven\" are prescribed: \"vertical\" (the last "
                 "one; the others are free, as on the benchmark's equator) or \"all\" (the others are 0: a clamped "
                 "support that moves)",
                 choices({"vertical", "all"}));
    g->set("Mirror Planes", Teuchos::Array<std::string>{},
                 "Type = gmsh: planes through the origin, among \"x\", \"y\", \"z\" (x = 0, ...), in which the mesh "
                 "is mirrored before use, e.g. {x}: the mesh file holds the half on the positive side and the model is "
                 "the whole, node for node symmetric. Bodies cut by the plane are joined with their image; the others "
                 "get an image body; \"symmetry x\" of a mirrored plane is dropped");
    g->sublist("Mesh Numbers", false,
                     "Type = gmsh: values for DefineConstant[] numbers of the .geo, e.g. level = 1 "
                     "(gmsh -setnumber)")
        .disableRecursiveValidation();
    g->sublist("Gmsh Options", false,
               "Type = gmsh with a .geo: gmsh's number options for meshing it, set over the file's, e.g. "
               "Mesh.Algorithm3D = 10 (HXT, gmsh's parallel 3D mesher: many times faster than the default "
               "Delaunay, a different mesh; doc/performance.md) and General.NumThreads = 2 (its threads). Each "
               "name must be a gmsh number option")
        .disableRecursiveValidation();
    g->set("Mesh Cache", "",
           "Type = gmsh with a .geo: a folder (relative: to the deck's) where the meshed .geo is kept as a "
           "binary .msh named by a checksum of the .geo and the files it includes, Mesh Numbers, Gmsh Options, "
           "Element Order and gmsh's version; a later run with the same key reads it instead of meshing "
           "(summary.txt says which). Empty: mesh every run");
    g->set("Element Order", 1,
           "1: linear cells (QUAD4; HEX8, TETRA4), or 2: quadratic cells with mid-edge nodes, QUAD9 (QUAD8 with "
           "Serendipity), HEX27 (HEX20), TETRA10, whose edges and faces follow curved boundaries: the sphere's "
           "arc of the built-in geometries (in 3D its surface); a .geo's curves and surfaces (gmsh's Mesh.ElementOrder). A .msh file "
           "is read as it is and its cells must have this order. Both interaction methods take either order "
           "(Method 3 on the curved segments and facets)",
           intBetween(1, 2));
    g->set("Serendipity", false,
           "Element Order = 2: quadrilaterals and hexahedra without their face and volume centre nodes, QUAD8 "
           "and HEX20 (a .geo: gmsh's Mesh.SecondOrderIncomplete = 1; a .msh must hold them), instead of the "
           "complete QUAD9 and HEX27; tetrahedra are TETRA10 either way");
    g->set("Sphere Radius", 1.0,
                 "radius R0 of the upper sphere: the reference length (with a gmsh mesh: R0 of gammaL = R0/r0 and of "
                 "the force unit)",
                 atLeast(1e-300));
    g->set("Second Sphere Radius", 1.0, "radius of the lower sphere (Type = sphere on sphere)",
                 atLeast(1e-300));
    g->set("Half-Space Size", 8.0, "width and depth of the half-space block, in sphere radii (>= 2)",
                 atLeast(2.0));
    g->set("Mesh Refinement", 0,
                 "level 0 (about 1400 nodes) .. 6; each level halves every cell. -1 doubles those of level 0: "
                 "with Element Order = 2 it has as many nodes as the linear level 0",
                 intBetween(mesh::kCoarsestLevel, mesh::kFinestLevel));
    g->set("Contact Zone Size", 0.5,
                 "radial extent of the finest cells around the axis, in sphere radii (0.02 .. 0.85): 20 cells on "
                 "the half-space and 16 on the sphere at level 0. Smaller zones resolve smaller contacts (large "
                 "gammaL) with the same number of cells",
                 between(0.02, 0.85));
    g->set("Azimuthal Cells", 8,
           "Type = sphere on half-space in 3D: cells over the quarter model's 90 degrees at Mesh Refinement 0 "
           "(each level doubles them), even: the meridian meshes of plane strain and axisymmetry swept about the "
           "axis, with a butterfly core of half as many cells per side around it. The core's radius, about Azimuthal "
           "Cells x Contact Zone Size / 40 sphere radii, must stay below about 0.35 (an error says how many fit)",
           intBetween(2, 64));
    auto& block = g->sublist("Block", false,
                                   "Type = block: corner at the origin; symmetry rollers on the faces x = 0, y = 0 "
                                   "(and z = 0 in 3D); the face at the far end of the last axis moves by the load u");
    block.set("Length X", 1.0, "edge length along x (the radius in axisymmetry)", atLeast(1e-300));
    block.set("Length Y", 1.0, "edge length along y", atLeast(1e-300));
    block.set("Length Z", 1.0, "edge length along z (3D)", atLeast(1e-300));
    block.set("Cells X", 4, "cells along x", intAtLeast(1));
    block.set("Cells Y", 4, "cells along y", intAtLeast(1));
    block.set("Cells Z", 4, "cells along z (3D)", intAtLeast(1));
    block.set("Element", "hex8",
              "3D cell shape: \"hex8\" or \"tet4\" (6 per hexahedron); with Geometry/Element Order = 2 they are "
              "HEX27 (HEX20 with Serendipity) and TETRA10",
              choices({"hex8", "tet4"}));
    block.set("Load", "stretch",
              "\"stretch\": the face at the far end of the last axis moves by u along that axis, on symmetry rollers; "
              "\"bend\": a cantilever (plane strain or 3D): the face x = 0 clamped, the lower edge of the face x = "
              "Length X (node set \"tip\": the corner (Length X, 0) in 2D, the line x = Length X, z = 0 in 3D) moves "
              "by u along the last axis (y in 2D, z in 3D), the rest is free; P is the tip force along that axis",
              choices({"stretch", "bend"}));
    block.set("Loaded Face", "roller",
              "Load = stretch: \"roller\": the loaded face slides freely (homogeneous uniaxial stress); \"clamped\": it "
              "cannot slide",
              choices({"roller", "clamped"}));
    block.set("Distortion", 0.0, "random shift of interior nodes, as a fraction of the smallest edge (0 .. 0.4)",
              between(0.0, 0.4));
    block.set("Distortion Seed", 1, "seed of the random node shift", intAtLeast(0));
    return Teuchos::RCP<const ParameterList>(g);
  }();
  return valid;
}

namespace {

// Per node of the mesh, whether it belongs to a cell of `body`.
std::vector<char> nodesOfBody(const Mesh& m, int body) {
  std::vector<char> inBody(std::size_t(m.numNodes()), 0);
  for (const auto& block : m.blocks)
    if (block.body == body)
      for (LocalIndex n : block.connectivity) inBody[std::size_t(n)] = 1;
  return inBody;
}

// The node set of every node of the body, added to the mesh on first use.
std::string wholeBodySet(Mesh& m, const std::vector<char>& inBody, const std::string& name) {
  const std::string set = name + " (all nodes)";
  if (m.nodeSets.count(set)) return set;
  std::vector<LocalIndex> nodes;
  for (LocalIndex n = 0; n < m.numNodes(); ++n)
    if (inBody[std::size_t(n)]) nodes.push_back(n);
  if (nodes.empty()) throw InputError("Bodies/" + name + ": the body has no cells");
  m.nodeSets[set] = std::move(nodes);
  return set;
}

}  // namespace

bool measureOnWholeBody(Model& model, int body, const std::string& name) {
  Mesh& m = *model.mesh;
  const std::vector<char> inBody = nodesOfBody(m, body);
  bool changed = false;
  const auto onBody = [&](ForceResponse& r) {
    const auto& ns = m.nodeSet(r.nodeSet);
    if (ns.empty() || !std::all_of(ns.begin(), ns.end(), [&](LocalIndex n) { return inBody[std::size_t(n)] != 0; }))
      return;
    r.nodeSet = wholeBodySet(m, inBody, name);
    changed = true;
  };
  onBody(model.force);
  if (model.balance) onBody(*model.balance);
  return changed;
}

void makeRigid(Model& model, int body, const std::string& name) {
  Mesh& m = *model.mesh;
  const std::vector<char> inBody = nodesOfBody(m, body);
  const std::string where = "Bodies/" + name + "/Rigid";
  const auto touches = [&](const std::string& set) {
    const auto& ns = m.nodeSet(set);
    return std::any_of(ns.begin(), ns.end(), [&](LocalIndex n) { return inBody[std::size_t(n)] != 0; });
  };
  static const char* const axes[] = {"x", "y", "z"};
  std::vector<DisplacementCondition> motion;
  for (int i = 0; i < m.dim; ++i) {
    const DisplacementCondition* found = nullptr;
    for (const auto& c : model.conditions) {
      if (c.component != i || !touches(c.nodeSet)) continue;
      if (found && (found->offset != c.offset || found->scale != c.scale))
        throw InputError(where + ": a rigid body moves as a whole, but its node sets \"" + found->nodeSet +
                         "\" and \"" + c.nodeSet + "\" prescribe different " + axes[i] + "-displacements");
      if (!found) found = &c;
    }
    if (!found)
      throw InputError(where + ": no condition holds or drives the body's " + axes[i] +
                       "-displacement; a rigid body has no unknowns of its own, so each component needs a fixed or "
                       "driven condition on one of its node sets");
    motion.push_back({"", i, found->offset, found->scale});
  }
  const std::string set = wholeBodySet(m, inBody, name);
  for (auto& c : motion) c.nodeSet = set;
  model.conditions.insert(model.conditions.end(), motion.begin(), motion.end());
  measureOnWholeBody(model, body, name);
}

Real reducedRadius(const ParameterList& g) {
  const Real R0 = g.get<double>("Sphere Radius"), R2 = g.get<double>("Second Sphere Radius");
  return g.get<std::string>("Type") == "sphere on sphere" ? R0 * R2 / (R0 + R2) : R0;
}

ElementOrder elementOrder(const ParameterList& g) {
  ElementOrder e{g.get<int>("Element Order"), g.get<bool>("Serendipity")};
  if (e.serendipity && e.order != 2)
    throw InputError("Geometry/Serendipity = true needs Geometry/Element Order = 2 (it is " + std::to_string(e.order) +
                     "); serendipity cells are quadratic");
  return e;
}

namespace {

// P means the force on the whole body in every formulation: a model that is a
// part of it, cut by symmetry planes across the drive (3D: x = 0, y = 0; plane
// strain: the symmetry line x = 0, "axis" or "symmetry x"), reports 2 x the
// resultant per plane, and says so. In axisymmetry forces are ring totals already.
// `mirrored`: the planes the mesh was mirrored in (Geometry/Mirror Planes), no cuts any more.
void reportWholeBody(Model& s, Formulation formulation, const std::string& mirrored = "") {
  std::vector<const char*> sets;
  if (formulation == Formulation::ThreeD) sets = {"symmetry x", "symmetry y"};
  if (formulation == Formulation::PlaneStrain && mirrored.find('x') == std::string::npos) sets = {"axis", "symmetry x"};
  std::string planes;
  for (const char* set : sets) {
    if (!s.mesh->nodeSets.count(set)) continue;
    // in plane strain "axis" and "symmetry x" name the same line x = 0
    if (formulation != Formulation::PlaneStrain || planes.empty()) s.force.scale *= 2.0;
    planes += std::string(planes.empty() ? "" : ", ") + set;
  }
  if (s.force.scale != 1.0)
    s.report.push_back("P = " + std::to_string(int(s.force.scale)) + " x the resultant on \"" + s.force.nodeSet +
                       "\": the force on the whole body of the mesh's symmetry planes (" + planes + ")" +
                       (formulation == Formulation::PlaneStrain ? ", per unit thickness" : ""));
  if (s.balance) s.balance->scale = s.force.scale;
}

// The cells of a mesh read from a file against Element Order and Serendipity: a clear error naming both.
void checkElementOrder(const Mesh& m, const ElementOrder& wanted, const std::string& file) {
  for (const auto& b : m.blocks) {
    const CellTypeInfo& row = cellTypeInfo(b.type);
    const bool serendipity = row.order == 2 && !row.simplex && row.numNodes < (row.dim == 2 ? 9 : 27);
    const std::string has = "mesh file \"" + file + "\": body \"" + b.name + "\" has " + row.name +
                            " cells (order " + std::to_string(row.order) + (serendipity ? ", serendipity" : "") + ")";
    if (row.order != wanted.order)
      throw InputError(has + ", but Geometry/Element Order = " + std::to_string(wanted.order) +
                       "; set it to " + std::to_string(row.order) + " or mesh the file again");
    if (row.order == 2 && !row.simplex && serendipity != wanted.serendipity)
      throw InputError(has + ", but Geometry/Serendipity = " + (wanted.serendipity ? "true" : "false") + "; set it to " +
                       (serendipity ? "true" : "false") + " or mesh the file again");
  }
}

// The meridian meshes of the sphere (its centre at centreY) and the half-space block.
mesh::QuarterDiskSpec sphereSpec(const ParameterList& g, Real centreY) {
  mesh::QuarterDiskSpec sphere;
  sphere.radius = g.get<double>("Sphere Radius");
  sphere.centerY = centreY;
  sphere.refinement = g.get<int>("Mesh Refinement");
  sphere.element = elementOrder(g);
  sphere.fineAngle = 0.8 * g.get<double>("Contact Zone Size");  // the fine cells of both bodies are then equally long
  sphere.name = "sphere";
  return sphere;
}

mesh::HalfSpaceSpec halfSpaceSpec(const ParameterList& g) {
  const Real R0 = g.get<double>("Sphere Radius");
  mesh::HalfSpaceSpec h;
  h.width = h.depth = g.get<double>("Half-Space Size") * R0;
  h.fineLength = g.get<double>("Contact Zone Size") * R0;
  h.refinement = g.get<int>("Mesh Refinement");
  h.element = elementOrder(g);
  return h;
}

// The benchmark in 3D: the meridian meshes swept over a quarter (x, y >= 0) into hexahedra, with the
// node sets, conditions and responses of a gmsh mesh of it (buildFromGmsh on
// meshes/sphere-on-half-space-3d.geo), so that either gives the same kind of run.
void buildSphereOnHalfSpaceQuarter(const ParameterList& g, const ContactDistance& contactDistance, Model& s) {
  const int cells = g.get<int>("Azimuthal Cells"), level = g.get<int>("Mesh Refinement");
  if (cells % 2 != 0)
    throw InputError(
        "Geometry/Azimuthal Cells = " + std::to_string(cells) +
        " is odd; the quarter's core has half of them on each of its two outer sides: give an even number");
  const Real zone = g.get<double>("Contact Zone Size");
  if (mesh::cellsAtLevel(cells, level) % 2 != 0)
    throw InputError("Geometry/Azimuthal Cells = " + std::to_string(cells) + " at Mesh Refinement " +
                     std::to_string(level) + " gives " + std::to_string(mesh::cellsAtLevel(cells, level)) +
                     " cells, odd; the quarter's core has half of them on each of its two outer sides: give a "
                     "multiple of 4");
  const int largest = mesh::cellsAtLevel(mesh::largestQuarterCells(sphereSpec(g, 1.0), halfSpaceSpec(g)), -level);
  if (cells > largest) {
    std::ostringstream zoneText;
    zoneText << zone;
    throw InputError("Geometry/Azimuthal Cells = " + std::to_string(cells) +
                     " with Contact Zone Size = " + zoneText.str() + ": the core around the axis (radius about " +
                     "Azimuthal Cells x Contact Zone Size / 40 sphere radii) would not turn into circles within the "
                     "sphere; at most " +
                     std::to_string(largest - largest % (level < 0 ? 4 : 2)) + " cells fit, or a smaller Contact Zone Size");
  }
  const Real R0 = g.get<double>("Sphere Radius");
  const Real rS0 = contactDistance();  // u = 0: undeformed surfaces r_S0 apart
  s.mesh =
      std::make_shared<Mesh>(mesh::sphereOnHalfSpaceQuarter(sphereSpec(g, R0 + rS0), halfSpaceSpec(g), mesh::cellsAtLevel(cells, level)));
  s.interacting = true;
  s.areaFactors = {R0, R0};
  s.conditions = {{"driven", 2, 0.0, -1.0}};
  s.initialMotion = {{"driven body", 2, 0.0, -1.0}};  // the sphere starts translated rigidly
  s.force = {"driven", 2, -1.0};                      // P > 0: compressive
  s.force.direction = {0.0, 0.0, -1.0};
  s.balance = ForceResponse{"fixed", 2, 1.0};
  s.balance->direction = {0.0, 0.0, 1.0};
  s.contact = ContactGeometry{"apex", "lower apex", 0, 1, rS0};
  reportWholeBody(s, Formulation::ThreeD);
  for (int i = 0; i < 3; ++i) s.conditions.push_back({"fixed", i, 0.0, 0.0});
  s.conditions.push_back({"symmetry x", 0, 0.0, 0.0});
  s.conditions.push_back({"symmetry y", 1, 0.0, 0.0});
}

// Sphere (radius R0, apex at the equilibrium gap above y = 0) over a half-space
// block or a second sphere; u moves the sphere's equator plane down.
void buildSphereContact(const ParameterList& g, Formulation formulation, const ContactDistance& contactDistance,
                        Model& s) {
  const bool onSphere = g.get<std::string>("Type") == "sphere on sphere";
  if (formulation == Formulation::ThreeD && onSphere)
    throw InputError(
        "Geometry/Type = \"sphere on sphere\" is built in plane strain or axisymmetry; "
        "Problem/Formulation = \"3D\" needs a mesh file (inputs/3d/two-spheres.xml)");
  if (formulation == Formulation::ThreeD) return buildSphereOnHalfSpaceQuarter(g, contactDistance, s);
  const Real R0 = g.get<double>("Sphere Radius"), R2 = g.get<double>("Second Sphere Radius");
  const int level = g.get<int>("Mesh Refinement");
  const Real rS0 = contactDistance();  // u = 0: undeformed surfaces r_S0 apart

  mesh::QuarterDiskSpec sphere = sphereSpec(g, R0 + rS0);
  const Real zone = g.get<double>("Contact Zone Size");
  auto m = std::make_shared<mesh::Mesh>(mesh::quarterDisk(sphere));
  auto& upper = m->nodeSets["upper body"];
  for (LocalIndex n = 0; n < m->numNodes(); ++n) upper.push_back(n);
  if (onSphere) {
    mesh::QuarterDiskSpec lower;
    lower.radius = R2;
    lower.centerY = -R2;
    lower.lowerHalf = false;
    lower.refinement = level;
    lower.element = sphere.element;
    lower.fineAngle = std::min(0.8 * zone * R0 / R2, 0.69);
    lower.name = "second sphere";
    mesh::append(*m, mesh::quarterDisk(lower), "lower ");
  } else {
    mesh::Mesh block = mesh::halfSpaceBlock(halfSpaceSpec(g));
    block.nodeSets["equator"] = block.nodeSets.at("bottom");  // the fixed far side
    mesh::append(*m, block, "lower ");
  }
  // Only the curved (or top) faces interact: the axis is a symmetry line and the
  // equator planes carry the supports.
  for (const char* set : {"axis", "equator"}) {
    mesh::removeFacetsOn(*m, 0, m->nodeSet(set));
    mesh::removeFacetsOn(*m, 1, m->nodeSet(std::string("lower ") + set));
  }
  if (!onSphere) mesh::removeFacetsOn(*m, 1, m->nodeSet("lower side"));
  s.mesh = m;
  s.interacting = true;
  s.areaFactors = formulation == Formulation::PlaneStrain ? std::vector<Real>{R0} : std::vector<Real>{R0, R0};
  s.conditions = {{"axis", 0, 0.0, 0.0},       {"equator", 1, 0.0, -1.0}, {"lower axis", 0, 0.0, 0.0},
                  {"lower equator", 0, 0.0, 0.0}, {"lower equator", 1, 0.0, 0.0}};
  s.force = {"equator", 1, -1.0};  // P > 0: compressive
  s.initialMotion = {{"upper body", 1, 0.0, -1.0}};  // the sphere starts translated rigidly
  s.balance = ForceResponse{"lower equator", 1, 1.0};
  s.contact = ContactGeometry{"apex", "lower apex", 0, 1, rS0};
  reportWholeBody(s, formulation);
}

// Number overrides of a .geo: every entry of Geometry/Mesh Numbers, a number.

std::map<std::string, double> meshNumbers(const ParameterList& numbers, const std::string& sublist) {
  std::map<std::string, double> out;
  for (auto it = numbers.begin(); it != numbers.end(); ++it) {
    const auto& entry = numbers.entry(it);
    const std::string name = numbers.name(it);
    if (entry.isType<double>()) out[name] = entry.getValue<double>(nullptr);
    else if (entry.isType<int>()) out[name] = entry.getValue<int>(nullptr);
    else throw InputError("Geometry/" + sublist + "/" + name + ": a number is expected");
  }
  return out;
}

// The unit direction of the drive: Geometry/Drive Vector, normalised and checked against the mesh, or
// the last axis, down or up (Drive Direction).
std::vector<Real> driveDirection(const ParameterList& g, const mesh::Mesh& m) {
  const auto& given = g.get<Teuchos::Array<double>>("Drive Vector");
  if (given.empty()) {
    std::vector<Real> d(m.dim, 0.0);
    d.back() = g.get<std::string>("Drive Direction") == "up" ? 1.0 : -1.0;
    return d;
  }
  if (!g.getEntry("Drive Direction").isDefault() || !g.getEntry("Driven Components").isDefault())
    throw InputError("Geometry/Drive Vector: give it, or Drive Direction and Driven Components, not both");
  if (int(given.size()) != m.dim)
    throw InputError("Geometry/Drive Vector: " + std::to_string(given.size()) + " entries; the mesh is " +
                     std::to_string(m.dim) + "D, give " + std::to_string(m.dim));
  Real norm = 0.0;
  for (double v : given) norm += v * v;
  norm = std::sqrt(norm);
  if (!(norm > 0.0) || !std::isfinite(norm))
    throw InputError("Geometry/Drive Vector: a finite, nonzero direction is expected");
  std::vector<Real> d;
  for (double v : given) d.push_back(v / norm);
  for (int i = 0; i < m.dim; ++i) {
    const std::string plane = std::string("symmetry ") + "xyz"[i];
    if (m.nodeSets.count(plane) && std::abs(d[i]) > 1e-12)
      throw InputError("Geometry/Drive Vector: its " + std::string(1, "xyz"[i]) + " component moves \"driven\" "
                       "across the symmetry plane of \"" + plane + "\"; a symmetric model is driven along it");
  }
  return d;
}

// A mesh from gmsh with the physical-group convention of meshes/README.md
// mapped to boundary conditions; its bodies interact when there are several.
void buildFromGmsh(const ParameterList& g, Formulation formulation, const ContactDistance& contactDistance, Model& s) {
  const std::string file = g.get<std::string>("File");
  if (file.empty()) throw InputError("Geometry/Type = \"gmsh\" needs Geometry/File (a gmsh .geo or .msh file)");
  mesh::GmshOptions options;
  options.dim = formulationDim(formulation);
  if (g.isSublist("Mesh Numbers")) options.numbers = meshNumbers(g.sublist("Mesh Numbers"), "Mesh Numbers");
  if (g.isSublist("Gmsh Options")) options.gmshOptions = meshNumbers(g.sublist("Gmsh Options"), "Gmsh Options");
  for (const auto& [name, value] : options.gmshOptions)
    if (!mesh::isGmshNumberOption(name))
      throw InputError("Geometry/Gmsh Options/" + name + ": not a number option of gmsh (allowed: gmsh's number "
                       "options, e.g. Mesh.Algorithm3D, General.NumThreads, Mesh.Optimize; `gmsh -help` lists them)");
  options.cache = g.get<std::string>("Mesh Cache");
  if (!options.cache.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(options.cache, ec);
    if (!std::filesystem::is_directory(options.cache, ec))
      throw InputError("Geometry/Mesh Cache: \"" + options.cache + "\" is not a folder and cannot be made one");
  }
  const ElementOrder element = elementOrder(g);
  options.element = element;
  mesh::GmshProvenance provenance;
  auto m = std::make_shared<mesh::Mesh>(mesh::readGmsh(file, options, &provenance));
  s.report.push_back(provenance.line);
  s.meshSource = provenance.line;
  checkElementOrder(*m, element, file);
  const auto fail = [&](const std::string& what) { throw InputError("mesh file \"" + file + "\": " + what); };
  std::string mirrored;
  for (const std::string& plane : g.get<Teuchos::Array<std::string>>("Mirror Planes")) {
    const int axis = plane == "x" ? 0 : plane == "y" ? 1 : plane == "z" ? 2 : -1;
    if (axis == 0 && formulation == Formulation::Axisymmetric)
      throw InputError("Geometry/Mirror Planes: \"x\" with Problem/Formulation = \"axisymmetric\": x is the radius, "
                       "the mesh cannot be mirrored across the axis; allowed: \"y\"");
    if (axis < 0 || axis >= m->dim || mirrored.find(plane) != std::string::npos)
      throw InputError("Geometry/Mirror Planes: \"" + plane + "\" " +
                       (axis >= 0 && axis < m->dim ? "is given twice" : "is not a plane of this mesh") +
                       "; allowed: distinct names among " + (m->dim == 3 ? "\"x\", \"y\", \"z\"" : "\"x\", \"y\""));
    mesh::mirror(*m, axis);
    mirrored += plane;
  }
  if (formulation == Formulation::Axisymmetric)
    for (LocalIndex n = 0; n < m->numNodes(); ++n)
      if (m->coord(n, 0) < 0.0)
        fail("node " + std::to_string(n) + " has x = " + std::to_string(m->coord(n, 0)) +
             " < 0; axisymmetric meshes lie in x >= 0 (x is the radius)");
  if (const std::string overlap = mesh::findBodyOverlap(*m); !overlap.empty())
    fail("bodies overlap in the reference configuration: " + overlap);
  if (!m->nodeSets.count("driven"))
    fail("no physical group \"driven\" (where the approach u is applied; meshes/README.md)");

  const int dim = m->dim, vertical = dim - 1;
  std::vector<int> nodeBody(m->numNodes(), 0);
  for (const auto& b : m->blocks)
    for (LocalIndex n : b.connectivity) nodeBody[n] = b.body;
  auto bodyOf = [&](const std::string& set) { return nodeBody[m->nodeSet(set).front()]; };
  // the bodies the driven set belongs to move rigidly with it at the start
  std::vector<char> drivenBody(m->numBodies, 0);
  for (LocalIndex n : m->nodeSet("driven")) drivenBody[nodeBody[n]] = 1;
  auto& moving = m->nodeSets["driven body"];
  for (LocalIndex n = 0; n < m->numNodes(); ++n)
    if (drivenBody[nodeBody[n]]) moving.push_back(n);

  const Real R0 = g.get<double>("Sphere Radius");
  Real offset = 0.0;
  // The drive: "driven" moves by u d. Along the last axis (Drive Direction) only that component is
  // prescribed unless Driven Components = all; along a Drive Vector every component is.
  const bool alongVector = !g.get<Teuchos::Array<double>>("Drive Vector").empty();
  const std::vector<Real> d = driveDirection(g, *m);
  const Real drive = d[vertical];
  const bool allComponents = alongVector || g.get<std::string>("Driven Components") == "all";
  if (m->numBodies > 1) {
    s.interacting = true;
    const Real rS0 = contactDistance();
    if (m->nodeSets.count("apex") && m->nodeSets.count("lower apex")) {
      for (const char* set : {"apex", "lower apex"})
        if (m->nodeSet(set).size() != 1)
          fail("node set \"" + std::string(set) + "\" has " + std::to_string(m->nodeSet(set).size()) +
               " nodes; it must be one point" +
               (mirrored.empty() ? std::string() : " (a point off a mirror plane of Geometry/Mirror Planes is doubled)"));
      s.contact = ContactGeometry{"apex", "lower apex", bodyOf("apex"), bodyOf("lower apex"), rS0};
      // u = 0 where the apexes are r_S0 apart, as in the built-in benchmark
      // (the driven body approaches the other one as u grows)
      const Real separation = std::abs(m->coord(m->nodeSet("apex").front(), vertical) -
                                       m->coord(m->nodeSet("lower apex").front(), vertical));
      if (!alongVector) offset = -drive * (rS0 - separation);
    }
    // the support reacts against the drive: P_lower ~ P whichever way the drive goes
    if (m->nodeSets.count("fixed")) {
      s.balance = ForceResponse{"fixed", vertical, -drive};
      for (Real di : d) s.balance->direction.push_back(-di);
    }
  }
  s.areaFactors = formulation == Formulation::PlaneStrain ? std::vector<Real>{R0} : std::vector<Real>{R0, R0};
  for (int i = 0; i < dim; ++i) {
    const Real shift = i == vertical ? offset : 0.0;
    if (i == vertical || allComponents) s.conditions.push_back({"driven", i, shift, d[i]});
    if (d[i] != 0.0) s.initialMotion.push_back({"driven body", i, shift, d[i]});
  }
  s.force = {"driven", vertical, drive};  // P > 0: compressive
  s.force.direction = d;
  s.mesh = m;
  reportWholeBody(s, formulation, mirrored);
  if (m->nodeSets.count("fixed"))
    for (int i = 0; i < dim; ++i) s.conditions.push_back({"fixed", i, 0.0, 0.0});
  if (m->nodeSets.count("axis")) s.conditions.push_back({"axis", 0, 0.0, 0.0});
  for (int i = 0; i < dim; ++i) {
    const std::string set = std::string("symmetry ") + "xyz"[i];
    if (m->nodeSets.count(set)) s.conditions.push_back({set, i, 0.0, 0.0});
  }
}

// The bent block's load line: the nodes in both node sets (the corner of the loaded face in 2D, its
// lower edge in 3D). Only they are driven: a whole driven face would also be held flat as it
// turns, a constraint whose energy grows as u^4 and stiffens the strip (6 % at u = L / 100 in
// plane strain), while a line load only disturbs the field near it.
void addEdgeSet(Mesh& m, const std::string& name, const std::string& a, const std::string& b) {
  const auto& na = m.nodeSet(a);
  const auto& nb = m.nodeSet(b);
  std::vector<LocalIndex> both;
  std::set_intersection(na.begin(), na.end(), nb.begin(), nb.end(), std::back_inserter(both));
  m.nodeSets[name] = both;
}

// A rectangle (plane strain, axisymmetry) or box stretched along its last
// axis by u, on symmetry rollers; or bent as a cantilever clamped at x = 0.
void buildBlock(const ParameterList& g, Formulation formulation, Model& s) {
  const auto& b = g.sublist("Block");
  const bool clamped = b.get<std::string>("Loaded Face") == "clamped";
  const bool bend = b.get<std::string>("Load") == "bend";
  if (bend && formulation == Formulation::Axisymmetric)
    throw InputError("Geometry/Block/Load = \"bend\" is a cantilever in plane strain or 3D; in axisymmetry x is the "
                     "radius (use Problem/Formulation = \"plane strain\" or \"3D\")");
  if (bend && clamped)
    throw InputError("Geometry/Block/Loaded Face = \"clamped\" is for Load = \"stretch\"; the bent block is driven "
                     "at the edge \"tip\" of its free end alone");
  if (formulation == Formulation::ThreeD) {
    BoxSpec spec;
    spec.element = elementOrder(g);
    spec.lx = b.get<double>("Length X");
    spec.ly = b.get<double>("Length Y");
    spec.lz = b.get<double>("Length Z");
    spec.nx = b.get<int>("Cells X");
    spec.ny = b.get<int>("Cells Y");
    spec.nz = b.get<int>("Cells Z");
    spec.tetrahedra = b.get<std::string>("Element") == "tet4";
    s.mesh = std::make_shared<Mesh>(box(spec));
    if (bend) {
      addEdgeSet(*s.mesh, "tip", "xmax", "zmin");
      s.conditions = {{"xmin", 0, 0.0, 0.0}, {"xmin", 1, 0.0, 0.0}, {"xmin", 2, 0.0, 0.0}, {"tip", 2, 0.0, 1.0}};
      s.force = {"tip", 2, 1.0};
      s.areaFactors = {spec.ly, spec.lz};
    } else {
      s.conditions = {{"xmin", 0, 0.0, 0.0}, {"ymin", 1, 0.0, 0.0}, {"zmin", 2, 0.0, 0.0}, {"zmax", 2, 0.0, 1.0}};
      if (clamped) s.conditions.insert(s.conditions.end(), {{"zmax", 0, 0.0, 0.0}, {"zmax", 1, 0.0, 0.0}});
      s.force = {"zmax", 2, 1.0};
      s.areaFactors = {spec.lx, spec.ly};
    }
  } else {
    RectangleSpec spec;
    spec.element = elementOrder(g);
    spec.lx = b.get<double>("Length X");
    spec.ly = b.get<double>("Length Y");
    spec.nx = b.get<int>("Cells X");
    spec.ny = b.get<int>("Cells Y");
    s.mesh = std::make_shared<Mesh>(rectangle(spec));
    if (bend) {
      addEdgeSet(*s.mesh, "tip", "right", "bottom");
      s.conditions = {{"left", 0, 0.0, 0.0}, {"left", 1, 0.0, 0.0}, {"tip", 1, 0.0, 1.0}};
      s.force = {"tip", 1, 1.0};
      s.areaFactors = {spec.ly};
    } else {
      s.conditions = {{"left", 0, 0.0, 0.0}, {"bottom", 1, 0.0, 0.0}, {"top", 1, 0.0, 1.0}};
      if (clamped) s.conditions.push_back({"top", 0, 0.0, 0.0});
      s.force = {"top", 1, 1.0};
      s.areaFactors = formulation == Formulation::Axisymmetric ? std::vector<Real>{kPi, spec.lx, spec.lx}
                                                               : std::vector<Real>{spec.lx};
    }
  }
  if (b.get<double>("Distortion") > 0.0)
    perturbInteriorNodes(*s.mesh, b.get<double>("Distortion"), unsigned(b.get<int>("Distortion Seed")));
}

// Every body must be held against rigid motion by its displacement conditions:
// with the interaction alone its tangent is singular (or nearly: a weak
// adhesive spring), and Newton fails without saying why. The conditions of a
// body, evaluated on the rigid modes (translations, rotations; in axisymmetry
// only the axial translation), must have full rank.
void checkBodiesAreHeld(const Model& s, Formulation formulation) {
  const mesh::Mesh& m = *s.mesh;
  const int dim = m.dim;
  const bool axi = formulation == Formulation::Axisymmetric;
  const int modes = axi ? 1 : dim == 2 ? 3 : 6;
  std::vector<int> nodeBody(m.numNodes(), -1);
  for (const auto& b : m.blocks)
    for (LocalIndex n : b.connectivity) nodeBody[n] = b.body;
  // Gram matrices G_b = sum over constrained (node, component) of r r^T, r_k = (mode k at the node)_component
  std::vector<std::array<Real, 36>> gram(m.numBodies);
  for (auto& g : gram) g.fill(0.0);
  Real scale = 0.0;  // the mesh's extent: rotations and translations on one footing
  for (LocalIndex n = 0; n < m.numNodes(); ++n)
    for (int i = 0; i < dim; ++i) scale = std::max(scale, std::abs(m.coord(n, i)));
  if (!(scale > 0.0)) scale = 1.0;
  for (const auto& c : s.conditions)
    for (LocalIndex n : m.nodeSet(c.nodeSet)) {
      Real x[3] = {0.0, 0.0, 0.0}, r[6] = {};
      for (int i = 0; i < dim; ++i) x[i] = m.coord(n, i) / scale;
      const int i = c.component;
      if (axi) {
        r[0] = i == 1 ? 1.0 : 0.0;
      } else if (dim == 2) {  // t_x, t_y, rotation (-y, x)
        r[0] = i == 0, r[1] = i == 1, r[2] = i == 0 ? -x[1] : x[0];
      } else {  // t_x, t_y, t_z, w x X for w = e_x, e_y, e_z
        const Real rot[3][3] = {{0.0, -x[2], x[1]}, {x[2], 0.0, -x[0]}, {-x[1], x[0], 0.0}};
        for (int k = 0; k < 3; ++k) r[k] = i == k, r[3 + k] = rot[k][i];
      }
      auto& g = gram[nodeBody[n]];
      for (int a = 0; a < modes; ++a)
        for (int b = 0; b < modes; ++b) g[a * 6 + b] += r[a] * r[b];
    }
  for (int b = 0; b < m.numBodies; ++b) {
    // rank of G by Gaussian elimination with full pivoting
    auto g = gram[b];
    Real first = 0.0;
    int rank = 0;
    for (int k = 0; k < modes; ++k) {
      int pr = k, pc = k;
      for (int i = k; i < modes; ++i)
        for (int j = k; j < modes; ++j)
          if (std::abs(g[i * 6 + j]) > std::abs(g[pr * 6 + pc])) pr = i, pc = j;
      const Real pivot = g[pr * 6 + pc];
      if (k == 0) first = std::abs(pivot);
      if (!(std::abs(pivot) > 1e-10 * first) || first == 0.0) break;
      for (int j = 0; j < 6; ++j) std::swap(g[k * 6 + j], g[pr * 6 + j]);
      for (int i = 0; i < 6; ++i) std::swap(g[i * 6 + k], g[i * 6 + pc]);
      for (int i = k + 1; i < modes; ++i) {
        const Real f = g[i * 6 + k] / g[k * 6 + k];
        for (int j = k; j < modes; ++j) g[i * 6 + j] -= f * g[k * 6 + j];
      }
      ++rank;
    }
    if (rank < modes) {
      std::string name;
      for (const auto& blk : m.blocks)
        if (blk.body == b) {
          name = blk.name;
          break;
        }
      throw InputError("body \"" + name + "\" (body " + std::to_string(b) + ") can move as a rigid body: its "
                       "boundary conditions hold " + std::to_string(rank) + " of its " + std::to_string(modes) +
                       " rigid-body modes; give it a \"fixed\", \"driven\" or symmetry node set "
                       "(meshes/README.md), or set Geometry/Driven Components = \"all\"");
    }
  }
}

}  // namespace

Model buildModel(const ParameterList& geometry, Formulation formulation, const ContactDistance& contactDistance) {
  Model model;
  const std::string type = geometry.get<std::string>("Type");
  if (type != "gmsh") {  // what meshes a .geo has no meaning for a built-in mesh: not silently ignored
    for (const char* list : {"Mesh Numbers", "Gmsh Options"})
      if (geometry.isSublist(list) && geometry.sublist(list).numParams() > 0)
        throw InputError(std::string("Geometry/") + list + " applies to Geometry/Type = \"gmsh\" only, not \"" +
                         type + "\"");
    if (!geometry.get<std::string>("Mesh Cache").empty())
      throw InputError("Geometry/Mesh Cache applies to Geometry/Type = \"gmsh\" only, not \"" + type + "\"");
  }
  if (type == "gmsh")
    buildFromGmsh(geometry, formulation, contactDistance, model);
  else if (type == "block")
    buildBlock(geometry, formulation, model);
  else
    buildSphereContact(geometry, formulation, contactDistance, model);
  for (const auto& c : model.conditions) model.mesh->nodeSet(c.nodeSet);  // a missing set is named now
  checkBodiesAreHeld(model, formulation);
  return model;
}

}  // namespace cgcm::mesh
