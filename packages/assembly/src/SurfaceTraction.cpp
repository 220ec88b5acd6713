#include "cgcm/assembly/SurfaceTraction.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "cgcm/interaction/Quadrature.hpp"

namespace cgcm::assembly {

namespace {

/// The traction t (3 per node) whose consistent node forces on the curved 3D facets of `surfaces` are
/// `force`: M t = force with the surface mass matrix M_ab = int N_a N_b da over those facets (current
/// coordinates x), by conjugate gradients with Jacobi preconditioning (M is symmetric positive definite).
/// Only the nodes of curved facets are written; returns whether any facet was curved.
bool projectOntoCurvedFacets(const std::vector<mesh::Surface>& surfaces, const std::vector<Real>& x,
                             const std::vector<Real>& force, std::vector<Real>& traction) {
  const std::size_t nn = x.size() / 3;
  std::vector<LocalIndex> local(nn, -1), nodes;
  std::vector<std::vector<std::pair<LocalIndex, Real>>> rows;
  auto index = [&](LocalIndex n) {
    if (local[std::size_t(n)] < 0) {
      local[std::size_t(n)] = LocalIndex(nodes.size());
      nodes.push_back(n);
      rows.emplace_back();
    }
    return local[std::size_t(n)];
  };
  for (const mesh::Surface& s : surfaces) {
    const int npf = s.nodesPerFacet;
    if (npf <= 4 || s.numFacets() == 0) continue;
    // N_a N_b da is of degree 4 in the parameters times the area element's: 4 points per direction
    const std::vector<interaction::FacetPoint> rule = interaction::facetQuadrature(npf, 4);
    for (LocalIndex f = 0; f < s.numFacets(); ++f) {
      const LocalIndex* n = &s.facets[std::size_t(f) * npf];
      LocalIndex id[9];
      for (int a = 0; a < npf; ++a) id[a] = index(n[a]);
      for (const interaction::FacetPoint& q : rule) {
        Real g[2][3] = {};
        for (int a = 0; a < npf; ++a)
          for (int d = 0; d < 2; ++d)
            for (int i = 0; i < 3; ++i) g[d][i] += q.dN[d][a] * x[3 * std::size_t(n[a]) + i];
        const Real m[3] = {g[0][1] * g[1][2] - g[0][2] * g[1][1], g[0][2] * g[1][0] - g[0][0] * g[1][2],
                           g[0][0] * g[1][1] - g[0][1] * g[1][0]};
        const Real da = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]) * q.weight;
        for (int a = 0; a < npf; ++a)
          for (int b = 0; b < npf; ++b) rows[std::size_t(id[a])].emplace_back(id[b], q.N[a] * q.N[b] * da);
      }
    }
  }
  if (nodes.empty()) return false;
  const std::size_t k = nodes.size();
  std::vector<Real> diagonal(k, 0.0);
  for (std::size_t r = 0; r < k; ++r) {  // merge each row's repeated columns
    auto& row = rows[r];
    std::sort(row.begin(), row.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    std::size_t w = 0;
    for (std::size_t i = 0; i < row.size(); ++i) {
      if (w > 0 && row[w - 1].first == row[i].first) row[w - 1].second += row[i].second;
      else row[w++] = row[i];
    }
    row.resize(w);
    for (const auto& [c, v] : row)
      if (std::size_t(c) == r) diagonal[r] = v;
  }
  auto multiply = [&](const std::vector<Real>& v, std::vector<Real>& out) {
    for (std::size_t r = 0; r < k; ++r) {
      Real sum = 0.0;
      for (const auto& [c, m] : rows[r]) sum += m * v[std::size_t(c)];
      out[r] = sum;
    }
  };
  auto dot = [&](const std::vector<Real>& a, const std::vector<Real>& b) {
    Real sum = 0.0;
    for (std::size_t r = 0; r < k; ++r) sum += a[r] * b[r];
    return sum;
  };
  std::vector<Real> t(k), res(k), z(k), p(k), Mp(k);
  for (int i = 0; i < 3; ++i) {
    for (std::size_t r = 0; r < k; ++r) res[r] = force[3 * std::size_t(nodes[r]) + i], t[r] = 0.0;
    const Real target = 1e-14 * std::sqrt(dot(res, res));
    for (std::size_t r = 0; r < k; ++r) p[r] = z[r] = res[r] / diagonal[r];
    Real rz = dot(res, z);
    for (std::size_t it = 0; it < 10 * k && std::sqrt(dot(res, res)) > target; ++it) {
      multiply(p, Mp);
      const Real alpha = rz / dot(p, Mp);
      for (std::size_t r = 0; r < k; ++r) t[r] += alpha * p[r], res[r] -= alpha * Mp[r];
      for (std::size_t r = 0; r < k; ++r) z[r] = res[r] / diagonal[r];
      const Real next = dot(res, z);
      for (std::size_t r = 0; r < k; ++r) p[r] = z[r] + (next / rz) * p[r];
      rz = next;
    }
    for (std::size_t r = 0; r < k; ++r) traction[3 * std::size_t(nodes[r]) + i] = t[r];
  }
  return true;
}

}  // namespace

