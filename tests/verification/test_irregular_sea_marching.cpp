// Acceptance: an irregular-sea time series from the time-marching path (2a) gives rms
// vertical accelerations within 5 % of the spectral ones (SeaResponse on the periodic-path RAOs, 2b) at the
// forward, LCG and transom positions. One Delft 372 demihull (model scale, Fn 0.75, 20 sections × 8 panels,
// transient Green-function kernel) in a model-scale JONSWAP sea whose peak encounter frequency lies at the
// heave resonance, marched over 30 simulated minutes (at scale 2, see kScale) after a 30 s start-up.
#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <complex>
#include <iostream>
#include <string>
#include <vector>

#include "io/formats/offsets_csv.h"
#include "parametric_hull/hydrostatics.h"
#include "seakeeping/motions/encounter_frequency.h"
#include "seakeeping/motions/frequency_list.h"
#include "seakeeping/motions/head_sea_ship_model.h"
#include "seas/irregular_sea.h"
#include "seas/passenger_positions.h"
#include "seakeeping/motions/periodic_motion_solver.h"
#include "seas/point_response.h"
#include "seakeeping/motions/rao_solver.h"
#include "seakeeping/strip/strip_force_model.h"
#include "seakeeping/strip/strip_geometry.h"
#include "seakeeping/motions/time_marching_motion.h"
#include "seas/wave_spectrum.h"

namespace sk = hullopt::sk;
namespace hull = hullopt::hull;

namespace {

constexpr double kG = 9.81;    // [m/s²]
constexpr double kRho = 1000;  // [kg/m³] model basin
// SeaState accepts Tz of 2–25 s only (full-scale seas), and the model's resonant sea has Tz ≈ 1.5 s, so the
// model is Froude-scaled up by kScale (lengths × kScale, times × √kScale; accelerations unchanged per unit
// Hs/L). The linear, non-dimensional problem is the model's.
constexpr double kScale = 2.0;
constexpr double kL = 3.0 * kScale;     // [m] Delft 372 model length 3 m
constexpr double kT = 0.15 * kScale;    // [m] draught
constexpr double kLcg = 1.41 * kScale;  // [m] from AP (delft372_particulars.csv); also CG-to-transom distance
constexpr double kKyy = 0.782 * kScale;

hull::HullForm OneDemihull() {
  hull::HullForm h;
  h.type = "offsets";
  h.draught_m = kT;
  h.length_m = kL;
  hull::Demihull body = hullopt::io::ReadOffsetsCsv("data/delft372/delft372_offsets.csv", 0.15);
  body.y_centre_m = 0.0;
  for (auto& st : body.stations) {
    st.x_m *= kScale;
    for (auto& y : st.y_m) y *= kScale;
    for (auto& z : st.z_m) z *= kScale;
  }
  h.bodies.push_back(body);
  return h;
}

// Vertical displacement s = x3 − x·x5 at x forward of the CG, then its second derivative by the fourth-order
// central difference (error (ω Δt)⁴/90 of the amplitude: 0.01 % at the heave resonance, ω_e Δt ≈ 0.27).
std::vector<double> PointAcceleration(const sk::MotionTimeSeries& ts, double x, double dt) {
  const std::size_t n = ts.t_s.size();
  std::vector<double> s(n), a;
  for (std::size_t i = 0; i < n; ++i) s[i] = ts.heave_m[i] - x * ts.pitch_rad[i];
  for (std::size_t i = 2; i + 2 < n; ++i)
    a.push_back((-s[i - 2] + 16 * s[i - 1] - 30 * s[i] + 16 * s[i + 1] - s[i + 2]) / (12 * dt * dt));
  return a;
}

}  // namespace

