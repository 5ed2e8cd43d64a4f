#pragma once
// Numeric tables of the project's data/ folders for the validation tests: `#` comment lines, one header row,
// then comma-separated numbers. Returns the rows as numbers, or an empty list if the file cannot be opened.
#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace hullopt::test {

/// Rows of data/<relative_path> (relative to the source tree), each as its numbers in column order.
inline std::vector<std::vector<double>> ReadDataTable(const std::string& relative_path) {
  std::ifstream in(std::string(HULLOPT_SOURCE_DIR) + "/data/" + relative_path);
  std::vector<std::vector<double>> out;
  std::string line;
  bool header = true;
  while (in && std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (header) { header = false; continue; }
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream row(line);
    std::vector<double> v;
    for (double x; row >> x;) v.push_back(x);
    out.push_back(v);
  }
  return out;
}

}  // namespace hullopt::test
