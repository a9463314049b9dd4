// DidYouMean: the fix for a typo in a key, kind or choice, and nothing when
// the given name is not close to any.
#include "dream/config/name_suggestion.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "dream/config/config_error.h"
#include "dream/config/config_node.h"

namespace dream::config {
namespace {

const std::vector<std::string> kKeys = {"spacing_m", "gain", "max_speed_mps", "tolerance_m", "resume_m"};

TEST(NameSuggestionTest, ATypoGetsTheClosestName) {
  EXPECT_EQ(DidYouMean("tolerence_m", kKeys), " (did you mean 'tolerance_m'?)");     // a letter wrong
  EXPECT_EQ(DidYouMean("max_sped_mps", kKeys), " (did you mean 'max_speed_mps'?)");  // one missing
  EXPECT_EQ(DidYouMean("gian", kKeys), " (did you mean 'gain'?)");                   // two swapped
  EXPECT_EQ(DidYouMean("Spacing_M", kKeys), " (did you mean 'spacing_m'?)");         // case
  EXPECT_EQ(DidYouMean("spacing", kKeys), " (did you mean 'spacing_m'?)");           // the start of one
  EXPECT_EQ(DidYouMean("hrvo_cirlce", {"go_to_goal", "hrvo_circle", "line_deployment"}),
            " (did you mean 'hrvo_circle'?)");
}

TEST(NameSuggestionTest, NothingCloseGetsNoSuggestion) {
  EXPECT_EQ(DidYouMean("bogus", kKeys), "");
  EXPECT_EQ(DidYouMean("gxyz", kKeys), "");  // short names allow one edit only
  EXPECT_EQ(DidYouMean("", kKeys), "");
  EXPECT_EQ(DidYouMean("ga", kKeys), "");    // too short to be taken for the start of "gain"
  EXPECT_EQ(DidYouMean("gain", kKeys), "");  // a known name needs no suggestion
  EXPECT_EQ(DidYouMean(std::string(10000, 'g'), kKeys), "");
  EXPECT_EQ(DidYouMean("gain", {}), "");
}

TEST(NameSuggestionTest, ConfigErrorsCarryIt) {
  const ConfigNode node = ConfigNode::LoadString("section:\n  tolerence_m: 0.1\n  mode: fsat\n", "test.yaml");
  const ConfigNode section = node.Required("section");
  try {
    section.RejectUnknownKeys({"tolerance_m", "mode"});
    FAIL() << "an unknown key was accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()),
              "test.yaml:2: section.tolerence_m: unknown key (did you mean 'tolerance_m'?); allowed keys here: "
              "tolerance_m, mode");
  }
  try {
    section.GetChoice<int>("mode", "fast", "mode", {{"fast", 1}, {"slow", 2}});
    FAIL() << "an unknown choice was accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(std::string(e.what()),
              "test.yaml:3: section.mode: unknown mode 'fsat' (did you mean 'fast'?); allowed: fast, slow");
  }
}

}  // namespace
}  // namespace dream::config
