#pragma once
// Files a campaign leaves besides its history: summary.json, best.yaml, sensitivity.csv, and the config
// fingerprint that guards resuming.
#include <yaml-cpp/yaml.h>

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "optimizer/sensitivity.h"

namespace hullopt::io {

/// FNV-1a 64-bit hash of a text, as 16 hex digits: the fingerprint of config.resolved.yaml.
std::string TextHash(const std::string& text);

/// Writes json (pretty, 2 spaces) to path. Throws InputError if it cannot be written.
void WriteJson(const std::string& path, const nlohmann::json& json);

/// The base config with the best variable values substituted: in hull.parametric.<name> when the value came
/// from there (start_source "hull.parametric"), else in <block>.start.<name>. Written with a comment header.
void WriteBestYaml(const std::string& path, const YAML::Node& base_config, const std::string& block,
                   const std::vector<std::string>& names, const std::vector<std::string>& start_source,
                   const std::vector<double>& best_x, const std::string& comment);

/// sensitivity.csv: variable,src,first_order_sobol
void WriteSensitivityCsv(const std::string& path, const std::vector<std::string>& names,
                         const opt::SensitivityResult& s);

/// Reads a small text file entirely; empty string if it does not exist.
std::string ReadTextFile(const std::string& path);

}  // namespace hullopt::io
