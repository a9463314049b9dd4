#pragma once

#include <yaml-cpp/yaml.h>

#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "dream/config/config_error.h"
#include "dream/config/name_suggestion.h"

namespace dream::config {

/// A YAML node that remembers which file and key it came from, so every
/// error names "file:line: key" and the allowed values.
class ConfigNode {
 public:
  /// Parses `path`. @throws ConfigError when the file is missing or not YAML.
  static ConfigNode LoadFile(const std::string& path);
  /// The bytes of the config file `path`, unparsed (for those that edit or
  /// copy it). Only a regular file of at most kMaxFileBytes is read: it is
  /// opened without blocking and checked on the opened descriptor, so a FIFO
  /// cannot hang the command and /dev/zero cannot fill its memory.
  /// @throws ConfigError naming it when it cannot be read or is refused.
  static std::string ReadFile(const std::string& path);
  /// The largest config file (or --set value) read: a config of 10,000
  /// obstacles is under 1 MiB.
  static constexpr size_t kMaxFileBytes = 16 << 20;
  /// Parses `text` as if it came from `source_name` (tests, embedded configs).
  static ConfigNode LoadString(const std::string& text, const std::string& source_name);
  /// The YAML tree of `text`, refusing what yaml-cpp accepts without a word:
  /// a duplicate key (yaml-cpp keeps the first), a second document (dropped),
  /// a key that is a list or mapping, and aliases that make a value contain
  /// itself or expand past kMaxValues values or kMaxDepth levels. For code
  /// that edits the tree before reading it (LoadString uses it too).
  /// @throws ConfigError "file:line: key: problem".
  static YAML::Node ParseYaml(const std::string& text, const std::string& source_name);
  /// A tree's size once aliases are expanded.
  struct Extent {
    size_t values = 1;  ///< nodes
    int height = 0;     ///< levels below the root
  };
  /// The checks of ParseYaml on a tree already loaded or edited in code (a
  /// --set value, a config after --set): its extent when they pass.
  /// @throws ConfigError "source_name:line: key: problem".
  static Extent CheckTree(const YAML::Node& root, const std::string& source_name);
  /// Limits on the tree after aliases are expanded: every reader of a config
  /// (the Python controller's JSON, --set) walks it recursively.
  static constexpr size_t kMaxValues = 1000000;
  static constexpr int kMaxDepth = 100;

  ConfigNode() = default;  ///< an undefined node
  ConfigNode(YAML::Node node, std::string file, std::string key);
  ConfigNode(const ConfigNode&) = default;
  /// Rebinds to `other`'s node. (YAML::Node's own assignment would overwrite
  /// the node this one points at, silently editing the loaded config.)
  ConfigNode& operator=(const ConfigNode& other) {
    node_.reset(other.node_);
    file_ = other.file_;
    key_ = other.key_;
    line_ = other.line_;
    return *this;
  }

  bool Has(const std::string& key) const;
  /// The child `key`. @throws ConfigError if it is missing.
  ConfigNode Required(const std::string& key) const;
  /// The child `key`, or an undefined node when missing.
  ConfigNode Optional(const std::string& key) const;
  bool IsDefined() const { return node_.IsDefined() && !node_.IsNull(); }
  bool IsSequence() const { return node_.IsSequence(); }
  bool IsMap() const { return node_.IsMap(); }
  size_t size() const { return node_.size(); }
  /// Element `i` of a sequence.
  ConfigNode operator[](size_t i) const;
  /// Map keys in file order.
  std::vector<std::string> Keys() const;

  /// Throws when the map holds a key not in `allowed` (catches typos).
  void RejectUnknownKeys(std::initializer_list<const char*> allowed) const;
  void RejectUnknownKeys(const std::vector<const char*>& allowed) const;

  // Scalar readers: each throws a ConfigError naming the key and the value
  // when the value has the wrong type or is not finite.
  double AsDouble() const;
  long long AsInt() const;
  /// AsInt for an int member: a value past int's range is an error naming
  /// it, never wrapped (4294967336 would otherwise become 40).
  int AsInt32() const;
  bool AsBool() const;
  std::string AsString() const;
  std::vector<double> AsDoubles() const;

  double GetDouble(const std::string& key, double fallback) const;
  long long GetInt(const std::string& key, long long fallback) const;
  int GetInt32(const std::string& key, int fallback) const;
  bool GetBool(const std::string& key, bool fallback) const;
  std::string GetString(const std::string& key, const std::string& fallback) const;
  /// The value `choices` gives the name at `key` (`fallback` when absent).
  /// @throws ConfigError at the key, "unknown <what> '<name>'; allowed: <names>".
  template <typename Value>
  Value GetChoice(const std::string& key, const std::string& fallback, const std::string& what,
                  std::initializer_list<std::pair<const char*, Value>> choices) const {
    const std::string name = GetString(key, fallback);
    std::string allowed;
    std::vector<std::string> names;
    for (const auto& [choice, value] : choices) {
      if (name == choice) return value;
      allowed += (allowed.empty() ? "" : ", ") + std::string(choice);
      names.emplace_back(choice);
    }
    Required(key).Fail("unknown " + what + " '" + name + "'" + DidYouMean(name, names) + "; allowed: " + allowed);
  }

  /// A ConfigError for this node: "file:line: key: message".
  [[noreturn]] void Fail(const std::string& message) const;
  /// Fail at `key`'s line when this map has `key`, else here (a default
  /// value is at fault, or the key's parent is the nearest line).
  [[noreturn]] void FailAt(const std::string& key, const std::string& message) const;
  /// For a params struct's IsValid() message, which starts with the field at
  /// fault ("gain must be > 0, got -1"): "file:line: controller.gain: must be
  /// > 0, got -1" when this map has that key, else the whole message here.
  [[noreturn]] void FailAtField(const std::string& error) const;

  const std::string& file() const { return file_; }
  const std::string& key() const { return key_; }
  const YAML::Node& yaml() const { return node_; }
  /// 1-based line of this node (of its parent when the key is missing), 0 when unknown.
  int line() const { return line_; }

 private:
  std::string Where() const;
  std::string ScalarText() const;
  /// The text of map key `key` of this node. @throws ConfigError when the key is not plain text.
  std::string KeyText(const YAML::Node& key) const;

  YAML::Node node_;
  std::string file_;
  std::string key_;
  int line_ = 0;  // 1-based line of this node, or of its parent when missing
};

}  // namespace dream::config
