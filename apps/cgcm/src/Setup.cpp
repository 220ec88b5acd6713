#include "cgcm/app/Setup.hpp"

#include "Distribution.hpp"

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <sstream>

#include "cgcm/app/SizeEstimate.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/interaction/Normalisation.hpp"
#include "cgcm/io/Deck.hpp"
#include "cgcm/mesh/Benchmark.hpp"
#include "cgcm/mesh/Generators.hpp"
#include "cgcm/mesh/GmshReader.hpp"
#include "cgcm/mesh/Mirror.hpp"
#include "cgcm/mesh/Overlap.hpp"
#include "cgcm/solver/LinearSolver.hpp"
#include "cgcm/solver/LoadStepper.hpp"
#include "cgcm/solver/NewtonSolver.hpp"
#include "cgcm/solver/ParameterValidators.hpp"

namespace cgcm::app {

using Teuchos::ParameterList;
using Teuchos::RCP;
using Teuchos::rcp;

namespace {

using validators::atLeast;
using validators::between;
using validators::choices;
using validators::intAtLeast;
using validators::intBetween;

}  // namespace

assembly::Formulation parseFormulation(const std::string& name) {
  if (name == "plane strain") return assembly::Formulation::PlaneStrain;
  if (name == "axisymmetric") return assembly::Formulation::Axisymmetric;
  if (name == "3D") return assembly::Formulation::ThreeD;
  throw InputError("Problem/Formulation = \"" + name + "\"; allowed: \"plane strain\", \"axisymmetric\", \"3D\"");
}

RCP<const ParameterList> validParameters() {
  static RCP<ParameterList> valid;
  if (!valid.is_null()) return valid;
  valid = rcp(new ParameterList("cgcm"));

  auto& problem = valid->sublist("Problem", false, "what is solved");
  problem.set("Formulation", "axisymmetric",
              "kinematics: \"plane strain\" (per unit thickness), \"axisymmetric\" (x = radius, y = axis; forces "
              "are totals over the full ring) or \"3D\"",
              choices({"plane strain", "axisymmetric", "3D"}));

  auto& geometry = valid->sublist("Geometry", false, "bodies and their mesh");
  geometry.set("Type", "sphere on half-space",
               "\"sphere on half-space\" (the paper's benchmark; cylinder on half-space in plane strain), "
               "\"sphere on sphere\", \"block\" (a rectangle or box stretched along its last axis), or \"gmsh\" "
               "(the mesh of Geometry/File; meshes/README.md)",
               choices({"sphere on half-space", "sphere on sphere", "block", "gmsh"}));
  geometry.set("File", "",
               "Type = gmsh: a gmsh .geo (meshed when read) or .msh file; a relative path is taken from the "
               "deck's folder. Node sets (physical groups) used: \"driven\" (its last displacement component is "
               "-u, the rest of its body starts translated with it), \"fixed\" (all components 0), \"axis\" and "
               "\"symmetry x|y|z\" (that component 0), \"apex\" and \"lower apex\" (one node each: the gap and "
               "contact radius columns, and u = 0 where they are r_S0 apart)");
  geometry.set("Drive Direction", "down",
               "Type = gmsh: the node set \"driven\" moves by u \"down\" (-y in 2D, -z in 3D) or \"up\" (+y, +z) "
               "along the last axis; the approach closes the gap either way",
               choices({"down", "up"}));
  geometry.set("Drive Vector", Teuchos::Array<double>{},
               "Type = gmsh: a direction d (one entry per dimension, normalised) along which \"driven\" moves by "
               "u d, every component prescribed, e.g. {1, 0, -1} for an oblique approach; P is the resultant along d. "
               "Replaces Drive Direction and Driven Components; u is the plain displacement (no apex offset). "
               "Empty: along the last axis (Drive Direction)");
  geometry.set("Driven Components", "vertical",
               "Type = gmsh: which displacement components of \"driven\" are prescribed: \"vertical\" (the last "
               "one; the others are free, as on the benchmark's equator) or \"all\" (the others are 0: a clamped "
               "support that moves)",
               choices({"vertical", "all"}));
  geometry.set("Mirror Planes", Teuchos::Array<std::string>{},
               "Type = gmsh: planes through the origin, among \"x\", \"y\", \"z\" (x = 0, ...), in which the mesh "
               "is mirrored before use, e.g. {x}: the mesh file holds the half on the positive side and the model is "
               "the whole, node for node symmetric. Bodies cut by the plane are joined with their image; the others "
               "get an image body; \"symmetry x\" of a mirrored plane is dropped");
  geometry.sublist("Mesh Numbers", false,
                   "Type = gmsh: values for DefineConstant[] numbers of the .geo, e.g. level = 1 "
                   "(gmsh -setnumber)")
      .disableRecursiveValidation();
  geometry.set("Sphere Radius", 1.0,
               "radius R0 of the upper sphere: the reference length (with a gmsh mesh: R0 of gammaL = R0/r0 and of "
               "the force unit)",
               atLeast(1e-300));
  geometry.set("Second Sphere Radius", 1.0, "radius of the lower sphere (Type = sphere on sphere)",
               atLeast(1e-300));
  geometry.set("Half-Space Size", 8.0, "width and depth of the half-space block, in sphere radii (>= 2)",
               atLeast(2.0));
  geometry.set("Mesh Refinement", 0, "level 0 (about 1400 nodes) .. 6; each level halves every cell",
               intBetween(0, 6));
  geometry.set("Contact Zone Size", 0.5,
               "radial extent of the finest cells around the axis, in sphere radii (0.02 .. 0.85): 20 cells on "
               "the half-space and 16 on the sphere at level 0. Smaller zones resolve smaller contacts (large "
               "gammaL) with the same number of cells",
               between(0.02, 0.85));
  auto& block = geometry.sublist("Block", false,
                                 "Type = block: corner at the origin; symmetry rollers on the faces x = 0, y = 0 "
                                 "(and z = 0 in 3D); the face at the far end of the last axis moves by the load u");
  block.set("Length X", 1.0, "edge length along x (the radius in axisymmetry)", atLeast(1e-300));
  block.set("Length Y", 1.0, "edge length along y", atLeast(1e-300));
  block.set("Length Z", 1.0, "edge length along z (3D)", atLeast(1e-300));
  block.set("Cells X", 4, "cells along x", intAtLeast(1));
  block.set("Cells Y", 4, "cells along y", intAtLeast(1));
  block.set("Cells Z", 4, "cells along z (3D)", intAtLeast(1));
  block.set("Element", "hex8", "3D cell type: \"hex8\" or \"tet4\" (6 per hexahedron)", choices({"hex8", "tet4"}));
  block.set("Loaded Face", "roller",
            "\"roller\": the loaded face slides freely (homogeneous uniaxial stress); \"clamped\": it cannot slide",
            choices({"roller", "clamped"}));
  block.set("Distortion", 0.0, "random shift of interior nodes, as a fraction of the smallest edge (0 .. 0.4)",
            between(0.0, 0.4));
  block.set("Distortion Seed", 1, "seed of the random node shift", intAtLeast(0));

  auto& material = valid->sublist("Material", false, "compressible Neo-Hookean solid (THEORY section 3)");
  material.set("Young's Modulus", 1.0, "Y > 0", atLeast(1e-300));
  material.set("Poisson's Ratio", 0.2, "nu, -1 < nu < 0.5", between(-0.999999, 0.499999));
  material.set("Volumetric Energy", "(Lambda/2)(ln J)^2",
               "U(J): \"(Lambda/2)(ln J)^2\" (default) or \"(Lambda/4)(J^2-1-2 ln J)\"",
               choices({"(Lambda/2)(ln J)^2", "(Lambda/4)(J^2-1-2 ln J)"}));
  material.set("Kinematics", "finite strain",
               "\"finite strain\" (default, Neo-Hookean) or \"small strain\": the model linearised about the "
               "reference configuration (linear elasticity with the same Y, nu), to measure what finite strain "
               "changes",
               choices({"finite strain", "small strain"}));

  valid->sublist("Bodies", false,
                 "per-body materials: a sublist named after a body of the mesh (the <name> of its \"body:<name>\" "
                 "group, or a built-in geometry's \"sphere\", \"half-space\", \"second sphere\", \"block\") "
                 "with any of Young's Modulus, Poisson's Ratio, Volumetric Energy, Kinematics; the rest comes from Material. "
                 "The interaction scales (gammaL, gammaW, the force unit) use Material's Young's modulus")
      .disableRecursiveValidation();

  auto& inter = valid->sublist("Interaction", false,
                                "Lennard-Jones interaction between the bodies (sphere geometries), THEORY sections 2, 4");
  {
    std::vector<std::string> names;
    std::string help;
    for (const auto& e : interaction::potentialRegistry()) {
      names.push_back(e.deckName);
      help += std::string(help.empty() ? "" : "; ") + "\"" + e.deckName + "\": " + e.description;
    }
    inter.set("Potential", names.front(), help, choices(names));
  }
  inter.set("Method", "half-space point",
            "\"half-space point\" (Method 3: each surface point against the other body as a half-space) or "
            "\"volume pair\" (Method 1: quadrature over pairs of cells of two bodies, the reference; cost grows "
            "with the cells within the cutoff, and cells near the surfaces should be about r0 or smaller)",
            choices({"half-space point", "volume pair"}));
  inter.set("Volume Quadrature Order", 2,
            "volume pair: Gauss points per direction of a cell for pairs of cells far apart (1 .. 6); closer pairs "
            "get more, up to the Max Volume Quadrature Order",
            intBetween(1, 6));
  inter.set("Max Volume Quadrature Order", 6,
            "volume pair: most Gauss points per direction for pairs of cells close to each other (1 .. 12 in 2D, "
            "1 .. 6 in 3D)",
            intBetween(1, 12));
  inter.set("Pair List Skin", 1.0,
            "volume pair: the pair list covers cutoff + skin (units of r0) and is rebuilt when a node has moved "
            "by half the skin",
            atLeast(0.01));
  inter.set("gammaL", 50.0, "R0 / r0: geometric scale (22)", atLeast(1e-300));
  inter.set("gammaW", 200.0, "Y / (beta0^2 r0^3 epsilon): energy-density ratio (28)", atLeast(1e-300));
  inter.set("gammaL bar", 0.0, "the paper's equivalent parameter; > 0 replaces gammaL through the Barred Convention",
            atLeast(0.0));
  inter.set("gammaW bar", 0.0, "the paper's equivalent parameter; > 0 replaces gammaW through the Barred Convention",
            atLeast(0.0));
  inter.set("Barred Convention", "literal",
            "how the paper's barred values convert: \"literal\" (gammaL = gammaL bar / (3/4)^(1/6), gammaW = "
            "gammaW bar / sqrt(3), the reading the paper's stability statements and Fig. 11 state support; "
            "doc/theory.md) or \"identity\" (gamma = gamma bar)",
            choices({"identity", "literal"}));
  inter.set("r0", 0.0, "physical input instead of the gammas: equilibrium distance of the pair potential (> 0 to use)",
            atLeast(0.0));
  inter.set("epsilon", 0.0, "physical input: energy well of the pair potential (with r0)", atLeast(0.0));
  inter.set("beta0", 1.0, "reference particle density of both bodies", atLeast(1e-300));
  inter.set("Quadrature Points", 4,
            "Gauss points per surface segment; in 3D per direction of a facet (n x n on a quadrilateral; on a "
            "triangle 1, 6, 7 points for n = 1, 2, 3 and 6 n (n + 1) beyond), and 2 unless given",
            intAtLeast(1));
  inter.set("Cutoff", 10.0, "interaction cutoff in units of r0: farther points are skipped", atLeast(1.0));
  inter.set("Cutoff Taper", 0.2,
            "fraction of the cutoff over which the traction is blended smoothly (C1) to zero, 0 .. 0.9; "
            "0 is a sharp cutoff, whose residual jumps when points cross it",
            between(0.0, 0.9));
  inter.set("Projection Smoothing", interaction::SurfaceInteractionOptions::kDefaultProjectionSmoothing,
            "width delta of the blend of a point's projections onto neighbouring segments (3D: triangles), in "
            "units of r0: near a concave corner (3D: edge) of the other surface the closest facet switches and "
            "the force direction would jump; the blend keeps the residual smooth. 0 uses the closest facet alone "
            "(the paper's Method 3; "
            "Newton can then find no equilibrium next to such a switch)",
            atLeast(0.0));
  inter.set("Search Radius Factor", 2.0,
            "matrix-graph search radius / cutoff (> 1); volume pair: the radius is cutoff + factor x Pair List Skin",
            atLeast(1.01));

  auto& loading = valid->sublist("Loading", false,
                                 "how the path is followed: the load parameter u is the prescribed displacement");
  loading.set("Control", "displacement",
              "\"displacement\": steps in u along the Approach Path; at a fold (jump-to-contact, jump-off-contact) "
              "the state jumps to the far stable branch at the same u (found by continuation), as under a rigid "
              "loading device. \"arc-length\": LOCA pseudo-arclength continuation through the folds, the unstable "
              "branch included (rows with stable = 0)",
              choices({"displacement", "arc-length"}));
  loading.setParameters(*solver::LoadPathSettings::validParameters());
  loading.set("Continuation Parameter", "u",
              "\"u\": the path is the Approach Path. \"gammaW\" or \"gammaL\": after the Approach Path (at the "
              "deck's gammas), arc-length continuation in that parameter along the Parameter Path at the last u",
              choices({"u", "gammaW", "gammaL"}));
  loading.set("Parameter Path", Teuchos::Array<double>{},
              "waypoints of the Continuation Parameter when it is not u, e.g. {100, 20}: from the deck's value "
              "through these; empty for u");
  loading.set("Parameter Bounds", Teuchos::Array<double>{},
              "{lower, upper}: the continuation stops as failed if its parameter leaves this range (arc-length "
              "control and jumps; default: the path's range widened by twice its span on each side)");

  valid->sublist("LOCA", false,
                 "passed to LOCA's stepper (sublists Stepper, Predictor, Step Size, Bifurcation, ... with LOCA's "
                 "own names), over cgcm's defaults: Stepper/Continuation Method = Arc Length, Max Steps = 2000; "
                 "Predictor/Method = Tangent; Step Size/Method = Adaptive, Initial, Min and Max Step Size from "
                 "Loading/Initial, Min and 2 x Max Increment. cgcm sets Stepper/Continuation Parameter, Initial "
                 "Value, Min and Max Value and Max Nonlinear Iterations itself; names LOCA does not read are "
                 "rejected before the run")
      .disableRecursiveValidation();

  auto& solverList = valid->sublist("Solver", false, "nonlinear and linear solvers");
  solverList.set("Partition", "geometric",
                 "how cells are split over MPI ranks: \"geometric\" (Zoltan2 multi-jagged cuts of the cell "
                 "centroids: compact parts, short interfaces) or \"contiguous\" (ranges of the mesh's cell "
                 "numbering); no effect on one rank",
                 choices({"geometric", "contiguous"}));
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
             "write results.e (Exodus II: displacement, stress and interaction traction fields per load-curve row; "
             "ParaView)");
  output.set("Max Memory", 0.0,
             "MB a run may use; a deck whose estimated memory (mesh size, measured per-unknown cost of the "
             "solver) exceeds it is refused before any work. 0: the memory this machine has available",
             atLeast(0.0));
  output.set("Checkpoint", true,
             "write checkpoint.bin after every accepted state (displacement control), so that "
             "`cgcm --restart <Directory>` can continue a run that was killed");
  return valid;
}

