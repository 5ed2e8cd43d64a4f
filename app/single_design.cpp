#include "app/single_design.h"

#include "app/design_resolution_check.h"
#include "app/run_checks.h"
#include "evaluation/validity_envelope.h"
#include "io/config/design_config.h"
#include "io/config/design_defaults.h"
#include "io/formats/input_error.h"
#include "io/config/run_cost.h"
#include "io/config/seas_config.h"

namespace hullopt::app {
namespace {

// Every block EvaluateSingleDesign reads, read once from the config as written (a separate record of keys and
// resolved values) and nothing built: a fault anywhere is refused before the default frequency grid builds
// the hull, and before any calm-water or strip work.
void CheckSingleDesignConfig(const io::YamlMap& root, const std::string& name, bool strict) {
  io::YamlMap check(root.raw(), "", root.file(), YAML::Node(YAML::NodeType::Map));
  if (check.Has("name")) check.Skip("name");  // read by the caller
  io::SkipCampaignBlocks(check, nullptr);
  io::ParseDesign(check, root.file(), name);
  io::ReadSeas(check);
  io::ReadMsiOptions(check);
  io::YamlMap positions = check.MapOrEmpty("positions");
  io::ReadPassengerPoints(positions, nullptr);
  positions.Finish();
  io::ReadResolutionCheck(check);
  if (strict) check.Finish();
}

}  // namespace

SingleDesign EvaluateSingleDesign(io::YamlMap& root, const std::string& name, const std::string& command,
                                  bool strict, const std::function<void()>& before_work) {
  SingleDesign s;
  const std::string& config = root.file();
  io::SkipCampaignBlocks(root, &s.notes, command);
  io::FillDefaultSeas(root, &s.notes);
  CheckSingleDesignConfig(root, name, strict);
  io::FillDefaultFrequencies(root, &s.notes);
  s.design = io::LoadDesignCase(root, config, name);
  io::NoteModelDefaults(root.raw(), s.design, &s.notes);
  const std::vector<sk::SeaState> seas = io::ReadSeas(root);
  s.options.msi = io::ReadMsiOptions(root);
  io::EvaluatedDesign& d = s.evaluated;
  d.name = name;
  d.hull = s.design.Extent();
  d.parameters = s.design.Parameters();
  d.frequency_advice = eval::SeaFrequencyAdvice(s.design, config);
  io::YamlMap positions = root.MapOrEmpty("positions");
  s.points = io::ReadPassengerPoints(positions, &d.hull);
  positions.Finish();
  s.resolution = io::ReadResolutionCheck(root);
  if (strict) root.Finish();
  if (before_work) before_work();
  const std::vector<double> omega = eval::SeaFrequencies(s.design);
  CheckRunCost(command, io::StripWorkFromResolved(root.resolved(), static_cast<long>(omega.size())));
  s.spectra = sk::BuildSpectra(seas);
  const eval::GridSeas grid_seas{s.spectra, d.hull, s.points, s.options};
  d.rao = eval::ComputeDesignRaos(s.design, omega, -1.0, &grid_seas);
  try {
    d.evaluation = sk::EvaluateDesign(d.rao, d.hull, s.spectra, s.points, s.options);
  } catch (const std::exception& e) {
    throw io::InputError(config + ": design '" + name + "': " + e.what());
  }
  for (auto& w : eval::ResponseEnvelopeWarnings(d.evaluation, s.design.water.g_m_s2)) d.rao.warnings.push_back(std::move(w));
  if (s.resolution.enabled)
    CheckDesignResolution(s.resolution, s.spectra, s.points, s.options, s.design, -1.0, config, &d);
  return s;
}

double SpeedKnots(const eval::DesignCase& design) { return design.speed_m_s / (1852.0 / 3600.0); }

}  // namespace hullopt::app
