#pragma once
// The last guard before a JSON output: nlohmann::json writes NaN and infinity as null, so a non-finite number
// would reach the file as a silent gap. Writers call this on the finished document.
#include <nlohmann/json.hpp>

#include <string>

namespace hullopt::io {

/// Throws InputError "file: quantity <json path> = nan|inf (design 'name')" for the first non-finite
/// number; the design is the nearest enclosing object's "name" or "design" text, if any.
void RequireFiniteJson(const nlohmann::json& document, const std::string& file);
void RequireFiniteJson(const nlohmann::ordered_json& document, const std::string& file);

}  // namespace hullopt::io
