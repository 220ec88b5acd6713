#include "cgcm/analytic/LennardJonesSphere.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <Teuchos_LAPACK.hpp>

#include "Numerics.hpp"
#include "cgcm/core/Error.hpp"

namespace cgcm::analytic {
namespace {


// Band of uniform rings around the edge e (the outermost peak of the
// tension), in units of ℓ: [e − ahead, e + outside] while the edge retracts,
// [e − behind, e + ahead + behind] while it grows (adhesion-scale
// continuation), [e − ahead, e + ahead] for the refinement of the minimum.
// The gap rises from z0 to 2 z0 within a fraction of ℓ outside a JKR edge,
// and the JKR pressure singularity is smoothed over a similar width inside.
constexpr Real kBandBehind = 1.5;
constexpr Real kBandAhead = 3.0;
constexpr Real kBandOutside = 2.0;
// The rings are rebuilt when the edge comes this close (in ℓ) to a band end.
constexpr Real kBandMarginInside = 1.0;
constexpr Real kBandMarginOutside = 1.5;
// Far radius in √(R z0): the rigid tail of the load beyond ρF is
// (32/3) ρF⁻⁴, 1e-7 at ρF = 100.
constexpr Real kFarRadiusMin = 100;
// Largest accepted move of the contact edge per step, in ℓ (a larger one means
// the Newton iteration has left the branch, or the step is too coarse to
// follow it), and largest change of P/(π w R).
constexpr Real kMaxEdgeMove = 1.0;
constexpr Real kMaxLoadChange = 0.05;
// Separation: no compressive zone and the axis gap above 3 z0.
constexpr Real kSeparatedGap = 3;
// Adhesion-scale continuation at the start.
constexpr Real kScaleStart = 0.02;
constexpr Real kScaleMin = 1e-4;

Real sigmaPrime(Real h) {
  const Real i = 1 / h;
  const Real i2 = i * i;
  const Real i4 = i2 * i2;
  return (8.0 / 3.0) * (3 * i4 - 9 * i4 * i4 * i2);
}

struct Mesh {
  std::vector<Real> edges;  // N + 1, from 0 to ρF
  std::vector<Real> mid;    // N midpoints
  std::vector<Real> area;   // ρ_{j+1}² − ρ_j²
  Real bandLo = 0, bandHi = 0;
};

/// N rings from 0 to ρF equidistributed with the density 1/(ℓ + dist(ρ,
/// [b1, b2])): uniform in the band, growing linearly with the distance from
/// it. The cumulative density has a closed-form inverse. Only the shape of
/// the density matters (N fixes its scale): a larger band share, tried as
/// 1/(ℓ + γ dist) with γ up to 4, made P_min less accurate at a given N,
/// which is limited by the rings inside the contact and outside.
Mesh buildMesh(int n, Real ell, Real b1, Real b2, Real rhoFar) {
  const Real g1 = std::log1p(b1 / ell);
  const Real g2 = g1 + (b2 - b1) / ell;
  const Real total = g2 + std::log1p((rhoFar - b2) / ell);
  Mesh m;
  m.bandLo = b1;
  m.bandHi = b2;
  m.edges.resize(n + 1);
  for (int k = 0; k <= n; ++k) {
    const Real t = total * k / n;
    Real r;
    if (t <= g1) {
      r = b1 - ell * std::expm1(g1 - t);
    } else if (t <= g2) {
      r = b1 + ell * (t - g1);
    } else {
      r = b2 + ell * std::expm1(t - g2);
    }
    m.edges[k] = r;
  }
  m.edges[0] = 0;
  m.edges[n] = rhoFar;
  m.mid.resize(n);
  m.area.resize(n);
  for (int j = 0; j < n; ++j) {
    m.mid[j] = 0.5 * (m.edges[j] + m.edges[j + 1]);
    m.area[j] = (m.edges[j + 1] - m.edges[j]) * (m.edges[j + 1] + m.edges[j]);
  }
  return m;
}

/// C_ij = μ^(3/2) [D(r_i, s_j+1) − D(r_i, s_j)], row-major.
std::vector<Real> influenceMatrix(const Mesh& m, Real coupling) {
  const int n = static_cast<int>(m.mid.size());
  std::vector<Real> c(static_cast<std::size_t>(n) * n);
  std::vector<Real> d(n + 1);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j <= n; ++j) d[j] = diskDisplacement(m.mid[i], m.edges[j]);
    Real* row = &c[static_cast<std::size_t>(i) * n];
    for (int j = 0; j < n; ++j) row[j] = coupling * (d[j + 1] - d[j]);
  }
  return c;
}

