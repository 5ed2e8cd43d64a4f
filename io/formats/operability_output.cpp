#include "io/formats/operability_output.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <nlohmann/json.hpp>

#include "io/formats/atomic_file.h"
#include "io/formats/input_error.h"

namespace hullopt::io {
namespace {
double Finite(double v, const std::string& what) {
  if (!std::isfinite(v)) throw InputError("operability: non-finite " + what);
  return v;
}
}  // namespace

std::vector<std::string> WriteOperabilityOutputs(const std::string& dir, const std::vector<DesignOperability>& designs,
                                                 const sk::ScatterDiagram& diagram,
                                                 const std::vector<sk::OperabilityCriterion>& criteria,
                                                 const std::string& scatter_source) {
  const std::string csv = dir + "/operability.csv", js = dir + "/operability.json";
  // Both files are built whole and only then written, each atomically: a failure (a non-finite value) leaves
  // no half-written table behind, and neither file is written without the other's content ready.
  std::ostringstream f;
  f << "design,Hs_m," << (diagram.period_is_tp ? "Tp_s" : "Tz_s")
    << ",probability,msi_mean_pct,msi_forward_pct,msi_lcg_pct,msi_transom_pct,rms_accel_forward_g,"
       "rms_accel_lcg_g,rms_accel_transom_g";
  for (const auto& c : criteria) f << ",met_" << c.name;
  f << "\n" << std::setprecision(10);
  nlohmann::json j;
  j["scatter_csv"] = scatter_source;
  j["period"] = diagram.period_is_tp ? "Tp" : "Tz";
  j["cells"] = diagram.cells.size();
  for (const auto& c : criteria)
    j["criteria"].push_back({{"name", c.name}, {"position", c.position}, {"quantity", c.is_msi ? "msi_pct" : "rms_accel_g"},
                             {"limit", c.limit}});
  for (const auto& d : designs) {
    for (const auto& cell : d.result.cells) {
      const auto& e = cell.evaluation;
      f << d.name << ',' << cell.cell.Hs_m << ',' << cell.cell.period_s << ',' << cell.cell.probability << ','
        << Finite(e.mean.msi_pct, "MSI");
      for (int k = 0; k < 3; ++k) f << ',' << Finite(e.positions[k].msi_pct, "MSI");
      for (int k = 0; k < 3; ++k) f << ',' << Finite(e.positions[k].rms_accel_g, "acceleration");
      for (bool met : cell.criterion_met) f << ',' << (met ? 1 : 0);
      f << "\n";
    }
    nlohmann::json jd;
    jd["design"] = d.name;
    jd["weighted_mean_msi_pct"] = Finite(d.result.weighted_mean_msi_pct, "mean MSI");
    for (size_t k = 0; k < criteria.size(); ++k)
      jd["criterion_time_pct"][criteria[k].name] = Finite(d.result.criterion_time_pct[k], "criterion time share");
    jd["all_criteria_time_pct"] = Finite(d.result.all_criteria_time_pct, "time share");
    j["designs"].push_back(jd);
  }
  WriteFileAtomically(csv, f.str());
  WriteFileAtomically(js, j.dump(2) + "\n");
  return {"operability.csv", "operability.json"};
}

void WriteOperabilityPolarCsv(const std::string& path, const eval::OperabilityPolar& polar,
                              const std::vector<eval::PolarCriterion>& criteria) {
  constexpr double kKnot = 1852.0 / 3600.0;  // [m/s]
  std::ostringstream f;
  f << "speed_kn,wave_direction_deg,operability";
  for (const auto& c : criteria) f << ",share_" << c.name;
  f << ",note\n" << std::setprecision(10);
  for (const auto& cell : polar.cells) {
    f << cell.speed_m_s / kKnot << ',' << cell.heading_deg << ',';
    if (cell.computed) f << Finite(cell.operability, "operability");
    for (double v : cell.criterion_share) {
      f << ',';
      if (cell.computed) f << Finite(v, "criterion share");
    }
    // The note is free text: quoted, with any quote doubled. A computed cell carries the roll damping's flags
    // raised at its speed.
    std::string text = cell.note;
    if (cell.computed)
      for (const auto& flag : polar.flags)
        if (std::find(flag.speeds_m_s.begin(), flag.speeds_m_s.end(), cell.speed_m_s) != flag.speeds_m_s.end())
          text += (text.empty() ? "warning: " : "; warning: ") + flag.text;
    std::string note;
    for (char ch : text) note += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    f << ",\"" << note << "\"\n";
  }
  WriteFileAtomically(path, f.str());
}

}  // namespace hullopt::io
