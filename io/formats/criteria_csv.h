#pragma once
// Seakeeping criteria files (docs/file-formats.md, 'Seakeeping criteria'): '#' comment lines, then the header
// row criterion,quantity,location,limit,unit,source and one criterion per row. The unit must be the
// quantity's (g, %, -), so a limit cannot be read in the wrong unit. The default set,
// data/criteria/nordforsk1987.csv, is built into the binary.
#include <string>

#include "evaluation/seakeeping_criteria.h"

namespace hullopt::io {

/// Parses the text of a criteria file; file names it in errors ("file:line: ..."). Throws InputError for a
/// missing or wrong header, an unknown quantity, a unit that is not the quantity's, a limit that is not a
/// number, a duplicate name or a criterion that is not valid (eval::SeakeepingCriterion::IsValid).
eval::CriteriaSet ParseCriteriaCsv(const std::string& text, const std::string& file, const std::string& title);
/// Reads a criteria file (title: its file name). Throws InputError.
eval::CriteriaSet LoadCriteriaCsv(const std::string& path);
/// The built-in NORDFORSK 1987 set (data/criteria/nordforsk1987.csv as built).
const eval::CriteriaSet& DefaultCriteria();

}  // namespace hullopt::io
