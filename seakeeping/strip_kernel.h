#pragma once
// The frequency-independent response of one water strip as the hull passes through it (ARCHITECTURE §5).
//
// A strip of water fixed in space is entered by the bow at step 0; at step n (n = 0 .. N−1) it holds the hull
// section at x_m[n] (from the AP), one time step dt = dx/U after the previous one, and it is discarded after the
// stern has passed. With the linear body condition on the mean hull every strip sees the same sequence of
// panelled sections, so one strip's linear response describes all of them:
//
//   f_n = Σ_{m ≤ n} force[n][m] · V_m
//
// f_n [N/m]: vertical hydrodynamic force per unit length on the section held at step n, from the disturbance
// potential only (radiation and diffraction together; the incident-wave Froude–Krylov and hydrostatic forces
// and the empirical damping are added by the ship equations), V_m [m/s]: the normal velocity prescribed at the
// collocation points (panel midpoints) of the panels of step m, positive into the fluid, i.e. (body velocity −
// incident-wave velocity) · n. force[n][m] is a row vector over the panels of step m [N/m per m/s].
#include <Eigen/Dense>
#include <vector>

#include "seakeeping/panel.h"

namespace hullopt::sk {

struct StripKernel {
  double speed_m_s = 0.0;  ///< [m/s] ship speed U
  double dx_m = 0.0;       ///< [m] strip advance per step (section spacing)
  double dt_s = 0.0;       ///< [s] time step dx/U
  double rho_kg_m3 = 0.0;  ///< [kg/m³]
  double g_m_s2 = 0.0;     ///< [m/s²]
  std::vector<double> x_m;                                  ///< [m] station from AP held at step n
  std::vector<std::vector<Panel>> panels;                   ///< panels (all bodies in the strip) at step n
  std::vector<std::vector<Eigen::RowVectorXd>> force;       ///< force[n][m], m = 0..n [N/m per m/s]
  int Steps() const { return static_cast<int>(x_m.size()); }
};

}  // namespace hullopt::sk
