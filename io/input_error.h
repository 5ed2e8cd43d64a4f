#pragma once
#include <stdexcept>
#include <string>

namespace hullopt::io {

/// Bad user input (config, data file, command line). The message is one line that names the file, line or key
/// and the rule that was broken; the app prints it and exits non-zero.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace hullopt::io
