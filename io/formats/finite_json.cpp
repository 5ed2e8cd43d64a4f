#include "io/formats/finite_json.h"

#include <cmath>

#include "io/formats/input_error.h"

namespace hullopt::io {
namespace {

template <class Json>
void Walk(const Json& j, const std::string& path, const std::string& design, const std::string& file) {
  if (j.is_object()) {
    std::string here = design;
    for (const char* k : {"name", "design"})
      if (j.contains(k) && j.at(k).is_string()) here = j.at(k).template get<std::string>();
    for (auto it = j.begin(); it != j.end(); ++it)
      Walk(it.value(), path.empty() ? it.key() : path + "." + it.key(), here, file);
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) Walk(j[i], path + "[" + std::to_string(i) + "]", design, file);
  } else if (j.is_number_float()) {
    const double v = j.template get<double>();
    if (!std::isfinite(v))
      throw InputError(file + ": quantity " + path + " = " + (std::isnan(v) ? "nan" : "inf") +
                       (design.empty() ? "" : " (design '" + design + "')") +
                       ": refusing to write a non-finite number");
  }
}

}  // namespace

void RequireFiniteJson(const nlohmann::json& d, const std::string& file) { Walk(d, "", "", file); }
void RequireFiniteJson(const nlohmann::ordered_json& d, const std::string& file) { Walk(d, "", "", file); }

}  // namespace hullopt::io
