#pragma once
// A model with folds known in closed form, for the continuation tests: a
// chain of n springs (stiffness k, rest length L) hanging from a support at
// height lambda + n L, whose tip is attracted by a wall at height 0 through
// the Lennard-Jones potential phi(g) = eps [(s/g)^12 - 2 (s/g)^6]. Its
// parameters: lambda and the wall's strength eps (p(0) = (lambda, eps)).
//
// Unknowns h_1..h_n (heights), energy sum_i k/2 (h_{i-1} - h_i - L)^2 + phi(h_n)
// with h_0 = lambda + n L. In equilibrium every spring carries the tension
// T = phi'(g) (g = h_n), so lambda = g + phi'(g)/K with K = k/n: the folds
// of lambda(g) are where phi''(g) = -K, and the Jacobian (tridiagonal) is
// positive definite exactly where dlambda/dg > 0 on the branch.
#include <Teuchos_CommHelpers.hpp>
#include <Thyra_TpetraThyraWrappers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>

#include <cmath>
#include <functional>
#include <vector>

#include "cgcm/core/Error.hpp"
#include "SmallModel.hpp"

namespace cgcm::test {

struct LennardJonesWall {
  double eps = 1.0, s = 1.0;
  double phi(double g) const { return eps * (std::pow(s / g, 12) - 2 * std::pow(s / g, 6)); }
  double dphi(double g) const { return eps * (-12 * std::pow(s / g, 12) + 12 * std::pow(s / g, 6)) / g; }
  double ddphi(double g) const { return eps * (156 * std::pow(s / g, 12) - 84 * std::pow(s / g, 6)) / (g * g); }
};

class ChainModel : public SmallModel {
 public:
  ChainModel(Teuchos::RCP<const assembly::Comm> comm, int n, double k, double L, LennardJonesWall wall,
             Teuchos::RCP<Thyra::LinearOpWithSolveFactoryBase<Real>> solver)
      : SmallModel("spring chain", Teuchos::rcp(new assembly::Map(n, 0, comm)), {"lambda", "eps"}, {0.0, wall.eps},
                   std::move(solver)),
        n_(n), k_(k), L_(L), wall_(wall) {
    std::vector<GlobalIndex> ghosted;
    for (std::size_t l = 0; l < owned_->getNodeNumElements(); ++l) ghosted.push_back(owned_->getGlobalElement(l));
    const GlobalIndex lo = owned_->getMinGlobalIndex(), hi = owned_->getMaxGlobalIndex();
    if (lo > 0) ghosted.push_back(lo - 1);
    if (hi < n - 1) ghosted.push_back(hi + 1);
    const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
    overlap_ = Teuchos::rcp(new assembly::Map(invalid, ghosted.data(), ghosted.size(), 0, comm));
    import_ = Teuchos::rcp(new assembly::Import(owned_, overlap_));
    graph_ = Teuchos::rcp(new Graph(owned_, 3));
    for (std::size_t l = 0; l < owned_->getNodeNumElements(); ++l) {
      const GlobalIndex i = owned_->getGlobalElement(l);
      std::vector<GlobalIndex> cols;
      for (GlobalIndex j = std::max<GlobalIndex>(0, i - 1); j <= std::min<GlobalIndex>(n - 1, i + 1); ++j)
        cols.push_back(j);
      graph_->insertGlobalIndices(i, cols.size(), cols.data());
    }
    graph_->fillComplete();
  }

