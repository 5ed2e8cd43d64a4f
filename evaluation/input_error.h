#pragma once
// An input the library refuses (a design that cannot be built, a setting out of range): the message names the
// source, the key or quantity and the rule, one line. io/ throws the same type for malformed config files.
#include <stdexcept>
#include <string>

namespace hullopt::eval {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace hullopt::eval
