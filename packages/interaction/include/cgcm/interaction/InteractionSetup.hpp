#pragma once
// The deck's Interaction sublist, declared and read here: the pair potential
// and its scales from one of three parameterisations (gammaL and gammaW; the
// paper's barred values; r0 and epsilon: doc/theory.md#normalisation), the method
// (Method 3 or Method 1) with its options, the interaction it builds on a
// mesh, and the scalar parameters gammaW and gammaL that continuation moves.
#include <Teuchos_ParameterList.hpp>

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "cgcm/core/Formulation.hpp"
#include "cgcm/core/ScalarParameter.hpp"
#include "cgcm/interaction/Interaction.hpp"
#include "cgcm/interaction/PairPotential.hpp"
#include "cgcm/interaction/SurfaceInteraction.hpp"
#include "cgcm/interaction/VolumeInteraction.hpp"
#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::interaction {

/// The Interaction sublist: every parameter with its default and help.
Teuchos::RCP<const Teuchos::ParameterList> validParameters();

/// The scales of the model the interaction is set in: R0 (gammaL = R0 / r0),
/// Y and nu of the bodies (gammaW, Tabor mu) and the contact's reduced radius
/// (the report's Tabor mu and Bradley force).
struct ReferenceScales {
  Real R0 = 1.0;
  Real youngsModulus = 1.0;
  Real poissonRatio = 0.0;
  Real reducedRadius = 1.0;
};

enum class Method { HalfSpacePoint, VolumePair };

/// Memory a run may take, and where that limit comes from (for messages).
struct MemoryBudget {
  double megabytes = std::numeric_limits<double>::infinity();
  std::string source;
};

struct InteractionSetup {
  std::shared_ptr<const PairPotential> potential;
  Real density = 1.0;  ///< reference particle density beta0 of every body
  Method method = Method::HalfSpacePoint;
  SurfaceInteractionOptions surfaceOptions;  ///< Method 3
  VolumeInteractionOptions volumeOptions;    ///< Method 1
  Real searchRadiusFactor = 2.0;             ///< graph search radius / cutoff (> 1)
  Real gammaL = 0.0, gammaW = 0.0;           ///< the deck's scaling parameters (doc/theory.md#normalisation)

  /// r_S0 of Lennard-Jones with this potential's r0, whatever the potential
  /// (a repulsive one has none): where u = 0 puts the undeformed surfaces.
  Real contactDistance() const;
  /// The interaction on `mesh` (its surfaces for Method 3, its cells for Method 1).
  std::shared_ptr<Interaction> create(const mesh::Mesh& mesh) const;
  /// gammaW and gammaL as continuation parameters of `interaction`, nominal at
  /// the deck's values: gammaW = Y / (beta0^2 r0^3 epsilon) at fixed r0 scales
  /// epsilon (the strength) by gammaW0 / gammaW; gammaL = R0 / r0 at fixed
  /// gammaW scales r0 (the length) by gammaL0 / gammaL with epsilon r0^3 fixed.
  std::vector<ScalarParameter> scalarParameters(std::shared_ptr<Interaction> interaction) const;
  /// Throws InputError if the method cannot integrate over `mesh`: Method 1 on a symmetric part
  /// (node sets "symmetry x|y|z", in plane strain "axis") needs the part x_i >= 0 with the set on
  /// x_i = 0 (it adds the mirror images), its pair list at the start within `memory`, and its
  /// contact cells within the quadrature tolerance.
  void checkMesh(const mesh::Mesh& mesh, Formulation formulation, const MemoryBudget& memory = {}) const;
};

/// The interaction a validated Interaction sublist describes. Throws
/// InputError for combinations the validators cannot reject (two
/// parameterisations at once, a taper in the repulsion, ...).
InteractionSetup fromParameters(const Teuchos::ParameterList& interaction, const ReferenceScales& scales,
                                Formulation formulation);

/// Lines for the run's log: the gammas, the physical scales, the potential's
/// surface properties with the cutoff, and the Lennard-Jones scales (Tabor mu,
/// Maugis-Dugdale lambda, Bradley's force).
std::vector<std::string> describe(const InteractionSetup& setup, const ReferenceScales& scales);

}  // namespace cgcm::interaction
