#pragma once
// What the solver tests' small models (ChainModel.hpp, TiltingBarModel.hpp)
// share: the state on an owned map, named scalar parameters in p(0), their
// Thyra spaces and nominal values, and a Jacobian on a fixed graph; a model
// gives its graph and evaluates f and W.
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Tpetra_CrsGraph.hpp>
#include <Tpetra_CrsMatrix.hpp>

#include <string>
#include <vector>

#include "cgcm/solver/ParameterizedModel.hpp"

namespace cgcm::test {

class SmallModel : public solver::ParameterizedModel {
 public:
  using MEB = Thyra::ModelEvaluatorBase;
  using Extract = Thyra::TpetraOperatorVectorExtraction<Real, LocalIndex, GlobalIndex, assembly::Node>;
  using Graph = Tpetra::CrsGraph<LocalIndex, GlobalIndex, assembly::Node>;

  // ParameterizedModel
  const Teuchos::Array<std::string>& parameterNames() const override { return *names_; }
  std::vector<Real> parameters() const override {
    std::vector<Real> p;
    for (int k = 0; k < int(names_->size()); ++k) p.push_back(Thyra::get_ele(*p_, k));
    return p;
  }
  void setParameter(int index, Real value) override { Thyra::set_ele(index, value, p_.ptr()); }

  // Thyra::ModelEvaluator
  Teuchos::RCP<const Thyra::VectorSpaceBase<Real>> get_x_space() const override { return space_; }
  Teuchos::RCP<const Thyra::VectorSpaceBase<Real>> get_f_space() const override { return space_; }
  Teuchos::RCP<const Thyra::VectorSpaceBase<Real>> get_p_space(int) const override { return pSpace_; }
  Teuchos::RCP<const Teuchos::Array<std::string>> get_p_names(int) const override { return names_; }
  MEB::InArgs<Real> getNominalValues() const override { return nominal_; }
  MEB::InArgs<Real> createInArgs() const override {
    MEB::InArgsSetup<Real> in;
    in.setModelEvalDescription(description_);
    in.set_Np(1);
    in.setSupports(MEB::IN_ARG_x);
    return in;
  }
  Teuchos::RCP<Thyra::LinearOpBase<Real>> create_W_op() const override {
    Teuchos::RCP<assembly::Operator> W = Teuchos::rcp(new assembly::CrsMatrix(graph_));
    return Thyra::tpetraLinearOp<Real, LocalIndex, GlobalIndex, assembly::Node>(space_, space_, W);
  }
  Teuchos::RCP<const Thyra::LinearOpWithSolveFactoryBase<Real>> get_W_factory() const override { return solver_; }

 protected:
  /// `owned`: the state's map; `names` and `values`: the parameters and their nominal values.
  SmallModel(std::string description, Teuchos::RCP<const assembly::Map> owned, const std::vector<std::string>& names,
             const std::vector<Real>& values, Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> solver)
      : owned_(std::move(owned)), description_(std::move(description)), solver_(std::move(solver)) {
    space_ = Thyra::createVectorSpace<Real>(owned_);
    pMap_ = Teuchos::rcp(new assembly::Map(names.size(), 0, owned_->getComm(), Tpetra::LocallyReplicated));
    pSpace_ = Thyra::createVectorSpace<Real>(pMap_);
    names_ = Teuchos::rcp(new Teuchos::Array<std::string>(names.begin(), names.end()));
    nominal_ = createInArgs();
    auto x0 = Thyra::createMember(space_);
    Thyra::assign(x0.ptr(), 0.0);
    nominal_.set_x(x0);
    p_ = Thyra::createMember(pSpace_);
    for (std::size_t k = 0; k < values.size(); ++k) Thyra::set_ele(Teuchos::Ordinal(k), values[k], p_.ptr());
    nominal_.set_p(0, p_);
  }

  /// The parameters of an evaluation (the nominal ones when it gives none).
  const Thyra::VectorBase<Real>& parametersOf(const MEB::InArgs<Real>& in) const {
    return in.get_p(0).is_null() ? *p_ : *in.get_p(0);
  }

  Teuchos::RCP<const assembly::Map> owned_;
  Teuchos::RCP<Graph> graph_;  ///< set by the model's constructor (filled)

 private:
  MEB::OutArgs<Real> createOutArgsImpl() const override {
    MEB::OutArgsSetup<Real> out;
    out.setModelEvalDescription(description_);
    out.set_Np_Ng(1, 0);
    out.setSupports(MEB::OUT_ARG_f);
    out.setSupports(MEB::OUT_ARG_W_op);
    return out;
  }

  std::string description_;
  Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> solver_;
  Teuchos::RCP<const assembly::Map> pMap_;
  Teuchos::RCP<const Thyra::VectorSpaceBase<Real>> space_, pSpace_;
  Teuchos::RCP<const Teuchos::Array<std::string>> names_;
  MEB::InArgs<Real> nominal_;
  Teuchos::RCP<Thyra::VectorBase<Real>> p_;
};

}  // namespace cgcm::test
