#include "dream/view/replay_json.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <vector>

#include "dream/view/view_frame.h"
#include "dream/view/violation_locator.h"
#include "drawing_json.h"
#include "json_parts.h"
#include "json_writer.h"

namespace dream::view {
namespace {

constexpr int kMetres = 4;
constexpr int kRadians = 4;
/// Obstacle rectangles, radio sends and radio links the replay lists at most
/// (each a few numbers); past them the lists stop and say so.
constexpr size_t kMaxObstacleValues = 2'000'000;
constexpr size_t kMaxRadioEntries = 200'000;
constexpr size_t kMaxLinkEntries = 500'000;
/// Shapes the controllers drew that the replay lists at most (each tens of bytes).
constexpr size_t kMaxDrawnShapes = 500'000;

/// The violations of every step, and the counts so far where they change.
struct Judged {
  std::vector<ViolationMark> marks;  // the first kMaxReplayMarks
  int64_t located = 0;
  // step, boundary errors, collision errors, obstacle collisions: so far, at each step they grow
  std::vector<std::array<int64_t, 4>> counts;
};

Judged JudgeEveryStep(const run_log::RunLog& log, const ViewSetup& setup) {
  Judged judged;
  ViolationLocator locator(setup.world);
  std::array<int64_t, 4> so_far{0, 0, 0, 0};
  std::vector<ViolationMark> found;
  for (size_t i = 0; i < log.judged_poses(); ++i) {
    const robot_poses_t& poses = log.poses()[i];
    found.clear();
    locator.Locate(poses, log.obstacles_at(i), &found);
    if (found.empty()) continue;
    bool out_of_bounds = false;
    for (const ViolationMark& mark : found) {
      out_of_bounds |= mark.kind == ViolationMark::Kind::kBoundary;
      so_far[2] += mark.kind == ViolationMark::Kind::kCollision ? 1 : 0;
      so_far[3] += mark.kind == ViolationMark::Kind::kObstacle ? 1 : 0;
      if (judged.marks.size() < kMaxReplayMarks) judged.marks.push_back(mark);
      ++judged.located;
    }
    so_far[1] += out_of_bounds ? 1 : 0;  // the Robotarium counts steps with any robot outside, not robots
    so_far[0] = poses.step;
    judged.counts.push_back(so_far);
  }
  return judged;
}

void PoseArray(JsonWriter& json, const robot_poses_t& poses) {
  json.BeginArray();
  for (int r = 0; r < poses.num_robots && static_cast<size_t>(r) < poses.x.size(); ++r) {
    json.Number(poses.x[r], kMetres).Number(poses.y[r], kMetres).Number(poses.theta[r], kRadians);
  }
  json.EndArray();
}

// What each robot drove with during the step that led to a frame: [v0, w0, v1, w1, ...].
void VelocityArray(JsonWriter& json, const robot_poses_t& poses) {
  json.BeginArray();
  for (int r = 0;
       r < poses.num_robots && static_cast<size_t>(r) < poses.v.size() && static_cast<size_t>(r) < poses.w.size();
       ++r) {
    json.Number(poses.v[r], kMetres).Number(poses.w[r], kRadians);
  }
  json.EndArray();
}

// Each frame's commands (DREAM_CMD_<id> answering its step): [v0, w0, v1, w1, ...], null for a
// robot whose command the log has not; null for the whole frame when it has none.
void CommandArrays(JsonWriter& json, const run_log::RunLog& log, const std::vector<size_t>& frames) {
  const size_t robots = static_cast<size_t>(std::max(0, log.num_robots()));
  std::map<int64_t, size_t> frame_of_step;
  for (size_t k = 0; k < frames.size(); ++k) frame_of_step[log.poses()[frames[k]].step] = k;
  std::vector<double> vw(frames.size() * robots * 2, std::nan(""));
  std::vector<bool> any(frames.size(), false);
  for (const run_log::RecordedCommand& c : log.commands()) {
    const auto found = frame_of_step.find(c.step);
    if (found == frame_of_step.end() || c.robot_id < 0 || static_cast<size_t>(c.robot_id) >= robots) continue;
    const size_t at = (found->second * robots + static_cast<size_t>(c.robot_id)) * 2;
    vw[at] = c.v_mps;
    vw[at + 1] = c.w_radps;
    any[found->second] = true;
  }
  json.Key("commands").BeginArray();
  for (size_t k = 0; k < frames.size(); ++k) {
    if (!any[k]) {
      json.Null();
      continue;
    }
    json.BeginArray();
    for (size_t r = 0; r < robots; ++r) {
      json.Number(vw[(k * robots + r) * 2], kMetres).Number(vw[(k * robots + r) * 2 + 1], kRadians);
    }
    json.EndArray();
  }
  json.EndArray();
}

void FrameArrays(JsonWriter& json, const run_log::RunLog& log, const std::vector<size_t>& frames) {
  std::map<int64_t, const robot_poses_t*> measured;
  for (const robot_poses_t& m : log.measured_poses()) measured[m.step] = &m;
  json.Key("steps").BeginArray();
  for (const size_t i : frames) json.Integer(log.poses()[i].step);
  json.EndArray();
  json.Key("t").BeginArray();
  for (const size_t i : frames) json.Number(static_cast<double>(log.poses()[i].utime) / 1e6, 3);
  json.EndArray();
  json.Key("poses").BeginArray();
  for (const size_t i : frames) PoseArray(json, log.poses()[i]);
  json.EndArray();
  json.Key("velocities").BeginArray();
  for (const size_t i : frames) VelocityArray(json, log.poses()[i]);
  json.EndArray();
  CommandArrays(json, log, frames);
  json.Key("measured");
  if (measured.empty()) {
    json.Null();
  } else {
    json.BeginArray();
    for (const size_t i : frames) {
      const auto found = measured.find(log.poses()[i].step);
      if (found == measured.end() || found->second->num_robots != log.poses()[i].num_robots) {
        json.Null();
      } else {
        PoseArray(json, *found->second);
      }
    }
    json.EndArray();
  }
}

bool SameObstacles(const obstacles_t& a, const obstacles_t& b) {
  if (a.obstacles.size() != b.obstacles.size()) return false;
  for (size_t i = 0; i < a.obstacles.size(); ++i) {
    const rectangle_obstacle_t& p = a.obstacles[i];
    const rectangle_obstacle_t& q = b.obstacles[i];
    if (p.id != q.id || p.center_x != q.center_x || p.center_y != q.center_y || p.width != q.width ||
        p.height != q.height) {
      return false;
    }
  }
  return true;
}

/// Obstacles where they change: [frame, [[id, cx, cy, w, h], ...]] each.
void ObstacleChanges(JsonWriter& json, const run_log::RunLog& log, const std::vector<size_t>& frames) {
  json.Key("obstacles").BeginArray();
  const obstacles_t* last = nullptr;
  size_t values = 0;
  bool cut = false;
  for (size_t f = 0; f < frames.size(); ++f) {
    const obstacles_t& now = log.obstacles_at(frames[f]);
    if (last != nullptr && SameObstacles(now, *last)) continue;  // published every step, mostly unchanged
    last = &now;
    values += now.obstacles.size() * 5;
    if (values > kMaxObstacleValues) {
      cut = true;
      break;
    }
    json.BeginArray().Integer(static_cast<int64_t>(f)).BeginArray();
    for (const rectangle_obstacle_t& o : now.obstacles) {
      json.BeginArray().Integer(o.id).Number(o.center_x, kMetres).Number(o.center_y, kMetres);
      json.Number(o.width, kMetres).Number(o.height, kMetres).EndArray();
    }
    json.EndArray().EndArray();
  }
  json.EndArray();
  json.Key("obstacles_cut").Bool(cut);
}

/// Radio sends by step, and who heard them when the setup knows: [step, sender] and [step, sender, receiver].
void RadioTraffic(JsonWriter& json, const run_log::RunLog& log, const ViewSetup& setup) {
  const auto& sends = log.radio_sends();
  const size_t listed = std::min(sends.size(), kMaxRadioEntries);
  json.Key("radio").BeginArray();
  for (size_t i = 0; i < listed; ++i) json.BeginArray().Integer(sends[i].step).Integer(sends[i].sender_id).EndArray();
  json.EndArray();
  json.Key("links").BeginArray();
  size_t links = 0;
  bool cut = listed < sends.size();
  for (size_t i = 0; i < listed && setup.overlays.hears && !log.poses().empty(); ++i) {
    const robot_poses_t& poses = log.poses()[log.PoseIndexAtStep(sends[i].step)];
    for (int receiver = 0; receiver < poses.num_robots; ++receiver) {
      if (receiver == sends[i].sender_id || !setup.overlays.hears(receiver, sends[i].sender_id, poses)) continue;
      if (++links > kMaxLinkEntries) {
        cut = true;
        break;
      }
      json.BeginArray().Integer(sends[i].step).Integer(sends[i].sender_id).Integer(receiver).EndArray();
    }
    if (links > kMaxLinkEntries) break;
  }
  json.EndArray();
  json.Key("radio_cut").Bool(cut);
}

/// What the controllers drew: [step, robot, clipped, shapes] by step, each shown until the robot's next.
void Drawings(JsonWriter& json, const run_log::RunLog& log) {
  size_t shapes = 0;
  bool cut = false;
  json.Key("drawings").BeginArray();
  for (const run_log::RecordedDrawing& drawing : log.drawings()) {
    shapes += drawing.shapes.size();
    if (shapes > kMaxDrawnShapes) {
      cut = true;
      break;
    }
    json.BeginArray().Integer(drawing.step).Integer(drawing.robot_id).Integer(drawing.clipped);
    AppendShapes(json, drawing.shapes);
    json.EndArray();
  }
  json.EndArray();
  json.Key("drawings_cut").Bool(cut);
}

void MetricsOverTime(JsonWriter& json, const MetricTimeline* metrics) {
  constexpr int kDigits = 7;
  json.Key("metrics").BeginObject();
  json.Key("stride").Integer(metrics ? metrics->stride() : 1);
  json.Key("series").BeginArray();
  static const MetricTimeline kNone;
  for (const MetricTimeline::Series& s : (metrics ? *metrics : kNone).series()) {
    json.BeginObject().Key("name").String(s.name);
    json.Key("steps").BeginArray();
    for (const auto& point : s.points) json.Integer(static_cast<int64_t>(point[0]));
    json.EndArray().Key("values").BeginArray();
    for (const auto& point : s.points) json.Significant(point[1], kDigits);
    json.EndArray();
    if (s.threshold) json.Key("threshold").Significant(*s.threshold, kDigits).Key("label").String(s.threshold_label);
    json.EndObject();
  }
  json.EndArray();
  json.EndObject();
}

}  // namespace

std::string RunReplayJson(const run_log::RunLog& log, const ViewSetup& setup, size_t max_pose_values,
                          const MetricTimeline* metrics) {
  max_pose_values = std::max<size_t>(max_pose_values, 1);
  const size_t steps = log.poses().size();
  const size_t per_step = static_cast<size_t>(std::max(1, log.num_robots())) * 3;
  const size_t stride = std::max<size_t>(1, (steps * per_step + max_pose_values - 1) / max_pose_values);
  std::vector<size_t> frames;
  for (size_t i = 0; i < steps; i += stride) frames.push_back(i);
  if (steps > 0 && frames.back() != steps - 1) frames.push_back(steps - 1);

  std::string out;
  out.reserve(64 + frames.size() * per_step * 8);
  JsonWriter json(&out);
  json.BeginObject();
  json.Key("type").String("run");
  AppendSetupFields(json, setup);
  json.Key("num_robots").Integer(log.num_robots());
  json.Key("run").String(log.poses().empty() ? "0" : std::to_string(log.poses().front().run_id));
  json.Key("stride").Integer(static_cast<int64_t>(stride));
  const std::optional<std::string> flaw = log.Flaw(true);
  json.Key("flaw").String(flaw ? flaw->substr(0, 500) : "");
  FrameArrays(json, log, frames);
  ObstacleChanges(json, log, frames);
  RadioTraffic(json, log, setup);
  Drawings(json, log);
  const Judged judged = JudgeEveryStep(log, setup);
  json.Key("violations").BeginArray();
  for (const ViolationMark& mark : judged.marks) AppendViolation(json, mark);
  json.EndArray();
  json.Key("located").Integer(judged.located);
  json.Key("counts").BeginArray();
  for (const auto& at : judged.counts)
    json.BeginArray().Integer(at[0]).Integer(at[1]).Integer(at[2]).Integer(at[3]).EndArray();
  json.EndArray();
  // The run's last status: what only it says (actuator warnings, rejected commands, lost robots).
  WriteStatusJson(json, "final", log.last_status() ? ViewFrame::Status::Of(*log.last_status()) : ViewFrame::Status{});
  MetricsOverTime(json, metrics);
  json.EndObject();
  return out;
}

}  // namespace dream::view
