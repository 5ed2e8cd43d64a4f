#include "io/formats/offsets_csv.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <vector>

#include "io/formats/atomic_file.h"
#include "io/formats/csv_fields.h"
#include "io/formats/input_error.h"
#include "io/formats/input_limits.h"

namespace hullopt::io {
namespace {

std::vector<std::string> SplitCsv(const std::string& line) {
  std::vector<std::string> out;
  std::string field;
  std::stringstream ss(line);
  while (std::getline(ss, field, ',')) out.push_back(field);
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

std::string Trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  const auto b = s.find_last_not_of(" \t\r");
  return s.substr(a, b - a + 1);
}

// A finite number that can be a hull coordinate (a keel at -1e300 m is refused, not integrated).
double ParseCoordinate(const std::string& field, const std::string& where, const char* column) {
  const double v = ParseCsvNumber(field, where, column);
  if (std::fabs(v) > kMaxCoordinate_m)
    throw InputError(where + ": " + column + " = '" + Trim(field) + "' is not a hull coordinate (|value| <= " +
                     std::to_string(int(kMaxCoordinate_m)) + " m)");
  return v;
}

}  // namespace

hull::Demihull ReadOffsetsCsv(const std::string& path, double draught_m) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open offsets file (does it exist and is it readable?)");
  std::string line;
  if (!std::getline(in, line))
    throw InputError(path + ":1: offsets file is empty (expected header x_m,y_m,z_m)");
  const auto header = SplitCsv(line);
  if (header.size() < 3 || Trim(header[0]) != "x_m" || Trim(header[1]) != "y_m" || Trim(header[2]) != "z_m")
    throw InputError(path + ":1: header must start with x_m,y_m,z_m (got '" + Trim(line) + "')");

  hull::Demihull body;
  body.role = "demihull";
  std::vector<int> first_line;  // file line of each station's first point
  int lineno = 1;
  while (std::getline(in, line)) {
    ++lineno;
    if (Trim(line).empty()) continue;
    const std::string where = path + ":" + std::to_string(lineno);
    const auto f = SplitCsv(line);
    if (f.size() < 3)
      throw InputError(where + ": malformed row '" + Trim(line) +
                       "': need at least 3 comma-separated values x_m,y_m,z_m");
    const double x = ParseCoordinate(f[0], where, "x_m"), y = ParseCoordinate(f[1], where, "y_m"),
                 z = ParseCoordinate(f[2], where, "z_m");
    if (y < 0.0) throw InputError(where + ": y_m = " + Trim(f[1]) + " is negative (half-breadths are >= 0)");
    if (body.stations.empty() || x != body.stations.back().x_m) {
      if (!body.stations.empty()) {
        if (x < body.stations.back().x_m)
          throw InputError(where + ": station x_m = " + Trim(f[0]) +
                           " comes after station x_m = " + std::to_string(body.stations.back().x_m) +
                           " (stations must be ordered from aft to forward, each one's points consecutive)");
        if (body.stations.back().y_m.size() < 2)
          throw InputError(path + ":" + std::to_string(first_line.back()) +
                           ": station x_m = " + std::to_string(body.stations.back().x_m) +
                           " has only one point (need keel to deck edge)");
      }
      if (y != 0.0)
        throw InputError(where + ": first point of station x_m = " + Trim(f[0]) + " has y_m = " + Trim(f[1]) +
                         " (each station starts at the keel on the centreline, y_m = 0)");
      body.stations.push_back(hull::Station{x, {}, {}});
      first_line.push_back(lineno);
    } else if (z < body.stations.back().z_m.back()) {
      throw InputError(where + ": z_m = " + Trim(f[2]) + " is below the previous point of station x_m = " +
                       Trim(f[0]) + " (points go from the keel up; z must not decrease)");
    }
    body.stations.back().y_m.push_back(y);
    body.stations.back().z_m.push_back(z);
  }
  if (body.stations.empty()) throw InputError(path + ":2: offsets file has a header but no points");
  if (body.stations.back().y_m.size() < 2)
    throw InputError(path + ":" + std::to_string(first_line.back()) +
                     ": station x_m = " + std::to_string(body.stations.back().x_m) +
                     " has only one point (need keel to deck edge)");
  int wet = 0;
  for (size_t i = 0; i < body.stations.size(); ++i) {
    const auto& s = body.stations[i];
    if (s.z_m.front() > draught_m) continue;  // dry station (e.g. above a rising keel): fine
    ++wet;
    if (s.z_m.back() < draught_m) {
      std::ostringstream m;
      m << path << ":" << first_line[i] << ": station x_m = " << s.x_m
        << " has no waterline crossing at draught_m = " << draught_m
        << " (its highest point z_m = " << s.z_m.back()
        << " is below the waterline; offsets must reach the deck edge)";
      throw InputError(m.str());
    }
  }
  if (wet == 0) {
    std::ostringstream m;
    m << path << ": no station reaches below the waterline at draught_m = " << draught_m
      << " (is draught_m in metres above the baseline?)";
    throw InputError(m.str());
  }
  return body;
}

void WriteOffsetsCsv(const std::string& path, const hull::HullForm& hull) {
  std::ostringstream out;
  out << "x_m,y_m,z_m,body,y_centre_m\n" << std::setprecision(9);
  for (size_t b = 0; b < hull.bodies.size(); ++b) {
    const auto& body = hull.bodies[b];
    for (const auto& s : body.stations)
      for (size_t k = 0; k < s.y_m.size(); ++k)
        out << s.x_m << ',' << s.y_m[k] << ',' << s.z_m[k] << ',' << (body.role.empty() ? "body" : body.role)
            << ',' << body.y_centre_m << '\n';
  }
  WriteFileAtomically(path, out.str());
}

}  // namespace hullopt::io
