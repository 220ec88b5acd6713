#pragma once
// The stability of an equilibrium from the spectrum of its tangent.
//
// The matrix: K_FF, the tangent df/dx on the free dofs (its Dirichlet unit
// rows and their columns left out). An equilibrium is stable under control of
// the continuation parameter when no eigenvalue of K_FF has a negative real
// part; a real eigenvalue crosses 0 exactly where det K_FF changes sign, at a
// fold or a branch point. Where K_FF is symmetric (the material, Method 1) it
// is the energy's Hessian. Method 3's tangent is not (its traction is not the
// gradient of an energy), and the eigenvalues are K_FF's own, not its
// symmetric part's: the symmetric part's eigenvalue crosses 0 away from the
// folds (doc/theory.md, "Stability from eigenvalues", has the measurement).
//
// What is computed, with one factorisation of K_FF (MUMPS):
// - symmetric: L D L^T; the number of negative eigenvalues exactly, from the
//   negative pivots (Sylvester's law of inertia), however many are asked for;
// - unsymmetric: LU; the negative real parts among the eigenvalues computed,
//   checked against the sign of det K_FF (the parity of the negative real eigenvalues);
// - the `count` eigenvalues nearest 0 and their eigenvectors: Anasazi's block
//   Krylov-Schur on K_FF^-1 (shift-invert at 0, the same factorisation); with
//   at most kDenseSize dofs, LAPACK's dense solvers instead (Krylov-Schur
//   needs a basis larger than such a problem).
#include <Teuchos_RCP.hpp>

#include <memory>
#include <vector>

#include "cgcm/solver/ParameterizedModel.hpp"

namespace cgcm::solver {

class MumpsFactorization;

struct Spectrum {
  std::vector<Real> eigenvalues;     ///< real parts of the eigenvalues of K_FF nearest 0, ascending (force / length)
  std::vector<Real> imaginaryParts;  ///< their imaginary parts (0: real)
  /// Their eigenvectors, on the model's map, 0 on the constrained dofs, each scaled to a largest entry of +1
  /// (the sign fixed so that results are reproducible).
  std::vector<Teuchos::RCP<Vector>> modes;
  /// The number of eigenvalues with a negative real part: exact for a symmetric K_FF (all of them, from the
  /// factorisation's inertia); otherwise those computed, plus one if the sign of det K_FF says that a
  /// negative real eigenvalue lies beyond them (`complete` false).
  int negative = 0;
  bool complete = true;
  bool symmetric = true;  ///< K_FF was symmetric (to kSymmetryTolerance of its largest entry)
  bool stable() const { return negative == 0; }
  /// The critical mode: the eigenvector (its real part) of the eigenvalue with the smallest real part computed.
  const Teuchos::RCP<Vector>& mode() const { return modes.front(); }
  /// The real part of the k-th eigenvalue by real part (k = 0, 1, ...) when the computed ones include it (the
  /// negative count places them in the whole spectrum), NaN otherwise.
  Real ordered(int k) const;
};

class TangentSpectrum {
 public:
  /// Problems with at most this many dofs are solved densely.
  static constexpr int kDenseSize = 200;
  /// K_FF counts as symmetric when no |K_ij - K_ji| exceeds this fraction of its largest entry.
  static constexpr Real kSymmetryTolerance = 1e-12;

  /// `count` >= 1 eigenvalues per state. `denseSize`: kDenseSize, or another bound (tests force either path).
  TangentSpectrum(Teuchos::RCP<ParameterizedModel> model, int count, int denseSize = kDenseSize);
  ~TangentSpectrum();

  /// The spectrum at the state (x, p): evaluates the tangent there. Throws
  /// NumericalError if the factorisation or the eigensolver fails. Collective.
  Spectrum compute(const Vector& x, const std::vector<Real>& p);

 private:
  Teuchos::RCP<ParameterizedModel> model_;
  int count_, denseSize_;
  std::unique_ptr<MumpsFactorization> mumps_;
};

}  // namespace cgcm::solver
