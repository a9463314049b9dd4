#include "dream/agents/hrvo/hrvo_thesis.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace dream::agents {
namespace {

// One of the thesis's leg lines, a x + b y + c = 0, written so that the
// wedge test is  mat . v < vec  for both rows (numpy: hrvo_mat @ v < hrvo_vec).
struct Row {
  double m0 = 0.0;
  double m1 = 0.0;
  double vec = 0.0;
};

// np.cross([0, 0, 1], [cos phi, sin phi]) = (-sin phi, cos phi, 0), then
// translated by temp_mat_ so the line passes through `apex`.
void LegLine(double phi_rad, double apex_x, double apex_y, double* a, double* b, double* c) {
  *a = -std::sin(phi_rad);
  *b = std::cos(phi_rad);
  *c = -apex_x * *a + -apex_y * *b;
}

// numpy's linspace(start, stop, num): i * ((stop - start) / (num - 1)) + start,
// with the last element exactly stop.
double Linspace(double start, double stop, int num, int i) {
  if (i == num - 1) return stop;
  return static_cast<double>(i) * ((stop - start) / static_cast<double>(num - 1)) + start;
}

// The two half-planes of one neighbour's HRVO; a velocity inside both is refused.
struct Wedge {
  Row left;
  Row right;
};

// Appendix A, for one detection: "Create VO triangle" (both legs through the
// neighbour's velocity), then "RVO" and "HRVO" (legs through the mean of both
// velocities; the one nearer the current velocity dxi replaces its VO leg).
Wedge HrvoWedge(const HrvoNeighbour& n, double safety, double dxi0, double dxi1) {
  // The thesis's movement sensor reports the angle from the neighbour to
  // this robot; its half-plane signs then select the wedge around angle + pi,
  // which points at the neighbour (docs/hrvo.md).
  double obst_dist = n.relative_position_m.norm();
  const double obst_angl = std::atan2(-n.relative_position_m.y(), -n.relative_position_m.x());
  const double obst_velx = n.velocity_mps.x();
  const double obst_vely = n.velocity_mps.y();
  obst_dist = obst_dist > safety ? obst_dist : safety;
  const double obst_phi = std::asin(safety / obst_dist);
  const double phi_l = obst_angl + obst_phi;
  const double phi_r = obst_angl - obst_phi;

  // VO: both legs through the neighbour's velocity.
  double a = 0.0, b = 0.0, c = 0.0;
  Row left, right;
  LegLine(phi_l, obst_velx, obst_vely, &a, &b, &c);
  left = {-a, -b, c};
  LegLine(phi_r, obst_velx, obst_vely, &a, &b, &c);
  right = {a, b, -c};

  // RVO lines through the mean of both velocities; the one nearer the
  // current velocity replaces its VO leg (HRVO).
  const double rvo_x = (obst_velx + dxi0) / 2.0;
  const double rvo_y = (obst_vely + dxi1) / 2.0;
  double al = 0.0, bl = 0.0, cl = 0.0, ar = 0.0, br = 0.0, cr = 0.0;
  LegLine(phi_l, rvo_x, rvo_y, &al, &bl, &cl);
  LegLine(phi_r, rvo_x, rvo_y, &ar, &br, &cr);
  const double dist_l = std::abs(al * dxi0 + bl * dxi1 + cl) / std::sqrt(al * al + bl * bl);
  const double dist_r = std::abs(ar * dxi0 + br * dxi1 + cr) / std::sqrt(ar * ar + br * br);
  // An exact tie (own velocity on the centre line, or overlapping robots,
  // whose legs coincide) keeps both VO legs. In numpy the tie is decided by
  // the last bit of sin/cos, which differs between numpy's SIMD code and
  // libm, so ties within rounding count as ties here.
  const double tie = 1e-12 * std::max(1.0, dist_l + dist_r);
  if (dist_l < dist_r - tie) left = {-al, -bl, cl};
  if (dist_l > dist_r + tie) right = {ar, br, -cr};
  return {left, right};
}

// Appendix A, "Search for valid velocities" for one detection: drops the kept
// samples inside `wedge` (hrvo_mat_ @ v < hrvo_vec_); whether any are left.
bool RemoveSamplesInside(const Wedge& wedge, const std::vector<Eigen::Vector2d>& samples, std::vector<char>* keep) {
  const Row& left = wedge.left;
  const Row& right = wedge.right;
  bool any_left = false;
  for (size_t k = 0; k < samples.size(); ++k) {
    if (!(*keep)[k]) continue;
    const Eigen::Vector2d& v = samples[k];
    const bool inside = left.m0 * v.x() + left.m1 * v.y() < left.vec && right.m0 * v.x() + right.m1 * v.y() < right.vec;
    if (inside) {
      (*keep)[k] = 0;
    } else {
      any_left = true;
    }
  }
  return any_left;
}

// Appendix A, "if self.check_boundaries": drops the kept samples that would
// leave the arena within the horizon; an empty set becomes {zero}.
void KeepSamplesInsideBoundaries(const HrvoParams& params, const Eigen::Vector2d& position_m,
                                 const std::vector<Eigen::Vector2d>& samples, std::vector<char>* keep) {
  bool any_inside = false;
  for (size_t k = 0; k < samples.size(); ++k) {
    if (!(*keep)[k]) continue;
    // The thesis adds 1 s of velocity (v * 1.0 is exactly v).
    const double xh = samples[k].x() * params.boundary_horizon_s + position_m.x();
    const double yh = samples[k].y() * params.boundary_horizon_s + position_m.y();
    if (params.x_min_m < xh && xh < params.x_max_m && params.y_min_m < yh && yh < params.y_max_m) {
      any_inside = true;
    } else {
      (*keep)[k] = 0;
    }
  }
  if (!any_inside) keep->back() = 1;
}

// Appendix A, "min_index = np.where(norm == np.amin(norm))[0][0]": the first
// kept sample nearest the preferred velocity. Mirror-image samples tie up to
// the last bit of sin/cos (numpy's and libm's differ there), so norms within
// rounding count as equal and the lower index wins, as it does for exact ties
// in numpy.
size_t NearestSample(const Eigen::Vector2d& preferred_velocity_mps, const std::vector<Eigen::Vector2d>& samples,
                     const std::vector<char>& keep) {
  size_t best = samples.size() - 1;
  double best_norm = INFINITY;
  for (size_t k = 0; k < samples.size(); ++k) {
    if (!keep[k]) continue;
    const double dx = samples[k].x() - preferred_velocity_mps.x();
    const double dy = samples[k].y() - preferred_velocity_mps.y();
    const double norm = std::sqrt(dx * dx + dy * dy);
    if (best_norm == INFINITY || norm < best_norm - 1e-12 * std::max(1.0, best_norm)) {
      best_norm = norm;
      best = k;
    }
  }
  return best;
}

}  // namespace

