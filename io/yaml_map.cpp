#include "io/yaml_map.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include "io/utf8_text.h"

namespace hullopt::io {
namespace {
std::string Line(const YAML::Node& n) {
  const auto m = n.Mark();
  return m.line >= 0 ? std::to_string(m.line + 1) : std::string("?");
}
std::string Scalar(const YAML::Node& n) {
  if (n.IsScalar()) return n.Scalar();
  if (n.IsSequence()) return "[sequence]";
  if (n.IsMap()) return "{mapping}";
  return "(null)";
}
}  // namespace

YamlMap::YamlMap(const YAML::Node& node, std::string path, std::string file, YAML::Node resolved)
    : node_(node),
      path_(std::move(path)),
      file_(std::move(file)),
      resolved_(resolved),
      used_(std::make_shared<std::set<std::string>>()) {
  if (node_ && !node_.IsNull() && !node_.IsMap()) {
    throw InputError(file_ + ":" + Line(node_) + ": key '" + path_ +
                     "' must be a mapping of key: value pairs");
  }
}

YamlMap YamlMap::LoadFile(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw InputError(file + ": cannot open config file (does it exist and is it readable?)");
  std::ostringstream text;
  text << in.rdbuf();
  RequireUtf8(text.str(), file);
  YAML::Node root;
  try {
    root = YAML::Load(text.str());
  } catch (const YAML::Exception& e) {
    throw InputError(file + ":" + std::to_string(e.mark.line + 1) + ": YAML syntax error: " + e.msg);
  }
  if (!root || root.IsNull()) throw InputError(file + ": config file is empty");
  return YamlMap(root, "", file, YAML::Node(YAML::NodeType::Map));
}

bool YamlMap::Has(const std::string& key) const { return node_ && node_[key] && !node_[key].IsNull(); }

std::string YamlMap::Full(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }

std::string YamlMap::Where(const std::string& key) const {
  const YAML::Node n = node_ ? node_[key] : YAML::Node();
  const std::string line = n ? Line(n) : (node_ ? Line(node_) : std::string("?"));
  return file_ + ":" + line + ": key '" + Full(key) + "'";
}

void YamlMap::Fail(const std::string& key, const std::string& rule) const {
  const YAML::Node n = node_ ? node_[key] : YAML::Node();
  std::string value = (n && n.IsScalar()) ? " = " + n.Scalar() : "";
  throw InputError(Where(key) + value + ": " + rule);
}

YAML::Node YamlMap::Get(const std::string& key) const {
  used_->insert(key);
  if (!Has(key)) {
    throw InputError(file_ + ":" + (node_ ? Line(node_) : std::string("?")) + ": missing required key '" +
                     Full(key) + "'");
  }
  return node_[key];
}

void YamlMap::Skip(const std::string& key) { used_->insert(key); }

double YamlMap::ToNumber(const YAML::Node& n, const std::string& key) const {
  if (!n.IsScalar()) Fail(key, "must be a number, got " + Scalar(n));
  double v = 0;
  try {
    v = n.as<double>();
  } catch (const YAML::Exception&) {
    Fail(key, "must be a number");
  }
  if (!std::isfinite(v)) Fail(key, "must be a finite number (NaN and infinity are not allowed)");
  return v;
}

double YamlMap::Number(const std::string& key) {
  const double v = ToNumber(Get(key), key);
  resolved_[key] = v;
  return v;
}

double YamlMap::Number(const std::string& key, double default_value) {
  used_->insert(key);
  const double v = Has(key) ? ToNumber(node_[key], key) : default_value;
  resolved_[key] = v;
  return v;
}

int YamlMap::Integer(const std::string& key) {
  const double v = ToNumber(Get(key), key);
  if (v != std::floor(v) || std::fabs(v) > 2e9) Fail(key, "must be a whole number");
  resolved_[key] = static_cast<int>(v);
  return static_cast<int>(v);
}

int YamlMap::Integer(const std::string& key, int default_value) {
  if (!Has(key)) {
    used_->insert(key);
    resolved_[key] = default_value;
    return default_value;
  }
  return Integer(key);
}

bool YamlMap::Boolean(const std::string& key, bool default_value) {
  used_->insert(key);
  bool v = default_value;
  if (Has(key)) {
    try {
      v = node_[key].as<bool>();
    } catch (const YAML::Exception&) {
      Fail(key, "must be true or false");
    }
  }
  resolved_[key] = v;
  return v;
}

std::string YamlMap::String(const std::string& key) {
  const YAML::Node n = Get(key);
  if (!n.IsScalar()) Fail(key, "must be a text value, got " + Scalar(n));
  resolved_[key] = n.Scalar();
  return n.Scalar();
}

std::string YamlMap::String(const std::string& key, const std::string& default_value) {
  if (!Has(key)) {
    used_->insert(key);
    resolved_[key] = default_value;
    return default_value;
  }
  return String(key);
}

std::string YamlMap::Choice(const std::string& key, const std::vector<std::string>& choices,
                            const std::string& default_value) {
  const std::string v = default_value.empty() ? String(key) : String(key, default_value);
  for (const auto& c : choices)
    if (c == v) return v;
  std::string list;
  for (const auto& c : choices) list += (list.empty() ? "" : ", ") + c;
  Fail(key, "must be one of: " + list);
}

std::vector<double> YamlMap::Numbers(const std::string& key) {
  const YAML::Node n = Get(key);
  if (!n.IsSequence()) Fail(key, "must be a list of numbers, e.g. [0.5, 1.0]");
  if (n.size() == 0) Fail(key, "must not be an empty list");
  std::vector<double> out;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const YAML::Node e = n[i];
    if (!e.IsScalar()) Fail(key, "element " + std::to_string(i + 1) + " must be a number");
    double v = 0;
    try {
      v = e.as<double>();
    } catch (const YAML::Exception&) {
      Fail(key, "element " + std::to_string(i + 1) + " = " + e.Scalar() + " is not a number");
    }
    if (!std::isfinite(v)) Fail(key, "element " + std::to_string(i + 1) + " must be finite");
    out.push_back(v);
  }
  YAML::Node seq(YAML::NodeType::Sequence);
  for (double v : out) seq.push_back(v);
  seq.SetStyle(YAML::EmitterStyle::Flow);
  resolved_[key] = seq;
  return out;
}

