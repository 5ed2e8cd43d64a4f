#include "seakeeping/green/frequency_domain_green.h"

#include <cmath>

#include "seakeeping/green/exponential_integral.h"

namespace hullopt::sk {

WaveGreenValue SmoothWaveGreen(double nu, double two_log_nu, double Y, double Z) {
  using C = std::complex<double>;
  const double ay = std::fabs(Y);  // +0.0 for Y = 0: E1 taken on the upper side of its cut
  const C w(nu * Z, nu * ay);      // ν ζc
  // e^w once: the radiating term 2πi e^{ν conj ζc} is 2πi conj(e^w).
  const C ew = std::exp(w);
  const C rad(2.0 * M_PI * ew.imag(), 2.0 * M_PI * ew.real());  // 2πi conj(e^w)
  WaveGreenValue out;
  const ScaledExpIntE1Pair e1 = ScaledExpIntE1AndPlusLog(w, ew);
  out.value = two_log_nu - 2.0 * e1.plus_log.real() + rad;
  // d g(νζc)/dζc = ν e^w E1(w): only log-singular at ζc = 0 (the ln ζc of g cancels the −1/ζc of e^w E1).
  const C f = nu * e1.scaled;
  out.dz = -2.0 * f.real() + nu * rad;
  const C d_abs_y = 2.0 * f.imag() - C(-nu * rad.imag(), nu * rad.real());  // ∂/∂|Y|: Re(i f) = −Im f
  out.dy = (Y >= 0 ? 1.0 : -1.0) * d_abs_y;
  return out;
}

WaveGreenValue SmoothWaveGreen(double nu, double Y, double Z) { return SmoothWaveGreen(nu, 2.0 * std::log(nu), Y, Z); }

void AddWeightedSmoothWaveGreen(double nu, double two_log_nu, double y, double z, int count, const double* eta,
                                const double* zeta, const double* weight, WaveGreenValue* sum) {
  for (int k = 0; k < count; ++k) {
    const WaveGreenValue s = SmoothWaveGreen(nu, two_log_nu, y - eta[k], z + zeta[k]);
    sum->value += weight[k] * s.value;
    sum->dy += weight[k] * s.dy;
    sum->dz += weight[k] * s.dz;
  }
}

WaveGreenValue PulsatingSourceGreen(double nu, double y, double z, double eta, double zeta) {
  WaveGreenValue out = SmoothWaveGreen(nu, y - eta, z + zeta);
  const double Y = y - eta, Zm = z - zeta, Zp = z + zeta;
  const double r2 = Y * Y + Zm * Zm, rp2 = Y * Y + Zp * Zp;
  out.value += 0.5 * std::log(r2) + 0.5 * std::log(rp2);
  out.dy += Y / r2 + Y / rp2;
  out.dz += Zm / r2 + Zp / rp2;
  return out;
}

}  // namespace hullopt::sk
