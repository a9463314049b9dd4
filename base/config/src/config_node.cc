#include "dream/config/config_node.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <yaml-cpp/eventhandler.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <sstream>
#include <unordered_map>
#include <utility>

namespace dream::config {
namespace {

// A config file is small and local: reading it never takes this long.
constexpr std::chrono::seconds kReadTimeout{10};

// What a message says a value is: "'text'", "a list", "a mapping".
std::string Describe(const YAML::Node& node) {
  if (node.IsScalar()) return "'" + node.Scalar() + "'";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a mapping";
  return "nothing";
}

// Records where the second document starts; ignores everything else.
class DocumentCounter : public YAML::EventHandler {
 public:
  int documents = 0;
  int second_line = 0;  // 1-based; 0 when there is no second document

  void OnDocumentStart(const YAML::Mark& mark) override {
    if (++documents == 2) second_line = mark.line + 1;
  }
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
  void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
  void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t, const std::string&) override {}
  void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
  void OnSequenceEnd() override {}
  void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t, YAML::EmitterStyle::value) override {}
  void OnMapEnd() override {}
};

// yaml-cpp's Load reads the first document and drops the rest without a
// word; one file is one run, so anything after it is a mistake (two configs
// pasted together, a stray "---").
void RejectSecondDocument(const std::string& text, const std::string& source_name) {
  std::istringstream in(text);
  YAML::Parser parser(in);
  DocumentCounter counter;
  try {
    while (counter.documents < 2 && parser.HandleNextDocument(counter)) {
    }
  } catch (const YAML::Exception& e) {
    // The first document parsed already, so the error is past it.
    if (counter.second_line == 0) {
      throw ConfigError(source_name + ":" + std::to_string(e.mark.line + 1) + ": not valid YAML: " + e.msg);
    }
  }
  if (counter.second_line > 0) {
    throw ConfigError(source_name + ":" + std::to_string(counter.second_line) +
                      ": a second YAML document (---) is not read; one run per file");
  }
}

// One walk over the loaded tree for what yaml-cpp does not check: duplicate
// keys (it keeps both entries and lookups find the first), keys that are not
// text, and aliases. An alias shares its anchor's node, so a tree can contain
// itself (`&a [*a]`) or be exponentially larger than its file; containers
// already walked are not walked again but their expanded size still counts.
class TreeCheck {
 public:
  explicit TreeCheck(const std::string& file) : file_(file) {}

  ConfigNode::Extent Run(const YAML::Node& root) { return Visit(root, "", 0); }

 private:
  using Extent = ConfigNode::Extent;

  [[noreturn]] void Fail(const YAML::Node& node, const std::string& key, const std::string& message) const {
    ConfigNode(node, file_, key).Fail(message);
  }

  Extent Visit(const YAML::Node& node, const std::string& key, int depth) {
    if (!node.IsMap() && !node.IsSequence()) return Extent{};
    for (const YAML::Node& open : open_) {
      if (open.is(node)) Fail(node, key, "contains itself through an alias (*); write the value out instead");
    }
    if (const Extent* seen = Walked(node)) {
      if (depth + seen->height > ConfigNode::kMaxDepth) FailTooDeep(node, key);
      return *seen;
    }
    if (depth > ConfigNode::kMaxDepth) FailTooDeep(node, key);
    open_.push_back(node);
    Extent extent;
    auto add = [&](const Extent& child) {
      extent.values += child.values;
      extent.height = std::max(extent.height, child.height + 1);
      if (extent.values > ConfigNode::kMaxValues) {
        Fail(node, key,
             "aliases (*) expand this value to more than " + std::to_string(ConfigNode::kMaxValues) +
                 " values; write it out without them");
      }
    };
    if (node.IsSequence()) {
      for (size_t i = 0; i < node.size(); ++i) add(Visit(node[i], key + "[" + std::to_string(i) + "]", depth + 1));
    } else {
      std::map<std::string, int> first_lines;  // key text -> 1-based line
      for (const auto& entry : node) {
        if (!entry.first.IsScalar()) {
          Fail(entry.first, key, "a key must be plain text, got " + Describe(entry.first));
        }
        const std::string& name = entry.first.Scalar();
        const std::string child_key = key.empty() ? name : key + "." + name;
        const int line = entry.first.Mark().line + 1;
        const auto [first, inserted] = first_lines.emplace(name, line);
        if (!inserted)
          Fail(entry.first, child_key, "duplicate key; first given at line " + std::to_string(first->second));
        add(Visit(entry.second, child_key, depth + 1));
      }
    }
    open_.pop_back();
    // A node made in code (a --set value's copy) has no position, and one
    // copied by YAML::Clone (a sweep's run config) has position 0; only the
    // parser's nodes can be reached again through an alias (and at position 0
    // the parser puts only the root, which no alias can reach), so the others
    // are not kept: they would all share one bucket.
    if (node.Mark().pos > 0) walked_[node.Mark().pos].emplace_back(node, extent);
    return extent;
  }

