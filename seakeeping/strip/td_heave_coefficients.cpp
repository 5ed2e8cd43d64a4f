#include "seakeeping/strip/td_heave_coefficients.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>

namespace hullopt::sk {
namespace {

using cd = std::complex<double>;

// E1(z) for |z| >= 1, Re z >= 0: continued fraction e^{−z}/(z + 1 − 1²/(z + 3 − 2²/(z + 5 − …))), modified
// Lentz.
cd ExponentialIntegralE1(cd z) {
  const double tiny = 1e-300;
  cd b = z + 1.0, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < 100000; ++i) {
    const double an = -static_cast<double>(i) * i;
    b += 2.0;
    d = 1.0 / (an * d + b);
    c = b + an / c;
    const cd del = c * d;
    h *= del;
    if (std::abs(del - 1.0) < 1e-15) break;
  }
  return h * std::exp(-z);
}

Eigen::VectorXd HeaveNormalVelocity(const std::vector<Panel>& panels) {
  Eigen::VectorXd v(panels.size());
  for (std::size_t j = 0; j < panels.size(); ++j) v(j) = panels[j].Normal()[1];
  return v;
}

}  // namespace

bool TimeDomainSectionOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = m;
    return false;
  };
  if (steps_per_period < 8)
    return fail("steps_per_period must be >= 8, got " + std::to_string(steps_per_period));
  if (!(memory_decay >= 5.0 && memory_decay <= 60.0))
    return fail("memory_decay must be in [5, 60], got " + std::to_string(memory_decay));
  if (max_lags < 10) return fail("max_lags must be >= 10, got " + std::to_string(max_lags));
  return operators.IsValid(error);
}

namespace {
struct SteadySums {
  Eigen::MatrixXcd K;
  Eigen::RowVectorXcd mom;
};
SteadySums Sums(const StripOperators& ops, double omega, int lags) {
  if (!ops.TimeInvariant())
    throw std::invalid_argument("steady heave response needs time-invariant operators");
  if (lags < 1 || lags >= ops.Steps())
    throw std::invalid_argument("steady heave response: lags out of range");
  const auto& panels = ops.PanelsAt(1);
  const double dt = ops.Dt();
  const int P = static_cast<int>(panels.size());
  SteadySums s{ops.System(1).cast<cd>(), ops.MomentumCurrent(1).cast<cd>()};
  const cd zstep = std::exp(cd(0.0, -omega * dt));
  cd z = 1.0;
  for (int l = 1; l <= lags; ++l) {
    z *= zstep;
    s.K -= z * ops.LagMemory(l).cast<cd>();
    s.mom += z * ops.LagMomentum(l).cast<cd>();
  }
  // Tail l > lags: G~ → 4/t (docs/theory.md, 'Transient Green function: limits'), so the interval integral of
  // the potential is 4 ln((l+½)/(l−½)) times the panel length, the same at every field point; Σ_{l>L} z^l
  // ln((l+½)/(l−½)) ≈ E1(iω dt (L + ½)).
  double W = 0;  // Σ L_i n_z,i over the field panels
  for (const Panel& p : panels) W += p.y2 - p.y1;
  const cd tail = ExponentialIntegralE1(cd(0.0, omega * dt * (lags + 0.5)));
  for (int j = 0; j < P; ++j) s.mom(j) += -(ops.Rho() / (2 * M_PI)) * W * panels[j].Length() * 4.0 * tail;
  return s;
}
}  // namespace

Eigen::VectorXcd SteadyHeaveSources(const StripOperators& ops, double omega, int lags) {
  const SteadySums s = Sums(ops, omega, lags);
  return s.K.partialPivLu().solve(HeaveNormalVelocity(ops.PanelsAt(1)).cast<cd>());
}

cd SteadyHeaveMomentum(const StripOperators& ops, double omega, int lags) {
  const SteadySums s = Sums(ops, omega, lags);
  return s.mom * s.K.partialPivLu().solve(HeaveNormalVelocity(ops.PanelsAt(1)).cast<cd>());
}

