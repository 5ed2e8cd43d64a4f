// solver: and mass: config sections: defaults, frequency forms, and one-line errors naming key and rule.
#include <catch2/catch.hpp>

#include "io/config/motion_config.h"

using hullopt::io::InputError;
using hullopt::io::YamlMap;

namespace {
YamlMap FromText(const std::string& text) {
  return YamlMap(YAML::Load(text), "solver", "test.yaml", YAML::Node(YAML::NodeType::Map));
}
hullopt::hull::Hydrostatics Hs() {
  hullopt::hull::Hydrostatics h;
  h.L_m = 3.0;
  h.T_m = 0.15;
  h.displacement_kg = 87.0;
  h.lcb_m_from_ap = 1.416;
  h.x_ap_m = 0.0;
  return h;
}
}  // namespace

TEST_CASE("solver section with defaults and a lambda/L list", "[config]") {
  auto m = FromText("Cs: 0.024\nfrequencies: { lambda_over_L: [1.0, 1.5, 2.0] }\n");
  const auto c = hullopt::io::ParseSolverConfig(m);
  CHECK(c.rao.method == hullopt::sk::RaoSolverOptions::Method::kTimeDomainStrip);
  CHECK(c.rao.sections == 40);
  CHECK(c.rao.panels == 14);
  CHECK(c.cs() == 0.024);
  CHECK(c.rao.marching.hydrodynamic_fraction == 0.2);
  CHECK(c.rao.path == hullopt::sk::RaoSolverOptions::Path::kPeriodic);
  CHECK(c.frequencies.quantity == hullopt::sk::FrequencySpec::Quantity::kLambdaOverL);
  CHECK(c.frequencies.values.size() == 3);
  CHECK(m.resolved()["sections"].as<int>() == 40);
}

TEST_CASE("solver frequency range", "[config]") {
  auto m = FromText("frequencies: { range: { quantity: omega_e_rad_s, from: 2, to: 12, count: 60 } }\n");
  const auto c = hullopt::io::ParseSolverConfig(m);
  CHECK(c.frequencies.values.size() == 60);
  CHECK(c.frequencies.values.back() == Approx(12.0));
}

TEST_CASE("bad solver and mass input: one clear error each", "[config][errors]") {
  auto bad = [](const std::string& text) {
    auto m = FromText(text);
    hullopt::io::ParseSolverConfig(m);
  };
  CHECK_THROWS_WITH(bad("frequencies: { omega_e_rad_s: [] }\n"), Catch::Contains("omega_e_rad_s"));
  CHECK_THROWS_WITH(bad("frequencies: { omega_rad_s: [1.0, -2.0] }\n"),
                    Catch::Contains("solver.frequencies.omega_rad_s") && Catch::Contains("> 0"));
  CHECK_THROWS_WITH(bad("Cs: -0.1\nfrequencies: { omega_rad_s: [1.0] }\n"), Catch::Contains("solver.Cs"));
  CHECK_THROWS_WITH(bad("hydrodynamic_fraction: 0\nfrequencies: { omega_rad_s: [1.0] }\n"),
                    Catch::Contains("hydrodynamic_fraction"));
  CHECK_THROWS_WITH(bad("panels: 13\nfrequencies: { omega_rad_s: [1.0] }\n"),
                    Catch::Contains("solver.panels"));
  CHECK_THROWS_WITH(bad("frequencies: { omega_rad_s: [1.0], lambda_over_L: [1.0] }\n"),
                    Catch::Contains("exactly one"));
  CHECK_THROWS_WITH(bad("path: sideways\nfrequencies: { omega_rad_s: [1.0] }\n"),
                    Catch::Contains("solver.path"));
  CHECK_THROWS_WITH(bad("frequencies: { omega_rad_s: [1.0] }\nCss: 1\n"), Catch::Contains("Css"));
  CHECK_THROWS_WITH(bad("stations: ends\nfrequencies: { omega_rad_s: [1.0] }\n"), Catch::Contains("solver.stations"));
  CHECK_THROWS_WITH(bad("sections: 2\nfrequencies: { omega_rad_s: [1.0] }\n"),
                    Catch::Contains("stations: cell_faces"));
  CHECK_THROWS_WITH(bad("sectional_force: lift\nfrequencies: { omega_rad_s: [1.0] }\n"),
                    Catch::Contains("solver.sectional_force"));
  CHECK_THROWS_WITH(bad("method: strip_theory_stf\nsectional_force: pressure\nfrequencies: { omega_rad_s: [1.0] }\n"),
                    Catch::Contains("time_domain_strip only"));
  CHECK_THROWS_AS(bad("Cs: 0.1\n"), InputError);  // frequencies are required

  auto mass = [](const std::string& text) {
    auto m = FromText(text);
    return hullopt::io::ParseMassConfig(m, Hs());
  };
  const auto d = mass("{}");
  CHECK(d.mass_kg == 87.0);
  CHECK(d.lcg_m_from_ap == 1.416);
  CHECK(d.kyy_m == Approx(0.75));
  CHECK_THROWS_WITH(mass("mass_kg: 0\n"), Catch::Contains("mass_kg"));
  CHECK_THROWS_WITH(mass("kyy_m: -1\n"), Catch::Contains("kyy_m"));
  CHECK_THROWS_WITH(mass("lcg_m_from_ap: 5\n"), Catch::Contains("lcg_m_from_ap"));
}

