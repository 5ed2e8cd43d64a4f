#include "resistance/friction_line.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace hullopt::res {

double Ittc1957FrictionCoefficient(double re) {
  if (!(re > 100.0) || !std::isfinite(re))
    throw std::invalid_argument("ITTC-1957 line: Reynolds number " + std::to_string(re) + " must be > 100");
  const double d = std::log10(re) - 2.0;
  return 0.075 / (d * d);
}

}  // namespace hullopt::res
