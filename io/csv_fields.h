#pragma once
// Splitting and reading the fields of one CSV line, shared by the CSV readers.
#include <string>
#include <vector>

namespace hullopt::io {

/// The comma-separated fields of `line`, each trimmed of blanks, tabs and CR; a trailing comma gives a last
/// empty field.
std::vector<std::string> SplitCsvTrimmed(const std::string& line);

/// The field as a finite number; throws InputError "<where>: <column> = '<field>' is not a number" (or "must
/// be a finite number" for inf/nan/overflow).
double ParseCsvNumber(const std::string& field, const std::string& where, const std::string& column);

}  // namespace hullopt::io