/// LU factorisation with partial pivoting (LAPACK getrf) of the row-major
/// n×n matrix A in place. LAPACK sees the column-major Aᵀ, so luSolve solves
/// with the transpose. False if the matrix is singular or a pivot is not finite.
bool luFactor(std::vector<Real>& a, std::vector<int>& piv, int n) {
  piv.resize(n);
  int info = 0;
  Teuchos::LAPACK<int, Real>().GETRF(n, n, a.data(), n, piv.data(), &info);
  if (info != 0) return false;
  for (int k = 0; k < n; ++k)
    if (!std::isfinite(a[static_cast<std::size_t>(k) * n + k])) return false;
  return true;
}

/// Solves A x = b with the factors of luFactor; b is overwritten by x.
void luSolve(const std::vector<Real>& a, const std::vector<int>& piv, std::vector<Real>& b, int n) {
  int info = 0;
  Teuchos::LAPACK<int, Real>().GETRS('T', n, 1, a.data(), n, piv.data(), b.data(), n, &info);
}

/// The discrete problem on one set of rings.
class RingSystem {
 public:
  RingSystem(Mesh mesh, Real coupling)
      : mesh_(std::move(mesh)), c_(influenceMatrix(mesh_, coupling)) {}

  const Mesh& mesh() const { return mesh_; }
  int size() const { return static_cast<int>(mesh_.mid.size()); }

  /// The parameter along which solve's tangent is taken.
  enum class Along { Approach, Scale };

  /// Damped Newton for the gaps H at approach Δ and adhesion scale s,
  /// starting from H; at most maxIterations factorisations of the Jacobian.
  /// On failure H is unspecified and false is returned. If `tangent` is
  /// given, it receives the derivative of H along Δ (dH/dΔ = −J⁻¹ 1) or s
  /// (dH/ds = J⁻¹ C σ̂(H)) at the solution, from the factors of the last
  /// iteration: the predictor of the next step.
  bool solve(std::vector<Real>& h, Real delta, Real scale, int maxIterations, long& count,
             std::vector<Real>* tangent = nullptr, Along along = Along::Approach) const {
    const int n = size();
    std::vector<Real> sig(n), res(n), disp(n);
    const Real tol = 1e-10 * std::fmax(1, std::fabs(delta));
    Real best = HUGE_VAL, last = HUGE_VAL;
    int stalled = 0, factorisations = 0;
    bool factored = false;
    // The Jacobian is refactored only when the residual has dropped by less
    // than this factor since the last iteration; otherwise the old factors
    // are reused (a chord step: O(N²) instead of O(N³)).
    constexpr Real kReuse = 0.25;
    for (int it = 0; it <= 4 * maxIterations; ++it) {
      for (int j = 0; j < n; ++j) sig[j] = scale * ljTraction(h[j]);
      Real norm = 0;
      for (int i = 0; i < n; ++i) {
        const Real* ci = &c_[static_cast<std::size_t>(i) * n];
        Real u = 0;
        for (int j = 0; j < n; ++j) u += ci[j] * sig[j];
        const Real r = mesh_.mid[i];
        disp[i] = u;
        res[i] = h[i] - (1 - delta + 0.5 * r * r + u);
        norm = std::fmax(norm, std::fabs(res[i]));
      }
      if (!std::isfinite(norm)) return false;
      if (norm <= tol) {
        if (tangent) {
          if (!factored && !factor(h, scale, count)) return false;
          if (along == Along::Approach) {
            tangent->assign(n, -1.0);
          } else {
            tangent->resize(n);
            for (int i = 0; i < n; ++i) (*tangent)[i] = disp[i] / scale;
          }
          luSolve(jac_, piv_, *tangent, n);
        }
        return true;
      }
      // A Newton iteration that does not improve on its best residual for
      // several steps has left the basin (beyond a fold): give up early.
      if (norm < best) {
        best = norm;
        stalled = 0;
      } else if (++stalled >= 6) {
        return false;
      }
      if (!factored || norm > kReuse * last) {
        if (factorisations == maxIterations) return false;
        ++factorisations;
        if (!factor(h, scale, count)) return false;
        factored = true;
      }
      last = norm;
      for (int i = 0; i < n; ++i) res[i] = -res[i];
      luSolve(jac_, piv_, res, n);
      // Damping: no gap may fall below half its value (the r⁻⁹ wall).
      Real alpha = 1;
      for (int i = 0; i < n; ++i) {
        if (!std::isfinite(res[i])) return false;
        if (res[i] < -0.5 * h[i]) alpha = std::fmin(alpha, -0.5 * h[i] / res[i]);
      }
      for (int i = 0; i < n; ++i) h[i] += alpha * res[i];
    }
    return false;
  }

