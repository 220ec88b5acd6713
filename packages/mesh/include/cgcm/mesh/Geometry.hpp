#pragma once
// The deck's Geometry sublist, declared and read here: the built-in
// geometries (the paper's sphere on a half-space or on a second sphere, a
// block) and gmsh meshes with the physical-group convention of
// meshes/README.md, each turned into a Model: the mesh, the displacement
// conditions that hold and drive its bodies, and the force responses the load
// curve reports.
#include <Teuchos_ParameterList.hpp>

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cgcm/core/Bytes.hpp"
#include "cgcm/core/Formulation.hpp"
#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::mesh {

/// u_component = offset + scale * (load parameter u) on every node of a node set.
struct DisplacementCondition {
  std::string nodeSet;
  int component;
  Real offset;
  Real scale;
};

/// A resultant force: sign * scale * sum of the internal force over a node
/// set (scale: 2 per symmetry plane of the mesh, for the whole body's force);
/// with a direction, its component along it instead of `component`, `sign`.
struct ForceResponse {
  std::string nodeSet;
  int component;
  Real sign;
  Real scale = 1.0;
  std::vector<Real> direction = {};  ///< unit vector (dim entries), or empty
};

/// Two-body contact responses: the gap on the axis between the apex nodes,
/// and the contact radius (where the surfaces are `contactDistance` apart).
struct ContactGeometry {
  std::string upperApex, lowerApex;  ///< node sets of one node each
  int upperBody = 0, lowerBody = 1;
  Real contactDistance = 0.0;        ///< r_S0 (Lennard-Jones) or its value for the same r0
};

/// A geometry ready for the solver.
struct Model {
  std::shared_ptr<Mesh> mesh;
  std::vector<DisplacementCondition> conditions;
  ForceResponse force;  ///< the "P" column of the load curve
  /// Initial guess at the start of the load path: these displacements (scaled
  /// by u) on whole bodies, e.g. the rigid approach of the upper body.
  std::vector<DisplacementCondition> initialMotion;
  /// Two bodies: the same resultant measured at the second body's support
  /// ("P_lower"); it equals P up to the interaction's force imbalance.
  std::optional<ForceResponse> balance;
  std::optional<ContactGeometry> contact;
  /// The bodies interact (the sphere geometries; gmsh meshes of several bodies).
  bool interacting = false;
  /// The force scale of the convergence test is Young's modulus times these
  /// factors, multiplied in this order: R0, R0 for contact (R0 per unit
  /// thickness in plane strain), the loaded face of a block.
  std::vector<Real> areaFactors = {1.0};
  Real forceScale(Real youngsModulus) const {
    for (Real a : areaFactors) youngsModulus *= a;
    return youngsModulus;
  }
  std::vector<std::string> report;  ///< what the run's log says about the model
  /// How the mesh was obtained (Type = gmsh: meshed, or read from the mesh cache, and in how long); empty
  /// for the built-in meshes. Also a line of the report.
  std::string meshSource;
};

/// Makes each force response whose nodes all lie in body `body` (named
/// `name`) sum over every node of the body (the node set "<name> (all nodes)",
/// added): the interaction's resultant on the body, its internal forces
/// summing to zero, instead of the reaction at its supports, whose round-off
/// grows with the body's modulus times its displacement. The two agree at
/// equilibrium. Returns whether a response changed.
bool measureOnWholeBody(Model& model, int body, const std::string& name);

/// Makes body `body` (named `name`) rigid, the limit of an infinitely stiff
/// material: every node of the body takes, in each displacement component, the
/// one condition its constrained nodes carry there (a rigid body translates as a
/// whole; rotations are not offered), and its forces are measured on the whole
/// body (measureOnWholeBody). Throws InputError naming Bodies/<name>/Rigid when
/// a component has no condition on the body (it would keep unknowns of its
/// own) or two different ones.
void makeRigid(Model& model, int body, const std::string& name);

/// Everything of a model but its mesh, as bytes, and back (the mesh stays null):
/// what the other ranks receive of rank 0's model (the mesh travels in subdomains, Subdomain.hpp).
void put(core::ByteWriter& out, const Model& model);
Model getModel(core::ByteReader& in);

/// The Geometry sublist: every parameter with its default and help.
Teuchos::RCP<const Teuchos::ParameterList> validParameters();

/// The reduced radius R1 R2 / (R1 + R2) of the contact a validated Geometry
/// sublist describes (the Sphere Radius unless it is a sphere on a sphere).
Real reducedRadius(const Teuchos::ParameterList& geometry);

/// The cells Geometry/Element Order and Serendipity of a validated Geometry sublist ask for.
/// Throws InputError for Serendipity without Element Order = 2.
ElementOrder elementOrder(const Teuchos::ParameterList& geometry);

/// r_S0 of the interaction, asked for only when the bodies interact (the
/// built-in contact geometries, gmsh meshes of several bodies), after the
/// mesh's own checks: the interaction's parameters are read only then.
using ContactDistance = std::function<Real()>;

/// The model of a validated Geometry sublist. `contactDistance` (r_S0) puts
/// u = 0 where the undeformed surfaces of interacting bodies are that far
/// apart. Throws InputError for meshes and combinations the validators cannot
/// reject (a body that can move rigidly, a missing node set, overlapping bodies, ...).
Model buildModel(const Teuchos::ParameterList& geometry, Formulation formulation,
                 const ContactDistance& contactDistance);

}  // namespace cgcm::mesh
