#include "parametric_hull/hydrostatics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "parametric_hull/section_geometry.h"

namespace hullopt::hull {
namespace {

std::vector<double> StationX(const Demihull& body) {
  std::vector<double> x;
  x.reserve(body.stations.size());
  for (const auto& s : body.stations) x.push_back(s.x_m);
  return x;
}

double Multiplicity(const Demihull& body) { return body.y_centre_m > 0.0 ? 2.0 : 1.0; }

void CheckHull(const HullForm& hull) {
  if (hull.bodies.empty() || hull.bodies[0].stations.empty())
    throw std::invalid_argument("hydrostatics: the hull has no main body with stations");
  if (!(hull.draught_m > 0.0))
    throw std::invalid_argument("hydrostatics: draught must be > 0 m, got " + std::to_string(hull.draught_m));
}

}  // namespace

int ReferenceHullCount(const HullForm& hull) {
  int n = 0;
  for (const auto& b : hull.bodies)
    if (b.role != "outrigger") n += b.y_centre_m > 0.0 ? 2 : 1;
  return std::max(n, 1);
}

double DisplacedVolume(const HullForm& hull) {
  CheckHull(hull);
  double v = 0.0;
  for (const auto& body : hull.bodies) {
    const std::vector<double> w = LongitudinalWeights(StationX(body));
    double vb = 0.0;
    for (size_t i = 0; i < body.stations.size(); ++i)
      vb += w[i] * 2.0 * ComputeSectionProperties(body.stations[i], hull.draught_m).area_m2;
    v += Multiplicity(body) * vb;
  }
  return v;
}

Hydrostatics ComputeHydrostatics(const HullForm& hull, double rho_kg_m3, double kg_m) {
  CheckHull(hull);
  if (!(rho_kg_m3 > 0.0))
    throw std::invalid_argument("hydrostatics: water density must be > 0 kg/m^3, got " +
                                std::to_string(rho_kg_m3));
  const double T = hull.draught_m;
  Hydrostatics h;
  h.T_m = T;
  h.kg_m = kg_m;
  h.reference_hulls = ReferenceHullCount(hull);

  // Main body: waterline extent and maximum breadth.
  const Demihull& main = hull.bodies[0];
  double x_first = INFINITY, x_last = -INFINITY, half_b = 0.0;
  for (const auto& s : main.stations) {
    const SectionProperties p = ComputeSectionProperties(s, T);
    if (!p.wet) continue;
    x_first = std::min(x_first, s.x_m);
    x_last = std::max(x_last, s.x_m);
    half_b = std::max(half_b, p.max_half_breadth_m);
  }
  if (!std::isfinite(x_first)) throw std::domain_error("hydrostatics: no station of the main body is wetted");
  h.x_ap_m = x_first;
  h.L_m = hull.length_m > 0.0 ? hull.length_m : x_last - x_first;
  h.B_m = 2.0 * half_b;

  // Totals over bodies: volume and moments, waterplane and moments, girth.
  double vol = 0.0, mx = 0.0, mz = 0.0, awp = 0.0, ax = 0.0, axx = 0.0, it_own = 0.0, it_offset = 0.0,
         ws = 0.0;
  for (const auto& body : hull.bodies) {
    if (body.stations.empty()) continue;
    const double m = Multiplicity(body);
    const std::vector<double> w = LongitudinalWeights(StationX(body));
    for (size_t i = 0; i < body.stations.size(); ++i) {
      const Station& s = body.stations[i];
      const SectionProperties p = ComputeSectionProperties(s, T);
      if (!p.wet) continue;
      const double a = 2.0 * p.area_m2, yw = p.waterline_half_breadth_m, bw = 2.0 * yw;
      const double wi = m * w[i];
      vol += wi * a;
      mx += wi * a * s.x_m;
      mz += wi * 2.0 * p.moment_z_m3;
      awp += wi * bw;
      ax += wi * bw * s.x_m;
      axx += wi * bw * s.x_m * s.x_m;
      it_own += wi * (2.0 / 3.0) * yw * yw * yw;
      it_offset += wi * bw * body.y_centre_m * body.y_centre_m;
      ws += wi * 2.0 * p.girth_m;
    }
  }
  if (!(vol > 0.0))
    throw std::domain_error("hydrostatics: the hull displaces no water at draught " + std::to_string(T) +
                            " m");
  if (!(awp > 0.0))
    throw std::domain_error("hydrostatics: the hull has no waterplane at draught " + std::to_string(T) +
                            " m");

  h.volume_m3 = vol;
  h.displacement_kg = rho_kg_m3 * vol;
  h.displacement_t = h.displacement_kg / 1000.0;
  h.lcb_m_from_ap = mx / vol;
  h.vcb_m = mz / vol;
  h.awp_m2 = awp;
  h.lcf_m_from_ap = ax / awp;
  h.i_l_m4 = axx - awp * h.lcf_m_from_ap * h.lcf_m_from_ap;  // parallel-axis shift to the LCF
  h.i_t_m4 = it_own + it_offset;
  h.bm_l_m = h.i_l_m4 / vol;
  h.bm_t_m = h.i_t_m4 / vol;
  h.gm_l_m = h.vcb_m + h.bm_l_m - kg_m;
  h.gm_t_m = h.vcb_m + h.bm_t_m - kg_m;
  h.wetted_surface_m2 = ws;

  // Midship section of all bodies.
  const double x_mid = h.x_ap_m + 0.5 * h.L_m;
  for (const auto& body : hull.bodies) {
    if (body.stations.empty()) continue;
    h.midship_area_m2 +=
        Multiplicity(body) * 2.0 * ComputeSectionProperties(InterpolateStation(body, x_mid), T).area_m2;
  }

  const double n = h.reference_hulls, L = h.L_m, B = h.B_m;
  if (L > 0.0 && B > 0.0) {
    h.Cb = vol / (n * L * B * T);
    h.Cm = h.midship_area_m2 / (n * B * T);
    h.Cwp = awp / (n * L * B);
  }
  if (h.midship_area_m2 > 0.0 && L > 0.0) h.Cp = vol / (L * h.midship_area_m2);
  h.Cvp = vol / (awp * T);
  if (L > 0.0) {
    h.LCB_pct_L = (h.lcb_m_from_ap - x_mid) / L * 100.0;
    h.LCF_pct_L = (h.lcf_m_from_ap - x_mid) / L * 100.0;
  }
  return h;
}

}  // namespace hullopt::hull
