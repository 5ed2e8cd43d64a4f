#pragma once
// Wigley's parabolic hull, f(x, z) = (B/2) (1 - (2x'/L)²) (1 - (d/T)²) (x' from midships, d depth below the
// waterline), as hullopt stations, with its analytic Michell amplitude function for the tests.
#include <cmath>
#include <complex>

#include "parametric_hull/hull_form.h"

namespace hullopt::test {

/// Wigley hull of length L, beam B, draught T: `stations` stations from AP (x = 0) to FP (x = L), each a
/// polyline of `points` points from the keel (d = T) to the deck (z = T + freeboard, wall-sided above the
/// waterline). The end stations have zero breadth.
inline hull::Demihull WigleyBody(double L, double B, double T, int stations, int points, double y_centre = 0.0) {
  hull::Demihull body;
  body.role = y_centre > 0.0 ? "demihull" : "main";
  body.y_centre_m = y_centre;
  for (int i = 0; i < stations; ++i) {
    hull::Station st;
    st.x_m = L * i / (stations - 1);
    const double xi = 2.0 * st.x_m / L - 1.0;
    const double wx = 1.0 - xi * xi;
    for (int k = 0; k < points; ++k) {
      const double d = T * (1.0 - double(k) / (points - 1));  // from the keel (d = T) up to the waterline
      st.y_m.push_back(0.5 * B * wx * (1.0 - (d / T) * (d / T)));
      st.z_m.push_back(T - d);
    }
    st.y_m.push_back(st.y_m.back());  // wall-sided above the waterline
    st.z_m.push_back(T + 0.5 * T);
    body.stations.push_back(st);
  }
  return body;
}

inline hull::HullForm WigleyHull(double L, double B, double T, int stations, int points) {
  hull::HullForm h;
  h.type = "monohull";
  h.draught_m = T;
  h.length_m = L;
  h.bodies.push_back(WigleyBody(L, B, T, stations, points));
  return h;
}

inline hull::HullForm WigleyCatamaran(double L, double B, double T, double spacing, int stations, int points) {
  hull::HullForm h = WigleyHull(L, B, T, stations, points);
  h.type = "catamaran";
  h.bodies[0] = WigleyBody(L, B, T, stations, points, 0.5 * spacing);
  return h;
}

/// Analytic amplitude function of the Wigley hull, I(λ) = ∫∫ f_x e^{-k0 λ² d} e^{i k0 λ x'} dx' dd with x'
/// from midships (a phase shift of the x-from-AP form, irrelevant to |I|): the x integral
///   ∫_{-c}^{c} (-8x/L²) e^{iax} dx = -(16 i/L²) (sin(ac)/a² - c cos(ac)/a),  c = L/2, a = k0 λ,
/// and the depth integral ∫_0^T (1 - d²/T²) e^{-bd} dd in closed form, b = k0 λ².
inline std::complex<double> WigleyAmplitude(double L, double B, double T, double k0, double lambda) {
  const double a = k0 * lambda, b = k0 * lambda * lambda, c = 0.5 * L;
  const std::complex<double> X =
      std::complex<double>(0.0, -16.0 / (L * L)) * (std::sin(a * c) / (a * a) - c * std::cos(a * c) / a);
  const double e = std::exp(-b * T);
  const double i0 = (1.0 - e) / b;
  const double i2 = 2.0 / (b * b * b) - e * (T * T / b + 2.0 * T / (b * b) + 2.0 / (b * b * b));
  return 0.5 * B * X * (i0 - i2 / (T * T));
}

}  // namespace hullopt::test
