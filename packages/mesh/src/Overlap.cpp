#include "cgcm/mesh/Overlap.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "cgcm/mesh/Generators.hpp"

namespace cgcm::mesh {

namespace {

using Vec = std::array<Real, 3>;

Vec sub(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Real dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Real norm(const Vec& a) { return std::sqrt(dot(a, a)); }

struct Box {
  Vec lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  void add(const Vec& p) {
    for (int i = 0; i < 3; ++i) lo[i] = std::min(lo[i], p[i]), hi[i] = std::max(hi[i], p[i]);
  }
  bool overlaps(const Box& o) const {
    for (int i = 0; i < 3; ++i)
      if (lo[i] > o.hi[i] || o.lo[i] > hi[i]) return false;
    return true;
  }
};

// A shape to test: the nodes of a cell, or of a boundary facet, with its box and size. The tests
// take a quadratic cell or facet as the straight one of its corners.
struct Shape {
  int body;
  std::vector<Vec> points;
  int corners = 0;  ///< the first points: the facet's corners (facets)
  const std::vector<std::vector<int>>* facets = nullptr;  ///< cells: local facets, oriented outward
  int facetCorners = 0;  ///< cells: the corners of each facet (its first nodes)
  Box box;
  Real size = 0.0;  ///< longest extent of the box
};

// Uniform grid of buckets over a box; a shape is entered into every bucket its box touches.
class Buckets {
 public:
  Buckets(const Box& box, std::size_t count, int dim) : box_(box) {
    const int per = std::max(1, int(std::pow(double(count), 1.0 / dim)));
    for (int i = 0; i < 3; ++i) n_[i] = i < dim ? per : 1;
    cells_.resize(std::size_t(n_[0]) * n_[1] * n_[2]);
  }
  void insert(std::size_t item, const Box& b) {
    visitBuckets(b, [&](std::vector<std::size_t>& bucket) { bucket.push_back(item); });
  }
  template <class F>
  bool any(const Box& b, F&& f) {
    bool found = false;
    visitBuckets(b, [&](std::vector<std::size_t>& bucket) {
      for (std::size_t item : bucket)
        if (!found && f(item)) found = true;
    });
    return found;
  }

 private:
  template <class F>
  void visitBuckets(const Box& b, F&& f) {
    if (!b.overlaps(box_)) return;
    int lo[3], hi[3];
    for (int i = 0; i < 3; ++i) {
      const Real w = box_.hi[i] - box_.lo[i];
      auto index = [&](Real x) {
        return w > 0.0 ? std::clamp(int((x - box_.lo[i]) / w * n_[i]), 0, n_[i] - 1) : 0;
      };
      lo[i] = index(b.lo[i]), hi[i] = index(b.hi[i]);
    }
    for (int k = lo[2]; k <= hi[2]; ++k)
      for (int j = lo[1]; j <= hi[1]; ++j)
        for (int i = lo[0]; i <= hi[0]; ++i) f(cells_[(std::size_t(k) * n_[1] + j) * n_[0] + i]);
  }
  Box box_;
  int n_[3];
  std::vector<std::vector<std::size_t>> cells_;
};

// Triangles (3D) or segments (2D) of a polygon's fan, as point indices.
std::vector<std::array<int, 3>> fan(std::size_t n, int dim) {
  if (dim == 2) return {{0, 1, 1}};
  std::vector<std::array<int, 3>> t;
  for (std::size_t k = 1; k + 1 < n; ++k) t.push_back({0, int(k), int(k + 1)});
  return t;
}

// Outward normal of a facet piece (unnormalised): 2D segment a->b with the body on its left, 3D triangle.
Vec normal(const Vec& a, const Vec& b, const Vec& c, int dim) {
  const Vec t = sub(b, a);
  return dim == 2 ? Vec{t[1], -t[0], 0.0} : cross(t, sub(c, a));
}

// p strictly inside the convex cell (farther than `tol` inside every facet).
bool inside(const Shape& cell, const Vec& p, int dim, Real tol) {
  for (const auto& f : *cell.facets) {
    std::vector<Vec> pts;
    for (int a = 0; a < cell.facetCorners; ++a) pts.push_back(cell.points[f[a]]);
    for (const auto& t : fan(pts.size(), dim)) {
      const Vec n = normal(pts[t[0]], pts[t[1]], pts[t[2]], dim);
      if (dot(n, sub(p, pts[t[0]])) > -tol * norm(n)) return false;
    }
  }
  return true;
}

int sign(Real v, Real tol) { return v > tol ? 1 : (v < -tol ? -1 : 0); }

// Segment pq strictly through the facet piece (2D: segment ab; 3D: triangle abc).
bool crosses(const Vec& p, const Vec& q, const Vec& a, const Vec& b, const Vec& c, int dim, Real tol) {
  if (dim == 2) {
    auto orient = [](const Vec& o, const Vec& u, const Vec& v) { return cross(sub(u, o), sub(v, o))[2]; };
    const Real t2 = tol * tol;
    return sign(orient(a, b, p), t2) * sign(orient(a, b, q), t2) < 0 &&
           sign(orient(p, q, a), t2) * sign(orient(p, q, b), t2) < 0;
  }
  auto volume = [](const Vec& o, const Vec& u, const Vec& v, const Vec& w) {
    return dot(sub(u, o), cross(sub(v, o), sub(w, o)));
  };
  const Real t3 = tol * tol * tol;
  if (sign(volume(a, b, c, p), t3) * sign(volume(a, b, c, q), t3) >= 0) return false;
  const int s1 = sign(volume(p, q, a, b), t3), s2 = sign(volume(p, q, b, c), t3), s3 = sign(volume(p, q, c, a), t3);
  return s1 != 0 && s1 == s2 && s2 == s3;
}

std::string at(const Vec& p, int dim) {
  std::ostringstream o;
  o.precision(6);
  o << "(";
  for (int i = 0; i < dim; ++i) o << (i ? ", " : "") << p[i];
  o << ")";
  return o.str();
}

}  // namespace

std::string findBodyOverlap(const Mesh& mesh) {
  if (mesh.numBodies < 2) return "";
  const int dim = mesh.dim;
  auto point = [&](LocalIndex n) {
    Vec p{0.0, 0.0, 0.0};
    for (int i = 0; i < dim; ++i) p[i] = mesh.coord(n, i);
    return p;
  };
  auto shape = [&](int body, const LocalIndex* nodes, int count) {
    Shape s;
    s.body = body;
    for (int a = 0; a < count; ++a) s.points.push_back(point(nodes[a])), s.box.add(s.points.back());
    for (int i = 0; i < 3; ++i) s.size = std::max(s.size, s.box.hi[i] - s.box.lo[i]);
    return s;
  };
  std::vector<std::string> names(mesh.numBodies);
  std::vector<Shape> cells, facets;
  std::vector<Box> bodyBox(mesh.numBodies);
  std::vector<int> nodeBody(mesh.numNodes(), -1);
  for (const auto& b : mesh.blocks) {
    if (names[b.body].empty()) names[b.body] = b.name;
    const int npc = nodesPerCell(b.type);
    for (LocalIndex c = 0; c < b.numCells(); ++c)
      for (int a = 0; a < npc; ++a) {
        const LocalIndex n = b.connectivity[std::size_t(c) * npc + a];
        nodeBody[n] = b.body;
        bodyBox[b.body].add(point(n));
      }
  }
  // Only what lies in the box of another body can overlap it: most meshes (bodies apart, in
  // boxes that do not meet) are done here, the rest test that zone alone.
  auto inOtherBody = [&](const Box& box, int body) {
    for (int other = 0; other < mesh.numBodies; ++other)
      if (other != body && box.overlaps(bodyBox[other])) return true;
    return false;
  };
  bool anyZone = false;
  for (int k = 0; k < mesh.numBodies && !anyZone; ++k) anyZone = inOtherBody(bodyBox[k], k);
  if (!anyZone) return "";
  for (const auto& b : mesh.blocks) {
    const int npc = nodesPerCell(b.type);
    for (LocalIndex c = 0; c < b.numCells(); ++c) {
      Shape cell = shape(b.body, &b.connectivity[std::size_t(c) * npc], npc);
      if (!inOtherBody(cell.box, b.body)) continue;
      cell.facets = &localFacets(b.type);
      cell.facetCorners = facetCornerCount(cellTypeInfo(b.type));
      cells.push_back(std::move(cell));
    }
  }
  Mesh boundary = mesh;  // every exterior facet, not only the interacting ones
  buildSurfaces(boundary);
  for (const auto& s : boundary.surfaces)
    for (LocalIndex f = 0; f < s.numFacets(); ++f) {
      Shape facet = shape(s.body, &s.facets[std::size_t(f) * s.nodesPerFacet], s.nodesPerFacet);
      if (!inOtherBody(facet.box, s.body)) continue;
      facet.corners = facetCornerCount(rowWithFacets(dim, s.nodesPerFacet));
      facets.push_back(std::move(facet));
    }

  Box all;  // the zone where bodies' boxes meet
  for (const auto* shapes : {&cells, &facets})
    for (const Shape& sh : *shapes) all.add(sh.box.lo), all.add(sh.box.hi);
  Buckets cellGrid(all, cells.size(), dim), facetGrid(all, facets.size(), dim);
  for (std::size_t k = 0; k < cells.size(); ++k) cellGrid.insert(k, cells[k].box);
  for (std::size_t k = 0; k < facets.size(); ++k) facetGrid.insert(k, facets[k].box);
  auto body = [&](int b) { return "body \"" + names[b] + "\""; };
  const Real relTol = 1e-9;

  for (LocalIndex n = 0; n < mesh.numNodes(); ++n) {
    if (nodeBody[n] < 0) continue;
    Box box;
    box.add(point(n));
    if (!inOtherBody(box, nodeBody[n])) continue;
    std::string found;
    cellGrid.any(box, [&](std::size_t k) {
      const Shape& c = cells[k];
      if (c.body == nodeBody[n] || !inside(c, point(n), dim, relTol * c.size)) return false;
      found = "node " + std::to_string(n) + " of " + body(nodeBody[n]) + " at " + at(point(n), dim) +
              " lies inside a cell of " + body(c.body);
      return true;
    });
    if (!found.empty()) return found;
  }
  for (const auto& f : facets) {
    const std::size_t np = std::size_t(f.corners);
    for (std::size_t e = 0; e < (dim == 2 ? 1 : np); ++e) {
      const Vec& p = f.points[e];
      const Vec& q = f.points[(e + 1) % np];
      Box box;
      box.add(p), box.add(q);
      std::string found;
      facetGrid.any(box, [&](std::size_t k) {
        const Shape& g = facets[k];
        if (g.body == f.body) return false;
        for (const auto& t : fan(std::size_t(g.corners), dim))
          if (crosses(p, q, g.points[t[0]], g.points[t[1]], g.points[t[2]], dim, relTol * std::max(f.size, g.size))) {
            found = "the boundaries of " + body(f.body) + " and " + body(g.body) + " cross near " + at(p, dim);
            return true;
          }
        return false;
      });
      if (!found.empty()) return found;
    }
  }
  return "";
}

}  // namespace cgcm::mesh
