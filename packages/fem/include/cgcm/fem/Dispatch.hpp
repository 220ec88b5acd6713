#pragma once
// From the run-time pair (Formulation, CellType) to the compile-time kernels.
// The bulk assembly and the stresses of results.e go through here; a new
// element is its shape functions (Elements.hpp), its row of
// core/CellType.hpp and one entry of `Elements` below.
#include <string>
#include <type_traits>

#include "cgcm/core/CellType.hpp"
#include "cgcm/core/Formulation.hpp"
#include "cgcm/fem/Elements.hpp"
#include "cgcm/fem/SolidKernel.hpp"

namespace cgcm::fem {

template <class... E>
struct ElementList {};
/// Every element with shape functions: the cell types the kernels take.
using Elements = ElementList<Quad4, Hex8, Tet4, Quad8, Quad9, Tet10, Hex20, Hex27>;

namespace detail {
template <class E>
constexpr bool matchesItsRow() {
  return E::numNodes == cellTypeInfo(E::cellType).numNodes && E::dim == cellTypeInfo(E::cellType).dim;
}

// Calls visit(E{}) for the element E of `type`; false if no element has that type.
template <class Visit, class... E>
KOKKOS_INLINE_FUNCTION bool visitElement(CellType type, Visit&& visit, ElementList<E...>) {
  static_assert((matchesItsRow<E>() && ...), "an element's numNodes or dim differs from its CellType row");
  return ((type == E::cellType ? (visit(E{}), true) : false) || ...);
}
}  // namespace detail

/// Calls visit(E{}) with the element type E of `type`; false (nothing called)
/// if no element has shape functions for it.
template <class Visit>
KOKKOS_INLINE_FUNCTION bool withElement(CellType type, Visit&& visit) {
  return detail::visitElement(type, visit, Elements{});
}

/// Calls visit(K{}) with K = SolidKernel<formulation tag, element of `type`>;
/// false (nothing called) if the formulation does not take that cell type
/// (solidKernelTakes says which it takes).
template <class Visit>
bool withSolidKernel(Formulation formulation, CellType type, Visit&& visit) {
  bool called = false;
  withElement(type, [&](auto element) {
    using E = decltype(element);
    if constexpr (E::dim == 2) {
      if (formulation == Formulation::PlaneStrain) visit(SolidKernel<PlaneStrain, E>{}), called = true;
      if (formulation == Formulation::Axisymmetric) visit(SolidKernel<Axisymmetric, E>{}), called = true;
    } else {
      if (formulation == Formulation::ThreeD) visit(SolidKernel<ThreeD, E>{}), called = true;
    }
  });
  return called;
}

/// Whether withSolidKernel(formulation, type, ·) has a kernel.
inline bool solidKernelTakes(Formulation formulation, CellType type) {
  return withSolidKernel(formulation, type, [](auto) {});
}

/// The cell types a formulation takes, for messages: "QUAD4, QUAD8, QUAD9" or "HEX8, TETRA4, ...".
inline std::string cellTypesTakenBy(Formulation formulation) {
  std::string out;
  for (const CellTypeInfo& row : kCellTypes)
    if (solidKernelTakes(formulation, row.type)) out += (out.empty() ? "" : ", ") + std::string(row.name);
  return out;
}

}  // namespace cgcm::fem
