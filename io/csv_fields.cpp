#include "io/csv_fields.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "io/input_error.h"

namespace hullopt::io {

std::vector<std::string> SplitCsvTrimmed(const std::string& line) {
  std::vector<std::string> out;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) {
    const size_t a = cell.find_first_not_of(" \t\r"), b = cell.find_last_not_of(" \t\r");
    out.push_back(a == std::string::npos ? "" : cell.substr(a, b - a + 1));
  }
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

double ParseCsvNumber(const std::string& field, const std::string& where, const std::string& column) {
  const size_t a = field.find_first_not_of(" \t\r");
  const std::string t = a == std::string::npos ? "" : field.substr(a, field.find_last_not_of(" \t\r") - a + 1);
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