HrvoThesis::HrvoThesis(const HrvoParams& params) : params_(params) {
  std::string error;
  if (!params_.IsValid(&error)) throw std::invalid_argument("HrvoThesis: " + error);
  // np.meshgrid(vel, th) flattened row-major: heading-major, then speed.
  samples_.reserve(kNumSamples);
  for (int h = 0; h < kNumHeadings; ++h) {
    const double th = Linspace(0.0, 2.0 * M_PI, kNumHeadings, h);
    for (int s = 0; s < kNumSpeeds; ++s) {
      const double vel = Linspace(0.0, params_.max_speed_mps, kNumSpeeds, s);
      samples_.emplace_back(vel * std::cos(th), vel * std::sin(th));
    }
  }
  samples_.emplace_back(0.0, 0.0);
  keep_.assign(samples_.size(), 1);
}

Eigen::Vector2d HrvoThesis::SafeVelocity(const Eigen::Vector2d& position_m, const Eigen::Vector2d& current_velocity_mps,
                                         const Eigen::Vector2d& preferred_velocity_mps,
                                         const std::vector<HrvoNeighbour>& neighbours) {
  const double safety = params_.safety_radius_m;
  const double dxi0 = current_velocity_mps.x();
  const double dxi1 = current_velocity_mps.y();
  std::fill(keep_.begin(), keep_.end(), 1);
  bool any_left = true;
  for (const HrvoNeighbour& n : neighbours) {
    const Wedge wedge = HrvoWedge(n, safety, dxi0, dxi1);
    if (!any_left) continue;  // (the thesis would raise IndexError here)
    any_left = RemoveSamplesInside(wedge, samples_, &keep_);
  }
  // An empty set becomes {zero}: the last sample is zero, keep only it.
  if (!any_left) keep_.back() = 1;

  if (params_.check_boundaries) KeepSamplesInsideBoundaries(params_, position_m, samples_, &keep_);

  Eigen::Vector2d out = samples_[NearestSample(preferred_velocity_mps, samples_, keep_)];
  const double limit_norm = out.norm();
  if (limit_norm > params_.max_speed_mps) out *= params_.max_speed_mps / limit_norm;
  return out;
}

}  // namespace dream::agents
