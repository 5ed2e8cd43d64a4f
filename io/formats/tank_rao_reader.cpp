#include "io/formats/tank_rao_reader.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>

#include "io/formats/csv_fields.h"
#include "io/formats/input_error.h"

namespace hullopt::io {
namespace {

// Largest plausible non-dimensional RAO magnitude: far above any measured peak (the paper's and the Delft 372
// data peak below 3), far below values whose squares overflow in the fit's residuals.
constexpr double kMaxTankRao = 100.0;

std::string Num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace

std::vector<opt::TankRaoPoint> ReadTankRaoCsv(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file + ": cannot open tank RAO file (does it exist and is it readable?)");
  const std::string contract =
      "a tank RAO CSV needs the columns Fn, omega_e_rad_s or lambda_over_L, heave_rao and pitch_rao";
  std::string line;
  int lineno = 0;
  std::vector<std::string> header;
  while (std::getline(in, line)) {
    ++lineno;
    const std::string t = TrimField(line);
    if (t.empty() || t[0] == '#') continue;
    header = SplitCsvLine(t);
    break;
  }
  if (header.empty()) throw InputError(file + ": empty file (no header line; " + contract + ")");
  const int header_line = lineno;
  std::map<std::string, int> col;
  for (int i = 0; i < static_cast<int>(header.size()); ++i) {
    if (col.count(header[i])) {
      throw InputError(file + ":" + std::to_string(header_line) + ": column '" + header[i] +
                       "' appears twice in the header");
    }
    col[header[i]] = i;
  }
  for (const char* required : {"Fn", "heave_rao", "pitch_rao"}) {
    if (!col.count(required)) {
      throw InputError(file + ":" + std::to_string(header_line) + ": missing column '" + required + "' (" +
                       contract + ")");
    }
  }
  const bool has_w = col.count("omega_e_rad_s") > 0, has_l = col.count("lambda_over_L") > 0;
  if (!has_w && !has_l) {
    throw InputError(file + ":" + std::to_string(header_line) +
                     ": missing column 'omega_e_rad_s' or 'lambda_over_L' (" + contract + ")");
  }

  std::vector<opt::TankRaoPoint> points;
  while (std::getline(in, line)) {
    ++lineno;
    const std::string t = TrimField(line);
    if (t.empty() || t[0] == '#') continue;
    const std::vector<std::string> f = SplitCsvLine(t);
    const std::string where = file + ":" + std::to_string(lineno);
    if (f.size() != header.size()) {
      throw InputError(where + ": " + std::to_string(f.size()) + " fields, the header has " +
                       std::to_string(header.size()));
    }
    // A cell as a finite number; `optional` cells may be empty (returns false then).
    auto number = [&](const std::string& name, double* v, bool optional = false) {
      const std::string& s = f[col.at(name)];
      if (s.empty()) {
        if (optional) return false;
        throw InputError(where + ": column '" + name + "' is empty: a number is required");
      }
      char* end = nullptr;
      *v = std::strtod(s.c_str(), &end);
      if (end == s.c_str() || *end != '\0') {
        throw InputError(where + ": column '" + name + "' = '" + s + "': not a number");
      }
      if (!std::isfinite(*v)) throw InputError(where + ": column '" + name + "' = " + s + ": must be finite");
      return true;
    };
    auto positive = [&](const std::string& name, double v, const std::string& why) {
      if (!(v > 0))
        throw InputError(where + ": column '" + name + "' = " + Num(v) + ": must be > 0 (" + why + ")");
    };
    opt::TankRaoPoint p;
    p.source = where;
    number("Fn", &p.Fn);
    positive("Fn", p.Fn, "the calibration needs forward speed");
    if (has_w) {
      p.has_omega_e = number("omega_e_rad_s", &p.omega_e_rad_s);
      positive("omega_e_rad_s", p.omega_e_rad_s, "a frequency");
    }
    if (has_l) {
      p.has_lambda_over_L = number("lambda_over_L", &p.lambda_over_L);
      positive("lambda_over_L", p.lambda_over_L, "a wave length ratio");
    }
    number("heave_rao", &p.heave_amp);
    number("pitch_rao", &p.pitch_amp);
    for (const auto& [name, v] : {std::pair<std::string, double>{"heave_rao", p.heave_amp},
                                  std::pair<std::string, double>{"pitch_rao", p.pitch_amp}}) {
      if (v < 0) {
        throw InputError(where + ": column '" + name + "' = " + Num(v) +
                         ": an RAO magnitude must be >= 0 (a sign belongs in the phase column)");
      }
      if (v > kMaxTankRao) {
        throw InputError(where + ": column '" + name + "' = " + Num(v) + ": must be <= " + Num(kMaxTankRao) +
                         " (non-dimensional RAOs |x3|/A and |x5|/(kA) are of order 1: measured peaks are below "
                         "3; a larger value is a unit or column error)");
      }
    }
    if (col.count("heave_phase_deg")) p.has_heave_phase = number("heave_phase_deg", &p.heave_phase_deg, true);
    if (col.count("pitch_phase_deg")) p.has_pitch_phase = number("pitch_phase_deg", &p.pitch_phase_deg, true);
    points.push_back(p);
  }
  if (points.empty()) throw InputError(file + ": no data rows after the header (empty file)");
  return points;
}

std::vector<opt::CalibrationCase> GroupTankRaoBySpeed(const std::vector<opt::TankRaoPoint>& points,
                                                      const std::vector<double>& speeds_Fn,
                                                      const std::string& hull_name, double hull_parameter,
                                                      double Fn_tolerance) {
  std::vector<opt::CalibrationCase> cases(speeds_Fn.size());
  std::string defined;
  for (std::size_t s = 0; s < speeds_Fn.size(); ++s) {
    char label[64];
    std::snprintf(label, sizeof label, "Fn %g", speeds_Fn[s]);
    cases[s].label = hull_name.empty() ? label : hull_name + " " + label;
    cases[s].hull = hull_name;
    cases[s].Fn = speeds_Fn[s];
    cases[s].hull_parameter = hull_parameter;
    defined += (defined.empty() ? "" : ", ") + Num(speeds_Fn[s]);
  }
  for (const auto& p : points) {
    std::size_t match = speeds_Fn.size();
    for (std::size_t s = 0; s < speeds_Fn.size(); ++s)
      if (std::fabs(p.Fn - speeds_Fn[s]) <= Fn_tolerance) match = s;
    if (match == speeds_Fn.size()) {
      throw InputError(p.source + ": column 'Fn' = " + Num(p.Fn) + ": not a speed of the config (Fn " +
                       defined + (hull_name.empty() ? "" : ", hull '" + hull_name + "'") +
                       "); add it to the config's speeds or remove the rows");
    }
    cases[match].points.push_back(p);
  }
  for (const auto& c : cases) {
    if (c.points.empty()) {
      throw InputError("config speed Fn " + Num(c.Fn) +
                       (hull_name.empty() ? "" : " of hull '" + hull_name + "'") +
                       " has no rows in the tank data files: give data for it or remove it from the config");
    }
  }
  return cases;
}

}  // namespace hullopt::io
