// The `orbit` experiment: each robot circles its own centre at a set radius
// and speed. A complete controller plugin: the Robot (control law), its
// metrics, the builder that reads its config keys, and one line registering
// the kind with the dream tools.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "dream/agents/controller_plugin.h"
#include "dream/agents/experiment_builder.h"
#include "dream/agents/robot.h"
#include "dream/agents/single_integrator_to_unicycle.h"
#include "dream/config/config_node.h"

namespace orbit {

using dream::agents::ExperimentMetrics;
using dream::agents::MetricsReport;
using dream::agents::RobotParams;
using dream::agents::UnicycleCommand;
using dream::agents::WorldSnapshot;

struct OrbitParams {
  std::vector<Eigen::Vector2d> centers_m;  // one per robot
  double radius_m = 0.25;
  double speed_mps = 0.1;
  double radial_gain = 2.0;  // 1/s: how hard a robot is pulled back onto its circle
};

/// The control law: drive along the circle (counter-clockwise) and towards it.
class OrbitRobot final : public dream::agents::Robot {
 public:
  OrbitRobot(int id, const RobotParams& robot_params, const OrbitParams& params)
      : Robot(id, robot_params),
        center_m_(params.centers_m.at(static_cast<size_t>(id))),
        radius_m_(params.radius_m),
        speed_mps_(params.speed_mps),
        radial_gain_(params.radial_gain) {}

  UnicycleCommand Update(int64_t /*step*/) override {
    if (!has_odometry()) return {};  // knows nothing yet: hold still
    const Eigen::Vector2d offset = pose().head<2>() - center_m_;
    const double distance_m = offset.norm();
    const Eigen::Vector2d outward = distance_m > 1e-9 ? Eigen::Vector2d(offset / distance_m) : Eigen::Vector2d::UnitX();
    const Eigen::Vector2d along(-outward.y(), outward.x());
    const Eigen::Vector2d velocity_mps = speed_mps_ * along + radial_gain_ * (radius_m_ - distance_m) * outward;
    return LimitActuators(si_to_uni_.Map(velocity_mps, pose().z()));
  }

 private:
  Eigen::Vector2d center_m_;
  double radius_m_;
  double speed_mps_;
  double radial_gain_;
  dream::agents::SingleIntegratorToUnicycle si_to_uni_;
};

/// What summary.json reports under `metrics`: how far robots strayed from
/// their circles once on them, and how many laps the slowest one drove.
class OrbitMetrics final : public ExperimentMetrics {
 public:
  OrbitMetrics(OrbitParams params, int settle_steps) : params_(std::move(params)), settle_steps_(settle_steps) {}

  void Observe(const WorldSnapshot& world) override {
    const size_t robots = std::min(params_.centers_m.size(), world.poses.size());
    angle_rad_.resize(robots, 0.0);
    turned_rad_.resize(robots, 0.0);
    for (size_t i = 0; i < robots; ++i) {
      const Eigen::Vector2d offset = world.poses[i].head<2>() - params_.centers_m[i];
      const double angle_rad = std::atan2(offset.y(), offset.x());
      if (seen_) turned_rad_[i] += std::remainder(angle_rad - angle_rad_[i], 2.0 * M_PI);
      angle_rad_[i] = angle_rad;
      if (world.step >= settle_steps_) {
        max_radius_error_m_ = std::max(max_radius_error_m_, std::abs(offset.norm() - params_.radius_m));
      }
    }
    seen_ = true;
  }

  void Write(MetricsReport* report) const override {
    double min_laps = turned_rad_.empty() ? 0.0 : turned_rad_[0];
    for (double turned : turned_rad_) min_laps = std::min(min_laps, turned);
    report->values["min_laps"] = min_laps / (2.0 * M_PI);
    report->values["max_radius_error_m"] = max_radius_error_m_;
  }

 private:
  OrbitParams params_;
  int settle_steps_;
  bool seen_ = false;
  std::vector<double> angle_rad_;
  std::vector<double> turned_rad_;  // counter-clockwise positive
  double max_radius_error_m_ = 0.0;
};

/// `kind: orbit`. Reads the kind's own keys, with errors that name file, line and key:
///     centers: [[x, y], ...]   one per robot, metres
///     radius_m: 0.25   speed_mps: 0.1   radial_gain: 2.0   settle_steps: 100 (metrics ignore the start)
class OrbitBuilder final : public dream::agents::ExperimentBuilder {
 public:
  static constexpr const char* kKind = "orbit";
  static std::vector<const char*> Keys() { return {"centers", "radius_m", "speed_mps", "radial_gain", "settle_steps"}; }

  OrbitBuilder(const dream::config::ConfigNode& section, int num_robots) {
    const dream::config::ConfigNode centers = section.Required("centers");
    if (!centers.IsSequence() || centers.size() != static_cast<size_t>(num_robots)) {
      centers.Fail("expected one [x, y] centre per robot (" + std::to_string(num_robots) + ")");
    }
    for (size_t i = 0; i < centers.size(); ++i) {
      const std::vector<double> xy = centers[i].AsDoubles();
      if (xy.size() != 2) centers[i].Fail("expected [x, y] in metres");
      params_.centers_m.emplace_back(xy[0], xy[1]);
    }
    params_.radius_m = section.GetDouble("radius_m", params_.radius_m);
    params_.speed_mps = section.GetDouble("speed_mps", params_.speed_mps);
    params_.radial_gain = section.GetDouble("radial_gain", params_.radial_gain);
    settle_steps_ = static_cast<int>(section.GetInt("settle_steps", settle_steps_));
    if (params_.radius_m <= 0.0) section.Required("radius_m").Fail("must be > 0");
    if (params_.speed_mps <= 0.0) section.Required("speed_mps").Fail("must be > 0");
    if (params_.radial_gain < 0.0) section.Required("radial_gain").Fail("must be >= 0");
  }

  std::unique_ptr<dream::agents::Robot> MakeRobot(int robot_id, const RobotParams& params) const override {
    return std::make_unique<OrbitRobot>(robot_id, params, params_);
  }
  std::unique_ptr<ExperimentMetrics> MakeMetrics() const override {
    return std::make_unique<OrbitMetrics>(params_, settle_steps_);
  }

 private:
  OrbitParams params_;
  int settle_steps_ = 100;
};

}  // namespace orbit

// The plugin's entry points: the dream tools call them after loading the file.
DREAM_REGISTER_CONTROLLER(orbit::OrbitBuilder)