  double K() const { return k_ / n_; }
  /// lambda of the equilibrium with tip gap g.
  double lambdaOf(double g) const { return g + wall_.dphi(g) / K(); }
  /// The equilibrium state with tip gap g.
  Teuchos::RCP<assembly::Vector> stateOf(double g) const {
    auto h = Teuchos::rcp(new assembly::Vector(owned_));
    const double T = wall_.dphi(g);
    auto v = h->getLocalViewHost(Tpetra::Access::OverwriteAll);
    for (std::size_t l = 0; l < owned_->getNodeNumElements(); ++l) {
      const GlobalIndex i = owned_->getGlobalElement(l);  // node i + 1, i.e. n - 1 - i springs below it
      v(l, 0) = g + double(n_ - 1 - i) * (L_ + T / k_);
    }
    return h;
  }
  /// Determinant of the Jacobian (tridiagonal, continuant recurrence) at tip gap g.
  double jacobianDeterminant(double g) const {
    double beforeLast = 0.0, last = 1.0;  // d_{i-2}, d_{i-1}
    for (int i = 0; i < n_; ++i) {
      const double diag = (i < n_ - 1) ? 2 * k_ : k_ + wall_.ddphi(g);
      const double d = diag * last - k_ * k_ * beforeLast;
      beforeLast = last;
      last = d;
    }
    return last;
  }
  /// Tip gap of a state (collective).
  double tipGap(const assembly::Vector& h) const {
    double local = 0.0, global = 0.0;
    auto v = h.getLocalViewHost(Tpetra::Access::ReadOnly);
    const LocalIndex l = owned_->getLocalElement(n_ - 1);
    if (l != Teuchos::OrdinalTraits<LocalIndex>::invalid()) local = v(l, 0);
    Teuchos::reduceAll(*owned_->getComm(), Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
    return global;
  }

  /// Called before every evaluation with lambda; may throw to simulate a failure.
  std::function<void(double)> beforeEvaluation;

 private:
  void evalModelImpl(const MEB::InArgs<Real>& in, const MEB::OutArgs<Real>& out) const override {
    const auto& p = parametersOf(in);
    const double lambda = Thyra::get_ele(p, 0);
    LennardJonesWall wall = wall_;
    wall.eps = Thyra::get_ele(p, 1);
    if (beforeEvaluation) beforeEvaluation(lambda);
    assembly::Vector h(overlap_);
    h.doImport(*Extract::getConstTpetraVector(in.get_x()), *import_, Tpetra::INSERT);
    auto hv = h.getLocalViewHost(Tpetra::Access::ReadOnly);
    auto at = [&](GlobalIndex i) { return i < 0 ? lambda + n_ * L_ : hv(overlap_->getLocalElement(i), 0); };
    // tension of the spring above node i (between i-1 and i; node -1 is the support)
    auto tension = [&](GlobalIndex i) { return k_ * (at(i - 1) - at(i) - L_); };
    if (!out.get_f().is_null()) {
      auto f = Extract::getTpetraVector(out.get_f());
      auto fv = f->getLocalViewHost(Tpetra::Access::OverwriteAll);
      for (std::size_t l = 0; l < owned_->getNodeNumElements(); ++l) {
        const GlobalIndex i = owned_->getGlobalElement(l);
        fv(l, 0) = -tension(i) + (i < n_ - 1 ? tension(i + 1) : wall.dphi(at(i)));
      }
    }
    if (!out.get_W_op().is_null()) {
      auto J = Teuchos::rcp_dynamic_cast<assembly::CrsMatrix>(Extract::getTpetraOperator(out.get_W_op()), true);
      J->resumeFill();
      for (std::size_t l = 0; l < owned_->getNodeNumElements(); ++l) {
        const GlobalIndex i = owned_->getGlobalElement(l);
        const double diag = i < n_ - 1 ? 2 * k_ : k_ + wall.ddphi(at(i));
        std::vector<GlobalIndex> cols{i};
        std::vector<double> vals{diag};
        if (i > 0) cols.push_back(i - 1), vals.push_back(-k_);
        if (i < n_ - 1) cols.push_back(i + 1), vals.push_back(-k_);
        J->replaceGlobalValues(i, cols.size(), vals.data(), cols.data());
      }
      J->fillComplete();
    }
  }

  int n_;
  double k_, L_;
  LennardJonesWall wall_;
  Teuchos::RCP<const assembly::Map> overlap_;
  Teuchos::RCP<const assembly::Import> import_;
};

}  // namespace cgcm::test
