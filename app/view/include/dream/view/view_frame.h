#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dream/lcm/drawn_shape.h"
#include "dream/run_status_t.hpp"
#include "dream/view/step_metrics.h"
#include "dream/view/violation_mark.h"

namespace dream::view {

/// What the page draws of one step of a run: the newest state seen on the
/// bus, as BusFrameCollector keeps it and FrameJson() sends it.
struct ViewFrame {
  /// A virtual obstacle where it is at the frame's step (rectangle_obstacle_t).
  struct Obstacle {
    int id = 0;
    double center_x_m = 0.0;
    double center_y_m = 0.0;
    double width_m = 0.0;
    double height_m = 0.0;
    double vx_mps = 0.0;
    double vy_mps = 0.0;
  };
  /// DREAM_STATUS as last seen (run_status_t), for the verdict so far.
  struct Status {
    bool seen = false;
    int state = 0;  ///< run_status_t::WAITING_FOR_AGENTS .. ABORTED
    int64_t boundary_errors = 0;
    int64_t collision_errors = 0;
    int64_t actuator_errors = 0;
    int64_t obstacle_collisions = 0;
    int64_t rejected_commands = 0;
    int64_t command_conflicts = 0;
    std::vector<int> lost_robot_ids;
    std::string detail;  ///< cut to kMaxDetailChars

    /// A DREAM_STATUS message as the page reads it (seen, the detail cut).
    static Status Of(const run_status_t& message);
  };
  static constexpr size_t kMaxDetailChars = 300;
  /// A second world on the bus: another run heard lately, not drawn (RunChoice).
  struct OtherWorld {
    int64_t run_id = 0;  ///< the other run heard last
    int64_t step = -1;   ///< its newest step heard; -1: none
    int state = -1;      ///< its newest DREAM_STATUS state; -1: none heard
    int runs = 0;        ///< other runs heard lately, this one included
    bool operator==(const OtherWorld& other) const {
      return run_id == other.run_id && step == other.step && state == other.state && runs == other.runs;
    }
    bool operator!=(const OtherWorld& other) const { return !(*this == other); }
  };

  int64_t run_id = 0;
  int64_t step = -1;  ///< -1: no poses seen yet
  int64_t utime = 0;  ///< simulated time, microseconds
  /// DREAM_POSES: what the world published (true poses in a log; in a live
  /// run with realism on, what the agents were sent).
  std::vector<double> x_m, y_m, theta_rad;
  /// DREAM_MEASURED_POSES of the same step (in logs with realism on); empty otherwise.
  std::vector<double> measured_x_m, measured_y_m, measured_theta_rad;
  /// What each robot drove with during the step that led here (DREAM_POSES' v, w: after the
  /// wheels' saturation), for the page's velocity arrows and a robot's details.
  std::vector<double> v_mps, w_radps;
  /// Each robot's newest command (DREAM_CMD_<id>: what its controller asked, before any
  /// saturation) for a step up to this one, for the command arrows; NaN for a robot with none,
  /// empty before any.
  std::vector<double> command_v_mps, command_w_radps;
  std::vector<Obstacle> obstacles;
  Status status;
  /// Robots that spoke on the radio since the previous frame, ascending.
  std::vector<int> radio_senders;
  /// (sender, receiver) pairs that hear each other at this step, when the
  /// run's config says who hears whom (ViewSetup); bounded by the robots.
  std::vector<std::pair<int, int>> radio_links;
  /// What each robot's controller drew last (DREAM_DRAW_<id>, checked by
  /// lcm::DrawingShapes), by robot, robots that drew nothing left out; and
  /// the shapes, points and text bytes their agents clipped in it.
  struct Drawn {
    int robot_id = 0;
    int64_t step = 0;
    int32_t clipped = 0;
    std::vector<lcm::DrawnShape> shapes;
  };
  std::vector<Drawn> drawings;
  /// The run's latest violations, oldest first (at most BusFrameCollector::kMaxMarks),
  /// and how many were located in the run so far (marks beyond the list were dropped).
  std::vector<ViolationMark> violations;
  int64_t violations_located = 0;
  /// The run's metrics after this step (ViewSetup::metrics), for the page's
  /// plots over time; empty without a config that says the kind.
  std::vector<MetricReading> metrics;
  /// Another run heard lately on the bus and not drawn; none when alone.
  std::optional<OtherWorld> other_world;

  /// The run's verdict as its world said it on DREAM_VERDICT (run_verdict_t)
  /// once summary.json was written: the one judge's, goal included, which
  /// the page ends the run on instead of its verdict so far.
  struct Judged {
    static constexpr size_t kMaxReasons = 64;  ///< reasons kept, at most
    std::string verdict;                       ///< clean, warning, not_ready or rejected
    std::string goal;                          ///< "met at step N (...)", "missed (...)", "none declared"
    int exit_code = 0;                         ///< the exit code of the command that ran the world
    std::vector<std::string> reasons;          ///< "rule: problem" each
  };
  /// None until the run drawn was judged.
  std::optional<Judged> judged;
};

}  // namespace dream::view
