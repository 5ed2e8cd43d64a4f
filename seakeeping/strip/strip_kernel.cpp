#include "seakeeping/strip/strip_kernel.h"

#include <sstream>

namespace hullopt::sk {

std::vector<std::string> StripKernelWarnings(const StripKernel& kernel, double limit) {
  int worst = -1, count = 0;
  for (int n = 0; n < static_cast<int>(kernel.system_condition.size()); ++n) {
    if (!(kernel.system_condition[n] <= limit)) {
      ++count;
      if (worst < 0 || !(kernel.system_condition[n] <= kernel.system_condition[worst])) worst = n;
    }
  }
  if (worst < 0) return {};
  std::ostringstream os;
  os.precision(4);
  os << count << " of " << kernel.Steps() << " strip sections have a near-singular 2D system (condition "
     << "number estimate above " << limit << "; worst " << kernel.system_condition[worst] << " at x = "
     << (worst < static_cast<int>(kernel.x_m.size()) ? kernel.x_m[worst] : 0.0)
     << " m from the AP): the panels cannot resolve those sections (typically a section thinner than its panels "
        "are long, such as a bulb flattened into a plate), so the heave and pitch damping may be wrong; check "
        "those sections and that the RAOs do not change with panels and sections";
  return {os.str()};
}

}  // namespace hullopt::sk
