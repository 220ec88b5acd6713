#include "cgcm/assembly/Dirichlet.hpp"

#include <algorithm>
#include <map>

namespace cgcm::assembly {

void DirichletConditions::add(const std::vector<LocalIndex>& nodes, int component, Real offset, Real scale) {
  std::map<LocalIndex, std::pair<Real, Real>> entries;
  for (std::size_t k = 0; k < lids_.size(); ++k) entries[lids_[k]] = {offset_[k], scale_[k]};
  const Map& owned = *dofs_->ownedMap();
  for (LocalIndex n : nodes) {
    if (!dofs_->ownsNode(n)) continue;
    entries[owned.getLocalElement(dofs_->dof(n, component))] = {offset, scale};
  }
  lids_.clear();
  offset_.clear();
  scale_.clear();
  for (const auto& [lid, v] : entries) {
    lids_.push_back(lid);
    offset_.push_back(v.first);
    scale_.push_back(v.second);
  }
}

void DirichletConditions::applyToResidual(const Vector& u, Real p, Vector& f) const {
  auto uv = u.getLocalViewHost(Tpetra::Access::ReadOnly);
  auto fv = f.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (std::size_t k = 0; k < lids_.size(); ++k) fv(lids_[k], 0) = uv(lids_[k], 0) - (offset_[k] + scale_[k] * p);
}

void DirichletConditions::impose(Real p, Vector& u) const {
  auto uv = u.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (std::size_t k = 0; k < lids_.size(); ++k) uv(lids_[k], 0) = offset_[k] + scale_[k] * p;
}

void DirichletConditions::zeroConstrained(Vector& v) const {
  auto vv = v.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (LocalIndex lid : lids_) vv(lid, 0) = 0.0;
}

void DirichletConditions::residualParameterDerivative(Vector& dfdp) const {
  dfdp.putScalar(0.0);
  auto v = dfdp.getLocalViewHost(Tpetra::Access::ReadWrite);
  for (std::size_t k = 0; k < lids_.size(); ++k) v(lids_[k], 0) = -scale_[k];
}

void DirichletConditions::applyToJacobian(Matrix& J) const {
  J.beginModify();
  {
    auto lcl = J.getLocalMatrixHost();
    const Map& rowMap = *J.getRowMap();
    const Map& colMap = *J.getColMap();
    for (LocalIndex lid : lids_) {
      const LocalIndex diag = colMap.getLocalElement(rowMap.getGlobalElement(lid));
      auto row = lcl.row(lid);
      for (LocalIndex j = 0; j < row.length; ++j) row.value(j) = (row.colidx(j) == diag) ? 1.0 : 0.0;
    }
  }
  J.endModify();
}

}  // namespace cgcm::assembly
