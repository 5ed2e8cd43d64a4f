#include "parametric_hull/hull_generator.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

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
// Stop when |ΔCp| + |ΔCwp| + 0.01 (|ΔLCB| + |ΔLCF|) [% L] is below this: four orders below the targets.
constexpr double kRetargetTol = 1e-6;
// Relative area tolerance of the SWATH bulb solves (round-off level: the areas are the hydrostatics' own).
constexpr double kAreaTol = 1e-13;
// Bow flare: the deck edge half-breadth above a station gains this fraction of (B/2 - b/2).
constexpr double kFlare = 0.3;
// Trihull outrigger form (fixed; the outriggers' size and position are design variables).
constexpr double kOutriggerCp = 0.65, kOutriggerCm = 0.75, kOutriggerCwp = 0.78, kOutriggerLcb = -2.0,
                 kOutriggerLcf = -4.0, kOutriggerTransom = 0.3, kOutriggerTransomBeam = 0.5;
// SWATH: strut waterline fullness used when strut_ratio is 0 (automatic), and bulb superellipse exponent.
constexpr double kAutoStrutFullness = 0.8, kBulbExponent = 2.0;
// Rounded-bulb SWATH family (bulb_height_ratio > 0): range of the bulb's superelliptic exponent solved at
// midships (1.5: a pointed, diamond-like bulb; 12: nearly a box); the aft fraction of L over which the
// bulb's bottom flattens into a chined, flat-bottomed transom (the paper's SW1/SW2: "a flat bottomed transom
// preceded by a chine extending for 30% of the length"), and the bottom exponent at the transom (a flat
// bottom with a tight bilge radius).
constexpr double kBulbExponentMin = 1.5, kBulbExponentMax = 12.0;
constexpr double kSwathChineFraction = 0.3, kChineExponent = 8.0;

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
  double bulb_height_ratio = 0.0;
  int stations = 41, points = 25;
  std::string name = "hull";
};

// Form curves of a body from the previous re-targeting pass, to warm-start the next.
struct CurveCache {
  bool valid = false;
  FormCurve wp, sac;
  // Trihull outriggers do not depend on the re-targeted values: built once, with their totals.
  bool has_body = false;
  Demihull body;
  double V = 0, Vx = 0, Awp = 0, Awpx = 0, Amid = 0;
};

// Area coefficients the round-bilge (superellipse) family reaches at full draught (section_family.h).
constexpr double kRoundBilgeSigmaMin = 0.15, kRoundBilgeSigmaMax = 0.98;

// The rounded-bulb family where no bulb stands out of the strut: a round-bilge section of the strut's
// breadth (the paper's "well rounded" sections) whose draught follows the monohull rule d = min(T,
// A/(σ_ref b)) (keel rise towards the ends, a flat-bottomed rounded-bilge transom), chined only if fuller
// than the round-bilge family reaches.
Station StrutFoot(SectionTarget t, double T, double sigma_ref) {
  t.draught_m = std::min(T, t.area_m2 / (std::min(sigma_ref, kRoundBilgeSigmaMax) * 2 * t.half_beam_m));
  const double sigma = t.area_m2 / (2 * t.half_beam_m * t.draught_m);
  if (sigma > kRoundBilgeSigmaMax) return HardChineSection(t);
  if (sigma < kRoundBilgeSigmaMin) t.draught_m = t.area_m2 / (0.25 * kPi * 2 * t.half_beam_m);
  return RoundBilgeSection(t);
}