std::array<double, 2> FarFieldWaveAmplitudes(const std::vector<Panel>& panels, const Eigen::VectorXcd& sigma,
                                             double omega, double g) {
  const double K = omega * omega / g;
  cd q[2] = {0.0, 0.0};
  for (std::size_t j = 0; j < panels.size(); ++j) {
    const Panel& p = panels[j];
    const double L = p.Length(), ca = (p.y2 - p.y1) / L, sa = (p.z2 - p.z1) / L;
    for (int side = 0; side < 2; ++side) {
      const double sgn = side == 0 ? 1.0 : -1.0;  // e^{Kζ + i sgn K η}
      const cd c = K * cd(p.z1, sgn * p.y1), d = K * cd(sa, sgn * ca);
      q[side] += sigma(j) * std::exp(c) * (std::exp(d * L) - 1.0) / d;
    }
  }
  return {omega / g * std::abs(q[0]), omega / g * std::abs(q[1])};
}

HeaveCoefficients TimeDomainHeaveCoefficients(const std::vector<Panel>& panels,
                                              const std::vector<double>& omega, double rho, double g,
                                              const TimeDomainSectionOptions& options) {
  std::string err;
  if (!options.IsValid(&err)) throw std::invalid_argument(err);
  if (omega.empty()) throw std::invalid_argument("heave coefficients: no frequencies given");
  for (double w : omega)
    if (!(w > 0.0) || !std::isfinite(w))
      throw std::invalid_argument("heave coefficients: frequencies must be > 0, got " + std::to_string(w));
  if (panels.empty()) throw std::invalid_argument("heave coefficients: no panels");
  const double w_max = *std::max_element(omega.begin(), omega.end());
  const double dt = 2 * M_PI / (w_max * options.steps_per_period);
  // Horizon: the slowest memory is between a collocation point just below the surface (depth z_min) and a
  // waterline end point a distance r' away; it decays like exp(−g t² z_min / (4 r'²)) (docs/theory.md,
  // 'Transient Green function: limits').
  double z_min = 1e300, r_max = 0;
  for (const Panel& a : panels) {
    z_min = std::min(z_min, -a.MidZ());
    for (const Panel& b : panels)
      for (auto [y, z] : {std::pair{b.y1, b.z1}, {b.y2, b.z2}})
        r_max = std::max(r_max, std::hypot(a.MidY() - y, a.MidZ() + z));
  }
  double horizon = std::sqrt(4.0 * options.memory_decay * r_max * r_max / (g * z_min));
  // ... and at least β = t sqrt(g/r') = 40 for every pair, so the 4/t tail summed by E1 is accurate to ~1e−3
  // of it.
  horizon = std::max(horizon, 40.0 * std::sqrt(r_max / g));
  const int lags = std::min(options.max_lags, static_cast<int>(std::ceil(horizon / dt)));
  const StripOperators ops =
      BuildFixedSectionOperators(panels, lags + 1, dt, rho, g, options.operators, /*steady_state_only=*/true);
  HeaveCoefficients out;
  out.dt_s = dt;
  out.lags = lags;
  const Eigen::VectorXd nz = HeaveNormalVelocity(panels);
  out.a33_infinite_kg_per_m = -ops.MomentumCurrent(0).dot(ops.Solve(0, nz).col(0));
  for (double w : omega) {
    const cd I = SteadyHeaveMomentum(ops, w, lags);
    out.omega_rad_s.push_back(w);
    out.a33_kg_per_m.push_back(-I.real());
    out.b33_kg_per_m_s.push_back(w * I.imag());
    const auto A = FarFieldWaveAmplitudes(panels, SteadyHeaveSources(ops, w, lags), w, g);
    out.b33_energy_kg_per_m_s.push_back(rho * g * g * (A[0] * A[0] + A[1] * A[1]) / (2 * w));
  }
  return out;
}

}  // namespace hullopt::sk
