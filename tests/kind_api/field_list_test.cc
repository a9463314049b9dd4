// Issue 24: each key of a params struct is named once, in its field list, and
// reading, the allowed keys, the checks with their errors and the docs' key
// table all come from that list.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "dream/agent_host/controller_registry.h"
#include "dream/kind_api/field_reader.h"
#include "dream/agents/fields/field_check.h"
#include "dream/agents/fields/field_names.h"
#include "dream/agents/fields/field_rule.h"
#include "dream/agents/fields/field_table.h"
#include "dream/config/config_error.h"
#include "dream/config/config_node.h"
#include "dream/files/file_text.h"
#include "../support/source_tree.h"

namespace dream::kind_api {
namespace {

using ::testing::HasSubstr;

enum class Shape { kRound, kSquare };

struct Inner {
  double depth_m = 0.5;
  template <typename Fields>
  void ListFields(Fields& fields) {
    fields.Number("depth_m", depth_m, agents::FieldRule::NonNegative(), "how deep, m");
  }
};

struct Example {
  double gain = 0.8;
  int count = 3;
  bool loud = false;
  Shape shape = Shape::kRound;
  Inner inner;
  template <typename Fields>
  void ListFields(Fields& fields) {
    fields.Number("gain", gain, agents::FieldRule::Positive(), "proportional gain, 1/s");
    fields.Whole("count", count, agents::FieldRule::Within(1, 10), "how many");
    fields.Flag("loud", loud, "speak up");
    fields.Choice("shape", shape, {{"round", Shape::kRound}, {"square", Shape::kSquare}}, "shape");
    fields.Section("inner", inner, "the inner part");
  }
};

config::ConfigNode Yaml(const std::string& text) { return config::ConfigNode::LoadString(text, "test.yaml"); }

std::string ReadError(const std::string& text) {
  try {
    Example example;
    ReadFields(Yaml(text), 1, &example);
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(FieldListTest, OneListGivesTheKeysInOrder) {
  EXPECT_EQ(agents::KeysOf<Example>(), (std::vector<std::string>{"gain", "count", "loud", "shape", "inner"}));
}

TEST(FieldListTest, ReadingReplacesDefaultsOnlyWhereTheSectionSaysSo) {
  Example example;
  ReadFields(Yaml("gain: 2.5\nshape: square\ninner: {depth_m: 0}\n"), 1, &example);
  EXPECT_EQ(example.gain, 2.5);
  EXPECT_EQ(example.count, 3);
  EXPECT_EQ(example.shape, Shape::kSquare);
  EXPECT_EQ(example.inner.depth_m, 0.0);
}

TEST(FieldListTest, ReadingRefusesWhatBreaksTheRuleNamingKeyAndValue) {
  EXPECT_THAT(ReadError("gain: -1\n"), HasSubstr("gain: must be > 0, got -1"));
  EXPECT_THAT(ReadError("gain: .nan\n"), HasSubstr("gain: expected a finite number"));
  EXPECT_THAT(ReadError("count: 11\n"), HasSubstr("count: must be in 1..10, got 11"));
  EXPECT_THAT(ReadError("count: 4294967297\n"), HasSubstr("count"));  // not wrapped to 1
  EXPECT_THAT(ReadError("shape: sqare\n"),
              HasSubstr("unknown shape 'sqare' (did you mean 'square'?); allowed: round, square"));
  EXPECT_THAT(ReadError("inner: {depth_m: -0.1}\n"), HasSubstr("depth_m: must be >= 0, got -0.1"));
  EXPECT_THAT(ReadError("inner: {dept_m: 1}\n"), HasSubstr("dept_m"));
}

TEST(FieldListTest, CheckingParamsGivesTheFirstBrokenRule) {
  Example example;
  std::string error;
  EXPECT_TRUE(agents::CheckFields(example, &error)) << error;
  example.inner.depth_m = -2.0;
  EXPECT_FALSE(agents::CheckFields(example, &error));
  EXPECT_EQ(error, "inner.depth_m must be >= 0, got -2");
  example.gain = 0.0;
  EXPECT_FALSE(agents::CheckFields(example, &error));
  EXPECT_EQ(error, "gain must be > 0, got 0");
}

TEST(FieldListTest, TheTableShowsDefaultsAndRules) {
  EXPECT_EQ(agents::KeyTableOf<Example>(),
            "| `gain` | 0.8 | proportional gain, 1/s, > 0 |\n"
            "| `count` | 3 | how many, in 1..10 |\n"
            "| `loud` | false | speak up |\n"
            "| `shape` | `round` | shape: `round`, `square` |\n"
            "| `inner.depth_m` | 0.5 | how deep, m, >= 0 |\n");
}

TEST(FieldListTest, RulesSayWhatTheyHold) {
  EXPECT_EQ(agents::FieldRule::RobotSpeed().Text(), "in (0, 0.2]");
  EXPECT_TRUE(agents::FieldRule::RobotSpeed().Holds(0.2));
  EXPECT_FALSE(agents::FieldRule::RobotSpeed().Holds(0.0));
  EXPECT_TRUE(agents::FieldRule::PositiveOrInfinite().Holds(1.0 / 0.0));
  EXPECT_FALSE(agents::FieldRule::Positive().Holds(1.0 / 0.0));
  EXPECT_FALSE(agents::FieldRule::PositiveOrInfinite().Holds(0.0 / 0.0));
}

// The key tables of config/README.md are what the kinds' field lists say:
// change a default, a rule or a meaning in code and this fails until the
// docs say the same (the rows to paste are in the message).
TEST(FieldListTest, ConfigReadmeShowsEveryKindsGeneratedKeyTable) {
  const std::string readme = files::ReadFileText(dream::testing::SourceDir() + "/config/README.md");
  const agent_host::ControllerRegistry& registry = agent_host::ControllerRegistry::BuiltIns();
  int tables = 0;
  for (const std::string& name : registry.Names()) {
    const ControllerKind* kind = registry.Find(name);
    if (!kind->key_table) continue;
    ++tables;
    const std::string rows = kind->key_table();
    EXPECT_NE(readme.find("| key | default | meaning |\n|---|---|---|\n" + rows), std::string::npos)
        << "config/README.md's table for kind " << name << " must be, verbatim:\n"
        << "| key | default | meaning |\n|---|---|---|\n"
        << rows;
  }
  EXPECT_GE(tables, 5) << "the built-in kinds with field lists";
}

}  // namespace
}  // namespace dream::kind_api
