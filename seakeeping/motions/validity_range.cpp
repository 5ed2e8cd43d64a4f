#include "seakeeping/motions/validity_range.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace hullopt::sk {

double MinValidFroudeNumber() { return 1.0 / std::sqrt(2.0 * M_PI); }

double MaxValidLambdaOverL(double Fn) {
  const double s_star = 0.5 * (std::sqrt(2.0) - 1.0);  // root of s² + s = 1/4
  return 2.0 * M_PI * Fn * Fn / (s_star * s_star);
}

std::vector<std::string> ValidityWarnings(double speed_m_s, double length_m, double g_m_s2,
                                          const std::vector<double>& omega_rad_s) {
  std::vector<std::string> w;
  if (!(length_m > 0 && g_m_s2 > 0)) return w;
  const double Fn = speed_m_s / std::sqrt(g_m_s2 * length_m);
  char buf[400];
  if (Fn < MinValidFroudeNumber()) {
    std::snprintf(buf, sizeof buf,
                  "Fn %.3g is below the validity range of the 2D+t strip method (Fn >= %.2f, where the "
                  "transverse wave length 2 pi Fn^2 L reaches the hull length; docs/ship-motions.md): the RAOs "
                  "are outside the method's assumptions",
                  Fn, MinValidFroudeNumber());
    w.push_back(buf);
  }
  const double lam_max = MaxValidLambdaOverL(Fn);
  int outside = 0;
  double longest = 0;
  for (double om : omega_rad_s) {
    const double lam = 2.0 * M_PI * g_m_s2 / (om * om) / length_m;
    if (lam > lam_max) {
      ++outside;
      longest = std::max(longest, lam);
    }
  }
  if (outside > 0) {
    std::snprintf(buf, sizeof buf,
                  "%d of %zu wave frequencies have lambda/L above %.3g (up to %.3g), the validity limit of the "
                  "2D+t strip method at Fn %.3g (tau = U omega_e / g > 1/4: radiated waves must not run ahead "
                  "of the bow; docs/ship-motions.md)",
                  outside, omega_rad_s.size(), lam_max, longest, Fn);
    w.push_back(buf);
  }
  return w;
}

}  // namespace hullopt::sk
