#include "io/formats/measured_coefficients_csv.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>

#include "io/formats/csv_fields.h"
#include "io/formats/input_error.h"

namespace hullopt::io {
namespace {

// The rows of a CSV file as column name → text, with each row's line number.
struct Table {
  std::string file;
  std::map<std::string, int> col;
  std::vector<std::vector<std::string>> rows;
  std::vector<int> line;

  double Number(std::size_t r, const std::string& name) const {
    const std::string& text = rows[r][col.at(name)];
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    if (text.empty() || *end != '\0' || !std::isfinite(v))
      throw InputError(file + ":" + std::to_string(line[r]) + ": column '" + name + "' = '" + text +
                       "': must be a finite number");
    return v;
  }
  std::string Text(std::size_t r, const std::string& name) const {
    const auto it = col.find(name);
    return it == col.end() ? std::string() : rows[r][it->second];
  }
};

Table ReadTable(const std::string& file, const std::vector<std::string>& required, const std::string& what) {
  std::ifstream in(file);
  if (!in) throw InputError(file + ": cannot open " + what + " file (does it exist and is it readable?)");
  Table t;
  t.file = file;
  std::string raw;
  int lineno = 0;
  bool have_header = false;
  std::size_t width = 0;
  while (std::getline(in, raw)) {
    ++lineno;
    const std::string s = TrimField(raw);
    if (s.empty() || s[0] == '#') continue;
    auto fields = SplitCsvLine(s);
    if (!have_header) {
      for (int i = 0; i < static_cast<int>(fields.size()); ++i) t.col[fields[i]] = i;
      for (const auto& c : required)
        if (!t.col.count(c))
          throw InputError(file + ":" + std::to_string(lineno) + ": missing column '" + c + "' (a " + what +
                           " file needs the columns of io/formats/measured_coefficients_csv.h)");
      width = fields.size();
      have_header = true;
      continue;
    }
    if (fields.size() != width)
      throw InputError(file + ":" + std::to_string(lineno) + ": " + std::to_string(fields.size()) +
                       " fields where the header has " + std::to_string(width));
    t.rows.push_back(std::move(fields));
    t.line.push_back(lineno);
  }
  if (!have_header) throw InputError(file + ": empty file (no header line)");
  if (t.rows.empty()) throw InputError(file + ": no data rows");
  return t;
}

// How the report's signs and phases map to hullopt's (docs/coefficients.md, "Conventions of the measured
// data", established against the computation at Fn 0.30).
constexpr double kCouplingSign = 1.0;
constexpr double kF3PhaseShiftDeg = 0.0;
constexpr double kF5PhaseShiftDeg = 0.0;

double WrapDeg(double d) {
  while (d > 180.0) d -= 360.0;
  while (d <= -180.0) d += 360.0;
  return d;
}

}  // namespace

std::vector<MeasuredCoefficientRow> ReadForcedOscillationCsv(const std::string& file, int dof) {
  const bool heave = dof == 3;
  const std::vector<std::string> cols =
      heave ? std::vector<std::string>{"Fn", "trim_sinkage", "omega_nondim_sqrtLg", "A33_kg", "A53_kg_m",
                                       "B33_kg_per_s", "B53_kg_m_per_s"}
            : std::vector<std::string>{"Fn", "trim_sinkage", "omega_nondim_sqrtLg", "A55_kg_m2", "A35_kg_m",
                                       "B55_kg_m2_per_s", "B35_kg_m_per_s"};
  const Table t = ReadTable(file, cols, heave ? "forced heave oscillation" : "forced pitch oscillation");
  std::vector<MeasuredCoefficientRow> out;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    MeasuredCoefficientRow m;
    m.Fn = t.Number(r, "Fn");
    m.trim_sinkage = t.Text(r, "trim_sinkage");
    m.omega_nondim = t.Number(r, "omega_nondim_sqrtLg");
    if (!(m.Fn > 0.0) || !(m.omega_nondim > 0.0))
      throw InputError(file + ":" + std::to_string(t.line[r]) + ": Fn and omega_nondim_sqrtLg must be > 0");
    m.a_diag = t.Number(r, cols[3]);
    m.a_cross = t.Number(r, cols[4]);
    m.b_diag = t.Number(r, cols[5]);
    m.b_cross = t.Number(r, cols[6]);
    out.push_back(m);
  }
  return out;
}

