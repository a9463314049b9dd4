#include "dream/agents/hrvo/hrvo_exact.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace dream::agents {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Slack, m/s, for points computed on a wedge leg or box edge: rounding may put
// them a few ulps inside the wedge they border. Physically irrelevant next to
// the safety radius's margin.
constexpr double kTolerance = 1e-9;
// Squared distances (m/s)^2 this close count as a tie (mirror-image
// candidates of a symmetric meeting differ only by rounding).
constexpr double kTieSq = 1e-12;
// The arena test is strict (the thesis's); keep this far inside, m/s.
constexpr double kBoxMargin = 2e-9;

Eigen::Vector2d ClipToDisc(const Eigen::Vector2d& v, double radius) {
  const double norm = v.norm();
  return norm > radius ? Eigen::Vector2d(v * (radius / norm)) : v;
}

// Narrows (lo, hi) to the t with c + t d > 0.
void KeepPositive(double c, double d, double* lo, double* hi) {
  if (d > 0.0) {
    *lo = std::max(*lo, -c / d);
  } else if (d < 0.0) {
    *hi = std::min(*hi, -c / d);
  } else if (c <= 0.0) {
    *hi = -kInf;  // empty
  }
}

// The open stretch (lo, hi) of o + t u inside `cone`.
void Blocked(const HrvoCone& cone, const Eigen::Vector2d& o, const Eigen::Vector2d& u, double* lo, double* hi) {
  *lo = -kInf;
  *hi = kInf;
  const Eigen::Vector2d w0 = o - cone.apex_mps;
  KeepPositive(Cross2(cone.right_leg, w0), Cross2(cone.right_leg, u), lo, hi);
  KeepPositive(-Cross2(cone.left_leg, w0), -Cross2(cone.left_leg, u), lo, hi);
}

bool Finite(const Eigen::Vector2d& v) { return std::isfinite(v.x()) && std::isfinite(v.y()); }

}  // namespace

bool HrvoExactTuning::IsValid(std::string* error) const {
  const auto fail = [error](const char* field, double value, const char* range) {
    if (error != nullptr) {
      std::ostringstream out;
      out << "HrvoExactTuning." << field << " = " << value << " is outside " << range;
      *error = out.str();
    }
    return false;
  };
  if (!std::isfinite(keep_right_rad) || keep_right_rad < 0.0 || keep_right_rad >= M_PI / 2.0) {
    return fail("keep_right_rad", keep_right_rad, "[0, pi/2) rad");
  }
  if (!std::isfinite(wall_margin_m) || wall_margin_m < 0.0 || wall_margin_m > 0.5) {
    return fail("wall_margin_m", wall_margin_m, "[0, 0.5] m");
  }
  return true;
}

HrvoExact::HrvoExact(const HrvoParams& params, const HrvoExactTuning& tuning) : params_(params), tuning_(tuning) {
  std::string error;
  if (!params_.IsValid(&error) || !tuning_.IsValid(&error)) throw std::invalid_argument("HrvoExact: " + error);
  keep_right_cos_ = std::cos(tuning_.keep_right_rad);
  keep_right_sin_ = std::sin(tuning_.keep_right_rad);
}

HrvoExact::Box HrvoExact::ArenaBox(const Eigen::Vector2d& position_m) const {
  if (!params_.check_boundaries) return {Eigen::Vector2d(-kInf, -kInf), Eigen::Vector2d(kInf, kInf)};
  return VelocityBox::KeepingInside(Eigen::Vector2d(params_.x_min_m, params_.y_min_m),
                                    Eigen::Vector2d(params_.x_max_m, params_.y_max_m), position_m,
                                    tuning_.wall_margin_m, params_.boundary_horizon_s, kBoxMargin);
}

bool HrvoExact::InBox(const Box& box, const Eigen::Vector2d& v) const {
  constexpr double kSlack = 1e-12;
  return v.x() >= box.lo.x() - kSlack && v.x() <= box.hi.x() + kSlack && v.y() >= box.lo.y() - kSlack &&
         v.y() <= box.hi.y() + kSlack;
}

bool HrvoExact::Free(const Eigen::Vector2d& v) const {
  for (const HrvoCone& cone : cones_) {
    if (cone.Contains(v, kTolerance)) return false;
  }
  return true;
}

void HrvoExact::Offer(const Eigen::Vector2d& v, const Eigen::Vector2d& target, Best* best) const {
  const double distance_sq = (v - target).squaredNorm();
  // Negative: v is clockwise of (right of) the target velocity.
  const double rightness = Cross2(target, v);
  if (!best->found || distance_sq < best->distance_sq - kTieSq ||
      (distance_sq <= best->distance_sq + kTieSq && rightness < best->rightness)) {
    best->velocity = v;
    best->distance_sq = distance_sq;
    best->rightness = rightness;
    best->found = true;
  }
}

