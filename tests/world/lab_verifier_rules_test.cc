// The lab verifier's rules (robotarium_matlab_verifier) at their boundaries:
// 100 counts pass and 101 fail, 1.5 x the declared duration, the 900 s cap,
// the declared robot count.
#include "dream/world/lab_verifier_rules.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace dream::world {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::IsEmpty;

std::vector<std::string> Rules(const std::vector<VerdictReason>& reasons) {
  std::vector<std::string> rules;
  for (const VerdictReason& reason : reasons) {
    EXPECT_EQ(reason.verdict, RunVerdict::kRejected) << reason.rule;
    rules.push_back(reason.rule);
  }
  return rules;
}

// 10 robots for 60 s, as the verifier's own config.json declares.
constexpr LabVerifierRules::Declaration kDeclared{10, 60.0};

LabVerifierRules::Counts Passing() {
  LabVerifierRules::Counts counts;
  counts.num_robots = 10;
  counts.iterations = 1000;  // 33 s
  return counts;
}

TEST(LabVerifierRulesTest, AWithinRulesRunPasses) {
  EXPECT_THAT(LabVerifierRules{}.Check(kDeclared, Passing()), IsEmpty());
}

TEST(LabVerifierRulesTest, TooCloseHundredTimesPassesAndHundredAndOneFails) {
  LabVerifierRules::Counts counts = Passing();
  counts.robots_too_close = 100;
  EXPECT_THAT(LabVerifierRules{}.Check(kDeclared, counts), IsEmpty());
  counts.robots_too_close = 101;
  const std::vector<VerdictReason> reasons = LabVerifierRules{}.Check(kDeclared, counts);
  EXPECT_THAT(Rules(reasons), ElementsAre("verifier_too_close"));
  EXPECT_THAT(reasons[0].problem, HasSubstr("101 times"));
  EXPECT_THAT(reasons[0].problem, HasSubstr("more than 100"));
}

TEST(LabVerifierRulesTest, OutsideHundredTimesPassesAndHundredAndOneFails) {
  LabVerifierRules::Counts counts = Passing();
  counts.robots_outside_boundaries = 100;
  EXPECT_THAT(LabVerifierRules{}.Check(kDeclared, counts), IsEmpty());
  counts.robots_outside_boundaries = 101;
  EXPECT_THAT(Rules(LabVerifierRules{}.Check(kDeclared, counts)), ElementsAre("verifier_out_of_bounds"));
}

TEST(LabVerifierRulesTest, LimitsComeFromTheRules) {
  LabVerifierRules rules;
  rules.robots_too_close_limit = 5;
  LabVerifierRules::Counts counts = Passing();
  counts.robots_too_close = 6;
  EXPECT_THAT(Rules(rules.Check(kDeclared, counts)), ElementsAre("verifier_too_close"));
}

TEST(LabVerifierRulesTest, OneAndAHalfTimesTheDeclaredDuration) {
  // 1.5 x 60 s = 90 s: 2727 x 0.033 = 89.991 s passes, 2728 x 0.033 = 90.024 s does not.
  LabVerifierRules::Counts counts = Passing();
  counts.iterations = 2727;
  EXPECT_THAT(LabVerifierRules{}.Check(kDeclared, counts), IsEmpty());
  counts.iterations = 2728;
  const std::vector<VerdictReason> reasons = LabVerifierRules{}.Check(kDeclared, counts);
  EXPECT_THAT(Rules(reasons), ElementsAre("verifier_duration"));
  EXPECT_THAT(reasons[0].problem, HasSubstr("90.02 s, over 1.5 x the declared 60.00 s"));
}

TEST(LabVerifierRulesTest, NineHundredSecondsAtMost) {
  // 27272 x 0.033 = 899.976 s is within the cap, 27273 x 0.033 = 900.009 s is not.
  LabVerifierRules::Counts counts = Passing();
  counts.iterations = 27272;
  const LabVerifierRules::Declaration at_cap{10, 27272 * 0.033};
  EXPECT_THAT(LabVerifierRules{}.Check(at_cap, counts), IsEmpty());
  counts.iterations = 27273;
  const LabVerifierRules::Declaration over_cap{10, 27273 * 0.033};
  EXPECT_THAT(Rules(LabVerifierRules{}.Check(over_cap, counts)), ElementsAre("lab_duration_cap"));
  // A declaration over the cap is refused even when the run itself is short.
  EXPECT_THAT(Rules(LabVerifierRules{}.Check({10, 900.5}, Passing())), ElementsAre("lab_duration_cap"));
}

TEST(LabVerifierRulesTest, DeclaredRobotCountMustMatch) {
  LabVerifierRules::Counts counts = Passing();
  counts.num_robots = 9;
  const std::vector<VerdictReason> reasons = LabVerifierRules{}.Check(kDeclared, counts);
  EXPECT_THAT(Rules(reasons), ElementsAre("verifier_robot_count"));
  EXPECT_THAT(reasons[0].problem, HasSubstr("asks for 9 robots but 10 are declared"));
}

TEST(LabVerifierRulesTest, EveryBrokenRuleIsListed) {
  LabVerifierRules::Counts counts;
  counts.num_robots = 3;
  counts.iterations = 30000;
  counts.robots_too_close = 500;
  counts.robots_outside_boundaries = 200;
  EXPECT_THAT(Rules(LabVerifierRules{}.Check(kDeclared, counts)),
              ElementsAre("verifier_robot_count", "verifier_too_close", "verifier_out_of_bounds", "verifier_duration",
                          "lab_duration_cap"));
}

}  // namespace
}  // namespace dream::world
