#include "seakeeping/sections/section_shapes.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace hullopt::sk {

HalfContour SemicircleContour(double radius_m, int points) {
  if (!(radius_m > 0)) throw std::invalid_argument("semicircle radius must be > 0 m");
  HalfContour c;
  for (int i = 0; i <= points; ++i) {
    const double th = 0.5 * M_PI * i / points;  // 0 at the keel, π/2 at the waterline
    c.push_back({radius_m * std::sin(th), -radius_m * std::cos(th)});
  }
  c.front() = {0.0, -radius_m};
  c.back() = {radius_m, 0.0};
  return c;
}

HalfContour RectangleContour(double beam_m, double draught_m) {
  if (!(beam_m > 0) || !(draught_m > 0)) throw std::invalid_argument("rectangle beam and draught must be > 0 m");
  return {{0.0, -draught_m}, {0.5 * beam_m, -draught_m}, {0.5 * beam_m, 0.0}};
}

HalfContour LewisContour(double beam_m, double draught_m, double sigma, int points) {
  if (!(beam_m > 0) || !(draught_m > 0)) throw std::invalid_argument("Lewis beam and draught must be > 0 m");
  const double H0 = beam_m / (2 * draught_m);
  const double c = (H0 - 1) / (H0 + 1);
  const double C1 = (3 + 4 * sigma / M_PI) + (1 - 4 * sigma / M_PI) * c * c;
  const double disc = 9 - 2 * C1;
  auto refuse = [&](const std::string& why) {
    std::ostringstream os;
    os << "no Lewis form for B/(2T) = " << H0 << ", area coefficient " << sigma << ": " << why;
    throw std::domain_error(os.str());
  };
  if (disc < 0) refuse("9 − 2·C1 < 0 (area coefficient too large for this beam/draught ratio)");
  const double a3 = (-C1 + 3 + std::sqrt(disc)) / C1;
  const double a1 = (1 + a3) * c;
  const double M = 0.5 * beam_m / (1 + a1 + a3);
  HalfContour out;
  double prev_z = -1e300;
  for (int i = 0; i <= points; ++i) {
    const double th = 0.5 * M_PI * i / points;
    const double y = M * ((1 + a1) * std::sin(th) - a3 * std::sin(3 * th));
    const double z = -M * ((1 - a1) * std::cos(th) + a3 * std::cos(3 * th));
    if (y < -1e-12 * beam_m || z < prev_z - 1e-12 * draught_m) refuse("the mapped contour is re-entrant");
    prev_z = z;
    out.push_back({std::max(0.0, y), z});
  }
  out.front()[0] = 0.0;
  out.back() = {0.5 * beam_m, 0.0};
  return out;
}

}  // namespace hullopt::sk