TEST_CASE("solver.time_scheme: by name, time-marching path only", "[config]") {
  using hullopt::sk::TimeSchemeKind;
  const std::string f = "frequencies: { omega_rad_s: [1.0] }\n";
  auto parse = [](const std::string& text) {
    auto m = FromText(text);
    return hullopt::io::ParseSolverConfig(m);
  };
  CHECK(parse("path: time_marching\n" + f).rao.marching.scheme == TimeSchemeKind::kWeightedAverageTrapezoid);
  CHECK(parse("path: time_marching\ntime_scheme: paper_single_pass\n" + f).rao.marching.scheme ==
        TimeSchemeKind::kPaperSinglePass);
  // The default may be written with the periodic path (a resolved time-marching config switched back).
  CHECK(parse("time_scheme: weighted_average_trapezoid\n" + f).rao.marching.scheme ==
        TimeSchemeKind::kWeightedAverageTrapezoid);
  // The periodic path's resolved config does not gain the key.
  auto m = FromText(f);
  hullopt::io::ParseSolverConfig(m);
  CHECK_FALSE(m.resolved()["time_scheme"]);
  CHECK_THROWS_WITH(parse("path: time_marching\ntime_scheme: rk4\n" + f),
                    Catch::Contains("solver.time_scheme") && Catch::Contains("weighted_average_trapezoid") &&
                        Catch::Contains("paper_single_pass"));
  CHECK_THROWS_WITH(parse("time_scheme: paper_single_pass\n" + f),
                    Catch::Contains("solver.time_scheme") && Catch::Contains("path: time_marching only"));
}

TEST_CASE("solver.panel_spacing: read only when given, into the strip geometry; bad values name the key",
          "[config]") {
  auto plain = FromText("frequencies: { omega_rad_s: [1.0] }\n");
  const auto d = hullopt::io::ParseSolverConfig(plain);
  CHECK_FALSE(plain.resolved()["panel_spacing"]);  // configs without it resolve as before
  CHECK(d.rao.Geometry().spacing.end_spacing == hullopt::sk::PanelSpacing{}.end_spacing);
  auto given = FromText("panel_spacing: { end_spacing: 0.08 }\nfrequencies: { omega_rad_s: [1.0] }\n");
  const auto c = hullopt::io::ParseSolverConfig(given);
  CHECK(c.rao.Geometry().spacing.end_spacing == 0.08);
  CHECK(c.rao.Geometry().spacing.grading == hullopt::sk::PanelSpacing{}.grading);
  auto bad = [](const std::string& text) {
    auto m = FromText(text + "frequencies: { omega_rad_s: [1.0] }\n");
    hullopt::io::ParseSolverConfig(m);
  };
  CHECK_THROWS_WITH(bad("panel_spacing: { end_spacing: 0 }\n"), Catch::Contains("solver.panel_spacing.end_spacing"));
  CHECK_THROWS_WITH(bad("panel_spacing: { grading: 20 }\n"), Catch::Contains("solver.panel_spacing.grading"));
  CHECK_THROWS_WITH(bad("panel_spacing: { ends: 0.1 }\n"), Catch::Contains("ends"));
}

