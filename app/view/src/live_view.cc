#include "dream/view/live_view.h"

#include <spdlog/spdlog.h>

#include <charconv>
#include <exception>
#include <string_view>
#include <vector>
#include <utility>

#include "dream/lcm/channels.h"
#include "dream/lcm/run_id.h"
#include "dream/run_log/run_log.h"
#include "dream/view/frame_json.h"
#include "dream/view/thread_priority.h"

namespace dream::view {

LiveView::LiveView(lcm::LcmInterface& bus, ViewServer& server, ViewSetup setup)
    : server_(server),
      setup_(std::move(setup)),
      collector_(bus, setup_.world, &RunChoice::Clock::now, !setup_.commands_on_request),
      pacer_(setup_.frame_rates, setup_.world.time_step_s) {
  if (setup_.metrics) collector_.FollowMetrics(setup_.metrics);
  server_.SetSetup(SetupJson(setup_));
  server_.SetClientMessageHandler([this](const std::string& message) { OnPageMessage(message); });
  pump_ = std::thread([this] {
    LowerThisThreadsPriority();
    while (!stop_.load()) {
      PumpOnce();
      std::this_thread::sleep_for(pacer_.Next(frame_.step, std::chrono::steady_clock::now()));
    }
  });
}

LiveView::~LiveView() {
  server_.SetClientMessageHandler(nullptr);  // synchronous: no page's message reaches a half-destroyed view
  stop_.store(true);
  if (pump_.joinable()) pump_.join();
  PumpOnce();  // the run's last state (FINISHED) reaches the page
}

void LiveView::PumpOnce() {
  if (!collector_.TakeFrame(&frame_, &version_)) return;
  try {
    AddRadioLinks(&frame_);
  } catch (const std::exception& error) {
    // The config's radio decided (agents' code): the frame goes without links.
    frame_.radio_links.clear();
  }
  server_.Broadcast(FrameJson(frame_));
  frames_sent_.fetch_add(1);
}

bool LiveView::OnPageMessage(const std::string& message) {
  if (message == "commands") {
    commands_asked_.store(true);
    return true;
  }
  constexpr std::string_view kFollow = "follow ";
  if (message.compare(0, kFollow.size(), kFollow) != 0) return false;
  const char* const end = message.data() + message.size();
  int64_t run_id = 0;
  const auto [parsed, error] = std::from_chars(message.data() + kFollow.size(), end, run_id);
  if (error != std::errc() || parsed != end || !collector_.Follow(run_id)) return false;
  spdlog::info("dream view: a page chose run {}: it is drawn from its next step", lcm::RunIdText(run_id));
  return true;
}

void LiveView::TakePageRequests() {
  if (commands_asked_.load()) collector_.SubscribeCommands();
}

void LiveView::ShowEndOf(const std::string& log_path) {
  // The run's last obstacles, status and poses, as RunLog reads them (the run's own, decoded once),
  // handed to the collector as the bus would: in the order the world publishes a step.
  const run_log::RunLog log = run_log::RunLog::Read(log_path);
  auto hand_over = [this](const char* channel, const auto& message) {
    std::vector<uint8_t> bytes(static_cast<size_t>(message.getEncodedSize()));
    message.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    collector_.OnMessage(channel, bytes.data(), static_cast<int>(bytes.size()));
  };
  if (!log.poses().empty()) hand_over(lcm::kObstaclesChannel, log.obstacles_at(log.poses().size() - 1));
  if (log.last_status()) hand_over(lcm::kStatusChannel, *log.last_status());
  if (!log.poses().empty()) hand_over(lcm::kPosesChannel, log.poses().back());
  if (!log.measured_poses().empty()) hand_over(lcm::kMeasuredPosesChannel, log.measured_poses().back());
  PumpOnce();
}

void LiveView::AddRadioLinks(ViewFrame* frame) {
  if (!setup_.overlays.hears || frame->x_m.empty()) return;
  // Who hears whom is the robots' own radio deciding on these poses (the
  // config's range, graph or roles): links from each robot that spoke.
  robot_poses_t poses{};
  poses.step = frame->step;
  poses.num_robots = static_cast<int32_t>(frame->x_m.size());
  poses.x = frame->x_m;
  poses.y = frame->y_m;
  poses.theta = frame->theta_rad;
  poses.v.assign(frame->x_m.size(), 0.0);
  poses.w.assign(frame->x_m.size(), 0.0);
  const int n = poses.num_robots;
  for (const int sender : frame->radio_senders) {
    for (int receiver = 0; receiver < n; ++receiver) {
      if (receiver != sender && setup_.overlays.hears(receiver, sender, poses)) {
        frame->radio_links.emplace_back(sender, receiver);
      }
    }
  }
}

}  // namespace dream::view
