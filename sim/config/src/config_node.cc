#include "dream/config/config_node.h"

#include <cmath>
#include <fstream>
#include <sstream>

namespace dream::config {

ConfigNode ConfigNode::LoadFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) {
    throw ConfigError(path + ": cannot open the config file (does it exist and is it readable?)");
  }
  std::stringstream text;
  text << in.rdbuf();
  return LoadString(text.str(), path);
}

ConfigNode ConfigNode::LoadString(const std::string& text, const std::string& source_name) {
  try {
    YAML::Node root = YAML::Load(text);
    if (!root.IsMap()) {
      throw ConfigError(source_name + ": the config must be a YAML mapping of keys (name:, robots:, ...)");
    }
    return ConfigNode(root, source_name, "");
  } catch (const YAML::ParserException& e) {
    throw ConfigError(source_name + ":" + std::to_string(e.mark.line + 1) + ": not valid YAML: " + e.msg);
  }
}

ConfigNode::ConfigNode(YAML::Node node, std::string file, std::string key)
    : node_(std::move(node)), file_(std::move(file)), key_(std::move(key)) {
  if (node_.IsDefined() && node_.Mark().line >= 0) line_ = node_.Mark().line + 1;
}

bool ConfigNode::Has(const std::string& key) const {
  return node_.IsMap() && node_[key].IsDefined() && !node_[key].IsNull();
}

ConfigNode ConfigNode::Optional(const std::string& key) const {
  const std::string child_key = key_.empty() ? key : key_ + "." + key;
  if (!node_.IsMap()) {
    ConfigNode missing(YAML::Node(YAML::NodeType::Undefined), file_, child_key);
    missing.line_ = line_;
    return missing;
  }
  ConfigNode child(node_[key], file_, child_key);
  if (!child.IsDefined()) child.line_ = line_;
  return child;
}

ConfigNode ConfigNode::Required(const std::string& key) const {
  ConfigNode child = Optional(key);
  if (!child.IsDefined()) child.Fail("missing; this key is required");
  return child;
}

ConfigNode ConfigNode::operator[](size_t i) const {
  return ConfigNode(node_[i], file_, key_ + "[" + std::to_string(i) + "]");
}

std::vector<std::string> ConfigNode::Keys() const {
  std::vector<std::string> keys;
  if (!node_.IsMap()) return keys;
  for (const auto& entry : node_) keys.push_back(entry.first.as<std::string>());
  return keys;
}

void ConfigNode::RejectUnknownKeys(std::initializer_list<const char*> allowed) const {
  if (!node_.IsMap()) Fail("must be a mapping of keys");
  for (const auto& entry : node_) {
    const std::string name = entry.first.as<std::string>();
    bool known = false;
    std::string list;
    for (const char* a : allowed) {
      known = known || name == a;
      list += (list.empty() ? "" : ", ") + std::string(a);
    }
    if (!known) {
      ConfigNode bad(entry.first, file_, key_.empty() ? name : key_ + "." + name);
      bad.Fail("unknown key; allowed keys here: " + list);
    }
  }
}

std::string ConfigNode::ScalarText() const {
  if (node_.IsScalar()) return "'" + node_.Scalar() + "'";
  if (node_.IsSequence()) return "a list";
  if (node_.IsMap()) return "a mapping";
  return "nothing";
}

double ConfigNode::AsDouble() const {
  double value = 0.0;
  if (!node_.IsScalar() || !YAML::convert<double>::decode(node_, value)) {
    Fail("expected a number, got " + ScalarText());
  }
  if (!std::isfinite(value)) Fail("expected a finite number, got " + ScalarText());
  return value;
}

long long ConfigNode::AsInt() const {
  long long value = 0;
  if (!node_.IsScalar() || !YAML::convert<long long>::decode(node_, value)) {
    Fail("expected a whole number, got " + ScalarText());
  }
  return value;
}

bool ConfigNode::AsBool() const {
  bool value = false;
  if (!node_.IsScalar() || !YAML::convert<bool>::decode(node_, value)) {
    Fail("expected true or false, got " + ScalarText());
  }
  return value;
}

std::string ConfigNode::AsString() const {
  if (!node_.IsScalar()) Fail("expected text, got " + ScalarText());
  return node_.Scalar();
}

std::vector<double> ConfigNode::AsDoubles() const {
  if (!node_.IsSequence()) Fail("expected a list of numbers like [0.5, -0.2], got " + ScalarText());
  std::vector<double> values;
  for (size_t i = 0; i < node_.size(); ++i) values.push_back((*this)[i].AsDouble());
  return values;
}

double ConfigNode::GetDouble(const std::string& key, double fallback) const {
  return Has(key) ? Optional(key).AsDouble() : fallback;
}
long long ConfigNode::GetInt(const std::string& key, long long fallback) const {
  return Has(key) ? Optional(key).AsInt() : fallback;
}
bool ConfigNode::GetBool(const std::string& key, bool fallback) const {
  return Has(key) ? Optional(key).AsBool() : fallback;
}
std::string ConfigNode::GetString(const std::string& key, const std::string& fallback) const {
  return Has(key) ? Optional(key).AsString() : fallback;
}

std::string ConfigNode::Where() const {
  std::string where = file_;
  if (line_ > 0) where += ":" + std::to_string(line_);
  return where + ": " + (key_.empty() ? std::string("(top level)") : key_);
}

void ConfigNode::Fail(const std::string& message) const { throw ConfigError(Where() + ": " + message); }

}  // namespace dream::config
