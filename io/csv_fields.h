#pragma once
// Fields of one line of a comma-separated data file, for the readers of measured data.
#include <string>
#include <vector>

namespace hullopt::io {

/// s without leading and trailing blanks (space, tab, carriage return).
std::string TrimField(const std::string& s);

/// The trimmed comma-separated fields of line; a field in double quotes may hold commas ("" is a quote).
std::vector<std::string> SplitCsvLine(const std::string& line);

}  // namespace hullopt::io
