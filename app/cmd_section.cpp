// `hullopt section CONFIG --out DIR`: heave added mass and damping per unit length of a 2D section (or of
// several identical sections side by side in one strip) from the chosen 2D solvers, written to section.csv
// (docs/file-formats.md) and plotted nondimensionally in section.svg.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "app/commands.h"
#include "app/output_options.h"
#include "app/output_dir.h"
#include "app/run_checks.h"
#include "io/formats/atomic_file.h"
#include "io/formats/input_error.h"
#include "io/config/section_config.h"
#include "io/report/svg_plot.h"
#include "io/config/yaml_map.h"
#include "seakeeping/sections/frequency_domain_section.h"
#include "seakeeping/sections/section_strip.h"
#include "seakeeping/strip/td_heave_coefficients.h"

namespace hullopt::app {
namespace {

using Strip = std::vector<std::vector<sk::Panel>>;

/// Heave coefficients of the whole strip from one method, one value per configured frequency.
struct MethodCurve {
  std::string method;
  std::vector<double> omega, a33, b33;  ///< [rad/s], [kg/m], [kg/(m·s)]
};

// The frequency-domain solver, source formulation ("frequency_domain") or direct ("frequency_domain_direct").
MethodCurve RunFrequencyDomain(const Strip& strip, const io::SectionRunConfig& cfg, const std::string& method) {
  sk::FrequencyDomainOptions opt;
  opt.rho_kg_m3 = cfg.rho_kg_m3;
  opt.g_m_s2 = cfg.g_m_s2;
  if (method == "frequency_domain_direct") opt.formulation = sk::SectionFormulation::kDirect;
  MethodCurve c{method, cfg.omegas_rad_s, {}, {}};
  for (const auto& h : sk::SolveSectionFrequencyDomain(strip, cfg.omegas_rad_s, opt)) {
    c.a33.push_back(h.a33());
    c.b33.push_back(h.b33());
  }
  return c;
}

// The time-domain strip solver: transient Green function, forced harmonic heave of all sections in the strip
// run to steady state (seakeeping/td_heave_coefficients.h); "time_domain_green_identity": the current sources'
// potential from Green's identity (sk::BodyPotential::kGreenIdentity).
MethodCurve RunTimeDomain(const Strip& strip, const io::SectionRunConfig& cfg, const std::string& method,
                          const std::string& config_file) {
  std::vector<sk::Panel> panels;
  for (const auto& section : strip) panels.insert(panels.end(), section.begin(), section.end());
  MethodCurve c{method, cfg.omegas_rad_s, {}, {}};
  sk::TimeDomainSectionOptions opt;
  if (method == "time_domain_green_identity") opt.operators.body_potential = sk::BodyPotential::kGreenIdentity;
  try {
    const sk::HeaveCoefficients h =
        sk::TimeDomainHeaveCoefficients(panels, cfg.omegas_rad_s, cfg.rho_kg_m3, cfg.g_m_s2, opt);
    c.a33 = h.a33_kg_per_m;
    c.b33 = h.b33_kg_per_m_s;
  } catch (const std::invalid_argument& e) {
    throw io::InputError(config_file + ": key 'section': time-domain solver: " + e.what());
  }
  return c;
}

MethodCurve RunMethod(const std::string& method, const Strip& strip, const io::SectionRunConfig& cfg,
                      const std::string& config_file) {
  if (method == "frequency_domain" || method == "frequency_domain_direct")
    return RunFrequencyDomain(strip, cfg, method);
  return RunTimeDomain(strip, cfg, method, config_file);
}

void WriteCsv(const std::vector<MethodCurve>& curves, const std::string& path) {
  std::ostringstream os;
  os << "method,omega_rad_s,a33_kg_per_m,b33_kg_per_m_s\n";
  char line[256];
  for (const auto& c : curves) {
    for (std::size_t i = 0; i < c.omega.size(); ++i) {
      std::snprintf(line, sizeof line, "%s,%.10g,%.10g,%.10g\n", c.method.c_str(), c.omega[i], c.a33[i],
                    c.b33[i]);
      os << line;
    }
  }
  io::WriteFileAtomically(path, os.str());
}

void WritePlot(const std::vector<MethodCurve>& curves, const io::SectionRunConfig& cfg,
               const std::string& path) {
  const double beam = sk::SectionBeam(cfg.strip);
  const double area = sk::SectionArea(cfg.strip) * cfg.strip.count;  // submerged area of the whole strip
  const double rho_a = cfg.rho_kg_m3 * area;
  io::PlotFigure fig;
  std::ostringstream title;
  title << "Heave added mass and damping per unit length: " << cfg.shape_name;
  if (cfg.strip.count > 1) title << " × " << cfg.strip.count << " at " << cfg.strip.spacing_m << " m spacing";
  fig.title = title.str();
  std::ostringstream foot;
  foot.precision(4);
  foot << "A: submerged area of the strip (" << area << " m²); B: beam of one section (" << beam << " m); "
       << cfg.strip.panels << " panels per section; ρ " << cfg.rho_kg_m3 << " kg/m³, g " << cfg.g_m_s2
       << " m/s²";
  for (const auto& w : cfg.warnings) foot << "; warning: " << w;
  fig.footnote = foot.str();
  fig.AddPanel("Added mass", "ω²(B/2)/g [-]", "a33 / (ρA) [-]");
  fig.AddPanel("Damping", "ω²(B/2)/g [-]", "b33 / (ρAω) [-]");
  for (const auto& c : curves) {
    std::vector<double> x, ya, yb;
    for (std::size_t i = 0; i < c.omega.size(); ++i) {
      x.push_back(c.omega[i] * c.omega[i] * 0.5 * beam / cfg.g_m_s2);
      ya.push_back(c.a33[i] / rho_a);
      yb.push_back(c.b33[i] / (rho_a * c.omega[i]));
    }
    fig.panels[0].series.push_back(io::PlotSeries::LineMarkers(c.method, x, ya));
    fig.panels[1].series.push_back(io::PlotSeries::LineMarkers(c.method, x, yb));
  }
  fig.panels[0].y_include_zero = true;
  fig.panels[1].y_include_zero = true;
  io::WriteSvg(fig, path);
}

void RunSection(const std::string& config_file, const std::string& out_dir) {
  io::YamlMap root = io::YamlMap::LoadFile(config_file);
  const io::SectionRunConfig cfg = io::ReadSectionConfig(root);
  Strip strip;
  try {
    strip = sk::PanelSectionStrip(cfg.strip);
  } catch (const std::exception& e) {  // ReadSectionConfig checked every field; this is a last guard
    throw io::InputError(config_file + ": section: " + e.what());
  }
  CheckOutputDirConfig(out_dir, "section", root.resolved());
  if (std::find(cfg.methods.begin(), cfg.methods.end(), "time_domain") != cfg.methods.end() ||
      std::find(cfg.methods.begin(), cfg.methods.end(), "time_domain_green_identity") != cfg.methods.end()) {
    io::StripWork work;
    work.method = "section_time_domain";
    work.panels = cfg.strip.panels;
    work.bodies = cfg.strip.count;
    work.frequencies = static_cast<long>(cfg.omegas_rad_s.size());
    work.lags = sk::TimeDomainSectionOptions{}.max_lags;
    CheckRunCost("section", work);
  }
  std::vector<MethodCurve> curves;
  for (const auto& m : cfg.methods) curves.push_back(RunMethod(m, strip, cfg, config_file));
  for (const auto& c : curves)
    for (std::size_t i = 0; i < c.omega.size(); ++i)
      if (!std::isfinite(c.a33[i]) || !std::isfinite(c.b33[i]))
        throw std::runtime_error("section: " + c.method + " gave a non-finite coefficient at omega = " +
                                 std::to_string(c.omega[i]) + " rad/s");
  PrepareOutputDir(out_dir, "section", config_file, root.resolved());
  for (const auto& w : cfg.warnings) std::cerr << "hullopt: warning: " << w << "\n";
  WriteCsv(curves, OutPath(out_dir, "section.csv"));
  WritePlot(curves, cfg, OutPath(out_dir, "section.svg"));
  Out() << "hullopt section: " << cfg.omegas_rad_s.size() << " frequencies, " << cfg.methods.size()
            << " method(s) -> " << OutPath(out_dir, "section.csv") << ", " << OutPath(out_dir, "section.svg")
            << "\n";
}

}  // namespace

void AddSectionCommand(CLI::App& app) {
  AddConfigCommand(app,
                   {"section", "Heave added mass and damping per unit length of 2D sections (section.csv, section.svg)",
                    "YAML config with a section: block (see examples/section_semicircle.yaml)", "CONFIG"},
                   RunSection);
}

}  // namespace hullopt::app
