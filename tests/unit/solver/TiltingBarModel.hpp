#pragma once
// A model with a pitchfork known in closed form, for the branch-point tests:
// a rigid bar of half-length l whose centre hangs at height z from a spring
// (stiffness k) driven to height lambda, held level by a torsional spring
// (stiffness kt), whose two ends are attracted by a wall at height 0 through
// the Lennard-Jones potential of ChainModel.hpp.
//
// Unknowns (z, theta); energy k/2 (z - lambda)^2 + kt/2 theta^2 + phi(g+) + phi(g-),
// g+- = z +- l sin(theta). The level branch (theta = 0) has lambda = z + 2 phi'(z)/k.
// Its tilt stiffness is kt + 2 l^2 phi''(z): the branch point where
// phi''(z) = -kt / (2 l^2), before the level branch's fold (phi''(z) = -k/2)
// when kt / l^2 < k. The tilted branch: kt theta + l cos(theta) (phi'(g+) - phi'(g-)) = 0
// and lambda = z + (phi'(g+) + phi'(g-)) / k.
#include <Teuchos_CommHelpers.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>

#include <cmath>

#include "ChainModel.hpp"

namespace cgcm::test {

class TiltingBarModel : public SmallModel {
 public:
  TiltingBarModel(Teuchos::RCP<const assembly::Comm> comm, double k, double kt, double l, LennardJonesWall wall,
                  Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> solver)
      : SmallModel("tilting bar", Teuchos::rcp(new assembly::Map(2, 0, comm)), {"lambda"}, {0.0}, std::move(solver)),
        k_(k), kt_(kt), l_(l), wall_(wall) {
    everywhere_ = Teuchos::rcp(new assembly::Map(2, 0, comm, Tpetra::LocallyReplicated));
    import_ = Teuchos::rcp(new assembly::Import(owned_, everywhere_));
    graph_ = Teuchos::rcp(new Graph(owned_, 2));
    const GlobalIndex both[2] = {0, 1};
    for (std::size_t l = 0; l < owned_->getNodeNumElements(); ++l)
      graph_->insertGlobalIndices(owned_->getGlobalElement(LocalIndex(l)), 2, both);
    graph_->fillComplete();
  }

  /// lambda on the level branch at height z.
  double levelLambda(double z) const { return z + 2.0 * wall_.dphi(z) / k_; }
  /// The tilt equation at (z, theta): zero on the tilted branch.
  double tiltResidual(double z, double theta) const {
    const double d = l_ * std::sin(theta);
    return kt_ * theta + l_ * std::cos(theta) * (wall_.dphi(z + d) - wall_.dphi(z - d));
  }
  /// lambda of the equilibrium at (z, theta) (the vertical balance).
  double lambdaAt(double z, double theta) const {
    const double d = l_ * std::sin(theta);
    return z + (wall_.dphi(z + d) + wall_.dphi(z - d)) / k_;
  }
  /// The state (z, theta).
  Teuchos::RCP<assembly::Vector> stateOf(double z, double theta) const {
    auto x = Teuchos::rcp(new assembly::Vector(owned_));
    auto v = x->getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (std::size_t l = 0; l < owned_->getNodeNumElements(); ++l)
      v(l, 0) = owned_->getGlobalElement(LocalIndex(l)) == 0 ? z : theta;
    return x;
  }
  /// (z, theta) of a state, on every rank (collective).
  std::pair<double, double> unknowns(const assembly::Vector& x) const {
    assembly::Vector all(everywhere_);
    all.doImport(x, *import_, Tpetra::INSERT);
    auto v = all.getLocalViewHost(Tpetra::Access::ReadOnly);
    return {v(0, 0), v(1, 0)};
  }

 private:
  void evalModelImpl(const MEB::InArgs<Real>& in, const MEB::OutArgs<Real>& out) const override {
    const double lambda = Thyra::get_ele(parametersOf(in), 0);
    const auto [z, theta] = unknowns(*Extract::getConstTpetraVector(in.get_x()));
    const double s = std::sin(theta), c = std::cos(theta), d = l_ * s;
    const double dp = wall_.dphi(z + d), dm = wall_.dphi(z - d), ddp = wall_.ddphi(z + d), ddm = wall_.ddphi(z - d);
    const double f[2] = {k_ * (z - lambda) + dp + dm, kt_ * theta + l_ * c * (dp - dm)};
    const double J[2][2] = {{k_ + ddp + ddm, l_ * c * (ddp - ddm)},
                            {l_ * c * (ddp - ddm), kt_ - l_ * s * (dp - dm) + l_ * l_ * c * c * (ddp + ddm)}};
    if (!out.get_f().is_null()) {
      auto fv = Extract::getTpetraVector(out.get_f())->getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (std::size_t l = 0; l < owned_->getNodeNumElements(); ++l) fv(l, 0) = f[owned_->getGlobalElement(LocalIndex(l))];
    }
    if (!out.get_W_op().is_null()) {
      auto W = Teuchos::rcp_dynamic_cast<assembly::CrsMatrix>(Extract::getTpetraOperator(out.get_W_op()), true);
      W->resumeFill();
      const GlobalIndex both[2] = {0, 1};
      for (std::size_t l = 0; l < owned_->getNodeNumElements(); ++l) {
        const GlobalIndex i = owned_->getGlobalElement(LocalIndex(l));
        W->replaceGlobalValues(i, 2, J[i], both);
      }
      W->fillComplete();
    }
  }

  double k_, kt_, l_;
  LennardJonesWall wall_;
  Teuchos::RCP<const assembly::Map> everywhere_;
  Teuchos::RCP<const assembly::Import> import_;
};

}  // namespace cgcm::test
