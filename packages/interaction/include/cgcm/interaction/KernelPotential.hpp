#pragma once
// The pair potentials the interaction kernels are compiled for, as plain
// data (no virtual call per quadrature point; both methods' kernels are
// templates on the potential and dispatch once per evaluation).
//
// A kernel potential is a struct with
//   Real phi(Real r) const;                          the pair potential
//   RadialLaw pointLaw(Real s) const;                phi(sqrt s) and its s-derivatives (Method 1, 3D)
//   void halfSpace(Real r, Real& value, Real& dvalue) const;
//                                                    Phi(r)/beta, the half-space integral (Method 3)
//   Self scaled(Real strength, Real b) const;        strength * phi(r / b) / b^3 (Problem's load scaling)
// and optionally, in closed form,
//   RadialLaw lineLaw(Real s) const;                 plane strain (Method 1)
//   RingLaw ringLaw(Real p, Real q, bool withHessian) const;   axisymmetric (Method 1)
// (KernelLaws.hpp; without them the kernels integrate pointLaw).
//
// A new potential is its struct in a header of its own, one alternative in
// KernelPotential below and one entry in potentialRegistry()
// (PairPotential.cpp), which names it for decks.
#include <variant>

#include "cgcm/interaction/InversePowerPair.hpp"
#include "cgcm/interaction/MorsePair.hpp"

namespace cgcm::interaction {

using KernelPotential = std::variant<InversePowerPair, MorsePair>;

/// The same potential at strength * eps and length scale b.
inline KernelPotential scaled(const KernelPotential& potential, Real strength, Real b) {
  return std::visit([&](const auto& p) { return KernelPotential(p.scaled(strength, b)); }, potential);
}

}  // namespace cgcm::interaction
