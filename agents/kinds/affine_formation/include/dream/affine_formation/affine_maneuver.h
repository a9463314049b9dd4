#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "dream/agents/geometry/affine_transform.h"

namespace dream::affine_formation {

/// One pose of the formation at a step: A = diag(scale_x, scale_y) R(rotation),
/// b = translation. The nominal shape is rotated first and then scaled along
/// the world axes, so a small scale_y after a rotation lays the robots out on
/// a horizontal line without two of them meeting.
struct AffineKeyframe {
  int64_t step = 0;           ///< when the formation has this shape, simulation steps
  double scale_x = 1.0;       ///< > 0
  double scale_y = 1.0;       ///< > 0
  double rotation_rad = 0.0;  ///< counter-clockwise
  Eigen::Vector2d translation_m = Eigen::Vector2d::Zero();

  agents::AffineTransform Transform() const;
};

/// The leaders' plan: keyframes at strictly increasing steps.
struct AffineManeuverParams {
  /// A bound on the list a config may give (a waypoint every 30 steps of the
  /// lab's 15 minutes fits); robots look keyframes up every step.
  static constexpr size_t kMaxKeyframes = 1000;

  std::vector<AffineKeyframe> keyframes;
  /// False with a message naming the keyframe index and field.
  bool IsValid(std::string* error) const;
};

/// A time-varying affine map (A(t), b(t)) through keyframes. Between two
/// keyframes every parameter (scales, rotation, translation) moves along a
/// smoothstep 3u^2 - 2u^3, so the targets start and stop with zero velocity
/// and nobody is asked for a jump in speed; before the first keyframe and
/// after the last the formation holds still.
class AffineManeuver {
 public:
  /// @throws std::invalid_argument when params are invalid.
  explicit AffineManeuver(AffineManeuverParams params);

  /// The map at a (possibly fractional) step.
  agents::AffineTransform At(double step) const;
  /// d/dstep of the map at `step` (per step; divide by the step length for per second).
  agents::AffineTransform RatePerStep(double step) const;

  /// Target and its velocity (m/s) of the point whose nominal position is `r`.
  Eigen::Vector2d Target(const Eigen::Vector2d& r, double step) const { return At(step).Apply(r); }
  Eigen::Vector2d TargetVelocity(const Eigen::Vector2d& r, double step, double time_step_s) const;

  int64_t first_step() const { return params_.keyframes.front().step; }
  int64_t last_step() const { return params_.keyframes.back().step; }
  const std::vector<AffineKeyframe>& keyframes() const { return params_.keyframes; }

 private:
  struct Blend {
    size_t from = 0;
    size_t to = 0;
    double h = 0.0;   // smoothstep position in [0, 1]
    double dh = 0.0;  // dh/dstep
  };
  Blend Locate(double step) const;

  AffineManeuverParams params_;
};

}  // namespace dream::affine_formation
