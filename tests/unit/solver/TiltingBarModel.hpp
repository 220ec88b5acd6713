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

class TiltingBarModel : public solver::ParameterizedModel {
 public:
  using MEB = Thyra::ModelEvaluatorBase;
  using Extract = Thyra::TpetraOperatorVectorExtraction<Real, LocalIndex, GlobalIndex, assembly::Node>;

  TiltingBarModel(Teuchos::RCP<const assembly::Comm> comm, double k, double kt, double l, LennardJonesWall wall,
                  Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> solver)
      : k_(k), kt_(kt), l_(l), wall_(wall), solver_(std::move(solver)) {
    owned_ = Teuchos::rcp(new assembly::Map(2, 0, comm));
    everywhere_ = Teuchos::rcp(new assembly::Map(2, 0, comm, Tpetra::LocallyReplicated));
    import_ = Teuchos::rcp(new assembly::Import(owned_, everywhere_));
    graph_ = Teuchos::rcp(new Tpetra::CrsGraph<LocalIndex, GlobalIndex, assembly::Node>(owned_, 2));
    const GlobalIndex both[2] = {0, 1};
    for (std::size_t l = 0; l < owned_->getNodeNumElements(); ++l)
      graph_->insertGlobalIndices(owned_->getGlobalElement(LocalIndex(l)), 2, both);
    graph_->fillComplete();
    space_ = Thyra::createVectorSpace<Real>(owned_);
    pMap_ = Teuchos::rcp(new assembly::Map(1, 0, comm, Tpetra::LocallyReplicated));
    pSpace_ = Thyra::createVectorSpace<Real>(pMap_);
    names_ = Teuchos::rcp(new Teuchos::Array<std::string>(1, "lambda"));
    nominal_ = createInArgs();
    auto x0 = Thyra::createMember(space_);
    Thyra::assign(x0.ptr(), 0.0);
    nominal_.set_x(x0);
    p_ = Thyra::createMember(pSpace_);
    Thyra::set_ele(0, 0.0, p_.ptr());
    nominal_.set_p(0, p_);
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

  // ParameterizedModel
  const Teuchos::Array<std::string>& parameterNames() const override { return *names_; }
  std::vector<Real> parameters() const override { return {Thyra::get_ele(*p_, 0)}; }
  void setParameter(int index, Real value) override { Thyra::set_ele(index, value, p_.ptr()); }

  // Thyra::ModelEvaluator
  Teuchos::RCP<const Thyra::VectorSpaceBase<Real>> get_x_space() const override { return space_; }
  Teuchos::RCP<const Thyra::VectorSpaceBase<Real>> get_f_space() const override { return space_; }
  Teuchos::RCP<const Thyra::VectorSpaceBase<Real>> get_p_space(int) const override { return pSpace_; }
  Teuchos::RCP<const Teuchos::Array<std::string>> get_p_names(int) const override { return names_; }
  MEB::InArgs<Real> getNominalValues() const override { return nominal_; }
  MEB::InArgs<Real> createInArgs() const override {
    MEB::InArgsSetup<Real> in;
    in.setModelEvalDescription("tilting bar");
    in.set_Np(1);
    in.setSupports(MEB::IN_ARG_x);
    return in;
  }
  Teuchos::RCP<Thyra::LinearOpBase<Real>> create_W_op() const override {
    Teuchos::RCP<assembly::Operator> W = Teuchos::rcp(new assembly::CrsMatrix(graph_));
    return Thyra::tpetraLinearOp<Real, LocalIndex, GlobalIndex, assembly::Node>(space_, space_, W);
  }
  Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<Real>> get_W_factory() const override { return solver_; }

 private:
  MEB::OutArgs<Real> createOutArgsImpl() const override {
    MEB::OutArgsSetup<Real> out;
    out.setModelEvalDescription("tilting bar");
    out.set_Np_Ng(1, 0);
    out.setSupports(MEB::OUT_ARG_f);
    out.setSupports(MEB::OUT_ARG_W_op);
    return out;
  }

  void evalModelImpl(const MEB::InArgs<Real>& in, const MEB::OutArgs<Real>& out) const override {
    const double lambda = Thyra::get_ele(in.get_p(0).is_null() ? *p_ : *in.get_p(0), 0);
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
  Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> solver_;
  Teuchos::RCP<const assembly::Map> owned_, everywhere_, pMap_;
  Teuchos::RCP<const assembly::Import> import_;
  Teuchos::RCP<Tpetra::CrsGraph<LocalIndex, GlobalIndex, assembly::Node>> graph_;
  Teuchos::RCP<const Thyra::VectorSpaceBase<Real>> space_, pSpace_;
  Teuchos::RCP<const Teuchos::Array<std::string>> names_;
  MEB::InArgs<Real> nominal_;
  Teuchos::RCP<Thyra::VectorBase<Real>> p_;
};

}  // namespace cgcm::test