bool HrvoExact::LineRange(const Eigen::Vector2d& o, const Eigen::Vector2d& u, double t_min, const Box& box, double* lo,
                          double* hi) const {
  *lo = t_min;
  *hi = kInf;
  // |o + t u| <= v_max (u is a unit vector).
  const double b = o.dot(u);
  const double discriminant = b * b - (o.squaredNorm() - params_.max_speed_mps * params_.max_speed_mps);
  if (discriminant < 0.0) return false;
  const double root = std::sqrt(discriminant);
  *lo = std::max(*lo, -b - root);
  *hi = std::min(*hi, -b + root);
  for (int k = 0; k < 2; ++k) {
    if (u[k] != 0.0) {
      const double t1 = (box.lo[k] - o[k]) / u[k];
      const double t2 = (box.hi[k] - o[k]) / u[k];
      *lo = std::max(*lo, std::min(t1, t2));
      *hi = std::min(*hi, std::max(t1, t2));
    } else if (o[k] < box.lo[k] || o[k] > box.hi[k]) {
      return false;
    }
  }
  return *lo <= *hi;
}

void HrvoExact::SearchLine(const Eigen::Vector2d& o, const Eigen::Vector2d& u, double lo, double hi, int skip_cone,
                           const Eigen::Vector2d& target, Best* best) {
  // Nearest point of the segment to the target; distance grows with
  // |t - t_nearest| along the line.
  const double t_nearest = std::clamp((target - o).dot(u), lo, hi);
  intervals_.clear();
  for (size_t j = 0; j < cones_.size(); ++j) {
    if (static_cast<int>(j) == skip_cone) continue;  // the line is this wedge's own edge
    double a = 0.0, b = 0.0;
    Blocked(cones_[j], o, u, &a, &b);
    a += kTolerance;
    b -= kTolerance;
    if (a < b && b > lo && a < hi) intervals_.emplace_back(a, b);
  }
  // The nearest free points on either side of t_nearest: step over every
  // blocked stretch holding the current point until none does. Usually one
  // or two passes; never more than one per stretch.
  const auto walk = [&](bool upwards) {
    double t = t_nearest;
    for (bool moved = true; moved;) {
      moved = false;
      for (const auto& [a, b] : intervals_) {
        if (a < t && t < b) {
          t = upwards ? b : a;
          moved = true;
        }
      }
    }
    return t;
  };
  const double up = walk(true);
  if (up == t_nearest) {
    Offer(o + t_nearest * u, target, best);
    return;
  }
  if (up <= hi) Offer(o + up * u, target, best);
  const double down = walk(false);
  if (down >= lo) Offer(o + down * u, target, best);
}

void HrvoExact::CircleCandidates(const Box& box, const Eigen::Vector2d& target) {
  const double v_max = params_.max_speed_mps;
  candidates_.clear();
  if (target.norm() > 0.0) candidates_.push_back(target * (v_max / target.norm()));
  const auto add_ray_crossings = [&](const Eigen::Vector2d& o, const Eigen::Vector2d& u) {
    const double b = o.dot(u);
    const double discriminant = b * b - (o.squaredNorm() - v_max * v_max);
    if (discriminant < 0.0) return;
    const double root = std::sqrt(discriminant);
    for (const double t : {-b - root, -b + root}) {
      if (t >= 0.0) candidates_.push_back(o + t * u);
    }
  };
  for (const HrvoCone& cone : cones_) {
    add_ray_crossings(cone.apex_mps, cone.right_leg);
    add_ray_crossings(cone.apex_mps, cone.left_leg);
  }
  for (int k = 0; k < 2; ++k) {
    for (const double edge : {box.lo[k], box.hi[k]}) {
      if (!(std::abs(edge) <= v_max)) continue;  // also skips infinite edges
      const double other = std::sqrt(v_max * v_max - edge * edge);
      for (const double sign : {-1.0, 1.0}) {
        Eigen::Vector2d point;
        point[k] = edge;
        point[1 - k] = sign * other;
        candidates_.push_back(point);
      }
    }
  }
}

Eigen::Vector2d HrvoExact::LeastPenetrating(const Box& box, const Eigen::Vector2d& target) {
  const double v_max = params_.max_speed_mps;
  // Made to respect speed and arena: the box holds zero and is convex, so
  // shrinking towards zero after clamping stays inside it.
  const auto hard = [&](const Eigen::Vector2d& v) { return ClipToDisc(v.cwiseMax(box.lo).cwiseMin(box.hi), v_max); };
  Eigen::Vector2d best = Eigen::Vector2d::Zero();
  double best_score = kInf;
  double best_distance_sq = kInf;
  const auto consider = [&](const Eigen::Vector2d& raw) {
    const Eigen::Vector2d v = hard(raw);
    double score = 0.0;
    for (const HrvoCone& cone : cones_) {
      score = std::max(score, cone.Penetration(v));
      if (score > best_score + kTieSq) return;  // cannot win
    }
    const double distance_sq = (v - target).squaredNorm();
    if (score < best_score - kTieSq || (score <= best_score + kTieSq && distance_sq < best_distance_sq)) {
      best = v;
      best_score = score;
      best_distance_sq = distance_sq;
    }
  };
  consider(target);
  consider(Eigen::Vector2d::Zero());
  for (const Eigen::Vector2d& v : candidates_) consider(v);
  for (const HrvoCone& cone : cones_) {
    consider(cone.apex_mps);
    for (const Eigen::Vector2d& leg : {cone.right_leg, cone.left_leg}) {
      double lo = 0.0, hi = 0.0;
      if (!LineRange(cone.apex_mps, leg, 0.0, box, &lo, &hi)) continue;
      consider(cone.apex_mps + std::clamp((target - cone.apex_mps).dot(leg), lo, hi) * leg);
      consider(cone.apex_mps + lo * leg);
      consider(cone.apex_mps + hi * leg);
    }
  }
  return best;
}

