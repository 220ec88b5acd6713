#include "cgcm/analytic/LoadCurveFit.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

#include "Numerics.hpp"
#include "cgcm/analytic/MaugisDugdale.hpp"
#include "cgcm/analytic/PullOff.hpp"
#include "cgcm/core/Error.hpp"

namespace cgcm::analytic {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\"");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\"");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> splitCsv(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) out.push_back(trim(field));
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

/// The stable (displacement-control) branch of the M-D curve at one λ:
/// ā ≥ ā_d, where δ̄(ā) increases.
class MdBranch {
 public:
  explicit MdBranch(Real lambda) : lambda_(lambda) {
    const PullOff p = pullOff(ContactModel::maugisDugdale(lambda));
    aEnd_ = p.displacementControl.a;
    deltaEnd_ = p.displacementControl.approach;
    loadEnd_ = p.displacementControl.load;
  }

  /// P̄ at δ̄ on the branch (the end load for δ̄ at or below the end).
  /// aGuess/sGuess carry a warm start between neighbouring calls.
  Real loadAtApproach(Real delta, Real& aGuess, Real& sGuess) const {
    if (delta <= deltaEnd_) return loadEnd_;
    auto eval = [&](Real a, MdSolution& sol) {
      sol = solveMaugisDugdale(lambda_, a, sGuess);
      sGuess = sol.s;
      return sol.approach - delta;
    };
    MdSolution sol;
    Real lo = aEnd_;
    Real hi = std::numeric_limits<Real>::infinity();
    // Start from the warm start, or from δ̄ ≈ ā² (the Hertz-like large-ā form).
    Real a = (aGuess > aEnd_) ? aGuess : std::fmax(std::sqrt(std::fabs(delta)), 2 * aEnd_ + 1e-3);
    Real g = eval(a, sol);
    while (g < 0) {
      lo = a;
      a *= 2;
      if (a > 1e8) throw NumericalError("M-D fit: approach out of the model's range");
      g = eval(a, sol);
    }
    hi = a;
    for (int it = 0; it < 100; ++it) {
      if (g == 0) break;
      if (g < 0) {
        lo = a;
      } else {
        hi = a;
      }
      const MdSlopes d = mdSlopes(sol);
      Real next = a - g / d.dApproach;
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      const Real step = std::fabs(next - a);
      a = next;
      g = eval(a, sol);
      if (step <= 1e-14 * a || hi - lo <= 1e-14 * hi) {
        aGuess = a;
        return sol.load;
      }
    }
    if (g == 0) {
      aGuess = a;
      return sol.load;
    }
    throw NumericalError("M-D fit: contact radius for a given approach not found");
  }

 private:
  Real lambda_;
  Real aEnd_ = 0;
  Real deltaEnd_ = 0;
  Real loadEnd_ = 0;
};

struct Residuals {
  Real sumSq = 0;
  Real maxAbs = 0;
};

}  // namespace

LoadCurve readLoadCurveCsv(const std::string& path, const std::string& uColumn,
                           const std::string& PColumn) {
  std::ifstream in(path);
  if (!in) throw InputError("load curve: cannot open '" + path + "'");
  auto where = [&](int line) { return "load curve " + path + ":" + std::to_string(line) + ": "; };
  std::string line;
  int lineNo = 0;
  std::vector<std::string> header;
  while (std::getline(in, line)) {
    ++lineNo;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    header = splitCsv(t);
    break;
  }
  if (header.empty()) throw InputError("load curve: '" + path + "' has no header line");
  auto column = [&](const std::string& name) {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) {
      std::string have;
      for (const auto& h : header) have += (have.empty() ? "" : ", ") + h;
      throw InputError(where(lineNo) + "no column '" + name + "' (columns: " + have + ")");
    }
    return static_cast<std::size_t>(it - header.begin());
  };
  const std::size_t iu = column(uColumn);
  const std::size_t iP = column(PColumn);
  LoadCurve curve;
  while (std::getline(in, line)) {
    ++lineNo;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const std::vector<std::string> fields = splitCsv(t);
    if (fields.size() != header.size()) {
      throw InputError(where(lineNo) + std::to_string(fields.size()) + " fields, header has " +
                       std::to_string(header.size()));
    }
    auto number = [&](std::size_t i) {
      const char* s = fields[i].c_str();
      char* end = nullptr;
      errno = 0;
      const Real v = std::strtod(s, &end);
      if (fields[i].empty() || *end != '\0' || errno == ERANGE || !std::isfinite(v)) {
        throw InputError(where(lineNo) + "column '" + header[i] + "': '" + fields[i] +
                         "' is not a finite number");
      }
      return v;
    };
    curve.u.push_back(number(iu));
    curve.P.push_back(number(iP));
  }
  if (curve.u.empty()) throw InputError("load curve: '" + path + "' has no data rows");
  return curve;
}

