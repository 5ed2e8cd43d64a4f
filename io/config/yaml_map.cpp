#include "io/config/yaml_map.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <yaml-cpp/eventhandler.h>

#include "io/formats/utf8_text.h"

namespace hullopt::io {
namespace {

// yaml-cpp 0.7 never returns from YAML::LoadAll when a ',' stands where a document's node should begin: at the
// start of the file, or after a top-level mapping that ends because a line is indented less than its first key
// ("  a: 1\n," loops forever, adding empty documents until memory runs out; found by fuzzing). The parser itself
// stops after each document, so the documents are counted here with an event handler that records where the
// second one begins, and no more than two are asked for.
class SecondDocumentMark : public YAML::EventHandler {
 public:
  int documents = 0;
  YAML::Mark second = YAML::Mark::null_mark();  // where the second document's first node begins

  void OnDocumentStart(const YAML::Mark&) override { ++documents; }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& m, YAML::anchor_t) override { Note(m); }
  void OnAlias(const YAML::Mark& m, YAML::anchor_t) override { Note(m); }
  void OnScalar(const YAML::Mark& m, const std::string&, YAML::anchor_t, const std::string&) override { Note(m); }
  void OnSequenceStart(const YAML::Mark& m, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    Note(m);
  }
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark& m, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {
    Note(m);
  }
  void OnMapEnd() override {}

 private:
  void Note(const YAML::Mark& m) {
    if (documents == 2 && second.is_null()) second = m;
  }
};

// What stands at the second document's mark says which mistake the user made.
std::string SecondDocumentRule(const std::string& text, const YAML::Mark& at) {
  const bool comma = at.pos >= 0 && static_cast<std::size_t>(at.pos) < text.size() && text[at.pos] == ',';
  if (comma) return "YAML syntax error: a ',' (a flow indicator) outside any [ ] or { } list";
  std::istringstream in(text);
  std::string line;
  for (int lineno = 0; std::getline(in, line) && lineno < at.line; ++lineno)
    if (line.compare(0, 3, "---") == 0)
      return "a second YAML document ('---' separator); a config file holds one document";
  return "this line is indented less than the config's first key, so it lies outside the config's mapping "
         "(indent all top-level keys alike)";
}

void RefuseSecondDocument(const std::string& text, const std::string& file) {
  std::istringstream in(text);
  YAML::Parser parser(in);
  SecondDocumentMark handler;
  while (handler.documents < 2 && parser.HandleNextDocument(handler)) {
  }
  if (handler.documents < 2) return;
  const std::string line = handler.second.line >= 0 ? std::to_string(handler.second.line + 1) : std::string("?");
  throw InputError(file + ":" + line + ": " + SecondDocumentRule(text, handler.second));
}
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

// Config files are a few kB; a larger one is not a config (and would only cost memory).
constexpr std::uintmax_t kMaxConfigBytes = 16u << 20;

namespace {
// Configs nest a few levels; deeper is not a config (and an alias could otherwise make the walk endless).
constexpr int kMaxDepth = 64;

void CheckKeysAt(const YAML::Node& node, const std::string& file, int depth);
}  // namespace

void YamlMap::CheckKeys(const YAML::Node& node, const std::string& file) { CheckKeysAt(node, file, 0); }

namespace {
void CheckKeysAt(const YAML::Node& node, const std::string& file, int depth) {
  if (depth > kMaxDepth)
    throw InputError(file + ":" + Line(node) + ": nested deeper than " + std::to_string(kMaxDepth) + " levels");
  if (node.IsSequence()) {
    for (const auto& e : node) CheckKeysAt(e, file, depth + 1);
    return;
  }
  if (!node.IsMap()) return;
  std::set<std::string> seen;
  for (const auto& kv : node) {
    const YAML::Node& k = kv.first;
    // Plain ("?") and quoted ("!") scalars only: a tagged, empty or collection key is not a key name.
    const bool text = k.IsScalar() && (k.Tag() == "?" || k.Tag() == "!") && !k.Scalar().empty();
    if (!text) {
      const std::string what = k.IsSequence() ? "a sequence" : k.IsMap() ? "a mapping"
                               : k.IsScalar() && !k.Scalar().empty() ? "tagged '" + k.Tag() + "'"
                                                                     : "empty";
      throw InputError(file + ":" + Line(k) + ": a key must be plain text (this one is " + what + ")");
    }
    if (!seen.insert(k.Scalar()).second)
      throw InputError(file + ":" + Line(k) + ": duplicate key '" + k.Scalar() +
                       "' (each key may appear once in a mapping)");
    CheckKeysAt(kv.second, file, depth + 1);
  }
}
}  // namespace

YamlMap YamlMap::LoadFile(const std::string& file) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec))
    throw InputError(file + ": is a folder, not a config file (give the YAML file)");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(file + ": cannot open config file (does it exist and is it readable?)");
  const auto bytes = std::filesystem::file_size(file, ec);
  if (!ec && bytes > kMaxConfigBytes)
    throw InputError(file + ": " + std::to_string(bytes) + " bytes is not a config file (at most " +
                     std::to_string(kMaxConfigBytes) + " bytes)");
  std::ostringstream text;
  text << in.rdbuf();
  RequireUtf8(text.str(), file);
  YAML::Node root;
  try {
    RefuseSecondDocument(text.str(), file);
    root = YAML::Load(text.str());
  } catch (const YAML::Exception& e) {
    throw InputError(file + ":" + std::to_string(e.mark.line + 1) + ": YAML syntax error: " + e.msg);
  }
  if (!root || root.IsNull()) throw InputError(file + ": config file is empty");
  if (!root.IsMap()) throw InputError(file + ":" + Line(root) + ": the config must be a mapping of key: value pairs");
  CheckKeys(root, file);
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
  if (v != std::floor(v)) Fail(key, "must be a whole number");
  if (std::fabs(v) > 2e9) Fail(key, "is out of range: a whole number of magnitude at most 2e9");
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

int YamlMap::Integer(const std::string& key, int default_value, int lo, int hi, const std::string& why) {
  used_->insert(key);
  const double v = Has(key) ? ToNumber(node_[key], key) : default_value;
  if (v != std::floor(v)) Fail(key, "must be a whole number");
  if (v < lo || v > hi)
    Fail(key, "must lie in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]" +
                  (why.empty() ? "" : " (" + why + ")"));
  resolved_[key] = static_cast<int>(v);
  return static_cast<int>(v);
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
    for (const auto& kv : node_) keys.push_back(kv.first.Scalar());
  return keys;
}

void YamlMap::Finish() const {
  if (!node_ || !node_.IsMap()) return;
  for (const auto& kv : node_) {
    const std::string k = kv.first.Scalar();
    if (!used_->count(k)) {
      throw InputError(file_ + ":" + Line(kv.first) + ": unknown key '" + Full(k) +
                       "' (misspelt, or not used by this command; see docs/config-reference.md)");
    }
  }
}

}  // namespace hullopt::io