Eigen::Vector2d HrvoExact::SafeVelocity(const Eigen::Vector2d& position_m, const Eigen::Vector2d& current_velocity_mps,
                                        const Eigen::Vector2d& preferred_velocity_mps,
                                        const std::vector<HrvoNeighbour>& neighbours) {
  last_was_safe_ = true;
  const Eigen::Vector2d preferred = Finite(preferred_velocity_mps) ? preferred_velocity_mps : Eigen::Vector2d::Zero();
  const Eigen::Vector2d current = Finite(current_velocity_mps) ? current_velocity_mps : Eigen::Vector2d::Zero();
  cones_.clear();
  for (const HrvoNeighbour& n : neighbours) {
    if (!Finite(n.relative_position_m) || !Finite(n.velocity_mps)) continue;
    const bool pass_left = HrvoCone::PassesLeft(n.relative_position_m, current, n.velocity_mps);
    cones_.push_back(HrvoCone::Hybrid(n, current, params_.safety_radius_m, pass_left));
  }
  const Box box = ArenaBox(Finite(position_m) ? position_m : Eigen::Vector2d::Zero());
  const double v_max = params_.max_speed_mps;

  // Usually the preferred velocity (at most max speed) is already safe.
  const Eigen::Vector2d clipped = ClipToDisc(preferred, v_max);
  if (InBox(box, clipped) && Free(clipped)) return clipped;

  // Keep right when a neighbour is in the way (not a wall): aim at the
  // preferred velocity turned clockwise.
  Eigen::Vector2d target = preferred;
  if (!Free(clipped)) {
    target = {keep_right_cos_ * preferred.x() + keep_right_sin_ * preferred.y(),
              -keep_right_sin_ * preferred.x() + keep_right_cos_ * preferred.y()};
    const Eigen::Vector2d clipped_target = ClipToDisc(target, v_max);
    if (InBox(box, clipped_target) && Free(clipped_target)) return clipped_target;
  }

  // Every leg and box edge, nearest first: a segment whose nearest point is
  // farther than the best safe velocity found cannot improve on it.
  segments_.clear();
  const auto add_segment = [&](const Eigen::Vector2d& o, const Eigen::Vector2d& u, double t_min, int cone) {
    Segment segment{o, u, 0.0, 0.0, cone, 0.0};
    if (!LineRange(o, u, t_min, box, &segment.lo, &segment.hi)) return;
    const double t = std::clamp((target - o).dot(u), segment.lo, segment.hi);
    segment.bound_sq = (o + t * u - target).squaredNorm();
    segments_.push_back(segment);
  };
  for (size_t i = 0; i < cones_.size(); ++i) {
    add_segment(cones_[i].apex_mps, cones_[i].right_leg, 0.0, static_cast<int>(i));
    add_segment(cones_[i].apex_mps, cones_[i].left_leg, 0.0, static_cast<int>(i));
  }
  if (params_.check_boundaries) {
    for (int k = 0; k < 2; ++k) {
      for (const double edge : {box.lo[k], box.hi[k]}) {
        Eigen::Vector2d o = Eigen::Vector2d::Zero();
        o[k] = edge;
        Eigen::Vector2d u = Eigen::Vector2d::Zero();
        u[1 - k] = 1.0;
        add_segment(o, u, -kInf, -1);
      }
    }
  }
  std::sort(segments_.begin(), segments_.end(),
            [](const Segment& a, const Segment& b) { return a.bound_sq < b.bound_sq; });
  Best best;
  for (const Segment& segment : segments_) {
    if (best.found && segment.bound_sq > best.distance_sq + kTieSq) break;
    SearchLine(segment.origin, segment.direction, segment.lo, segment.hi, segment.cone, target, &best);
  }
  CircleCandidates(box, target);
  for (const Eigen::Vector2d& v : candidates_) {
    if (best.found && (v - target).squaredNorm() > best.distance_sq + kTieSq) continue;
    if (InBox(box, v) && Free(v)) Offer(v, target, &best);
  }
  if (best.found) return best.velocity;
  last_was_safe_ = false;
  return LeastPenetrating(box, target);
}

}  // namespace dream::agents
