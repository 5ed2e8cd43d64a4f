#pragma once
// The ITTC-1957 model-ship correlation line, C_F = 0.075 / (log10 Re - 2)^2.
namespace hullopt::res {

/// Frictional resistance coefficient at Reynolds number re (U L / nu). Throws std::invalid_argument for
/// re <= 100 (the line has its pole at Re = 100 and is meaningless below ~1e5).
double Ittc1957FrictionCoefficient(double re);

}  // namespace hullopt::res