std::vector<std::string> YamlMap::Strings(const std::string& key) {
  const YAML::Node n = Get(key);
  if (!n.IsSequence()) Fail(key, "must be a list of text values");
  std::vector<std::string> out;
  for (std::size_t i = 0; i < n.size(); ++i) {
    if (!n[i].IsScalar()) Fail(key, "element " + std::to_string(i + 1) + " must be a text value");
    out.push_back(n[i].Scalar());
  }
  YAML::Node seq(YAML::NodeType::Sequence);
  for (const auto& v : out) seq.push_back(v);
  resolved_[key] = seq;
  return out;
}

YamlMap YamlMap::Map(const std::string& key) {
  const YAML::Node n = Get(key);
  if (!n.IsMap()) Fail(key, "must be a mapping of key: value pairs");
  resolved_[key] = YAML::Node(YAML::NodeType::Map);
  return YamlMap(n, Full(key), file_, resolved_[key]);
}

YamlMap YamlMap::MapOrEmpty(const std::string& key) {
  if (!Has(key)) {
    used_->insert(key);
    resolved_[key] = YAML::Node(YAML::NodeType::Map);
    return YamlMap(YAML::Node(YAML::NodeType::Map), Full(key), file_, resolved_[key]);
  }
  return Map(key);
}

std::vector<YamlMap> YamlMap::ListOfMaps(const std::string& key) {
  const YAML::Node n = Get(key);
  if (!n.IsSequence()) Fail(key, "must be a list of mappings (lines starting with '- ')");
  if (n.size() == 0) Fail(key, "must not be an empty list");
  YAML::Node seq(YAML::NodeType::Sequence);
  std::vector<YamlMap> out;
  for (std::size_t i = 0; i < n.size(); ++i) {
    seq.push_back(YAML::Node(YAML::NodeType::Map));
  }
  resolved_[key] = seq;
  for (std::size_t i = 0; i < n.size(); ++i) {
    out.emplace_back(n[i], Full(key) + "[" + std::to_string(i) + "]", file_, resolved_[key][i]);
  }
  return out;
}

std::vector<std::string> YamlMap::Keys() const {
  std::vector<std::string> keys;
  if (node_ && node_.IsMap())
    for (const auto& kv : node_) keys.push_back(kv.first.as<std::string>());
  return keys;
}

void YamlMap::Finish() const {
  if (!node_ || !node_.IsMap()) return;
  for (const auto& kv : node_) {
    const std::string k = kv.first.as<std::string>();
    if (!used_->count(k)) {
      throw InputError(file_ + ":" + Line(kv.first) + ": unknown key '" + Full(k) +
                       "' (misspelt, or not used by this command; see docs/config-reference.md)");
    }
  }
}

}  // namespace hullopt::io