  // A container reached before (through an alias), or null.
  const Extent* Walked(const YAML::Node& node) const {
    const auto bucket = walked_.find(node.Mark().pos);
    if (bucket == walked_.end()) return nullptr;
    for (const auto& [walked, extent] : bucket->second) {
      if (walked.is(node)) return &extent;
    }
    return nullptr;
  }

  [[noreturn]] void FailTooDeep(const YAML::Node& node, const std::string& key) const {
    Fail(node, key, "nested more than " + std::to_string(ConfigNode::kMaxDepth) + " levels deep");
  }

  const std::string& file_;
  std::vector<YAML::Node> open_;  // the containers being walked: this one's ancestors
  // Walked containers by source position (is() tells nodes at one position apart).
  std::unordered_map<int, std::vector<std::pair<YAML::Node, Extent>>> walked_;
};

}  // namespace

ConfigNode ConfigNode::LoadFile(const std::string& path) { return LoadString(ReadFile(path), path); }

std::string ConfigNode::ReadFile(const std::string& path) {
  // Non-blocking: opening a FIFO for reading would otherwise wait for a
  // writer, deaf to Ctrl-C; what the path is, is then asked of the opened
  // descriptor, so it cannot change between the check and the read.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) {
    throw ConfigError(path + ": cannot open the config file: " + std::strerror(errno) +
                      " (does it exist and is it readable?)");
  }
  struct Closer {
    int fd;
    ~Closer() { ::close(fd); }
  } closer{fd};
  struct stat status {};
  if (::fstat(fd, &status) != 0) throw ConfigError(path + ": cannot read the config file: " + std::strerror(errno));
  if (!S_ISREG(status.st_mode)) {
    const char* kind = S_ISDIR(status.st_mode)    ? "a folder"
                       : S_ISFIFO(status.st_mode) ? "a FIFO (named pipe)"
                       : S_ISCHR(status.st_mode)  ? "a character device"
                       : S_ISBLK(status.st_mode)  ? "a block device"
                       : S_ISSOCK(status.st_mode) ? "a socket"
                                                  : "not a regular file";
    throw ConfigError(path + ": is " + std::string(kind) + ", not a config file; give the path of a YAML file");
  }
  const auto too_large = [&](const std::string& size) {
    return ConfigError(path + ": the config file is " + size + " bytes; a config holds at most " +
                       std::to_string(kMaxFileBytes) + " bytes (is this the right file?)");
  };
  if (static_cast<uint64_t>(status.st_size) > kMaxFileBytes) throw too_large(std::to_string(status.st_size));
  // Read to at most one byte past the limit, whatever the size said (a file
  // may grow, /proc files say 0), and give up past a time limit, checked
  // between reads (a file on a slow mount; a read the kernel itself holds,
  // on a hard network mount, is beyond it).
  std::string text;
  const auto deadline = std::chrono::steady_clock::now() + kReadTimeout;
  char buffer[65536];
  while (true) {
    const ssize_t got = ::read(fd, buffer, sizeof buffer);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw ConfigError(path + ": cannot read the config file: " + std::strerror(errno));
    if (got == 0) break;
    text.append(buffer, static_cast<size_t>(got));
    if (text.size() > kMaxFileBytes) throw too_large("more than " + std::to_string(kMaxFileBytes));
    if (std::chrono::steady_clock::now() > deadline) {
      throw ConfigError(path + ": reading the config file took more than " +
                        std::to_string(std::chrono::duration_cast<std::chrono::seconds>(kReadTimeout).count()) +
                        " s; is it on a mount that does not answer?");
    }
  }
  return text;
}

