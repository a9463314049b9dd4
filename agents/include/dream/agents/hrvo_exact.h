#pragma once

#include <Eigen/Core>
#include <string>
#include <utility>
#include <vector>

#include "dream/agents/hrvo_avoidance.h"
#include "dream/agents/hrvo_cone.h"
#include "dream/agents/hrvo_params.h"

namespace dream::agents {

/// HRVO (Snape et al. 2011) without sampling: the exact velocity closest to
/// the preferred one among those that are
///   - outside every neighbour's HrvoCone::Hybrid wedge,
///   - within max speed,
///   - (if enabled) such that position + boundary_horizon_s * v stays inside
///     the arena (a robot already outside may still stop or move back in).
/// That set is closed, so its nearest point to the preferred velocity is the
/// preferred velocity itself or lies on its boundary: on a wedge leg, an
/// arena-box edge or the speed circle. Each leg and box edge is searched
/// exactly (the stretches other wedges block are intervals along it); the
/// circle's candidates are the preferred direction and its crossings with the
/// legs and edges. Equally near candidates (a symmetric head-on meeting) go to
/// the one on the right of the preferred velocity, so a pair facing each
/// other both keep right.
///
/// When no safe velocity exists (crowded), it returns the candidate whose
/// deepest penetration into any wedge is smallest, so robots keep moving
/// away from the worst conflict instead of freezing.
///
/// Cost: O(n) when the preferred velocity is safe, else O(n^2 log n) for n
/// neighbours (n intervals sorted on each of 2n legs). Scratch vectors are
/// reused, so after the first calls it does not allocate.
class HrvoExact final : public HrvoAvoidance {
 public:
  /// @throws std::invalid_argument when params are invalid.
  explicit HrvoExact(const HrvoParams& params = {});

  Eigen::Vector2d SafeVelocity(const Eigen::Vector2d& position_m, const Eigen::Vector2d& current_velocity_mps,
                               const Eigen::Vector2d& preferred_velocity_mps,
                               const std::vector<HrvoNeighbour>& neighbours) override;

  /// Whether the last SafeVelocity found a safe velocity (false: it fell back
  /// to the least-penetrating one).
  bool last_was_safe() const { return last_was_safe_; }
  /// The wedges of the last call, one per neighbour, in order.
  const std::vector<HrvoCone>& last_cones() const { return cones_; }
  const HrvoParams& params() const { return params_; }

 private:
  struct Box {
    Eigen::Vector2d lo;
    Eigen::Vector2d hi;
  };
  struct Best {
    Eigen::Vector2d velocity = Eigen::Vector2d::Zero();
    double distance_sq = 0.0;
    double rightness = 0.0;
    bool found = false;
  };

  Box VelocityBox(const Eigen::Vector2d& position_m) const;
  bool InBox(const Box& box, const Eigen::Vector2d& v) const;
  bool Free(const Eigen::Vector2d& v, int skip_cone) const;
  void Offer(const Eigen::Vector2d& v, const Eigen::Vector2d& preferred, Best* best) const;
  // Allowed parameter range of o + t u: inside the speed disc and the box, t >= t_min.
  bool LineRange(const Eigen::Vector2d& o, const Eigen::Vector2d& u, double t_min, const Box& box, double* lo,
                 double* hi) const;
  void SearchLine(const Eigen::Vector2d& o, const Eigen::Vector2d& u, double lo, double hi, int skip_cone,
                  const Eigen::Vector2d& preferred, Best* best);
  void CircleCandidates(const Box& box, const Eigen::Vector2d& preferred);
  Eigen::Vector2d LeastPenetrating(const Box& box, const Eigen::Vector2d& preferred);

  HrvoParams params_;
  bool last_was_safe_ = true;
  std::vector<HrvoCone> cones_;                        // scratch: one wedge per neighbour
  std::vector<std::pair<double, double>> intervals_;  // scratch: blocked stretches of one line
  std::vector<Eigen::Vector2d> candidates_;           // scratch: points on the speed circle
};

}  // namespace dream::agents