namespace {

// Interaction parameters from the deck, with the scales they imply.
InteractionSetup buildInteraction(const ParameterList& in, Real R0, Real Y, Real nu, Real reducedRadius,
                                  assembly::Formulation formulation, std::vector<std::string>& report,
                                  Real& forceScale) {
  const bool barred = in.get<double>("gammaL bar") > 0.0 || in.get<double>("gammaW bar") > 0.0;
  const bool physical = in.get<double>("r0") > 0.0 || in.get<double>("epsilon") > 0.0;
  const bool plainSet = !in.getEntry("gammaL").isDefault() || !in.getEntry("gammaW").isDefault();
  if (int(barred) + int(physical) + int(plainSet) > 1)
    throw InputError("Interaction: give one of (gammaL, gammaW), (gammaL bar, gammaW bar) or (r0, epsilon)");
  const Real beta0 = in.get<double>("beta0");
  Real gammaL = in.get<double>("gammaL"), gammaW = in.get<double>("gammaW");
  if (barred) {
    const Real gLb = in.get<double>("gammaL bar"), gWb = in.get<double>("gammaW bar");
    if (!(gLb > 0.0 && gWb > 0.0)) throw InputError("Interaction: set both gammaL bar and gammaW bar (> 0)");
    const bool literal = in.get<std::string>("Barred Convention") == "literal";
    gammaL = literal ? gLb / std::pow(0.75, 1.0 / 6.0) : gLb;
    gammaW = literal ? gWb / std::sqrt(3.0) : gWb;
  } else if (physical) {
    if (!(in.get<double>("r0") > 0.0 && in.get<double>("epsilon") > 0.0))
      throw InputError("Interaction: set both r0 and epsilon (> 0)");
    interaction::InteractionParameters p{in.get<double>("epsilon"), in.get<double>("r0"), beta0, R0, Y};
    const auto sc = interaction::toScaling(p);
    gammaL = sc.gammaL;
    gammaW = sc.gammaW;
  }
  const auto phys = interaction::fromScaling(gammaL, gammaW, R0, Y, beta0);
  InteractionSetup s;
  s.potential = interaction::makePotential(in.get<std::string>("Potential"), phys.epsilon, phys.r0);
  s.densities = {beta0, beta0};
  s.options.formulation = formulation == assembly::Formulation::Axisymmetric ? interaction::Formulation::Axisymmetric
                          : formulation == assembly::Formulation::ThreeD     ? interaction::Formulation::ThreeD
                                                                              : interaction::Formulation::PlaneStrain;
  // 3D: n x n points per quad, 6 or 7 per triangle at n = 2, 3, but 6 n (n + 1) beyond: 2 unless set
  const bool threeD = formulation == assembly::Formulation::ThreeD;
  s.options.quadraturePoints = threeD && in.getEntry("Quadrature Points").isDefault() ? 2 : in.get<int>("Quadrature Points");
  s.options.cutoff = in.get<double>("Cutoff") * phys.r0;
  s.options.cutoffTaper = in.get<double>("Cutoff Taper");
  s.options.projectionSmoothing = in.get<double>("Projection Smoothing") * phys.r0;
  if ((1.0 - s.options.cutoffTaper) * in.get<double>("Cutoff") < 2.0)
    throw InputError("Interaction/Cutoff Taper = " + std::to_string(s.options.cutoffTaper) +
                     " with Interaction/Cutoff = " + std::to_string(in.get<double>("Cutoff")) +
                     " starts the taper below 2 r0, in the range of the repulsion; need (1 - taper) * cutoff >= 2");
  s.searchRadiusFactor = in.get<double>("Search Radius Factor");
  s.volumeMethod = in.get<std::string>("Method") == "volume pair";
  s.volumeOptions.formulation = s.options.formulation;
  s.volumeOptions.quadratureOrder = in.get<int>("Volume Quadrature Order");
  s.volumeOptions.maxQuadratureOrder = in.get<int>("Max Volume Quadrature Order");
  s.volumeOptions.cutoff = s.options.cutoff;
  s.volumeOptions.skin = in.get<double>("Pair List Skin") * phys.r0;
  if (s.volumeMethod && s.volumeOptions.maxQuadratureOrder < s.volumeOptions.quadratureOrder)
    throw InputError("Interaction/Max Volume Quadrature Order = " + std::to_string(s.volumeOptions.maxQuadratureOrder) +
                     " is below Interaction/Volume Quadrature Order = " +
                     std::to_string(s.volumeOptions.quadratureOrder));
  if (s.volumeMethod && threeD && s.volumeOptions.maxQuadratureOrder > interaction::kMaxVolumeOrder3D)
    throw InputError("Interaction/Max Volume Quadrature Order = " + std::to_string(s.volumeOptions.maxQuadratureOrder) +
                     ": at most " + std::to_string(interaction::kMaxVolumeOrder3D) + " in 3D");

  // Derived scales (THEORY sections 2, 4, 5), for the run's report.
  const Real rS0 = phys.r0 / std::pow(15.0, 1.0 / 6.0);
  const Real taperStart = (1.0 - s.options.cutoffTaper) * s.options.cutoff;
  const Real w = interaction::LennardJones::workFactor() * beta0 * beta0 * phys.epsilon * std::pow(phys.r0, 4);
  const Real sigmaMax = interaction::LennardJones::peakTractionFactor() * beta0 * beta0 * phys.epsilon *
                        std::pow(phys.r0, 3);
  const Real Estar = Y / (2.0 * (1.0 - nu * nu));
  const Real tabor = std::cbrt(reducedRadius * w * w / (Estar * Estar * rS0 * rS0 * rS0));
  const Real lambda = sigmaMax * std::cbrt(9.0 * reducedRadius / (2.0 * kPi * w * Estar * Estar));
  // The force unit of the paper, E0/R0 = Y R0^2 (per unit thickness: Y R0), is
  // the scale of the convergence test: the round-off floor of the residual
  // comes from the bulk (about 3e-12 Y R0^2 on the level-0 benchmark mesh).
  forceScale = formulation == assembly::Formulation::PlaneStrain ? Y * R0 : Y * R0 * R0;
  s.gammaL = gammaL;
  s.gammaW = gammaW;
  std::ostringstream o;
  o.precision(6);
  o << "gammaL = " << gammaL << ", gammaW = " << gammaW << " (barred, literal reading: "
    << gammaL * std::pow(0.75, 1.0 / 6.0) << ", " << gammaW * std::sqrt(3.0) << "); gammaK = gammaW/gammaL = "
    << gammaW / gammaL;
  report.push_back(o.str());
  o.str("");
  o << "R0 = " << R0 << ", E0 = Y R0^3 = " << Y * R0 * R0 * R0 << ", r0 = " << phys.r0 << ", epsilon = "
    << phys.epsilon << ", beta0 = " << beta0;
  report.push_back(o.str());
  o.str("");
  // the potential's own surface properties (a repulsive one has no r_S0 and w = 0)
  const auto ownRS0 = s.potential->surfaceEquilibriumDistance();
  o << "potential " << s.potential->name() << ": r_S0 = ";
  if (ownRS0)
    o << *ownRS0;
  else
    o << "none";
  o << ", w = " << s.potential->workOfAdhesion(beta0, beta0)
    << ", sigma_max = " << s.potential->peakTraction(beta0, beta0) << ", cutoff = " << s.options.cutoff
    << " (taper from " << taperStart << "), |T(taper start)| = "
    << std::abs(s.potential->traction(taperStart, beta0, beta0)) / sigmaMax
    << " sigma_max(Lennard-Jones), work removed by the cutoff = "
    << 100.0 * interaction::neglectedWorkFraction(*s.potential, taperStart, s.options.cutoff) << " % of w";
  report.push_back(o.str());
  o.str("");
  o << "Lennard-Jones scales (of its r0 and epsilon, whatever the potential): Tabor mu = " << tabor << ", Maugis-Dugdale lambda (theory) = " << lambda
    << ", 2 pi w R = " << 2 * kPi * w * reducedRadius << ", 1.5 pi w R = " << 1.5 * kPi * w * reducedRadius
    << " (R = " << reducedRadius << ")";
  report.push_back(o.str());
  o.str("");
  o << "force unit F_ref = Y R0^2 = " << forceScale << " (per unit thickness in plane strain: Y R0)";
  report.push_back(o.str());
  return s;
}

// Sphere (radius R0, apex at the equilibrium gap above y = 0) over a half-space
// block or a second sphere; u moves the sphere's equator plane down.
void buildSphereContact(const ParameterList& deck, ProblemSetup& s) {
  const auto& g = deck.sublist("Geometry");
  const bool onSphere = g.get<std::string>("Type") == "sphere on sphere";
  if (s.formulation == assembly::Formulation::ThreeD)
    throw InputError("Geometry/Type = \"" + g.get<std::string>("Type") +
                     "\" is built in plane strain or axisymmetry; Problem/Formulation = \"3D\" needs a mesh file");
  const Real R0 = g.get<double>("Sphere Radius"), R2 = g.get<double>("Second Sphere Radius");
  const int level = g.get<int>("Mesh Refinement");
  const auto& in = deck.sublist("Interaction");
  const Real reducedRadius = onSphere ? R0 * R2 / (R0 + R2) : R0;
  s.interaction = buildInteraction(in, R0, s.material.youngsModulus(), s.material.poissonRatio(), reducedRadius,
                                   s.formulation, s.report, s.forceScale);
  const Real r0 = s.interaction->potential->r0();
  const Real rS0 = r0 / std::pow(15.0, 1.0 / 6.0);  // u = 0: undeformed surfaces r_S0 apart

  mesh::QuarterDiskSpec sphere;
  sphere.radius = R0;
  sphere.centerY = R0 + rS0;
  sphere.refinement = level;
  const Real zone = g.get<double>("Contact Zone Size");
  sphere.fineAngle = 0.8 * zone;  // the fine cells of both bodies are then equally long
  sphere.name = "sphere";
  auto m = std::make_shared<mesh::Mesh>(mesh::quarterDisk(sphere));
  auto& upper = m->nodeSets["upper body"];
  for (LocalIndex n = 0; n < m->numNodes(); ++n) upper.push_back(n);
  if (onSphere) {
    mesh::QuarterDiskSpec lower;
    lower.radius = R2;
    lower.centerY = -R2;
    lower.lowerHalf = false;
    lower.refinement = level;
    lower.fineAngle = std::min(0.8 * zone * R0 / R2, 0.69);
    lower.name = "second sphere";
    mesh::append(*m, mesh::quarterDisk(lower), "lower ");
  } else {
    mesh::HalfSpaceSpec h;
    h.width = h.depth = g.get<double>("Half-Space Size") * R0;
    h.fineLength = zone * R0;
    h.refinement = level;
    mesh::Mesh block = mesh::halfSpaceBlock(h);
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
  s.conditions = {{"axis", 0, 0.0, 0.0},       {"equator", 1, 0.0, -1.0}, {"lower axis", 0, 0.0, 0.0},
                  {"lower equator", 0, 0.0, 0.0}, {"lower equator", 1, 0.0, 0.0}};
  s.load = {"equator", 1, -1.0};  // P > 0: compressive
  s.initialMotion = {{"upper body", 1, 0.0, -1.0}};  // the sphere starts translated rigidly
  s.balance = ForceResponse{"lower equator", 1, 1.0};
  s.contact = ContactGeometry{"apex", "lower apex", 0, 1, rS0};
}

// Number overrides of a .geo: every entry of Geometry/Mesh Numbers, a number.
std::map<std::string, double> meshNumbers(const ParameterList& numbers) {
  std::map<std::string, double> out;
  for (auto it = numbers.begin(); it != numbers.end(); ++it) {
    const auto& entry = numbers.entry(it);
    const std::string name = numbers.name(it);
    if (entry.isType<double>()) out[name] = entry.getValue<double>(nullptr);
    else if (entry.isType<int>()) out[name] = entry.getValue<int>(nullptr);
    else throw InputError("Geometry/Mesh Numbers/" + name + ": a number is expected");
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
// mapped to boundary conditions; Lennard-Jones between all bodies when there
// are several.
void buildFromGmsh(const ParameterList& deck, ProblemSetup& s) {
  const auto& g = deck.sublist("Geometry");
  const std::string file = g.get<std::string>("File");
  if (file.empty()) throw InputError("Geometry/Type = \"gmsh\" needs Geometry/File (a gmsh .geo or .msh file)");
  mesh::GmshOptions options;
  options.dim = assembly::formulationDim(s.formulation);
  if (g.isSublist("Mesh Numbers")) options.numbers = meshNumbers(g.sublist("Mesh Numbers"));
  auto m = std::make_shared<mesh::Mesh>(mesh::readGmsh(file, options));
  const auto fail = [&](const std::string& what) { throw InputError("mesh file \"" + file + "\": " + what); };
  std::string mirrored;
  for (const std::string& plane : g.get<Teuchos::Array<std::string>>("Mirror Planes")) {
    const int axis = plane == "x" ? 0 : plane == "y" ? 1 : plane == "z" ? 2 : -1;
    if (axis == 0 && s.formulation == assembly::Formulation::Axisymmetric)
      throw InputError("Geometry/Mirror Planes: \"x\" with Problem/Formulation = \"axisymmetric\": x is the radius, "
                       "the mesh cannot be mirrored across the axis; allowed: \"y\"");
    if (axis < 0 || axis >= m->dim || mirrored.find(plane) != std::string::npos)
      throw InputError("Geometry/Mirror Planes: \"" + plane + "\" " +
                       (axis >= 0 && axis < m->dim ? "is given twice" : "is not a plane of this mesh") +
                       "; allowed: distinct names among " + (m->dim == 3 ? "\"x\", \"y\", \"z\"" : "\"x\", \"y\""));
    mesh::mirror(*m, axis);
    mirrored += plane;
  }
  if (s.formulation == assembly::Formulation::Axisymmetric)
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

  const Real R0 = g.get<double>("Sphere Radius"), Y = s.material.youngsModulus();
  Real offset = 0.0;
  // The drive: "driven" moves by u d. Along the last axis (Drive Direction) only that component is
  // prescribed unless Driven Components = all; along a Drive Vector every component is.
  const bool alongVector = !g.get<Teuchos::Array<double>>("Drive Vector").empty();
  const std::vector<Real> d = driveDirection(g, *m);
  const Real drive = d[vertical];
  const bool allComponents = alongVector || g.get<std::string>("Driven Components") == "all";
  if (m->numBodies > 1) {
    s.interaction = buildInteraction(deck.sublist("Interaction"), R0, Y, s.material.poissonRatio(), R0,
                                     s.formulation, s.report, s.forceScale);
    s.interaction->densities.assign(m->numBodies, s.interaction->densities.front());
    const Real rS0 = s.interaction->potential->r0() / std::pow(15.0, 1.0 / 6.0);
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
  } else {
    s.forceScale = s.formulation == assembly::Formulation::PlaneStrain ? Y * R0 : Y * R0 * R0;
  }
  for (int i = 0; i < dim; ++i) {
    const Real shift = i == vertical ? offset : 0.0;
    if (i == vertical || allComponents) s.conditions.push_back({"driven", i, shift, d[i]});
    if (d[i] != 0.0) s.initialMotion.push_back({"driven body", i, shift, d[i]});
  }
  s.load = {"driven", vertical, drive};  // P > 0: compressive
  s.load.direction = d;
  if (dim == 3) {
    // a quarter or half model: P is the force on the whole body
    std::string planes;
    for (const char* set : {"symmetry x", "symmetry y"})
      if (m->nodeSets.count(set)) s.load.scale *= 2.0, planes += std::string(planes.empty() ? "" : ", ") + set;
    if (s.load.scale != 1.0)
      s.report.push_back("P = " + std::to_string(int(s.load.scale)) +
                         " x the resultant on \"driven\": the force on the whole body of the mesh's symmetry planes (" +
                         planes + ")");
  }
  if (s.balance) s.balance->scale = s.load.scale;
  if (m->nodeSets.count("fixed"))
    for (int i = 0; i < dim; ++i) s.conditions.push_back({"fixed", i, 0.0, 0.0});
  if (m->nodeSets.count("axis")) s.conditions.push_back({"axis", 0, 0.0, 0.0});
  for (int i = 0; i < dim; ++i) {
    const std::string set = std::string("symmetry ") + "xyz"[i];
    if (m->nodeSets.count(set)) s.conditions.push_back({set, i, 0.0, 0.0});
  }
  s.mesh = m;
}

// Method 1 integrates over the cells the mesh has: a symmetry plane (or, in
// plane strain, the symmetry line of the built-in half models) would drop the
// mirror half of every body from the interaction.
void checkVolumeMethodModel(const ProblemSetup& s) {
  if (!s.interaction || !s.interaction->volumeMethod) return;
  std::vector<std::string> planes;
  for (const char* set : {"symmetry x", "symmetry y", "symmetry z"})
    if (s.mesh->nodeSets.count(set)) planes.push_back(set);
  if (s.formulation == assembly::Formulation::PlaneStrain && s.mesh->nodeSets.count("axis"))
    planes.push_back("axis (a symmetry line in plane strain)");
  if (planes.empty()) return;
  std::string list;
  for (const auto& p : planes) list += (list.empty() ? "\"" : ", \"") + p + "\"";
  throw InputError("Interaction/Method = \"volume pair\" integrates over the whole bodies, but the mesh is a "
                   "symmetric part of them (" + list + "): mirror it (Geometry/Mirror Planes) or use "
                   "\"half-space point\"");
}

// Every body must be held against rigid motion by its displacement conditions:
// with the interaction alone its tangent is singular (or nearly: a weak
// adhesive spring), and Newton fails without saying why. The conditions of a
// body, evaluated on the rigid modes (translations, rotations; in axisymmetry
// only the axial translation), must have full rank.
void checkBodiesAreHeld(const ProblemSetup& s) {
  const mesh::Mesh& m = *s.mesh;
  const int dim = m.dim;
  const bool axi = s.formulation == assembly::Formulation::Axisymmetric;
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

// The material of a validated Material (or Bodies/<name>) list.
material::NeoHookean materialFrom(const ParameterList& mat) {
  const auto law = mat.get<std::string>("Volumetric Energy") == "(Lambda/2)(ln J)^2"
                       ? material::VolumetricLaw::LogSquared
                       : material::VolumetricLaw::QuadraticJ;
  auto m = material::NeoHookean::fromYoungPoisson(mat.get<double>("Young's Modulus"),
                                                  mat.get<double>("Poisson's Ratio"), law);
  if (mat.get<std::string>("Kinematics") == "small strain") m.kinematics = material::Kinematics::SmallStrain;
  return m;
}

// Bodies/<name> sublists: a material per named body, validated like Material.
void applyBodyMaterials(const ParameterList& deck, ProblemSetup& s) {
  if (!deck.isSublist("Bodies")) return;
  const ParameterList& bodies = deck.sublist("Bodies");
  const mesh::Mesh& m = *s.mesh;
  std::vector<std::string> names(m.numBodies);
  for (const auto& b : m.blocks)
    if (names[b.body].empty()) names[b.body] = b.name;
  std::string known;
  for (const auto& n : names) known += (known.empty() ? "\"" : ", \"") + n + "\"";
  std::vector<material::NeoHookean> materials(m.numBodies, s.material);
  std::vector<char> hasEntry(m.numBodies, 0);
  const ParameterList& validMaterial = validParameters()->sublist("Material");
  for (auto it = bodies.begin(); it != bodies.end(); ++it) {
    const std::string name = bodies.name(it);
    if (!bodies.isSublist(name))
      throw InputError("Bodies/" + name + ": a sublist named after a body is expected; the bodies are " + known);
    const auto found = std::find(names.begin(), names.end(), name);
    if (found == names.end())
      throw InputError("Bodies/" + name + ": the mesh has no body of that name; its bodies are " + known);
    ParameterList own = deck.sublist("Material");
    const ParameterList& given = bodies.sublist(name);
    for (auto p = given.begin(); p != given.end(); ++p) {
      const std::string key = given.name(p), path = "Bodies/" + name + "/" + key;
      if (!validMaterial.isParameter(key))
        throw InputError(path + ": not a material parameter; allowed: Young's Modulus, Poisson's Ratio, Volumetric "
                         "Energy, Kinematics");
      const auto& valid = validMaterial.getEntry(key);
      Teuchos::ParameterEntry entry = given.entry(p);
      if (valid.isType<double>() && entry.isType<int>()) entry.setValue(double(entry.getValue<int>(nullptr)));
      if (valid.isType<double>() && entry.isType<std::string>()) {  // a number given as text (command line)
        try {
          entry.setValue(io::parseDouble(path, entry.getValue<std::string>(nullptr)));
        } catch (const InputError& e) {
          throw InputError(std::string(e.what()) + "; " + valid.docString());
        }
      }
      try {
        if (!valid.validator().is_null()) valid.validator()->validate(entry, key, name);
      } catch (const std::exception&) {
        std::ostringstream v;
        entry.leftshift(v, false);
        throw InputError(path + " = " + v.str() + " is not allowed; " + valid.docString());
      }
      own.setEntry(key, entry);
    }
    hasEntry[found - names.begin()] = 1;
    materials[found - names.begin()] = materialFrom(own);
    std::ostringstream o;
    o << "body \"" << name << "\": Young's modulus " << own.get<double>("Young's Modulus") << ", Poisson's ratio "
      << own.get<double>("Poisson's Ratio");
    s.report.push_back(o.str());
  }
  // a mirror image (Geometry/Mirror Planes) is made of its original unless it has an entry of its own
  for (int b = 0; b < m.numBodies; ++b) {
    if (hasEntry[b]) continue;
    std::string base = names[b];
    while (base.size() > 14 && base.compare(base.size() - 14, 13, " mirrored in ") == 0) base.resize(base.size() - 14);
    const auto original = std::find(names.begin(), names.end(), base);
    if (original == names.end() || !hasEntry[original - names.begin()]) continue;
    materials[b] = materials[original - names.begin()];
    s.report.push_back("body \"" + names[b] + "\": the material of \"" + base + "\" (its mirror image)");
  }
  s.bodyMaterials = std::move(materials);
}

}  // namespace

void resolveMeshFile(Teuchos::ParameterList& deck, const std::string& deckPath) {
  if (!deck.isSublist("Geometry") || !deck.sublist("Geometry").isType<std::string>("File")) return;
  const std::filesystem::path file = deck.sublist("Geometry").get<std::string>("File");
  if (file.empty() || file.is_absolute()) return;
  // absolute, so that parameters.xml (and a --restart from it) works from any folder
  deck.sublist("Geometry").set(
      "File", std::filesystem::absolute(std::filesystem::path(deckPath).parent_path() / file).lexically_normal().string());
}

ProblemSetup buildProblem(const ParameterList& deck) {
  ProblemSetup s;
  s.formulation = parseFormulation(deck.sublist("Problem").get<std::string>("Formulation"));
  s.material = materialFrom(deck.sublist("Material"));
  s.partition = assembly::parseCellPartition(deck.sublist("Solver").get<std::string>("Partition"));
  if (s.material.kinematics == material::Kinematics::SmallStrain)
    s.report.push_back("Material/Kinematics = small strain: linear elasticity on the reference configuration");

  const auto& geometry = deck.sublist("Geometry");
  const std::string type = geometry.get<std::string>("Type");
  // absurd sizes are refused before the mesh is allocated (mesh files: once read)
  const MemoryLimit memory = memoryLimit(deck.sublist("Output"));
  if (const auto size = estimateBuiltInMesh(deck, s.formulation))
    checkSize(*size, memory, type == "block" ? "Geometry/Block/Cells X, Y, Z" : "Geometry/Mesh Refinement");
  if (type == "gmsh") {
    buildFromGmsh(deck, s);
    checkSize(estimateSize(s.mesh->numNodes(), s.mesh->numCells(), s.formulation), memory,
              "Geometry/File \"" + geometry.get<std::string>("File") + "\"");
  } else if (type != "block") {
    buildSphereContact(deck, s);
  } else {
    const auto& b = geometry.sublist("Block");
    const bool clamped = b.get<std::string>("Loaded Face") == "clamped";
    if (s.formulation == assembly::Formulation::ThreeD) {
      mesh::BoxSpec spec;
      spec.lx = b.get<double>("Length X");
      spec.ly = b.get<double>("Length Y");
      spec.lz = b.get<double>("Length Z");
      spec.nx = b.get<int>("Cells X");
      spec.ny = b.get<int>("Cells Y");
      spec.nz = b.get<int>("Cells Z");
      spec.tetrahedra = b.get<std::string>("Element") == "tet4";
      s.mesh = std::make_shared<mesh::Mesh>(mesh::box(spec));
      s.conditions = {{"xmin", 0, 0.0, 0.0}, {"ymin", 1, 0.0, 0.0}, {"zmin", 2, 0.0, 0.0}, {"zmax", 2, 0.0, 1.0}};
      if (clamped) s.conditions.insert(s.conditions.end(), {{"zmax", 0, 0.0, 0.0}, {"zmax", 1, 0.0, 0.0}});
      s.load = {"zmax", 2, 1.0};
      s.forceScale = s.material.youngsModulus() * spec.lx * spec.ly;
    } else {
      mesh::RectangleSpec spec;
      spec.lx = b.get<double>("Length X");
      spec.ly = b.get<double>("Length Y");
      spec.nx = b.get<int>("Cells X");
      spec.ny = b.get<int>("Cells Y");
      s.mesh = std::make_shared<mesh::Mesh>(mesh::rectangle(spec));
      s.conditions = {{"left", 0, 0.0, 0.0}, {"bottom", 1, 0.0, 0.0}, {"top", 1, 0.0, 1.0}};
      if (clamped) s.conditions.push_back({"top", 0, 0.0, 0.0});
      s.load = {"top", 1, 1.0};
      const Real Y = s.material.youngsModulus();
      s.forceScale = s.formulation == assembly::Formulation::Axisymmetric ? Y * kPi * spec.lx * spec.lx : Y * spec.lx;
    }
    if (b.get<double>("Distortion") > 0.0)
      mesh::perturbInteriorNodes(*s.mesh, b.get<double>("Distortion"), unsigned(b.get<int>("Distortion Seed")));
  }
  for (const auto& c : s.conditions) s.mesh->nodeSet(c.nodeSet);  // a missing set is named now
  checkBodiesAreHeld(s);
  applyBodyMaterials(deck, s);
  checkVolumeMethodModel(s);
  s.numNodes = std::size_t(s.mesh->numNodes());
  s.numCells = std::size_t(s.mesh->numCells());
  return s;
}

namespace {

Discretization discretize(const Distribution& dist, const ProblemSetup& setup,
                          Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> linearSolver) {
  Discretization d;
  d.mesh = dist.mesh;
  d.dofs = dist.dofs;
  d.problem = setup.bodyMaterials.empty()
                    ? std::make_shared<assembly::Problem>(d.dofs, d.mesh, setup.formulation, setup.material)
                    : std::make_shared<assembly::Problem>(d.dofs, d.mesh, setup.formulation, setup.bodyMaterials);
  if (setup.interaction) {
    const auto& in = *setup.interaction;
    if (in.volumeMethod) {
      d.volumeInteraction = std::make_shared<interaction::VolumeInteraction>(*d.mesh, in.densities, in.potential,
                                                                             in.volumeOptions);
      d.problem->setInteraction(d.volumeInteraction, in.searchRadiusFactor);
    } else {
      d.interaction = std::make_shared<interaction::SurfaceInteraction>(d.mesh->surfaces, in.densities,
                                                                        in.potential, in.options);
      d.problem->setInteraction(d.interaction, in.searchRadiusFactor);
    }
  }
  d.dirichlet = std::make_shared<assembly::DirichletConditions>(d.dofs);
  for (const auto& c : setup.conditions) d.dirichlet->add(d.mesh->nodeSet(c.nodeSet), c.component, c.offset, c.scale);
  std::vector<solver::ScalarParameter> parameters;
  if (setup.interaction) {
    // gammaW = Y / (beta0^2 r0^3 epsilon) at fixed r0: epsilon, hence every
    // traction, scales with gammaW0 / gammaW.
    const auto surface = d.interaction;
    const auto volume = d.volumeInteraction;
    const Real gammaW0 = setup.interaction->gammaW;
    parameters.push_back({"gammaW", gammaW0, [surface, volume, gammaW0](Real gammaW) {
                            if (!(gammaW > 0.0)) throw NumericalError("gammaW = " + std::to_string(gammaW) + " <= 0");
                            if (surface) surface->setStrength(gammaW0 / gammaW);
                            if (volume) volume->setStrength(gammaW0 / gammaW);
                          }});
    // gammaL = R0 / r0 at fixed gammaW: r0 scales with gammaL0 / gammaL and
    // epsilon r0^3 stays, so the traction law is T0(r / b) (cutoff included);
    // u keeps the origin of the deck's gammaL.
    const Real gammaL0 = setup.interaction->gammaL;
    parameters.push_back({"gammaL", gammaL0, [surface, volume, gammaL0](Real gammaL) {
                            if (!(gammaL > 0.0)) throw NumericalError("gammaL = " + std::to_string(gammaL) + " <= 0");
                            if (surface) surface->setLengthScale(gammaL0 / gammaL);
                            if (volume) volume->setLengthScale(gammaL0 / gammaL);
                          }});
  }
  d.model = Teuchos::rcp(new solver::ModelEvaluator(d.problem, d.dirichlet, std::move(linearSolver),
                                                    std::move(parameters)));
  return d;
}

}  // namespace

Discretization discretize(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const ProblemSetup& setup,
                          Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> linearSolver) {
  return discretize(distribute(comm, setup), setup, std::move(linearSolver));
}

Discretization discretize(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const ProblemSetup& setup,
                          const Teuchos::ParameterList& linearSolver) {
  const auto dist = distribute(comm, setup);
  const bool rigid = linearSolver.get<std::string>("MueLu Near Null Space") == "rigid body modes";
  const auto modes = rigid ? assembly::rigidBodyModes(*dist.dofs, *dist.mesh, setup.formulation) : Teuchos::null;
  return discretize(dist, setup,
                    solver::buildLinearSolver(linearSolver, comm->getSize(), dist.dofs->dofsPerNode(), modes,
                                              !setup.interaction.has_value()));
}

}  // namespace cgcm::app
