// The NPL 5b-like catamaran of the 14-hull study through the public API: hull at 1000 t, hydrostatics,
// RAOs at 40 kn (20 sections x 8 panels, Cs 0.065), and MSI in a 3 m, Tz 7.5 s JONSWAP head sea.
#include <hullopt/hullopt.h>
// Each public header also by its own namespaced path (the package installs them all under include/hullopt/).
#include <hullopt/seas/wave_spectrum.h>

#include <cstdio>
#include <exception>

int main() {
  using namespace hullopt;
  try {
    hull::DesignVariables dv;  // the defaults are the NPL 5b-like catamaran of Table 1
    const hull::HullForm h = hull::GenerateHull(dv);
    const hull::Hydrostatics hs = hull::ComputeHydrostatics(h, 1025.0);
    hull::MassProperties mass;
    mass.mass_kg = hs.displacement_kg;
    mass.lcg_m_from_ap = hs.lcb_m_from_ap;
    mass.kyy_m = 0.25 * hs.L_m;
    mass.kg_m = hs.T_m;
    sk::RaoSolverOptions o;
    o.sections = 20;
    o.panels = 8;
    o.motion.damping_cs = 0.065;
    const double U = 40 * 1852.0 / 3600.0;
    const auto omega = sk::WaveFrequencies(
        sk::FrequencySpec::Range(sk::FrequencySpec::Quantity::kOmega, 0.2, 3.0, 30), U, 9.81, hs.L_m);
    const sk::RaoTable rao = sk::ComputeRaos(h, mass, U, 1025.0, 9.81, omega, o, sk::TransientGreenKernelBuilder());
    const sk::HullExtent extent{mass.lcg_m_from_ap - hs.x_ap_m, hs.x_ap_m + hs.L_m - mass.lcg_m_from_ap};
    const auto ev = sk::EvaluateDesign(rao, extent, {sk::SeaState::JonswapTz(3.0, 7.5)});
    std::printf("hullopt %s: L %.2f m, displacement %.1f t, mean MSI %.2f %% in Hs 3 m, Tz 7.5 s\n", kVersion,
                hs.L_m, hs.displacement_t, ev.seas[0].mean.msi_pct);
    return ev.seas[0].mean.msi_pct > 0.0 ? 0 : 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "npl5b_msi: %s\n", e.what());
    return 1;
  }
}
