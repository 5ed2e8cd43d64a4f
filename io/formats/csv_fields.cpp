#include "io/formats/csv_fields.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "io/formats/input_error.h"

namespace hullopt::io {

std::string TrimField(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> SplitCsvLine(const std::string& line) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        out.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        out.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.emplace_back();
    } else {
      out.back() += c;
    }
  }
  for (auto& f : out) f = TrimField(f);
  return out;
}

std::vector<std::string> SplitCsvTrimmed(const std::string& line) {
  if (line.empty()) return {};
  return SplitCsvLine(line);
}

double ParseCsvNumber(const std::string& field, const std::string& where, const std::string& column) {
  const std::string t = TrimField(field);
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(t.c_str(), &end);
  if (t.empty() || end != t.c_str() + t.size())
    throw InputError(where + ": " + column + " = '" + t + "' is not a number");
  if (!std::isfinite(v) || errno == ERANGE)
    throw InputError(where + ": " + column + " = '" + t + "' must be a finite number");
  return v;
}

}  // namespace hullopt::io
