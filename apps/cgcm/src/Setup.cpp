#include "cgcm/app/Setup.hpp"

#include <Teuchos_StandardParameterEntryValidators.hpp>

#include "cgcm/core/Error.hpp"
#include "cgcm/io/Deck.hpp"
#include "cgcm/mesh/Generators.hpp"
#include "cgcm/solver/LinearSolver.hpp"
#include "cgcm/solver/LoadStepper.hpp"
#include "cgcm/solver/NewtonSolver.hpp"

namespace cgcm::app {

using Teuchos::ParameterList;
using Teuchos::RCP;
using Teuchos::rcp;

namespace {

RCP<Teuchos::StringValidator> choices(std::initializer_list<std::string> names) {
  return rcp(new Teuchos::StringValidator(Teuchos::Array<std::string>(names)));
}

RCP<Teuchos::EnhancedNumberValidator<double>> atLeast(double min) {
  auto v = rcp(new Teuchos::EnhancedNumberValidator<double>());
  v->setMin(min);
  return v;
}

RCP<Teuchos::EnhancedNumberValidator<double>> between(double min, double max) {
  return rcp(new Teuchos::EnhancedNumberValidator<double>(min, max));
}

RCP<Teuchos::EnhancedNumberValidator<int>> intAtLeast(int min) {
  auto v = rcp(new Teuchos::EnhancedNumberValidator<int>());
  v->setMin(min);
  return v;
}

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
  geometry.set("Type", "block", "\"block\": a rectangle (2D) or box (3D) compressed or stretched along its last axis",
               choices({"block"}));
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

  valid->sublist("Loading", false,
                 "displacement control: the load parameter u is the prescribed displacement, stepped along the path")
      .setParameters(*solver::LoadPathSettings::validParameters());

  auto& solverList = valid->sublist("Solver", false, "nonlinear and linear solvers");
  solverList.sublist("Newton", false, "Newton's method (NOX) at each load step")
      .setParameters(*solver::NewtonSettings::validParameters());
  solverList.sublist("Linear Solver", false, "linear solves inside Newton (Stratimikos)")
      .setParameters(*solver::linearSolverValidParameters());

  auto& output = valid->sublist("Output", false, "what is written where");
  output.set("Directory", "output", "folder for the load curve and the echoed parameters (created if missing)");
  output.set("Print Steps", true, "print one line per load step");
  return valid;
}

ProblemSetup buildProblem(const ParameterList& deck) {
  ProblemSetup s;
  s.formulation = parseFormulation(deck.sublist("Problem").get<std::string>("Formulation"));
  const auto& mat = deck.sublist("Material");
  const auto law = mat.get<std::string>("Volumetric Energy") == "(Lambda/2)(ln J)^2"
                       ? material::VolumetricLaw::LogSquared
                       : material::VolumetricLaw::QuadraticJ;
  s.material = material::NeoHookean::fromYoungPoisson(mat.get<double>("Young's Modulus"),
                                                      mat.get<double>("Poisson's Ratio"), law);

  const auto& geometry = deck.sublist("Geometry");
  const std::string type = geometry.get<std::string>("Type");
  if (type == "block") {
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
    }
    if (b.get<double>("Distortion") > 0.0)
      mesh::perturbInteriorNodes(*s.mesh, b.get<double>("Distortion"), unsigned(b.get<int>("Distortion Seed")));
  }
  return s;
}

}  // namespace cgcm::app
