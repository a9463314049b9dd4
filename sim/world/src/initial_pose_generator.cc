#include "dream/world/initial_pose_generator.h"

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <unordered_map>

#include "field_check.h"

namespace dream::world {
namespace {

constexpr double kPi = 3.14159265358979323846;

// std::uniform_real_distribution differs between standard libraries; this
// does not: the top 53 bits of one draw, scaled into [0, 1).
double UnitUniform(std::mt19937_64& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// Occupied cells so each candidate checks only a 5 x 5 neighbourhood. The
// cell is spacing / 1.5: its diagonal (0.94 spacing) is shorter than the
// spacing, so a cell holds at most one accepted point, and two cells reach
// 1.33 spacing, so every point closer than the spacing is looked at.
class SpacingGrid {
 public:
  explicit SpacingGrid(double spacing_m) : spacing_m_(spacing_m), cell_m_(spacing_m / 1.5) {}

  bool IsFree(double x_m, double y_m, const std::vector<Pose2>& placed) const {
    const int64_t cx = Cell(x_m);
    const int64_t cy = Cell(y_m);
    for (int64_t dx = -2; dx <= 2; ++dx) {
      for (int64_t dy = -2; dy <= 2; ++dy) {
        const auto it = cells_.find(Key(cx + dx, cy + dy));
        if (it == cells_.end()) continue;
        const Pose2& other = placed[it->second];
        if (std::hypot(other.x_m - x_m, other.y_m - y_m) < spacing_m_) return false;
      }
    }
    return true;
  }

  void Add(double x_m, double y_m, std::size_t index) { cells_[Key(Cell(x_m), Cell(y_m))] = index; }

 private:
  int64_t Cell(double coordinate_m) const { return static_cast<int64_t>(std::floor(coordinate_m / cell_m_)); }
  static uint64_t Key(int64_t cx, int64_t cy) {
    return (static_cast<uint64_t>(cx) << 32) ^ (static_cast<uint64_t>(cy) & 0xffffffffu);
  }

  double spacing_m_;
  double cell_m_;
  std::unordered_map<uint64_t, std::size_t> cells_;
};

std::string Metres(double value) { return field_check::FormatValue(value); }

// Every check of the constructor's arguments, before the members are built.
const WorldParams& ValidatedWorld(const WorldParams& world, const InitialPoseParams& params) {
  field_check::Checked("InitialPoseGenerator", world);
  field_check::Checked("InitialPoseGenerator", params);
  // Two robots facing each other have collision centres spacing - 2 * offset
  // apart; that must stay above the collision diameter.
  const double min_safe_spacing_m = world.collision_diameter_m + 2.0 * world.collision_offset_m;
  if (!(params.min_spacing_m > min_safe_spacing_m)) {
    throw std::invalid_argument("InitialPoseGenerator: " + field_check::FormatValue(params.min_spacing_m) +
                                " m for initial_poses.generate.min_spacing_m is out of range; allowed: > "
                                "collision_diameter_m + 2 * collision_offset_m = " +
                                Metres(min_safe_spacing_m) + " m");
  }
  if (2.0 * params.wall_margin_m >= world.arena.width_m() || 2.0 * params.wall_margin_m >= world.arena.height_m()) {
    throw std::invalid_argument(
        "InitialPoseGenerator: initial_poses.generate.wall_margin_m = " + Metres(params.wall_margin_m) +
        " is out of range; allowed: less than half the arena's width and height (" + Metres(world.arena.width_m()) +
        " x " + Metres(world.arena.height_m()) + " m)");
  }
  return world;
}

}  // namespace

InitialPoseGenerator::InitialPoseGenerator(const WorldParams& world, const InitialPoseParams& params,
                                           const std::vector<RectangleObstacleSpec>& obstacles)
    : world_(ValidatedWorld(world, params)), params_(params), obstacle_check_(world, obstacles) {}

std::vector<Pose2> InitialPoseGenerator::Generate(int num_robots, uint64_t seed) const {
  if (num_robots < 0) {
    throw std::invalid_argument("InitialPoseGenerator::Generate: num_robots = " + std::to_string(num_robots) +
                                " is out of range; allowed: >= 0");
  }
  const double x_min_m = world_.arena.x_min_m + params_.wall_margin_m;
  const double y_min_m = world_.arena.y_min_m + params_.wall_margin_m;
  const double width_m = world_.arena.width_m() - 2.0 * params_.wall_margin_m;
  const double height_m = world_.arena.height_m() - 2.0 * params_.wall_margin_m;
  const double spacing_m = params_.min_spacing_m;
  const std::string where = " with min_spacing_m = " + Metres(spacing_m) + " in the " + Metres(width_m) + " x " +
                            Metres(height_m) + " m area inside wall_margin_m = " + Metres(params_.wall_margin_m);

  // Discs of diameter `spacing` around the points are disjoint and lie in the
  // area grown by spacing / 2 on every side; no packing beats the hexagonal
  // density pi / (2 sqrt 3). Beyond that bound, fail at once.
  const double packing_bound =
      (width_m + spacing_m) * (height_m + spacing_m) * 2.0 / (std::sqrt(3.0) * spacing_m * spacing_m);
  if (static_cast<double>(num_robots) > packing_bound) {
    throw std::invalid_argument("InitialPoseGenerator: cannot place " + std::to_string(num_robots) + " robots" + where +
                                ": even a perfect hexagonal packing holds at most " +
                                std::to_string(static_cast<int64_t>(packing_bound)) +
                                "; use a smaller min_spacing_m or fewer robots");
  }

  std::mt19937_64 rng(seed);
  std::vector<Pose2> poses;
  poses.reserve(static_cast<std::size_t>(num_robots));
  SpacingGrid grid(spacing_m);
  const int64_t max_attempts = static_cast<int64_t>(num_robots) * params_.max_attempts_per_robot;
  int64_t attempts = 0;
  int64_t too_close = 0;          // candidates within min_spacing_m of a placed robot
  int64_t touching_obstacle = 0;  // candidates whose collision disc touched an obstacle
  while (static_cast<int>(poses.size()) < num_robots && attempts < max_attempts) {
    ++attempts;
    const double x_m = x_min_m + UnitUniform(rng) * width_m;
    const double y_m = y_min_m + UnitUniform(rng) * height_m;
    if (!grid.IsFree(x_m, y_m, poses)) {
      ++too_close;
      continue;
    }
    // UnitUniform < 1, so theta < pi up to rounding; fold the rare pi back.
    double theta_rad = -kPi + UnitUniform(rng) * (2.0 * kPi);
    if (theta_rad >= kPi) theta_rad = -kPi;
    // The disc's centre depends on the heading, so obstacles are checked
    // after it is drawn; a refusal costs this candidate's three draws only.
    const Pose2 pose{x_m, y_m, theta_rad};
    if (obstacle_check_.FirstTouchedObstacle(pose) >= 0) {
      ++touching_obstacle;
      continue;
    }
    grid.Add(x_m, y_m, poses.size());
    poses.push_back(pose);
  }
  if (static_cast<int>(poses.size()) < num_robots) {
    std::string refusals;
    std::string advice = "use a smaller min_spacing_m or fewer robots";
    if (obstacle_check_.has_obstacles()) {
      refusals = " (" + std::to_string(touching_obstacle) + " touched an obstacle, " + std::to_string(too_close) +
                 " were closer than min_spacing_m to a placed robot)";
      advice = "use smaller or fewer obstacles, a smaller min_spacing_m or wall_margin_m, or fewer robots";
    }
    throw std::invalid_argument("InitialPoseGenerator: placed only " + std::to_string(poses.size()) + " of " +
                                std::to_string(num_robots) + " robots" + where + " after " + std::to_string(attempts) +
                                " random attempts" + refusals + "; " + advice);
  }
  return poses;
}

}  // namespace dream::world
