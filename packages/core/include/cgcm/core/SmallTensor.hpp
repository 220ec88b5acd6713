#pragma once
// Fixed-size vectors and matrices for use inside Kokkos kernels: plain arrays,
// no allocation, everything inlined.
#include <Kokkos_Macros.hpp>
#include <cmath>

#include "cgcm/core/Types.hpp"

namespace cgcm {

template <int N>
struct Vec {
  Real v[N];
  KOKKOS_INLINE_FUNCTION Real& operator[](int i) { return v[i]; }
  KOKKOS_INLINE_FUNCTION const Real& operator[](int i) const { return v[i]; }
  KOKKOS_INLINE_FUNCTION static Vec zero() {
    Vec r;
    for (int i = 0; i < N; ++i) r.v[i] = 0.0;
    return r;
  }
};

template <int M, int N = M>
struct Mat {
  Real a[M][N];
  KOKKOS_INLINE_FUNCTION Real& operator()(int i, int j) { return a[i][j]; }
  KOKKOS_INLINE_FUNCTION const Real& operator()(int i, int j) const { return a[i][j]; }
  KOKKOS_INLINE_FUNCTION static Mat zero() {
    Mat r;
    for (int i = 0; i < M; ++i)
      for (int j = 0; j < N; ++j) r.a[i][j] = 0.0;
    return r;
  }
  KOKKOS_INLINE_FUNCTION static Mat identity() {
    static_assert(M == N, "identity of a non-square matrix");
    Mat r = zero();
    for (int i = 0; i < M; ++i) r.a[i][i] = 1.0;
    return r;
  }
};

using Vec2 = Vec<2>;
using Vec3 = Vec<3>;
using Mat2 = Mat<2>;
using Mat3 = Mat<3>;

template <int N>
KOKKOS_INLINE_FUNCTION Real dot(const Vec<N>& a, const Vec<N>& b) {
  Real s = 0.0;
  for (int i = 0; i < N; ++i) s += a[i] * b[i];
  return s;
}

template <int N>
KOKKOS_INLINE_FUNCTION Real norm(const Vec<N>& a) {
  return std::sqrt(dot(a, a));
}

template <int N>
KOKKOS_INLINE_FUNCTION Vec<N> operator+(const Vec<N>& a, const Vec<N>& b) {
  Vec<N> r;
  for (int i = 0; i < N; ++i) r[i] = a[i] + b[i];
  return r;
}

template <int N>
KOKKOS_INLINE_FUNCTION Vec<N> operator-(const Vec<N>& a, const Vec<N>& b) {
  Vec<N> r;
  for (int i = 0; i < N; ++i) r[i] = a[i] - b[i];
  return r;
}

template <int N>
KOKKOS_INLINE_FUNCTION Vec<N> operator*(Real s, const Vec<N>& a) {
  Vec<N> r;
  for (int i = 0; i < N; ++i) r[i] = s * a[i];
  return r;
}

KOKKOS_INLINE_FUNCTION Vec3 cross(const Vec3& a, const Vec3& b) {
  return Vec3{{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}};
}

template <int M, int K, int N>
KOKKOS_INLINE_FUNCTION Mat<M, N> operator*(const Mat<M, K>& A, const Mat<K, N>& B) {
  Mat<M, N> C;
  for (int i = 0; i < M; ++i)
    for (int j = 0; j < N; ++j) {
      Real s = 0.0;
      for (int k = 0; k < K; ++k) s += A.a[i][k] * B.a[k][j];
      C.a[i][j] = s;
    }
  return C;
}

template <int M, int N>
KOKKOS_INLINE_FUNCTION Vec<M> operator*(const Mat<M, N>& A, const Vec<N>& x) {
  Vec<M> y;
  for (int i = 0; i < M; ++i) {
    Real s = 0.0;
    for (int j = 0; j < N; ++j) s += A.a[i][j] * x[j];
    y[i] = s;
  }
  return y;
}

template <int M, int N>
KOKKOS_INLINE_FUNCTION Mat<N, M> transpose(const Mat<M, N>& A) {
  Mat<N, M> T;
  for (int i = 0; i < M; ++i)
    for (int j = 0; j < N; ++j) T.a[j][i] = A.a[i][j];
  return T;
}

template <int N>
KOKKOS_INLINE_FUNCTION Real trace(const Mat<N>& A) {
  Real s = 0.0;
  for (int i = 0; i < N; ++i) s += A.a[i][i];
  return s;
}

KOKKOS_INLINE_FUNCTION Real det(const Mat2& A) { return A.a[0][0] * A.a[1][1] - A.a[0][1] * A.a[1][0]; }

KOKKOS_INLINE_FUNCTION Real det(const Mat3& A) {
  return A.a[0][0] * (A.a[1][1] * A.a[2][2] - A.a[1][2] * A.a[2][1]) -
         A.a[0][1] * (A.a[1][0] * A.a[2][2] - A.a[1][2] * A.a[2][0]) +
         A.a[0][2] * (A.a[1][0] * A.a[2][1] - A.a[1][1] * A.a[2][0]);
}

/// Inverse given the determinant (the caller has checked it is non-zero).
KOKKOS_INLINE_FUNCTION Mat2 inverse(const Mat2& A, Real detA) {
  const Real s = 1.0 / detA;
  return Mat2{{{s * A.a[1][1], -s * A.a[0][1]}, {-s * A.a[1][0], s * A.a[0][0]}}};
}

KOKKOS_INLINE_FUNCTION Mat3 inverse(const Mat3& A, Real detA) {
  const Real s = 1.0 / detA;
  Mat3 B;
  B.a[0][0] = s * (A.a[1][1] * A.a[2][2] - A.a[1][2] * A.a[2][1]);
  B.a[0][1] = s * (A.a[0][2] * A.a[2][1] - A.a[0][1] * A.a[2][2]);
  B.a[0][2] = s * (A.a[0][1] * A.a[1][2] - A.a[0][2] * A.a[1][1]);
  B.a[1][0] = s * (A.a[1][2] * A.a[2][0] - A.a[1][0] * A.a[2][2]);
  B.a[1][1] = s * (A.a[0][0] * A.a[2][2] - A.a[0][2] * A.a[2][0]);
  B.a[1][2] = s * (A.a[0][2] * A.a[1][0] - A.a[0][0] * A.a[1][2]);
  B.a[2][0] = s * (A.a[1][0] * A.a[2][1] - A.a[1][1] * A.a[2][0]);
  B.a[2][1] = s * (A.a[0][1] * A.a[2][0] - A.a[0][0] * A.a[2][1]);
  B.a[2][2] = s * (A.a[0][0] * A.a[1][1] - A.a[0][1] * A.a[1][0]);
  return B;
}

}  // namespace cgcm
