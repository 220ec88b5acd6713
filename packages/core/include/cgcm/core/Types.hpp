#pragma once
// Scalar and index types shared by every package.
#include <cstdint>

namespace cgcm {

using Real = double;
/// Local (per-rank) index: matches Tpetra's local ordinal of the Debian build.
using LocalIndex = int;
/// Global index: matches Tpetra's global ordinal of the Debian build (long long).
using GlobalIndex = long long;

/// pi, the one definition of the code (usable in kernels).
inline constexpr Real kPi = 3.14159265358979323846;

}  // namespace cgcm
