#include "io/report/evaluation_report.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "hullopt/version.h"
#include "io/formats/finite_json.h"
#include "io/formats/atomic_file.h"
#include "io/formats/input_error.h"
#include "io/report/seakeeping_plots.h"
#include "io/report/svg_plot.h"

namespace hullopt::io {
namespace {

std::string Csv(double v) {
  if (!std::isfinite(v)) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// Design names may hold commas or quotes: quote them per RFC 4180.
std::string CsvText(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string ReportPath(const std::string& dir, const std::string& name) {
  return (std::filesystem::path(dir) / name).string();
}

nlohmann::json PositionJson(const sk::PositionResult& r, double hs) {
  nlohmann::json j;
  j["position"] = r.position;
  j["x_from_cg_m"] = std::isfinite(r.x_from_cg_m) ? nlohmann::json(r.x_from_cg_m) : nlohmann::json(nullptr);
  j["rms_accel_m_s2"] = r.rms_accel_m_s2;
  j["rms_accel_g"] = r.rms_accel_g;
  j["rms_accel_g_per_m"] = r.rms_accel_g / hs;
  j["rms_displacement_m"] = r.rms_displacement_m;
  j["msi_omega_e_rad_s"] = r.omega_char_rad_s;
  j["msi_pct"] = r.msi_pct;
  return j;
}

}  // namespace

void WriteMsiCsv(const std::string& path, const std::vector<EvaluatedDesign>& designs) {
  std::ostringstream f;
  f << "design,Hs_m,Tz_s,position,x_from_cg_m,rms_accel_g,msi_pct,notes\n";
  for (const auto& d : designs) {
    // The design's warnings and generator adjustments go on each of its rows, so no filtered copy loses them.
    std::string notes;
    for (const auto& w : d.rao.warnings) notes += (notes.empty() ? "" : "; ") + w;
    for (const auto& s : d.evaluation.seas) {
      auto row = [&](const sk::PositionResult& r) {
        for (double v : {s.sea.Hs_m, s.Tz_s, r.rms_accel_g, r.msi_pct})
          if (!std::isfinite(v))
            throw InputError(path + ": design '" + d.name + "', position '" + r.position +
                             "': a non-finite acceleration or MSI; refusing to write it");
        f << CsvText(d.name) << ',' << Csv(s.sea.Hs_m) << ',' << Csv(s.Tz_s) << ',' << CsvText(r.position)
          << ',' << Csv(r.x_from_cg_m) << ',' << Csv(r.rms_accel_g) << ',' << Csv(r.msi_pct) << ','
          << CsvText(notes) << '\n';
      };
      for (const auto& r : s.positions) row(r);
      row(s.mean);
    }
  }
  WriteFileAtomically(path, f.str());
}

std::vector<std::string> EvaluationWarnings(const std::vector<EvaluatedDesign>& designs,
                                            const EvaluationReportOptions& report) {
  std::vector<std::string> w;
  for (const auto& d : designs) {
    for (const auto& r : d.rao.warnings) w.push_back("design '" + d.name + "': " + r);
    for (const auto& s : d.evaluation.seas) {
      if (s.truncated_wave_energy_fraction > report.truncation_warning_fraction) {
        char buf[320];
        std::snprintf(buf, sizeof buf,
                      "design '%s', sea Hs %g m Tz %.3g s: the RAO table (omega %.3g..%.3g rad/s) leaves out "
                      "%.1f%% of the wave energy (threshold %.1f%%); ",
                      d.name.c_str(), s.sea.Hs_m, s.Tz_s, d.rao.omega_rad_s.front(), d.rao.omega_rad_s.back(),
                      100.0 * s.truncated_wave_energy_fraction, 100.0 * report.truncation_warning_fraction);
        w.push_back(buf + (d.frequency_advice.empty() ? std::string("extend the RAO frequency range") : d.frequency_advice));
      }
    }
  }
  return w;
}

nlohmann::json ResolutionCheckJson(const sk::ResolutionCheck& r) {
  return {{"sections", r.sections},
          {"panels", r.panels},
          {"fine_sections", r.fine_sections},
          {"fine_panels", r.fine_panels},
          {"heave_peak", r.heave_peak},
          {"heave_peak_fine", r.heave_peak_fine},
          {"heave_peak_change", r.heave_peak_change},
          {"pitch_peak", r.pitch_peak},
          {"pitch_peak_fine", r.pitch_peak_fine},
          {"pitch_peak_change", r.pitch_peak_change},
          {"max_msi_change_pct", r.max_msi_change_pct},
          {"mean_msi_pct", r.mean_msi_pct},
          {"fine_mean_msi_pct", r.fine_mean_msi_pct},
          {"converged", r.converged}};
}

nlohmann::json EvaluationSummaryJson(const std::vector<EvaluatedDesign>& designs,
                                     const sk::EvaluationOptions& options,
                                     const std::vector<std::string>& warnings) {
  nlohmann::json j;
  j["tool"] = std::string("hullopt ") + kVersion;
  j["command"] = "evaluate";
  j["conventions"] = {
      {"axes", "x forward, z up, origin at the CG; heave positive up, pitch positive bow-down"},
      {"seas", "long-crested head seas (180 deg); omega_e = omega + omega^2 U/g"},
      {"point_motion", "s = x3 - x*x5 from complex RAOs; a = -omega_e^2 s"},
      {"positions", "forward = LCG + 0.6*(LCG-to-transom distance); mean = mean of forward, lcg, transom"},
      {"rms_accel_g", "standard deviation of vertical acceleration / g"}};
  j["msi"] = {{"model", sk::MsiModelName(options.msi.model)},
              {"exposure_h", options.msi.exposure_h},
              {"frequency", sk::MsiFrequencyName(options.msi.frequency)},
              {"acceleration", sk::AccelerationStatisticName(options.msi.statistic)},
              {"iso_km", options.msi.iso_km}};
  j["quadrature_intervals"] = options.response.quadrature_intervals;
  j["designs"] = nlohmann::json::array();
  for (const auto& d : designs) {
    nlohmann::json jd;
    jd["name"] = d.name;
    jd["group"] = d.group;
    jd["parameters"] = d.parameters;
    jd["speed_m_s"] = d.rao.speed_m_s;
    jd["speed_kn"] = d.rao.speed_m_s * 3600.0 / 1852.0;
    jd["cg_to_transom_m"] = d.hull.cg_to_transom_m;
    jd["cg_to_bow_m"] = d.hull.cg_to_bow_m;
    jd["rao_omega_range_rad_s"] = {d.rao.omega_rad_s.front(), d.rao.omega_rad_s.back()};
    jd["seas"] = nlohmann::json::array();
    double mean_msi = 0.0;
    for (const auto& s : d.evaluation.seas) {
      nlohmann::json js;
      js["spectrum"] = sk::SpectrumName(s.sea.spectrum);
      js["Hs_m"] = s.sea.Hs_m;
      js["Tz_s"] = s.Tz_s;
      js["Tp_s"] = s.Tp_s;
      js["gamma"] = s.sea.gamma;
      js["peak_omega_e_rad_s"] = s.peak_omega_e_rad_s;
      js["truncated_wave_energy_fraction"] = s.truncated_wave_energy_fraction;
      js["positions"] = nlohmann::json::array();
      for (const auto& r : s.positions) js["positions"].push_back(PositionJson(r, s.sea.Hs_m));
      js["mean"] = PositionJson(s.mean, s.sea.Hs_m);
      js["mean_msi_pct"] = s.mean.msi_pct;
      mean_msi += s.mean.msi_pct / d.evaluation.seas.size();
      jd["seas"].push_back(js);
    }
    jd["mean_msi_pct_over_seas"] = mean_msi;
    if (d.resolution) {
      jd["resolution_check"] = ResolutionCheckJson(*d.resolution);
    }
    j["designs"].push_back(jd);
  }
  j["warnings"] = warnings;
  return j;
}

std::vector<std::string> WriteEvaluationOutputs(const std::string& dir,
                                                const std::vector<EvaluatedDesign>& designs,
                                                const sk::EvaluationOptions& options,
                                                const EvaluationReportOptions& report) {
  if (designs.empty()) throw InputError("evaluate: no designs to report");
  std::vector<std::string> files;
  WriteMsiCsv(ReportPath(dir, "msi.csv"), designs);
  files.push_back("msi.csv");
  const auto warnings = EvaluationWarnings(designs, report);
  {
    const std::string path = ReportPath(dir, "summary.json");
    const auto summary = EvaluationSummaryJson(designs, options, warnings);
    RequireFiniteJson(summary, path);
    WriteFileAtomically(path, summary.dump(2) + "\n");
    files.push_back("summary.json");
  }
  if (!report.plots) return files;
  auto write = [&](const PlotFigure& fig, const std::string& name) {
    WriteSvg(fig, ReportPath(dir, name));
    files.push_back(name);
  };
  // Fig. 7 at the first design's speed, from the seas it was evaluated in.
  std::vector<sk::WaveSpectrum> spectra;
  for (const auto& s : designs[0].evaluation.seas) spectra.emplace_back(s.sea);
  write(EncounterSpectraFigure(spectra, designs[0].rao.speed_m_s, designs[0].rao.g_m_s2),
        "encounter_spectra.svg");
  write(RaoFigure(designs), "raos.svg");
  const size_t ref = ReferenceSeaIndex(designs[0].evaluation.seas);
  write(AccelerationPerMetreFigure(designs, ref), "accel_per_m.svg");
  write(AccelerationPerMetreVsHsFigure(designs), "accel_per_m_vs_Hs.svg");
  write(MsiAlongHullFigure(designs), "msi_positions.svg");
  write(MsiVsHsFigure(designs), "msi_vs_Hs.svg");
  for (const auto& [key, label] : report.plot_parameters) {
    bool any = false;
    for (const auto& d : designs) any = any || d.parameters.count(key);
    if (any) write(MsiVsParameterFigure(designs, key, label, ref), "msi_vs_" + key + ".svg");
  }
  return files;
}

}  // namespace hullopt::io
