#pragma once
// Deep-water pulsating-source Green function of the 2D strip plane (y, z), free surface z = 0, fluid z < 0,
// time factor e^{iωt} (physical quantity = Re[complex amplitude · e^{iωt}]), wavenumber ν = ω²/g.
//
// Source at q = (η, ζ), field point p = (y, z); Y = y − η, Z = z + ζ (<= 0), ζc = Z + i|Y|, r = |p − q|,
// r' = |p − q̄| = |ζc| with q̄ = (η, −ζ):
//
//   G = ln r − ln r' − 2 PV∫₀^∞ e^{kZ} cos(kY) / (k − ν) dk + 2πi e^{νZ} cos(νY)
//     = ln r − ln r' − 2 Re[e^{νζc} E1(νζc)] + 2πi e^{ν conj(ζc)}
//     = ln r + ln r' + Gs,    Gs = 2 ln ν − 2 Re g(νζc) + 2πi e^{ν conj(ζc)},   g(w) = e^w E1(w) + ln w.
//
// G satisfies G_z − νG = 0 on z = 0 and, for |Y| → ∞, G → 2πi e^{νZ} e^{−iν|Y|}: outgoing waves with e^{iωt}.
// (Wehausen & Laitone 1960 §13 form; the closed form follows from PV∫₀^∞ e^{−ks}/(k − ν) dk = e^{−νs} E1(−νs)
// + iπ e^{−νs} with the contour passing above the pole.) The split into ln r + ln r' (integrated over a panel
// in closed form by rankine_panel.h) and the smooth remainder Gs (continuous, with a log-singular gradient
// only at ζc = 0) is what the panel solver integrates with Gauss–Legendre.
#include <complex>

namespace hullopt::sk {

/// Value [-] and field-point gradient [1/m] of a part of the Green function.
struct WaveGreenValue {
  std::complex<double> value;
  std::complex<double> dy;  ///< ∂/∂y at the field point
  std::complex<double> dz;  ///< ∂/∂z at the field point
};

/// The smooth part Gs (see above) for wavenumber nu [1/m] > 0, Y = y − η [m], Z = z + ζ <= 0 [m].
WaveGreenValue SmoothWaveGreen(double nu, double Y, double Z);
/// The same with two_log_nu = 2 ln ν given (a panel integral evaluates Gs at many points of one ν).
WaveGreenValue SmoothWaveGreen(double nu, double two_log_nu, double Y, double Z);

/// sum += Σ_k weight[k] · Gs at the field point (y, z) for sources at (eta[k], zeta[k]), k < count: the
/// quadrature of a panel segment in one call.
void AddWeightedSmoothWaveGreen(double nu, double two_log_nu, double y, double z, int count, const double* eta,
                                const double* zeta, const double* weight, WaveGreenValue* sum);

/// The whole Green function G at p = (y, z) for a source at (eta, zeta), both with z, ζ <= 0 and p ≠ q.
WaveGreenValue PulsatingSourceGreen(double nu, double y, double z, double eta, double zeta);

}  // namespace hullopt::sk
