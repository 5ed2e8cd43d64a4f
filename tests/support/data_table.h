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

namespace hullopt::test {

/// A data/ table with its header: the column names and the rows as numbers.
struct NamedDataTable {
  std::vector<std::string> names;
  std::vector<std::vector<double>> rows;
  /// Index of the column `name`, or -1.
  int Column(const std::string& name) const {
    const auto it = std::find(names.begin(), names.end(), name);
    return it == names.end() ? -1 : static_cast<int>(it - names.begin());
  }
};

/// data/<relative_path> as ReadDataTable, with the names of the header row. Empty if the file cannot be opened.
inline NamedDataTable ReadNamedDataTable(const std::string& relative_path) {
  NamedDataTable out;
  out.rows = ReadDataTable(relative_path);
  std::ifstream in(std::string(HULLOPT_SOURCE_DIR) + "/data/" + relative_path);
  std::string line;
  while (in && std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream header(line);
    for (std::string name; std::getline(header, name, ',');) out.names.push_back(name);
    break;
  }
  return out;
}

}  // namespace hullopt::test
