#include "io/formats/rao_table_csv.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <fstream>
#include <map>
#include <sstream>
#include <vector>

#include "io/formats/csv_fields.h"
#include "io/formats/input_error.h"
#include "seakeeping/motions/rao_interpolation.h"

namespace hullopt::io {

// An RAO above this is a unit or column error, not a motion: squared in the spectral moments it would overflow.
constexpr double kMaxRaoAmplitude = 1000.0;

sk::RaoTable ReadRaoTableCsv(const std::string& path, double g) {
  std::ifstream f(path);
  if (!f) throw InputError(path + ": cannot open RAO file");
  const std::vector<std::string> required = {"omega_e_rad_s",   "omega_rad_s", "heave_amp",
                                             "heave_phase_deg", "pitch_amp",   "pitch_phase_deg"};
  std::map<std::string, size_t> col;
  sk::RaoTable t;
  t.g_m_s2 = g;
  std::string line;
  int line_no = 0, header_line = 0;
  std::vector<double> speeds;
  std::vector<int> row_lines;
  constexpr double kDegToRad = 3.14159265358979323846 / 180.0;
  while (std::getline(f, line)) {
    ++line_no;
    if (line.find_first_not_of(" \t\r") == std::string::npos || line[line.find_first_not_of(" \t")] == '#')
      continue;
    const auto cells = SplitCsvTrimmed(line);
    const std::string where = path + ":" + std::to_string(line_no);
    if (!header_line) {
      header_line = line_no;
      for (size_t i = 0; i < cells.size(); ++i) col[cells[i]] = i;
      for (const auto& name : required)
        if (!col.count(name))
          throw InputError(where + ": header lacks column '" + name +
                           "' (expected omega_e_rad_s,omega_rad_s,lambda_over_L,heave_amp,heave_phase_deg,"
                           "pitch_amp,pitch_phase_deg)");
      continue;
    }
    // A rao.csv over headings (`rao` with solver.headings_deg) gives head seas only in its 180 deg rows; any
    // other heading read as head seas would imply another speed, or none, and a wrong MSI.
    if (col.count("wave_direction_deg")) {
      const size_t c = col["wave_direction_deg"];
      const std::string cell = c < cells.size() ? cells[c] : std::string();
      char* end = nullptr;
      const double beta = std::strtod(cell.c_str(), &end);
      if (cell.empty() || *end != '\0' || beta != 180.0)
        throw InputError(where + ": wave_direction_deg = " + cell +
                         ": a RAO file is read for head seas (180 deg) only; oblique seas are computed from the "
                         "design's config (hull: with operability.polar)");
    }
    std::map<std::string, double> v;
    for (const auto& name : required) {
      const size_t c = col[name];
      if (c >= cells.size()) throw InputError(where + ": missing value in column '" + name + "'");
      char* end = nullptr;
      const double x = std::strtod(cells[c].c_str(), &end);
      if (cells[c].empty() || *end != '\0')
        throw InputError(where + ": column '" + name + "' = '" + cells[c] + "' is not a number");
      if (!std::isfinite(x)) throw InputError(where + ": column '" + name + "' must be finite");
      v[name] = x;
    }
    const double w = v["omega_rad_s"], we = v["omega_e_rad_s"];
    if (!(w > 0.0)) throw InputError(where + ": omega_rad_s must be > 0");
    if (!t.omega_rad_s.empty() && !(w > t.omega_rad_s.back()))
      throw InputError(where + ": omega_rad_s must increase from row to row");
    if (v["heave_amp"] < 0.0 || v["pitch_amp"] < 0.0)
      throw InputError(where + ": RAO amplitudes must be >= 0 (the sign is in the phase)");
    for (const char* amp : {"heave_amp", "pitch_amp"})
      if (v[amp] > kMaxRaoAmplitude)
        throw InputError(where + ": column '" + amp + "' = " + cells[col[amp]] + " is not a response amplitude " +
                         "(at most " + std::to_string(int(kMaxRaoAmplitude)) + " per unit wave; resonance peaks of " +
                         "real hulls are below 10)");
    t.omega_rad_s.push_back(w);
    t.omega_e_rad_s.push_back(we);
    t.heave.push_back(std::polar(v["heave_amp"], v["heave_phase_deg"] * kDegToRad));
    t.pitch.push_back(std::polar(v["pitch_amp"], v["pitch_phase_deg"] * kDegToRad));
    speeds.push_back((we - w) * g / (w * w));
    row_lines.push_back(line_no);
  }
  if (!header_line) throw InputError(path + ": empty RAO file (no header)");
  if (t.omega_rad_s.size() < 2)
    throw InputError(path + ": needs at least 2 frequency rows, has " + std::to_string(t.omega_rad_s.size()));
  // One speed for the whole table, every row within 1e-3 relative (CSV round-off) or 1 mm/s of the median
  // (so the error names the odd row out, not the first row), then the mean of the rows.
  std::vector<double> sorted = speeds;
  std::sort(sorted.begin(), sorted.end());
  const double median = sorted[(sorted.size() - 1) / 2];
  for (size_t i = 0; i < speeds.size(); ++i) {
    if (std::abs(speeds[i] - median) > std::max(1e-3 * std::abs(median), 1e-3)) {
      std::ostringstream o;
      o << path << ":" << row_lines[i] << ": omega_e_rad_s implies speed " << speeds[i]
        << " m/s (omega_e = omega + omega^2 U/g), most rows " << median << " m/s: one speed per file";
      throw InputError(o.str());
    }
  }
  double u = 0.0;
  for (double s : speeds) u += s / speeds.size();
  if (std::abs(u) < 1e-3) u = 0.0;
  if (u < 0.0) throw InputError(path + ": omega_e < omega implies a negative speed; head seas need U >= 0");
  t.speed_m_s = u;
  // Recompute ω_e from ω and the one speed so round-off in the file cannot break the table's consistency.
  for (size_t i = 0; i < t.omega_rad_s.size(); ++i)
    t.omega_e_rad_s[i] = t.omega_rad_s[i] + t.omega_rad_s[i] * t.omega_rad_s[i] * u / g;
  std::string error;
  if (!sk::IsValidRaoTable(t, &error)) throw InputError(path + ": " + error);
  return t;
}

}  // namespace hullopt::io
