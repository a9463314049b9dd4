#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "dream/applied_commands_t.hpp"
#include "dream/obstacles_t.hpp"
#include "dream/robot_poses_t.hpp"
#include "dream/run_status_t.hpp"
#include "dream/run_verdict_t.hpp"
#include "dream/run_log/recorded_command.h"
#include "dream/run_log/recorded_drawing.h"

namespace dream::run_log {

class WorldsHeard;

/// One DREAM_RADIO_<n> message: robot `sender_id` broadcast at `step`.
struct RadioSend {
  int64_t step = 0;
  int32_t sender_id = 0;
};

/// A run's LCM log (run.lcmlog as `dream run`, `sim`, `launch`, `lab-replay`
/// and `import` write it), read once into what every reader of a run needs:
/// the experiment's metrics, the pictures and videos, the bridge (export,
/// compare, lab-replay) and the lab verifier's counts. The one place that
/// decodes a run log; read it once and hand it to each of them.
///
/// Messages are read as they decode: a message that does not (a forged count,
/// a foreign type on a DREAM_* channel) is left out, channels of no interest
/// are skipped, and what keeps the log from being a whole run is kept as its
/// Flaw(): pictures and metrics use what decodes, the bridge refuses it.
///
/// A recording of the bus (lcm-logger of a live run) reads as the run's own
/// log does: the world's resends of a step are taken as that step, once
/// (resends()), and a second world's messages (another run id) are left out
/// (other_run_ids()): the log is of the world with the most steps.
class RunLog {
 public:
  /// Reads the log at `path`. Every message is checked against its type's
  /// wire layout before it is decoded (lcm::DecodeProblem), so no count in
  /// the log makes it allocate more than the log's own bytes.
  /// @throws std::runtime_error naming the file (and the byte) when it is
  ///         missing, not an LCM log, cut short or has a damaged event
  ///         (lcm::LogReader).
  static RunLog Read(const std::string& path);

  const std::string& path() const { return path_; }

  /// Every DREAM_POSES message that decodes, in log order (may be empty).
  const std::vector<robot_poses_t>& poses() const { return poses_; }
  /// The run id of poses() (0 without poses).
  int64_t run_id() const { return run_id_; }
  /// The world's resends of a step (the same message again) left out of
  /// poses() and measured_poses(): none in a run's own log, many in an
  /// lcm-logger recording of a lockstep run.
  int64_t resends() const { return resends_; }
  /// Other worlds heard in the log (their poses or status), left out.
  const std::vector<int64_t>& other_run_ids() const { return other_run_ids_; }
  /// How many of poses(), from the first, the world judged: all but the last,
  /// where the run ended (the world checks a step's poses before it steps on),
  /// so whatever locates violations in a log counts what summary.json counts.
  size_t judged_poses() const { return poses_.empty() ? 0 : poses_.size() - 1; }
  /// The most robots any step has (0 without poses).
  int num_robots() const { return num_robots_; }
  /// The steps of the first and last poses (-1 without poses).
  int64_t first_step() const { return poses_.empty() ? -1 : poses_.front().step; }
  int64_t last_step() const { return poses_.empty() ? -1 : poses_.back().step; }
  /// The index of the last pose whose step is <= `step` (0 before the first).
  size_t PoseIndexAtStep(int64_t step) const;

  /// Every DREAM_MEASURED_POSES message that decodes, in log order: what the
  /// agents were sent when world.realism was on (poses() then holds the true
  /// poses); empty otherwise.
  const std::vector<robot_poses_t>& measured_poses() const { return measured_poses_; }

  /// Every DREAM_OBSTACLES message that decodes, by step (log order within a step).
  const std::vector<obstacles_t>& obstacles() const { return obstacles_; }
  /// The obstacles at the step of poses()[pose_index]: the last DREAM_OBSTACLES
  /// for that step or an earlier one, wherever it stands in the log (the world
  /// publishes a step's obstacles next to its poses); an empty message before
  /// the first.
  const obstacles_t& obstacles_at(size_t pose_index) const;

