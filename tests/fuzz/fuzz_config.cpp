// libFuzzer harness: the YAML config loader and every config block reader (hull, water, speed, solver, mass,
// seas, msi, section, calibrate, optimize/explore). Each reader gets a fresh load of the same input.
#include <optional>

#include "fuzz_input.h"
#include "calibration/calibrate_config.h"
#include "io/config/campaign_config.h"
#include "io/config/hull_config.h"
#include "io/formats/input_error.h"
#include "io/config/motion_config.h"
#include "io/config/seas_config.h"
#include "io/config/section_config.h"
#include "io/config/speed_config.h"
#include "io/config/water_config.h"
#include "io/config/yaml_map.h"

namespace {
using hullopt::io::InputError;
using hullopt::io::YamlMap;

template <class F>
void Try(const std::string& path, F f) {
  try {
    YamlMap root = YamlMap::LoadFile(path);
    f(root);
  } catch (const InputError&) {
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  namespace io = hullopt::io;
  namespace calib = hullopt::calib;
  const std::string path = hullopt::fuzz::WriteScratch(data, size, ".yaml");
  Try(path, [](YamlMap& r) {
    const io::WaterOptions w = io::ParseWater(r);
    io::ParseHullConfig(r, w);
    io::ParseSpeed(r, false);
  });
  Try(path, [](YamlMap& r) {
    YamlMap s = r.Map("solver");
    io::ParseSolverConfig(s, false);
  });
  Try(path, [](YamlMap& r) {
    io::ReadSeas(r);
    io::ReadMsiOptions(r);
  });
  Try(path, [](YamlMap& r) { io::ReadSectionConfig(r); });
  Try(path, [](YamlMap& r) { calib::ReadCalibrateConfig(r); });
  for (auto command : {io::CampaignCommand::kOptimize, io::CampaignCommand::kExplore}) {
    Try(path, [&](YamlMap& r) {
      std::optional<YamlMap> block;
      const io::CampaignConfig c = io::ReadCampaignConfig(r, r.raw(), command, &block);
      io::ValidateCampaign(c, command, path);
    });
  }
  Try(path, [](YamlMap& r) { r.Finish(); });
  return 0;
}
