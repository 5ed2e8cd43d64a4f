#include "seakeeping/motions/roll_damping.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace hullopt::sk {
namespace {

bool Finite(double v) { return std::isfinite(v); }
bool Positive(double v) { return v > 0.0 && Finite(v); }

// Kawahara et al.'s nondimensional damping B̂ = B/(ρ∇B²) √(B/(2g)), ∇ = L B d Cb: the factor from B̂ to B.
double DimensionalFactor(const RollDampingHull& h, const RollDampingOptions& o) {
  const double volume = h.length_m * h.breadth_m * h.draught_m * h.block_coefficient;
  return o.rho_kg_m3 * volume * h.breadth_m * h.breadth_m * std::sqrt(2.0 * o.g_m_s2 / h.breadth_m);
}

// Ikeda's hull-lift roll damping (Himeno 1981, B_L): B_L = ½ ρ S_L U k_N l_0 l_R (1 − 1.4 OG/l_R +
// 0.7 OG²/(l_0 l_R)), S_L = L d, k_N = 2π d/L + κ (4.1 B/L − 0.045), κ = 0 (Cm <= 0.92), 0.1 (<= 0.97), 0.3
// (above), l_0 = 0.3 d, l_R = 0.5 d; OG positive down.
double HullLift(const RollDampingHull& h, double u, const RollDampingOptions& o) {
  const double d = h.draught_m, L = h.length_m, og = h.og_m;
  const double kappa = h.midship_coefficient <= 0.92 ? 0.0 : h.midship_coefficient <= 0.97 ? 0.1 : 0.3;
  const double kn = 2.0 * M_PI * d / L + kappa * (4.1 * h.breadth_m / L - 0.045);
  const double l0 = 0.3 * d, lr = 0.5 * d;
  return 0.5 * o.rho_kg_m3 * L * d * u * kn * l0 * lr * (1.0 - 1.4 * og / lr + 0.7 * og * og / (l0 * lr));
}

// Kawahara et al.'s bilge-keel component B̂_BK at φa (their fit takes φa in degrees), dimensional [N m s].
double BilgeKeel(const RollDampingHull& h, double w, const RollDampingOptions& o) {
  if (h.bilge_keel_length_m <= 0.0) return 0.0;
  const double cb = h.block_coefficient, cm = h.midship_coefficient, bd = h.breadth_m / h.draught_m;
  const double ogd = h.og_m / h.draught_m, bb = h.bilge_keel_breadth_m / h.breadth_m;
  const double ll = h.bilge_keel_length_m / h.length_m, phi = o.roll_amplitude_rad * 180.0 / M_PI;
  const double w_hat = w * std::sqrt(h.breadth_m / (2.0 * o.g_m_s2));
  const double f1 = (-0.3651 * cb + 0.3907) * (bd - 2.83) * (bd - 2.83) - 2.21 * cb + 2.632;
  const double f2 = 0.00255 * phi * phi + 0.122 * phi + 0.4794;
  const double f3 = (-0.8913 * bb * bb - 0.0733 * bb) * ll * ll + (5.2857 * bb * bb - 0.01185 * bb + 0.00189) * ll;
  const double b1 = (5.0 * bb + 0.3 * bd - 0.2 * ll + 0.00125 * phi * phi - 0.0425 * phi - 1.86) * ogd;
  const double b2 = -15.0 * bb + 1.2 * cb - 0.1 * bd - 0.0657 * ogd * ogd + 0.0586 * ogd + 1.6164;
  const double b3 = 2.5 * ogd + 15.75;
  const double b_hat = f1 * f2 * f3 * std::exp(b1 + b2 * std::pow(cm, b3)) * w_hat;
  return std::max(0.0, b_hat) * DimensionalFactor(h, o);
}

void Range(std::vector<std::string>& out, const char* name, double v, double lo, double hi) {
  if (v >= lo && v <= hi) return;
  std::ostringstream os;
  os << "roll damping (Ikeda, Kawahara et al. 2009): " << name << " = " << v << " is outside the range [" << lo
     << ", " << hi << "] the formulae were fitted in (conventional cargo ships): the viscous roll damping is "
     << "extrapolated";
  out.push_back(os.str());
}

}  // namespace

