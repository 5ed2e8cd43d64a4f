#pragma once
// Splitting and reading the fields of one line of a comma-separated data file, shared by every CSV reader
// (offsets, RAO tables, tank RAOs, measured coefficients, scatter diagrams).
#include <string>
#include <vector>

namespace hullopt::io {

/// s without leading and trailing blanks (space, tab, carriage return).
std::string TrimField(const std::string& s);

/// The trimmed comma-separated fields of line; a field in double quotes may hold commas ("" is a quote); a
/// trailing comma gives a last empty field.
std::vector<std::string> SplitCsvLine(const std::string& line);

/// SplitCsvLine, with no fields at all for an empty line.
std::vector<std::string> SplitCsvTrimmed(const std::string& line);

/// The field as a finite number; throws InputError "<where>: <column> = '<field>' is not a number" (or "must
/// be a finite number" for inf/nan/overflow).
double ParseCsvNumber(const std::string& field, const std::string& where, const std::string& column);

}  // namespace hullopt::io