  /// The commands of this run on DREAM_CMD_<id>, ordered by step, then robot:
  /// of the run id of its poses, for a robot of the run whose id is the
  /// channel's, answering a step the log has poses for (first_step() ..
  /// last_step()); one per robot and step (the first: the world records the
  /// one it took, a recording of the bus may hold resends). So at most
  /// poses().size() x num_robots(), whatever the log holds; the rest is left out.
  const std::vector<RecordedCommand>& commands() const { return commands_; }
  /// In a `dream lab-replay` log, what the lab executed at each step on
  /// DREAM_LAB_CMD_<id>, by the rules of commands() (the lab's carry run id 0,
  /// as they answer no world, or the run's); empty in other logs.
  const std::vector<RecordedCommand>& lab_commands() const { return lab_commands_; }
  /// Every DREAM_APPLIED of this run that decodes: which command drove each
  /// robot, one per step the log has poses for (the first), for as many
  /// robots as the poses have; ordered by step.
  const std::vector<applied_commands_t>& applied() const { return applied_; }

  /// Every DREAM_RADIO_<n> broadcast of this run (the run id of its poses,
  /// sender n, one of its robots) that decodes, by step (log order within a step).
  const std::vector<RadioSend>& radio_sends() const { return radio_sends_; }

  /// What the robots' controllers drew (DREAM_DRAW_<id>) in this run: of its
  /// id, a robot of the run and its channel's, a step the log has poses for,
  /// a drawing by lcm::DrawingShapes; ordered by step, then robot, one per
  /// robot and step (the last heard). See DrawingsShownAt().
  const std::vector<RecordedDrawing>& drawings() const { return drawings_; }

  /// The last DREAM_STATUS that decodes: how the run ended (FINISHED,
  /// ABORTED), or where it stood when the log stops; none in a log without one.
  const std::optional<run_status_t>& last_status() const { return last_status_; }
  /// The run's DREAM_VERDICT (the one judge's, appended once summary.json was
  /// written): the last one of run_id() that decodes; none in a log without one
  /// (an imported lab run, a run older than the message, a log the disk refused).
  const std::optional<run_verdict_t>& verdict() const { return verdict_; }
  /// Of the robots lost at the end (last_status()'s lost_robot_ids), those
  /// whose agent said why on DREAM_FAULT_<id>: id -> "step k: detail", from
  /// the first fault of this run (the run id of its poses) on the channel
  /// whose robot_id is the channel's (a fault from another agent, which the
  /// world refused, names a robot that drove on; another run's is none of
  /// this run's: the world refuses it and logs from before it did are read so).
  const std::map<int, std::string>& robot_faults() const { return robot_faults_; }

  /// Why this is not a whole run log, the first in the log, as an error naming
  /// the file: a DREAM_POSES or DREAM_OBSTACLES message (with `with_status`, a
  /// DREAM_STATUS too) that does not decode, named by its event and byte, with
  /// the decoder's reason; poses whose steps do not go 0, 1, 2, ... each once;
  /// no robot at step 0, or a robot count that changes; or no poses at all.
  /// Nothing for a whole run log.
  std::optional<std::string> Flaw(bool with_status) const;

 private:
  /// A flaw and the index of the event where it shows.
  struct Problem {
    int64_t event_index = 0;
    std::string text;
  };

  /// Keeps the followed world's poses, measured poses, status and obstacles.
  void TakeRun(WorldsHeard worlds);
  /// Checks poses_ (poses_[i] read at event events[i]) go 0, 1, 2, ..., up to
  /// the first flaw already found.
  void CheckSequence(const std::vector<int64_t>& events);
  /// Orders obstacles and radio by step, finds each pose's obstacles, keeps
  /// the faults of the robots lost at the end.
  void Index(const std::map<int, std::string>& faults);

  std::string path_;
  int64_t run_id_ = 0;
  int64_t resends_ = 0;
  std::vector<int64_t> other_run_ids_;
  std::vector<robot_poses_t> poses_;
  int num_robots_ = 0;
  std::vector<robot_poses_t> measured_poses_;
  std::vector<obstacles_t> obstacles_;
  std::vector<size_t> obstacle_index_;  // per pose: index into obstacles_, kNone before the first
  std::vector<RadioSend> radio_sends_;
  std::vector<RecordedCommand> commands_;
  std::vector<RecordedCommand> lab_commands_;
  std::vector<applied_commands_t> applied_;
  std::vector<RecordedDrawing> drawings_;
  std::optional<run_status_t> last_status_;
  std::optional<run_verdict_t> verdict_;
  std::map<int, std::string> robot_faults_;
  std::optional<Problem> world_flaw_;   // poses and obstacles
  std::optional<Problem> status_flaw_;  // an undecodable DREAM_STATUS
};

}  // namespace dream::run_log
