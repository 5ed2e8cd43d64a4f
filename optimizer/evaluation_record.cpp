#include "optimizer/evaluation_record.h"

#include <cstring>
#include <sstream>

namespace hullopt::opt {

const EvaluationRecord* LookupReplay(const ReplayLookup& lookup, int run, int step,
                                     const std::vector<double>& x) {
  if (!lookup) return nullptr;
  const EvaluationRecord* rec = lookup(run, step);
  if (rec == nullptr) return nullptr;
  bool same = rec->x.size() == x.size();
  for (std::size_t i = 0; same && i < x.size(); ++i)
    same = std::memcmp(&rec->x[i], &x[i], sizeof(double)) == 0;
  if (!same) {
    std::ostringstream s;
    s.precision(17);
    s << "logged evaluation (run " << run << ", step " << step << ") was made at x = (";
    for (std::size_t i = 0; i < rec->x.size(); ++i) s << (i ? ", " : "") << rec->x[i];
    s << ") but the campaign now asks for x = (";
    for (std::size_t i = 0; i < x.size(); ++i) s << (i ? ", " : "") << x[i];
    s << ")";
    throw ReplayMismatch(s.str());
  }
  return rec;
}

}  // namespace hullopt::opt