  Real load(const std::vector<Real>& h) const {
    Real p = 0;
    for (int j = 0; j < size(); ++j) p += ljTraction(h[j]) * mesh_.area[j];
    return p;
  }

  /// Outermost radius (√(R z0)) where H rises through `level` (0 if H(0) is
  /// above it). Level 1: the sign change of σ; level 3^(1/6): the peak tension.
  Real crossing(const std::vector<Real>& h, Real level) const {
    for (int i = size() - 2; i >= 0; --i) {
      if (h[i] < level && h[i + 1] >= level) {
        const Real t = (level - h[i]) / (h[i + 1] - h[i]);
        return mesh_.mid[i] + t * (mesh_.mid[i + 1] - mesh_.mid[i]);
      }
    }
    return h.back() < level ? mesh_.mid.back() : 0;
  }

  /// H on this system's midpoints, interpolated linearly from another mesh.
  std::vector<Real> interpolate(const Mesh& from, const std::vector<Real>& h) const {
    std::vector<Real> out(size());
    std::size_t k = 0;
    const std::size_t last = from.mid.size() - 1;
    for (int i = 0; i < size(); ++i) {
      const Real r = mesh_.mid[i];
      if (r <= from.mid[0]) {
        out[i] = h[0];
        continue;
      }
      if (r >= from.mid[last]) {
        out[i] = h[last] + 0.5 * (r * r - from.mid[last] * from.mid[last]);
        continue;
      }
      while (from.mid[k + 1] < r) ++k;
      const Real t = (r - from.mid[k]) / (from.mid[k + 1] - from.mid[k]);
      out[i] = h[k] + t * (h[k + 1] - h[k]);
    }
    return out;
  }

 private:
  /// Factors the Jacobian I − C diag(s σ̂'(H)).
  bool factor(const std::vector<Real>& h, Real scale, long& count) const {
    const int n = size();
    ++count;
    jac_.resize(static_cast<std::size_t>(n) * n);
    std::vector<Real> d(n);
    for (int j = 0; j < n; ++j) d[j] = scale * sigmaPrime(h[j]);
    for (int i = 0; i < n; ++i) {
      const Real* ci = &c_[static_cast<std::size_t>(i) * n];
      Real* ji = &jac_[static_cast<std::size_t>(i) * n];
      for (int j = 0; j < n; ++j) ji[j] = -ci[j] * d[j];
      ji[i] += 1;
    }
    return luFactor(jac_, piv_, n);
  }

  Mesh mesh_;
  std::vector<Real> c_;
  // Work space of the Newton iteration.
  mutable std::vector<Real> jac_;
  mutable std::vector<int> piv_;
};

