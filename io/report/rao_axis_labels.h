#pragma once
// Axis labels of the RAO magnitudes, the same in every plot and as in rao.csv and docs/conventions.md: heave
// per wave amplitude, pitch per wave slope amplitude kA (k = ω²/g), both angles in radians.
namespace hullopt::io {

inline constexpr const char* kHeaveRaoLabel = "|x3|/A [m/m]";
inline constexpr const char* kPitchRaoLabel = "|x5|/(kA) [rad/rad]";

}  // namespace hullopt::io