std::vector<MeasuredWaveLoadRow> ReadRestrainedWaveLoadCsv(const std::string& file, int* skipped) {
  const Table t = ReadTable(file,
                            {"Fn", "lambda_over_L", "wave_amp_mm", "F3a_N", "F3_phase_deg", "F5a_Nm",
                             "F5_phase_deg"},
                            "restrained-model wave load");
  std::vector<MeasuredWaveLoadRow> out;
  int n_skipped = 0;
  for (std::size_t r = 0; r < t.rows.size(); ++r) {
    if (!t.Text(r, "note").empty()) {
      ++n_skipped;
      continue;
    }
    MeasuredWaveLoadRow m;
    m.Fn = t.Number(r, "Fn");
    m.lambda_over_L = t.Number(r, "lambda_over_L");
    m.wave_amp_m = t.Number(r, "wave_amp_mm") / 1000.0;
    m.F3_N = t.Number(r, "F3a_N");
    m.F3_phase_deg = t.Number(r, "F3_phase_deg");
    m.F5_N_m = t.Number(r, "F5a_Nm");
    m.F5_phase_deg = t.Number(r, "F5_phase_deg");
    if (!(m.Fn > 0.0) || !(m.lambda_over_L > 0.0) || !(m.wave_amp_m > 0.0) || m.F3_N < 0.0 || m.F5_N_m < 0.0)
      throw InputError(file + ":" + std::to_string(t.line[r]) +
                       ": Fn, lambda_over_L and wave_amp_mm must be > 0 and the amplitudes >= 0");
    out.push_back(m);
  }
  if (skipped) *skipped = n_skipped;
  return out;
}

}  // namespace hullopt::io

namespace hullopt::io {

MeasuredCoefficientPoints MeasuredPointsForSpeed(const std::vector<MeasuredCoefficientRow>& heave,
                                                 const std::vector<MeasuredCoefficientRow>& pitch,
                                                 const std::vector<MeasuredWaveLoadRow>& loads, double Fn,
                                                 const std::string& trim_sinkage, double U, double g,
                                                 double L) {
  constexpr double kFnTolerance = 0.005;  // the files give Fn to two decimals
  MeasuredCoefficientPoints m;
  m.label = "measured, van 't Veer (1998)";
  auto take = [&](const std::vector<MeasuredCoefficientRow>& rows, std::vector<double>& x, std::vector<double>& a,
                  std::vector<double>& b, std::vector<double>& a_cross, std::vector<double>& b_cross) {
    for (const auto& r : rows)
      if (std::fabs(r.Fn - Fn) <= kFnTolerance && r.trim_sinkage == trim_sinkage) {
        x.push_back(r.omega_nondim);
        a.push_back(r.a_diag);
        b.push_back(r.b_diag);
        a_cross.push_back(kCouplingSign * r.a_cross);
        b_cross.push_back(kCouplingSign * r.b_cross);
      }
  };
  take(heave, m.heave_x, m.A33, m.B33, m.A53, m.B53);
  take(pitch, m.pitch_x, m.A55, m.B55, m.A35, m.B35);
  if (trim_sinkage == "zero")  // the restrained tests were run at zero trim and sinkage only
    for (const auto& r : loads)
      if (std::fabs(r.Fn - Fn) <= kFnTolerance) {
        const double k = 2.0 * M_PI / (r.lambda_over_L * L), w = std::sqrt(g * k);
        m.load_x.push_back((w + w * w * U / g) * std::sqrt(L / g));
        m.F3_amp.push_back(r.F3_N / r.wave_amp_m);
        m.F5_amp.push_back(r.F5_N_m / r.wave_amp_m);
        m.F3_phase_deg.push_back(WrapDeg(r.F3_phase_deg + kF3PhaseShiftDeg));
        m.F5_phase_deg.push_back(WrapDeg(r.F5_phase_deg + kF5PhaseShiftDeg));
      }
  return m;
}

}  // namespace hullopt::io
