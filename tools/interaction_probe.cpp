// interaction_probe: the interaction forces of one state of a run, by every
// formulation, on the same configuration: Method 3 with either surface density,
// Method 1, and Method 1 on a body that is not stretched (the state's shape
// taken as the reference configuration, so that its particle density is beta0
// everywhere). The differences between them separate what each approximation
// of Method 3 contributes (doc/theory.md#surface-density):
//   Method 3 (current area) - Method 1 (unstretched)  the half-space approximation
//                                                     (shape only: both count beta0 per current measure)
//   Method 1 - Method 1 (unstretched)                 the density change of the stretched bodies
//
//   interaction_probe RUN_DIR [CSV]
//
// RUN_DIR: the output folder of a run (its parameters.xml and checkpoint.bin:
// the last accepted state). Prints the resultant on every body per formulation;
// CSV (optional): per node that any formulation loads, its body, whether it is
// on the surface, its reference and current coordinates and the force on it by
// each formulation. 2D and axisymmetric (forces per unit thickness, or totals
// over the ring), and 3D. One rank.
// Exit code 2: bad usage or input.
#include <Tpetra_Core.hpp>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "cgcm/app/Setup.hpp"
#include "cgcm/core/Error.hpp"
#include "cgcm/interaction/InteractionSetup.hpp"
#include "cgcm/io/Deck.hpp"
#include "cgcm/solver/Checkpoint.hpp"

