#pragma once
// Hand-built strip kernels on a wall-sided box hull, for checking the ship equations against closed forms.
//
// Box: length L, beam B, draught T, stations at the strip midpoints x_n = L − (n + ½)Δx from the AP (bow
// first). Panels: port side (1), bottom (n_bottom), starboard side (1), ordered port waterline → keel →
// starboard waterline as the Panel contract requires.
//
// Kernels:
//  - zero: f_n = 0 (no disturbance potential) → hydrostatics, Froude–Krylov and Cs damping only;
//  - added mass in momentum form: f_n = −(a u_n(t) − a u_{n−1}(t − Δt))/Δt, u_n = Σ c_i V_i the mean vertical
//    relative velocity of the bottom (c_i = n_z,i l_i / Σ n_z² l), and f_0 = −a u_0/Δt as the strip meets the
//    bow. In the continuous limit f = −a (∂/∂t − U ∂/∂x) u plus a bow impulse: the classical slender-body
//    force.
#include <cmath>
#include <vector>

#include "seakeeping/strip/strip_kernel.h"

namespace hullopt::testing {

struct BoxHull {
  double L = 10.0, B = 1.0, T = 0.5;
  int sections = 40;
  int bottom_panels = 4;
  double speed = 7.92;  // Fn 0.8 at L = 10 m
  double rho = 1025.0, g = 9.81;
};

inline std::vector<sk::Panel> BoxPanels(const BoxHull& h) {
  std::vector<sk::Panel> p;
  p.push_back({h.B / 2, 0.0, h.B / 2, -h.T});
  for (int i = 0; i < h.bottom_panels; ++i) {
    const double y1 = h.B / 2 - h.B * i / h.bottom_panels, y2 = h.B / 2 - h.B * (i + 1) / h.bottom_panels;
    p.push_back({y1, -h.T, y2, -h.T});
  }
  p.push_back({-h.B / 2, -h.T, -h.B / 2, 0.0});
  return p;
}

/// added_mass_kg_m = 0 gives the zero kernel.
inline sk::StripKernel BoxKernel(const BoxHull& h, double added_mass_kg_m) {
  sk::StripKernel k;
  k.speed_m_s = h.speed;
  k.dx_m = h.L / h.sections;
  k.dt_s = k.dx_m / h.speed;
  k.rho_kg_m3 = h.rho;
  k.g_m_s2 = h.g;
  const auto panels = BoxPanels(h);
  Eigen::RowVectorXd c(panels.size());
  double norm = 0.0;
  for (std::size_t i = 0; i < panels.size(); ++i)
    norm += std::pow(panels[i].Normal()[1], 2) * panels[i].Length();
  for (std::size_t i = 0; i < panels.size(); ++i) c[i] = panels[i].Normal()[1] * panels[i].Length() / norm;
  for (int n = 0; n < h.sections; ++n) {
    k.x_m.push_back(h.L - (n + 0.5) * k.dx_m);
    k.panels.push_back(panels);
    std::vector<Eigen::RowVectorXd> rows(n + 1, Eigen::RowVectorXd::Zero(panels.size()));
    rows[n] = -added_mass_kg_m / k.dt_s * c;
    if (n >= 1) rows[n - 1] = added_mass_kg_m / k.dt_s * c;
    k.force.push_back(rows);
  }
  return k;
}

}  // namespace hullopt::testing
