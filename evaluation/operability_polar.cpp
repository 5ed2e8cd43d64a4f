#include "evaluation/operability_polar.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "evaluation/oblique_design.h"

namespace hullopt::eval {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string Num(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

}  // namespace

std::string PolarQuantityName(PolarQuantity q) {
  switch (q) {
    case PolarQuantity::kRmsVerticalAcceleration: return "rms_vertical_acceleration";
    case PolarQuantity::kRmsLateralAcceleration: return "rms_lateral_acceleration";
    case PolarQuantity::kRmsRoll: return "rms_roll";
    case PolarQuantity::kMsi: return "msi";
  }
  return "";
}

std::string PolarQuantityUnit(PolarQuantity q) {
  switch (q) {
    case PolarQuantity::kRmsRoll: return "deg";
    case PolarQuantity::kMsi: return "%";
    default: return "g";
  }
}

bool PolarOptions::IsValid(std::string* error) const {
  std::string e;
  if (speeds_m_s.empty()) e = "speeds: the list is empty";
  for (std::size_t i = 0; i < speeds_m_s.size() && e.empty(); ++i)
    if (!(speeds_m_s[i] >= 0.0) || !std::isfinite(speeds_m_s[i]))
      e = "speeds[" + std::to_string(i) + "] = " + Num(speeds_m_s[i]) + " m/s: must be finite and >= 0";
  if (e.empty() && headings_deg.empty()) e = "headings_deg: the list is empty";
  if (e.empty()) e = CheckHeadingList(headings_deg, "headings_deg");
  if (e.empty() && omega_rad_s.size() < 2) e = "omega: at least 2 wave frequencies are needed";
  for (std::size_t i = 0; i < omega_rad_s.size() && e.empty(); ++i)
    if (!(omega_rad_s[i] > 0.0) || !std::isfinite(omega_rad_s[i]) || (i > 0 && !(omega_rad_s[i] > omega_rad_s[i - 1])))
      e = "omega[" + std::to_string(i) + "] = " + Num(omega_rad_s[i]) + " rad/s: must be > 0 and increasing";
  if (e.empty() && !evaluation.IsValid(&e)) e = "evaluation: " + e;
  if (e.empty()) return true;
  if (error) *error = e;
  return false;
}

double ZeroEncounterWaveFrequency(double U, double heading_deg, double g) {
  const double u = U * std::cos(heading_deg * kPi / 180.0);
  return u > 1e-12 * std::max(U, 1.0) ? g / u : std::numeric_limits<double>::infinity();
}

OperabilityPolar ComputeOperabilityPolar(const ObliqueSolve& solve, double g, const sk::HullExtent& hull,
                                         const sk::ScatterDiagram& diagram,
                                         const std::vector<PolarCriterion>& criteria,
                                         const std::vector<sk::PassengerPosition>& user_points,
                                         const PolarOptions& options, const SpeedFault& unsolvable) {
  std::string err;
  if (!options.IsValid(&err)) throw std::invalid_argument("operability polar: " + err);
  if (!diagram.IsValid(&err)) throw std::invalid_argument("scatter diagram: " + err);
  if (!hull.IsValid(&err)) throw std::invalid_argument(err);
  if (criteria.empty()) throw std::invalid_argument("operability polar: no criteria");
  // The points of every criterion (a mean criterion: the three standard positions).
  const std::vector<sk::PassengerPosition> standard = sk::StandardPassengerPositions(hull.cg_to_transom_m);
  std::vector<ShipPoint> points;
  std::vector<std::vector<std::size_t>> criterion_points;
  for (const auto& c : criteria) {
    if (!(c.limit > 0.0) || !std::isfinite(c.limit))
      throw std::invalid_argument("criterion '" + c.name + "': limit " + Num(c.limit) + " must be > 0");
    if (!std::isfinite(c.y_m) || !std::isfinite(c.z_m))
      throw std::invalid_argument("criterion '" + c.name + "': y and z must be finite");
    std::vector<std::size_t> idx;
    if (c.quantity != PolarQuantity::kRmsRoll) {
      std::vector<sk::PassengerPosition> at;
      if (c.position == "mean") at = standard;
      for (const auto& p : standard)
        if (p.name == c.position) at.push_back(p);
      for (const auto& p : user_points)
        if (p.name == c.position) at.push_back(p);
      if (at.empty())
        throw std::invalid_argument("criterion '" + c.name + "': unknown position '" + c.position +
                                    "' (forward, lcg, transom, mean or a user point)");
      for (const auto& p : at) {
        idx.push_back(points.size());
        points.push_back({p.name, p.x_from_cg_m, c.y_m, c.z_m});
      }
    }
    criterion_points.push_back(idx);
  }
  std::vector<sk::WaveSpectrum> spectra;
  double psum = 0.0;
  for (std::size_t i = 0; i < diagram.cells.size(); ++i) {
    spectra.emplace_back(diagram.Sea(i));
    psum += diagram.cells[i].probability;
  }
  const std::size_t nh = options.headings_deg.size();
  OperabilityPolar out;
  for (double U : options.speeds_m_s) {
    std::vector<double> solved;
    std::vector<std::size_t> solved_index(nh, nh);
    std::vector<PolarCell> row(nh);
    const std::string speed_fault = unsolvable ? unsolvable(U) : std::string();
    for (std::size_t h = 0; h < nh; ++h) {
      PolarCell& cell = row[h];
      cell.speed_m_s = U;
      cell.heading_deg = options.headings_deg[h];
      if (!speed_fault.empty()) {
        cell.computed = false;
        cell.operability = std::numeric_limits<double>::quiet_NaN();
        cell.criterion_share.assign(criteria.size(), std::numeric_limits<double>::quiet_NaN());
        cell.note = speed_fault;
        continue;
      }
      const double w0 = ZeroEncounterWaveFrequency(U, cell.heading_deg, g);
      if (options.omega_rad_s.back() >= w0) {
        cell.computed = false;
        cell.operability = std::numeric_limits<double>::quiet_NaN();
        cell.criterion_share.assign(criteria.size(), std::numeric_limits<double>::quiet_NaN());
        cell.note = "encounter frequency <= 0 for wave frequencies >= g/(U cos beta) = " + Num(w0) +
                    " rad/s, within the frequency grid (up to " + Num(options.omega_rad_s.back()) +
                    " rad/s): following or quartering seas at speed, outside the strip theory";
        continue;
      }
      solved_index[h] = solved.size();
      solved.push_back(cell.heading_deg);
    }
    sk::ObliqueStripResult result;
    if (!solved.empty()) result = solve(U, solved);
    for (std::size_t h = 0; h < nh; ++h) {
      PolarCell& cell = row[h];
      if (!cell.computed) continue;
      cell.criterion_share.assign(criteria.size(), 0.0);
      double all = 0.0;
      for (std::size_t s = 0; s < spectra.size(); ++s) {
        const ObliqueSeaStatistics st =
            ObliqueStatisticsInSea(result, solved_index[h], g, spectra[s], points, options.evaluation);
        const double p = diagram.cells[s].probability;
        bool every = true;
        for (std::size_t c = 0; c < criteria.size(); ++c) {
          double v = 0.0;
          if (criteria[c].quantity == PolarQuantity::kRmsRoll) {
            v = st.rms_roll_rad * 180.0 / kPi;
          } else {
            for (std::size_t j : criterion_points[c]) {
              const PointSeaStatistics& q = st.points[j];
              switch (criteria[c].quantity) {
                case PolarQuantity::kRmsVerticalAcceleration: v += q.rms_vertical_accel_m_s2 / g; break;
                case PolarQuantity::kRmsLateralAcceleration: v += q.rms_lateral_accel_m_s2 / g; break;
                default: v += q.msi_pct; break;
              }
            }
            v /= static_cast<double>(criterion_points[c].size());
          }
          const bool met = v <= criteria[c].limit;
          if (met) cell.criterion_share[c] += p / psum;
          every = every && met;
        }
        if (every) all += p;
      }
      cell.operability = all / psum;
    }
    for (auto& c : row) out.cells.push_back(std::move(c));
  }
  return out;
}

OperabilityPolar ComputeOperabilityPolar(const DesignCase& design, double kxx_m, const sk::ScatterDiagram& diagram,
                                         const std::vector<PolarCriterion>& criteria,
                                         const std::vector<sk::PassengerPosition>& user_points,
                                         const PolarOptions& options) {
  sk::ObliqueStripOptions strip;
  SetDesignRollDamping(design, options.roll_damping, &strip);
  std::vector<PolarFlag> flags;
  auto raise = [&](const std::string& f, double U, bool method) {
    auto it = std::find_if(flags.begin(), flags.end(), [&](const PolarFlag& p) { return p.text == f; });
    if (it == flags.end()) it = flags.insert(flags.end(), PolarFlag{f, {}, method});
    it->speeds_m_s.push_back(U);
  };
  const ObliqueSolve solve = [&](double U, const std::vector<double>& headings) {
    std::vector<std::string> warnings;
    sk::ObliqueStripResult r = SolveObliqueDesign(design, U, options.omega_rad_s, headings, kxx_m, strip, &warnings);
    for (const std::string& w : warnings) raise(w, U, true);
    // The flags at this speed's roll natural frequency (SolveObliqueDesign puts the design's rho and g in).
    sk::RollDampingOptions roll = strip.roll_damping;
    roll.rho_kg_m3 = design.water.rho_kg_m3;
    roll.g_m_s2 = design.water.g_m_s2;
    for (const std::string& f : sk::RollDampingRangeFlags(strip.roll_damping_hull, RollNaturalFrequency(r), U, roll))
      raise(f, U, false);
    return r;
  };
  OperabilityPolar out = ComputeOperabilityPolar(solve, design.water.g_m_s2, design.Extent(), diagram, criteria,
                                                 user_points, options,
                                                 [&](double U) { return ObliqueSpeedFault(design, U); });
  out.method = ObliqueMethodNote(design);
  out.roll_damping = RollDampingNote(strip);
  out.flags = std::move(flags);
  return out;
}

}  // namespace hullopt::eval