TEST_CASE("solver.section_formulation: read only when given, strip theory only", "[config]") {
  auto plain = FromText("method: strip_theory_stf\nfrequencies: { omega_rad_s: [1.0] }\n");
  const auto d = hullopt::io::ParseSolverConfig(plain);
  CHECK_FALSE(plain.resolved()["section_formulation"]);  // configs without it resolve as before
  CHECK(d.rao.section_formulation == hullopt::sk::SectionFormulation::kSource);
  auto given = FromText("method: strip_theory_stf\nsection_formulation: direct\nfrequencies: { omega_rad_s: [1.0] }\n");
  CHECK(hullopt::io::ParseSolverConfig(given).rao.section_formulation == hullopt::sk::SectionFormulation::kDirect);
  auto bad = [](const std::string& text) {
    auto m = FromText(text + "frequencies: { omega_rad_s: [1.0] }\n");
    hullopt::io::ParseSolverConfig(m);
  };
  CHECK_THROWS_WITH(bad("section_formulation: direct\n"),
                    Catch::Contains("solver.section_formulation") && Catch::Contains("strip_theory_stf only"));
  CHECK_THROWS_WITH(bad("method: strip_theory_stf\nsection_formulation: dipole\n"),
                    Catch::Contains("solver.section_formulation"));
  hullopt::sk::RaoSolverOptions o;
  o.section_formulation = hullopt::sk::SectionFormulation::kDirect;
  std::string err;
  CHECK_FALSE(o.IsValid(&err));  // the time-domain method is the default
  CHECK_THAT(err, Catch::Contains("strip_theory_stf only"));
  o.method = hullopt::sk::RaoSolverOptions::Method::kStripTheory;
  CHECK(o.IsValid(&err));
}

TEST_CASE("solver.body_potential: read only when given, time-domain momentum form only", "[config]") {
  auto plain = FromText("frequencies: { omega_rad_s: [1.0] }\n");
  const auto d = hullopt::io::ParseSolverConfig(plain);
  CHECK_FALSE(plain.resolved()["body_potential"]);  // configs without it resolve as before
  CHECK(d.body_potential == hullopt::sk::BodyPotential::kSourceSum);
  auto given = FromText("body_potential: green_identity\nfrequencies: { omega_rad_s: [1.0] }\n");
  CHECK(hullopt::io::ParseSolverConfig(given).body_potential == hullopt::sk::BodyPotential::kGreenIdentity);
  auto bad = [](const std::string& text) {
    auto m = FromText(text + "frequencies: { omega_rad_s: [1.0] }\n");
    hullopt::io::ParseSolverConfig(m);
  };
  CHECK_THROWS_WITH(bad("method: strip_theory_stf\nbody_potential: green_identity\n"),
                    Catch::Contains("solver.body_potential") && Catch::Contains("time_domain_strip only"));
  CHECK_THROWS_WITH(bad("sectional_force: pressure\nbody_potential: green_identity\n"),
                    Catch::Contains("solver.body_potential") && Catch::Contains("momentum only"));
  CHECK_THROWS_WITH(bad("body_potential: dipoles\n"), Catch::Contains("solver.body_potential"));
}

TEST_CASE("solver.adaptive_grid: on by default, off and the caps when given, caps checked", "[config]") {
  auto d = FromText("frequencies: { lambda_over_L: [1.0, 1.5, 2.0] }\n");
  const auto c0 = hullopt::io::ParseSolverConfig(d);
  CHECK(c0.grid.enabled);
  CHECK_FALSE(d.resolved()["adaptive_grid"]);  // read only when given: configs without it resolve as before
  auto m = FromText("adaptive_grid: off\nadaptive_grid_max_passes: 3\nadaptive_grid_max_frequencies: 120\n"
                    "frequencies: { lambda_over_L: [1.0, 1.5, 2.0] }\n");
  const auto c = hullopt::io::ParseSolverConfig(m);
  CHECK_FALSE(c.grid.enabled);
  CHECK(c.grid.max_passes == 3);
  CHECK(c.grid.max_frequencies == 120);
  auto on = FromText("adaptive_grid: on\nfrequencies: { lambda_over_L: [1.0] }\n");
  CHECK(hullopt::io::ParseSolverConfig(on).grid.enabled);
  auto passes = FromText("adaptive_grid_max_passes: 0\nfrequencies: { lambda_over_L: [1.0] }\n");
  CHECK_THROWS_WITH(hullopt::io::ParseSolverConfig(passes),
                    Catch::Contains("solver.adaptive_grid_max_passes") && Catch::Contains("[1, 50]"));
  auto count = FromText("adaptive_grid_max_frequencies: 2\nfrequencies: { lambda_over_L: [1.0] }\n");
  CHECK_THROWS_WITH(hullopt::io::ParseSolverConfig(count),
                    Catch::Contains("solver.adaptive_grid_max_frequencies") && Catch::Contains("[3, 1000]"));
  auto word = FromText("adaptive_grid: sometimes\nfrequencies: { lambda_over_L: [1.0] }\n");
  CHECK_THROWS_WITH(hullopt::io::ParseSolverConfig(word), Catch::Contains("solver.adaptive_grid"));
}
