#include "io/formats/coefficients_csv_writer.h"

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <stdexcept>

#include "io/formats/input_error.h"

namespace hullopt::io {

std::string FormatCoefficientsCsv(const sk::CoefficientTable& t, double length_m,
                                  const std::vector<std::string>& notes) {
  if (!(length_m > 0.0)) throw std::invalid_argument("coefficients: ship length L must be > 0");
  std::ostringstream os;
  os << std::setprecision(10);
  os << "# hullopt coefficients: heave-pitch added mass, damping, restoring and exciting loads in head seas\n"
     << "# axes: x forward, z up, origin at the CG; heave x3 up, pitch x5 bow-down, F5 moment bow-down positive\n"
     << "# equations: sum_j [-omega_e^2 (M_ij + A_ij) + i omega_e B_ij + C_ij] X_j = F_i A "
        "(M = diag(mass, pitch inertia))\n"
     << "# A_ij, B_ij: force i per motion j of everything that moves with the hull (strip kernel or 2D "
        "sections with their forward-speed terms, plus the Cs damping); C_ij: hydrostatic strip sums only\n"
     << "# F_i per unit wave amplitude for the wave A cos(omega_e t) at the CG; F = FK + diff + Cs "
        "(Froude-Krylov, diffraction, wave part of the Cs damping); phases in deg, lead positive\n"
     << "# U = " << t.speed_m_s << " m/s, g = " << t.g_m_s2 << " m/s^2, L = " << length_m
     << " m, strip step dt = " << t.dt_s << " s\n";
  if (!t.rows.empty())
    os << "# mass = " << t.rows[0].mass_kg << " kg, pitch inertia = " << t.rows[0].inertia_kg_m2
       << " kg m^2 (the ship's, not part of A_ij)\n";
  for (const auto& n : notes) os << "# " << n << "\n";
  os << "omega_e_rad_s,omega_rad_s,lambda_over_L,omega_e_sqrt_L_over_g,A33_kg,B33_kg_per_s,A35_kg_m,"
        "B35_kg_m_per_s,A53_kg_m,B53_kg_m_per_s,A55_kg_m2,B55_kg_m2_per_s,C33_N_per_m,C35_N_per_rad,C53_N,"
        "C55_N_m_per_rad";
  const char* dof[2] = {"F3", "F5"};
  const char* unit[2] = {"N_per_m", "N_m_per_m"};
  const char* part[4] = {"", "_FK", "_diff", "_Cs"};
  for (int i = 0; i < 2; ++i)
    for (int p = 0; p < 4; ++p) os << "," << dof[i] << part[p] << "_amp_" << unit[i] << "," << dof[i] << part[p] << "_phase_deg";
  os << "\n";
  for (const auto& c : t.rows) {
    const double w = c.omega_rad_s;
    std::vector<double> v = {c.omega_e_rad_s, w, 2.0 * M_PI * t.g_m_s2 / (w * w) / length_m,
                             c.omega_e_rad_s * std::sqrt(length_m / t.g_m_s2)};
    for (auto ij : {std::pair{0, 0}, {0, 1}, {1, 0}, {1, 1}}) {
      v.push_back(c.A(ij.first, ij.second));
      v.push_back(c.B(ij.first, ij.second));
    }
    v.insert(v.end(), {c.restoring[0][0], c.restoring[0][1], c.restoring[1][0], c.restoring[1][1]});
    for (int i = 0; i < 2; ++i)
      for (const auto& f : {c.Exciting(i), c.froude_krylov[i], c.diffraction[i], c.damping_wave[i]}) {
        v.push_back(std::abs(f));
        v.push_back(std::arg(f) * 180.0 / M_PI);
      }
    for (double x : v)
      if (!std::isfinite(x)) {
        std::ostringstream e;
        e << "non-finite coefficient at omega = " << w << " rad/s (omega_e = " << c.omega_e_rad_s
          << " rad/s): not written";
        throw std::domain_error(e.str());
      }
    for (std::size_t j = 0; j < v.size(); ++j) os << (j ? "," : "") << v[j];
    os << "\n";
  }
  return os.str();
}

void WriteCoefficientsCsv(const std::string& path, const sk::CoefficientTable& table, double length_m,
                          const std::vector<std::string>& notes) {
  const std::string text = FormatCoefficientsCsv(table, length_m, notes);
  std::ofstream out(path);
  if (!out) throw InputError(path + ": cannot write coefficients.csv");
  out << text;
  if (!out) throw InputError(path + ": error while writing coefficients.csv");
}

}  // namespace hullopt::io
