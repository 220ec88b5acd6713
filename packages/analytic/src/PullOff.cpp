#include "cgcm/analytic/PullOff.hpp"

#include <cmath>
#include <sstream>
#include <vector>

#include "Numerics.hpp"
#include "cgcm/analytic/MaugisDugdale.hpp"
#include "cgcm/core/Error.hpp"

namespace cgcm::analytic {
namespace {

// Scan of the Maugis-Dugdale slopes: ā from 1e-6 to 10, 24 points per
// decade. Every extremum of P̄(ā) and δ̄(ā) lies below ā ≈ 1.2 (the JKR
// load-control radius (3/2)^(1/3) is the largest), and the slopes are
// smooth on this grid's scale, so a sign change between neighbours brackets
// each extremum. Below 1e-6 the slopes lose accuracy: they are differences
// of terms of size λc̄²/ā.
constexpr Real kScanMaxA = 10;
constexpr int kScanPerDecade = 24;

struct Sample {
  Real a;
  MdSolution sol;
  MdSlopes d;
};

PullOffPoint mdPoint(Real lambda, Real a, Real sGuess) {
  const MdSolution sol = solveMaugisDugdale(lambda, a, sGuess);
  return {sol.load, a, sol.approach};
}

/// The minimum of P̄ (which = load) or δ̄ (which = approach) over the scan,
/// refined by a bracketing root finder (TOMS 748) on the analytic slope. Returns false if the
/// slope is positive at the smallest scanned radius and has no − to + sign
/// change (the minimum is the ā → 0 end of the branch).
bool mdMinimum(Real lambda, const std::vector<Sample>& scan, bool load, PullOffPoint& out) {
  auto value = [&](const Sample& s) { return load ? s.sol.load : s.sol.approach; };
  auto slope = [&](const Sample& s) { return load ? s.d.dLoad : s.d.dApproach; };
  int best = -1;
  for (std::size_t i = 0; i + 1 < scan.size(); ++i) {
    if (slope(scan[i]) < 0 && slope(scan[i + 1]) >= 0) {
      if (best < 0 || std::fmin(value(scan[i]), value(scan[i + 1])) <
                          std::fmin(value(scan[best]), value(scan[best + 1]))) {
        best = static_cast<int>(i);
      }
    }
  }
  if (best < 0) {
    if (slope(scan.back()) <= 0) {
      std::ostringstream msg;
      msg << "Maugis-Dugdale pull-off (lambda = " << lambda << "): the "
          << (load ? "load" : "approach") << " still decreases at a = " << kScanMaxA;
      throw NumericalError(msg.str());
    }
    return false;
  }
  const Sample& lo = scan[best];
  const Sample& hi = scan[best + 1];
  Real sGuess = lo.sol.s;
  auto f = [&](Real a) {
    const MdSolution sol = solveMaugisDugdale(lambda, a, sGuess);
    sGuess = sol.s;
    const MdSlopes d = mdSlopes(sol);
    return load ? d.dLoad : d.dApproach;
  };
  std::ostringstream what;
  what << "Maugis-Dugdale " << (load ? "load" : "displacement") << "-control pull-off (lambda = "
       << lambda << ")";
  const Real a = detail::bracketedRoot(f, lo.a, hi.a, slope(lo), slope(hi), 1e-14 * hi.a, what.str());
  out = mdPoint(lambda, a, lo.sol.s);
  // The extremum is a minimum: it cannot exceed the bracketing samples.
  const Real refined = load ? out.load : out.approach;
  if (!(refined <= std::fmax(value(lo), value(hi)))) {
    throw NumericalError(what.str() + ": refined point is not a minimum");
  }
  return true;
}

PullOff mdPullOff(Real lambda) {
  const int decades = static_cast<int>(std::lround(std::log10(kScanMaxA / kPullOffScanMinA)));
  const int n = decades * kScanPerDecade + 1;
  std::vector<Sample> scan;
  scan.reserve(n);
  Real sGuess = -1;
  for (int i = 0; i < n; ++i) {
    const Real a = kPullOffScanMinA * std::pow(10.0, static_cast<Real>(i) / kScanPerDecade);
    Sample s;
    s.a = a;
    s.sol = solveMaugisDugdale(lambda, a, sGuess);
    s.d = mdSlopes(s.sol);
    sGuess = s.sol.s;
    scan.push_back(s);
  }
  const MdZeroContact zero = mdZeroContactLimit(lambda);
  const PullOffPoint end{zero.load, 0, zero.approach};
  PullOff p;
  p.adhesive = true;
  if (!mdMinimum(lambda, scan, true, p.loadControl)) p.loadControl = end;
  p.displacementJump = mdMinimum(lambda, scan, false, p.displacementControl);
  if (!p.displacementJump) p.displacementControl = end;
  return p;
}

}  // namespace

PullOff pullOff(const ContactModel& model) {
  PullOff p;
  switch (model.kind()) {
    case Model::Hertz:
      p.adhesive = false;
      p.displacementJump = false;
      p.loadControl = {0, 0, 0};
      p.displacementControl = {0, 0, 0};
      return p;
    case Model::Jkr: {
      // dP̄/dā = 3ā² − (3/2)√6 ā^(1/2) = 0  →  ā³ = 3/2, P̄ = 3/2 − 3 = −3/2.
      const Real aLoad = std::cbrt(1.5);
      p.loadControl = {-1.5, aLoad, model.at(aLoad).approach};
      // dδ̄/dā = 2ā − (√6/3) ā^(−1/2) = 0  →  ā³ = 1/6, P̄ = 1/6 − 1 = −5/6.
      const Real aDisp = std::cbrt(1.0 / 6.0);
      p.displacementControl = {-5.0 / 6.0, aDisp, model.at(aDisp).approach};
      return p;
    }
    case Model::Dmt:
      // P̄ = ā³ − 2 and δ̄ = ā² both have their minimum at ā = 0.
      p.displacementJump = false;
      p.loadControl = {-2, 0, 0};
      p.displacementControl = {-2, 0, 0};
      return p;
    case Model::MaugisDugdale:
      return mdPullOff(model.lambda());
  }
  return p;
}

}  // namespace cgcm::analytic
