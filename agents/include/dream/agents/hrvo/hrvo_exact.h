#pragma once

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "dream/agents/hrvo/hrvo_avoidance.h"
#include "dream/agents/hrvo/hrvo_cone.h"
#include "dream/agents/geometry/velocity_box.h"
#include "dream/agents/hrvo/hrvo_params.h"

namespace dream::agents {

/// HrvoExact's own choices beyond HrvoParams.
struct HrvoExactTuning {
  /// Traffic rule: when the preferred velocity is unsafe, look for the safe
  /// velocity nearest the preferred one turned this far clockwise (to the
  /// right). Every robot keeps right, so a symmetric jam (the circle swap's
  /// crowded centre) turns into a roundabout instead of a standstill; 0 gives
  /// the plain nearest safe velocity. [0, pi/2) rad; 0.7 (40 deg) was the
  /// best of 0 .. 1 in the circle swap and random crossings (docs/hrvo.md).
  double keep_right_rad = 0.7;
  /// With the arena check on, keep position + horizon * v this far inside
  /// the arena. An exact answer rides that constraint when a robot slides
  /// along a wall, and a unicycle, moving along its heading rather than the
  /// asked velocity, drifts across it by a centimetre or two. [0, 0.5] m.
  double wall_margin_m = 0.05;

  /// False with a message naming the field, its value and the allowed range.
  bool IsValid(std::string* error) const;
};

/// HRVO (Snape et al. 2011) without sampling: the exact velocity nearest the
/// target among those that are
///   - outside every neighbour's HrvoCone::Hybrid wedge (side chosen from the
///     current velocity, as in the HRVO paper and the thesis),
///   - within max speed,
///   - (if enabled) such that position + boundary_horizon_s * v stays
///     wall_margin_m inside the arena (a robot already closer to the edge may
///     still stop or move back in, never further out).
/// The target is the preferred velocity; when that is unsafe, the preferred
/// velocity turned HrvoExactTuning::keep_right_rad clockwise.
///
/// That set is closed, so its nearest point to the target is the target
/// itself or lies on its boundary: on a wedge leg, an arena-box edge or the
/// speed circle. Each leg and box edge is searched exactly (the stretches
/// other wedges block are intervals along it); the circle's candidates are
/// the target's direction and its crossings with the legs and edges. Equally
/// near candidates go to the one on the right, so even with keep_right_rad 0
/// a pair meeting exactly head-on both keep right.
///
/// When no velocity is safe (crowded), it returns the candidate whose deepest
/// penetration into any wedge is smallest, so a robot keeps moving away from
/// the worst conflict instead of freezing.
///
/// Cost: O(n) when the preferred velocity is safe, else O(n^2) for n
/// neighbours in practice (n blocked stretches on each of 2n legs; stepping
/// over chained stretches is O(n^3) only in a contrived worst case). Legs are
/// searched nearest first and the search stops at the first leg that cannot
/// beat the best answer so far. No trigonometry.
/// Scratch vectors are reused, so after the first calls it does not allocate.
class HrvoExact final : public HrvoAvoidance {
 public:
  /// @throws std::invalid_argument when params are invalid.
  explicit HrvoExact(const HrvoParams& params = {}, const HrvoExactTuning& tuning = {});

  Eigen::Vector2d SafeVelocity(const Eigen::Vector2d& position_m, const Eigen::Vector2d& current_velocity_mps,
                               const Eigen::Vector2d& preferred_velocity_mps,
                               const std::vector<HrvoNeighbour>& neighbours) override;

  /// Whether the last SafeVelocity found a safe velocity (false: it took the
  /// least-penetrating one).
  bool last_was_safe() const { return last_was_safe_; }
  /// The wedges of the last call, one per neighbour, in order.
  const std::vector<HrvoCone>& last_cones() const { return cones_; }
  const HrvoParams& params() const { return params_; }
  const HrvoExactTuning& tuning() const { return tuning_; }

 private:
  using Box = VelocityBox;
  // A stretch o + t u, t in [lo, hi], of a wedge leg (cone = its index) or a
  // box edge (cone = -1); bound_sq: its nearest point's squared distance to
  // the target.
  struct Segment {
    Eigen::Vector2d origin;
    Eigen::Vector2d direction;
    double lo;
    double hi;
    int cone;
    double bound_sq;
  };
  struct Best {
    Eigen::Vector2d velocity = Eigen::Vector2d::Zero();
    double distance_sq = 0.0;
    double rightness = 0.0;
    bool found = false;
  };

  Box ArenaBox(const Eigen::Vector2d& position_m) const;
  bool InBox(const Box& box, const Eigen::Vector2d& v) const;
  bool Free(const Eigen::Vector2d& v) const;
  void Offer(const Eigen::Vector2d& v, const Eigen::Vector2d& target, Best* best) const;
  // Allowed parameter range of o + t u: inside the speed disc and the box, t >= t_min.
  bool LineRange(const Eigen::Vector2d& o, const Eigen::Vector2d& u, double t_min, const Box& box, double* lo,
                 double* hi) const;
  void SearchLine(const Eigen::Vector2d& o, const Eigen::Vector2d& u, double lo, double hi, int skip_cone,
                  const Eigen::Vector2d& target, Best* best);
  void CircleCandidates(const Box& box, const Eigen::Vector2d& target);
  Eigen::Vector2d LeastPenetrating(const Box& box, const Eigen::Vector2d& target);

  HrvoParams params_;
  HrvoExactTuning tuning_;
  double keep_right_cos_ = 1.0;  // the keep-right rotation, computed once
  double keep_right_sin_ = 0.0;
  bool last_was_safe_ = true;
  std::vector<HrvoCone> cones_;                       // scratch: one wedge per neighbour
  std::vector<std::pair<double, double>> intervals_;  // scratch: blocked stretches of one line
  std::vector<Eigen::Vector2d> candidates_;           // scratch: points on the speed circle
  std::vector<Segment> segments_;                     // scratch: legs and edges to search
};

}  // namespace dream::agents