SurfaceTractions surfaceTractions(const mesh::Mesh& mesh, Formulation formulation, const std::vector<Real>& u,
                                  const std::vector<Real>& force) {
  const int d = mesh.dim;
  const LocalIndex nn = mesh.numNodes();
  if (u.size() != mesh.coords.size() || force.size() != mesh.coords.size())
    throw std::logic_error("surfaceTractions: displacement and force need dim entries per node of the mesh");
  std::vector<Real> x(mesh.coords);
  for (std::size_t k = 0; k < x.size(); ++k) x[k] += u[k];
  SurfaceTractions out;
  auto& area = out.area;
  area.assign(std::size_t(nn), 0.0);
  std::vector<Real> normal(d * std::size_t(nn), 0.0);  // sum of the node's facets' area vectors
  const bool axisymmetric = formulation == Formulation::Axisymmetric;
  // 3D: a facet's area vector (sum of its corner triangles' for a quad), shared equally by its nodes
  auto addPolygon = [&](const LocalIndex* n, int count) {
    Real m[3] = {0.0, 0.0, 0.0};
    for (int a = 1; a + 1 < count; ++a) {
      const Real* x0 = &x[3 * std::size_t(n[0])];
      const Real* x1 = &x[3 * std::size_t(n[a])];
      const Real* x2 = &x[3 * std::size_t(n[a + 1])];
      const Real e1[3] = {x1[0] - x0[0], x1[1] - x0[1], x1[2] - x0[2]};
      const Real e2[3] = {x2[0] - x0[0], x2[1] - x0[1], x2[2] - x0[2]};
      m[0] += 0.5 * (e1[1] * e2[2] - e1[2] * e2[1]);
      m[1] += 0.5 * (e1[2] * e2[0] - e1[0] * e2[2]);
      m[2] += 0.5 * (e1[0] * e2[1] - e1[1] * e2[0]);
    }
    const Real A = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    for (int a = 0; a < count; ++a) {
      area[n[a]] += A / count;
      for (int i = 0; i < 3; ++i) normal[3 * std::size_t(n[a]) + i] += m[i];
    }
  };
  // The straight pieces of a quadratic 3D facet through its nodes (Exodus order: corners,
  // mid-edge nodes from edge 0-1 on, centre): Tri6 four triangles; Quad8 the four corner
  // triangles and the quadrilateral of the mid-edge nodes; Quad9 four quadrilaterals.
  const int tri6[4][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}};
  const int quad8[4][3] = {{0, 4, 7}, {4, 1, 5}, {5, 2, 6}, {6, 3, 7}};
  const int quad9[4][4] = {{0, 4, 8, 7}, {4, 1, 5, 8}, {8, 5, 2, 6}, {7, 8, 6, 3}};
  for (const mesh::Surface& s : mesh.surfaces) {
    const int npf = s.nodesPerFacet;
    if (s.numFacets() > 0 && (d == 2 ? npf != 2 && npf != 3 : npf != 3 && npf != 4 && npf != 6 && npf != 8 && npf != 9))
      throw std::logic_error("surfaceTractions: facets of " + std::to_string(npf) + " nodes in " + std::to_string(d) +
                             "D; the lumped areas are those of segments, triangles and quadrilaterals, linear or "
                             "quadratic");
    for (LocalIndex f = 0; f < s.numFacets(); ++f) {
      const LocalIndex* n = &s.facets[std::size_t(f) * npf];
      if (d == 2 && npf == 2) {
        const Real tx = x[2 * n[1]] - x[2 * n[0]], ty = x[2 * n[1] + 1] - x[2 * n[0] + 1];
        const Real length = std::hypot(tx, ty);
        // share of each node: integral of N_a (times 2 pi r in axisymmetry)
        const Real a0 = axisymmetric ? 2.0 * kPi * length * (2.0 * x[2 * n[0]] + x[2 * n[1]]) / 6.0 : 0.5 * length;
        const Real a1 = axisymmetric ? 2.0 * kPi * length * (x[2 * n[0]] + 2.0 * x[2 * n[1]]) / 6.0 : 0.5 * length;
        area[n[0]] += a0, area[n[1]] += a1;
        for (int a = 0; a < 2; ++a) normal[2 * n[a]] += ty, normal[2 * n[a] + 1] -= tx;  // outward, length-weighted
        continue;
      }
      if (d == 2) {
        // a quadratic edge (ends, then mid node): the integral of N_a (times 2 pi r) over the curved
        // edge, 3-point Gauss (exact on a straight edge in plane strain), so that the consistent node
        // forces of a uniform traction (1/6, 2/3, 1/6 of it) give that traction at every node
        const Real g = std::sqrt(0.6), tq[3] = {-g, 0.0, g}, wq[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
        for (int q = 0; q < 3; ++q) {
          const Real t = tq[q], N[3] = {0.5 * t * (t - 1.0), 0.5 * t * (t + 1.0), 1.0 - t * t},
                     dN[3] = {t - 0.5, t + 0.5, -2.0 * t};
          Real xq = 0.0, tx = 0.0, ty = 0.0;
          for (int a = 0; a < 3; ++a) {
            xq += N[a] * x[2 * n[a]];
            tx += dN[a] * x[2 * n[a]];
            ty += dN[a] * x[2 * n[a] + 1];
          }
          const Real w = wq[q] * (axisymmetric ? 2.0 * kPi * xq : 1.0);
          for (int a = 0; a < 3; ++a) {
            area[n[a]] += w * N[a] * std::hypot(tx, ty);
            normal[2 * n[a]] += wq[q] * N[a] * ty, normal[2 * n[a] + 1] -= wq[q] * N[a] * tx;
          }
        }
        continue;
      }
      auto piece = [&](const int* idx, int count) {
        LocalIndex sub[4];
        for (int k = 0; k < count; ++k) sub[k] = n[idx[k]];
        addPolygon(sub, count);
      };
      if (npf == 3 || npf == 4) {
        addPolygon(n, npf);
      } else if (npf == 6) {
        for (const auto& t : tri6) piece(t, 3);
      } else if (npf == 8) {
        for (const auto& t : quad8) piece(t, 3);
        addPolygon(n + 4, 4);
      } else {
        for (const auto& t : quad9) piece(t, 4);
      }
    }
  }
  out.traction.assign(d * std::size_t(nn), 0.0);
  out.pressure.assign(std::size_t(nn), 0.0);
  // curved 3D facets: the traction whose consistent forces are the node forces (their lumped areas
  // are not in proportion to those forces: a TRI6's corners carry none of a uniform traction)
  std::vector<Real> projected(d == 3 ? 3 * std::size_t(nn) : 0, 0.0);
  std::vector<char> onCurved(std::size_t(nn), 0);
  if (d == 3 && projectOntoCurvedFacets(mesh.surfaces, x, force, projected))
    for (const mesh::Surface& s : mesh.surfaces)
      if (s.nodesPerFacet > 4)
        for (LocalIndex n : s.facets) onCurved[std::size_t(n)] = 1;
  for (LocalIndex n = 0; n < nn; ++n) {
    if (!(area[n] > 0.0)) continue;
    Real tn = 0.0, len2 = 0.0;
    for (int i = 0; i < d; ++i) {
      const Real t = onCurved[std::size_t(n)] ? projected[3 * std::size_t(n) + i] : force[d * std::size_t(n) + i] / area[n];
      const Real m = normal[d * std::size_t(n) + i];
      out.traction[d * std::size_t(n) + i] = t;
      tn += t * m;
      len2 += m * m;
    }
    if (len2 > 0.0) out.pressure[n] = -tn / std::sqrt(len2);
  }
  return out;
}

}  // namespace cgcm::assembly
