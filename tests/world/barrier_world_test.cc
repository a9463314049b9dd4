// BarrierWorld: the certificate between the commands and the world's step.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "dream/barriers/unicycle_barrier.h"
#include "dream/world/barrier_world.h"
#include "dream/world/unicycle_world.h"

namespace dream::world {
namespace {

std::unique_ptr<World> HeadOn() {
  return std::make_unique<UnicycleWorld>(WorldParams{}, std::vector<Pose2>{{-0.4, 0.0, 0.0}, {0.4, 0.0, M_PI}});
}

void DriveAtEachOther(World* world, int steps) {
  for (int k = 0; k < steps; ++k) {
    world->SetCommand(0, UnicycleCommand{0.15, 0.0});
    world->SetCommand(1, UnicycleCommand{0.15, 0.0});
    world->Step();
  }
}

TEST(BarrierWorldTest, HeadOnRobotsCollideWithoutAndStopShortWith) {
  std::unique_ptr<World> bare = HeadOn();
  DriveAtEachOther(bare.get(), 150);
  EXPECT_GT(bare->violations().collision_errors, 0);

  BarrierWorld guarded(HeadOn(), barriers::UnicycleBarrierParams::RpsWithBoundary());
  DriveAtEachOther(&guarded, 150);
  EXPECT_EQ(guarded.violations().collision_errors, 0);
  EXPECT_GT(guarded.steps_changed(), 0);
  EXPECT_EQ(guarded.failed_steps(), 0);
  // They stop short of each other, beyond the certificate's distance between their projected points.
  const double gap =
      std::hypot(guarded.poses()[1].x_m - guarded.poses()[0].x_m, guarded.poses()[1].y_m - guarded.poses()[0].y_m);
  EXPECT_GT(gap, 0.12);
  EXPECT_LT(gap, 0.4);
}

TEST(BarrierWorldTest, DrivesWithTheCertificatesCommandsOnTheSeenPoses) {
  BarrierWorld guarded(HeadOn(), barriers::UnicycleBarrierParams::RpsWithBoundary());
  barriers::UnicycleBarrier barrier(barriers::UnicycleBarrierParams::RpsWithBoundary());
  DriveAtEachOther(&guarded, 60);
  Eigen::Matrix3Xd poses(3, 2);
  for (int i = 0; i < 2; ++i) {
    const Pose2& p = guarded.poses()[static_cast<size_t>(i)];
    poses.col(i) << p.x_m, p.y_m, p.theta_rad;
  }
  Eigen::Matrix2Xd wanted(2, 2);
  wanted << 0.15, 0.15, 0.0, 0.0;
  const barriers::BarrierResult expected = barrier.Apply(wanted, poses);
  DriveAtEachOther(&guarded, 1);
  ASSERT_GT(std::abs(expected.commands(0, 0) - 0.15), 1e-3);  // the certificate does bend them here
  for (int i = 0; i < 2; ++i) {  // within the wheels' limits: only the wheel-speed round trip's rounding
    EXPECT_NEAR(guarded.velocities()[static_cast<size_t>(i)].v_mps, expected.commands(0, i), 1e-12);
    EXPECT_NEAR(guarded.velocities()[static_cast<size_t>(i)].w_radps, expected.commands(1, i), 1e-12);
  }
}

TEST(BarrierWorldTest, AStoppedRobotStaysStoppedAndIsAvoided) {
  BarrierWorld guarded(HeadOn(), barriers::UnicycleBarrierParams::RpsWithBoundary());
  for (int k = 0; k < 150; ++k) {
    guarded.SetCommand(0, UnicycleCommand{0.15, 0.0});
    guarded.StopRobot(1);
    guarded.Step();
  }
  EXPECT_EQ(guarded.velocities()[1].v_mps, 0.0);
  EXPECT_EQ(guarded.poses()[1].x_m, 0.4);
  EXPECT_EQ(guarded.violations().collision_errors, 0);
  EXPECT_THROW(guarded.SetCommand(2, UnicycleCommand{}), std::out_of_range);
  EXPECT_THROW(guarded.SetCommand(0, UnicycleCommand{NAN, 0.0}), std::invalid_argument);
}

}  // namespace
}  // namespace dream::world
