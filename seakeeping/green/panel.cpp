#include "seakeeping/green/panel.h"

#include <stdexcept>
#include <string>

namespace hullopt::sk {

std::vector<Panel> PanelSymmetricSection(const std::vector<std::array<double, 2>>& half_contour, int n_panels,
                                         double y_centre_m) {
  if (half_contour.size() < 2) throw std::invalid_argument("section contour needs at least 2 points");
  if (n_panels < 4 || n_panels % 2 != 0)
    throw std::invalid_argument("panels per section must be even and >= 4, got " + std::to_string(n_panels));
  const double scale = std::fabs(half_contour.front()[1]) + 1e-300;
  if (std::fabs(half_contour.front()[0]) > 1e-9 * scale + 1e-12)
    throw std::invalid_argument("section contour must start on the centreline (y = 0) at the keel");
  if (std::fabs(half_contour.back()[1]) > 1e-9 * scale + 1e-12)
    throw std::invalid_argument("section contour must end at the waterline (z = 0)");
  // Cumulative arc length of the half contour, keel (s = 0) to waterline (s = S).
  std::vector<double> s(half_contour.size(), 0.0);
  for (std::size_t i = 1; i < half_contour.size(); ++i)
    s[i] = s[i - 1] + std::hypot(half_contour[i][0] - half_contour[i - 1][0],
                                 half_contour[i][1] - half_contour[i - 1][1]);
  const double S = s.back();
  if (!(S > 0)) throw std::invalid_argument("section contour has zero girth");
  auto at = [&](double si) {
    std::size_t k = 1;
    while (k + 1 < s.size() && s[k] < si) ++k;
    const double seg = s[k] - s[k - 1];
    const double f = seg > 0 ? (si - s[k - 1]) / seg : 0.0;
    return std::array<double, 2>{half_contour[k - 1][0] + f * (half_contour[k][0] - half_contour[k - 1][0]),
                                 half_contour[k - 1][1] + f * (half_contour[k][1] - half_contour[k - 1][1])};
  };
  // Half-cosine spacing on the half girth: fine at the waterline (s = S), moderate at the keel.
  const int nh = n_panels / 2;
  std::vector<std::array<double, 2>> pts(nh + 1);
  for (int i = 0; i <= nh; ++i) {
    const double t = static_cast<double>(i) / nh;
    pts[i] = at(S * std::sin(0.5 * M_PI * t));
  }
  pts[0] = {0.0, half_contour.front()[1]};
  pts[nh] = {half_contour.back()[0], 0.0};
  std::vector<Panel> panels;
  panels.reserve(n_panels);
  // Port side: waterline down to keel (y > 0).
  for (int i = nh; i > 0; --i)
    panels.push_back({y_centre_m + pts[i][0], pts[i][1], y_centre_m + pts[i - 1][0], pts[i - 1][1]});
  // Starboard side: keel up to waterline (y < 0).
  for (int i = 0; i < nh; ++i)
    panels.push_back({y_centre_m - pts[i][0], pts[i][1], y_centre_m - pts[i + 1][0], pts[i + 1][1]});
  return panels;
}

}  // namespace hullopt::sk
