#include "io/config/yaml_difference.h"

#include <cstdlib>
#include <set>

namespace hullopt::io {
namespace {

// Emitted text of a node (flow style, one line), so that numbers compare as they were written.
std::string Text(const YAML::Node& n) {
  YAML::Emitter em;
  em << YAML::Flow << n;
  return em.c_str();
}

// Two scalars that both read as the same double (0.065 written by hand, 0.065000000000000002 emitted).
bool SameNumber(const YAML::Node& a, const YAML::Node& b) {
  if (!a.IsScalar() || !b.IsScalar()) return false;
  auto parse = [](const std::string& s, double* v) {
    char* end = nullptr;
    *v = std::strtod(s.c_str(), &end);
    return !s.empty() && *end == '\0';
  };
  double x = 0, y = 0;
  return parse(a.Scalar(), &x) && parse(b.Scalar(), &y) && x == y;
}

std::string Where(const std::string& path) { return "key '" + (path.empty() ? std::string("(top)") : path) + "'"; }

std::string Diff(const YAML::Node& a, const YAML::Node& b, const std::string& path) {
  if (a.IsMap() && b.IsMap()) {
    std::set<std::string> seen;
    for (const auto& kv : b) {
      const std::string key = kv.first.as<std::string>();
      seen.insert(key);
      const std::string sub = path.empty() ? key : path + "." + key;
      if (!a[key]) return Where(sub) + ": absent before, now '" + Text(kv.second) + "'";
      const std::string d = Diff(a[key], kv.second, sub);
      if (!d.empty()) return d;
    }
    for (const auto& kv : a) {
      const std::string key = kv.first.as<std::string>();
      if (!seen.count(key))
        return Where(path.empty() ? key : path + "." + key) + ": '" + Text(kv.second) + "' before, absent now";
    }
    return "";
  }
  if (a.IsSequence() && b.IsSequence() && a.size() == b.size()) {
    for (std::size_t i = 0; i < a.size(); ++i) {
      const std::string d = Diff(a[i], b[i], path + "[" + std::to_string(i) + "]");
      if (!d.empty()) return d;
    }
    return "";
  }
  const std::string ta = Text(a), tb = Text(b);
  if (ta == tb || SameNumber(a, b)) return "";
  return Where(path) + ": '" + ta + "' before, now '" + tb + "'";
}

}  // namespace

std::string FirstYamlDifference(const YAML::Node& before, const YAML::Node& now) {
  // Round-trip `now` through text so that both sides hold scalars as emitted.
  YAML::Emitter em;
  em << now;
  return Diff(before, YAML::Load(em.c_str()), "");
}

}  // namespace hullopt::io
