#pragma once
// Calm-water resistance of a hull at a speed: R_T = (1 + k) R_F + R_W + R_h, P_E = R_T U.
//   R_F  ITTC-1957 friction line on each body's wetted surface at its own Reynolds number U L_body / ν;
//   1+k  form factor, default 1 (the ITTC-1957 procedure: the line itself was drawn steeper than a flat-plate
//        line to absorb part of the form effect; set it for a two-dimensional (ITTC-1978) extrapolation);
//   R_W  Michell's integral with the multihull interference (michell_integral.h);
//   R_h  the dry-transom hydrostatic pressure deficit (dry_transom.h).
// Coefficients divide by ½ ρ U² S with S the total wetted surface.
#include <string>
#include <vector>

#include "parametric_hull/hull_form.h"
#include "resistance/centre_plane.h"
#include "resistance/michell_integral.h"
#include "resistance/dry_transom.h"

namespace hullopt::res {

struct ResistanceOptions {
  double form_factor = 1.0;               ///< 1 + k, in [1, 2]
  /// [m^2/s] kinematic viscosity; 0 = 15 °C fresh or sea water chosen by the density (water_viscosity.h)
  double kinematic_viscosity_m2_s = 0.0;
  int surface_points = 64;                ///< girth points per station for the wetted surface (>= 4)
  MichellOptions michell;
  bool IsValid(std::string* error) const;
};

struct ResistanceAtSpeed {
  double U_m_s = 0.0;
  double Fn = 0.0;               ///< U / √(g L), L of the main body
  double Re = 0.0;               ///< U L / ν of the main body
  double C_F = 0.0;              ///< ITTC-1957 coefficient of the main body
  double S_m2 = 0.0;             ///< [m^2] wetted surface, all bodies
  double R_F_N = 0.0;            ///< [N] frictional resistance (without the form factor)
  double R_V_N = 0.0;            ///< [N] viscous resistance (1 + k) R_F
  double R_W_N = 0.0;            ///< [N] wave resistance
  double R_H_N = 0.0;            ///< [N] dry-transom hydrostatic deficit
  double R_T_N = 0.0;            ///< [N] total
  double C_W = 0.0, C_T = 0.0;   ///< on ½ ρ U² S
  double P_E_W = 0.0;            ///< [W] effective power R_T U
  double wave_tail_bound_N = 0.0;  ///< [N] bound on the Michell tail beyond lambda_max (not in R_W)
  double transom_Fn = 0.0;       ///< U / √(g T_transom), 0 without a transom
  /// Why the numbers are doubtful (empty if they are not): a wet-transom speed, a tail above 1 % of R_W.
  std::string warning;
};

/// The hull's resistance model: the centre-plane grids, wetted surfaces and transom are computed once.
class CalmWaterResistance {
 public:
  /// Throws std::invalid_argument for invalid options or a hull without wet stations.
  CalmWaterResistance(const hull::HullForm& hull, const ResistanceOptions& options);
  /// At speed U_m_s > 0 in water of density rho_kg_m3 and gravity g_m_s2 (std::invalid_argument otherwise).
  ResistanceAtSpeed At(double U_m_s, double rho_kg_m3, double g_m_s2) const;
  double WettedSurface_m2() const { return surface_total_; }
  double MainLength_m() const { return body_length_.empty() ? 0.0 : body_length_[0]; }
  const TransomGeometry& Transom() const { return transom_; }

 private:
  ResistanceOptions options_;
  std::vector<CentrePlaneGrid> grids_;
  std::vector<double> body_surface_;  // [m^2] per body, mirror pairs doubled
  std::vector<double> body_length_;   // [m] wetted length per body
  double surface_total_ = 0.0;
  TransomGeometry transom_;
};

}  // namespace hullopt::res