bool RollDampingHull::IsValid(std::string* error) const {
  std::ostringstream os;
  if (!Positive(length_m) || !Positive(breadth_m) || !Positive(draught_m))
    os << "length_m = " << length_m << ", breadth_m = " << breadth_m << ", draught_m = " << draught_m
       << " must be finite numbers > 0";
  else if (!(block_coefficient > 0 && block_coefficient <= 1) || !(midship_coefficient > 0 && midship_coefficient <= 1))
    os << "block_coefficient = " << block_coefficient << " and midship_coefficient = " << midship_coefficient
       << " must lie in (0, 1]";
  else if (!Finite(og_m))
    os << "og_m = " << og_m << " must be finite";
  else if (!(bilge_keel_length_m >= 0) || !Finite(bilge_keel_length_m) || !(bilge_keel_breadth_m >= 0) ||
           !Finite(bilge_keel_breadth_m) || ((bilge_keel_length_m > 0) != (bilge_keel_breadth_m > 0)))
    os << "bilge keels (length " << bilge_keel_length_m << " m, breadth " << bilge_keel_breadth_m
       << " m) must be finite, >= 0, and both 0 or both > 0";
  else if (body_offset_m.size() != body_waterplane_m2.size())
    os << "body_offset_m (" << body_offset_m.size() << ") and body_waterplane_m2 (" << body_waterplane_m2.size()
       << ") must have one entry per body";
  else
    for (std::size_t i = 0; i < body_offset_m.size(); ++i)
      if (!(body_offset_m[i] >= 0) || !Finite(body_offset_m[i]) || !(body_waterplane_m2[i] >= 0) ||
          !Finite(body_waterplane_m2[i])) {
        os << "body " << i << ": offset " << body_offset_m[i] << " m and waterplane " << body_waterplane_m2[i]
           << " m^2 must be finite and >= 0";
        break;
      }
  if (os.str().empty()) return true;
  if (error) *error = os.str();
  return false;
}

bool RollDampingOptions::IsValid(std::string* error) const {
  std::ostringstream os;
  if (!(roll_amplitude_rad > 0.0 && roll_amplitude_rad < 0.5))
    os << "roll_amplitude_rad = " << roll_amplitude_rad << " must lie in (0, 0.5) (0 to 29 deg)";
  else if (!Positive(kinematic_viscosity_m2_s))
    os << "kinematic_viscosity_m2_s = " << kinematic_viscosity_m2_s << " must be a finite number > 0";
  else if (!Positive(rho_kg_m3) || !Positive(g_m_s2))
    os << "rho_kg_m3 = " << rho_kg_m3 << " and g_m_s2 = " << g_m_s2 << " must be finite numbers > 0";
  else if (!(damping_cs >= 0.0) || !Finite(damping_cs))
    os << "damping_cs = " << damping_cs << " must be a finite number >= 0";
  if (os.str().empty()) return true;
  if (error) *error = os.str();
  return false;
}

double EquivalentLinearRollDamping(double b1, double b2, double w, double phi_a) {
  return b1 + 8.0 / (3.0 * M_PI) * w * phi_a * b2;
}

double KatoFrictionRollDamping(const RollDampingHull& h, double w, const RollDampingOptions& o) {
  const double d = h.draught_m, cb = h.block_coefficient, phi = o.roll_amplitude_rad;
  // Kawahara et al. take S_f/L = 1.7 d + Cb B inside r_f and 1.75 d + Cb B for S_f (as published).
  const double rf = d * ((0.887 + 0.145 * cb) * (1.7 + cb * h.breadth_m / d) - 2.0 * h.og_m / d) / M_PI;
  if (!(rf > 0.0))
    throw std::domain_error("roll damping: the mean radius r_f = " + std::to_string(rf) +
                            " m of the hull about the roll axis is not > 0 (OG = " + std::to_string(h.og_m) +
                            " m): the roll axis lies below the hull");
  const double sf = h.length_m * (1.75 * d + cb * h.breadth_m);
  const double period = 2.0 * M_PI / w;
  const double cf = 1.328 / std::sqrt(3.22 * rf * rf * phi * phi / (period * o.kinematic_viscosity_m2_s));
  return 4.0 / (3.0 * M_PI) * o.rho_kg_m3 * sf * rf * rf * rf * phi * w * cf;
}

namespace {
// Kawahara et al.'s C_R fit as it stands (negative outside its range for some hulls).
double RawEddyCoefficient(const RollDampingHull& h) {
  const double cb = h.block_coefficient, cm = h.midship_coefficient, bd = h.breadth_m / h.draught_m;
  const double ogd = h.og_m / h.draught_m;
  const double fe1 = (-0.0182 * cb + 0.0155) * std::pow(bd - 1.8, 3);
  const double fe2 = -79.414 * std::pow(cb, 4) + 215.695 * std::pow(cb, 3) - 215.883 * cb * cb + 93.894 * cb - 14.848;
  const double be1 = (3.98 * cb - 5.1525) * (-0.2 * bd + 1.6) * ogd *
                     ((0.9717 * cb * cb - 1.55 * cb + 0.723) * ogd + 0.04567 * cb + 0.9408);
  const double be2 = (0.25 * ogd + 0.95) * ogd - 219.2 * std::pow(cb, 3) + 443.7 * cb * cb - 283.3 * cb + 59.6;
  const double be3 = -15.0 * cb * bd + 46.5 * cb + 11.2 * bd - 28.6;
  return (fe1 + fe2) * std::exp(be1 + be2 * std::pow(cm, be3));
}
}  // namespace

