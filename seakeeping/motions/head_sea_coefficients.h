#pragma once
// Frequency-domain coefficients of the heave–pitch equations of one hull at one speed in head seas, taken from
// the same strip force the RAOs use: per encounter frequency the added mass A_ij, damping B_ij, restoring C_ij
// (i, j = 3, 5) and the exciting force and moment, split into Froude–Krylov, diffraction and the Cs term.
//
// Axes and signs as head_sea_ship_model.h: origin at the CG, heave x3 up, pitch x5 bow-down, F5 the moment
// about +y (bow-down positive). Motion x_j = Re(X_j e^{iω_e t}); the hull force on the left of the equations is
// −(−ω_e² A_ij + iω_e B_ij + C_ij) X_j, so that
//   Σ_j [−ω_e² (M_ij + A_ij) + iω_e B_ij + C_ij] X_j = F_i A,
// M = diag(M, I5). A_ij and B_ij hold everything of the strip force that moves with the hull (the strip
// kernel or the 2D sections, with their forward-speed terms, plus the Cs damping ½ Cs ρ U B v); C_ij only the
// hydrostatic strip sums (ρ g Σ B w, −ρ g Σ B x w, ρ g Σ B x² w). A speed-dependent in-phase force therefore
// appears in A_ij, as it does in a forced-oscillation test that subtracts the hydrostatic C.
// Exciting F_i per unit wave amplitude, for the wave A cos(ω_e t) at the CG: F = Re(F̂ A e^{iω_e t}).
// A_ij: kg (33), kg m (35, 53), kg m² (55); B_ij: kg/s, kg m/s, kg m²/s; F3 N/m, F5 N m/m.
#include <array>
#include <complex>

namespace hullopt::sk {

struct HeadSeaCoefficients {
  double omega_rad_s = 0.0;    ///< [rad/s] wave frequency ω
  double omega_e_rad_s = 0.0;  ///< [rad/s] encounter frequency ω_e
  /// [rad/s] the frequency the motion derivatives use (ω_e, or the trapezoid's Ω for PeriodicKinematics::
  /// kTrapezoid); A and B are defined with it so that the equations above reproduce the RAOs exactly.
  double motion_omega_rad_s = 0.0;
  double k_rad_m = 0.0;  ///< [rad/m] wave number ω²/g
  double mass_kg = 0.0, inertia_kg_m2 = 0.0;
  /// Hull force i per unit amplitude of motion j (index 0 heave, 1 pitch) from everything that moves with the
  /// hull except hydrostatics: ω² A − iω B.
  std::complex<double> moving[2][2] = {{0.0, 0.0}, {0.0, 0.0}};
  double restoring[2][2] = {{0.0, 0.0}, {0.0, 0.0}};  ///< C_ij [N/m, N, N, N m] (C35 per rad)
  /// Exciting force (0) and moment (1) per unit wave amplitude: the incident wave's pressure, the diffraction
  /// (the strip force from the incident-wave normal velocity) and the Cs damping's wave part.
  std::complex<double> froude_krylov[2] = {0.0, 0.0};
  std::complex<double> diffraction[2] = {0.0, 0.0};
  std::complex<double> damping_wave[2] = {0.0, 0.0};

  double A(int i, int j) const { return moving[i][j].real() / (motion_omega_rad_s * motion_omega_rad_s); }
  double B(int i, int j) const { return -moving[i][j].imag() / motion_omega_rad_s; }
  std::complex<double> Exciting(int i) const { return froude_krylov[i] + diffraction[i] + damping_wave[i]; }
  /// X3/A and X5/(kA) from the equations above (Cramer's rule: non-finite entries propagate).
  std::array<std::complex<double>, 2> Solve() const;
};

}  // namespace hullopt::sk