namespace {

using cgcm::LocalIndex;
using cgcm::Real;
namespace ia = cgcm::interaction;

struct Variant {
  std::string name;
  std::vector<Real> force;  // on every node, dim per node (the force applied to the node's body)
  std::vector<std::array<Real, 3>> resultant;
};

// Forces applied to the nodes by `setup`'s interaction built on `shape` (a mesh whose reference
// coordinates may differ from `mesh`'s), evaluated at `coords`.
Variant evaluate(const std::string& name, const ia::InteractionSetup& setup, const cgcm::mesh::Mesh& shape,
                 const std::vector<Real>& coords) {
  Variant v{name, std::vector<Real>(coords.size(), 0.0), {}};
  const int dim = shape.dim;
  const auto interaction = setup.create(shape);
  if (auto* surface = dynamic_cast<ia::SurfaceInteraction*>(interaction.get())) {
    surface->updatePairs(coords);
    std::vector<ia::PairContribution> out;
    surface->evaluate(coords, out, false);
    for (const auto& c : out)  // f is the residual's share: the force applied is -f
      for (int a = 0; a < c.numRowNodes; ++a)
        for (int i = 0; i < dim; ++i) v.force[std::size_t(c.rowNodes[a]) * dim + i] -= c.f[dim * a + i];
    v.resultant = surface->summary().resultant;
  } else if (auto* volume = dynamic_cast<ia::VolumeInteraction*>(interaction.get())) {
    volume->updatePairs(coords.data());
    volume->evaluate(
        coords.data(),
        [&](const auto& c, long) {
          for (int a = 0; a < c.numRowNodes; ++a)
            for (int i = 0; i < dim; ++i) v.force[std::size_t(c.rowNodes[a]) * dim + i] -= c.f[dim * a + i];
        },
        false);
    v.resultant = volume->summary().resultant;
  }
  return v;
}

int run(const std::string& dir, const std::string& csv) {
  const std::string deckPath = dir + "/parameters.xml";
  auto deck = cgcm::io::readDeck(deckPath);
  cgcm::io::validateDeck(*deck, *cgcm::app::validParameters());
  cgcm::solver::ProblemSetup setup = cgcm::app::buildProblem(*deck);
  if (!setup.interaction) throw cgcm::InputError(deckPath + ": the bodies of this model do not interact");
  const cgcm::mesh::Mesh& mesh = *setup.model.mesh;
  const cgcm::solver::Checkpoint checkpoint = cgcm::solver::readCheckpoint(dir);
  const int dim = mesh.dim;
  const std::size_t numNodes = std::size_t(mesh.numNodes());
  if (checkpoint.u.size() != numNodes * std::size_t(dim))
    throw cgcm::InputError(dir + "/checkpoint.bin holds " + std::to_string(checkpoint.u.size()) +
                           " displacements; the deck's mesh has " + std::to_string(numNodes * dim) + " dofs");
  std::vector<Real> coords(mesh.coords);
  for (std::size_t n = 0; n < numNodes; ++n)
    for (int i = 0; i < dim; ++i)
      coords[n * dim + i] += checkpoint.u[std::size_t(mesh.globalNode(LocalIndex(n))) * dim + i];

  // the state's shape as a stress-free body: Method 1 on it has density beta0 in the current shape
  cgcm::mesh::Mesh shape = mesh;
  shape.coords = coords;

  ia::InteractionSetup current = *setup.interaction, reference = current, volume = current;
  current.method = reference.method = ia::Method::HalfSpacePoint;
  current.surfaceOptions.surfaceDensity = ia::SurfaceDensity::CurrentArea;
  reference.surfaceOptions.surfaceDensity = ia::SurfaceDensity::ReferenceArea;
  volume.method = ia::Method::VolumePair;
  volume.checkMesh(mesh, setup.formulation);
  std::vector<Variant> variants;
  variants.push_back(evaluate("method3_current_area", current, mesh, coords));
  variants.push_back(evaluate("method3_reference_area", reference, mesh, coords));
  variants.push_back(evaluate("method1", volume, mesh, coords));
  variants.push_back(evaluate("method1_unstretched", volume, shape, coords));
  // Method 1's own quadrature error on this state: twice the base order, up to the most the kernel holds
  ia::InteractionSetup fine = volume;
  fine.volumeOptions.quadratureOrder =
      std::min(2 * volume.volumeOptions.quadratureOrder, mesh.dim == 3 ? ia::kMaxVolumeOrder3D : ia::kMaxVolumeOrder2D);
  fine.volumeOptions.maxQuadratureOrder = 0;
  variants.push_back(evaluate("method1_fine_quadrature", fine, mesh, coords));

  const auto& last = checkpoint.curve.back();
  std::printf("state: step %d, u = %.10g, P = %.10g (load curve)\n", last.step, last.u, last.P);
  std::printf("%-24s", "resultant on body");
  for (int b = 0; b < mesh.numBodies; ++b) std::printf("  %10d x %8s y %8s%s", b, "", "", dim == 3 ? "        z" : "");
  std::printf("\n");
  for (const auto& v : variants) {
    std::printf("%-24s", v.name.c_str());
    for (const auto& r : v.resultant)
      for (int i = 0; i < dim; ++i) std::printf("  %+.10e", r[i]);
    std::printf("\n");
  }

  if (csv.empty()) return 0;
  std::ofstream out(csv);
  if (!out) throw cgcm::InputError("cannot write " + csv);
  out.precision(12);
  const char* axes[] = {"x", "y", "z"};
  out << "body,node,surface";
  for (int i = 0; i < dim; ++i) out << ",X" << axes[i];
  for (int i = 0; i < dim; ++i) out << ",x" << axes[i];
  for (const auto& v : variants)
    for (int i = 0; i < dim; ++i) out << "," << v.name << "_f" << axes[i];
  out << "\n";
  // every node some formulation puts a force on: Method 1's forces act on the nodes inside the bodies too
  std::vector<int> bodyOf(numNodes, -1);
  std::vector<char> onSurface(numNodes, 0);
  for (const auto& block : mesh.blocks)
    for (LocalIndex n : block.connectivity) bodyOf[n] = block.body;
  for (const auto& surface : mesh.surfaces)
    for (LocalIndex n : surface.facets) onSurface[n] = 1;
  for (std::size_t n = 0; n < numNodes; ++n) {
    bool loaded = false;
    for (const auto& v : variants)
      for (int i = 0; i < dim; ++i) loaded = loaded || v.force[n * dim + i] != 0.0;
    if (!loaded) continue;
    out << bodyOf[n] << "," << n << "," << int(onSurface[n]);
    for (int i = 0; i < dim; ++i) out << "," << mesh.coord(LocalIndex(n), i);
    for (int i = 0; i < dim; ++i) out << "," << coords[n * dim + i];
    for (const auto& v : variants)
      for (int i = 0; i < dim; ++i) out << "," << v.force[n * dim + i];
    out << "\n";
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  Tpetra::ScopeGuard scope(&argc, &argv);
  if (argc < 2 || argc > 3 || std::string(argv[1]).rfind("--", 0) == 0) {
    std::cerr << "usage: interaction_probe RUN_DIR [CSV]\n";
    return 2;
  }
  if (Tpetra::getDefaultComm()->getSize() != 1) {
    std::cerr << "interaction_probe: runs on one rank\n";
    return 2;
  }
  try {
    return run(argv[1], argc == 3 ? argv[2] : "");
  } catch (const cgcm::InputError& e) {
    std::cerr << "interaction_probe: error: " << e.what() << "\n";
    return 2;
  }
}
