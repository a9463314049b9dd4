// `barriers:` in a run config: defaults are rps's, every key read, each
// mistake named by file, line and key; and the world a config asks for
// filters its commands through the certificate when apply_in is world.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "dream/run_config/run_config.h"
#include "dream/run_config/world_of_config.h"
#include "dream/world/barrier_world.h"
#include "dream/world/realistic_world.h"
#include "dream/world/unicycle_world.h"

namespace dream::config {
namespace {

using run_config::BarrierConfig;

std::string ConfigWith(const std::string& barrier_lines, const std::string& world_lines = "") {
  return "name: demo\nrobots: 2\nsteps: 10\ninitial_poses:\n  - [-0.3, 0.0, 0.0]\n  - [0.3, 0.0, 3.14159]\n"
         "world:\n  mode: lockstep\n" +
         world_lines + barrier_lines + "controller:\n  kind: go_to_goal\n  goals: [[0.3, 0.0], [-0.3, 0.0]]\n";
}

run_config::RunConfig Load(const std::string& text) {
  return run_config::LoadRunConfig(ConfigNode::LoadString(text, "test.yaml"));
}

std::string ErrorOf(const std::string& text) {
  try {
    Load(text);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(BarrierConfigTest, AbsentMeansNone) {
  const BarrierConfig barriers = Load(ConfigWith("")).barriers;
  EXPECT_EQ(barriers.kind, BarrierConfig::Kind::kNone);
  EXPECT_FALSE(barriers.InWorld());
  EXPECT_EQ(Load(ConfigWith("barriers:\n  kind: none\n")).barriers.kind, BarrierConfig::Kind::kNone);
}

TEST(BarrierConfigTest, UnicycleDefaultsAreRpsWithBoundary) {
  const BarrierConfig barriers = Load(ConfigWith("barriers:\n  kind: unicycle\n")).barriers;
  EXPECT_TRUE(barriers.InWorld());
  const barriers::UnicycleBarrierParams rps = barriers::UnicycleBarrierParams::RpsWithBoundary();
  EXPECT_EQ(barriers.unicycle.safety_radius_m, rps.safety_radius_m);
  EXPECT_EQ(barriers.unicycle.barrier_gain, rps.barrier_gain);
  EXPECT_EQ(barriers.unicycle.projection_distance_m, rps.projection_distance_m);
  EXPECT_EQ(barriers.unicycle.magnitude_limit_mps, rps.magnitude_limit_mps);
  ASSERT_TRUE(barriers.unicycle.boundary.has_value());
  EXPECT_EQ(barriers.unicycle.boundary->x_max_m, 1.6);
}

TEST(BarrierConfigTest, EveryKeyIsRead) {
  const BarrierConfig barriers =
      Load(ConfigWith("barriers:\n  kind: unicycle\n  safety_radius_m: 0.15\n  barrier_gain: 100\n"
                      "  projection_distance_m: 0.05\n  magnitude_limit_mps: 0.15\n  boundary_m: none\n"))
          .barriers;
  EXPECT_EQ(barriers.unicycle.safety_radius_m, 0.15);
  EXPECT_EQ(barriers.unicycle.barrier_gain, 100.0);
  EXPECT_EQ(barriers.unicycle.projection_distance_m, 0.05);
  EXPECT_EQ(barriers.unicycle.magnitude_limit_mps, 0.15);
  EXPECT_FALSE(barriers.unicycle.boundary.has_value());
  const BarrierConfig box =
      Load(ConfigWith("barriers:\n  kind: unicycle\n  boundary_m: [-1.5, 1.5, -0.9, 0.9]\n")).barriers;
  ASSERT_TRUE(box.unicycle.boundary.has_value());
  EXPECT_EQ(box.unicycle.boundary->y_min_m, -0.9);
  const BarrierConfig si =
      Load(ConfigWith("barriers:\n  kind: single_integrator\n  apply_in: controller\n  barrier_gain: 50\n")).barriers;
  EXPECT_EQ(si.kind, BarrierConfig::Kind::kSingleIntegrator);
  EXPECT_EQ(si.apply_in, BarrierConfig::ApplyIn::kController);
  EXPECT_EQ(si.single_integrator.barrier_gain, 50.0);
  EXPECT_EQ(si.single_integrator.safety_radius_m, 0.15);  // rps's si default
  EXPECT_FALSE(si.InWorld());
}

TEST(BarrierConfigTest, MistakesNameFileLineKeyAndValue) {
  EXPECT_NE(ErrorOf(ConfigWith("barriers:\n  kind: unicycel\n"))
                .find("test.yaml:10: barriers.kind: unknown barrier kind "
                      "'unicycel' (did you mean 'unicycle'?)"),
            std::string::npos)
      << ErrorOf(ConfigWith("barriers:\n  kind: unicycel\n"));
  EXPECT_NE(ErrorOf(ConfigWith("barriers:\n  kind: unicycle\n  safety_radius_m: -0.1\n"))
                .find("test.yaml:11: barriers.safety_radius_m: must be > 0, got -0.1"),
            std::string::npos);
  EXPECT_NE(ErrorOf(ConfigWith("barriers:\n  kind: unicycle\n  gain: 3\n")).find("barriers"), std::string::npos);
  EXPECT_NE(ErrorOf(ConfigWith("barriers:\n  kind: unicycle\n  boundary_m: [1, -1, 0, 1]\n"))
                .find("test.yaml:11: barriers.boundary_m: must be [x_min, x_max, y_min, y_max]"),
            std::string::npos);
  EXPECT_NE(ErrorOf(ConfigWith("barriers:\n  kind: single_integrator\n")).find("needs apply_in: controller"),
            std::string::npos);
  EXPECT_NE(ErrorOf(ConfigWith("barriers:\n  kind: single_integrator\n  apply_in: controller\n"
                               "  projection_distance_m: 0.03\n"))
                .find("test.yaml:12: barriers.projection_distance_m: only kind unicycle"),
            std::string::npos);
  EXPECT_NE(ErrorOf(ConfigWith("barriers:\n  barrier_gain: 100\n")).find("take no other key"), std::string::npos);
  EXPECT_NE(ErrorOf(ConfigWith("barriers: yes\n")).find("barriers: must be a map"), std::string::npos);
}

TEST(BarrierConfigTest, TheWorldFiltersOnlyWhenTheConfigSaysWorld) {
  const auto plain = run_config::WorldOfConfig(Load(ConfigWith("")));
  EXPECT_EQ(dynamic_cast<const world::BarrierWorld*>(plain.get()), nullptr);
  const auto controller =
      run_config::WorldOfConfig(Load(ConfigWith("barriers:\n  kind: unicycle\n  apply_in: controller\n")));
  EXPECT_EQ(dynamic_cast<const world::BarrierWorld*>(controller.get()), nullptr);
  const auto filtered = run_config::WorldOfConfig(Load(ConfigWith("barriers:\n  kind: unicycle\n")));
  const auto* barrier_world = dynamic_cast<const world::BarrierWorld*>(filtered.get());
  ASSERT_NE(barrier_world, nullptr);
  EXPECT_NE(dynamic_cast<const world::UnicycleWorld*>(&world::SteppingWorldOf(*filtered)), nullptr);
  const auto lab = run_config::WorldOfConfig(Load(ConfigWith("barriers:\n  kind: unicycle\n", "  realism: lab\n")));
  EXPECT_NE(dynamic_cast<const world::RealisticWorld*>(&world::SteppingWorldOf(*lab)), nullptr);
}

}  // namespace
}  // namespace dream::config
