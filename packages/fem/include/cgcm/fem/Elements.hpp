#pragma once
// Isoparametric elements: parent-domain shape functions, their parent
// derivatives, and the element's volume quadrature rule.
//
// Every element type E offers
//   static constexpr int numNodes, numQp, dim;
//   static constexpr int quadratureDegree;  the rule integrates exactly every polynomial of
//                                           degree <= it in each coordinate (cube) or of total
//                                           degree <= it (simplex) over the parent domain
//   static void parentCoordinates(int a, Real (&xi)[dim]);          node a in the parent domain
//   static void shape(const Real (&xi)[dim], Real (&N)[numNodes], Real (&dN)[numNodes][dim]);
//   static void quadraturePoint(int q, Real (&xi)[dim], Real& weight);
//   static void shapeAtQp(int q, Real (&N)[numNodes], Real (&dN)[numNodes][dim], Real& weight);
// all KOKKOS_INLINE_FUNCTION, and its row of core/CellType.hpp (with an entry in
// fem::Elements, Dispatch.hpp)
//   static constexpr CellType cellType;
//
// Node orderings (the Exodus II ones; the corners, nodes 0 .. 2^dim - 1 or 0 .. dim,
// are those of the linear element of the same shape):
//   Quad4  (ξ, η) ∈ [−1,1]²: 0 (−1,−1), 1 (1,−1), 2 (1,1), 3 (−1,1) — counter-clockwise.
//   Quad8  Quad4, then the mid-edge nodes 4 (0,−1), 5 (1,0), 6 (0,1), 7 (−1,0) of the
//          edges (0,1), (1,2), (2,3), (3,0). Serendipity.
//   Quad9  Quad8, then the centre 8 (0,0). Biquadratic Lagrange.
//   Hex8   (ξ, η, ζ) ∈ [−1,1]³: bottom face 0-3 as Quad4 at ζ = −1 (counter-clockwise seen
//          from +ζ), top face 4-7 the same at ζ = +1.
//   Hex20  Hex8, then the mid-edge nodes of the bottom edges 8 (0,1), 9 (1,2), 10 (2,3),
//          11 (3,0); of the vertical edges 12 (0,4), 13 (1,5), 14 (2,6), 15 (3,7); of the top
//          edges 16 (4,5), 17 (5,6), 18 (6,7), 19 (7,4). Serendipity.
//   Hex27  Hex20, then the volume centre 20 (0,0,0) and the face centres 21 (0,0,−1),
//          22 (0,0,1), 23 (−1,0,0), 24 (1,0,0), 25 (0,−1,0), 26 (0,1,0), i.e. the faces of
//          Exodus sides 5, 6, 4, 2, 1, 3 (SEACAS Ioss Hex27). Triquadratic Lagrange.
//          (VTK orders Hex20's and Hex27's higher nodes differently.)
//   Tet4   0 (0,0,0), 1 (1,0,0), 2 (0,1,0), 3 (0,0,1) — positive volume for the right-hand
//          ordering (x1−x0)·((x2−x0)×(x3−x0)) > 0.
//   Tet10  Tet4, then the mid-edge nodes 4 (0,1), 5 (1,2), 6 (0,2), 7 (0,3), 8 (1,3),
//          9 (2,3). Quadratic.
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

/// √(3/5): the outer abscissae of the three-point Gauss rule on [−1, 1] (weights 5/9, 8/9, 5/9).
constexpr Real gauss3 = 0.77459666924148337704;

/// The tensor-product three-point Gauss rule of the quadratic quadrilaterals and
/// hexahedra: point q = i + 3 j (+ 9 k) at abscissae (−√(3/5), 0, √(3/5))[i, j, k].
template <class E>
struct ThreePointGauss : ShapeAtQuadraturePoints<E> {
  template <int Dim>
  KOKKOS_INLINE_FUNCTION static void quadraturePoint(int q, Real (&xi)[Dim], Real& weight) {
    weight = 1.0;
    for (int i = 0; i < Dim; ++i, q /= 3) {
      const int k = q % 3;
      xi[i] = (k - 1) * gauss3;
      weight *= k == 1 ? 8.0 / 9.0 : 5.0 / 9.0;
    }
  }
};

/// The quadratic Lagrange polynomial on [−1, 1] that is 1 at the node p ∈ {−1, 0, 1}
/// and 0 at the other two, and its derivative, at t.
KOKKOS_INLINE_FUNCTION void lagrange2(Real p, Real t, Real& L, Real& dL) {
  if (p == 0.0) {
    L = 1.0 - t * t;
    dL = -2.0 * t;
  } else {
    L = 0.5 * t * (t + p);
    dL = t + 0.5 * p;
  }
}

