#include "evaluation/seakeeping_criteria.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "seas/relative_motion.h"

namespace hullopt::eval {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// x/L of "fp" or "x_over_L=V"; false for another location. *ok false for a malformed value.
bool StationLocation(const std::string& loc, double* x_over_L, bool* ok) {
  *ok = true;
  if (loc == "fp") {
    *x_over_L = 1.0;
    return true;
  }
  const std::string prefix = "x_over_L=";
  if (loc.rfind(prefix, 0) != 0) return false;
  const std::string v = loc.substr(prefix.size());
  char* end = nullptr;
  *x_over_L = std::strtod(v.c_str(), &end);
  *ok = !v.empty() && end && *end == '\0' && std::isfinite(*x_over_L) && *x_over_L >= 0.0 && *x_over_L <= 1.0;
  return true;
}

double Interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  if (at <= x.front()) return y.front();
  if (at >= x.back()) return y.back();
  const auto it = std::upper_bound(x.begin(), x.end(), at);
  const size_t i = static_cast<size_t>(it - x.begin());
  const double t = (at - x[i - 1]) / (x[i] - x[i - 1]);
  return y[i - 1] + t * (y[i] - y[i - 1]);
}

std::string CriterionNumber(double v, int digits = 3) {
  char b[32];
  std::snprintf(b, sizeof b, "%.*g", digits, v);
  return b;
}

}  // namespace

std::string CriterionQuantityName(CriterionQuantity q) {
  switch (q) {
    case CriterionQuantity::kRmsVerticalAcceleration: return "rms_vertical_acceleration";
    case CriterionQuantity::kMsi: return "msi";
    case CriterionQuantity::kSlammingProbability: return "slamming_probability";
    case CriterionQuantity::kDeckWetnessProbability: return "deck_wetness_probability";
  }
  return "";
}

std::string CriterionQuantityUnit(CriterionQuantity q) {
  switch (q) {
    case CriterionQuantity::kRmsVerticalAcceleration: return "g";
    case CriterionQuantity::kMsi: return "%";
    default: return "-";
  }
}

bool ParseCriterionQuantity(const std::string& name, CriterionQuantity* q) {
  for (auto c : {CriterionQuantity::kRmsVerticalAcceleration, CriterionQuantity::kMsi,
                 CriterionQuantity::kSlammingProbability, CriterionQuantity::kDeckWetnessProbability})
    if (CriterionQuantityName(c) == name) {
      *q = c;
      return true;
    }
  return false;
}

bool SeakeepingCriterion::IsValid(std::string* error) const {
  std::string e;
  double x = 0.0;
  bool ok = true;
  const bool station = StationLocation(location, &x, &ok);
  const bool probability = quantity == CriterionQuantity::kSlammingProbability ||
                           quantity == CriterionQuantity::kDeckWetnessProbability;
  if (name.empty())
    e = "criterion: the name is empty";
  else if (!(limit > 0.0) || !std::isfinite(limit))
    e = "criterion '" + name + "': limit " + CriterionNumber(limit) + " must be > 0";
  else if (probability && limit > 1.0)
    e = "criterion '" + name + "': a probability limit " + CriterionNumber(limit) + " must be <= 1";
  else if (location.empty())
    e = "criterion '" + name + "': the location is empty";
  else if (station && !ok)
    e = "criterion '" + name + "': location '" + location + "': x_over_L must be a number within 0..1";
  else if (probability && !station)
    e = "criterion '" + name + "': location '" + location + "': a " + CriterionQuantityName(quantity) +
        " is judged at fp or x_over_L=V";
  else if (quantity == CriterionQuantity::kMsi && station)
    e = "criterion '" + name + "': location '" + location +
        "': MSI is judged at a passenger position (forward, lcg, transom, a user point) or mean";
  if (e.empty()) return true;
  if (error) *error = e;
  return false;
}

double BowGeometry::DraughtAt(double x) const { return waterline_z_m - Interpolate(x_over_L, keel_z_m, x); }
double BowGeometry::FreeboardAt(double x) const { return Interpolate(x_over_L, deck_z_m, x) - waterline_z_m; }

BowGeometry BowGeometryOf(const DesignCase& design) {
  BowGeometry g;
  const auto& h = design.hydrostatics;
  g.waterline_z_m = design.hull.draught_m;
  g.length_m = h.L_m;
  if (design.hull.bodies.empty() || !(h.L_m > 0.0)) return g;
  for (const auto& s : design.hull.bodies.front().stations) {
    if (s.z_m.empty()) continue;
    const double x = (s.x_m - h.x_ap_m) / h.L_m;
    if (!g.x_over_L.empty() && !(x > g.x_over_L.back())) continue;
    g.x_over_L.push_back(x);
    g.keel_z_m.push_back(*std::min_element(s.z_m.begin(), s.z_m.end()));
    g.deck_z_m.push_back(*std::max_element(s.z_m.begin(), s.z_m.end()));
  }
  return g;
}

