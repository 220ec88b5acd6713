#pragma once
// The measure of a mesh's cells as the isoparametric map of their nodes gives it
// (curved quadratic cells included), by each element's quadrature rule, and the
// smallest Jacobian determinant at the quadrature points and the nodes.
#include <algorithm>
#include <vector>

#include "cgcm/fem/Dispatch.hpp"
#include "cgcm/mesh/Mesh.hpp"

namespace cgcm::mesh::testing {

struct IsoparametricMeasure {
  std::vector<double> perBody;  ///< area (2D) or volume (3D) of each body's cells
  double smallestJacobian = 1e300;
};

inline double determinant(const double (&J)[3][3], int dim) {
  if (dim == 2) return J[0][0] * J[1][1] - J[0][1] * J[1][0];
  return J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
         J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
}

inline IsoparametricMeasure isoparametricMeasure(const Mesh& m) {
  IsoparametricMeasure out;
  out.perBody.assign(std::size_t(m.numBodies), 0.0);
  for (const auto& b : m.blocks) {
    const bool found = fem::withElement(b.type, [&](auto element) {
      using E = decltype(element);
      constexpr int d = E::dim;
      for (LocalIndex c = 0; c < b.numCells(); ++c) {
        const LocalIndex* nodes = &b.connectivity[std::size_t(c) * E::numNodes];
        // J = sum_a x_a (dN_a/dxi)^T at xi
        auto jacobian = [&](const Real (&xi)[d]) {
          Real N[E::numNodes], dN[E::numNodes][d];
          E::shape(xi, N, dN);
          double J[3][3] = {};
          for (int a = 0; a < E::numNodes; ++a)
            for (int i = 0; i < d; ++i)
              for (int j = 0; j < d; ++j) J[i][j] += m.coord(nodes[a], i) * dN[a][j];
          return determinant(J, d);
        };
        for (int q = 0; q < E::numQp; ++q) {
          Real xi[d], w;
          E::quadraturePoint(q, xi, w);
          const double detJ = jacobian(xi);
          out.perBody[std::size_t(b.body)] += w * detJ;
          out.smallestJacobian = std::min(out.smallestJacobian, detJ);
        }
        for (int a = 0; a < E::numNodes; ++a) {
          Real xi[d];
          E::parentCoordinates(a, xi);
          out.smallestJacobian = std::min(out.smallestJacobian, jacobian(xi));
        }
      }
    });
    if (!found) ADD_FAILURE() << "no shape functions for " << cellTypeName(b.type);
  }
  return out;
}

}  // namespace cgcm::mesh::testing
