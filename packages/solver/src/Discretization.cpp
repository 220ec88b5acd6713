// From rank 0 to the others: each rank's subdomain of the mesh. Rank 0 alone
// builds (meshes, reads) the whole mesh. Then each rank's discrete problem.
#include "cgcm/solver/Discretization.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <exception>
#include <stdexcept>
#include <string>

#include "cgcm/core/Error.hpp"
#include "cgcm/mesh/Subdomain.hpp"
#include "cgcm/solver/LinearSolver.hpp"

namespace cgcm::solver {

void runOnRoot(const Teuchos::Comm<int>& comm, const std::function<void()>& work) {
  enum Outcome : int { Done, BadInput, FailedEvaluation, OtherError };
  std::exception_ptr failure;
  int outcome = Done;
  std::string message;
  if (comm.getRank() == 0) try {
      work();
    } catch (const InputError& e) {
      failure = std::current_exception(), outcome = BadInput, message = e.what();
    } catch (const NumericalError& e) {
      failure = std::current_exception(), outcome = FailedEvaluation, message = e.what();
    } catch (const std::exception& e) {
      failure = std::current_exception(), outcome = OtherError, message = e.what();
    } catch (...) {
      failure = std::current_exception(), outcome = OtherError, message = "unknown error";
    }
  Teuchos::broadcast(comm, 0, &outcome);
  if (outcome == Done) return;
  int size = int(message.size());
  Teuchos::broadcast(comm, 0, &size);
  message.resize(std::size_t(size));
  Teuchos::broadcast(comm, 0, size, message.data());
  if (failure) std::rethrow_exception(failure);
  if (outcome == BadInput) throw InputError(message);
  if (outcome == FailedEvaluation) throw NumericalError(message);
  throw std::runtime_error(message);
}

namespace {

// Bytes between ranks, in pieces that an int counts.
constexpr long long kPiece = 1 << 30;

void sendBytes(const Teuchos::Comm<int>& comm, int to, const std::vector<char>& bytes) {
  const long long size = (long long)bytes.size();
  Teuchos::send(comm, 1, &size, to);
  for (long long at = 0; at < size; at += kPiece)
    Teuchos::send(comm, int(std::min(kPiece, size - at)), bytes.data() + at, to);
}

std::vector<char> receiveBytes(const Teuchos::Comm<int>& comm, int from) {
  long long size = 0;
  Teuchos::receive(comm, from, 1, &size);
  std::vector<char> bytes(static_cast<std::size_t>(size));
  for (long long at = 0; at < size; at += kPiece)
    Teuchos::receive(comm, from, int(std::min(kPiece, size - at)), bytes.data() + at);
  return bytes;
}

}  // namespace

void decodeOnEveryRank(const Teuchos::Comm<int>& comm, const std::function<void()>& decode) {
  std::string error;
  try {
    decode();
  } catch (const std::exception& e) {
    error = e.what();
  }
  int failed = 0;
  Teuchos::reduceAll(comm, Teuchos::REDUCE_MAX, int(!error.empty()), Teuchos::outArg(failed));
  if (failed)
    throw std::logic_error("rank " + std::to_string(comm.getRank()) + ": what rank 0 sent " +
                           (error.empty() ? "could not be read on another rank" : "could not be read: " + error));
}

void broadcastBytes(const Teuchos::Comm<int>& comm, std::vector<char>& bytes) {
  long long size = (long long)bytes.size();
  Teuchos::broadcast(comm, 0, &size);
  bytes.resize(std::size_t(size));
  for (long long at = 0; at < size; at += kPiece)
    Teuchos::broadcast(comm, 0, int(std::min(kPiece, size - at)), bytes.data() + at);
}

Distribution distribute(const Teuchos::RCP<const Teuchos::Comm<int>>& comm, const ProblemSetup& setup) {
  const int dim = formulationDim(setup.formulation);
  const int rank = comm->getRank(), p = comm->getSize();
  if (rank == 0 && !setup.model.mesh) throw std::logic_error("distribute: rank 0 needs the whole mesh");
  if (p == 1)
    return {setup.model.mesh, Teuchos::rcp(new assembly::DofMap(comm, *setup.model.mesh, dim, setup.partition))};
  std::shared_ptr<const mesh::Mesh> mine;
  if (setup.interaction && setup.interaction->method == interaction::Method::VolumePair) {
    // Method 1 pairs cells of the whole bodies: every rank holds the whole mesh.
    std::vector<char> bytes;
    runOnRoot(*comm, [&] { bytes = mesh::toBytes(*setup.model.mesh); });
    broadcastBytes(*comm, bytes);
    decodeOnEveryRank(*comm, [&] {
      mine = rank == 0 ? setup.model.mesh : std::make_shared<const mesh::Mesh>(mesh::meshFromBytes(bytes));
    });
    return {mine, Teuchos::rcp(new assembly::DofMap(comm, *mine, dim, setup.partition))};
  }
  // Rank 0 cuts the subdomains one at a time and sends each before the next (its memory: the whole mesh and
  // two subdomains); a failure to cut one stops every rank at once.
  std::vector<int> owners;
  std::vector<LocalIndex> probed;  // the contact probe reads its apexes on every rank
  runOnRoot(*comm, [&] {
    owners = assembly::partitionCells(*setup.model.mesh, setup.partition, p);
    if (setup.model.contact)
      for (const auto& name : {setup.model.contact->upperApex, setup.model.contact->lowerApex}) {
        const auto& nodes = setup.model.mesh->nodeSet(name);
        probed.insert(probed.end(), nodes.begin(), nodes.end());
      }
  });
  std::vector<char> bytes;
  for (int r = 1; r < p; ++r) {
    runOnRoot(*comm, [&] { bytes = mesh::toBytes(mesh::subdomain(*setup.model.mesh, owners, r, probed)); });
    if (rank == 0) sendBytes(*comm, r, bytes);
    if (rank == r) bytes = receiveBytes(*comm, 0);
  }
  if (rank == 0) std::vector<char>().swap(bytes);
  runOnRoot(*comm, [&] {
    mine = std::make_shared<const mesh::Mesh>(mesh::subdomain(*setup.model.mesh, owners, 0, probed));
  });
  decodeOnEveryRank(*comm, [&] {
    if (rank != 0) mine = std::make_shared<const mesh::Mesh>(mesh::meshFromBytes(bytes));
  });
  return {mine, Teuchos::rcp(new assembly::DofMap(comm, *mine, dim, assembly::CellPartition::Subdomain))};
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
  std::vector<ScalarParameter> parameters;
  if (setup.interaction) {
    const auto interaction = setup.interaction->create(*d.mesh);
    d.problem->setInteraction(interaction, setup.interaction->searchRadiusFactor);
    parameters = setup.interaction->scalarParameters(interaction);
  }
  d.dirichlet = std::make_shared<assembly::DirichletConditions>(d.dofs);
  for (const auto& c : setup.model.conditions)
    d.dirichlet->add(d.mesh->nodeSet(c.nodeSet), c.component, c.offset, c.scale);
  d.model = Teuchos::rcp(new ModelEvaluator(d.problem, d.dirichlet, std::move(linearSolver), std::move(parameters)));
  // A body stiffer than Material's has its residual measured in its own force unit.
  d.model->setResidualWeights(d.problem->residualWeights(setup.material.youngsModulus()));
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
                    buildLinearSolver(linearSolver, comm->getSize(), dist.dofs->dofsPerNode(), modes,
                                      !setup.interaction.has_value()));
}

}  // namespace cgcm::solver
