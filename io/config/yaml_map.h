#pragma once
// Strict reading of YAML config mappings: every key must be known and consumed, types and finiteness are
// checked, and each value read (defaults included) is recorded into a "resolved" tree that the app writes out
// as config.resolved.yaml. Errors are InputError with "file:line: key 'a.b.c': rule".
#include <yaml-cpp/yaml.h>

#include <memory>
#include <set>
#include <string>
#include <vector>

#include "io/formats/input_error.h"

namespace hullopt::io {

class YamlMap {
 public:
  /// node must be a mapping (or null = empty). path is the dotted key path ("" at the root), file the source.
  YamlMap(const YAML::Node& node, std::string path, std::string file, YAML::Node resolved);
  /// Loads a YAML file as the root mapping. Throws InputError (with the line) for a missing file, a folder, a
  /// syntax error, a second document, a duplicate key, or a key that is not plain text (a sequence, a mapping,
  /// a tag, an empty key): anywhere in the file.
  static YamlMap LoadFile(const std::string& file);
  /// Checks a parsed tree as LoadFile does (duplicate and non-text keys), naming file and line.
  static void CheckKeys(const YAML::Node& node, const std::string& file);

  bool Has(const std::string& key) const;

  double Number(const std::string& key);                        ///< required finite number
  double Number(const std::string& key, double default_value);  ///< optional finite number
  int Integer(const std::string& key);
  int Integer(const std::string& key, int default_value);
  /// Optional whole number in [lo, hi]; the error states the range (and `why`, e.g. the cost, if given).
  int Integer(const std::string& key, int default_value, int lo, int hi, const std::string& why = "");
  bool Boolean(const std::string& key, bool default_value);
  std::string String(const std::string& key);
  std::string String(const std::string& key, const std::string& default_value);
  /// Scalar string restricted to a list of choices; the error lists the choices.
  std::string Choice(const std::string& key, const std::vector<std::string>& choices,
                     const std::string& default_value = "");
  std::vector<double> Numbers(const std::string& key);  ///< a non-empty sequence of finite numbers
  std::vector<std::string> Strings(const std::string& key);

  YamlMap Map(const std::string& key);                      ///< required sub-mapping
  YamlMap MapOrEmpty(const std::string& key);               ///< optional sub-mapping (empty when absent)
  std::vector<YamlMap> ListOfMaps(const std::string& key);  ///< required non-empty sequence of mappings
  /// Keys of this mapping in file order (for maps whose keys are user names, e.g. variables).
  std::vector<std::string> Keys() const;
  /// Marks a key as consumed without reading it (for keys owned by another command).
  void Skip(const std::string& key);

  /// Throws InputError naming the first key that was never consumed (unknown or misspelt key).
  void Finish() const;

  /// "file:line: key 'path.key'" for messages.
  std::string Where(const std::string& key) const;
  /// Throws InputError "file:line: key 'path.key' = value: rule".
  [[noreturn]] void Fail(const std::string& key, const std::string& rule) const;

  const std::string& path() const { return path_; }
  const std::string& file() const { return file_; }
  /// The resolved tree (values as read, defaults filled in) of this mapping.
  YAML::Node resolved() const { return resolved_; }
  /// The mapping as read (for lookups that must not mark keys consumed).
  const YAML::Node& raw() const { return node_; }

 private:
  YAML::Node Get(const std::string& key) const;  // throws if missing
  std::string Full(const std::string& key) const;
  double ToNumber(const YAML::Node& n, const std::string& key) const;

  YAML::Node node_;
  std::string path_;
  std::string file_;
  YAML::Node resolved_;
  std::shared_ptr<std::set<std::string>> used_;
};

}  // namespace hullopt::io
