#pragma once
// Magnitude limits of numbers read from data files (docs/bad-inputs.md).

namespace hullopt::io {

/// [m] Largest coordinate of a hull file: 1000 km is no hull in any length unit, and well inside the range
/// where areas and volumes (powers 2 to 4) stay finite.
constexpr double kMaxCoordinate_m = 1.0e6;

}  // namespace hullopt::io
