#pragma once
// Checks on a RaoTable and complex interpolation of its RAOs at an encounter frequency.
#include <complex>
#include <string>

#include "seakeeping/motions/rao_table.h"

namespace hullopt::sk {

/// At least 2 frequencies; all vectors the same length; ω and ω_e finite, > 0, strictly increasing;
/// ω_e = ω + ω²U/g within 1e-4 relative (CSV round-off); RAOs finite; U ≥ 0, g > 0. The error names the index
/// and value.
bool IsValidRaoTable(const RaoTable& table, std::string* error);

struct ComplexRao {
  std::complex<double> heave;  ///< X3/A [m/m]
  std::complex<double> pitch;  ///< X5/(kA) [-]
};

/// RAOs at encounter frequency omega_e [rad/s] by linear interpolation of the real and imaginary parts on ω_e
/// (complex form: it keeps the phase, which |x3 − x·x5| needs). Throws std::out_of_range outside the table.
ComplexRao InterpolateRao(const RaoTable& table, double omega_e_rad_s);

}  // namespace hullopt::sk