/// Tensor-product (Lagrange) quadratic shape function of the node at p ∈ {−1, 0, 1}^Dim.
template <int Dim>
KOKKOS_INLINE_FUNCTION void lagrangeShape(const Real (&p)[Dim], const Real (&xi)[Dim], Real& N, Real (&dN)[Dim]) {
  Real L[Dim], dL[Dim];
  for (int i = 0; i < Dim; ++i) lagrange2(p[i], xi[i], L[i], dL[i]);
  N = 1.0;
  for (int i = 0; i < Dim; ++i) N *= L[i];
  for (int j = 0; j < Dim; ++j) {
    dN[j] = dL[j];
    for (int i = 0; i < Dim; ++i)
      if (i != j) dN[j] *= L[i];
  }
}

/// Quadratic serendipity shape function of the node at p: a corner (every p_i = ±1),
///   N = 2^−Dim Π (1 + p_i ξ_i) (Σ p_i ξ_i − (Dim − 1)),
/// or an edge midpoint (p_k = 0, the others ±1),
///   N = 2^(1−Dim) (1 − ξ_k²) Π_{i≠k} (1 + p_i ξ_i).
template <int Dim>
KOKKOS_INLINE_FUNCTION void serendipityShape(const Real (&p)[Dim], const Real (&xi)[Dim], Real& N,
                                             Real (&dN)[Dim]) {
  Real s[Dim];
  int k = -1;  // the axis along which the node sits mid-edge
  for (int i = 0; i < Dim; ++i) {
    s[i] = p[i] == 0.0 ? 1.0 - xi[i] * xi[i] : 1.0 + p[i] * xi[i];
    if (p[i] == 0.0) k = i;
  }
  Real prod = 1.0;
  for (int i = 0; i < Dim; ++i) prod *= s[i];
  // d prod / d ξ_j
  Real dprod[Dim];
  for (int j = 0; j < Dim; ++j) {
    dprod[j] = j == k ? -2.0 * xi[j] : p[j];
    for (int i = 0; i < Dim; ++i)
      if (i != j) dprod[j] *= s[i];
  }
  if (k >= 0) {
    const Real c = 2.0 / (1 << Dim);
    N = c * prod;
    for (int j = 0; j < Dim; ++j) dN[j] = c * dprod[j];
  } else {
    const Real c = 1.0 / (1 << Dim);
    Real t = -(Dim - 1.0);
    for (int i = 0; i < Dim; ++i) t += p[i] * xi[i];
    N = c * prod * t;
    for (int j = 0; j < Dim; ++j) dN[j] = c * (dprod[j] * t + prod * p[j]);
  }
}
}  // namespace detail

/// Bilinear quadrilateral, 2×2 Gauss quadrature.
struct Quad4 : detail::GaussPointsAtNodes<Quad4> {
  static constexpr CellType cellType = CellType::Quad4;
  static constexpr int numNodes = 4;
  static constexpr int numQp = 4;
  static constexpr int quadratureDegree = 3;
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
  static constexpr int quadratureDegree = 3;
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
  static constexpr int quadratureDegree = 1;
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

namespace detail {
/// Nodes of the quadratic quadrilaterals: Quad4's corners, the mid-edge nodes 4-7, the centre 8.
KOKKOS_INLINE_FUNCTION void quadraticQuadNode(int a, Real (&xi)[2]) {
  if (a < 4) {
    Quad4::parentCoordinates(a, xi);
  } else if (a < 8) {
    Real p[2], r[2];
    Quad4::parentCoordinates(a - 4, p);
    Quad4::parentCoordinates((a - 3) & 3, r);
    for (int i = 0; i < 2; ++i) xi[i] = 0.5 * (p[i] + r[i]);
  } else {
    xi[0] = xi[1] = 0.0;
  }
}

/// Nodes of the quadratic hexahedra: Hex8's corners, the mid-edge nodes 8-19, the centre 20,
/// the face centres 21-26.
KOKKOS_INLINE_FUNCTION void quadraticHexNode(int a, Real (&xi)[3]) {
  if (a < 8) {
    Hex8::parentCoordinates(a, xi);
  } else if (a < 20) {
    const int e = (a - 8) & 3;       // edge e of the bottom or top face, or vertical edge at corner e
    const int level = (a - 8) >> 2;  // 0 bottom, 1 vertical, 2 top
    Real p[2], r[2];
    Quad4::parentCoordinates(e, p);
    Quad4::parentCoordinates(level == 1 ? e : (e + 1) & 3, r);
    xi[0] = 0.5 * (p[0] + r[0]);
    xi[1] = 0.5 * (p[1] + r[1]);
    xi[2] = level - 1.0;
  } else {
    xi[0] = xi[1] = xi[2] = 0.0;
    if (a > 20) {
      const int f = a - 21;  // −ζ, +ζ, −ξ, +ξ, −η, +η
      xi[f < 2 ? 2 : f < 4 ? 0 : 1] = (f & 1) ? 1.0 : -1.0;
    }
  }
}
}  // namespace detail

namespace detail {
/// A quadratic tensor-product cell with 3-point Gauss per direction: its nodes from `node`
/// (quadraticQuadNode, quadraticHexNode), each node's shape function serendipity or Lagrange.
template <class E, CellType Type, int NumNodes, int Dim, bool Serendipity>
struct QuadraticTensorCell : ThreePointGauss<E> {
  static constexpr CellType cellType = Type;
  static constexpr int numNodes = NumNodes;
  static constexpr int numQp = Dim == 2 ? 9 : 27;
  static constexpr int quadratureDegree = 5;
  static constexpr int dim = Dim;

