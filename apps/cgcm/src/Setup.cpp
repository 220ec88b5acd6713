#include "cgcm/app/Setup.hpp"

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "cgcm/app/SizeEstimate.hpp"
#include "cgcm/core/Bytes.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/core/ParameterValidators.hpp"
#include "cgcm/material/MaterialParameters.hpp"
#include "cgcm/mesh/Mirror.hpp"
#include "cgcm/solver/LinearSolver.hpp"
#include "cgcm/solver/NewtonSolver.hpp"
#include "cgcm/solver/PathFollower.hpp"

namespace cgcm::app {

using Teuchos::ParameterList;
using Teuchos::RCP;
using Teuchos::rcp;

RCP<const ParameterList> validParameters() {
  using validators::atLeast;
  using validators::choices;
  static RCP<ParameterList> valid;
  if (!valid.is_null()) return valid;
  valid = rcp(new ParameterList("cgcm"));

  auto& problem = valid->sublist("Problem", false, "what is solved");
  problem.set("Formulation", "axisymmetric",
              "kinematics: \"plane strain\" (per unit thickness), \"axisymmetric\" (x = radius, y = axis; forces "
              "are totals over the full ring) or \"3D\"",
              choices({"plane strain", "axisymmetric", "3D"}));
  // each package declares its own sublist
  valid->sublist("Geometry", false, "bodies and their mesh") = *mesh::validParameters();
  valid->sublist("Material", false, "compressible Neo-Hookean solid (doc/theory.md#bulk)") =
      *material::validParameters();
  valid->sublist("Bodies", false,
                 "per-body materials: a sublist named after a body of the mesh (the <name> of its \"body:<name>\" "
                 "group, or a built-in geometry's \"sphere\", \"half-space\", \"second sphere\", \"block\") "
                 "with any of Young's Modulus, Poisson's Ratio, Volumetric Energy, Kinematics; the rest comes from Material. "
                 "Rigid = true makes the body rigid: every node follows the body's fixed or driven condition in "
                 "each component (a translation), and a force measured on it is the interaction's resultant. "
                 "The interaction scales (gammaL, gammaW, the force unit) use Material's Young's modulus") =
      *material::validBodiesParameters();

  valid->sublist("Interaction", false,
                 "Lennard-Jones interaction between the bodies (sphere geometries), doc/theory.md#method-3, "
                 "#normalisation") =
      *interaction::validParameters();

  valid->sublist("Loading", false, "how the path is followed: the load parameter u is the prescribed displacement") =
      *solver::PathPlan::validParameters();
  valid->sublist("LOCA", false, solver::PathPlan::locaHelp()).disableRecursiveValidation();

  auto& solverList = valid->sublist("Solver", false, "nonlinear and linear solvers");
  solverList.setParameters(*assembly::validParameters());
  solverList.sublist("Newton", false, "Newton's method (NOX) at each load step and in every continuation corrector")
      .setParameters(*solver::NewtonSettings::validParameters());
  solverList.sublist("Linear Solver", false, "linear solves inside Newton (Stratimikos)")
      .setParameters(*solver::linearSolverValidParameters())
      .sublist("Stratimikos")
      .disableRecursiveValidation();  // setParameters copies a sublist's entries, not this flag

  auto& output = valid->sublist("Output", false, "what is written where");
  output.set("Directory", "output", "folder for the load curve and the echoed parameters (created if missing)");
  output.set("Print Steps", true, "print one line per load step");
  output.set("Exodus", true,
             "write results.e (Exodus II: displacement, stress, interaction traction and force fields per "
             "load-curve row; ParaView)");
  output.set("Max Memory", 0.0,
             "MB a run may use; a deck whose estimated memory (mesh size, measured per-unknown cost of the "
             "solver) exceeds it is refused before any work. 0: the memory this machine has available",
             atLeast(0.0));
  output.set("Eigenvalues", 0,
             "n > 0: at every accepted state the n eigenvalues nearest 0 of the tangent's symmetric part on the "
             "free dofs (force/length; Anasazi, with one MUMPS LDL^T factorisation per state) and the count of "
             "its negative eigenvalues (exact, from the factorisation), which then decides `stable`; the "
             "critical mode (critical_mode_* in results.e) and, on arc-length paths, branch points (an "
             "eigenvalue crossing 0 without a fold) located to solver tolerance. 0: stability from the parity "
             "of the folds passed (cheaper, blind to branch points)",
             validators::intBetween(0, 50));
  output.set("Checkpoint", true,
             "write checkpoint.bin after every accepted state (displacement control), so that "
             "`cgcm --restart <Directory>` can continue a run that was killed");
  return valid;
}

void resolveMeshFile(Teuchos::ParameterList& deck, const std::string& deckPath) {
  if (!deck.isSublist("Geometry")) return;
  // absolute, so that parameters.xml (and a --restart from it) works from any folder
  for (const char* name : {"File", "Mesh Cache"}) {
    if (!deck.sublist("Geometry").isType<std::string>(name)) continue;
    const std::filesystem::path file = deck.sublist("Geometry").get<std::string>(name);
    if (file.empty() || file.is_absolute()) continue;
    deck.sublist("Geometry").set(
        name, std::filesystem::absolute(std::filesystem::path(deckPath).parent_path() / file).lexically_normal().string());
  }
}

namespace {

// The scales the interaction is set in: the deck's R0, the Material's Y and
// nu, the contact's reduced radius.
interaction::ReferenceScales referenceScales(const ParameterList& deck, const material::NeoHookean& material) {
  const auto& geometry = deck.sublist("Geometry");
  return {geometry.get<double>("Sphere Radius"), material.youngsModulus(), material.poissonRatio(),
          mesh::reducedRadius(geometry)};
}

// What the deck alone gives (every rank builds it): formulation, material, partition.
solver::ProblemSetup setupFromDeck(const ParameterList& deck) {
  solver::ProblemSetup s;
  s.formulation = parseFormulation(deck.sublist("Problem").get<std::string>("Formulation"));
  s.material = material::fromParameters(deck.sublist("Material"));
  s.partition = assembly::parseCellPartition(deck.sublist("Solver").get<std::string>("Partition"));
  if (s.material.kinematics == material::Kinematics::SmallStrain)
    s.report.push_back("Material/Kinematics = small strain: linear elasticity on the reference configuration");
  return s;
}

// The interaction between the bodies: read when the model has interacting bodies (its r_S0 places u = 0).
const interaction::InteractionSetup& readInteraction(const ParameterList& deck, solver::ProblemSetup& s) {
  if (!s.interaction)
    s.interaction = interaction::fromParameters(deck.sublist("Interaction"), referenceScales(deck, s.material),
                                                s.formulation);
  return *s.interaction;
}

// Joins a model to the deck's set-up: the force scale, the interaction when the bodies interact (read
// from the deck if not yet) with its report lines, the model's lines.
void attachModel(solver::ProblemSetup& s, mesh::Model model, const ParameterList& deck) {
  s.forceScale = model.forceScale(s.material.youngsModulus());
  if (model.interacting) readInteraction(deck, s);  // ranks other than 0 read it here
  if (s.interaction) {
    const auto lines = interaction::describe(*s.interaction, referenceScales(deck, s.material));
    s.report.insert(s.report.end(), lines.begin(), lines.end());
    std::ostringstream o;
    o.precision(6);
    o << "force unit F_ref = Y R0^2 = " << s.forceScale << " (per unit thickness in plane strain: Y R0)";
    s.report.push_back(o.str());
  }
  s.report.insert(s.report.end(), model.report.begin(), model.report.end());
  s.model = std::move(model);
}

}  // namespace

solver::ProblemSetup buildProblem(const ParameterList& deck) {
  solver::ProblemSetup s = setupFromDeck(deck);
  const auto& geometry = deck.sublist("Geometry");
  const std::string type = geometry.get<std::string>("Type");
  // absurd sizes are refused before the mesh is allocated (mesh files: once read)
  const MemoryLimit memory = memoryLimit(deck.sublist("Output"));
  if (const auto size = estimateBuiltInMesh(deck, s.formulation))
    checkSize(*size, memory, type == "block" ? "Geometry/Block/Cells X, Y, Z" : "Geometry/Mesh Refinement");
  // asked for as soon as the geometry knows its bodies interact, before a built-in mesh is made
  const auto contactDistance = [&] { return readInteraction(deck, s).contactDistance(); };
  attachModel(s, mesh::buildModel(geometry, s.formulation, contactDistance), deck);
  const mesh::Mesh& m = *s.model.mesh;
  if (type == "gmsh")
    checkSize(estimateSize(m.numNodes(), m.numCells(), s.formulation), memory,
              "Geometry/File \"" + geometry.get<std::string>("File") + "\"");
  if (deck.isSublist("Bodies")) {  // always, in a validated deck
    std::vector<std::string> names = mesh::bodyNames(m), originals;
    for (const auto& name : names) originals.push_back(mesh::unmirroredName(name));
    s.bodyMaterials =
        material::bodyMaterials(deck.sublist("Material"), deck.sublist("Bodies"), names, originals, s.report);
    const auto rigid = material::rigidBodies(deck.sublist("Bodies"), names, originals, s.report);
    for (std::size_t b = 0; b < rigid.size(); ++b) {
      if (rigid[b])
        mesh::makeRigid(s.model, int(b), names[b]);
      else if (s.bodyMaterials[b].youngsModulus() > s.material.youngsModulus() &&
               mesh::measureOnWholeBody(s.model, int(b), names[b]))
        s.report.push_back("body \"" + names[b] + "\": stiffer than Material, its force is measured over all its "
                           "nodes (the interaction's resultant on it), not at its supports");
    }
  }
  if (s.interaction) s.interaction->checkMesh(m, s.formulation, {memory.megabytes, memory.describe()});
  s.numNodes = std::size_t(m.numNodes());
  s.numCells = std::size_t(m.numCells());
  return s;
}

namespace {

// What rank 0's model and mesh add to the deck's set-up, without the mesh: the
// other ranks make the rest from the deck themselves (setupFromDeck).
std::vector<char> toBytes(const solver::ProblemSetup& s) {
  core::ByteWriter out;
  mesh::put(out, s.model);
  out.put(s.bodyMaterials);
  out.put(std::uint64_t(s.report.size()));
  for (const auto& line : s.report) out.put(line);
  out.put(s.numNodes);
  out.put(s.numCells);
  return out.take();
}

solver::ProblemSetup setupFromBytes(const Teuchos::ParameterList& deck, const std::vector<char>& bytes) {
  core::ByteReader in(bytes);
  solver::ProblemSetup s = setupFromDeck(deck);
  attachModel(s, mesh::getModel(in), deck);
  s.bodyMaterials = in.getVector<material::NeoHookean>();
  s.report.resize(in.getCount(sizeof(std::uint64_t)));  // rank 0's, the body materials' lines included
  for (auto& line : s.report) line = in.getString();
  s.numNodes = in.get<std::size_t>();
  s.numCells = in.get<std::size_t>();
  if (!in.atEnd()) throw std::logic_error("setupFromBytes: bytes left over");
  return s;
}

}  // namespace

solver::ProblemSetup buildProblem(const Teuchos::Comm<int>& comm, const Teuchos::ParameterList& deck) {
  if (comm.getSize() == 1) return buildProblem(deck);
  solver::ProblemSetup setup;
  std::vector<char> bytes;
  solver::runOnRoot(comm, [&] {
    setup = buildProblem(deck);
    bytes = toBytes(setup);
  });
  solver::broadcastBytes(comm, bytes);
  solver::decodeOnEveryRank(comm, [&] {
    if (comm.getRank() != 0) setup = setupFromBytes(deck, bytes);
  });
  return setup;
}

}  // namespace cgcm::app