YAML::Node ConfigNode::ParseYaml(const std::string& text, const std::string& source_name) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw ConfigError(source_name + ":" + std::to_string(e.mark.line + 1) + ": not valid YAML: " + e.msg);
  }
  RejectSecondDocument(text, source_name);
  CheckTree(root, source_name);
  return root;
}

ConfigNode::Extent ConfigNode::CheckTree(const YAML::Node& root, const std::string& source_name) {
  return TreeCheck(source_name).Run(root);
}

ConfigNode ConfigNode::LoadString(const std::string& text, const std::string& source_name) {
  YAML::Node root = ParseYaml(text, source_name);
  if (!root.IsMap()) {
    throw ConfigError(source_name + ": the config must be a YAML mapping of keys (name:, robots:, ...)");
  }
  return ConfigNode(root, source_name, "");
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
  for (const auto& entry : node_) keys.push_back(KeyText(entry.first));
  return keys;
}

void ConfigNode::RejectUnknownKeys(std::initializer_list<const char*> allowed) const {
  RejectUnknownKeys(std::vector<const char*>(allowed));
}

void ConfigNode::RejectUnknownKeys(const std::vector<const char*>& allowed) const {
  if (!node_.IsMap()) Fail("must be a mapping of keys");
  for (const auto& entry : node_) {
    const std::string name = KeyText(entry.first);
    bool known = false;
    std::string list;
    for (const char* a : allowed) {
      known = known || name == a;
      list += (list.empty() ? "" : ", ") + std::string(a);
    }
    if (!known) {
      ConfigNode bad(entry.first, file_, key_.empty() ? name : key_ + "." + name);
      bad.Fail("unknown key" + DidYouMean(name, std::vector<std::string>(allowed.begin(), allowed.end())) +
               "; allowed keys here: " + list);
    }
  }
}

std::string ConfigNode::ScalarText() const { return Describe(node_); }

// ParseYaml refuses such keys already; this covers trees built in code.
std::string ConfigNode::KeyText(const YAML::Node& key) const {
  if (!key.IsScalar()) ConfigNode(key, file_, key_).Fail("a key must be plain text, got " + Describe(key));
  return key.Scalar();
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

int ConfigNode::AsInt32() const {
  const long long value = AsInt();
  if (value > std::numeric_limits<int>::max()) {
    Fail("must be <= " + std::to_string(std::numeric_limits<int>::max()) + ", got " + std::to_string(value));
  }
  if (value < std::numeric_limits<int>::min()) {
    Fail("must be >= " + std::to_string(std::numeric_limits<int>::min()) + ", got " + std::to_string(value));
  }
  return static_cast<int>(value);
}

bool ConfigNode::AsBool() const {
  bool value = false;
  if (!node_.IsScalar() || !YAML::convert<bool>::decode(node_, value)) {
    Fail("expected true or false, got " + ScalarText());
  }
  // yaml-cpp would read "yes" as true; in YAML a quoted value is text.
  if (node_.Tag() == "!") {
    Fail("expected true or false, got the quoted text \"" + node_.Scalar() + "\" (write true or false without quotes)");
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
int ConfigNode::GetInt32(const std::string& key, int fallback) const {
  return Has(key) ? Optional(key).AsInt32() : fallback;
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

void ConfigNode::FailAt(const std::string& key, const std::string& message) const {
  if (Has(key)) Required(key).Fail(message);
  Fail(message);
}

void ConfigNode::FailAtField(const std::string& error) const {
  const size_t space = error.find(' ');
  const std::string field = error.substr(0, space);
  if (space != std::string::npos && Has(field)) Required(field).Fail(error.substr(space + 1));
  Fail(error);
}

}  // namespace dream::config
