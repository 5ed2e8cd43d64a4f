#include "evaluation/validity_envelope.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "parametric_hull/plausibility.h"
#include "seas/wave_spectrum.h"

namespace hullopt::eval {
namespace {

constexpr double kInf = INFINITY;

std::string EnvelopeNumber(double v) {
  std::ostringstream s;
  s.precision(4);
  s << v;
  return s.str();
}

// k_yy is checked by the mass plausibility rules; its row shows their numbers so that there is one table.
EnvelopeRule KyyRow() {
  const hull::PlausibilityLimits lim;
  return {EnvelopeQuantity::kKyyOverL, "kyy/L", "k_yy / L", lim.kyy_usual_min_over_L, lim.kyy_usual_max_over_L,
          lim.kyy_min_over_L, lim.kyy_max_over_L,
          "fast vessels have k_yy 0.2-0.3 L (Lloyd 1989, Seakeeping, ch. 13); outside 0.15-0.35 L the mass "
          "distribution is unusual",
          "0.5 L puts all the mass at the ends; below 0.1 L it would be concentrated at the CG"};
}

std::vector<EnvelopeRule> BuildRules() {
  using Q = EnvelopeQuantity;
  return {
      {Q::kFroudeNumber, "Fn", "U / sqrt(g L)", 0.0, 1.2, 0.0, 3.0,
       "above Fn 1.2 a slender hull is semi-planing (Faltinsen 2005, Hydrodynamics of High-Speed Marine "
       "Vehicles, ch. 1): running trim, sinkage and dynamic lift the strips at the given attitude do not "
       "include; the paper validated Fn 0.65-0.86",
       "Fn = Fn_vol (V^(1/3)/L)^(1/2) and every hull has L/V^(1/3) >= 4, so Fn 3 is Fn_vol >= 6: a fully "
       "planing craft; usually a speed in knots given as m/s"},
      {Q::kVolumetricFroude, "Fn_vol", "U / sqrt(g V^(1/3))", 0.0, 3.0, 0.0, 6.0,
       "planing begins near Fn_vol 3 (Savitsky 1964; Faltinsen 2005 ch. 9): hydrodynamic lift, not buoyancy, "
       "carries the weight and the at-rest waterline of the strip method is not where the hull runs",
       "at Fn_vol 6 dynamic lift carries nearly all the weight (Savitsky 1964): the hull skims on a fraction "
       "of its at-rest wetted length and buoyancy-based strip theory has no content"},
      {Q::kWaveSteepness, "Hs/lambda_p", "Hs / (g Tp^2 / (2 pi))", 0.0, 1.0 / 20.0, 0.0, 1.0 / 7.0,
       "above 1/20 a sea is steeper than design seas (DNV-RP-C205 3.5.5: 1/15 at Tp 8 s to 1/25 at 15 s) "
       "and linear (Airy) wave theory loses accuracy",
       "1/7 is the breaking limit of a regular wave (Michell 1893): no sea has a significant steepness above it"},
      {Q::kRmsAccelerationG, "rms a/g", "sigma_a / g", 0.0, 1.0, 0.0, kInf,
       "an rms vertical acceleration above 1 g means accelerations beyond -1 g most cycles: the hull leaves "
       "the water and slams, which linear theory does not model (its MSI is not a prediction)",
       "a result, never refused"},
      {Q::kDampingCs, "Cs", "D = 1/2 Cs rho U v B", 0.0, 0.2, 0.0, 1.0,
       "Davis & Holloway (2003) fitted Cs 0-0.135 to tank data; beyond 0.2 the damping is not calibrated",
       "D is a lift on the section at the angle of attack v/U with slope Cs per radian; a low-aspect-ratio "
       "section's slope is well below 1 (slender-wing pi AR/2): Cs > 1 is no hull's damping"},
      {Q::kGravity, "g", "gravitational acceleration [m/s^2]", 9.78, 9.84, 9.5, 10.5,
       "Earth's surface gravity lies in 9.780 (equator) to 9.832 (poles) m/s^2 (WGS-84 normal gravity)",
       "5 % from Earth's (g = 10 for hand checks passes with the warning): another unit or a typing error"},
      {Q::kWaterDensity, "rho", "water density [kg/m^3]", 990.0, 1030.0, 900.0, 1100.0,
       "fresh water is 992-1000 kg/m^3 at 0-40 C, sea water 1020-1030 (ITTC 7.5-02-01-03)",
       "no water is 10 % off: another unit (t/m^3 gives 1.025) or a typing error"},
      {Q::kStaticTrimDeg, "static trim (deg)", "atan(|LCG - LCB| / BM_L) [deg]", 0.0, 1.0, 0.0, 5.0,
       "the RAOs are of the hull at the given waterline; an LCG off the LCB trims it at rest by about "
       "(LCG - LCB)/GM_L, which above 1 deg changes the waterline the strips see",
       "at 5 deg the hull floats at a waterline the hydrostatics and RAOs do not describe: give the LCG of "
       "the mass, or the attitude (hull.attitude), that floats at this waterline"},
      {Q::kKgOverDepth, "KG/D", "KG / D (D: top of the hull's stations)", 0.0, 2.0, 0.0, 4.0,
       "a CG more than a hull depth above the deck needs most of the mass in the superstructure (the Delft "
       "372 tank model with its instruments, KG 1.7 D, is the highest in the data)",
       "a CG three depths above the deck is no vessel's (it would capsize at rest)"},
      KyyRow(),
      {Q::kHullSpacingOverL, "hull spacing/L", "largest centre distance between hulls / L", 0.0, 0.6, 0.0, 2.0,
       "catamarans and trimarans space their hulls 0.2-0.4 L (Molland, Wellicome & Couser 1996); slender "
       "demihulls (L/B 25) sit 6-8 beams apart at 0.25 L, so the rule is in lengths, not beams",
       "a cross structure twice the hull's length apart is no vessel; usually a unit error in spacing_m"},
      {Q::kHullLength, "L", "waterline length [m]", 0.5, 400.0, 0.05, 1000.0,
       "tank models are 1-10 m, the longest ships 400-460 m",
       "no model is under 5 cm and no ship over 1 km: a hull file and its draught in millimetres"},
      {Q::kDisplacementTonnes, "displacement", "rho V [t]", 0.0, 5.0e5, 0.0, 2.0e6,
       "the largest ships displace 5-7e5 t",
       "three times the largest ship ever built: a hull in millimetres or a unit error"},
  };
}

std::string RangeText(double lo, double hi) {
  if (std::isinf(hi)) return ">= " + EnvelopeNumber(lo);
  return "[" + EnvelopeNumber(lo) + ", " + EnvelopeNumber(hi) + "]";
}

}  // namespace

const std::vector<EnvelopeRule>& EnvelopeRules() {
  static const std::vector<EnvelopeRule> rules = BuildRules();
  return rules;
}

const EnvelopeRule& EnvelopeRuleOf(EnvelopeQuantity q) {
  for (const auto& r : EnvelopeRules())
    if (r.quantity == q) return r;
  throw std::logic_error("validity envelope: no row for a quantity");
}

std::vector<EnvelopeFinding> CheckEnvelopeValue(EnvelopeQuantity q, double value, const std::string& key,
                                                const std::string& context) {
  const EnvelopeRule& r = EnvelopeRuleOf(q);
  const std::string head =
      std::string(r.name) + " = " + EnvelopeNumber(value) + (context.empty() ? "" : " (" + context + ")");
  if (!(value >= r.hard_min && value <= r.hard_max))
    return {{q, key, head + " is outside the method's validity envelope " + RangeText(r.hard_min, r.hard_max) +
                         ": " + r.hard_source,
             true}};
  if (!(value >= r.flag_min && value <= r.flag_max))
    return {{q, key, head + " is outside the usual range " + RangeText(r.flag_min, r.flag_max) + ": " +
                         r.flag_source,
             false}};
  return {};
}

std::vector<EnvelopeFinding> CheckEnvelope(const EnvelopeInput& in) {
  using Q = EnvelopeQuantity;
  std::vector<EnvelopeFinding> out;
  auto add = [&](std::vector<EnvelopeFinding> f) { out.insert(out.end(), f.begin(), f.end()); };
  if (!std::isnan(in.g_m_s2)) add(CheckEnvelopeValue(Q::kGravity, in.g_m_s2, "water.g_m_s2"));
  if (!std::isnan(in.rho_kg_m3)) add(CheckEnvelopeValue(Q::kWaterDensity, in.rho_kg_m3, "water.rho_kg_m3"));
  if (!std::isnan(in.cs)) add(CheckEnvelopeValue(Q::kDampingCs, in.cs, "solver.Cs"));
  const hull::Hydrostatics* hs = in.hs;
  if (hs) {
    add(CheckEnvelopeValue(Q::kHullLength, hs->L_m, "hull", "the hull's waterline length"));
    add(CheckEnvelopeValue(Q::kDisplacementTonnes, hs->displacement_t, "hull",
                           "V " + EnvelopeNumber(hs->volume_m3) + " m^3"));
  }
  if (hs && in.hull && hs->L_m > 0.0) {
    const double s = LargestHullSpacing(*in.hull);
    if (s > 0.0)
      add(CheckEnvelopeValue(Q::kHullSpacingOverL, s / hs->L_m, "hull",
                             "centre spacing " + EnvelopeNumber(s) + " m, L " + EnvelopeNumber(hs->L_m) + " m"));
  }
  const double g = std::isnan(in.g_m_s2) ? 9.81 : in.g_m_s2;
  if (hs && !std::isnan(in.speed_m_s) && hs->L_m > 0.0 && hs->volume_m3 > 0.0 && g > 0.0) {
    const double U = in.speed_m_s;
    const std::string ctx = "U " + EnvelopeNumber(U) + " m/s = " + EnvelopeNumber(U / (1852.0 / 3600.0)) + " kn";
    add(CheckEnvelopeValue(Q::kFroudeNumber, U / std::sqrt(g * hs->L_m), "speed", ctx + ", L " + EnvelopeNumber(hs->L_m) + " m"));
    const double v13 = std::cbrt(hs->volume_m3);
    add(CheckEnvelopeValue(Q::kVolumetricFroude, U / std::sqrt(g * v13), "speed",
                           ctx + ", V^(1/3) " + EnvelopeNumber(v13) + " m"));
  }
  if (hs && in.mass) {
    const hull::MassProperties& m = *in.mass;
    if (hs->bm_l_m > 0.0) {
      const double d = m.lcg_m_from_ap - hs->lcb_m_from_ap;
      const double trim = std::atan(std::fabs(d) / hs->bm_l_m) * 180.0 / M_PI;
      add(CheckEnvelopeValue(Q::kStaticTrimDeg, trim, "mass.lcg_m_from_ap",
                             "LCG " + EnvelopeNumber(std::fabs(d)) + " m " + (d >= 0 ? "forward" : "aft") + " of the LCB, BM_L " +
                                 EnvelopeNumber(hs->bm_l_m) + " m"));
    }
    const double depth = in.hull ? HullDepth(*in.hull) : 0.0;
    if (depth > 0.0)
      add(CheckEnvelopeValue(Q::kKgOverDepth, m.kg_m / depth, "mass.kg_m",
                             "KG " + EnvelopeNumber(m.kg_m) + " m, depth of the hull's stations " + EnvelopeNumber(depth) + " m"));
  }
  std::stable_partition(out.begin(), out.end(), [](const EnvelopeFinding& f) { return f.refuse; });
  return out;
}

double PeakWaveLength(const sk::SeaState& sea, double g_m_s2) {
  const double tp = std::isnan(sea.Tp_s) ? sea.Tz_s / sk::ZeroCrossingToPeakPeriodRatio(sea.gamma) : sea.Tp_s;
  return g_m_s2 * tp * tp / (2.0 * M_PI);
}

std::vector<std::string> ResponseEnvelopeWarnings(const sk::DesignEvaluation& ev, double g_m_s2) {
  std::vector<std::string> w;
  for (std::size_t i = 0; i < ev.seas.size(); ++i) {
    const sk::SeaEvaluation& s = ev.seas[i];
    const std::string sea = "sea " + std::to_string(i + 1) + " (Hs " + EnvelopeNumber(s.sea.Hs_m) + " m, Tp " + EnvelopeNumber(s.Tp_s) + " s)";
    const double lambda_p = g_m_s2 * s.Tp_s * s.Tp_s / (2.0 * M_PI);
    for (const auto& f : CheckEnvelopeValue(EnvelopeQuantity::kWaveSteepness, s.sea.Hs_m / lambda_p, "seas",
                                            sea + ", lambda_p " + EnvelopeNumber(lambda_p) + " m"))
      w.push_back(f.message);  // beyond the hard limit the sea was refused as it was read
    double worst = 0.0;
    std::string where;
    for (const auto& p : s.positions)
      if (p.rms_accel_g > worst) {
        worst = p.rms_accel_g;
        where = p.position;
      }
    for (const auto& f : CheckEnvelopeValue(EnvelopeQuantity::kRmsAccelerationG, worst, "seas",
                                            sea + ", at the " + where + " position"))
      w.push_back(f.message);
  }
  return w;
}

double HullDepth(const hull::HullForm& hull) {
  double top = 0.0;
  for (const auto& b : hull.bodies)
    for (const auto& st : b.stations)
      for (double z : st.z_m) top = std::max(top, z);
  return top;
}

double LargestHullSpacing(const hull::HullForm& hull) {
  // Centrelines: each body at +-y_centre (a mirrored pair when y_centre > 0).
  std::vector<double> y;
  for (const auto& b : hull.bodies) {
    y.push_back(b.y_centre_m);
    if (b.y_centre_m > 0.0) y.push_back(-b.y_centre_m);
  }
  if (y.size() < 2) return 0.0;
  return *std::max_element(y.begin(), y.end()) - *std::min_element(y.begin(), y.end());
}

}  // namespace hullopt::eval
