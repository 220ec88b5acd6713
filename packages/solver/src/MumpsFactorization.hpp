#pragma once
// One MUMPS instance (Debian's libmumps, double precision, MPI): a matrix
// handed over as distributed coordinates, factorised, and solved for
// right-hand sides on Tpetra maps (gathered on rank 0, solutions scattered
// back). The analysis (ordering, symbolic factorisation) is kept while the
// coordinates' pattern is unchanged; each new value set is factorised again.
//
// Used by the "MUMPS" linear solve strategy (MumpsSolver.hpp: general LU) and
// by the tangent's spectrum (TangentSpectrum.hpp: symmetric LDL^T, whose
// negative pivots count the negative eigenvalues).
#include <dmumps_c.h>

#include <vector>

#include "cgcm/assembly/TpetraTypes.hpp"

namespace cgcm::solver {

class MumpsFactorization {
 public:
  enum class Symmetry { General, Symmetric };
  /// `ordering`: MUMPS' ICNTL(7) (0 AMD, 4 PORD); `determinant`: compute the determinant's sign too.
  MumpsFactorization(Symmetry symmetry, int ordering, bool determinant = false)
      : symmetry_(symmetry), ordering_(ordering), determinant_(determinant) {}
  ~MumpsFactorization() { release(); }
  MumpsFactorization(const MumpsFactorization&) = delete;
  MumpsFactorization& operator=(const MumpsFactorization&) = delete;

  /// Factorises the n x n matrix whose entries this rank holds as 1-based
  /// coordinates (irn, jcn, val); an entry given twice, by any ranks, counts
  /// with the sum of its values. Symmetric: the lower triangle only (irn >=
  /// jcn). Right-hand sides live on `rangeMap`, solutions on `domainMap`,
  /// global index = base + coordinate - 1. Throws std::runtime_error naming
  /// the failed phase. Collective.
  void factorize(const Teuchos::RCP<const assembly::Map>& rangeMap, const Teuchos::RCP<const assembly::Map>& domainMap,
                 GlobalIndex n, GlobalIndex base, std::vector<int> irn, std::vector<int> jcn, std::vector<Real> val);

  /// x = A^-1 b. Collective.
  void solve(const assembly::MultiVector& b, assembly::MultiVector& x) const;

  /// Symmetric: the number of negative pivots of the last factorisation, which
  /// is the number of negative eigenvalues of the matrix (Sylvester's law of inertia).
  int negativePivots() const;
  /// With `determinant`: the sign of the last factorised matrix's determinant (+1, -1; 0 if singular).
  int determinantSign() const;

  Symmetry symmetry() const { return symmetry_; }

  GlobalIndex size() const { return n_; }

 private:
  void release();

  Symmetry symmetry_;
  int ordering_;
  bool determinant_;
  mutable DMUMPS_STRUC_C id_{};
  bool initialized_ = false;
  GlobalIndex n_ = 0;
  std::vector<int> irn_, jcn_;
  std::vector<Real> val_;
  Teuchos::RCP<const assembly::Map> rootMap_;
  Teuchos::RCP<const assembly::Import> gather_, scatter_;
};

}  // namespace cgcm::solver
