#pragma once
// Isoparametric elements: parent-domain shape functions, their parent
// derivatives, and the element's volume quadrature rule.
//
// Every element type E offers
//   static constexpr CellType cellType;                               its row of core/CellType.hpp
//   static constexpr int numNodes, numQp, dim;
//   static void parentCoordinates(int a, Real (&xi)[dim]);          node a in the parent domain
//   static void shape(const Real (&xi)[dim], Real (&N)[numNodes], Real (&dN)[numNodes][dim]);
//   static void quadraturePoint(int q, Real (&xi)[dim], Real& weight);
//   static void shapeAtQp(int q, Real (&N)[numNodes], Real (&dN)[numNodes][dim], Real& weight);
// all KOKKOS_INLINE_FUNCTION.
//
// Node orderings (the usual Exodus / VTK ones):
//   Quad4  (ξ, η) ∈ [−1,1]²: 0 (−1,−1), 1 (1,−1), 2 (1,1), 3 (−1,1) — counter-clockwise.
//   Hex8   (ξ, η, ζ) ∈ [−1,1]³: bottom face 0-3 as Quad4 at ζ = −1 (counter-clockwise seen
//          from +ζ), top face 4-7 the same at ζ = +1.
//   Tet4   0 (0,0,0), 1 (1,0,0), 2 (0,1,0), 3 (0,0,1) — positive volume for the right-hand
//          ordering (x1−x0)·((x2−x0)×(x3−x0)) > 0.
#include <Kokkos_Macros.hpp>

#include "cgcm/core/CellType.hpp"
#include "cgcm/core/Types.hpp"

namespace cgcm::fem {

namespace detail {
/// 1/√3: abscissa of the two-point Gauss rule on [−1, 1].
constexpr Real gauss2 = 0.57735026918962576451;

/// shapeAtQp of every element E: its shape functions at quadrature point q.
template <class E>
struct ShapeAtQuadraturePoints {
  template <int NumNodes, int Dim>
  KOKKOS_INLINE_FUNCTION static void shapeAtQp(int q, Real (&N)[NumNodes], Real (&dN)[NumNodes][Dim],
                                               Real& weight) {
    Real xi[Dim];
    E::quadraturePoint(q, xi, weight);
    E::shape(xi, N, dN);
  }
};

/// The tensor-product two-point Gauss rule of Quad4 and Hex8, its points
/// ordered like the nodes (the q-th point nearest node q), weights 1.
template <class E>
struct GaussPointsAtNodes : ShapeAtQuadraturePoints<E> {
  template <int Dim>
  KOKKOS_INLINE_FUNCTION static void quadraturePoint(int q, Real (&xi)[Dim], Real& weight) {
    E::parentCoordinates(q, xi);
    for (int i = 0; i < Dim; ++i) xi[i] *= gauss2;
    weight = 1.0;
  }
};
}  // namespace detail

/// Bilinear quadrilateral, 2×2 Gauss quadrature.
struct Quad4 : detail::GaussPointsAtNodes<Quad4> {
  static constexpr CellType cellType = CellType::Quad4;
  static constexpr int numNodes = 4;
  static constexpr int numQp = 4;
  static constexpr int dim = 2;

  KOKKOS_INLINE_FUNCTION static void parentCoordinates(int a, Real (&xi)[dim]) {
    xi[0] = (a == 1 || a == 2) ? 1.0 : -1.0;
    xi[1] = (a >= 2) ? 1.0 : -1.0;
  }

  KOKKOS_INLINE_FUNCTION static void shape(const Real (&xi)[dim], Real (&N)[numNodes], Real (&dN)[numNodes][dim]) {
    for (int a = 0; a < numNodes; ++a) {
      Real p[dim];
      parentCoordinates(a, p);
      const Real s = 1.0 + p[0] * xi[0];
      const Real t = 1.0 + p[1] * xi[1];
      N[a] = 0.25 * s * t;
      dN[a][0] = 0.25 * p[0] * t;
      dN[a][1] = 0.25 * p[1] * s;
    }
  }
};

/// Trilinear hexahedron, 2×2×2 Gauss quadrature.
struct Hex8 : detail::GaussPointsAtNodes<Hex8> {
  static constexpr CellType cellType = CellType::Hex8;
  static constexpr int numNodes = 8;
  static constexpr int numQp = 8;
  static constexpr int dim = 3;

  KOKKOS_INLINE_FUNCTION static void parentCoordinates(int a, Real (&xi)[dim]) {
    const int b = a & 3;
    xi[0] = (b == 1 || b == 2) ? 1.0 : -1.0;
    xi[1] = (b >= 2) ? 1.0 : -1.0;
    xi[2] = (a >= 4) ? 1.0 : -1.0;
  }

  KOKKOS_INLINE_FUNCTION static void shape(const Real (&xi)[dim], Real (&N)[numNodes], Real (&dN)[numNodes][dim]) {
    for (int a = 0; a < numNodes; ++a) {
      Real p[dim];
      parentCoordinates(a, p);
      const Real s = 1.0 + p[0] * xi[0];
      const Real t = 1.0 + p[1] * xi[1];
      const Real u = 1.0 + p[2] * xi[2];
      N[a] = 0.125 * s * t * u;
      dN[a][0] = 0.125 * p[0] * t * u;
      dN[a][1] = 0.125 * p[1] * s * u;
      dN[a][2] = 0.125 * p[2] * s * t;
    }
  }
};

/// Linear tetrahedron, one-point (centroid) quadrature.
struct Tet4 : detail::ShapeAtQuadraturePoints<Tet4> {
  static constexpr CellType cellType = CellType::Tet4;
  static constexpr int numNodes = 4;
  static constexpr int numQp = 1;
  static constexpr int dim = 3;

  KOKKOS_INLINE_FUNCTION static void parentCoordinates(int a, Real (&xi)[dim]) {
    for (int i = 0; i < dim; ++i) xi[i] = (a == i + 1) ? 1.0 : 0.0;
  }

  KOKKOS_INLINE_FUNCTION static void shape(const Real (&xi)[dim], Real (&N)[numNodes], Real (&dN)[numNodes][dim]) {
    N[0] = 1.0 - xi[0] - xi[1] - xi[2];
    N[1] = xi[0];
    N[2] = xi[1];
    N[3] = xi[2];
    for (int i = 0; i < dim; ++i) {
      dN[0][i] = -1.0;
      for (int a = 1; a < numNodes; ++a) dN[a][i] = (a == i + 1) ? 1.0 : 0.0;
    }
  }

  /// The centroid, weight 1/6 (the parent volume).
  KOKKOS_INLINE_FUNCTION static void quadraturePoint(int /*q*/, Real (&xi)[dim], Real& weight) {
    for (int i = 0; i < dim; ++i) xi[i] = 0.25;
    weight = 1.0 / 6.0;
  }
};

}  // namespace cgcm::fem
