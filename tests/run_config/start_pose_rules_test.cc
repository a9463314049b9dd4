// A start pose the config accepts is one the world does not count as a
// boundary error at step 0 and `dream export` does not refuse
// (start_inside_arena): checked on poses around every wall, down to the last
// representable double on either side of the limit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "dream/bridge/pre_validation.h"
#include "dream/run_config/run_config.h"
#include "dream/run_status_t.hpp"
#include "dream/world/unicycle_world.h"

namespace dream::config {
namespace {

std::string Exact(double value) {
  char text[40];
  std::snprintf(text, sizeof(text), "%.17g", value);
  return text;
}

/// Whether a one-robot config starting at (x, y) loads.
bool ConfigAccepts(double x, double y) {
  const std::string text = "name: walls\nrobots: 1\ninitial_poses:\n  - [" + Exact(x) + ", " + Exact(y) +
                           ", 0.0]\ncontroller: {kind: go_to_goal, goals: [[0, 0]]}\n";
  try {
    run_config::LoadRunConfig(ConfigNode::LoadString(text, "walls.yaml"));
    return true;
  } catch (const ConfigError&) {
    return false;
  }
}

/// The rules `dream export` refuses a still one-robot run at (x, y) by.
std::vector<std::string> ExportRefusals(double x, double y) {
  bridge::RunTrack track;
  track.num_robots = 1;
  for (int64_t k = 0; k <= 1; ++k) {
    track.utime.push_back(k * 33000);
    track.poses.push_back(world::Pose2{x, y, 0.0});
    track.commands.push_back(world::UnicycleCommand{});
    track.obstacles.emplace_back();
  }
  bridge::RunEnd end;
  end.seen = true;
  end.state = run_status_t::FINISHED;
  std::vector<std::string> rules;
  for (const bridge::ExportProblem& p : bridge::PreValidate(track, end, world::WorldParams{}, 240))
    rules.push_back(p.rule);
  return rules;
}

bool BoundaryErrorAtStepZero(double x, double y) {
  world::UnicycleWorld world(world::WorldParams{}, {world::Pose2{x, y, 0.0}}, {});
  world.Step();
  return world.violations().boundary_errors > 0;
}

TEST(StartPoseRulesTest, AcceptedMeansNoBoundaryErrorAndNoExportRefusal) {
  const world::Arena arena;
  const double radius = 0.055;
  // (x, y) on a line across each wall, through the limit of the lab's rule.
  struct Wall {
    double limit;
    bool is_x;
  };
  const Wall walls[] = {{arena.x_min_m + radius, true},
                        {arena.x_max_m - radius, true},
                        {arena.y_min_m + radius, false},
                        {arena.y_max_m - radius, false}};
  int accepted = 0;
  int refused = 0;
  for (const Wall& wall : walls) {
    std::vector<double> across;
    for (int k = -80; k <= 80; ++k) across.push_back(wall.limit + k * 0.001);
    for (double v = wall.limit, w = wall.limit, i = 0; i < 4; ++i) {
      v = std::nextafter(v, -10.0);
      w = std::nextafter(w, 10.0);
      across.push_back(v);
      across.push_back(w);
    }
    for (double v : across) {
      const double x = wall.is_x ? v : 0.3;
      const double y = wall.is_x ? 0.3 : v;
      const std::vector<std::string> refusals = ExportRefusals(x, y);
      const bool export_refuses = std::find(refusals.begin(), refusals.end(), "start_inside_arena") != refusals.end();
      const bool accepts = ConfigAccepts(x, y);
      EXPECT_EQ(accepts, !export_refuses) << "(" << Exact(x) << ", " << Exact(y) << ")";
      if (accepts) {
        EXPECT_FALSE(BoundaryErrorAtStepZero(x, y)) << "(" << Exact(x) << ", " << Exact(y) << ")";
        EXPECT_TRUE(refusals.empty()) << "(" << Exact(x) << ", " << Exact(y) << "): " << refusals.front();
      }
      (accepts ? accepted : refused) += 1;
    }
  }
  // Both sides of every wall's limit were tried.
  EXPECT_GT(accepted, 300);
  EXPECT_GT(refused, 300);
}

}  // namespace
}  // namespace dream::config
