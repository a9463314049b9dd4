#include "dream/view/bus_frame_collector.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <utility>

#include "dream/lcm/channels.h"
#include "dream/lcm/command_batch.h"
#include "dream/lcm/drawing_shapes.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/lcm/message_limits.h"
#include "dream/world/run_verdict.h"

namespace dream::view {
namespace {

/// Which kinds of violation a status counts more of than the one before.
struct NewViolations {
  bool boundary = false;
  bool collision = false;
  bool obstacle = false;
  bool any() const { return boundary || collision || obstacle; }
};

bool WantedKind(const NewViolations& added, ViolationMark::Kind kind) {
  switch (kind) {
    case ViolationMark::Kind::kBoundary:
      return added.boundary;
    case ViolationMark::Kind::kCollision:
      return added.collision;
    case ViolationMark::Kind::kObstacle:
      return added.obstacle;
  }
  return false;
}

// run_verdict_t's constant as the verdict it names; none for any other value.
std::optional<world::RunVerdict> VerdictOf(int8_t value) {
  switch (value) {
    case run_verdict_t::CLEAN:
      return world::RunVerdict::kClean;
    case run_verdict_t::WARNING:
      return world::RunVerdict::kWarning;
    case run_verdict_t::NOT_READY:
      return world::RunVerdict::kNotReady;
    case run_verdict_t::REJECTED:
      return world::RunVerdict::kRejected;
    default:
      return std::nullopt;
  }
}

}  // namespace

BusFrameCollector::BusFrameCollector(lcm::LcmInterface& bus, const world::WorldParams& world,
                                     std::function<RunChoice::Clock::time_point()> now, bool commands)
    : choice_(std::move(now)), locator_(world), bus_(bus) {
  // kViewChannelsRegex's channels, each a regex of its own: a regex with alternatives has no literal
  // prefix, and one would let every datagram of the group through the kernel's filter.
  for (const char* regex : {lcm::kPosesChannel, lcm::kMeasuredPosesChannel, lcm::kObstaclesChannel, lcm::kStatusChannel,
                            lcm::kVerdictChannel}) {
    subscriptions_.push_back(bus.Subscribe(
        regex, [this](const std::string& channel, const void* data, int size) { OnMessage(channel, data, size); }));
  }
  for (const char* prefix : {lcm::kRadioChannelPrefix, lcm::kDrawChannelPrefix}) {
    subscriptions_.push_back(bus.Subscribe(
        std::string(prefix) + "[0-9]+",
        [this](const std::string& channel, const void* data, int size) { OnMessage(channel, data, size); }));
  }
  if (commands) SubscribeCommands();
}

void BusFrameCollector::SubscribeCommands() {
  if (command_subscription_.active()) return;
  // The commands, for the command arrows: 20 datagrams a step of a 20-robot run on udpm, the most of
  // what a view receives, so `dream view` asks for them only once a page shows the arrows.
  command_subscription_ = bus_.Subscribe(
      std::string(lcm::kCommandChannelPrefix) + "[0-9]+",
      [this](const std::string& channel, const void* data, int size) { OnMessage(channel, data, size); });
  // A `dream run` script's: every robot's command in one message a step.
  commands_subscription_ = bus_.Subscribe(lcm::kCommandsChannel, [this](const std::string& channel, const void* data,
                                                                        int size) { OnMessage(channel, data, size); });
}

void BusFrameCollector::OnMessage(const std::string& channel, const void* data, int size) {
  if (channel == lcm::kPosesChannel) {
    if (!lcm::Decode(data, size, &poses_in_)) {
      std::lock_guard<std::mutex> lock(mutex_);
      ++bad_messages_;
      return;
    }
    std::lock_guard<std::mutex> lock(mutex_);
    OnPoses();
  } else if (channel == lcm::kMeasuredPosesChannel) {  // recorded with world.realism on
    const bool decoded = lcm::Decode(data, size, &measured_in_);
    std::lock_guard<std::mutex> lock(mutex_);
    if (!decoded) {
      ++bad_messages_;
    } else if (choice_.OnMessageOf(measured_in_.run_id)) {
      std::swap(measured_, measured_in_);
      ++version_;
    }
  } else if (channel == lcm::kObstaclesChannel) {
    const bool decoded = lcm::Decode(data, size, &obstacles_in_);
    std::lock_guard<std::mutex> lock(mutex_);
    if (!decoded) {
      ++bad_messages_;
      return;
    }
    OnObstacles();
  } else if (channel == lcm::kStatusChannel) {
    const bool decoded = lcm::Decode(data, size, &status_in_);
    std::lock_guard<std::mutex> lock(mutex_);
    if (!decoded) {
      ++bad_messages_;
      return;
    }
    OnStatus(status_in_);
  } else if (channel == lcm::kVerdictChannel) {
    const bool decoded = lcm::Decode(data, size, &verdict_in_);
    std::lock_guard<std::mutex> lock(mutex_);
    if (!decoded) {
      ++bad_messages_;
      return;
    }
    OnVerdict();
  } else if (const std::optional<int> robot = lcm::RobotIdFromChannel(channel, lcm::kCommandChannelPrefix)) {
    const bool decoded = lcm::Decode(data, size, &command_in_);
    std::lock_guard<std::mutex> lock(mutex_);
    if (!decoded) {
      ++bad_messages_;
      return;
    }
    OnCommand(*robot);
  } else if (channel == lcm::kCommandsChannel) {
    const bool decoded = lcm::Decode(data, size, &commands_in_);
    std::lock_guard<std::mutex> lock(mutex_);
    if (!decoded) {
      ++bad_messages_;
      return;
    }
    OnCommands();
  } else if (const std::optional<int> drawer = lcm::RobotIdFromChannel(channel, lcm::kDrawChannelPrefix)) {
    drawing_in_ = drawing_t();  // lcm-gen's decoder leaves an array whose count is 0 as it was
    const bool decoded = lcm::Decode(data, size, &drawing_in_);
    std::lock_guard<std::mutex> lock(mutex_);
    if (!decoded) {
      ++bad_messages_;
      return;
    }
    OnDrawing(*drawer);
  } else if (const std::optional<int> sender = lcm::RobotIdFromChannel(channel, lcm::kRadioChannelPrefix)) {
    // Who spoke is in the channel's name; the payload is the algorithm's own
    // and is not decoded (a view draws, it does not listen).
    std::lock_guard<std::mutex> lock(mutex_);
    if (*sender >= poses_.num_robots) return;  // no robot of this run (and bounded by the run's robots)
    const auto at = std::lower_bound(radio_senders_.begin(), radio_senders_.end(), *sender);
    if (at == radio_senders_.end() || *at != *sender) radio_senders_.insert(at, *sender);
    ++version_;
  }
}

void BusFrameCollector::StartRun(int64_t run_id) {
  run_id_ = run_id;
  poses_ = robot_poses_t();
  previous_poses_ = robot_poses_t();
  measured_ = robot_poses_t();
  previous_obstacles_ = obstacles_t();
  // The status and obstacles a world publishes just before a step's poses.
  if (unfollowed_obstacles_.run_id == run_id) {
    std::swap(obstacles_, unfollowed_obstacles_);
  } else if (obstacles_.run_id != run_id) {
    obstacles_ = obstacles_t();
  }
  unfollowed_obstacles_ = obstacles_t();
  if (unfollowed_status_.run_id == run_id) {
    status_ = unfollowed_status_;
    status_seen_ = true;
  } else if (status_.run_id != run_id) {
    status_seen_ = false;
  }
  unfollowed_status_ = run_status_t();
  radio_senders_.clear();
  command_v_.clear();
  command_w_.clear();
  command_step_.clear();
  drawn_.clear();
  marks_.clear();
  marks_located_ = 0;
  judged_.reset();
  StartMetrics();
}

void BusFrameCollector::FollowMetrics(std::function<std::unique_ptr<StepMetrics>()> make) {
  std::lock_guard<std::mutex> lock(mutex_);
  make_metrics_ = std::move(make);
  StartMetrics();
}

void BusFrameCollector::StartMetrics() {
  metrics_.reset();  // the previous run's thread ends (after the steps it is computing)
  metrics_version_ = 0;
  if (make_metrics_) metrics_ = std::make_unique<MetricsThread>(make_metrics_);
}

void BusFrameCollector::ObserveMetrics() {
  if (metrics_) metrics_->Offer(poses_, obstacles_);
}

void BusFrameCollector::OnVerdict() {
  // The agents' rule: the run followed, and only once it said it is over.
  const bool followed = run_id_ != 0 && verdict_in_.run_id == run_id_ && choice_.OnMessageOf(verdict_in_.run_id);
  const std::optional<world::RunVerdict> verdict = VerdictOf(verdict_in_.verdict);
  if (!followed || !choice_.ended() || !verdict) {
    ++verdicts_refused_;
    return;
  }
  ViewFrame::Judged judged;
  judged.verdict = world::RunVerdictName(*verdict);
  judged.goal = verdict_in_.goal_text.substr(0, ViewFrame::kMaxDetailChars);
  judged.exit_code = verdict_in_.exit_code;
  std::istringstream lines(verdict_in_.reasons);
  for (std::string line; std::getline(lines, line) && judged.reasons.size() < ViewFrame::Judged::kMaxReasons;) {
    judged.reasons.push_back(line.substr(0, ViewFrame::kMaxDetailChars));
  }
  judged_ = std::move(judged);
  ++version_;
}

void BusFrameCollector::OnCommand(int robot) {
  // The run drawn's, for one of its robots on its own channel, answering a step up to the one drawn.
  if (run_id_ == 0 || command_in_.run_id != run_id_ || command_in_.robot_id != robot || robot < 0 ||
      robot >= poses_.num_robots || command_in_.step > poses_.step) {
    return;
  }
  const size_t i = static_cast<size_t>(robot);
  if (command_step_.size() != static_cast<size_t>(poses_.num_robots)) {
    command_v_.assign(static_cast<size_t>(poses_.num_robots), std::nan(""));
    command_w_.assign(static_cast<size_t>(poses_.num_robots), std::nan(""));
    command_step_.assign(static_cast<size_t>(poses_.num_robots), -1);
  }
  if (command_in_.step < command_step_[i]) return;
  command_v_[i] = command_in_.v;
  command_w_[i] = command_in_.w;
  command_step_[i] = command_in_.step;
  ++version_;
}

void BusFrameCollector::OnCommands() {
  // The run drawn's only: another run's robot count is not this one's.
  if (run_id_ == 0 || commands_in_.run_id != run_id_) return;
  // A message the world refuses whole (a robot listed twice, more entries than the run's robots) draws no arrow.
  const lcm::CommandBatch batch(commands_in_, poses_.num_robots);
  if (batch.problem()) {
    ++bad_messages_;
    return;
  }
  for (size_t i = 0; i < batch.size(); ++i) {
    command_in_ = batch.Entry(i);
    OnCommand(command_in_.robot_id);
  }
}

void BusFrameCollector::OnDrawing(int robot) {
  // As a command: the run drawn's, for one of its robots on its own channel, of a step up to the one drawn.
  if (run_id_ == 0 || drawing_in_.run_id != run_id_ || drawing_in_.robot_id != robot || robot >= poses_.num_robots ||
      drawing_in_.step > poses_.step) {
    return;
  }
  if (!lcm::DrawingShapes::Problem(drawing_in_).empty()) {
    ++bad_messages_;
    return;
  }
  if (drawn_.size() != static_cast<size_t>(poses_.num_robots)) {
    drawn_.assign(static_cast<size_t>(poses_.num_robots), ViewFrame::Drawn{});
    for (int i = 0; i < poses_.num_robots; ++i) drawn_[static_cast<size_t>(i)] = {i, -1, 0, {}};
  }
  ViewFrame::Drawn& drawn = drawn_[static_cast<size_t>(robot)];
  if (drawing_in_.step < drawn.step) return;
  drawn.step = drawing_in_.step;
  drawn.clipped = drawing_in_.clipped;
  drawn.shapes = lcm::DrawingShapes::Of(drawing_in_);
  ++version_;
}

void BusFrameCollector::OnObstacles() {
  if (!choice_.OnMessageOf(obstacles_in_.run_id)) {
    std::swap(unfollowed_obstacles_, obstacles_in_);  // another world's: not drawn over this one
    return;
  }
  // Swapped, not copied: the handler's cost per step stays a decode.
  if (obstacles_in_.step != obstacles_.step) std::swap(previous_obstacles_, obstacles_);
  std::swap(obstacles_, obstacles_in_);
  ++version_;
}

void BusFrameCollector::OnPoses() {
  const RunChoice::Decision decision = choice_.OnPoses(poses_in_.run_id, poses_in_.step);
  switch (decision) {
    case RunChoice::Decision::kIgnore:
      return;  // another run, out of sequence, or not confirmed
    case RunChoice::Decision::kStartOver:
      StartRun(poses_in_.run_id);
      break;
    case RunChoice::Decision::kResend:
    case RunChoice::Decision::kNewStep:
      break;
  }
  // A resend of the same step replaces it; a new step moves it to previous.
  // Swapped, not copied: the handler's cost per step stays a decode.
  if (poses_in_.step != poses_.step || poses_.num_robots == 0) std::swap(previous_poses_, poses_);
  std::swap(poses_, poses_in_);
  if (decision != RunChoice::Decision::kResend) ObserveMetrics();  // each step once
  ++version_;
}

void BusFrameCollector::OnStatus(const run_status_t& status) {
  if (!choice_.OnStatus(status.run_id, status.step, status.state)) {
    unfollowed_status_ = status;  // another world's, or of a run not drawn yet
    return;
  }
  NewViolations added;
  if (status_seen_ && status.run_id == status_.run_id) {
    added.boundary = status.boundary_errors > status_.boundary_errors;
    added.collision = status.collision_errors > status_.collision_errors;
    added.obstacle = status.obstacle_collisions > status_.obstacle_collisions;
  }
  status_ = status;
  status_seen_ = true;
  ++version_;
  // The world validated the poses of the step before this status's, then
  // stepped; it publishes a step's obstacles and status before its poses, so
  // those poses are the newest or the ones before, depending on the order.
  if (!added.any()) return;
  const int64_t validated = status.step - 1;
  const robot_poses_t* poses = poses_.step == validated && poses_.num_robots > 0                     ? &poses_
                               : previous_poses_.step == validated && previous_poses_.num_robots > 0 ? &previous_poses_
                                                                                                     : nullptr;
  if (poses == nullptr) return;  // frames were missed (a view started mid-run): nothing to place
  static const obstacles_t kNoObstacles{};
  const obstacles_t& obstacles = obstacles_.step == validated            ? obstacles_
                                 : previous_obstacles_.step == validated ? previous_obstacles_
                                                                         : kNoObstacles;
  std::vector<ViolationMark> found;
  locator_.Locate(*poses, obstacles, &found);
  for (const ViolationMark& mark : found) {
    if (!WantedKind(added, mark.kind)) continue;
    if (marks_.size() >= kMaxMarks) marks_.pop_front();
    marks_.push_back(mark);
    ++marks_located_;
  }
}

bool BusFrameCollector::TakeFrame(ViewFrame* frame, uint64_t* version) {
  std::lock_guard<std::mutex> lock(mutex_);
  const std::optional<ViewFrame::OtherWorld> other_world = choice_.OtherWorldHeard();
  if (other_world != other_world_) {  // heard, or gone quiet: said even when the run drawn is still
    other_world_ = other_world;
    ++version_;
  }
  if (metrics_ && metrics_->version() != metrics_version_) {  // figures computed since, of steps already drawn
    metrics_version_ = metrics_->version();
    ++version_;
  }
  if (*version == version_) return false;
  *version = version_;
  frame->run_id = run_id_;
  frame->step = poses_.num_robots > 0 ? poses_.step : -1;
  frame->utime = poses_.utime;
  frame->x_m = poses_.x;
  frame->y_m = poses_.y;
  frame->theta_rad = poses_.theta;
  frame->v_mps = poses_.v;
  frame->w_radps = poses_.w;
  const bool commands = command_v_.size() == poses_.x.size();
  frame->command_v_mps = commands ? command_v_ : std::vector<double>();
  frame->command_w_radps = commands ? command_w_ : std::vector<double>();
  const bool measured_now = measured_.num_robots == poses_.num_robots && measured_.step == poses_.step;
  frame->measured_x_m = measured_now ? measured_.x : std::vector<double>();
  frame->measured_y_m = measured_now ? measured_.y : std::vector<double>();
  frame->measured_theta_rad = measured_now ? measured_.theta : std::vector<double>();
  frame->obstacles.clear();
  for (const rectangle_obstacle_t& o : obstacles_.obstacles) {
    frame->obstacles.push_back({o.id, o.center_x, o.center_y, o.width, o.height, o.vx, o.vy});
  }
  frame->status = status_seen_ ? ViewFrame::Status::Of(status_) : ViewFrame::Status{};
  frame->radio_senders.swap(radio_senders_);
  radio_senders_.clear();
  frame->radio_links.clear();
  frame->drawings.clear();
  for (const ViewFrame::Drawn& drawn : drawn_) {
    if (!drawn.shapes.empty() || drawn.clipped > 0) frame->drawings.push_back(drawn);
  }
  frame->violations.assign(marks_.begin(), marks_.end());
  frame->violations_located = marks_located_;
  frame->other_world = other_world_;
  frame->judged = judged_;
  frame->metrics.clear();
  if (metrics_) metrics_->Read(&frame->metrics);
  return true;
}

bool BusFrameCollector::WaitForMetrics(std::chrono::steady_clock::duration timeout) {
  std::lock_guard<std::mutex> lock(mutex_);  // the metrics' thread never takes it
  return !metrics_ || metrics_->WaitUntilComputed(timeout);
}

bool BusFrameCollector::Follow(int64_t run_id) {
  std::lock_guard<std::mutex> lock(mutex_);
  return choice_.Choose(run_id);
}

int64_t BusFrameCollector::verdicts_refused() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return verdicts_refused_;
}

int64_t BusFrameCollector::bad_messages() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return bad_messages_;
}

}  // namespace dream::view