// A station of the rounded-bulb SWATH family: the bulb keeps the midship height h and fullness nb and narrows
// to meet the area (down to the strut's own thickness, below which the section is a strut foot); where the
// area exceeds the midship bulb's, the bulb grows in height at breadth B. Aft of kSwathChineFraction L the
// bulb's bottom flattens towards the transom (exponent rising to kChineExponent).
Station RoundedBulbStation(SectionTarget t, const BodySpec& b, double xi, double h, double nb, double sac_peak) {
  const double f = std::max(0.0, 1.0 - xi / kSwathChineFraction);
  const double nb_low = nb + f * std::max(0.0, kChineExponent - nb);
  const auto area = [&](double e, double hh) {
    return SectionArea(SwathSection(t, e, hh, nb, nb_low), t.waterline_z_m);
  };
  const double st = t.half_beam_m;
  if (st >= b.B / 2 || t.area_m2 <= area(st, h))
    return StrutFoot(t, b.T, b.Cm + b.keel_rise * (1.0 - b.Cm) * (2 * xi - 1) * (2 * xi - 1));
  if (t.area_m2 <= area(b.B / 2, h)) {
    const double e = IncreasingRoot([&](double m) { return area(m, h) / t.area_m2 - 1.0; }, st, b.B / 2, kAreaTol);
    return SwathSection(t, e, h, nb, nb_low);
  }
  if (t.area_m2 > area(b.B / 2, b.T)) {
    // Fuller than the midship bulb filling the draught: a fuller bulb (larger exponent) of breadth B and
    // full height.
    const auto full = [&](double n) { return SectionArea(SwathSection(t, b.B / 2, b.T, n, std::max(n, nb_low)), t.waterline_z_m); };
    if (t.area_m2 > full(kBulbExponentMax))
      throw std::domain_error(
          "impossible SWATH: section at x = " + Num(t.x_m) + " m needs area " + Num(t.area_m2) +
          " m^2, more than a bulb of breadth B filling the draught (the sectional area curve peaks at " +
          Num(sac_peak) + " x midships; move LCB_pct_L towards 0 or lower Cp)");
    const double n = IncreasingRoot([&](double m) { return full(m) / t.area_m2 - 1.0; }, nb, kBulbExponentMax, kAreaTol);
    return SwathSection(t, b.B / 2, b.T, n, std::max(n, nb_low));
  }
  const double hh = IncreasingRoot([&](double m) { return area(b.B / 2, m) / t.area_m2 - 1.0; }, h, b.T, kAreaTol);
  return SwathSection(t, b.B / 2, hh, nb, nb_low);
}

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
  // peak. The curve's peak is sampled too when it lies in the sampled range: with an exponent below 1 the
  // curve falls from it with infinite slope, so a fixed sample just beside a moving peak would make the score
  // (and the choice of curve, form_curve.h) change by per cent for a 1e-5 shift of the peak.
  const CurveScore sac_score = [&](const FormCurve& c) {
    if (swath) return c.peak;
    const auto ratio = [&](double xi) { return c(xi) * b.Cm / std::max(1e-9, wp(xi)); };
    double worst = c.xi_peak <= 0.9 ? ratio(c.xi_peak) : 0.0;
    for (int i = 0; i < 40; ++i) worst = std::max(worst, ratio(0.9 * i / 39.0));
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
  // Rounded-bulb family: the bulb height is the design variable, its fullness (exponent) meets Cm.
  const bool rounded = swath && b.bulb_height_ratio > 0.0;
  if (swath && !rounded) {
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
  double nb_mid = kBulbExponent;
  const auto bulb_area = [&](SectionTarget t, double e, double h, double nb, double nb_low) {
    return SectionArea(SwathSection(t, e, h, nb, nb_low), t.waterline_z_m);
  };
  if (rounded) {
    SectionTarget t = base;
    t.half_beam_m = wp(0.5) * b.B / 2;
    t.draught_m = b.T;
    const double h = b.bulb_height_ratio * b.T;
    bulb_h_mid = h;
    // A strut as wide as the bulb at midships (a semi-SWATH whose waterplane reduction lies forward): the
    // midship section is a round-bilge strut foot and the bulb, where it stands out forward, is elliptic.
    const bool midship_bulb = t.half_beam_m < b.B / 2 && Am > bulb_area(t, t.half_beam_m, h, kBulbExponent, 0.0);
    const double lo = bulb_area(t, b.B / 2, h, kBulbExponentMin, 0.0),
                 hi = bulb_area(t, b.B / 2, h, kBulbExponentMax, 0.0);
    if (midship_bulb && !(Am > lo && Am < hi))
      throw std::domain_error("impossible SWATH: midship area coefficient Cm = Cb/Cp = " + Num(b.Cm) +
                              " needs a bulb of height bulb_height_ratio = " + Num(b.bulb_height_ratio) +
                              " T and breadth B between " + Num(lo / (b.B * b.T)) + " (pointed) and " +
                              Num(hi / (b.B * b.T)) + " (box) with strut_ratio = " + Num(peak) +
                              " (rule: raise bulb_height_ratio for a fuller midship section, lower it for a "
                              "finer one)");
    if (midship_bulb)
      nb_mid = IncreasingRoot([&](double n) { return bulb_area(t, b.B / 2, h, n, 0.0) / Am - 1.0; },
                              kBulbExponentMin, kBulbExponentMax, kAreaTol);
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
    if (rounded) {
      body.stations.push_back(RoundedBulbStation(t, b, xi, bulb_h_mid, nb_mid, sac.peak));
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
  m.bulb_height_ratio = dv.bulb_height_ratio;
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
  if (!outrigger_cache->has_body) {
    outrigger_cache->body = BuildBody(o, outrigger_cache);
    outrigger_cache->body.role = "outrigger";
    outrigger_cache->body.y_centre_m = dv.outrigger_offset_over_L * L;
    // Built on the ship's waterline z = T, keel at T - T_o.
    const BodyTotals t = Totals(outrigger_cache->body, T, 0.5 * L);
    outrigger_cache->V = t.V;
    outrigger_cache->Vx = t.Vx;
    outrigger_cache->Awp = t.Awp;
    outrigger_cache->Awpx = t.Awpx;
    outrigger_cache->Amid = t.Amid;
    outrigger_cache->has_body = true;
  }
  const Demihull& outrigger = outrigger_cache->body;
  BodyTotals ot;
  ot.V = outrigger_cache->V;
  ot.Vx = outrigger_cache->Vx;
  ot.Awp = outrigger_cache->Awp;
  ot.Awpx = outrigger_cache->Awpx;
  ot.Amid = outrigger_cache->Amid;
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

// Nearest feasible waterplane: LCF is moved inside the family's reach by the first of these margins [% L]
// with which the whole hull builds (the re-targeting passes shift the curve targets by the discretisation
// error of the hull, up to a few 0.1 % L for a full waterplane), Cwp by the first of them / 100.
constexpr double kFeasibleMarginsPct[] = {0.05, 0.1, 0.2, 0.4, 0.8, 1.6};
// Scan steps towards feasibility (LCF [% L], Cwp) before the bisection, and the bisection's resolution.
constexpr double kLcfScanStep = 0.25, kCwpScanStep = 0.01, kBisectTol = 1e-3;

bool WaterplaneFits(double peak, double end, double cwp, double lcf) {
  try {
    SolveFormCurveWithPeak(peak, end, cwp, 0.5 + lcf / 100.0, "waterplane");
    return true;
  } catch (const std::domain_error&) {
    return false;
  }
}

// Boundary of a feasible set between an infeasible `bad` and a feasible `good` value, by bisection; returns
// a value on the feasible side.
template <class Fits>
double Bisect(Fits fits, double bad, double good) {
  while (std::fabs(good - bad) > kBisectTol) {
    const double m = 0.5 * (bad + good);
    (fits(m) ? good : bad) = m;
  }
  return good;
}

// The nearest waterplane the family reaches from (Cwp, LCF): LCF moved towards midships at the same Cwp, and
// Cwp lowered at the same LCF (NaN where the scan finds none).
struct NearestWaterplane {
  double lcf_pct_L = NAN;  // with Cwp kept
  double cwp = NAN;        // with LCF kept
};
NearestWaterplane FindNearestWaterplane(double peak, double end, double cwp, double lcf) {
  NearestWaterplane n;
  const double dir = lcf < 0.0 ? 1.0 : -1.0;  // towards midships, then beyond
  for (double l = lcf + dir * kLcfScanStep; std::fabs(l) < 25.0; l += dir * kLcfScanStep)
    if (WaterplaneFits(peak, end, cwp, l)) {
      const double b = Bisect([&](double v) { return WaterplaneFits(peak, end, cwp, v); }, l - dir * kLcfScanStep, l);
      n.lcf_pct_L = b;
      break;
    }
  for (double c = cwp - kCwpScanStep; c > 0.05; c -= kCwpScanStep)
    if (WaterplaneFits(peak, end, c, lcf)) {
      n.cwp = Bisect([&](double v) { return WaterplaneFits(peak, end, v, lcf); }, c + kCwpScanStep, c);
      n.cwp -= kFeasibleMarginsPct[0] / 100.0;
      break;
    }
  return n;
}

// Is the waterplane (Cwp, LCF) of a monohull, catamaran or SWATH beyond the curve family? (peak, end: the
// curve's peak and transom breadths / B). The trihull's main-hull waterplane is derived from the totals and is
// checked in the build.
bool WaterplaneInfeasible(const DesignVariables& dv, double* peak, double* end) {
  if (dv.type == HullType::kTrihull) return false;
  *peak = dv.type == HullType::kSwath ? (dv.strut_ratio > 0.0 ? dv.strut_ratio : dv.Cwp / kAutoStrutFullness)
                                      : 1.0;
  *end = dv.transom_beam_ratio * *peak;
  if (!(dv.Cwp < *peak)) return false;  // refused in the build with its own rule
  return !WaterplaneFits(*peak, *end, dv.Cwp, dv.LCF_pct_L);
}

HullForm GenerateFeasible(const DesignVariables& dv);

}  // namespace

HullForm GenerateHull(const DesignVariables& dv) {
  std::string error;
  if (!dv.IsValid(&error)) throw std::invalid_argument(error);
  double peak = 1.0, end = 0.0;
  if (!WaterplaneInfeasible(dv, &peak, &end)) {
    try {
      return GenerateFeasible(dv);
    } catch (const std::domain_error& e) {
      // Reachable as asked, but not once the re-targeting has added the hull's discretisation error: as
      // unreachable (below), unless the failure is not the waterplane's.
      if (dv.type == HullType::kTrihull || std::string(e.what()).find("waterplane curve") == std::string::npos)
        throw;
    }
  }
  // An unreachable waterplane: refused with the nearest reachable ones named, or (on_infeasible: nearest)
  // built with Cwp kept and LCF moved, the change recorded.
  const NearestWaterplane n = FindNearestWaterplane(peak, end, dv.Cwp, dv.LCF_pct_L);
  std::ostringstream what;
  what << "waterplane Cwp = " << dv.Cwp << " with LCF_pct_L = " << dv.LCF_pct_L
       << " is beyond the fair-curve family (rule: a waterplane this full cannot have its centroid that far "
          "from midships; peak breadth "
       << peak << " B, transom breadth " << end << " B; necessary bound for any curve no wider than its peak: "
       << "LCF_pct_L >= " << (dv.Cwp / peak / 2 - 0.5) * 100 << ")";
  // The nearest LCF with which the whole hull builds.
  DesignVariables moved = dv;
  HullForm hull;
  bool built = false;
  std::string last_error;
  if (std::isfinite(n.lcf_pct_L)) {
    const double dir = dv.LCF_pct_L < 0.0 ? 1.0 : -1.0;
    for (double margin : kFeasibleMarginsPct) {
      moved.LCF_pct_L = n.lcf_pct_L + dir * margin;
      try {
        hull = GenerateFeasible(moved);
        built = true;
        break;
      } catch (const std::domain_error& e) {
        last_error = e.what();
      }
    }
  }
  if (dv.on_infeasible == OnInfeasible::kRefuse || !built) {
    std::ostringstream os;
    os << what.str() << "; nearest feasible: ";
    if (built) os << "LCF_pct_L = " << Num(moved.LCF_pct_L) << " (Cwp kept)";
    if (built && std::isfinite(n.cwp)) os << " or ";
    if (std::isfinite(n.cwp)) os << "Cwp = " << Num(n.cwp) << " (LCF kept)";
    if (!built && !std::isfinite(n.cwp)) os << "none found";
    if (built) os << "; on_infeasible: nearest builds the first";
    if (!built && !last_error.empty()) os << " (with LCF moved: " << last_error << ")";
    throw std::domain_error(os.str());
  }
  std::ostringstream adj;
  adj << "on_infeasible: nearest: LCF_pct_L " << dv.LCF_pct_L << " -> " << Num(moved.LCF_pct_L) << " ("
      << (moved.LCF_pct_L - dv.LCF_pct_L >= 0 ? "+" : "") << Num(moved.LCF_pct_L - dv.LCF_pct_L) << " % L), Cwp "
      << dv.Cwp << " kept: the " << what.str();
  hull.adjustments.push_back(adj.str());
  return hull;
}

namespace {

HullForm GenerateFeasible(const DesignVariables& dv) {
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

}  // namespace

}  // namespace hullopt::hull
