#include "app/campaign_setup.h"

#ifdef _OPENMP
#include <omp.h>
#endif

#include <optional>

#include "app/evaluator_factory.h"
#include "io/campaign_outputs.h"
#include "io/input_error.h"

namespace hullopt::app {

LoadedCampaign LoadCampaign(const std::string& config_file, io::CampaignCommand command) {
  LoadedCampaign out;
  io::YamlMap root = io::YamlMap::LoadFile(config_file);
  try {
    out.raw = YAML::LoadFile(config_file);
  } catch (const YAML::Exception& e) {
    throw io::InputError(config_file + ": " + e.what());
  }
  std::optional<io::YamlMap> block;
  out.config = io::ReadCampaignConfig(root, out.raw, command, &block);
  out.evaluator = MakeEvaluator(root, *block, out.config.definition);
  block->Finish();
  root.Finish();
  out.config.definition.known_quantities = out.evaluator->QuantityNames();
  out.config.definition.known_variables = out.evaluator->VariableNames();
  io::ValidateCampaign(out.config, command, config_file);
  out.resolved = root.resolved();
  YAML::Emitter em;
  em << out.resolved;
  out.config_hash = io::TextHash(em.c_str());
  return out;
}

int ResolveThreads(int requested) {
  if (requested > 0) return requested;
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

}  // namespace hullopt::app
