// The three sensor kinds share their validation helpers, hence one file.
#include <cmath>
#include <stdexcept>

#include "dream/agents/framework/movement_sensor.h"
#include "dream/agents/framework/number_text.h"
#include "dream/agents/framework/obstacle_sensor.h"
#include "dream/agents/framework/odometry_sensor.h"
#include "dream/agents/framework/robot.h"

namespace dream::agents {
namespace {

bool Fail(std::string* error, const std::string& message) {
  if (error != nullptr) *error = message;
  return false;
}

constexpr double kFullCircleSlackRad = 1e-4;

bool NonNegative(double value) { return std::isfinite(value) && value >= 0.0; }
bool Positive(double value) { return std::isfinite(value) && value > 0.0; }

template <typename Params>
const Params& Checked(const Params& params) {
  std::string error;
  if (!params.IsValid(&error)) throw std::invalid_argument(error);
  return params;
}

double WrapAngle(double angle_rad) { return std::atan2(std::sin(angle_rad), std::cos(angle_rad)); }

}  // namespace

bool OdometrySensorParams::IsValid(std::string* error) const {
  if (!NonNegative(noise_std)) return Fail(error, "noise_std must be >= 0, got " + NumberText(noise_std));
  return true;
}

bool MovementSensorParams::IsValid(std::string* error) const {
  if (!Positive(range_m)) return Fail(error, "range_m must be > 0, got " + NumberText(range_m));
  if (!std::isfinite(direction_rad)) return Fail(error, "direction_rad must be finite");
  // 2 pi as people write it (6.2832, rounded up) is a full circle too.
  if (!(field_of_view_rad > 0.0 && field_of_view_rad <= 2 * M_PI + kFullCircleSlackRad)) {
    return Fail(error, "field_of_view_rad must be in (0, 2 pi = 6.2832], got " + NumberText(field_of_view_rad));
  }
  if (!NonNegative(noise_std)) return Fail(error, "noise_std must be >= 0, got " + NumberText(noise_std));
  if (!NonNegative(velocity_point_ahead_m)) {
    return Fail(error, "velocity_point_ahead_m must be >= 0, got " + NumberText(velocity_point_ahead_m));
  }
  return true;
}

bool ObstacleSensorParams::IsValid(std::string* error) const {
  if (!Positive(range_m)) return Fail(error, "range_m must be > 0, got " + NumberText(range_m));
  if (!NonNegative(noise_std)) return Fail(error, "noise_std must be >= 0, got " + NumberText(noise_std));
  return true;
}

OdometrySensor::OdometrySensor(const OdometrySensorParams& params, uint64_t seed)
    : params_(Checked(params)), noise_(seed) {}

void OdometrySensor::Sense(const WorldSnapshot& world, Robot& robot) {
  OdometryReading reading;
  reading.step = world.step;
  const Eigen::Vector3d& pose = world.poses.at(static_cast<size_t>(robot.id()));
  for (int i = 0; i < 3; ++i) reading.pose[i] = pose[i] + noise_.Gaussian(params_.noise_std);
  reading.pose.z() = WrapAngle(reading.pose.z());
  robot.OnOdometry(reading);
}

MovementSensor::MovementSensor(const MovementSensorParams& params, uint64_t seed)
    : params_(Checked(params)), noise_(seed) {}

void MovementSensor::Sense(const WorldSnapshot& world, Robot& robot) {
  MovementReading reading;
  reading.step = world.step;
  const auto self = static_cast<size_t>(robot.id());
  const Eigen::Vector3d& own = world.poses.at(self);
  const double half_fov = params_.field_of_view_rad / 2.0;
  for (size_t i = 0; i < world.poses.size(); ++i) {
    if (i == self) continue;
    const Eigen::Vector2d offset = world.poses[i].head<2>() - own.head<2>();
    const double distance = offset.norm();
    if (distance <= 0.0 || distance > params_.range_m) continue;
    const double bearing = std::atan2(offset.y(), offset.x());
    if (std::abs(WrapAngle(bearing - own.z() - params_.direction_rad)) > half_fov + 1e-12) continue;
    NeighbourDetection detection;
    detection.distance_m = distance + noise_.Gaussian(params_.noise_std);
    detection.bearing_rad = WrapAngle(bearing + noise_.Gaussian(params_.noise_std));
    const double theta = world.poses[i].z();
    const Eigen::Vector2d vw = i < world.velocities.size() ? world.velocities[i] : Eigen::Vector2d::Zero();
    const double ahead = params_.velocity_point_ahead_m;
    detection.velocity_mps = {std::cos(theta) * vw.x() - ahead * std::sin(theta) * vw.y() +
                                  noise_.Gaussian(params_.noise_std),
                              std::sin(theta) * vw.x() + ahead * std::cos(theta) * vw.y() +
                                  noise_.Gaussian(params_.noise_std)};
    reading.neighbours.push_back(detection);
  }
  robot.OnMovement(reading);
}

ObstacleSensor::ObstacleSensor(const ObstacleSensorParams& params, uint64_t seed)
    : params_(Checked(params)), noise_(seed) {}

void ObstacleSensor::Sense(const WorldSnapshot& world, Robot& robot) {
  ObstacleReading reading;
  reading.step = world.step;
  const Eigen::Vector2d own = world.poses.at(static_cast<size_t>(robot.id())).head<2>();
  for (const ObstacleView& obstacle : world.obstacles) {
    const Eigen::Vector2d half = obstacle.size_m / 2.0;
    const Eigen::Vector2d closest = own.cwiseMax(obstacle.center_m - half).cwiseMin(obstacle.center_m + half);
    if ((closest - own).norm() > params_.range_m) continue;
    const double noise_x = noise_.Gaussian(params_.noise_std);  // x first: keeps the seeded stream's order
    const Eigen::Vector2d noise(noise_x, noise_.Gaussian(params_.noise_std));
    reading.closest_points_m.push_back(closest + noise);
    reading.rectangles.push_back({obstacle.center_m + noise, obstacle.size_m});
  }
  robot.OnObstacles(reading);
}

}  // namespace dream::agents
