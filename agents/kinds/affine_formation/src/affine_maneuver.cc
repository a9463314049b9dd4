#include "dream/affine_formation/affine_maneuver.h"

#include <cmath>
#include <stdexcept>

#include "dream/agents/framework/params_check.h"

namespace dream::affine_formation {
namespace {

Eigen::Matrix2d Rotation(double angle_rad) {
  Eigen::Matrix2d r;
  r << std::cos(angle_rad), -std::sin(angle_rad), std::sin(angle_rad), std::cos(angle_rad);
  return r;
}

// dR/dangle
Eigen::Matrix2d RotationDerivative(double angle_rad) {
  Eigen::Matrix2d r;
  r << -std::sin(angle_rad), -std::cos(angle_rad), std::cos(angle_rad), -std::sin(angle_rad);
  return r;
}

double Lerp(double a, double b, double h) { return a + (b - a) * h; }

}  // namespace

agents::AffineTransform AffineKeyframe::Transform() const {
  agents::AffineTransform transform;
  transform.linear = Eigen::Vector2d(scale_x, scale_y).asDiagonal() * Rotation(rotation_rad);
  transform.translation_m = translation_m;
  return transform;
}

bool AffineManeuverParams::IsValid(std::string* error) const {
  if (keyframes.empty()) return agents::FailParams(error, "keyframes: need at least one keyframe");
  if (keyframes.size() > kMaxKeyframes) {
    return agents::FailParams(
        error, "keyframes: at most " + std::to_string(kMaxKeyframes) + ", got " + std::to_string(keyframes.size()));
  }
  for (size_t k = 0; k < keyframes.size(); ++k) {
    const AffineKeyframe& f = keyframes[k];
    const std::string where = "keyframes[" + std::to_string(k) + "].";
    if (f.step < 0) return agents::FailParams(error, where + "step must be >= 0, got " + std::to_string(f.step));
    if (k > 0 && f.step <= keyframes[k - 1].step) {
      return agents::FailParams(error, where + "step must be greater than the previous keyframe's (" +
                                           std::to_string(keyframes[k - 1].step) + "), got " + std::to_string(f.step));
    }
    if (!agents::CheckPositive(error, where + "scale_x", f.scale_x) ||
        !agents::CheckPositive(error, where + "scale_y", f.scale_y)) {
      return false;
    }
    if (!std::isfinite(f.rotation_rad)) return agents::FailParams(error, where + "rotation_rad must be finite");
    if (!f.translation_m.allFinite()) return agents::FailParams(error, where + "translation must be finite");
  }
  return true;
}

AffineManeuver::AffineManeuver(AffineManeuverParams params) : params_(std::move(params)) {
  std::string error;
  if (!params_.IsValid(&error)) throw std::invalid_argument(error);
}

AffineManeuver::Blend AffineManeuver::Locate(double step) const {
  const auto& keys = params_.keyframes;
  Blend blend;
  if (keys.size() == 1 || step <= double(keys.front().step)) return blend;
  if (step >= double(keys.back().step)) {
    blend.from = blend.to = keys.size() - 1;
    return blend;
  }
  size_t k = 0;
  while (double(keys[k + 1].step) <= step) ++k;
  const double span = double(keys[k + 1].step - keys[k].step);
  const double u = (step - double(keys[k].step)) / span;
  blend.from = k;
  blend.to = k + 1;
  blend.h = u * u * (3.0 - 2.0 * u);
  blend.dh = 6.0 * u * (1.0 - u) / span;
  return blend;
}

agents::AffineTransform AffineManeuver::At(double step) const {
  const Blend b = Locate(step);
  const AffineKeyframe& f0 = params_.keyframes[b.from];
  const AffineKeyframe& f1 = params_.keyframes[b.to];
  AffineKeyframe now;
  now.scale_x = Lerp(f0.scale_x, f1.scale_x, b.h);
  now.scale_y = Lerp(f0.scale_y, f1.scale_y, b.h);
  now.rotation_rad = Lerp(f0.rotation_rad, f1.rotation_rad, b.h);
  now.translation_m = f0.translation_m + (f1.translation_m - f0.translation_m) * b.h;
  return now.Transform();
}

agents::AffineTransform AffineManeuver::RatePerStep(double step) const {
  const Blend b = Locate(step);
  const AffineKeyframe& f0 = params_.keyframes[b.from];
  const AffineKeyframe& f1 = params_.keyframes[b.to];
  const Eigen::Vector2d scale(Lerp(f0.scale_x, f1.scale_x, b.h), Lerp(f0.scale_y, f1.scale_y, b.h));
  const Eigen::Vector2d scale_rate = Eigen::Vector2d(f1.scale_x - f0.scale_x, f1.scale_y - f0.scale_y) * b.dh;
  const double angle = Lerp(f0.rotation_rad, f1.rotation_rad, b.h);
  const double angle_rate = (f1.rotation_rad - f0.rotation_rad) * b.dh;
  agents::AffineTransform rate;
  // d(S R)/dt = S' R + S R' angle'
  rate.linear = scale_rate.asDiagonal() * Rotation(angle) +
                Eigen::Matrix2d(scale.asDiagonal() * RotationDerivative(angle)) * angle_rate;
  rate.translation_m = (f1.translation_m - f0.translation_m) * b.dh;
  return rate;
}

Eigen::Vector2d AffineManeuver::TargetVelocity(const Eigen::Vector2d& r, double step, double time_step_s) const {
  return RatePerStep(step).Apply(r) / time_step_s;
}

}  // namespace dream::affine_formation
