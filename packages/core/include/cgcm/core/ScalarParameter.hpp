#pragma once
// A named scalar parameter of the residual besides the load: the solver
// continues in it (LOCA), the package that owns the physics says how a value
// reaches it.
#include <functional>
#include <string>

#include "cgcm/core/Types.hpp"

namespace cgcm {

/// Its name (the deck's: Loading/Continuation Parameter), its nominal value,
/// and how a value reaches the physics. `apply` must make the residual a
/// smooth function of the value; it throws NumericalError for values the
/// physics cannot take.
struct ScalarParameter {
  std::string name;
  Real nominal = 0.0;
  std::function<void(Real)> apply;
};

}  // namespace cgcm
