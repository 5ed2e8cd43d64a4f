// Conditioning of every strip step of the Davis & Holloway (2003) study hulls at the paper's resolution
// (40 sections × 14 panels per demihull): the condition estimate of each step's source system (the one
// StripKernelWarnings checks against kIllConditionedStrip) for every hull of configs/davis-holloway-2003/,
// printed per hull. Independent fact used: the semicircle and the box of moderate proportions have condition
// estimates of order 1–10 (test_strip_conditioning.cpp); a hull section of ordinary proportions is no worse.
// The SWATHs are the hard case: their generated bulb flattens towards the bow into a plate less than a
// millimetre thick and 4–5 m wide, which panels on both faces make near-singular (1080 at x = 63 m for SW2
// with the former arc-length spacing); the panelling cuts such a fold at its root (seakeeping/green/panel.h).
// Measured worst (median) at 40 × 14: catamarans 3.3–11.6 (1.3–4.8), SWATHs 17.5–45.7 (1.7–4.1), trihull
// 5.2, monohulls 6.9–7.6 (table in docs/study-14-hulls.md).
#include <catch2/catch.hpp>
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>

#include "io/config/hull_config.h"
#include "io/config/speed_config.h"
#include "io/config/water_config.h"
#include "parametric_hull/hydrostatics.h"
#include "seakeeping/strip/strip_geometry.h"
#include "seakeeping/strip/strip_kernel.h"
#include "seakeeping/strip/strip_kernel_builder.h"

using namespace hullopt;

TEST_CASE("study hulls: strip-step condition estimates at 40 x 14", "[conditioning][study]") {
  std::vector<std::string> configs;
  for (const auto& e : std::filesystem::directory_iterator(HULLOPT_SOURCE_DIR "/configs/davis-holloway-2003"))
    if (e.path().extension() == ".yaml") configs.push_back(e.path().string());
  std::sort(configs.begin(), configs.end());
  REQUIRE(configs.size() == 14);
  std::printf("hull, worst strip-step condition estimate at 40 x 14, at x [m], median\n");
  for (const auto& cfg : configs) {
    const std::string name = std::filesystem::path(cfg).stem().string();
    io::YamlMap root = io::YamlMap::LoadFile(cfg);
    const io::WaterOptions water = io::ParseWater(root);
    const io::HullOptions opts = io::ParseHullConfig(root, water);
    const io::SpeedOptions speed = io::ParseSpeed(root, true);
    hull::HullForm h;
    try {
      h = io::LoadHull(opts, cfg);
    } catch (const io::InputError&) {
      std::printf("%s, refused by the generator (impossible waterplane)\n", name.c_str());
      continue;
    }
    const auto hs = hull::ComputeHydrostatics(h, water.rho_kg_m3);
    sk::StripGeometryOptions g;  // 40 × 14, all bodies
    const auto k = sk::StripKernelGeometry(h, g, speed.MetresPerSecond(hs.L_m, water.g_m_s2), water.rho_kg_m3,
                                           water.g_m_s2);
    sk::StripOperatorOptions o;  // as the RAO path builds it (seakeeping/motions/rao_solver.cpp)
    o.layout = k.layout;
    const auto built = sk::BuildStripKernelMirrorReduced(k.panels, k.x_m, k.dt_s, k.rho_kg_m3, k.g_m_s2, o);
    std::vector<double> c;
    double worst = 0, at = 0;
    for (std::size_t n = 0; n < built.system_condition.size(); ++n) {
      if (k.panels[n].empty()) continue;
      c.push_back(built.system_condition[n]);
      if (c.back() > worst) worst = c.back(), at = k.x_m[n];
    }
    std::nth_element(c.begin(), c.begin() + c.size() / 2, c.end());
    std::printf("%s, %.3g, %.2f, %.3g\n", name.c_str(), worst, at, c[c.size() / 2]);
    INFO(name << ": worst " << worst << " at x = " << at << " m");
    CHECK(worst < sk::kIllConditionedStrip);
  }
}