std::vector<std::size_t> fitWindow(const LoadCurve& curve, const FitOptions& options) {
  if (curve.u.size() != curve.P.size() || curve.u.empty()) {
    throw InputError("load curve: u and P must be non-empty and of equal length");
  }
  Real lo = -std::numeric_limits<Real>::infinity();
  Real hi = std::numeric_limits<Real>::infinity();
  if (options.uMin || options.uMax) {
    if (options.uMin) lo = *options.uMin;
    if (options.uMax) hi = *options.uMax;
    if (!(lo < hi)) throw InputError("fit: the window needs u-min < u-max");
  } else {
    const auto it = std::min_element(curve.P.begin(), curve.P.end());
    lo = curve.u[static_cast<std::size_t>(it - curve.P.begin())];
  }
  std::vector<std::size_t> idx;
  for (std::size_t i = 0; i < curve.u.size(); ++i) {
    if (curve.u[i] >= lo && curve.u[i] <= hi) idx.push_back(i);
  }
  // Ascending u, so that the warm start follows the curve.
  std::stable_sort(idx.begin(), idx.end(),
                   [&](std::size_t a, std::size_t b) { return curve.u[a] < curve.u[b]; });
  return idx;
}

Real mdCgcmLoadAtApproach(const CgcmMapping& map, Real lambda, Real offset, Real u) {
  const MdBranch branch(lambda);
  Real aGuess = -1;
  Real sGuess = -1;
  return map.fF * branch.loadAtApproach((u - offset) / map.fdelta, aGuess, sGuess);
}

FitResult fitMaugisDugdale(const LoadCurve& curve, const CgcmMapping& map,
                           const FitOptions& options) {
  if (!(std::isfinite(options.lambdaMin) && std::isfinite(options.lambdaMax) &&
        options.lambdaMin > 0 && options.lambdaMin < options.lambdaMax)) {
    std::ostringstream msg;
    msg << "fit: lambda range [" << options.lambdaMin << ", " << options.lambdaMax
        << "] must satisfy 0 < min < max";
    throw InputError(msg.str());
  }
  if (!std::isfinite(options.offset)) throw InputError("fit: offset must be finite");
  const std::vector<std::size_t> idx = fitWindow(curve, options);
  const std::size_t params = options.fitOffset ? 2 : 1;
  if (idx.size() < 3 || idx.size() < params + 1) {
    throw InputError("fit: the window holds " + std::to_string(idx.size()) +
                     " points, at least 3 are needed");
  }
  std::vector<Real> u, P;
  for (std::size_t i : idx) {
    u.push_back(curve.u[i]);
    P.push_back(curve.P[i]);
  }
  const Real uFrom = u.front();
  const Real uTo = u.back();
  const Real bound = options.offsetBound ? *options.offsetBound : 0.5 * (uTo - uFrom);
  if (options.fitOffset && !(std::isfinite(bound) && bound > 0)) {
    throw InputError("fit: the offset search half-width must be finite and > 0");
  }

  int evaluations = 0;
  std::vector<Real> aWarm(u.size(), -1);
  std::vector<Real> sWarm(u.size(), -1);
  auto residuals = [&](const MdBranch& branch, Real offset) {
    ++evaluations;
    Residuals r;
    for (std::size_t i = 0; i < u.size(); ++i) {
      const Real model = map.fF * branch.loadAtApproach((u[i] - offset) / map.fdelta, aWarm[i], sWarm[i]);
      const Real d = P[i] - model;
      r.sumSq += d * d;
      r.maxAbs = std::fmax(r.maxAbs, std::fabs(d));
    }
    return r;
  };
  // Best offset at one λ (the fixed one without fitOffset): (offset, Σr²).
  auto bestOffset = [&](Real logLambda) {
    const MdBranch branch(std::exp(logLambda));
    if (!options.fitOffset) return std::make_pair(options.offset, residuals(branch, options.offset).sumSq);
    return detail::bracketedMinimum([&](Real off) { return residuals(branch, off).sumSq; },
                                 options.offset - bound, options.offset + bound, 0.0, 1e-10 * bound,
                                 "M-D fit (offset)");
  };

  // Scan log λ, 6 points per decade, then refine between the best point's
  // neighbours.
  const Real x0 = std::log(options.lambdaMin);
  const Real x1 = std::log(options.lambdaMax);
  const int n = std::max(3, static_cast<int>(std::ceil(6 * (x1 - x0) / std::log(10.0))) + 1);
  std::vector<Real> xs(n), fs(n);
  int best = 0;
  for (int k = 0; k < n; ++k) {
    xs[k] = x0 + (x1 - x0) * k / (n - 1);
    fs[k] = bestOffset(xs[k]).second;
    if (fs[k] < fs[best]) best = k;
  }
  const Real lo = xs[std::max(0, best - 1)];
  const Real hi = xs[std::min(n - 1, best + 1)];
  const auto [x, fx] = detail::bracketedMinimum([&](Real xl) { return bestOffset(xl).second; }, lo, hi,
                                             0.0, 1e-10, "M-D fit (lambda)");
  FitResult res;
  res.lambda = std::exp(x);
  res.offset = bestOffset(x).first;
  (void)fx;
  const Residuals r = residuals(MdBranch(res.lambda), res.offset);
  res.points = u.size();
  res.rms = std::sqrt(r.sumSq / static_cast<Real>(u.size()));
  res.maxAbs = r.maxAbs;
  const auto [pMin, pMax] = std::minmax_element(P.begin(), P.end());
  res.rmsRelative = (*pMax > *pMin) ? res.rms / (*pMax - *pMin) : 0;
  res.uFrom = uFrom;
  res.uTo = uTo;
  res.atBound = (x - x0 < 1e-3) || (x1 - x < 1e-3);
  res.objectiveEvaluations = evaluations;
  return res;
}

}  // namespace cgcm::analytic
