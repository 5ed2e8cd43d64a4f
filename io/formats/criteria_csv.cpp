#include "io/formats/criteria_csv.h"

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "hullopt/default_criteria.h"
#include "io/formats/csv_fields.h"
#include "io/formats/input_error.h"

namespace hullopt::io {

eval::CriteriaSet ParseCriteriaCsv(const std::string& text, const std::string& file, const std::string& title) {
  eval::CriteriaSet set;
  set.title = title;
  set.file = file;
  std::istringstream in(text);
  std::string line;
  int n = 0;
  bool header = false;
  std::set<std::string> names;
  const std::vector<std::string> kHeader = {"criterion", "quantity", "location", "limit", "unit", "source"};
  while (std::getline(in, line)) {
    ++n;
    const std::string where = file + ":" + std::to_string(n);
    const std::string trimmed = TrimField(line);
    if (trimmed.empty() || trimmed[0] == '#') continue;
    const std::vector<std::string> f = SplitCsvLine(line);
    if (!header) {
      if (f != kHeader)
        throw InputError(where + ": the header row must be criterion,quantity,location,limit,unit,source");
      header = true;
      continue;
    }
    if (f.size() != kHeader.size())
      throw InputError(where + ": " + std::to_string(f.size()) + " fields, expected 6 (" +
                       "criterion,quantity,location,limit,unit,source)");
    eval::SeakeepingCriterion c;
    c.name = f[0];
    if (!eval::ParseCriterionQuantity(f[1], &c.quantity))
      throw InputError(where + ": quantity '" + f[1] +
                       "' is not one of rms_vertical_acceleration, msi, slamming_probability, "
                       "deck_wetness_probability");
    c.location = f[2];
    c.limit = ParseCsvNumber(f[3], where, "limit");
    const std::string unit = eval::CriterionQuantityUnit(c.quantity);
    if (f[4] != unit)
      throw InputError(where + ": unit '" + f[4] + "': a " + f[1] + " limit is given in '" + unit + "'");
    c.source = f[5];
    std::string e;
    if (!c.IsValid(&e)) throw InputError(where + ": " + e);
    if (!names.insert(c.name).second) throw InputError(where + ": criterion '" + c.name + "' is given twice");
    set.criteria.push_back(std::move(c));
  }
  if (!header) throw InputError(file + ": no header row criterion,quantity,location,limit,unit,source");
  if (set.criteria.empty()) throw InputError(file + ": no criteria");
  return set;
}

eval::CriteriaSet LoadCriteriaCsv(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot read the criteria file");
  std::ostringstream s;
  s << in.rdbuf();
  return ParseCriteriaCsv(s.str(), path, std::filesystem::path(path).filename().string());
}

const eval::CriteriaSet& DefaultCriteria() {
  static const eval::CriteriaSet set =
      ParseCriteriaCsv(kDefaultCriteriaCsv, kDefaultCriteriaFile, "NORDFORSK 1987, fast small craft");
  return set;
}

}  // namespace hullopt::io