TEST_CASE("marched irregular sea: rms accelerations match the spectral ones at the three positions",
          "[motions][time-domain][irregular][delft372]") {
  const auto t_start = std::chrono::steady_clock::now();
  const hull::HullForm form = OneDemihull();
  const auto hs = hull::ComputeHydrostatics(form, kRho);
  const hull::MassProperties mass{hs.displacement_kg, kLcg, kKyy, 0.34 * kScale};
  const double U = 0.75 * std::sqrt(kG * kL);

  sk::StripGeometryOptions geo;
  geo.sections = 20;
  geo.panels = 8;
  sk::StripKernel kernel = sk::StripKernelGeometry(form, geo, U, kRho, kG);
  sk::TransientGreenKernelBuilder()(&kernel);
  sk::MotionOptions mo;
  mo.damping_cs = 0.024;
  mo.hull_name = "Delft 372 demihull";
  const sk::HeadSeaShipModel model(kernel, mass, mo);
  const double dt = kernel.dt_s;

  // Heave resonance from a periodic sweep in encounter frequency.
  const auto sweep = sk::SolvePeriodicRaos(
      model, sk::WaveFrequencies(
                 sk::FrequencySpec::Range(sk::FrequencySpec::Quantity::kOmegaE, 1.0, 15.0, 113), U, kG, kL));
  double peak_we = 0, peak = 0;
  for (std::size_t i = 0; i < sweep.heave.size(); ++i)
    if (std::abs(sweep.heave[i]) > peak) peak = std::abs(sweep.heave[i]), peak_we = sweep.omega_e_rad_s[i];

  // Sea: JONSWAP (γ 3.3), Hs 0.05·kScale m (linear: Hs only scales), Tz such that the peak encounter
  // frequency sits at the heave resonance.
  const double peak_w = (-1.0 + std::sqrt(1.0 + 4.0 * U / kG * peak_we)) / (2.0 * U / kG);
  const double tz = sk::ZeroCrossingToPeakPeriodRatio(3.3) * 2.0 * M_PI / peak_w;
  const sk::WaveSpectrum spectrum(sk::SeaState::JonswapTz(0.05 * kScale, tz));
  const double wp = spectrum.omega_peak();

  // One band for both paths: 0.5–3 ωp of wave frequency holds all but ~1 % of the wave variance; the RAO
  // table spans it, so SeaResponse and the components integrate the same energy.
  const double w_lo = 0.5 * wp, w_hi = 3.0 * wp;
  const auto omegas = sk::WaveFrequencies(
      sk::FrequencySpec::Range(sk::FrequencySpec::Quantity::kOmega, w_lo, w_hi, 200), U, kG, kL);
  const auto rao = sk::SolvePeriodicRaos(model, omegas);
  const auto rao_trap = sk::SolvePeriodicRaos(model, omegas, sk::PeriodicKinematics::kTrapezoid);
  const sk::SeaResponse spectral(rao, spectrum), spectral_trap(rao_trap, spectrum);

  sk::IrregularSeaOptions so;
  so.components = 300;
  so.omega_min_rad_s = w_lo;
  so.omega_max_rad_s = w_hi;
  so.seed = 2003;
  std::vector<sk::WaveComponent> sea;  // the marcher's component type: same ζ = a cos(ω_e t + φ) at the CG
  for (const auto& c : sk::IrregularSeaComponents(spectrum, U, kG, so))
    sea.push_back({c.amplitude_m, c.omega_rad_s, c.phase_rad});

  constexpr double kRecord = 1800.0;  // [s] model time analysed: 30 simulated minutes
  constexpr double kRamp = 10.0;      // [s] half-cosine ramp-in of the sea
  constexpr double kDiscard = 30.0;   // [s] ramp plus ~10 heave-decay times discarded
  sk::KernelStripForceModel forces(kernel);
  const auto t_march = std::chrono::steady_clock::now();
  const auto ts = sk::MarchHeadSea(model, forces, sea, kRecord + kDiscard, kRamp, sk::MarchingOptions{});
  const double march_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_march).count();
  const std::size_t skip = static_cast<std::size_t>(kDiscard / dt);

  std::cout << "irregular-sea marching: Delft 372 demihull at scale " << kScale << ", displacement "
            << hs.displacement_kg << " kg, U " << U << " m/s, dt " << dt << " s; heave resonance omega_e "
            << peak_we << " rad/s; JONSWAP Hs " << 0.05 * kScale << " m"
            << " Tz " << tz << " s (omega_p " << wp << " rad/s, peak omega_e "
            << sk::HeadSeaEncounterFrequency(wp, U, kG) << " rad/s); " << sea.size() << " components; "
            << kRecord << " s analysed after " << kDiscard << " s; march " << march_s << " s wall\n";
  // Tolerance: the acceptance criterion's 5 %. Expected scatter: the rms of a record of N response cycles has
  // a relative standard error ≈ 1/√(2N) for a broad-band process, more for the narrow-band resonant response
  // (N_eff smaller): 1800 s at ω_e ≈ 5.5 rad/s is ~1600 cycles, 1.8 % nominal, a few % with the resonance's
  // bandwidth (the realisation is fixed by the seed, so the figure is reproducible). The component sum (300
  // bins, frequency jittered in each bin) adds < 1 %. The marcher's trapezoid kinematics warp the frequency
  // by (ω_e Δt)²/12 ≈ 0.6 % at the resonance (ω_e Δt = 0.27), which moves the rms by ~1 % against the
  // exact-kinematics reference checked here (the trapezoid-kinematics one is printed beside it).
  constexpr double kRmsTolerance = 0.05;
  for (const auto& p : sk::StandardPassengerPositions(kLcg)) {
    const auto a = PointAcceleration(ts, p.x_from_cg_m, dt);
    double sum2 = 0;
    for (std::size_t i = skip; i < a.size(); ++i) sum2 += a[i] * a[i];
    const double rms_td = std::sqrt(sum2 / static_cast<double>(a.size() - skip));
    const double rms_sp = spectral.Moments(p.x_from_cg_m).rms_acceleration_m_s2();
    const double rms_sp_trap = spectral_trap.Moments(p.x_from_cg_m).rms_acceleration_m_s2();
    std::cout << "  " << p.name << " (x " << p.x_from_cg_m << " m): rms a spectral " << rms_sp
              << " m/s^2 (trapezoid kinematics " << rms_sp_trap << "), time-domain " << rms_td
              << " m/s^2, ratio " << rms_td / rms_sp << "\n";
    INFO(p.name << ": time-domain rms " << rms_td << " spectral " << rms_sp);
    CHECK(std::abs(rms_td / rms_sp - 1.0) <= kRmsTolerance);
  }
  std::cout << "  total " << std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count()
            << " s wall\n";
}
