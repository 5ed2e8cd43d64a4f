#include "parametric_hull/hull_generator.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "parametric_hull/form_curve.h"
#include "parametric_hull/hydrostatics.h"
#include "parametric_hull/section_family.h"
#include "parametric_hull/section_geometry.h"

namespace hullopt::hull {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Fixed-point passes on Cp, Cwp, LCB, LCF: each removes most of the discretisation error (it is smooth in the
// targets); 6 passes bring it to round-off level for the Table 1 hulls.
constexpr int kRetargetPasses = 6;
constexpr double kRetargetTol = 1e-8;
// Relative area tolerance of the SWATH bulb solves (round-off level: the areas are the hydrostatics' own).
constexpr double kAreaTol = 1e-13;
// Bow flare: the deck edge half-breadth above a station gains this fraction of (B/2 - b/2).
constexpr double kFlare = 0.3;
// Trihull outrigger form (fixed; the outriggers' size and position are design variables).
constexpr double kOutriggerCp = 0.65, kOutriggerCm = 0.75, kOutriggerCwp = 0.78, kOutriggerLcb = -2.0,
                 kOutriggerLcf = -4.0, kOutriggerTransom = 0.3, kOutriggerTransomBeam = 0.5;
// SWATH: strut waterline fullness used when strut_ratio is 0 (automatic), and bulb superellipse exponent.
constexpr double kAutoStrutFullness = 0.8, kBulbExponent = 2.0;

std::string Num(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// Root of an increasing function f on [a, c] with f(a) < 0 < f(c), by the Illinois variant of regula falsi
// (a handful of evaluations for the smooth area functions here).
template <class F>
double IncreasingRoot(F f, double a, double c, double rel_tol) {
  double fa = f(a), fc = f(c);
  int side = 0;
  double x = 0.5 * (a + c);
  for (int it = 0; it < 100; ++it) {
    x = (a * fc - c * fa) / (fc - fa);
    const double fx = f(x);
    if (std::fabs(fx) < rel_tol || c - a < 1e-15 * std::fabs(c)) break;
    if (fx < 0.0) {
      a = x;
      fa = fx;
      if (side == -1) fc *= 0.5;
      side = -1;
    } else {
      c = x;
      fc = fx;
      if (side == 1) fa *= 0.5;
      side = 1;
    }
  }
  return x;
}

// Shape inputs of one body (dimensions of that body).
struct BodySpec {
  SectionStyle style = SectionStyle::kRoundBilge;
  double L = 1, B = 1, T = 1;  // T: this body's draught
  double waterline_z = 1;      // waterline height above the ship baseline (keel of the main hull = 0)
  double deck_z = 1.6;
  double Cp = 0.6, Cm = 0.8, Cwp = 0.7, LCB = 0, LCF = 0;
  double transom_immersion = 0.3, transom_beam = 0.6, keel_rise = 0.3, strut_ratio = 0.5;
  int stations = 41, points = 25;
  std::string name = "hull";
};

// Form curves of a body from the previous re-targeting pass, to warm-start the next.
struct CurveCache {
  bool valid = false;
  FormCurve wp, sac;
};

Demihull BuildBody(const BodySpec& b, CurveCache* cache) {
  const bool swath = b.style == SectionStyle::kSwathBulb;
  const double peak = swath ? b.strut_ratio : 1.0;
  if (swath && !(b.Cwp < peak))
    throw std::domain_error("impossible SWATH: Cwp = " + Num(b.Cwp) +
                            " needs a strut at least as wide as Cwp*B, but strut_ratio = " + Num(peak) +
                            " (rule: Cwp < strut_ratio)");
  const FormCurve wp = SolveFormCurveWithPeak(
      peak, b.transom_beam * peak, b.Cwp, 0.5 + b.LCF / 100.0,
      b.name + " waterplane curve (Cwp = " + Num(b.Cwp) + ", LCF_pct_L = " + Num(b.LCF) + ")",
      cache->valid ? &cache->wp : nullptr);
  const auto sigma_ref = [&](double xi) {
    return b.Cm + b.keel_rise * (1.0 - b.Cm) * (2 * xi - 1) * (2 * xi - 1);
  };
  // Transom area ratio consistent with the transom draught: A_T = σ_ref(0) b_T τ T.
  // SWATH: the transom section is the midship bulb section scaled by τ in depth and transom_beam in breadth.
  const double transom_ratio = swath ? b.transom_immersion * b.transom_beam
                                     : b.transom_immersion * b.transom_beam * sigma_ref(0.0) / b.Cm;
  // Choose the area curve whose fullest section relative to its waterline breadth is least full (a Cm/w is
  // the area coefficient of a full-draught section; families reach at most 0.98 to 1), for SWATH the lowest
  // peak.
  const CurveScore sac_score = [&](const FormCurve& c) {
    if (swath) return c.peak;
    double worst = 0.0;
    for (int i = 0; i < 40; ++i) {
      const double xi = 0.9 * i / 39.0;
      worst = std::max(worst, c(xi) * b.Cm / std::max(1e-9, wp(xi)));
    }
    return worst;
  };
  const FormCurve sac = SolveFormCurveAtMidship(
      transom_ratio, b.Cp, 0.5 + b.LCB / 100.0,
      b.name + " sectional area curve (Cp = " + Num(b.Cp) + ", LCB_pct_L = " + Num(b.LCB) + ")",
      cache->valid ? &cache->sac : nullptr, sac_score);
  cache->wp = wp;
  cache->sac = sac;
  cache->valid = true;
  const double Am = b.Cm * b.B * b.T;

  // SWATH: bulb height at midships from the midship area with the bulb at full breadth B.
  double bulb_h_mid = 0.0;
  SectionTarget base;
  base.waterline_z_m = b.waterline_z;
  base.deck_z_m = b.deck_z;
  base.points = b.points;
  auto swath_area = [&](SectionTarget t, double e, double h) {
    return SectionArea(SwathSection(t, e, h, kBulbExponent), t.waterline_z_m);
  };
  if (swath) {
    SectionTarget t = base;
    t.half_beam_m = wp(0.5) * b.B / 2;
    t.draught_m = b.T;
    const double lo = swath_area(t, b.B / 2, 1e-6 * b.T), hi = swath_area(t, b.B / 2, b.T);
    if (!(Am > lo && Am < hi))
      throw std::domain_error(
          "impossible SWATH: midship area coefficient Cm = Cb/Cp = " + Num(b.Cm) + " must lie between " +
          Num(lo / (b.B * b.T)) + " (strut only) and " + Num(hi / (b.B * b.T)) +
          " (bulb filling the draught) for B/T = " + Num(b.B / b.T) + " and strut_ratio = " + Num(peak));
    bulb_h_mid = IncreasingRoot([&](double h) { return swath_area(t, b.B / 2, h) / Am - 1.0; }, 1e-6 * b.T,
                                b.T, kAreaTol);
  }

  Demihull body;
  body.stations.reserve(b.stations);
  for (int i = 0; i < b.stations; ++i) {
    const double xi = double(i) / (b.stations - 1);
    SectionTarget t = base;
    t.x_m = xi * b.L;
    t.area_m2 = std::max(0.0, sac(xi)) * Am;
    t.half_beam_m = std::max(0.0, wp(xi)) * b.B / 2;
    if (i == b.stations - 1) t.area_m2 = t.half_beam_m = 0.0;  // the stem
    // Draught at the section coefficient σ_ref; at the stem the limit of the ratio just aft of it.
    const double xr = i == b.stations - 1 ? 1.0 - 1e-7 : xi;
    const double ar = std::max(0.0, sac(xr)) * Am, br = std::max(0.0, wp(xr)) * b.B / 2;
    if (!swath) {
      const double sr = sigma_ref(xr);
      t.draught_m = br > 0.0 ? std::min(b.T, ar / (sr * 2 * br)) : 0.0;
      t.deck_half_beam_m = t.half_beam_m + kFlare * (b.B / 2 - t.half_beam_m);
      body.stations.push_back(b.style == SectionStyle::kHardChine ? HardChineSection(t)
                                                                  : RoundBilgeSection(t));
      continue;
    }
    // SWATH station: scale the midship bulb by λ (width and height); where even a full-depth strut has more
    // area than needed, the strut ends in a round-bilge foot above the baseline.
    t.deck_half_beam_m = t.half_beam_m;
    t.draught_m = b.T;
    if (t.area_m2 <= 0.0 || t.half_beam_m <= 0.0) {
      t.draught_m = br > 0.0 ? std::min(b.T, ar / (0.25 * kPi * 2 * br)) : 0.0;
      body.stations.push_back(RoundBilgeSection(t));
      continue;
    }
    const double lam_min = 1e-3;
    if (t.area_m2 < swath_area(t, lam_min * b.B / 2, lam_min * bulb_h_mid)) {
      // Less area than a full-depth strut: a strut with a chined bottom down to the keel while that can hold
      // it (area coefficient >= 0.5), else a rounded strut foot that rises off the keel.
      const double sigma_full = t.area_m2 / (2 * t.half_beam_m * b.T);
      if (sigma_full >= 0.5) {
        body.stations.push_back(HardChineSection(t));
      } else {
        t.draught_m = t.area_m2 / (0.25 * kPi * 2 * t.half_beam_m);
        body.stations.push_back(RoundBilgeSection(t));
      }
      continue;
    }
    double e = b.B / 2, h = bulb_h_mid;
    if (t.area_m2 <= swath_area(t, b.B / 2, bulb_h_mid)) {
      const double lam = IncreasingRoot(
          [&](double m) { return swath_area(t, m * b.B / 2, m * bulb_h_mid) / t.area_m2 - 1.0; }, lam_min,
          1.0, kAreaTol);
      e = lam * b.B / 2;
      h = lam * bulb_h_mid;
    } else {  // more area than the midship bulb: a taller bulb of the same breadth
      if (t.area_m2 > swath_area(t, b.B / 2, b.T))
        throw std::domain_error(
            "impossible SWATH: section at x = " + Num(t.x_m) + " m needs area " + Num(t.area_m2) +
            " m^2, more than a bulb of breadth B filling the draught (the sectional area curve peaks at " +
            Num(sac.peak) + " x midships; move LCB_pct_L towards 0 or lower Cp)");
      h = IncreasingRoot([&](double m) { return swath_area(t, b.B / 2, m) / t.area_m2 - 1.0; }, bulb_h_mid,
                         b.T, kAreaTol);
    }
    body.stations.push_back(SwathSection(t, e, h, kBulbExponent));
  }
  return body;
}

struct Targets {
  double Cp, Cwp, LCB, LCF;
};

// Totals of one body over its stations (volume, x-moment, waterplane area and x-moment, midship area).
struct BodyTotals {
  double V = 0, Vx = 0, Awp = 0, Awpx = 0, Amid = 0;
};
BodyTotals Totals(const Demihull& body, double T, double x_mid) {
  HullForm h;
  h.draught_m = T;
  h.bodies = {body};
  h.bodies[0].y_centre_m = 0.0;
  const Hydrostatics hs = ComputeHydrostatics(h, 1000.0);
  BodyTotals t;
  t.V = hs.volume_m3;
  t.Vx = hs.volume_m3 * hs.lcb_m_from_ap;
  t.Awp = hs.awp_m2;
  t.Awpx = hs.awp_m2 * hs.lcf_m_from_ap;
  t.Amid = 2.0 * ComputeSectionProperties(InterpolateStation(body, x_mid), T).area_m2;
  return t;
}

HullForm Build(const DesignVariables& dv, double L, double Cm, const Targets& tg, CurveCache* main_cache,
               CurveCache* outrigger_cache) {
  const double B = L / dv.L_over_B, T = B / dv.B_over_T;
  BodySpec m;
  m.style = dv.section_style;
  m.L = L;
  m.B = B;
  m.T = T;
  m.waterline_z = T;
  m.deck_z = T * (1.0 + dv.freeboard_over_T);
  m.Cp = tg.Cp;
  m.Cm = Cm;
  m.Cwp = tg.Cwp;
  m.LCB = tg.LCB;
  m.LCF = tg.LCF;
  m.transom_immersion = dv.transom_immersion;
  m.transom_beam = dv.transom_beam_ratio;
  m.keel_rise = dv.keel_rise;
  m.strut_ratio = dv.strut_ratio > 0.0 ? dv.strut_ratio : dv.Cwp / kAutoStrutFullness;
  m.stations = dv.stations;
  m.points = dv.section_points;
  if (dv.type == HullType::kSwath && !(m.strut_ratio <= 1.0))
    throw std::domain_error("impossible SWATH: Cwp = " + Num(dv.Cwp) +
                            " with the automatic strut waterline fullness " + Num(kAutoStrutFullness) +
                            " needs strut_ratio = " + Num(m.strut_ratio) +
                            "  > 1 (set strut_ratio <= 1 explicitly, above Cwp)");

  HullForm hull;
  hull.type = ToString(dv.type);
  hull.draught_m = T;
  hull.length_m = L;
  if (dv.type != HullType::kTrihull) {
    m.name = dv.type == HullType::kMonohull ? "hull" : "demihull";
    Demihull body = BuildBody(m, main_cache);
    if (dv.type == HullType::kMonohull) {
      body.role = "main";
    } else {
      body.role = "demihull";
      body.y_centre_m = 0.5 * (dv.spacing_m > 0.0 ? dv.spacing_m : dv.spacing_over_L * L);
    }
    hull.bodies = {body};
    return hull;
  }
  // Trihull: outriggers first, then the main hull takes the rest of every total.
  BodySpec o = m;
  o.style = SectionStyle::kRoundBilge;
  o.name = "outrigger";
  o.L = dv.outrigger_length_ratio * L;
  o.B = o.L / dv.outrigger_L_over_B;
  o.T = o.B / dv.outrigger_B_over_T;
  if (!(o.T < T))
    throw std::domain_error("trihull: outrigger draught " + Num(o.T) +
                            " m must be below the main hull draught " + Num(T) +
                            " m (raise outrigger_L_over_B or outrigger_B_over_T)");
  o.Cp = kOutriggerCp;
  o.Cm = kOutriggerCm;
  o.Cwp = kOutriggerCwp;
  o.LCB = kOutriggerLcb;
  o.LCF = kOutriggerLcf;
  o.transom_immersion = kOutriggerTransom;
  o.transom_beam = kOutriggerTransomBeam;
  Demihull outrigger = BuildBody(o, outrigger_cache);
  outrigger.role = "outrigger";
  outrigger.y_centre_m = dv.outrigger_offset_over_L * L;
  const double x_mid = 0.5 * L;
  const BodyTotals ot = Totals(outrigger, T, x_mid);  // built on the ship's waterline z = T, keel at T - T_o
  const double Vt = tg.Cp * Cm * L * B * T, Amt = Cm * B * T, Awpt = tg.Cwp * L * B;
  const double Vm = Vt - 2 * ot.V, Amm = Amt - 2 * ot.Amid, Awpm = Awpt - 2 * ot.Awp;
  if (!(Vm > 0 && Amm > 0 && Awpm > 0))
    throw std::domain_error(
        "trihull: the outriggers (outrigger_L_over_B = " + Num(dv.outrigger_L_over_B) +
        ", outrigger_B_over_T = " + Num(dv.outrigger_B_over_T) +
        ") take more volume, midship area or waterplane than the whole trihull has; make them smaller");
  m.name = "trihull main hull";
  m.Cp = Vm / (L * Amm);
  m.Cm = Amm / (B * T);
  m.Cwp = Awpm / (L * B);
  m.LCB = ((Vt * (0.5 + tg.LCB / 100.0) * L - 2 * ot.Vx) / Vm / L - 0.5) * 100.0;
  m.LCF = ((Awpt * (0.5 + tg.LCF / 100.0) * L - 2 * ot.Awpx) / Awpm / L - 0.5) * 100.0;
  if (!(m.Cm < 1.0 && m.Cp < 1.0))
    throw std::domain_error("trihull: with these outriggers the main hull would need Cp = " + Num(m.Cp) +
                            ", Cm = " + Num(m.Cm) + " (rule: both < 1)");
  Demihull main = BuildBody(m, main_cache);
  main.role = "main";
  hull.bodies = {main, outrigger};
  return hull;
}

void Scale(HullForm* h, double s) {
  h->draught_m *= s;
  h->length_m *= s;
  for (auto& b : h->bodies) {
    b.y_centre_m *= s;
    for (auto& st : b.stations) {
      st.x_m *= s;
      for (auto& y : st.y_m) y *= s;
      for (auto& z : st.z_m) z *= s;
    }
  }
}

}  // namespace

HullForm GenerateHull(const DesignVariables& dv) {
  std::string error;
  if (!dv.IsValid(&error)) throw std::invalid_argument(error);
  const double V = dv.displacement_t * 1000.0 / dv.rho_kg_m3;
  const int n_ref = (dv.type == HullType::kCatamaran || dv.type == HullType::kSwath) ? 2 : 1;
  // Nominal length from Cb at the requested L/B, B/T; the final scaling makes the displacement exact.
  const double L0 = std::cbrt(V / n_ref * dv.L_over_B * dv.L_over_B * dv.B_over_T / dv.Cb);
  const double Cm = dv.Cb / dv.Cp;
  Targets tg{dv.Cp, dv.Cwp, dv.LCB_pct_L, dv.LCF_pct_L};
  HullForm hull;
  CurveCache main_cache, outrigger_cache;
  for (int pass = 0; pass < kRetargetPasses; ++pass) {
    hull = Build(dv, L0, Cm, tg, &main_cache, &outrigger_cache);
    const Hydrostatics hs = ComputeHydrostatics(hull, dv.rho_kg_m3);
    const double dCp = dv.Cp - hs.Cp, dCwp = dv.Cwp - hs.Cwp, dLcb = dv.LCB_pct_L - hs.LCB_pct_L,
                 dLcf = dv.LCF_pct_L - hs.LCF_pct_L;
    if (std::fabs(dCp) + std::fabs(dCwp) + 1e-2 * (std::fabs(dLcb) + std::fabs(dLcf)) < kRetargetTol) break;
    tg.Cp += dCp;
    tg.Cwp += dCwp;
    tg.LCB += dLcb;
    tg.LCF += dLcf;
  }
  const double v = DisplacedVolume(hull);
  Scale(&hull, std::cbrt(V / v));
  return hull;
}

}  // namespace hullopt::hull
