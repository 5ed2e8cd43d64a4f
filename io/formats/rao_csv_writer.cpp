#include "io/formats/rao_csv_writer.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "io/formats/atomic_file.h"
#include "io/formats/input_error.h"

namespace hullopt::io {

std::string FormatRaoCsv(const sk::RaoTable& t, double length_m, const std::vector<std::string>& notes) {
  const std::size_t n = t.omega_rad_s.size();
  if (t.omega_e_rad_s.size() != n || t.heave.size() != n || t.pitch.size() != n)
    throw std::invalid_argument("RAO table columns differ in length");
  if (!(length_m > 0.0))
    throw std::invalid_argument("RAO table: ship length L must be > 0 for lambda_over_L");
  std::ostringstream os;
  os << "# hullopt rao: heave and pitch response amplitude operators in regular head seas (180 deg)\n"
     << "# axes: x forward, z up, origin at the CG; heave x3 positive up, pitch x5 positive bow-down\n"
     << "# wave elevation A cos(omega_e t) at the CG; k = omega^2/g (deep water); omega_e = omega + omega^2 "
        "U/g\n"
     << "# heave_amp = |x3|/A [m/m]; pitch_amp = |x5|/(kA) [rad/rad]; lambda_over_L = 2 pi g/(omega^2 L)\n"
     << "# phases in degrees relative to the wave crest at the CG, phase lead positive\n"
     << std::setprecision(10) << "# U = " << t.speed_m_s << " m/s, g = " << t.g_m_s2
     << " m/s^2, L = " << length_m << " m\n";
  for (const auto& note : notes) os << "# " << note << "\n";
  os << "omega_e_rad_s,omega_rad_s,lambda_over_L,heave_amp,heave_phase_deg,pitch_amp,pitch_phase_deg\n";
  for (std::size_t i = 0; i < n; ++i) {
    const double w = t.omega_rad_s[i];
    const double lambda_over_L = 2.0 * M_PI * t.g_m_s2 / (w * w) / length_m;
    const double v[7] = {t.omega_e_rad_s[i],
                         w,
                         lambda_over_L,
                         std::abs(t.heave[i]),
                         std::arg(t.heave[i]) * 180 / M_PI,
                         std::abs(t.pitch[i]),
                         std::arg(t.pitch[i]) * 180 / M_PI};
    for (double x : v) {
      if (!std::isfinite(x)) {
        std::ostringstream e;
        e << "non-finite RAO value at omega = " << w << " rad/s (omega_e = " << t.omega_e_rad_s[i]
          << " rad/s): not written";
        throw std::domain_error(e.str());
      }
    }
    for (int j = 0; j < 7; ++j) os << (j ? "," : "") << v[j];
    os << "\n";
  }
  return os.str();
}

std::string FormatObliqueRaoCsv(const sk::ObliqueStripResult& r, double speed_m_s, double g_m_s2,
                                double length_m, const std::vector<std::string>& notes) {
  if (!(length_m > 0.0))
    throw std::invalid_argument("RAO table: ship length L must be > 0 for lambda_over_L");
  std::ostringstream os;
  os << "# hullopt rao: response amplitude operators in regular oblique seas (solver.headings_deg)\n"
     << "# axes: x forward, y to port, z up, rotations about the CG; heave x3 positive up, pitch x5 positive "
        "bow-down, sway x2 positive to port, roll x4 positive starboard-down, yaw x6 positive bow to port\n"
     << "# wave_direction_deg: the heading beta, the direction the waves travel, from +x counter-clockwise "
        "seen "
        "from above (180 head seas, 90 beam seas from starboard)\n"
     << "# wave elevation A cos(omega_e t) at the CG; k = omega^2/g (deep water); omega_e = omega - omega^2 "
        "U "
        "cos(heading)/g\n"
     << "# heave_amp, sway_amp = |x|/A [m/m]; pitch_amp, roll_amp, yaw_amp = |x|/(kA) [rad/rad]; "
        "lambda_over_L = "
        "2 pi g/(omega^2 L)\n"
     << "# phases in degrees relative to the wave crest at the CG, phase lead positive\n"
     << std::setprecision(10) << "# U = " << speed_m_s << " m/s, g = " << g_m_s2 << " m/s^2, L = " << length_m
     << " m\n";
  for (const auto& note : notes) os << "# " << note << "\n";
  os << "wave_direction_deg,omega_e_rad_s,omega_rad_s,lambda_over_L,heave_amp,heave_phase_deg,pitch_amp,"
        "pitch_phase_deg,"
        "sway_amp,sway_phase_deg,roll_amp,roll_phase_deg,yaw_amp,yaw_phase_deg\n";
  for (const sk::ObliqueWaveResult& wr : r.waves) {
    const double w = wr.omega_rad_s;
    std::vector<double> v = {wr.heading_deg, wr.omega_e_rad_s, w, 2.0 * M_PI * g_m_s2 / (w * w) / length_m};
    for (int d : {2, 4, 1, 3, 5}) {  // heave, pitch, sway, roll, yaw
      v.push_back(std::abs(wr.rao[d]));
      v.push_back(std::arg(wr.rao[d]) * 180 / M_PI);
    }
    for (double x : v)
      if (!std::isfinite(x)) {
        std::ostringstream e;
        e << "non-finite RAO value at heading " << wr.heading_deg << " deg, omega = " << w
          << " rad/s (omega_e = " << wr.omega_e_rad_s << " rad/s): not written";
        throw std::domain_error(e.str());
      }
    for (std::size_t j = 0; j < v.size(); ++j) os << (j ? "," : "") << v[j];
    os << "\n";
  }
  return os.str();
}

void WriteObliqueRaoCsv(const std::string& path, const sk::ObliqueStripResult& result, double speed_m_s,
                        double g_m_s2, double length_m, const std::vector<std::string>& notes) {
  WriteFileAtomically(path, FormatObliqueRaoCsv(result, speed_m_s, g_m_s2, length_m, notes));
}

void WriteRaoCsv(const std::string& path, const sk::RaoTable& table, double length_m,
                 const std::vector<std::string>& notes) {
  const std::string text = FormatRaoCsv(table, length_m, notes);
  WriteFileAtomically(path, text);
}

}  // namespace hullopt::io
