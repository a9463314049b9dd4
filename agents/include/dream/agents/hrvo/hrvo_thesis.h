#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "dream/agents/hrvo/hrvo_avoidance.h"
#include "dream/agents/hrvo/hrvo_params.h"

namespace dream::agents {

/// The thesis's Robot_hrvo.HRVO (Appendix A.1), ported line by line so it
/// reproduces the thesis robots' choices (agents/hrvo/reference/thesis_hrvo.py
/// is the numpy transcription the tests check it against; docs/hrvo.md has
/// the details):
///  - per neighbour, two leg lines at bearing +/- asin(R / max(d, R)) through
///    the neighbour's velocity (VO); the leg whose reciprocal line (through the
///    mean of own current and neighbour velocity) is nearer own current
///    velocity is replaced by that reciprocal line (HRVO); an exact tie keeps
///    both VO legs;
///  - 201 candidates: 20 headings linspace(0, 2 pi, 20) (0 and 2 pi both, so
///    19 distinct) x 10 speeds linspace(0, v_max, 10), plus zero;
///  - drop candidates strictly inside any neighbour's wedge, then (if
///    enabled) those not strictly inside the arena after boundary_horizon_s;
///    an empty set becomes {zero} after each filter;
///  - return the first candidate nearest the preferred velocity, clipped to
///    max speed.
/// Where the thesis compares equal quantities (mirror-image samples, legs
/// of overlapping robots), numpy's result hangs on the last bit of its own
/// sin/cos; here differences below 1e-12 count as ties (both VO legs, lowest
/// sample index), as exact arithmetic would have it.
/// The thesis crashes (IndexError) when a neighbour other than the last
/// removes every candidate; here the set stays empty and the result is zero.
class HrvoThesis final : public HrvoAvoidance {
 public:
  static constexpr int kNumHeadings = 20;
  static constexpr int kNumSpeeds = 10;
  static constexpr int kNumSamples = kNumHeadings * kNumSpeeds + 1;

  /// @throws std::invalid_argument when params are invalid.
  explicit HrvoThesis(const HrvoParams& params = {});

  Eigen::Vector2d SafeVelocity(const Eigen::Vector2d& position_m, const Eigen::Vector2d& current_velocity_mps,
                               const Eigen::Vector2d& preferred_velocity_mps,
                               const std::vector<HrvoNeighbour>& neighbours) override;

  /// Candidate `index` in the thesis's order (heading-major, zero last).
  const Eigen::Vector2d& sample(int index) const { return samples_[static_cast<size_t>(index)]; }
  const HrvoParams& params() const { return params_; }

 private:
  HrvoParams params_;
  std::vector<Eigen::Vector2d> samples_;
  std::vector<char> keep_;  // scratch: which samples survive
};

}  // namespace dream::agents
