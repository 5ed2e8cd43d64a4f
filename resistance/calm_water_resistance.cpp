#include "resistance/calm_water_resistance.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "resistance/friction_line.h"
#include "resistance/water_viscosity.h"
#include "resistance/wetted_surface.h"

namespace hullopt::res {
namespace {
// A Michell tail bound above this fraction of R_W is reported: the truncation may then matter at the 1 % level.
constexpr double kTailWarnFraction = 0.01;
}  // namespace

bool ResistanceOptions::IsValid(std::string* error) const {
  std::ostringstream os;
  if (!(form_factor >= 1.0 && form_factor <= 2.0))
    os << "form_factor = " << form_factor << ": 1 + k must be in [1, 2]";
  else if (!(kinematic_viscosity_m2_s == 0.0 || (kinematic_viscosity_m2_s >= 1e-7 && kinematic_viscosity_m2_s <= 1e-4)))
    os << "kinematic_viscosity_m2_s = " << kinematic_viscosity_m2_s
       << ": must be 0 (from the density) or in [1e-7, 1e-4] m^2/s (water is ~1.1e-6)";
  else if (surface_points < 4 || surface_points > 4096)
    os << "surface_points = " << surface_points << ": must be in [4, 4096]";
  else if (!michell.IsValid(error))
    return false;
  if (os.str().empty()) return true;
  if (error) *error = os.str();
  return false;
}

CalmWaterResistance::CalmWaterResistance(const hull::HullForm& hull, const ResistanceOptions& options)
    : options_(options) {
  std::string err;
  if (!options.IsValid(&err)) throw std::invalid_argument("resistance: " + err);
  grids_ = SampleCentrePlanes(hull, options.michell.depth_points);
  for (const auto& b : hull.bodies) {
    const double m = b.y_centre_m > 0.0 ? 2.0 : 1.0;
    body_surface_.push_back(m * BodyWettedSurface(b, hull.draught_m, options.surface_points));
    surface_total_ += body_surface_.back();
  }
  for (const auto& g : grids_) body_length_.push_back(g.x_m.back() - g.x_m.front());
  transom_ = ComputeTransomGeometry(hull);
}

ResistanceAtSpeed CalmWaterResistance::At(double U, double rho, double g) const {
  if (!(U > 0.0) || !std::isfinite(U))
    throw std::invalid_argument("resistance: speed U = " + std::to_string(U) + " m/s: must be > 0");
  if (!(rho > 0.0) || !(g > 0.0)) throw std::invalid_argument("resistance: density and gravity must be > 0");
  const double nu = options_.kinematic_viscosity_m2_s > 0.0 ? options_.kinematic_viscosity_m2_s
                                                            : ViscosityForDensity(rho);
  ResistanceAtSpeed r;
  r.U_m_s = U;
  const double q = 0.5 * rho * U * U;
  r.S_m2 = surface_total_;
  for (size_t j = 0; j < grids_.size(); ++j) {
    const double re = U * body_length_[j] / nu;
    const double cf = Ittc1957FrictionCoefficient(re);
    if (j == 0) {
      r.Re = re;
      r.C_F = cf;
    }
    r.R_F_N += q * body_surface_[j] * cf;
  }
  r.R_V_N = options_.form_factor * r.R_F_N;
  const WaveResistanceResult w = MichellWaveResistance(grids_, U, g, rho, options_.michell);
  r.R_W_N = w.R_W_N;
  r.wave_tail_bound_N = w.tail_bound_N;
  r.R_H_N = rho * g * transom_.first_moment_m3;
  r.R_T_N = r.R_V_N + r.R_W_N + r.R_H_N;
  r.C_W = r.R_W_N / (q * r.S_m2);
  r.C_T = r.R_T_N / (q * r.S_m2);
  r.P_E_W = r.R_T_N * U;
  r.Fn = U / std::sqrt(g * MainLength_m());
  std::ostringstream warn;
  if (transom_.max_depth_m > 0.0) {
    r.transom_Fn = U / std::sqrt(g * transom_.max_depth_m);
    if (r.transom_Fn < kDryTransomFroude)
      warn << "transom Froude number " << r.transom_Fn << " < " << kDryTransomFroude
           << ": the transom may not run dry (dry-transom model outside its range)";
  }
  if (w.tail_bound_N > kTailWarnFraction * w.R_W_N) {
    if (!warn.str().empty()) warn << "; ";
    warn << "Michell tail bound " << w.tail_bound_N << " N > 1% of R_W " << w.R_W_N << " N (raise lambda_max)";
  }
  r.warning = warn.str();
  return r;
}

}  // namespace hullopt::res
