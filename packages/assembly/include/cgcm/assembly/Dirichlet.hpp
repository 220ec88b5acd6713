#pragma once
// Prescribed displacements u_i = offset_i + scale_i * p, where p is the load
// parameter (the model parameter that load stepping and continuation drive).
// The residual row of a constrained dof becomes u_i - (offset_i + scale_i p)
// and its Jacobian row the unit row, so Newton enforces the value exactly.
#include <string>
#include <vector>

#include "cgcm/assembly/DofMap.hpp"

namespace cgcm::assembly {

class DirichletConditions {
 public:
  explicit DirichletConditions(Teuchos::RCP<const DofMap> dofs) : dofs_(std::move(dofs)) {}

  /// Constrains component `component` of every node in `nodes`. A dof
  /// constrained twice keeps the last condition.
  void add(const std::vector<LocalIndex>& nodes, int component, Real offset, Real scale);

  /// Overwrites the constrained rows of f with u_i - (offset_i + scale_i p).
  void applyToResidual(const Vector& u, Real p, Vector& f) const;
  /// Replaces the constrained rows of J by unit rows (collective).
  void applyToJacobian(Matrix& J) const;
  /// Sets the constrained entries of u to their prescribed values.
  void impose(Real p, Vector& u) const;
  /// Sets the constrained entries of v to zero.
  void zeroConstrained(Vector& v) const;
  /// df/dp: -scale_i on constrained rows, 0 elsewhere.
  void residualParameterDerivative(Vector& dfdp) const;

  std::size_t numConstrainedOwnedDofs() const { return lids_.size(); }

 private:
  Teuchos::RCP<const DofMap> dofs_;
  std::vector<LocalIndex> lids_;  ///< owned-map local ids, kept sorted and unique
  std::vector<Real> offset_, scale_;
};

}  // namespace cgcm::assembly
