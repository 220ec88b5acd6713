#pragma once
// The stability of an equilibrium from the spectrum of its tangent.
//
// The matrix: S = (K + K^T)/2 on the free dofs, K = df/dx with its Dirichlet
// rows (unit rows) and their columns left out. Where K is symmetric (the
// material, Method 1) S is the energy's Hessian; Method 3's tangent is not
// quite symmetric (its traction is not the gradient of an energy), and S is
// the part that decides whether the energy of a small motion v, v.K v = v.S v,
// can decrease (doc/theory.md, "Stability from eigenvalues").
//
// What is computed, with one L D L^T factorisation of S (MUMPS):
// - the number of negative eigenvalues of S, exactly: the negative pivots of
//   L D L^T (Sylvester's law of inertia), however many eigenvalues are asked
//   for; a state is stable when there are none;
// - the `count` eigenvalues nearest 0 and their eigenvectors: Anasazi's block
//   Krylov-Schur on S^-1 (shift-invert at 0, the same factorisation); with at
//   most kDenseSize free dofs, LAPACK's dense symmetric solver instead
//   (Krylov-Schur needs a basis larger than such a problem).
#include <Teuchos_RCP.hpp>

#include <memory>
#include <vector>

#include "cgcm/solver/ParameterizedModel.hpp"

namespace cgcm::solver {

class MumpsFactorization;

struct Spectrum {
  std::vector<Real> eigenvalues;  ///< the eigenvalues of S nearest 0, ascending (force / length)
  /// Their eigenvectors, on the model's map, 0 on the constrained dofs, each scaled to a largest entry of +1
  /// (the sign fixed so that results are reproducible).
  std::vector<Teuchos::RCP<Vector>> modes;
  int negative = 0;  ///< the number of negative eigenvalues of S (all, not only the computed ones)
  bool stable() const { return negative == 0; }
  /// The critical mode: the eigenvector of the smallest eigenvalue computed.
  const Teuchos::RCP<Vector>& mode() const { return modes.front(); }
  /// The k-th smallest eigenvalue of S (k = 0, 1, ...) when the computed ones include it (the negative
  /// count places them in the whole spectrum), NaN otherwise.
  Real ordered(int k) const;
};

class TangentSpectrum {
 public:
  /// Problems with at most this many free dofs are solved densely.
  static constexpr int kDenseSize = 200;

  /// `count` >= 1 eigenvalues per state. `denseSize`: kDenseSize, or another bound (tests force either path).
  TangentSpectrum(Teuchos::RCP<ParameterizedModel> model, int count, int denseSize = kDenseSize);
  ~TangentSpectrum();

  int count() const { return count_; }

  /// The spectrum at the state (x, p): evaluates the tangent there. Throws
  /// NumericalError if the factorisation or the eigensolver fails. Collective.
  Spectrum compute(const Vector& x, const std::vector<Real>& p);

 private:
  Teuchos::RCP<ParameterizedModel> model_;
  int count_, denseSize_;
  Teuchos::RCP<Thyra::LinearOpBase<Real>> W_;
  std::unique_ptr<MumpsFactorization> mumps_;
};

}  // namespace cgcm::solver
