// What yaml-cpp accepts without a word and ConfigNode refuses: duplicate
// keys, a second document, keys that are not text, self-containing or
// exploding aliases; and type errors that name file, line and key.
#include "dream/config/config_node.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "../support/scratch_folder.h"
#include "dream/run_config/run_config.h"

namespace dream::config {
namespace {

/// The ConfigError message of loading `text` as test.yaml, or "" if it loads.
std::string ParseError(const std::string& text) {
  try {
    ConfigNode::LoadString(text, "test.yaml");
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

/// The ConfigError message of `read` on the loaded `text`, or "" if it passes.
template <typename Read>
std::string ReadError(const std::string& text, Read read) {
  try {
    read(ConfigNode::LoadString(text, "test.yaml"));
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(ConfigNodeTest, DuplicateTopLevelKeyNamesBothLines) {
  EXPECT_EQ(ParseError("name: a\nrobots: 1\nname: b\n"), "test.yaml:3: name: duplicate key; first given at line 1");
}

TEST(ConfigNodeTest, DuplicateKeysAreFoundAtAnyDepth) {
  EXPECT_EQ(ParseError("controller:\n  kind: go_to_goal\n  gain: 0.8\n  gain: 0.9\n"),
            "test.yaml:4: controller.gain: duplicate key; first given at line 3");
  EXPECT_EQ(ParseError("obstacles:\n  - center: [0, 0]\n    size: [1, 1]\n  - center: [1, 0]\n    center: [2, 0]\n"),
            "test.yaml:5: obstacles[1].center: duplicate key; first given at line 4");
  EXPECT_EQ(ParseError("world: {mode: lockstep, mode: realtime}\n"),
            "test.yaml:1: world.mode: duplicate key; first given at line 1");
  // Quoting does not make it another key: the lookup finds the first either way.
  EXPECT_EQ(ParseError("seed: 1\n'seed': 2\n"), "test.yaml:2: seed: duplicate key; first given at line 1");
}

TEST(ConfigNodeTest, SameKeyInDifferentMapsIsNotADuplicate) {
  const ConfigNode root = ConfigNode::LoadString(
      "obstacles:\n  - {center: [0, 0], size: [1, 1]}\n  - {center: [1, 0], size: [1, 1]}\n", "test.yaml");
  EXPECT_EQ(root.Required("obstacles")[1].Required("center").AsDoubles(), (std::vector<double>{1.0, 0.0}));
}

TEST(ConfigNodeTest, SecondDocumentIsAnErrorAtItsSeparator) {
  const std::string expected = "test.yaml:3: a second YAML document (---) is not read; one run per file";
  EXPECT_EQ(ParseError("name: a\nrobots: 1\n---\nname: b\n"), expected);
  // An empty one after a trailing separator too: the file is not what it looks like.
  EXPECT_EQ(ParseError("name: a\nrobots: 1\n---\n"), expected);
  // The second document is named even when it is broken YAML itself.
  EXPECT_EQ(ParseError("name: a\nrobots: 1\n--- [unclosed\n"), expected);
}

TEST(ConfigNodeTest, OneDocumentWithMarkersLoads) {
  EXPECT_EQ(ParseError("---\nname: a\n"), "");
  EXPECT_EQ(ParseError("%YAML 1.2\n---\nname: a\n...\n# the end\n"), "");
  EXPECT_EQ(ConfigNode::LoadString("---\nname: a\n...\n", "test.yaml").Required("name").AsString(), "a");
}

TEST(ConfigNodeTest, KeysMustBePlainText) {
  EXPECT_EQ(ParseError("name: a\n{x: 1}: 2\n"), "test.yaml:2: (top level): a key must be plain text, got a mapping");
  EXPECT_EQ(ParseError("controller:\n  ? [a, b]\n  : 1\n"),
            "test.yaml:2: controller: a key must be plain text, got a list");
  // A tree built in code (dream sweep edits one) is checked where its keys are read.
  YAML::Node built(YAML::NodeType::Map);
  built[YAML::Load("[a, b]")] = 1;
  const ConfigNode node(built, "built.yaml", "controller");
  try {
    node.Keys();
    FAIL() << "a list key was read as text";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("built.yaml"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("controller: a key must be plain text, got a list"), std::string::npos)
        << e.what();
  }
}

TEST(ConfigNodeTest, AliasesThatRepeatAValueLoad) {
  const ConfigNode root = ConfigNode::LoadString(
      "obstacles:\n  - {center: [0, 0], size: &block [0.2, 0.2]}\n  - {center: [1, 0], size: *block}\n", "test.yaml");
  EXPECT_EQ(root.Required("obstacles")[1].Required("size").AsDoubles(), (std::vector<double>{0.2, 0.2}));
}

TEST(ConfigNodeTest, AliasThatContainsItselfIsAnError) {
  // Every recursive reader (the Python controller's JSON) would never end.
  const std::string error = ParseError("controller: &c\n  kind: python\n  again: *c\n");
  // The line is the anchor's (yaml-cpp keeps no line for an alias), the key the alias's.
  EXPECT_NE(error.find("test.yaml:1: controller.again: contains itself through an alias"), std::string::npos) << error;
  EXPECT_NE(ParseError("a: &l [1, *l]\n").find("a[1]: contains itself through an alias"), std::string::npos);
}

TEST(ConfigNodeTest, AliasesThatExplodeAreAnError) {
  // Ten times ten times ... : 10^8 values from a 300-byte file.
  std::string text = "l0: &l0 [x, x, x, x, x, x, x, x, x, x]\n";
  for (int i = 1; i <= 8; ++i) {
    const std::string prev = "*l" + std::to_string(i - 1);
    std::string row = "l" + std::to_string(i) + ": &l" + std::to_string(i) + " [";
    for (int k = 0; k < 10; ++k) row += (k ? ", " : "") + prev;
    text += row + "]\n";
  }
  const std::string error = ParseError(text);
  EXPECT_NE(error.find("aliases (*) expand this value to more than 1000000 values"), std::string::npos) << error;
  // Up to l4 (111,111 values) it loads: large lists written with aliases stay allowed.
  EXPECT_EQ(ParseError(text.substr(0, text.find("l5:"))), "");
}

TEST(ConfigNodeTest, NestingIsBounded) {
  const std::string deep =
      "a: " + std::string(ConfigNode::kMaxDepth + 5, '[') + std::string(ConfigNode::kMaxDepth + 5, ']');
  EXPECT_NE(ParseError(deep).find("nested more than 100 levels deep"), std::string::npos) << ParseError(deep);
  const std::string fine =
      "a: " + std::string(ConfigNode::kMaxDepth - 1, '[') + std::string(ConfigNode::kMaxDepth - 1, ']');
  EXPECT_EQ(ParseError(fine), "");
}

/// The ConfigError message of ConfigNode::ReadFile(path), or "" if it reads.
std::string ReadFileError(const std::string& path) {
  try {
    ConfigNode::ReadFile(path);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(ConfigNodeTest, OnlyARegularFileOfBoundedSizeIsReadAsAConfig) {
  testing::ScratchFolder folder("config_read_file");
  const std::string fifo = (folder.path() / "config.yaml").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // Before: opening the FIFO waited for a writer forever (this test hung).
  EXPECT_EQ(ReadFileError(fifo), fifo + ": is a FIFO (named pipe), not a config file; give the path of a YAML file");
  // Before: read 2 GB, then std::bad_alloc.
  EXPECT_EQ(ReadFileError("/dev/zero"),
            "/dev/zero: is a character device, not a config file; give the path of a YAML file");
  EXPECT_EQ(ReadFileError(folder.path().string()),
            folder.path().string() + ": is a folder, not a config file; give the path of a YAML file");
  const std::string large = (folder.path() / "large.yaml").string();
  std::ofstream(large) << "name: x\n";
  std::filesystem::resize_file(large, ConfigNode::kMaxFileBytes + 1);  // sparse: no disk used
  EXPECT_EQ(ReadFileError(large), large +
                                      ": the config file is 16777217 bytes; a config holds at most 16777216 bytes "
                                      "(is this the right file?)");
  std::filesystem::resize_file(large, ConfigNode::kMaxFileBytes);
  EXPECT_EQ(ConfigNode::ReadFile(large).size(), ConfigNode::kMaxFileBytes);
  const std::string missing = (folder.path() / "missing.yaml").string();
  EXPECT_EQ(ReadFileError(missing), missing +
                                        ": cannot open the config file: No such file or directory (does it "
                                        "exist and is it readable?)");
}

TEST(ConfigNodeTest, EveryScalarReaderNamesFileLineKeyAndWhatItGot) {
  const std::string text = "list: [1, 2]\nmap: {a: 1}\nword: many\nnumber: 2.5\n";
  struct Case {
    const char* key;
    std::string (*read)(const ConfigNode&);
    const char* expected;
  };
  const Case cases[] = {
      {"list", [](const ConfigNode& n) { return std::to_string(n.AsDouble()); },
       "test.yaml:1: list: expected a number, got a list"},
      {"map", [](const ConfigNode& n) { return std::to_string(n.AsDouble()); },
       "test.yaml:2: map: expected a number, got a mapping"},
      {"word", [](const ConfigNode& n) { return std::to_string(n.AsDouble()); },
       "test.yaml:3: word: expected a number, got 'many'"},
      {"list", [](const ConfigNode& n) { return std::to_string(n.AsInt()); },
       "test.yaml:1: list: expected a whole number, got a list"},
      {"number", [](const ConfigNode& n) { return std::to_string(n.AsInt()); },
       "test.yaml:4: number: expected a whole number, got '2.5'"},
      {"map", [](const ConfigNode& n) { return std::to_string(n.AsBool()); },
       "test.yaml:2: map: expected true or false, got a mapping"},
      {"word", [](const ConfigNode& n) { return std::to_string(n.AsBool()); },
       "test.yaml:3: word: expected true or false, got 'many'"},
      {"list", [](const ConfigNode& n) { return n.AsString(); }, "test.yaml:1: list: expected text, got a list"},
      {"map", [](const ConfigNode& n) { return n.AsString(); }, "test.yaml:2: map: expected text, got a mapping"},
      {"map", [](const ConfigNode& n) { return std::to_string(n.AsDoubles().size()); },
       "test.yaml:2: map: expected a list of numbers like [0.5, -0.2], got a mapping"},
      {"number", [](const ConfigNode& n) { return std::to_string(n.AsDoubles().size()); },
       "test.yaml:4: number: expected a list of numbers like [0.5, -0.2], got '2.5'"},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(ReadError(text, [&c](const ConfigNode& root) { c.read(root.Required(c.key)); }), c.expected) << c.key;
  }
  // An element of a list names its index and its own line.
  EXPECT_EQ(ReadError("xs:\n  - 1\n  - [2]\n", [](const ConfigNode& root) { root.Required("xs").AsDoubles(); }),
            "test.yaml:3: xs[1]: expected a number, got a list");
}

TEST(ConfigNodeTest, AQuotedValueIsTextNotAFlag) {
  // yaml-cpp reads "yes" (quoted) as true; YAML says a quoted value is text.
  const std::string text = "quoted: \"yes\"\nsingle: 'true'\nplain: true\nword: no\n";
  EXPECT_EQ(ReadError(text, [](const ConfigNode& root) { root.GetBool("quoted", false); }),
            "test.yaml:1: quoted: expected true or false, got the quoted text \"yes\" (write true or false without "
            "quotes)");
  EXPECT_EQ(ReadError(text, [](const ConfigNode& root) { root.GetBool("single", false); }),
            "test.yaml:2: single: expected true or false, got the quoted text \"true\" (write true or false without "
            "quotes)");
  const ConfigNode root = ConfigNode::LoadString(text, "test.yaml");
  EXPECT_TRUE(root.GetBool("plain", false));
  EXPECT_FALSE(root.GetBool("word", true));  // YAML 1.1's words, plain, are still flags
}

TEST(ConfigNodeTest, Int32ReadersRefuseWhatIntCannotHold) {
  const std::string text = "big: 4294967336\nlow: -2147483649\nmax: 2147483647\n";
  EXPECT_EQ(ReadError(text, [](const ConfigNode& root) { root.GetInt32("big", 0); }),
            "test.yaml:1: big: must be <= 2147483647, got 4294967336");
  EXPECT_EQ(ReadError(text, [](const ConfigNode& root) { root.Required("low").AsInt32(); }),
            "test.yaml:2: low: must be >= -2147483648, got -2147483649");
  const ConfigNode root = ConfigNode::LoadString(text, "test.yaml");
  EXPECT_EQ(root.GetInt32("max", 0), 2147483647);
  EXPECT_EQ(root.GetInt32("absent", -7), -7);
}

TEST(ConfigNodeTest, RunConfigTypeErrorsNeverShowYamlCppText) {
  const std::string base =
      "name: demo\ndescription: free text\nrobots: 2\nsteps: 100\nstop_when_done: true\nworld: {agent_timeout_s: 2.0}\n"
      "initial_poses:\n  - [0.0, 0.0, 0.0]\n  - [0.5, 0.0, 1.57]\n"
      "obstacles:\n  - {center: [1.0, 0.5], size: [0.2, 0.2]}\ncontroller: {kind: go_to_goal}\n";
  // Each scalar of the file replaced by a list, then by a mapping: the error
  // is ConfigNode's, with file and line, never yaml-cpp's "bad conversion".
  const char* scalars[] = {"demo", "free text", "2", "100", "true", "2.0", "0.5", "1.57", "1.0"};
  for (const char* scalar : scalars) {
    for (const char* replacement : {"[1, 2]", "{a: 1}"}) {
      std::string text = base;
      const size_t at = text.find(scalar);
      ASSERT_NE(at, std::string::npos) << scalar;
      text.replace(at, std::string(scalar).size(), replacement);
      const std::string error = ReadError(text, [](const ConfigNode& root) { run_config::LoadRunConfig(root); });
      EXPECT_EQ(error.rfind("test.yaml:", 0), 0u) << scalar << " -> " << replacement << ": " << error;
      EXPECT_NE(error.find(std::string(", got ") + (replacement[0] == '[' ? "a list" : "a mapping")), std::string::npos)
          << scalar << " -> " << replacement << ": " << error;
      EXPECT_EQ(error.find("bad conversion"), std::string::npos) << error;
    }
  }
}

TEST(ConfigNodeTest, GetChoiceGivesTheNamedValueOrTheFallbackAndNamesTheAllowedNames) {
  enum class Mode { kLoop, kPingPong };
  const auto choose = [](const ConfigNode& node) {
    return node.GetChoice<Mode>("mode", "loop", "path mode", {{"loop", Mode::kLoop}, {"ping_pong", Mode::kPingPong}});
  };
  EXPECT_EQ(choose(ConfigNode::LoadString("mode: ping_pong\n", "test.yaml")), Mode::kPingPong);
  EXPECT_EQ(choose(ConfigNode::LoadString("other: 1\n", "test.yaml")), Mode::kLoop);
  EXPECT_EQ(ReadError("other: 1\nmode: bounce\n", [&choose](const ConfigNode& root) { choose(root); }),
            "test.yaml:2: mode: unknown path mode 'bounce'; allowed: loop, ping_pong");
}

TEST(ConfigNodeTest, FailAtPointsAtTheKeyWhenItIsThereElseAtTheMap) {
  const std::string text = "robot:\n  kind: x\n  gain: -1\n";
  const auto fail_at = [](const std::string& key) {
    return [key](const ConfigNode& root) { root.Required("robot").FailAt(key, "bad"); };
  };
  EXPECT_EQ(ReadError(text, fail_at("gain")), "test.yaml:3: robot.gain: bad");
  EXPECT_EQ(ReadError(text, fail_at("speed")), "test.yaml:2: robot: bad");
}

// A params struct's IsValid() message starts with the field at fault.
TEST(ConfigNodeTest, FailAtFieldNamesTheFieldsKeyAndLineOrKeepsTheWholeMessage) {
  const std::string text = "robot:\n  kind: x\n  gain: -1\n";
  const auto fail_at_field = [](const std::string& error) {
    return [error](const ConfigNode& root) { root.Required("robot").FailAtField(error); };
  };
  EXPECT_EQ(ReadError(text, fail_at_field("gain must be > 0, got -1")), "test.yaml:3: robot.gain: must be > 0, got -1");
  // A default value at fault (no such key here), or a message about no one field.
  EXPECT_EQ(ReadError(text, fail_at_field("tolerance_m must be > 0, got 0")),
            "test.yaml:2: robot: tolerance_m must be > 0, got 0");
  EXPECT_EQ(ReadError(text, fail_at_field("gain")), "test.yaml:2: robot: gain");
}

}  // namespace
}  // namespace dream::config
