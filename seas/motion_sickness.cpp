#include "seas/motion_sickness.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace hullopt::sk {
namespace {
constexpr double kPi = 3.14159265358979323846;
}

std::string MsiModelName(MsiModel model) {
  switch (model) {
    case MsiModel::kLloyd:
      return "lloyd";
    case MsiModel::kOHanlonMcCauley1974:
      return "ohanlon_mccauley_1974";
    case MsiModel::kMcCauley1976:
      return "mccauley_1976";
    case MsiModel::kIso2631Msdv:
      return "iso_2631";
  }
  return "?";
}
std::string MsiFrequencyName(MsiFrequency f) {
  return f == MsiFrequency::kDisplacementM4M2 ? "displacement_m4_m2" : "acceleration_zero_crossing";
}
std::string AccelerationStatisticName(AccelerationStatistic s) {
  return s == AccelerationStatistic::kMeanAbsolute ? "mean_absolute" : "rms";
}

bool MsiOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = m;
    return false;
  };
  std::ostringstream v;
  v << exposure_h;
  if (!(exposure_h >= 0.1 && exposure_h <= 24.0))
    return fail("exposure_h = " + v.str() + ": must be within 0.1..24 h");
  if ((model == MsiModel::kLloyd || model == MsiModel::kOHanlonMcCauley1974) && exposure_h != 2.0)
    return fail("exposure_h = " + v.str() + ": the " + MsiModelName(model) +
                " fit is for a 2-hour exposure only; use mccauley_1976 or iso_2631 for another");
  if (!(iso_km > 0.0 && iso_km <= 1.0)) {
    std::ostringstream k;
    k << iso_km;
    return fail("iso_km = " + k.str() + ": must be within (0, 1]");
  }
  return true;
}

double StandardNormalCdf(double z) { return 0.5 * std::erfc(-z / std::sqrt(2.0)); }

double MsiLloyd(double a_g, double omega) {
  if (!(a_g > 0.0)) return 0.0;
  const double lw = std::log10(omega);
  const double mu = -0.819 + 2.32 * lw * lw;
  return 100.0 * StandardNormalCdf((std::log10(a_g) - mu) / 0.4);
}

namespace {
double Z1974(double a_g, double f_hz) {
  const double lf = std::log10(f_hz);
  return 2.128 * std::log10(a_g) - 9.277 * lf - 5.809 * lf * lf - 1.851;
}
}  // namespace

double MsiOHanlonMcCauley1974(double a_g, double f_hz) {
  if (!(a_g > 0.0)) return 0.0;
  return 100.0 * StandardNormalCdf(Z1974(a_g, f_hz));
}

double MsiMcCauley1976(double a_g, double f_hz, double t_min) {
  if (!(a_g > 0.0)) return 0.0;
  const double za = Z1974(a_g, f_hz);
  const double zt = 1.134 * za + 1.989 * std::log10(t_min) - 2.904;
  return 100.0 * StandardNormalCdf(za) * StandardNormalCdf(zt);
}

double IsoMotionSicknessDoseValue(double weighted_rms, double exposure_s) {
  return weighted_rms * std::sqrt(exposure_s);
}

double MsiCharacteristicFrequency(const PointMoments& m, MsiFrequency which) {
  if (which == MsiFrequency::kDisplacementM4M2) return m.m2 > 0.0 ? std::sqrt(m.m4 / m.m2) : 0.0;
  return m.m4 > 0.0 ? std::sqrt(m.m6 / m.m4) : 0.0;
}

double MotionSicknessIncidence(const PointMoments& m, const MsiOptions& o, double g) {
  std::string error;
  if (!o.IsValid(&error)) throw std::invalid_argument("MSI options: " + error);
  if (o.model == MsiModel::kIso2631Msdv) {
    const double aw = std::sqrt(std::max(m.m4_iso_wf, 0.0));
    const double vi = o.iso_km * IsoMotionSicknessDoseValue(aw, o.exposure_h * 3600.0);
    return std::min(vi, 100.0);
  }
  const double sigma = m.rms_acceleration_m_s2();
  const double w = MsiCharacteristicFrequency(m, o.frequency);
  if (!(sigma > 0.0) || !(w > 0.0)) return 0.0;
  const double a = (o.statistic == AccelerationStatistic::kMeanAbsolute ? std::sqrt(2.0 / kPi) : 1.0) * sigma;
  const double a_g = a / g;
  switch (o.model) {
    case MsiModel::kLloyd:
      return MsiLloyd(a_g, w);
    case MsiModel::kOHanlonMcCauley1974:
      return MsiOHanlonMcCauley1974(a_g, w / (2.0 * kPi));
    case MsiModel::kMcCauley1976:
      return MsiMcCauley1976(a_g, w / (2.0 * kPi), o.exposure_h * 60.0);
    case MsiModel::kIso2631Msdv:
      break;
  }
  return 0.0;
}

}  // namespace hullopt::sk
