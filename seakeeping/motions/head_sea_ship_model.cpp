#include "seakeeping/motions/head_sea_ship_model.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "seakeeping/motions/head_sea_wave.h"

namespace hullopt::sk {

bool MotionOptions::IsValid(std::string* error) const {
  if (!std::isfinite(damping_cs) || damping_cs < 0.0) {
    std::ostringstream os;
    os << "damping coefficient Cs = " << damping_cs << ": must be a finite number >= 0";
    if (error) *error = os.str();
    return false;
  }
  return true;
}

double StationData::FroudeKrylovWidth(double k) const {
  double g = 0.0;
  for (Eigen::Index i = 0; i < dy.size(); ++i) {
    // ∫_0^1 e^{k(z1 + (z2 − z1)s)} ds = e^{k z1} (e^{kΔz} − 1)/(kΔz), written with expm1 so that level panels
    // (Δz → 0) and k → 0 stay exact.
    const double a = k * (z2[i] - z1[i]);
    const double mean = std::fabs(a) < 1e-12 ? 1.0 + 0.5 * a : std::expm1(a) / a;
    g -= dy[i] * std::exp(k * z1[i]) * mean;
  }
  return g;
}

HeadSeaShipModel::HeadSeaShipModel(const StripKernel& kernel, const hull::MassProperties& mass,
                                   const MotionOptions& options)
    : kernel_(&kernel), options_(options) {
  auto fail = [&](const std::string& rule) {
    throw std::invalid_argument(
        "ship motions" +
        (options.hull_name.empty() ? std::string() : " of hull '" + options.hull_name + "'") + ": " + rule);
  };
  std::string err;
  if (!options.IsValid(&err)) fail(err);
  std::ostringstream os;
  if (!(kernel.speed_m_s > 0.0) || !std::isfinite(kernel.speed_m_s)) {
    os << "ship speed U = " << kernel.speed_m_s << " m/s: must be > 0 (the strip method needs forward speed)";
    fail(os.str());
  }
  if (!(kernel.dx_m > 0.0) || !(kernel.dt_s > 0.0) ||
      std::fabs(kernel.dt_s * kernel.speed_m_s - kernel.dx_m) > 1e-9 * kernel.dx_m) {
    os << "strip kernel step: dx = " << kernel.dx_m << " m, dt = " << kernel.dt_s
       << " s, U = " << kernel.speed_m_s << " m/s: need dx > 0 and dt = dx/U";
    fail(os.str());
  }
  if (!(kernel.rho_kg_m3 > 0.0) || !(kernel.g_m_s2 > 0.0)) fail("water density and gravity must be > 0");
  const int n_steps = kernel.Steps();
  if (n_steps < 2) fail("the strip kernel needs at least 2 steps (sections along the hull)");
  if (static_cast<int>(kernel.panels.size()) != n_steps || static_cast<int>(kernel.force.size()) != n_steps)
    fail("strip kernel: x_m, panels and force must have one entry per step");
  for (int n = 0; n < n_steps; ++n) {
    if (static_cast<int>(kernel.force[n].size()) != n + 1)
      fail("strip kernel: force[n] must hold n + 1 rows");
    for (int m = 0; m <= n; ++m)
      if (kernel.force[n][m].size() != static_cast<Eigen::Index>(kernel.panels[m].size()))
        fail("strip kernel: force[n][m] must have one entry per panel of step m");
  }
  if (!(mass.mass_kg > 0.0) || !std::isfinite(mass.mass_kg)) {
    os << "mass = " << mass.mass_kg << " kg: must be > 0";
    fail(os.str());
  }
  if (!(mass.kyy_m > 0.0) || !std::isfinite(mass.kyy_m)) {
    os << "pitch radius of gyration k_yy = " << mass.kyy_m << " m: must be > 0";
    fail(os.str());
  }
  if (!std::isfinite(mass.lcg_m_from_ap)) fail("LCG must be finite");
  mass_kg_ = mass.mass_kg;
  inertia_kg_m2_ = mass.mass_kg * mass.kyy_m * mass.kyy_m;

  stations_.resize(n_steps);
  for (int n = 0; n < n_steps; ++n) {
    const auto& ps = kernel.panels[n];
    StationData& s = stations_[n];
    const auto np = static_cast<Eigen::Index>(ps.size());
    s.x_cg_m = kernel.x_m[n] - mass.lcg_m_from_ap;
    s.weight_m = kernel.Weight(n);
    s.nz.resize(np);
    s.z_mid.resize(np);
    s.dy.resize(np);
    s.z1.resize(np);
    s.z2.resize(np);
    for (Eigen::Index i = 0; i < np; ++i) {
      const Panel& p = ps[i];
      s.nz[i] = p.Normal()[1];
      s.z_mid[i] = p.MidZ();
      s.dy[i] = p.y2 - p.y1;
      s.z1[i] = p.z1;
      s.z2[i] = p.z2;
    }
    s.beam_m = -s.dy.sum();
    if (s.beam_m < -1e-12) fail("panels of step " + std::to_string(n) + " are ordered starboard to port");
  }
}

void HeadSeaShipModel::ReportNonFinite(const std::string& what, double omega) const {
  std::ostringstream os;
  os << "hull '" << (options_.hull_name.empty() ? std::string("(unnamed)") : options_.hull_name)
     << "': non-finite " << what << " at omega = " << omega
     << " rad/s (omega_e = " << HeadSeaEncounterFrequency(omega, speed(), g()) << " rad/s)";
  throw std::domain_error(os.str());
}

}  // namespace hullopt::sk
