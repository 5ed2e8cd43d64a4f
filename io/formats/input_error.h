#pragma once
// A malformed input: the one-line message names the file, line, key and rule. The same type as the
// evaluation layer's refusals, so a caller catches both in one place.
#include "evaluation/input_error.h"

namespace hullopt::io {

using InputError = eval::InputError;

}  // namespace hullopt::io
