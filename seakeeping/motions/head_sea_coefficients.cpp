#include "seakeeping/motions/head_sea_coefficients.h"

namespace hullopt::sk {

std::array<std::complex<double>, 2> HeadSeaCoefficients::Solve() const {
  using cd = std::complex<double>;
  const double w2 = motion_omega_rad_s * motion_omega_rad_s;
  // a_ij = −ω² M_ij − (moving_ij − C_ij); Cramer's rule so that a NaN anywhere reaches X.
  const cd a11 = -w2 * mass_kg - moving[0][0] + restoring[0][0];
  const cd a12 = -moving[0][1] + restoring[0][1];
  const cd a21 = -moving[1][0] + restoring[1][0];
  const cd a22 = -w2 * inertia_kg_m2 - moving[1][1] + restoring[1][1];
  const cd f3 = Exciting(0), f5 = Exciting(1);
  const cd det = a11 * a22 - a12 * a21;
  return {(a22 * f3 - a12 * f5) / det, (a11 * f5 - a21 * f3) / det / k_rad_m};
}

}  // namespace hullopt::sk