  KOKKOS_INLINE_FUNCTION static void parentCoordinates(int a, Real (&xi)[dim]) {
    if constexpr (Dim == 2)
      quadraticQuadNode(a, xi);
    else
      quadraticHexNode(a, xi);
  }

  KOKKOS_INLINE_FUNCTION static void shape(const Real (&xi)[dim], Real (&N)[numNodes], Real (&dN)[numNodes][dim]) {
    for (int a = 0; a < numNodes; ++a) {
      Real p[dim];
      parentCoordinates(a, p);
      if constexpr (Serendipity)
        serendipityShape(p, xi, N[a], dN[a]);
      else
        lagrangeShape(p, xi, N[a], dN[a]);
    }
  }
};
}  // namespace detail

/// Serendipity quadratic quadrilateral, 3×3 Gauss quadrature.
struct Quad8 : detail::QuadraticTensorCell<Quad8, CellType::Quad8, 8, 2, true> {};
/// Biquadratic (Lagrange) quadrilateral, 3×3 Gauss quadrature.
struct Quad9 : detail::QuadraticTensorCell<Quad9, CellType::Quad9, 9, 2, false> {};
/// Serendipity quadratic hexahedron, 3×3×3 Gauss quadrature.
struct Hex20 : detail::QuadraticTensorCell<Hex20, CellType::Hex20, 20, 3, true> {};
/// Triquadratic (Lagrange) hexahedron, 3×3×3 Gauss quadrature.
struct Hex27 : detail::QuadraticTensorCell<Hex27, CellType::Hex27, 27, 3, false> {};

/// Quadratic tetrahedron, four-point quadrature of degree 2.
struct Tet10 : detail::ShapeAtQuadraturePoints<Tet10> {
  static constexpr CellType cellType = CellType::Tet10;
  static constexpr int numNodes = 10;
  static constexpr int numQp = 4;
  static constexpr int quadratureDegree = 2;
  static constexpr int dim = 3;

  /// The corners of mid-edge node 4 + e.
  KOKKOS_INLINE_FUNCTION static void edge(int e, int& a, int& b) {
    constexpr int corners[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};
    a = corners[e][0];
    b = corners[e][1];
  }

  KOKKOS_INLINE_FUNCTION static void parentCoordinates(int a, Real (&xi)[dim]) {
    if (a < 4) {
      Tet4::parentCoordinates(a, xi);
      return;
    }
    int b, c;
    edge(a - 4, b, c);
    Real p[dim], r[dim];
    Tet4::parentCoordinates(b, p);
    Tet4::parentCoordinates(c, r);
    for (int i = 0; i < dim; ++i) xi[i] = 0.5 * (p[i] + r[i]);
  }

  /// In the barycentric coordinates λ = (1 − ξ − η − ζ, ξ, η, ζ): corner a λ_a (2 λ_a − 1),
  /// mid-edge (a, b) 4 λ_a λ_b.
  KOKKOS_INLINE_FUNCTION static void shape(const Real (&xi)[dim], Real (&N)[numNodes], Real (&dN)[numNodes][dim]) {
    const Real l[4] = {1.0 - xi[0] - xi[1] - xi[2], xi[0], xi[1], xi[2]};
    Real dl[4][dim];
    for (int i = 0; i < dim; ++i) {
      dl[0][i] = -1.0;
      for (int a = 1; a < 4; ++a) dl[a][i] = (a == i + 1) ? 1.0 : 0.0;
    }
    for (int a = 0; a < 4; ++a) {
      N[a] = l[a] * (2.0 * l[a] - 1.0);
      for (int i = 0; i < dim; ++i) dN[a][i] = (4.0 * l[a] - 1.0) * dl[a][i];
    }
    for (int e = 0; e < 6; ++e) {
      int a, b;
      edge(e, a, b);
      N[4 + e] = 4.0 * l[a] * l[b];
      for (int i = 0; i < dim; ++i) dN[4 + e][i] = 4.0 * (dl[a][i] * l[b] + l[a] * dl[b][i]);
    }
  }

  /// The symmetric four-point rule: barycentric coordinates (β, α, α, α) and their
  /// permutations, α = (5 − √5)/20, β = (5 + 3√5)/20, weights 1/24. Point 0 is nearest
  /// corner 0, point q nearest corner q.
  KOKKOS_INLINE_FUNCTION static void quadraturePoint(int q, Real (&xi)[dim], Real& weight) {
    constexpr Real alpha = 0.13819660112501051518;
    constexpr Real beta = 0.58541019662496845446;
    for (int i = 0; i < dim; ++i) xi[i] = (q == i + 1) ? beta : alpha;
    weight = 1.0 / 24.0;
  }
};

}  // namespace cgcm::fem
