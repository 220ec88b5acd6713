#include "cgcm/interaction/InteractionSetup.hpp"

#include <cmath>
#include <sstream>

#include "cgcm/core/Error.hpp"
#include "cgcm/core/ParameterValidators.hpp"
#include "cgcm/interaction/Normalisation.hpp"

namespace cgcm::interaction {

using Teuchos::ParameterList;

Teuchos::RCP<const ParameterList> validParameters() {
  using namespace validators;
  static const Teuchos::RCP<const ParameterList> valid = [] {
    auto inter = Teuchos::rcp(new ParameterList("Interaction"));
    std::vector<std::string> names;
    std::string help;
    for (const auto& e : potentialRegistry()) {
      names.push_back(e.deckName);
      help += std::string(help.empty() ? "" : "; ") + "\"" + e.deckName + "\": " + e.description;
    }
    inter->set("Potential", names.front(), help, choices(names));
    for (const auto& e : potentialRegistry())
      if (e.declareParameters)
        e.declareParameters(inter->sublist(e.deckName, false, std::string("the ") + e.deckName + " potential's own parameters"));
    inter->set("Method", "half-space point",
               "\"half-space point\" (Method 3: each surface point against the other body as a half-space) or "
               "\"volume pair\" (Method 1: quadrature over pairs of cells of two bodies, the reference; cost grows "
               "with the cells within the cutoff, and cells near the surfaces should be about r0 or smaller)",
               choices({"half-space point", "volume pair"}));
    inter->set("Volume Quadrature Order", 2,
               "volume pair: the fewest Gauss points per direction of a cell (1 .. 6); pairs of cells closer "
               "than their size get more, as Volume Quadrature Tolerance asks, up to the Max Volume Quadrature Order",
               intBetween(1, 6));
    inter->set("Max Volume Quadrature Order", 0,
               "volume pair: most Gauss points per direction for pairs of cells close to each other (1 .. 12 in "
               "2D, 1 .. 6 in 3D; 4 for pairs with a tetrahedron); 0: the most the kernel holds (12 in 2D and "
               "axisymmetry, 6 in 3D). A mesh whose cells in contact need more to meet the Volume Quadrature "
               "Tolerance is refused; the run's summary counts the pairs at the cap and those above the tolerance",
               intBetween(0, 12));
    inter->set("Volume Quadrature Tolerance", 1e-4,
               "volume pair: each pair of cells gets the lowest Gauss order (from Volume Quadrature Order up) whose "
               "estimated error of the pair's force, relative to the larger of its repulsive and attractive parts, is "
               "at most this at the closest the cells come before the pair list is rebuilt (in contact: r0 / 2). A "
               "mesh whose surface cells where the bodies meet need more than the Max Volume Quadrature Order there "
               "is refused before the run, with the cell size it needs. 0: no estimate, every pair takes Volume "
               "Quadrature Order (for checks of other things than accuracy)",
               between(0.0, 1.0));
    inter->set("Pair List Skin", 1.0,
               "volume pair: the pair list covers cutoff + skin (units of r0) and is rebuilt when a node has moved "
               "by half the skin",
               atLeast(0.01));
    inter->set("gammaL", 50.0, "R0 / r0: geometric scale (22)", atLeast(1e-300));
    inter->set("gammaW", 200.0, "Y / (beta0^2 r0^3 epsilon): energy-density ratio (28)", atLeast(1e-300));
    inter->set("gammaL bar", 0.0,
               "the paper's equivalent parameter; > 0 replaces gammaL through the Barred Convention", atLeast(0.0));
    inter->set("gammaW bar", 0.0,
               "the paper's equivalent parameter; > 0 replaces gammaW through the Barred Convention", atLeast(0.0));
    inter->set("Barred Convention", "literal",
               "how the paper's barred values convert: \"literal\" (gammaL = gammaL bar / (3/4)^(1/6), gammaW = "
               "gammaW bar / sqrt(3), the reading the paper's stability statements and Fig. 11 state support; "
               "doc/theory.md) or \"identity\" (gamma = gamma bar)",
               choices({"identity", "literal"}));
    inter->set("r0", 0.0,
               "physical input instead of the gammas: equilibrium distance of the pair potential (> 0 to use)",
               atLeast(0.0));
    inter->set("epsilon", 0.0, "physical input: energy well of the pair potential (with r0)", atLeast(0.0));
    inter->set("beta0", 1.0, "reference particle density of both bodies", atLeast(1e-300));
    inter->set("Quadrature Points", 4,
               "Gauss points per surface segment; in 3D per direction of a facet (n x n on a quadrilateral; on a "
               "triangle 1, 6, 7 points for n = 1, 2, 3 and 6 n (n + 1) beyond), and 2 unless given",
               intAtLeast(1));
    inter->set("Surface Density", "current area",
               "half-space point: how a body's surface layer is counted. \"current area\" (the default): the "
               "reference density beta0 over the current area da, the paper's eq. (21); \"reference area\": beta0 "
               "over the undeformed area dA, the layer's particles conserved as the surface stretches. Against "
               "Method 1, current area is within 1.2 % at the JKR end where the surface stretches little "
               "(sigma_max/E* up to 0.3), reference area as close only up to Tabor mu = 3; where it stretches "
               "much both are too weak, reference area far more (doc/theory.md#surface-density)",
               choices({"current area", "reference area"}));
    inter->set("Cutoff", 10.0,
               "interaction cutoff in units of r0: farther points are skipped. It removes part of the work of "
               "adhesion w (printed at the start): half-space point 0.67 % at 10 (with the taper); volume pair, "
               "whose cut falls between point pairs, up to 3.0 % at 10, 0.8 % at 20, falling as 1/cutoff^2",
               atLeast(1.0));
    inter->set("Cutoff Taper", 0.2,
               "fraction of the cutoff over which the traction is blended smoothly (C1) to zero, 0 .. 0.9; "
               "0 is a sharp cutoff, whose residual jumps when points cross it",
               between(0.0, 0.9));
    inter->set("Projection Smoothing", SurfaceInteractionOptions::kDefaultProjectionSmoothing,
               "width delta of the blend of a point's projections onto neighbouring segments (3D: triangles), in "
               "units of r0: near a concave corner (3D: edge) of the other surface the closest facet switches and "
               "the force direction would jump; the blend keeps the residual smooth. 0 uses the closest facet "
               "alone (the paper's Method 3; "
               "Newton can then find no equilibrium next to such a switch)",
               atLeast(0.0));
    inter->set("Search Radius Factor", 2.0,
               "matrix-graph search radius / cutoff (> 1); volume pair: the radius is cutoff + factor x Pair List "
               "Skin",
               atLeast(1.01));
    return Teuchos::RCP<const ParameterList>(inter);
  }();
  return valid;
}

namespace {

// (gammaL, gammaW) from whichever of the three parameterisations the list gives.
ScalingParameters scalingFrom(const ParameterList& in, const ReferenceScales& scales) {
  const bool barred = in.get<double>("gammaL bar") > 0.0 || in.get<double>("gammaW bar") > 0.0;
  const bool physical = in.get<double>("r0") > 0.0 || in.get<double>("epsilon") > 0.0;
  const bool plainSet = !in.getEntry("gammaL").isDefault() || !in.getEntry("gammaW").isDefault();
  if (int(barred) + int(physical) + int(plainSet) > 1)
    throw InputError("Interaction: give one of (gammaL, gammaW), (gammaL bar, gammaW bar) or (r0, epsilon)");
  if (barred) {
    const Real gLb = in.get<double>("gammaL bar"), gWb = in.get<double>("gammaW bar");
    if (!(gLb > 0.0 && gWb > 0.0)) throw InputError("Interaction: set both gammaL bar and gammaW bar (> 0)");
    const bool literal = in.get<std::string>("Barred Convention") == "literal";
    return {literal ? gLb / std::pow(0.75, 1.0 / 6.0) : gLb, literal ? gWb / std::sqrt(3.0) : gWb};
  }
  if (physical) {
    if (!(in.get<double>("r0") > 0.0 && in.get<double>("epsilon") > 0.0))
      throw InputError("Interaction: set both r0 and epsilon (> 0)");
    return toScaling({in.get<double>("epsilon"), in.get<double>("r0"), in.get<double>("beta0"), scales.R0,
                      scales.youngsModulus});
  }
  return {in.get<double>("gammaL"), in.get<double>("gammaW")};
}

// The sublist of the chosen potential's own parameters; another potential's parameter set to
// other than its default is refused (it would have no effect).
ParameterList ownParameters(const ParameterList& in) {
  const std::string chosen = in.get<std::string>("Potential");
  const ParameterList& valid = *validParameters();
  for (const auto& e : potentialRegistry()) {
    if (!in.isSublist(e.deckName) || chosen == e.deckName || !valid.isSublist(e.deckName)) continue;
    const ParameterList& given = in.sublist(e.deckName);
    const ParameterList& declared = valid.sublist(e.deckName);
    for (auto it = given.begin(); it != given.end(); ++it) {
      const std::string& name = given.name(it);
      if (declared.isParameter(name) && given.entry(it).getAny(false) == declared.getEntry(name).getAny(false)) continue;
      throw InputError("Interaction/" + std::string(e.deckName) + "/" + name + " is set, but Interaction/Potential = \"" +
                       chosen + "\"; it belongs to \"" + e.deckName + "\"");
    }
  }
  return in.isSublist(chosen) ? in.sublist(chosen) : ParameterList();
}

}  // namespace

InteractionSetup fromParameters(const ParameterList& in, const ReferenceScales& scales, Formulation formulation) {
  const Real beta0 = in.get<double>("beta0");
  const ScalingParameters gammas = scalingFrom(in, scales);
  const auto phys = interaction::fromScaling(gammas.gammaL, gammas.gammaW, scales.R0, scales.youngsModulus, beta0);
  InteractionSetup s;
  s.potential = makePotential(in.get<std::string>("Potential"), phys.epsilon, phys.r0, ownParameters(in));
  s.density = beta0;
  s.gammaL = gammas.gammaL;
  s.gammaW = gammas.gammaW;
  s.method = in.get<std::string>("Method") == "volume pair" ? Method::VolumePair : Method::HalfSpacePoint;
  s.searchRadiusFactor = in.get<double>("Search Radius Factor");

  auto& surface = s.surfaceOptions;
  surface.formulation = formulation;
  // 3D: n x n points per quad, 6 or 7 per triangle at n = 2, 3, but 6 n (n + 1) beyond: 2 unless set
  const bool threeD = formulation == Formulation::ThreeD;
  surface.quadraturePoints = threeD && in.getEntry("Quadrature Points").isDefault() ? 2 : in.get<int>("Quadrature Points");
  surface.surfaceDensity = in.get<std::string>("Surface Density") == "reference area"
                               ? SurfaceDensity::ReferenceArea
                               : SurfaceDensity::CurrentArea;
  surface.cutoff = in.get<double>("Cutoff") * phys.r0;
  surface.cutoffTaper = in.get<double>("Cutoff Taper");
  surface.projectionSmoothing = in.get<double>("Projection Smoothing") * phys.r0;
  if ((1.0 - surface.cutoffTaper) * in.get<double>("Cutoff") < 2.0)
    throw InputError("Interaction/Cutoff Taper = " + std::to_string(surface.cutoffTaper) +
                     " with Interaction/Cutoff = " + std::to_string(in.get<double>("Cutoff")) +
                     " starts the taper below 2 r0, in the range of the repulsion; need (1 - taper) * cutoff >= 2");

  auto& volume = s.volumeOptions;
  volume.formulation = formulation;
  volume.quadratureOrder = in.get<int>("Volume Quadrature Order");
  volume.maxQuadratureOrder = in.get<int>("Max Volume Quadrature Order");
  volume.quadratureTolerance = in.get<double>("Volume Quadrature Tolerance");
  volume.cutoff = surface.cutoff;
  volume.skin = in.get<double>("Pair List Skin") * phys.r0;
  if (s.method == Method::VolumePair && volume.maxQuadratureOrder > 0 &&
      volume.maxQuadratureOrder < volume.quadratureOrder)
    throw InputError("Interaction/Max Volume Quadrature Order = " + std::to_string(volume.maxQuadratureOrder) +
                     " is below Interaction/Volume Quadrature Order = " + std::to_string(volume.quadratureOrder));
  if (s.method == Method::VolumePair && threeD && volume.maxQuadratureOrder > kMaxVolumeOrder3D)
    throw InputError("Interaction/Max Volume Quadrature Order = " + std::to_string(volume.maxQuadratureOrder) +
                     ": at most " + std::to_string(kMaxVolumeOrder3D) + " in 3D");
  return s;
}

Real InteractionSetup::contactDistance() const { return LennardJones::surfaceEquilibriumDistance(potential->r0()); }

namespace {

// The symmetry planes of a mesh that is a symmetric part of its model, for Method 1's image
// cells: "symmetry x|y|z", checked to be the part x_i >= 0 with the set on x_i = 0; in plane
// strain also "axis", the symmetry line x = 0, unless the mesh has nodes on both sides of it (a
// model mirrored in x keeps its "axis" as an interior line, Geometry/Mirror Planes); in
// axisymmetry x = 0 is the axis, no plane. A body with a node on a plane is cut by it (the rule
// of mesh::mirror: it is one body with its image).
void setSymmetryPlanes(const mesh::Mesh& mesh, Formulation formulation, VolumeInteractionOptions& options) {
  static const char* axes = "xyz";
  options.symmetryPlanes = 0;
  options.bodySymmetryPlanes.assign(std::size_t(mesh.numBodies), 0);
  Real extent = 0.0;
  for (Real x : mesh.coords) extent = std::max(extent, std::abs(x));
  const Real tolerance = 1e-9 * std::max(extent, Real(1e-300));
  std::vector<int> nodeBody(std::size_t(mesh.numNodes()), -1);
  for (const auto& b : mesh.blocks)
    for (LocalIndex n : b.connectivity) nodeBody[std::size_t(n)] = b.body;
  for (int i = 0; i < mesh.dim; ++i) {
    if (i == 0 && formulation == Formulation::Axisymmetric) continue;
    const std::string name = std::string("symmetry ") + axes[i];
    const bool line = i == 0 && formulation == Formulation::PlaneStrain && mesh.nodeSets.count("axis");
    if (!mesh.nodeSets.count(name) && !line) continue;
    const std::string set = mesh.nodeSets.count(name) ? name : "axis";
    if (set == "axis") {
      bool bothSides = false;
      for (LocalIndex n = 0; n < mesh.numNodes() && !bothSides; ++n) bothSides = mesh.coord(n, 0) < -tolerance;
      if (bothSides) continue;
    }
    const std::string what = "Interaction/Method = \"volume pair\" on a mesh with the node set \"" + set +
                             "\": it integrates over the whole model through mirror images, so the mesh must be "
                             "the part " + axes[i] + " >= 0 of a model symmetric in " + axes[i] + " = 0, but ";
    for (LocalIndex n : mesh.nodeSet(set))
      if (std::abs(mesh.coord(n, i)) > tolerance)
        throw InputError(what + "its node " + std::to_string(n) + " has " + axes[i] + " = " +
                         std::to_string(mesh.coord(n, i)));
    for (LocalIndex n = 0; n < mesh.numNodes(); ++n) {
      if (mesh.coord(n, i) < -tolerance)
        throw InputError(what + "node " + std::to_string(n) + " has " + axes[i] + " = " +
                         std::to_string(mesh.coord(n, i)) + " (mirror the mesh: Geometry/Mirror Planes)");
      if (std::abs(mesh.coord(n, i)) <= tolerance && nodeBody[std::size_t(n)] >= 0)
        options.bodySymmetryPlanes[std::size_t(nodeBody[std::size_t(n)])] |= 1 << i;
    }
    options.symmetryPlanes |= 1 << i;
  }
}

}  // namespace

std::shared_ptr<Interaction> InteractionSetup::create(const mesh::Mesh& mesh) const {
  const std::vector<Real> densities(std::size_t(mesh.numBodies), density);
  if (method == Method::VolumePair) {
    VolumeInteractionOptions options = volumeOptions;
    setSymmetryPlanes(mesh, volumeOptions.formulation, options);
    return std::make_shared<VolumeInteraction>(mesh, densities, potential, options);
  }
  auto surface = std::make_shared<SurfaceInteraction>(mesh.surfaces, densities, potential, surfaceOptions);
  // the table of dA only where it is read
  if (surfaceOptions.surfaceDensity == SurfaceDensity::ReferenceArea) surface->setReferenceConfiguration(mesh.coords);
  return surface;
}

std::vector<ScalarParameter> InteractionSetup::scalarParameters(std::shared_ptr<Interaction> interaction) const {
  const Real gammaW0 = gammaW, gammaL0 = gammaL;
  return {{"gammaW", gammaW0,
           [interaction, gammaW0](Real value) {
             if (!(value > 0.0)) throw NumericalError("gammaW = " + std::to_string(value) + " <= 0");
             interaction->setStrength(gammaW0 / value);
           }},
          // u keeps the origin of the deck's gammaL
          {"gammaL", gammaL0, [interaction, gammaL0](Real value) {
             if (!(value > 0.0)) throw NumericalError("gammaL = " + std::to_string(value) + " <= 0");
             interaction->setLengthScale(gammaL0 / value);
           }}};
}

void InteractionSetup::checkMesh(const mesh::Mesh& mesh, Formulation formulation, const MemoryBudget& memory) const {
  // Method 1 integrates over the cells the mesh has and their mirror images across its symmetry planes.
  if (method != Method::VolumePair) return;
  VolumeInteractionOptions options = volumeOptions;
  options.formulation = formulation;
  setSymmetryPlanes(mesh, formulation, options);
  const VolumeInteraction volume(mesh, std::vector<Real>(std::size_t(mesh.numBodies), density), potential,
                                 options);
  // Every pair of cells within the cutoff is listed (each rank builds the whole list before
  // keeping its rows): the list grows like (cutoff / cell size)^dim per cell near the other body.
  const auto size = volume.pairListSize(mesh.coords.data(), memory.megabytes);
  if (size.megabytes > memory.megabytes) {
    std::ostringstream o;
    o.precision(3);
    o << "Interaction/Method = \"volume pair\": at the start " << (size.stopped ? "more than " : "") << size.pairs
      << " directed cell pairs lie within Interaction/Cutoff + Pair List Skin (" << volume.cutoff() + volume.skin()
      << "), and their list and matrix couplings need " << (size.stopped ? "more than " : "about ") << size.megabytes
      << " MB, more than " << memory.source
      << ": coarser cells near the contact, a smaller Interaction/Cutoff, or \"half-space point\"";
    throw InputError(o.str());
  }
  // The cells that meet first must be integrated to the tolerance when they are in contact
  // (at kContactGapFloor r0): the rule's error grows with cell size over gap, and beyond about
  // 4 no order up to the kernel's most brings it down (doc/theory.md#method-1).
  if (volumeOptions.quadratureTolerance <= 0.0) return;
  std::vector<char> surfaceCells(std::size_t(mesh.numCells()), 0);
  for (const auto& surface : mesh.surfaces)
    for (LocalIndex cell : surface.facetCells)
      if (cell >= 0) surfaceCells[cell] = 1;
  const auto c = volume.contactQuadrature(mesh.coords.data(), surfaceCells);
  if (c.withinTolerance) return;
  const Real r0 = potential->r0();
  std::ostringstream o;
  o.precision(3);
  o << "Interaction/Method = \"volume pair\": the surface cells where the bodies meet are up to " << c.largestSize / r0
    << " r0 long (the longest edge; half of it on a tetrahedron), and in contact (" << kContactGapFloor
    << " r0 apart) their pair quadrature at order " << c.order << ", the most "
    << (volumeOptions.maxQuadratureOrder > 0 ? "Interaction/Max Volume Quadrature Order" : "the kernel") << " gives"
    << (c.maxOrder == kMaxTetOrder ? " with a tetrahedron" : "") << ", has an estimated error of " << c.estimate
    << " of the pairs' force, above Interaction/Volume Quadrature Tolerance = " << volumeOptions.quadratureTolerance
    << ". Cells of at most " << c.neededSize / r0 << " r0 there meet it (" << c.largestSize / c.neededSize
    << " times smaller): on the built-in meshes Geometry/Contact Zone Size sets them (cells of Contact Zone Size / 20 "
       "sphere radii at Mesh Refinement 0: scale it by "
    << c.neededSize / c.largestSize << ") and each level of Geometry/Mesh Refinement halves them ("
    << int(std::ceil(std::log2(c.largestSize / c.neededSize))) << " more); or allow a larger tolerance";
  throw InputError(o.str());
}

std::vector<std::string> describe(const InteractionSetup& s, const ReferenceScales& scales) {
  // Derived scales (doc/theory.md#method-3, #normalisation; doc/analytic-models.md).
  const Real beta0 = s.density, r0 = s.potential->r0(), epsilon = s.potential->epsilon();
  const Real Y = scales.youngsModulus, nu = scales.poissonRatio, R = scales.reducedRadius, R0 = scales.R0;
  const Real rS0 = s.contactDistance();
  const Real cutoff = s.surfaceOptions.cutoff;
  const Real taperStart = (1.0 - s.surfaceOptions.cutoffTaper) * cutoff;
  const Real w = LennardJones::workFactor() * beta0 * beta0 * epsilon * std::pow(r0, 4);
  const Real sigmaMax = LennardJones::peakTractionFactor() * beta0 * beta0 * epsilon * std::pow(r0, 3);
  const Real Estar = Y / (2.0 * (1.0 - nu * nu));
  const Real tabor = std::cbrt(R * w * w / (Estar * Estar * rS0 * rS0 * rS0));
  const Real lambda = sigmaMax * std::cbrt(9.0 * R / (2.0 * kPi * w * Estar * Estar));
  std::vector<std::string> lines;
  std::ostringstream o;
  o.precision(6);
  o << "gammaL = " << s.gammaL << ", gammaW = " << s.gammaW << " (barred, literal reading: "
    << s.gammaL * std::pow(0.75, 1.0 / 6.0) << ", " << s.gammaW * std::sqrt(3.0)
    << "); gammaK = gammaW/gammaL = " << s.gammaW / s.gammaL;
  lines.push_back(o.str());
  o.str("");
  o << "R0 = " << R0 << ", E0 = Y R0^3 = " << Y * R0 * R0 * R0 << ", r0 = " << r0 << ", epsilon = " << epsilon
    << ", beta0 = " << beta0;
  lines.push_back(o.str());
  o.str("");
  // the potential's own surface properties (a repulsive one has no r_S0 and w = 0)
  const auto ownRS0 = s.potential->surfaceEquilibriumDistance();
  o << "potential " << s.potential->name() << ": r_S0 = ";
  if (ownRS0)
    o << *ownRS0;
  else
    o << "none";
  o << ", w = " << s.potential->workOfAdhesion(beta0, beta0) << ", sigma_max = "
    << s.potential->peakTraction(beta0, beta0) << ", cutoff = " << cutoff;
  if (s.method == Method::VolumePair)
    o << " (point pairs farther apart are left out where their cells are not listed), work removed by the "
         "cutoff = at most "
      << 100.0 * pairCutoffWorkFraction(*s.potential, cutoff) << " % of w";
  else
    o << " (taper from " << taperStart << "), |T(taper start)| = "
      << std::abs(s.potential->traction(taperStart, beta0, beta0)) / sigmaMax
      << " sigma_max(Lennard-Jones), work removed by the cutoff = "
      << 100.0 * neglectedWorkFraction(*s.potential, taperStart, cutoff) << " % of w";
  if (s.method == Method::HalfSpacePoint)
    o << ", surface density beta0 over the "
      << (s.surfaceOptions.surfaceDensity == SurfaceDensity::ReferenceArea ? "reference" : "current") << " area";
  lines.push_back(o.str());
  o.str("");
  o << "Lennard-Jones scales (of its r0 and epsilon, whatever the potential): Tabor mu = " << tabor
    << ", Maugis-Dugdale lambda (theory) = " << lambda << ", 2 pi w R = " << 2 * kPi * w * R
    << ", 1.5 pi w R = " << 1.5 * kPi * w * R << " (R = " << R << ")";
  lines.push_back(o.str());
  return lines;
}

}  // namespace cgcm::interaction
