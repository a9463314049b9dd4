// summary.json's violations_located: each kind's fields, the bound, the rest counted.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "dream/node/run_summary.h"

namespace dream::node {
namespace {

using Kind = world::LocatedViolation::Kind;

TEST(ViolationsLocatedJsonTest, EachKindNamesItsRobotsStepsAndPosition) {
  world::LocatedViolations located;
  located.listed.push_back({Kind::kCollision, 2, 5, 120, 134, 0.25, -0.5, 0.09});
  located.listed.push_back({Kind::kObstacle, 3, 7, 140, 140, 1.0, 0.0, 0.01});
  located.listed.push_back({Kind::kBoundary, 4, -1, 150, 160, 1.61, 0.2});  // worst not measured: left out
  located.unlisted = 12;
  const nlohmann::json json = nlohmann::json::parse(ViolationsLocatedJson(located, 3).dump());
  EXPECT_EQ(json, nlohmann::json::parse(R"({
    "listed": [
      {"kind": "collision", "robots": [2, 5], "first_step": 120, "last_step": 134, "position": [0.25, -0.5],
       "closest_m": 0.09},
      {"kind": "obstacle", "robots": [3], "obstacle": 7, "first_step": 140, "last_step": 140, "position": [1.0, 0.0],
       "worst_overlap_m": 0.01},
      {"kind": "boundary", "robots": [4], "first_step": 150, "last_step": 160, "position": [1.61, 0.2]}
    ],
    "unlisted": 12,
    "max_listed": 3})"));
}

TEST(ViolationsLocatedJsonTest, ACleanRunListsNone) {
  EXPECT_EQ(nlohmann::json::parse(ViolationsLocatedJson({}, 100).dump()),
            nlohmann::json::parse(R"({"listed": [], "unlisted": 0, "max_listed": 100})"));
}

}  // namespace
}  // namespace dream::node
