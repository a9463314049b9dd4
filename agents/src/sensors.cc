// The three sensor kinds share their angle and validation helpers, hence one file.
#include <cmath>

#include "dream/agents/framework/movement_sensor.h"
#include "dream/agents/framework/number_text.h"
#include "dream/agents/framework/obstacle_sensor.h"
#include "dream/agents/framework/odometry_sensor.h"
#include "dream/agents/framework/params_check.h"
#include "dream/agents/framework/robot.h"

namespace dream::agents {
namespace {

constexpr double kFullCircleSlackRad = 1e-4;

double WrapAngle(double angle_rad) { return std::atan2(std::sin(angle_rad), std::cos(angle_rad)); }

}  // namespace

bool OdometrySensorParams::IsValid(std::string* error) const { return CheckNonNegative(error, "noise_std", noise_std); }

bool MovementSensorParams::IsValid(std::string* error) const {
  if (!CheckPositive(error, "range_m", range_m)) return false;
  if (!std::isfinite(direction_rad)) return FailParams(error, "direction_rad must be finite");
  // 2 pi as people write it (6.2832, rounded up) is a full circle too.
  if (!(field_of_view_rad > 0.0 && field_of_view_rad <= 2 * M_PI + kFullCircleSlackRad)) {
    return FailParams(error, "field_of_view_rad must be in (0, 2 pi = 6.2832], got " + NumberText(field_of_view_rad));
  }
  return CheckNonNegative(error, "noise_std", noise_std) &&
         CheckNonNegative(error, "velocity_point_ahead_m", velocity_point_ahead_m);
}

bool ObstacleSensorParams::IsValid(std::string* error) const {
  return CheckPositive(error, "range_m", range_m) && CheckNonNegative(error, "noise_std", noise_std);
}

void OdometrySensor::Sense(const WorldSnapshot& world, Robot& robot) {
  OdometryReading reading;
  reading.step = world.step;
  const Eigen::Vector3d& pose = world.poses.at(static_cast<size_t>(robot.id()));
  for (int i = 0; i < 3; ++i) reading.pose[i] = pose[i] + noise().Gaussian(params().noise_std);
  reading.pose.z() = WrapAngle(reading.pose.z());
  robot.OnOdometry(reading);
}

void MovementSensor::Sense(const WorldSnapshot& world, Robot& robot) {
  MovementReading reading;
  reading.step = world.step;
  const auto self = static_cast<size_t>(robot.id());
  const Eigen::Vector3d& own = world.poses.at(self);
  const double half_fov = params().field_of_view_rad / 2.0;
  for (size_t i = 0; i < world.poses.size(); ++i) {
    if (i == self) continue;
    const Eigen::Vector2d offset = world.poses[i].head<2>() - own.head<2>();
    const double distance = offset.norm();
    if (distance <= 0.0 || distance > params().range_m) continue;
    const double bearing = std::atan2(offset.y(), offset.x());
    if (std::abs(WrapAngle(bearing - own.z() - params().direction_rad)) > half_fov + 1e-12) continue;
    NeighbourDetection detection;
    detection.distance_m = distance + noise().Gaussian(params().noise_std);
    detection.bearing_rad = WrapAngle(bearing + noise().Gaussian(params().noise_std));
    const double theta = world.poses[i].z();
    const Eigen::Vector2d vw = i < world.velocities.size() ? world.velocities[i] : Eigen::Vector2d::Zero();
    const double ahead = params().velocity_point_ahead_m;
    detection.velocity_mps = {
        std::cos(theta) * vw.x() - ahead * std::sin(theta) * vw.y() + noise().Gaussian(params().noise_std),
        std::sin(theta) * vw.x() + ahead * std::cos(theta) * vw.y() + noise().Gaussian(params().noise_std)};
    reading.neighbours.push_back(detection);
  }
  robot.OnMovement(reading);
}

void ObstacleSensor::Sense(const WorldSnapshot& world, Robot& robot) {
  ObstacleReading reading;
  reading.step = world.step;
  const Eigen::Vector2d own = world.poses.at(static_cast<size_t>(robot.id())).head<2>();
  for (const ObstacleView& obstacle : world.obstacles) {
    const Eigen::Vector2d half = obstacle.size_m / 2.0;
    const Eigen::Vector2d closest = own.cwiseMax(obstacle.center_m - half).cwiseMin(obstacle.center_m + half);
    if ((closest - own).norm() > params().range_m) continue;
    const double noise_x = noise().Gaussian(params().noise_std);  // x first: keeps the seeded stream's order
    const Eigen::Vector2d point_noise(noise_x, noise().Gaussian(params().noise_std));
    reading.closest_points_m.push_back(closest + point_noise);
    reading.rectangles.push_back({obstacle.center_m + point_noise, obstacle.size_m});
  }
  robot.OnObstacles(reading);
}

}  // namespace dream::agents
