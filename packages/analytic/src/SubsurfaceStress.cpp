#include "cgcm/analytic/SubsurfaceStress.hpp"

#include <cmath>
#include <exception>
#include <sstream>
#include <thread>

#include "cgcm/analytic/Quadrature.hpp"
#include "cgcm/core/Error.hpp"

namespace cgcm::analytic {
namespace {


/// s = r and s = r ± z·4ⁿ up to `reach`: the scales of the kernel spike,
/// which has width ~z at s = r and tails ~z³/|r−s|⁴.
std::vector<Real> spikePoints(Real r, Real z, Real reach) {
  std::vector<Real> pts{r};
  for (Real d = z; d < reach; d *= 4) {
    pts.push_back(r - d);
    pts.push_back(r + d);
  }
  return pts;
}

}  // namespace

Real boussinesqRingKernel(Real r, Real s, Real z) {
  const Real z2 = z * z;
  const Real dm = (r - s) * (r - s) + z2;  // α − β, no cancellation
  const Real dp = (r + s) * (r + s) + z2;  // α + β
  const EllipticKE ke = ellipticKE(4 * r * s / dp, dm / dp);
  const Real kp2 = dm / dp;
  // z³/dm² is formed as (z/dm)(z²/dm) so that it stays in range as z → 0.
  return (2 / kPi) * s * (z / dm) * (z2 / dm) * (2 * (1 + kp2) * ke.E - kp2 * ke.K) /
         std::sqrt(dp);
}

Real sigmaZ(const PressureProfile& p, Real r, Real z, const StressOptions& options) {
  if (!(std::isfinite(r) && r >= 0 && std::isfinite(z) && z >= 0)) {
    std::ostringstream msg;
    msg << "stress: need finite r >= 0 and z >= 0, got r = " << r << ", z = " << z;
    throw InputError(msg.str());
  }
  if (z == 0) return -p(r);

  const Real a = p.contactRadius();
  const Real c = p.outerRadius();
  const Real pr = p(r);
  // Subtract p(r) where the spike lies inside the loaded disc; at r = a of
  // JKR p(r) = −∞ and the direct form is used (the stress is singular there).
  const bool subtract = r < c && std::isfinite(pr);
  const Real shift = subtract ? pr : 0;
  const Real tol = options.relTol * p.scale() / 3;
  const std::vector<Real> spikes = spikePoints(r, z, 4 * std::fmax(r, c));
  std::ostringstream what;
  what << "stress at r = " << r << ", z = " << z;

  // [0, a] with s = a(1 − t²), ds = 2a t dt.
  std::vector<Real> ptsA{0.0, 1.0};
  for (Real s : spikes) {
    if (s > 0 && s < a) ptsA.push_back(std::sqrt(1 - s / a));
  }
  auto fA = [&](Real t) {
    const Real s = a * (1 - t * t);
    return boussinesqRingKernel(r, s, z) * (p.nearEdge(t) - shift) * 2 * a * t;
  };
  Real sum = integrateAdaptive(fA, ptsA, tol, options.relTol, options.maxIntervals, what.str()).value;

  // [a, c]: the Maugis-Dugdale adhesive zone, p = −λ.
  if (c > a) {
    std::vector<Real> ptsB{a, c};
    for (Real s : spikes) {
      if (s > a && s < c) ptsB.push_back(s);
    }
    auto fB = [&](Real s) { return boussinesqRingKernel(r, s, z) * (p(s) - shift); };
    sum += integrateAdaptive(fB, ptsB, tol, options.relTol, options.maxIntervals, what.str()).value;
  }

  if (subtract) {
    // p(r) ∫₀^c G ds = p(r) (1 − ∫_c^∞ G ds), the tail by s = c/t, ds = −c/t² dt;
    // the integrand vanishes like 3 z³ t²/c³ as t → 0.
    std::vector<Real> ptsC{0.0, 1.0};
    for (Real s : spikes) {
      if (s > c) ptsC.push_back(c / s);
    }
    auto fC = [&](Real t) { return boussinesqRingKernel(r, c / t, z) * c / (t * t); };
    const Real tail = integrateAdaptive(fC, ptsC, tol / (std::fabs(pr) > 1 ? std::fabs(pr) : 1),
                                        options.relTol, options.maxIntervals, what.str())
                          .value;
    sum += pr * (1 - tail);
  }
  return -sum;
}

std::vector<Real> sigmaZGrid(const PressureProfile& p, const std::vector<Real>& r,
                             const std::vector<Real>& z, const StressOptions& options,
                             int threads) {
  if (threads < 1) throw InputError("stress grid: threads must be >= 1");
  const std::size_t nr = r.size();
  const std::size_t nz = z.size();
  std::vector<Real> out(nr * nz);
  auto rows = [&](std::size_t first, std::size_t stride) {
    for (std::size_t j = first; j < nz; j += stride) {
      for (std::size_t i = 0; i < nr; ++i) out[j * nr + i] = sigmaZ(p, r[i], z[j], options);
    }
  };
  if (threads == 1 || nz < 2) {
    rows(0, 1);
    return out;
  }
  const std::size_t n = static_cast<std::size_t>(threads);
  std::vector<std::exception_ptr> errors(n);
  std::vector<std::thread> pool;
  for (std::size_t k = 0; k < n; ++k) {
    pool.emplace_back([&, k] {
      try {
        rows(k, n);
      } catch (...) {
        errors[k] = std::current_exception();
      }
    });
  }
  for (auto& t : pool) t.join();
  for (auto& e : errors) {
    if (e) std::rethrow_exception(e);
  }
  return out;
}

Real hertzAxisSigmaZ(Real p0, Real a, Real z) { return -p0 / (1 + (z / a) * (z / a)); }

}  // namespace cgcm::analytic