double KawaharaEddyCoefficient(const RollDampingHull& h) {
  // Outside the fitted range the fit can turn negative (e.g. Cb < 0.45): no eddy damping then (flagged by
  // RollDampingRangeFlags), never a negative damping.
  return std::max(0.0, RawEddyCoefficient(h));
}

RollDampingComponents ViscousRollDamping(const RollDampingHull& h, double w, double speed_m_s,
                                         const RollDampingOptions& o) {
  std::string err;
  if (!o.IsValid(&err)) throw std::invalid_argument("roll damping options: " + err);
  if (!h.IsValid(&err)) throw std::invalid_argument("roll damping hull: " + err);
  if (!Positive(w)) throw std::invalid_argument("roll damping: omega = " + std::to_string(w) + " rad/s must be > 0");
  if (!Finite(speed_m_s)) throw std::invalid_argument("roll damping: the speed must be finite");
  RollDampingComponents c;
  if (o.model == RollDampingModel::kNone) return c;
  const double u = std::fabs(speed_m_s);
  if (h.Multihull()) {
    for (std::size_t i = 0; i < h.body_offset_m.size(); ++i)
      c.demihull_cs += h.body_offset_m[i] * h.body_offset_m[i] * 0.5 * o.damping_cs * o.rho_kg_m3 * u *
                       h.body_waterplane_m2[i];
  } else {
    // Speed factors (Ikeda; Himeno 1981): friction × (1 + 4.1 U/(ωL)); eddy × (0.04K)²/(1 + (0.04K)²), K = ωL/U.
    c.friction = KatoFrictionRollDamping(h, w, o) * (1.0 + 4.1 * u / (w * h.length_m));
    const double k04 = u > 0.0 ? 0.04 * w * h.length_m / u : 0.0;
    const double eddy_speed = u > 0.0 ? k04 * k04 / (1.0 + k04 * k04) : 1.0;
    c.eddy_quadratic = 0.5 * o.rho_kg_m3 * h.length_m * std::pow(h.draught_m, 4) * KawaharaEddyCoefficient(h) *
                       eddy_speed;
    c.lift = u > 0.0 ? std::max(0.0, HullLift(h, u, o)) : 0.0;
    c.bilge_keel_quadratic = BilgeKeel(h, w, o) / (8.0 / (3.0 * M_PI) * w * o.roll_amplitude_rad);
  }
  c.linear = c.friction + c.lift + c.demihull_cs;
  c.quadratic = c.eddy_quadratic + c.bilge_keel_quadratic;
  c.equivalent = EquivalentLinearRollDamping(c.linear, c.quadratic, w, o.roll_amplitude_rad);
  return c;
}

std::vector<std::string> RollDampingRangeFlags(const RollDampingHull& h, double max_omega, double speed_m_s,
                                               const RollDampingOptions& o) {
  std::vector<std::string> out;
  if (o.model == RollDampingModel::kNone) return out;
  if (h.Multihull()) {
    out.push_back(
        "roll damping: Ikeda's monohull formulae do not cover a demihull pair; the viscous roll damping is the "
        "demihulls' Cs heave damping at their offsets (B44 = sum y_i^2 0.5 Cs rho U A_wp,i), a model without "
        "validation for roll");
    if (!(o.damping_cs > 0.0) || speed_m_s == 0.0)
      out.push_back(std::string("roll damping: the demihulls' Cs term is zero here (") +
                    (speed_m_s == 0.0 ? "zero speed" : "Cs = 0") +
                    "): roll has potential damping only and is too large near its resonance");
    return out;
  }
  const double bd = h.breadth_m / h.draught_m;
  Range(out, "Cb", h.block_coefficient, 0.5, 0.85);
  Range(out, "B/d", bd, 2.5, 4.5);
  Range(out, "OG/d", h.og_m / h.draught_m, -1.5, 0.2);
  Range(out, "Cm", h.midship_coefficient, 0.9, 0.99);
  if (h.bilge_keel_length_m > 0.0) {
    Range(out, "bilge keel b/B", h.bilge_keel_breadth_m / h.breadth_m, 0.01, 0.06);
    Range(out, "bilge keel l/L", h.bilge_keel_length_m / h.length_m, 0.05, 0.4);
  }
  Range(out, "omega_hat = omega sqrt(B/2g)", max_omega * std::sqrt(h.breadth_m / (2.0 * o.g_m_s2)), 0.0, 1.0);
  if (const double cr = RawEddyCoefficient(h); cr < 0.0) {
    std::ostringstream os;
    os << "roll damping (Ikeda, Kawahara et al. 2009): the eddy-making fit gives C_R = " << cr
       << " < 0 for this hull: its eddy damping is taken as 0";
    out.push_back(os.str());
  }
  return out;
}

}  // namespace hullopt::sk
