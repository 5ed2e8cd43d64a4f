#pragma once
// Exponential integral E1 of complex argument, for the wave part of the deep-water pulsating-source Green
// function (frequency_domain_green.h). Branch cut along the negative real axis; on the cut the side is chosen
// by the sign of the imaginary part's zero, as std::log does (Im z = +0 gives the limit from above, E1(−x +
// i0) = −Ei(x) − iπ).
#include <complex>

namespace hullopt::sk {

/// e^z E1(z) for complex z ≠ 0 (the product stays O(1/|z|) where E1 itself under- or overflows).
/// Power series for |z| <= 5 (and near the negative real axis up to |z| = 40), the Laguerre continued
/// fraction elsewhere, and the asymptotic series near the negative real axis beyond |z| = 40 (the region
/// split of Zhang & Jin's E1Z, Computation of Special Functions, 1996, §19.3). Relative accuracy about 1e-14.
std::complex<double> ScaledExpIntE1(std::complex<double> z);

/// E1(z) = e^{−z} · ScaledExpIntE1(z).
std::complex<double> ExpIntE1(std::complex<double> z);

/// e^z E1(z) + ln z: the part of e^z E1(z) left after removing its logarithmic singularity at z = 0;
/// continuous at 0 with the value −γ (Euler's constant). Used so that the log singularity can be integrated
/// in closed form.
std::complex<double> ScaledExpIntE1PlusLog(std::complex<double> z);

/// Both of the above at one z (z ≠ 0 for a finite `scaled`), sharing the exponential, the logarithm and the
/// series: the values are those of the two functions.
struct ScaledExpIntE1Pair {
  std::complex<double> scaled;    ///< e^z E1(z)
  std::complex<double> plus_log;  ///< e^z E1(z) + ln z
};
ScaledExpIntE1Pair ScaledExpIntE1AndPlusLog(std::complex<double> z);
/// The same with e^z supplied by the caller (exp_z = std::exp(z)), who needs it anyway.
ScaledExpIntE1Pair ScaledExpIntE1AndPlusLog(std::complex<double> z, std::complex<double> exp_z);

}  // namespace hullopt::sk
