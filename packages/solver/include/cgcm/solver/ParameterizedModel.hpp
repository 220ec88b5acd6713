#pragma once
// What continuation needs of a model besides Thyra's ModelEvaluator: named
// scalar parameters in p(0), and hooks for a matrix graph that may have to
// grow along a path (interaction couplings appear as bodies approach).
#include <Thyra_StateFuncModelEvaluatorBase.hpp>
#include <Teuchos_RCP.hpp>

#include <string>
#include <vector>

#include "cgcm/assembly/TpetraTypes.hpp"

namespace NOX::Abstract {
class Vector;
}

namespace cgcm::solver {

using assembly::Vector;

class ParameterizedModel : public Thyra::StateFuncModelEvaluatorBase<Real> {
 public:
  /// Names of the entries of p(0), in order.
  virtual const Teuchos::Array<std::string>& parameterNames() const = 0;
  /// The values used when a caller passes no p(0); continuation passes its own.
  virtual std::vector<Real> parameters() const = 0;
  virtual void setParameter(int index, Real value) = 0;
  /// Index of a parameter in p(0); throws InputError listing the names.
  int parameterIndex(const std::string& name) const;

  /// True if the Jacobian's graph holds every coupling the state x needs, with a margin.
  virtual bool graphCovers(const Vector& x) { return true; }
  /// Grows the graph to cover x (`widen`: with a larger search radius than usual).
  virtual void growGraph(const Vector& x, bool widen) {}
  /// True if an evaluation since clearGraphOutdated() met entries outside the graph.
  virtual bool graphOutdated() const { return false; }
  virtual void clearGraphOutdated() {}

  /// Weights of the convergence test's residual 2-norm, sqrt(Σ w_i f_i²) (residualNorm), or null for
  /// the plain norm.
  const Teuchos::RCP<const NOX::Abstract::Vector>& residualWeights() const { return residualWeights_; }
  /// Sets them from a vector on the model's map (null: the plain norm).
  void setResidualWeights(const Teuchos::RCP<Vector>& weights);

 private:
  Teuchos::RCP<const NOX::Abstract::Vector> residualWeights_;
};

}  // namespace cgcm::solver