/// The gap of a Hertz contact at approach Δ (contact radius √Δ), raised by
/// z0: the starting point of the adhesion-scale continuation.
std::vector<Real> hertzGap(const Mesh& m, Real delta) {
  std::vector<Real> h(m.mid.size());
  const Real a = std::sqrt(std::fmax(delta, 0));
  for (std::size_t i = 0; i < h.size(); ++i) {
    const Real r = m.mid[i];
    if (r <= a) {
      h[i] = 1;
    } else if (a == 0) {
      h[i] = 1 - delta + 0.5 * r * r;
    } else {
      const Real x = r / a;
      h[i] = 1 + (a * a / kPi) * (std::sqrt(x * x - 1) - (2 - x * x) * std::acos(1 / x));
    }
  }
  return h;
}

std::string numberText(Real v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

Real ljTraction(Real gap) {
  const Real i = 1 / gap;
  const Real i3 = i * i * i;
  return (8.0 / 3.0) * (i3 * i3 * i3 - i3);
}

Real diskDisplacement(Real r, Real b) {
  if (b <= 0) return 0;
  if (r < b) return (4 / kPi) * b * std::comp_ellint_2(r / b);
  if (r == b) return (4 / kPi) * b;
  const Real k = b / r;
  return (4 / kPi) * r * (std::comp_ellint_2(k) - (1 - k * k) * std::comp_ellint_1(k));
}

LjSphereCurve ljSphereRetraction(Real mu, const LjSphereOptions& opt) {
  if (!std::isfinite(mu) || !(mu >= 1e-3 && mu <= 1e3)) {
    throw InputError("ljSphereRetraction: mu = " + numberText(mu) +
                     " is out of range (allowed: 1e-3 <= mu <= 1e3)");
  }
  if (opt.rings < 50 || opt.rings > 5000) {
    throw InputError("ljSphereRetraction: rings = " + std::to_string(opt.rings) +
                     " is out of range (allowed: 50 to 5000)");
  }
  if (!std::isfinite(opt.deltaStart) || opt.deltaStart < 0) {
    throw InputError("ljSphereRetraction: deltaStart = " + numberText(opt.deltaStart) +
                     " is not allowed (0 for automatic, or > 0: an approach in compression)");
  }
  if (opt.maxSteps < 10 || opt.maxSteps > 1000000) {
    throw InputError("ljSphereRetraction: maxSteps = " + std::to_string(opt.maxSteps) +
                     " is out of range (allowed: 10 to 1e6)");
  }
  const int n = opt.rings;
  const Real coupling = std::pow(mu, 1.5);  // diskDisplacement carries the 4/π
  const Real ell = std::fmin(1.0, std::pow(mu, -1.5));
  // JKR zero-load radius a0 = (9π/2)^(1/3) √μ (units √(R z0)); JKR approach at
  // a = x a0: Δ = a0² (x² − (2/3)√x).
  const Real a0 = std::cbrt(4.5 * kPi) * std::sqrt(mu);
  const Real x0 = 1.2;
  const Real delta0 =
      opt.deltaStart > 0 ? opt.deltaStart
                         : std::fmax(1.0, a0 * a0 * (x0 * x0 - (2.0 / 3.0) * std::sqrt(x0)));
  const Real rhoFar = std::fmax(kFarRadiusMin, 8 * std::fmax(a0, std::sqrt(delta0)));
  // ā = ρ / ((3π/4)^(1/3) √μ).
  const Real toJg = 1 / (std::cbrt(0.75 * kPi) * std::sqrt(mu));

  LjSphereCurve out;
  out.mu = mu;
  out.rings = n;

  // The band follows the outermost peak of the tension (H = 3^(1/6)), which
  // sits in the cohesive zone; σ changes sign further inside (in the JKR
  // limit at a√(1 − p0'/p0), well inside the crack tip a).
  const Real peakGap = std::pow(3.0, 1.0 / 6.0);
  enum class Travel { Outwards, Inwards, None };
  auto makeSystem = [&](Real e, Travel travel) {
    Real in = kBandAhead, outside = kBandOutside;
    if (travel == Travel::Outwards) {
      in = kBandBehind;
      outside = kBandAhead + kBandBehind;
    } else if (travel == Travel::None) {
      in = outside = kBandAhead;
    }
    const Real lo = std::fmax(0.0, e - in * ell);
    const Real hi = std::fmax(e, 0.0) + outside * ell;
    return RingSystem(buildMesh(n, ell, lo, hi, rhoFar), coupling);
  };
  auto needsRemesh = [&](const RingSystem& sys, Real e) {
    const Mesh& m = sys.mesh();
    if (e > m.bandHi - kBandMarginOutside * ell) return true;
    return m.bandLo > 0 && e < m.bandLo + kBandMarginInside * ell;
  };
  // Rebuilds the rings around the edge e and re-solves from the interpolated
  // gap (slope: the tangent along `along`); keeps the old rings if that fails.
  auto remesh = [&](RingSystem& sys, std::vector<Real>& h, std::vector<Real>& slope, Real delta,
                    Real scale, Real e, Travel travel, RingSystem::Along along) {
    RingSystem next = makeSystem(e, travel);
    std::vector<Real> hn = next.interpolate(sys.mesh(), h);
    std::vector<Real> sn;
    if (!next.solve(hn, delta, scale, 60, out.factorisations, &sn, along)) return false;
    sys = std::move(next);
    h = std::move(hn);
    slope = std::move(sn);
    ++out.remeshes;
    return true;
  };

  // ---- start: adhesion-scale continuation at Δ0 from the Hertz gap --------
  RingSystem sys = makeSystem(std::sqrt(delta0), Travel::Outwards);
  std::vector<Real> h;
  Real scale = kScaleStart;
  for (;;) {
    h = hertzGap(sys.mesh(), delta0);
    if (sys.solve(h, delta0, scale, 200, out.factorisations)) break;
    scale *= 0.5;
    if (scale < kScaleMin) {
      throw NumericalError("ljSphereRetraction (mu = " + numberText(mu) +
                           "): no solution at the starting approach delta/z0 = " +
                           numberText(delta0) + " even with the adhesion scaled down");
    }
  }
  {
    // Steps in s with the tangent predictor, limited like the retraction's
    // by the move of the edge.
    std::vector<Real> slope;
    if (!sys.solve(h, delta0, scale, 60, out.factorisations, &slope, RingSystem::Along::Scale)) {
      throw NumericalError("ljSphereRetraction (mu = " + numberText(mu) +
                           "): no solution at the starting approach delta/z0 = " +
                           numberText(delta0));
    }
    Real e = sys.crossing(h, peakGap);
    Real ds = scale;
    while (scale < 1) {
      if (ds < 1e-6) {
        throw NumericalError("ljSphereRetraction (mu = " + numberText(mu) +
                             "): the adhesion-scale continuation at delta/z0 = " +
                             numberText(delta0) + " stalled at scale " + numberText(scale));
      }
      const Real next = std::fmin(1.0, scale + ds);
      std::vector<Real> hn(h.size()), slopeNext;
      for (std::size_t i = 0; i < hn.size(); ++i) {
        hn[i] = std::fmax(h[i] + (next - scale) * slope[i], 0.5 * h[i]);
      }
      long its = out.factorisations;
      bool ok = sys.solve(hn, delta0, next, 25, out.factorisations, &slopeNext,
                          RingSystem::Along::Scale);
      its = out.factorisations - its;
      Real en = 0;
      if (ok) {
        en = sys.crossing(hn, peakGap);
        ok = std::fabs(en - e) <= kMaxEdgeMove * ell;
      }
      if (!ok) {
        ds *= 0.5;
        continue;
      }
      const Real move = std::fabs(en - e);
      scale = next;
      h = std::move(hn);
      slope = std::move(slopeNext);
      e = en;
      if (needsRemesh(sys, e) &&
          remesh(sys, h, slope, delta0, scale, e, Travel::Outwards, RingSystem::Along::Scale)) {
        e = sys.crossing(h, peakGap);
      }
      if (its <= 4 && move < 0.5 * kMaxEdgeMove * ell) ds *= 1.5;
    }
    remesh(sys, h, slope, delta0, 1, e, Travel::Inwards, RingSystem::Along::Approach);
  }

  // ---- retraction ------------------------------------------------------------
  struct Sample {
    Real delta, load, contact, peak;
  };
  std::vector<Sample> samples;
  Real delta = delta0;
  Real e = sys.crossing(h, peakGap);
  Real load = sys.load(h);
  samples.push_back({delta, load, sys.crossing(h, 1), e});
  // The state at the smallest load so far, for the final refinement.
  Real bestLoad = load;
  Mesh bestMesh = sys.mesh();
  std::vector<Real> bestGap = h;
  // First step: an edge move of about ℓ/2 on a Hertz-like branch
  // (dΔ/dρ ≈ ρ); the fold is declared when Newton fails below 1e-4 of it.
  const Real maxStep = std::fmax(0.05, 0.05 * delta0);
  Real step = std::fmin(maxStep, 0.5 * std::fmax(e, 1.0) * ell);
  const Real minStep = 1e-4 * step;
  std::vector<Real> slope;  // dH/dΔ at the current point
  if (!sys.solve(h, delta, 1, 60, out.factorisations, &slope)) {
    throw NumericalError("ljSphereRetraction (mu = " + numberText(mu) +
                         "): the starting point could not be re-solved");
  }
  int accepted = 0;
  while (accepted < opt.maxSteps) {
    if (step < minStep) {
      out.reachedEnd = true;  // fold: no solution close to the last one
      break;
    }
    const Real dn = delta - step;
    // Tangent predictor, kept off the wall.
    std::vector<Real> hn(h.size());
    for (std::size_t i = 0; i < hn.size(); ++i) {
      hn[i] = std::fmax(h[i] - step * slope[i], 0.5 * h[i]);
    }
    std::vector<Real> slopeNext;
    long its = out.factorisations;
    bool ok = sys.solve(hn, dn, 1, 25, out.factorisations, &slopeNext);
    its = out.factorisations - its;
    Real en = 0, pn = 0;
    const Real loadTol = kMaxLoadChange * std::fmax(1.0, std::fabs(load));
    if (ok) {
      en = sys.crossing(hn, peakGap);
      pn = sys.load(hn);
      ok = std::fabs(en - e) <= kMaxEdgeMove * ell && std::fabs(pn - load) <= loadTol;
    }
    if (!ok) {
      step *= 0.5;
      continue;
    }
    const Real move = std::fabs(en - e);
    const Real change = std::fabs(pn - load);
    h = std::move(hn);
    slope = std::move(slopeNext);
    delta = dn;
    e = en;
    load = pn;
    ++accepted;
    if (needsRemesh(sys, e) &&
        remesh(sys, h, slope, delta, 1, e, Travel::Inwards, RingSystem::Along::Approach)) {
      e = sys.crossing(h, peakGap);
      load = sys.load(h);
    }
    const Real contact = sys.crossing(h, 1);
    samples.push_back({delta, load, contact, e});
    if (load < bestLoad) {
      bestLoad = load;
      bestMesh = sys.mesh();
      bestGap = h;
    }
    if (contact == 0 && h[0] > kSeparatedGap) {
      out.reachedEnd = true;  // separated
      break;
    }
    if (its <= 4 && move < 0.5 * kMaxEdgeMove * ell && change < 0.5 * loadTol) {
      step = std::fmin(maxStep, 1.5 * step);
    }
  }

  out.retraction.reserve(samples.size());
  std::size_t kMin = 0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    out.retraction.push_back(
        {samples[k].delta, samples[k].load, samples[k].contact * toJg, samples[k].peak * toJg});
    if (samples[k].load < samples[kMin].load) kMin = k;
  }
  out.minimumLoad = samples[kMin].load;
  out.deltaAtMinimum = samples[kMin].delta;
  out.contactRadiusAtMinimum = samples[kMin].contact * toJg;
  out.peakRadiusAtMinimum = samples[kMin].peak * toJg;
  out.minimumInterior = kMin > 0 && kMin + 1 < samples.size();
  if (!out.minimumInterior) return out;

  // ---- refinement of the minimum on one set of rings -------------------------
  // Rebuilding the rings shifts P slightly (by the change of the
  // discretisation error), so the minimum is located again on rings centred
  // at the edge of the smallest sample: the load is bracketed at the local
  // step d and minimised over the bracket (Brent).
  {
    const Real d = std::fmin(samples[kMin - 1].delta - samples[kMin].delta,
                             samples[kMin].delta - samples[kMin + 1].delta);
    RingSystem fine = makeSystem(samples[kMin].peak, Travel::None);
    struct Probe {
      Real delta, load;
      std::vector<Real> gap, slope;
    };
    Probe centre{samples[kMin].delta, 0, fine.interpolate(bestMesh, bestGap), {}};
    if (!fine.solve(centre.gap, centre.delta, 1, 60, out.factorisations, &centre.slope)) {
      return out;
    }
    centre.load = fine.load(centre.gap);
    // The solution at Δ, from the tangent predictor at `from`.
    auto stepTo = [&](const Probe& from, Real delta, Probe& p) {
      p.delta = delta;
      p.gap.resize(from.gap.size());
      for (std::size_t i = 0; i < p.gap.size(); ++i) {
        p.gap[i] = std::fmax(from.gap[i] + (delta - from.delta) * from.slope[i], 0.5 * from.gap[i]);
      }
      if (!fine.solve(p.gap, delta, 1, 25, out.factorisations, &p.slope)) return false;
      p.load = fine.load(p.gap);
      return true;
    };
    // The same, in up to 8 substeps if a direct step fails.
    auto probeAt = [&](const Probe& from, Real delta, Probe& p) {
      for (int parts = 1; parts <= 8; parts *= 2) {
        Probe cur = from;
        bool ok = true;
        for (int k = 1; k <= parts && ok; ++k) {
          Probe next;
          ok = stepTo(cur, from.delta + (delta - from.delta) * k / parts, next);
          cur = std::move(next);
        }
        if (ok) {
          p = std::move(cur);
          return true;
        }
      }
      return false;
    };
    // Bracket: hi.delta > mid.delta > lo.delta with mid.load below both.
    Probe hi, lo, mid = std::move(centre);
    if (!probeAt(mid, mid.delta + d, hi) || !probeAt(mid, mid.delta - d, lo)) return out;
    for (int guard = 0; guard < 12 && !(mid.load <= hi.load && mid.load <= lo.load); ++guard) {
      // Walk downhill by d until the middle is the smallest.
      if (hi.load < mid.load) {
        lo = std::move(mid);
        mid = std::move(hi);
        if (!probeAt(mid, mid.delta + d, hi)) return out;
      } else {
        hi = std::move(mid);
        mid = std::move(lo);
        if (!probeAt(mid, mid.delta - d, lo)) return out;
      }
    }
    if (!(mid.load <= hi.load && mid.load <= lo.load)) return out;
    // Brent's minimiser on the bracket; every evaluation continues from the
    // state solved last, which lies close by.
    Probe last = mid;
    auto loadAt = [&](Real delta) {
      Probe p;
      if (!probeAt(last, delta, p)) throw NumericalError("no solution at delta/z0 = " + numberText(delta));
      last = std::move(p);
      return last.load;
    };
    try {
      const Real best = detail::bracketedMinimum(loadAt, lo.delta, hi.delta, 0.0, 1e-4 * d, "LJ sphere minimum").first;
      Probe atBest;
      if (probeAt(last, best, atBest) && atBest.load <= mid.load) mid = std::move(atBest);
    } catch (const NumericalError&) {
      // keep the smallest bracketed sample
    }
    out.minimumLoad = mid.load;
    out.deltaAtMinimum = mid.delta;
    out.contactRadiusAtMinimum = fine.crossing(mid.gap, 1) * toJg;
    out.peakRadiusAtMinimum = fine.crossing(mid.gap, peakGap) * toJg;
    out.refined = true;
  }
  return out;
}

}  // namespace cgcm::analytic
