#pragma once
// Least-squares fit of the Maugis-Dugdale load curve to a computed CGCM load
// curve P(u).
//
// The data: the columns `u` and `P` of a load-curve CSV (read by header
// name), in CGCM normalisation (R0 = Y = 1), P > 0 compressive, u the
// approach with u = 0 where the undeformed surfaces sit at the equilibrium
// distance r_S0, so that u corresponds to the M-D approach δ.
//
// The model at (λ, offset): the M-D curve mapped by CgcmMapping,
//   P_C(ā) = f_F P̄(ā),   u_C(ā) = f_δ δ̄(ā) + offset,
// on its stable branch under displacement control, ā ≥ ā_d (ā_d the
// displacement-control pull-off radius, 0 when δ̄(ā) is monotone). There
// δ̄(ā) increases, so the model load at a data point u is unique: solve
// δ̄(ā) = (u − offset)/f_δ. Data points with u below the branch's end
// u_C(ā_d) are compared with the load at that end.
//
// The objective is Σ (P_i − P_C(u_i))² over the fitted points. λ is found on
// log λ by a scan (6 points per decade) followed by Brent's minimiser
// (golden section with parabolic steps) between the scan neighbours of the
// best point; with fitOffset, the offset is minimised the same way for each
// λ inside [offset − offsetBound, offset + offsetBound].
//
// Fitted points (the default window): u ≥ u(P_min), the approach of the
// curve's most tensile point, i.e. the minimum and everything on the
// contact side of it. The approach phase before the pull-in (P ≈ 0 while
// the surfaces are still apart) is outside the M-D model, which has no
// interaction beyond the adhesive zone. uMin/uMax replace this window.
#include <optional>
#include <string>
#include <vector>

#include "cgcm/analytic/CgcmMapping.hpp"
#include "cgcm/analytic/Models.hpp"

namespace cgcm::analytic {

struct LoadCurve {
  std::vector<Real> u;
  std::vector<Real> P;
};

/// Reads the columns named `uColumn` and `PColumn` of a CSV with a header
/// line (lines starting with '#' and blank lines are skipped). Throws
/// InputError naming the file and line for a missing file or column, a row
/// with the wrong number of fields, or a field that is not a number.
LoadCurve readLoadCurveCsv(const std::string& path, const std::string& uColumn = "u",
                           const std::string& PColumn = "P");

struct FitOptions {
  /// Search range of λ.
  Real lambdaMin = kLambdaMin;
  Real lambdaMax = kLambdaMax;
  bool fitOffset = false;
  /// The offset (fixed, or the centre of the search when fitOffset).
  Real offset = 0;
  /// Half-width of the offset search; unset: half the u-span of the window.
  std::optional<Real> offsetBound;
  /// Explicit window of fitted points; unset: the default window above.
  std::optional<Real> uMin;
  std::optional<Real> uMax;
};

struct FitResult {
  Real lambda = 0;
  Real offset = 0;
  Real rms = 0;          ///< √(Σ r²/n), in CGCM load units
  Real maxAbs = 0;       ///< max |r|
  Real rmsRelative = 0;  ///< rms over the range of P in the window
  std::size_t points = 0;
  Real uFrom = 0;  ///< smallest fitted u
  Real uTo = 0;    ///< largest fitted u
  bool atBound = false;  ///< λ ended within 1e-3 (in log) of a search bound
  int objectiveEvaluations = 0;
};

/// Indices of the points of `curve` inside the window of `options`.
std::vector<std::size_t> fitWindow(const LoadCurve& curve, const FitOptions& options);

/// The model load P_C at approach u for (λ, offset) as defined above.
Real mdCgcmLoadAtApproach(const CgcmMapping& map, Real lambda, Real offset, Real u);

/// Throws InputError for an invalid option (λ range, offset bound, window
/// with fewer than 3 points, or fewer points than fitted parameters + 1).
FitResult fitMaugisDugdale(const LoadCurve& curve, const CgcmMapping& map,
                           const FitOptions& options);

}  // namespace cgcm::analytic
