// IsValid messages name the field, its value and the allowed range.
#include <cmath>
#include <limits>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "dream/world/initial_pose_params.h"
#include "dream/world/rectangle_obstacle_spec.h"
#include "dream/world/world_params.h"

namespace dream::world {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;

template <typename Params>
std::string ErrorOf(const Params& params) {
  std::string error;
  EXPECT_FALSE(params.IsValid(&error));
  return error;
}

TEST(WorldParamsTest, DefaultsAreTheRobotariumAndValid) {
  const WorldParams params;
  std::string error;
  EXPECT_TRUE(params.IsValid(&error)) << error;
  EXPECT_TRUE(params.IsValid(nullptr));
  EXPECT_EQ(params.time_step_s, 0.033);
  EXPECT_EQ(params.arena.x_min_m, -1.6);
  EXPECT_EQ(params.arena.y_max_m, 1.0);
  EXPECT_EQ(params.max_wheel_speed_radps, 12.5);
  EXPECT_EQ(params.collision_diameter_m, 0.135);
  EXPECT_EQ(params.collision_offset_m, 0.025);
  EXPECT_EQ(params.command_timeout_s, 0.5);
}

TEST(WorldParamsTest, EachFieldIsCheckedWithAClearMessage) {
  WorldParams params;
  params.time_step_s = 0.0;
  EXPECT_THAT(ErrorOf(params), AllOf(HasSubstr("time_step_s = 0"), HasSubstr("(0, 1] s")));
  params = WorldParams{};
  params.wheel_radius_m = std::nan("");
  EXPECT_THAT(ErrorOf(params), AllOf(HasSubstr("wheel_radius_m = nan"), HasSubstr("> 0 m")));
  params = WorldParams{};
  params.base_length_m = -0.11;
  EXPECT_THAT(ErrorOf(params), HasSubstr("base_length_m = -0.11"));
  params = WorldParams{};
  params.max_wheel_speed_radps = std::numeric_limits<double>::infinity();
  EXPECT_THAT(ErrorOf(params), HasSubstr("max_wheel_speed_radps = inf"));
  params = WorldParams{};
  params.collision_diameter_m = 0.0;
  EXPECT_THAT(ErrorOf(params), HasSubstr("collision_diameter_m = 0"));
  params = WorldParams{};
  params.collision_offset_m = -0.025;
  EXPECT_THAT(ErrorOf(params), AllOf(HasSubstr("collision_offset_m = -0.025"), HasSubstr(">= 0 m")));
  params = WorldParams{};
  params.command_timeout_s = 0.0;
  EXPECT_THAT(ErrorOf(params), AllOf(HasSubstr("command_timeout_s = 0"), HasSubstr("+inf disables")));
  params.command_timeout_s = std::numeric_limits<double>::infinity();
  EXPECT_TRUE(params.IsValid(nullptr));
  params = WorldParams{};
  params.arena.x_max_m = -2.0;
  EXPECT_THAT(ErrorOf(params), AllOf(HasSubstr("arena.x_max_m = -2"), HasSubstr("> arena.x_min_m (-1.6)")));
  params = WorldParams{};
  params.arena.y_min_m = std::nan("");
  EXPECT_THAT(ErrorOf(params), HasSubstr("arena.y_min_m = nan"));
}

TEST(ArenaTest, ContainsIsStrictLikeTheRobotarium) {
  const Arena arena;
  EXPECT_TRUE(arena.Contains(1.6, 1.0));
  EXPECT_TRUE(arena.Contains(-1.6, -1.0));
  EXPECT_FALSE(arena.Contains(1.6000001, 0.0));
  EXPECT_FALSE(arena.Contains(0.0, -1.0000001));
  EXPECT_DOUBLE_EQ(arena.width_m(), 3.2);
  EXPECT_DOUBLE_EQ(arena.height_m(), 2.0);
}

TEST(RectangleObstacleSpecTest, MessagesNameTheObstacleAndField) {
  RectangleObstacleSpec spec;
  spec.id = 3;
  spec.width_m = 0.2;
  spec.height_m = 0.0;
  EXPECT_THAT(ErrorOf(spec), HasSubstr("rectangle_obstacle[id=3].height_m = 0"));
  spec.height_m = 0.2;
  std::string error;
  EXPECT_TRUE(spec.IsValid(&error)) << error;
  spec.path = ObstaclePath{};
  EXPECT_THAT(ErrorOf(spec), HasSubstr("path.waypoints_m is empty"));
  spec.path->waypoints_m = {Eigen::Vector2d(1.0, std::nan(""))};
  spec.path->speed_mps = 0.1;
  EXPECT_THAT(ErrorOf(spec), HasSubstr("path.waypoints_m[0].y = nan"));
  spec.path->waypoints_m = {Eigen::Vector2d(1.0, 0.0)};
  spec.path->speed_mps = -0.1;
  EXPECT_THAT(ErrorOf(spec), AllOf(HasSubstr("path.speed_mps = -0.1"), HasSubstr("> 0 m/s")));
  spec.path->speed_mps = 0.1;
  spec.path->waypoints_m = {Eigen::Vector2d(0.0, 0.0)};
  EXPECT_THAT(ErrorOf(spec), HasSubstr("zero length"));
}

TEST(InitialPoseParamsTest, MessagesNameTheField) {
  InitialPoseParams params;
  EXPECT_TRUE(params.IsValid(nullptr));
  params.min_spacing_m = -1.0;
  EXPECT_THAT(ErrorOf(params), HasSubstr("initial_poses.generate.min_spacing_m = -1"));
  params = InitialPoseParams{};
  params.wall_margin_m = -0.1;
  EXPECT_THAT(ErrorOf(params), HasSubstr("initial_poses.generate.wall_margin_m = -0.1"));
  params = InitialPoseParams{};
  params.max_attempts_per_robot = 0;
  EXPECT_THAT(ErrorOf(params), AllOf(HasSubstr("max_attempts_per_robot = 0"), HasSubstr("[1, 1000000]")));
}

}  // namespace
}  // namespace dream::world