SeakeepingVerdict JudgeDesign(const sk::RaoTable& rao, const sk::HullExtent& hull,
                              const sk::DesignEvaluation& evaluation, const BowGeometry& geometry,
                              const CriteriaSet& set, const sk::ResponseOptions& response) {
  std::string err;
  for (const auto& c : set.criteria)
    if (!c.IsValid(&err)) throw std::invalid_argument(err);
  if (!hull.IsValid(&err)) throw std::invalid_argument(err);
  const double L = hull.cg_to_transom_m + hull.cg_to_bow_m;  // AP to FP about the CG
  const double g = rao.g_m_s2;
  SeakeepingVerdict v;
  for (const auto& sea : evaluation.seas) {
    SeaVerdict sv;
    sv.Hs_m = sea.sea.Hs_m;
    sv.Tz_s = sea.Tz_s;
    sv.all_met = true;
    const sk::WaveSpectrum spectrum(sea.sea);
    const sk::SeaResponse point(rao, spectrum, response);
    for (const auto& c : set.criteria) {
      CriterionCheck k;
      double x_over_L = 0.0;
      bool ok = true;
      if (StationLocation(c.location, &x_over_L, &ok)) {
        k.x_from_cg_m = -hull.cg_to_transom_m + x_over_L * L;
        if (c.quantity == CriterionQuantity::kRmsVerticalAcceleration) {
          k.value = point.Moments(k.x_from_cg_m).rms_acceleration_m_s2() / g;
        } else if (!geometry.known()) {
          k.judged = false;
          k.note = "not judged: no hull geometry (RAOs read from a file)";
        } else {
          const sk::RelativeMotionMoments r = sk::RelativeMotionAt(rao, spectrum, k.x_from_cg_m, response);
          if (c.quantity == CriterionQuantity::kDeckWetnessProbability) {
            const double f = geometry.FreeboardAt(x_over_L);
            if (f > 0.0) {
              k.value = sk::DeckWetnessProbability(f, r);
              k.note = "freeboard " + CriterionNumber(f) + " m, rms relative motion " + CriterionNumber(r.rms_m()) + " m";
            } else {
              k.value = 1.0;
              k.note = "deck edge at or below the waterline";
            }
          } else {
            const double T = geometry.DraughtAt(x_over_L);
            const double vth = sk::OchiThresholdVelocity(geometry.length_m, g);
            if (T > 0.0) {
              k.value = sk::SlammingProbability(T, vth, r);
              k.note = "draught " + CriterionNumber(T) + " m, v_th " + CriterionNumber(vth) + " m/s, rms relative motion " +
                       CriterionNumber(r.rms_m()) + " m";
            } else {
              k.value = 0.0;
              k.note = "station clear of the water at rest: no bottom slamming by Ochi's criterion";
            }
          }
          k.events_per_hour = sk::EventsPerHour(k.value, r);
        }
      } else {
        const sk::PositionResult* p = nullptr;
        if (c.location == "mean") p = &sea.mean;
        for (const auto& q : sea.positions)
          if (q.position == c.location) p = &q;
        if (!p)
          throw std::invalid_argument("criterion '" + c.name + "': location '" + c.location +
                                      "' is not a position of the design (fp, x_over_L=V, forward, lcg, transom, "
                                      "mean or a user point)");
        k.x_from_cg_m = p->x_from_cg_m;
        k.value = c.quantity == CriterionQuantity::kMsi ? p->msi_pct : p->rms_accel_g;
      }
      if (k.judged) {
        k.met = k.value <= c.limit;
        k.margin = (c.limit - k.value) / c.limit;
        sv.all_met = sv.all_met && k.met;
      } else {
        k.value = kNaN;
        k.margin = kNaN;
      }
      sv.checks.push_back(k);
    }
    v.seas.push_back(std::move(sv));
  }
  // The limiting Hs: every sea up to it (by Hs) meets every judged criterion.
  std::vector<const SeaVerdict*> by_hs;
  for (const auto& s : v.seas) by_hs.push_back(&s);
  std::stable_sort(by_hs.begin(), by_hs.end(), [](auto* a, auto* b) { return a->Hs_m < b->Hs_m; });
  for (const auto* s : by_hs) {
    if (!s->all_met) break;
    v.limiting_Hs_m = s->Hs_m;
  }
  return v;
}

}  // namespace hullopt::eval
