#include "dream/python_host/python_host_process.h"

#include <poll.h>
#include <signal.h>
#include <spdlog/spdlog.h>
#include <sys/eventfd.h>
#include <sys/mman.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <algorithm>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>

#include "dream/config/config_error.h"
#include "dream/config/sim_node_options.h"
#include "dream/lcm/channels.h"
#include "dream/lcm/message_header.h"
#include "dream/robot_busy_t.hpp"
#include "dream/robot_fault_t.hpp"
#include "dream/python_host/spawned_python_host.h"
#include "host_texts.h"

namespace dream::python_host {
namespace {

using Clock = std::chrono::steady_clock;
using namespace host_texts;  // NOLINT: this file's helpers, kept in host_texts.h for the file's size

}  // namespace

void PythonHostProcess::Check(const std::string& spec_json, double start_timeout_s, const std::atomic<bool>& stop) {
  Limits limits;
  limits.start_timeout_s = start_timeout_s;
  limits = WithDefaults(limits);
  const std::string module_path = ModulePathOf(spec_json);
  const SpawnedPythonHost spawned = SpawnedPythonHost::Start();
  RelayLink link(spawned.link_fd);
  std::string trace;
  auto cleanup = [&] {
    ::close(spawned.trace_fd);
    ::munmap(spawned.cell, SpawnedPythonHost::kCellBytes);
  };
  link.Send('S', "", StartFrame(spec_json, {}, 0, limits, true));
  const auto started = Clock::now();
  while (true) {
    pollfd fd{link.fd(), POLLIN, 0};
    ::poll(&fd, 1, 50);
    std::vector<RelayLink::Frame> frames;
    std::string problem;
    const RelayLink::Read read = link.ReadAvailable(&frames, &problem);
    for (const RelayLink::Frame& frame : frames) {
      if (frame.kind == 'R' || frame.kind == 'E') {
        KillAndReap(spawned.pid);
        cleanup();
        if (frame.kind == 'R') return;
        if (frame.channel == "ConfigError") throw config::ConfigError(frame.data);
        throw std::runtime_error(frame.data);
      }
    }
    ReadTrace(spawned.trace_fd, &trace);
    std::string why;
    if (stop.load()) {
      KillAndReap(spawned.pid);
      cleanup();
      throw std::runtime_error("interrupted (Ctrl-C or SIGTERM) while loading the Python controller " + module_path);
    }
    const double waited = Seconds(Clock::now() - started);
    if (read != RelayLink::Read::kOpen || HasEnded(spawned.pid)) {
      ReadTrace(spawned.trace_fd, &trace);
      const bool in_call = spawned.cell[0].load() != 0;
      const int64_t robot = spawned.cell[1].load();
      why = (in_call ? CallTextOf(robot, -1) : std::string("the check")) +
            " ended its Python process: " + ExitTextOf(KillAndReap(spawned.pid)) + " (os._exit, or a crash)";
    } else if (waited > kKillFraction * limits.start_timeout_s) {
      const int64_t robot = spawned.cell[1].load();
      RequestTrace(spawned.pid, spawned.trace_fd, module_path,
                   DurationOf(kCheckTraceWaitFraction * limits.start_timeout_s), &trace);
      KillAndReap(spawned.pid);
      why = StuckTextOf(-1, robot, -1, limits, false, false);
    } else {
      continue;
    }
    ReadTrace(spawned.trace_fd, &trace);
    cleanup();
    const std::string line = TracedLineOf(trace, module_path);
    throw config::ConfigError((line.empty() ? module_path : line) + ": " + why);
  }
}

PythonHostProcess::PythonHostProcess(lcm::LcmBus& bus, const std::string& spec_json, const std::vector<int>& robot_ids,
                                     int64_t agent_id, const Limits& limits)
    : bus_(bus),
      robot_ids_(robot_ids),
      agent_id_(agent_id),
      limits_(WithDefaults(limits)),
      module_path_(ModulePathOf(spec_json)),
      busy_(robot_ids, limits_.agent_timeout_s) {
  started_ = Clock::now();
  const SpawnedPythonHost spawned = SpawnedPythonHost::Start();
  pid_ = spawned.pid;
  link_ = std::make_unique<RelayLink>(spawned.link_fd);
  trace_fd_ = spawned.trace_fd;
  cell_ = spawned.cell;
  wake_fd_ = ::eventfd(0, EFD_CLOEXEC | EFD_NONBLOCK);
  // Written before the relay starts: the process reads it first.
  const std::string start = StartFrame(spec_json, robot_ids, agent_id, limits_, false);
  RelayLink::Encode('S', "", start.data(), start.size(), &outbox_);
  // The bus may outlive this object: the subscription ends with it.
  subscription_ = bus_.Subscribe(lcm::kAgentInboxRegex, [this](const std::string& channel, const void* data, int size) {
    OnBusMessage(channel, data, size);
  });
  relay_ = std::thread(&PythonHostProcess::RelayLoop, this);
}

PythonHostProcess::~PythonHostProcess() {
  subscription_.Cancel();  // no bus message reaches a half-destroyed relay
  quit_.store(true);
  if (relay_.joinable()) relay_.join();
  bool ended = false;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    ended = ended_;
    ended_ = true;  // the bus's handler forwards nothing more
  }
  if (!ended) {
    // The end of the stream stops it (dream-agent-shared --python-host); a grace
    // period, then the group goes, whatever it forked or ignores.
    link_->Shutdown();
    const auto until = Clock::now() + std::chrono::duration<double>(kGraceS);
    while (!HasEnded(pid_) && Clock::now() < until) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    KillAndReap(pid_);
  }
  if (trace_fd_ >= 0) ::close(trace_fd_);
  if (wake_fd_ >= 0) ::close(wake_fd_);
  if (cell_ != nullptr) ::munmap(cell_, SpawnedPythonHost::kCellBytes);
}

void PythonHostProcess::OnBusMessage(const std::string& channel, const void* data, int size) {
  // Radio this host's process sent comes back from the bus: it heard it already.
  if (channel.rfind(lcm::kRadioChannelPrefix, 0) == 0 &&
      lcm::MessageHeader::AgentIdOf(data, static_cast<size_t>(size)) == agent_id_) {
    return;
  }
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (ended_) return;
    if (channel == lcm::kPosesChannel) {
      if (const auto header = lcm::MessageHeader::Read(data, static_cast<size_t>(size))) {
        world_step_ = {header->utime, header->step, header->run_id};
        busy_.StepArrived(header->run_id, header->step, Clock::now());
        busy_due_from_.store(busy_.NextDue().time_since_epoch().count(), std::memory_order_relaxed);
      }
    }
    if (outbox_.size() > kMaxOutboxBytes) return;
    const bool was_empty = outbox_.empty();
    RelayLink::Encode('M', channel, data, static_cast<size_t>(size), &outbox_);
    if (was_empty) {
      // Straight to the socket when it takes it (the usual case): no wake-up
      // of the relay thread on the step's path.
      const ssize_t sent = ::send(link_->fd(), outbox_.data(), outbox_.size(), MSG_DONTWAIT | MSG_NOSIGNAL);
      if (sent > 0) outbox_.erase(0, static_cast<size_t>(sent));
      if (outbox_.empty()) return;
    }
  }
  const uint64_t one = 1;
  const ssize_t written = ::write(wake_fd_, &one, sizeof one);
  (void)written;
}

bool PythonHostProcess::Ended() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return ended_;
}

void PythonHostProcess::RelayLoop() {
  while (!quit_.load()) {
    bool writing = false;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      writing = !outbox_.empty();
    }
    pollfd fds[3] = {{link_->fd(), static_cast<short>(POLLIN | (writing ? POLLOUT : 0)), 0},
                     {wake_fd_, POLLIN, 0},
                     {trace_fd_, POLLIN, 0}};
    ::poll(fds, 3, 20);
    if (fds[1].revents & POLLIN) {
      uint64_t count = 0;
      const ssize_t got = ::read(wake_fd_, &count, sizeof count);
      (void)got;
    }
    if (fds[2].revents & POLLIN) ReadTrace(trace_fd_, &trace_);
    std::vector<RelayLink::Frame> frames;
    std::string problem;
    const RelayLink::Read read = link_->ReadAvailable(&frames, &problem);
    for (const RelayLink::Frame& frame : frames) HandleFrame(frame);
    if (read == RelayLink::Read::kMalformed) {
      EndProcess("its Python process sent dream " + problem +
                     " on its link (a controller writing on dream's descriptors, or forking)",
                 "", false);
      return;
    }
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      if (!outbox_.empty()) {
        const ssize_t sent = ::send(link_->fd(), outbox_.data(), outbox_.size(), MSG_DONTWAIT | MSG_NOSIGNAL);
        if (sent > 0) outbox_.erase(0, static_cast<size_t>(sent));
      }
    }
    std::string how;
    if (read == RelayLink::Read::kClosed) {
      // It closed the link: it is ending (a moment to see it), or a controller closed the descriptor.
      const auto until = Clock::now() + std::chrono::milliseconds(200);
      while (!HasEnded(pid_) && Clock::now() < until) std::this_thread::sleep_for(std::chrono::milliseconds(5));
      if (!HasEnded(pid_)) {
        EndProcess("its Python process closed its link to dream (a controller closing dream's descriptors?)", "", true);
        return;
      }
    }
    if (HasEnded(pid_, &how)) {
      // What it sent last (a fault, its report) counts.
      frames.clear();
      link_->ReadAvailable(&frames, &problem);
      for (const RelayLink::Frame& frame : frames) HandleFrame(frame);
      EndProcess("", how, false);
      return;
    }
    const std::string stuck = StuckCall(Clock::now());
    if (!stuck.empty()) {
      EndProcess(stuck, "", true);
      return;
    }
    SayBusy(Clock::now());
  }
}

void PythonHostProcess::SayBusy(Clock::time_point now) {
  // No note is due before busy_due_from_ (busy_.NextDue(), stored with mutex_
  // held where it changes: a step's arrival, Due): such a pass, the usual one, returns without
  // mutex_, which guards busy_ itself. Only a step's arrival (the bus thread)
  // can race this read; read before it, the old time either takes the lock
  // (Due then decides on the new state) or skips a pass when the new step's
  // first note is a quarter of agent_timeout_s away: the next pass sees it.
  if (now.time_since_epoch().count() < busy_due_from_.load(std::memory_order_relaxed)) return;
  std::vector<int> due;
  Step at;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    if (ended_) return;  // before ready_ too: loading and setup() hold the world's start
    due = busy_.Due(now, failed_);
    busy_due_from_.store(busy_.NextDue().time_since_epoch().count(), std::memory_order_relaxed);
    at = world_step_;
  }
  if (due.empty() || at.run_id == 0) return;
  const int64_t token = cell_[0].load();
  robot_busy_t busy{};
  busy.utime = at.utime;
  busy.step = at.step;
  busy.run_id = at.run_id;
  busy.agent_id = agent_id_;
  busy.call_robot_id = token > 0 ? static_cast<int32_t>(cell_[1].load()) : -1;
  busy.call_s = token > 0 && token == watched_token_ ? Seconds(now - watched_since_) : 0.0;
  for (int id : due) {
    busy.robot_id = id;
    std::string bytes(static_cast<size_t>(busy.getEncodedSize()), '\0');
    busy.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    bus_.Publish(lcm::BusyChannel(id), bytes.data(), static_cast<int>(bytes.size()));
  }
}

void PythonHostProcess::HandleFrame(const RelayLink::Frame& frame) {
  bool publish = false;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    publish = Take(frame);
  }
  // Not under mutex_: the bus's handlers take it (OnBusMessage).
  if (publish) bus_.Publish(frame.channel, frame.data.data(), static_cast<int>(frame.data.size()));
}

bool PythonHostProcess::Take(const RelayLink::Frame& frame) {
  switch (frame.kind) {
    case 'M': {
      // Only what the process may say: its robots' commands, radio and faults.
      const std::optional<lcm::AgentChannel> own = lcm::ParseAgentChannel(frame.channel);
      if (!own || std::find(robot_ids_.begin(), robot_ids_.end(), own->robot_id) == robot_ids_.end()) {
        spdlog::warn("the Python controllers' process published on {}, not a channel of its robots: dropped",
                     frame.channel);
        return false;
      }
      const std::optional<lcm::MessageHeader> header = lcm::MessageHeader::Read(frame.data.data(), frame.data.size());
      if (own->kind == lcm::AgentChannel::Kind::kCommand && header) {
        answered_step_ = {header->utime, header->step, header->run_id};
        busy_.Answered(own->robot_id, header->step);
      } else if (own->kind == lcm::AgentChannel::Kind::kFault) {
        failed_.insert(own->robot_id);
      }
      return !ended_;
    }
    case 'R':
      ready_ = true;
      return false;
    case 'E':
      error_ = frame.data;
      return false;
    case 'D':
      try {
        const nlohmann::json done = nlohmann::json::parse(frame.data);
        world_finished_ = done.at("world_finished").get<bool>();
        last_step_answered_ = done.at("last_step_answered").get<int64_t>();
        end_detail_ = done.at("end_detail").get<std::string>();
        report_json_ = done.at("report").get<std::string>();
        done_received_ = true;
      } catch (const std::exception& error) {
        spdlog::warn("the Python controllers' process ended with a report dream cannot read: {}", error.what());
      }
      return false;
    default:
      return false;
  }
}

std::string PythonHostProcess::StuckCall(Clock::time_point now) {
  const int64_t token = cell_[0].load(std::memory_order_relaxed);
  bool ready = false;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    ready = ready_;
  }
  if (token == 0) {
    watched_token_ = 0;
    // Between calls: the runtime itself must start within the start limit.
    if (!ready && Seconds(now - started_) > limits_.start_timeout_s) {
      char text[200];
      std::snprintf(text, sizeof text,
                    "the Python controllers' process did not start within the world's "
                    "start_timeout_s of %g s: it was killed",
                    limits_.start_timeout_s);
      return text;
    }
    return "";
  }
  if (token != watched_token_) {
    watched_token_ = token;
    watched_since_ = now;
    return "";
  }
  // The process's watchdog raises in the call first (at 0.8 of the limit,
  // on its own clock): the kill waits for that to have had its chance, so
  // which of the two ends a call does not depend on which clock a starved
  // machine runs first (the world waits meanwhile: BusyAnnouncer).
  const double limit_s = token > 0 ? limits_.agent_timeout_s : limits_.start_timeout_s;
  const bool raised = cell_[python_embedded::kCallCellRaised].load() == token;
  if (raised && raised_token_ != token) {
    raised_token_ = token;
    raised_seen_ = now;
  }
  // Loading and setup() from the process's start, as the world counts its
  // start_timeout_s from before they begin.
  const bool overdue = raised
                           ? Seconds(now - raised_seen_) > kKillAfterRaiseFraction * limit_s
                           : Seconds(now - (token > 0 ? watched_since_ : started_)) > kKillUnraisedFraction * limit_s;
  if (!overdue) return "";
  return StuckTextOf(token, cell_[1].load(), cell_[2].load(), limits_, true, raised);
}

void PythonHostProcess::EndProcess(const std::string& why, const std::string& exit_text, bool trace) {
  // Which call ran, read before the process goes.
  const int64_t token = cell_[0].load();
  const int64_t robot = cell_[1].load();
  const int64_t step = token > 0 ? cell_[2].load() : -1;
  if (trace) {
    const double limit_s = token > 0 ? limits_.agent_timeout_s : limits_.start_timeout_s;
    RequestTrace(pid_, trace_fd_, module_path_, DurationOf(kTraceWaitFraction * limit_s), &trace_);
  }
  // Killed now, reaped after the faults are out: the world's deadline is
  // near, and a large process takes a while to go.
  ::kill(-pid_, SIGKILL);
  ::kill(pid_, SIGKILL);
  ReadTrace(trace_fd_, &trace_);
  struct Reap {
    pid_t pid;
    ~Reap() { KillAndReap(pid); }
  } reap{pid_};
  std::unique_lock<std::mutex> lock(mutex_);
  ended_ = true;
  if (why.empty() && done_received_ && exit_text == "exit code 0") return;  // it ended as asked
  std::string culprit_detail;
  std::string others_detail;
  const std::string line = TracedLineOf(trace_, module_path_);
  const std::string where = line.empty() ? "" : line + ": ";
  if (!why.empty()) {
    culprit_detail = where + why;
  } else if (!error_.empty()) {
    culprit_detail =
        (ready_ ? "the Python controllers' process failed: " : "the Python controllers could not start: ") + error_;
  } else if (token != 0) {
    culprit_detail =
        where + CallTextOf(robot, step) + " ended its Python process: " + exit_text + " (os._exit, or a crash)";
  } else {
    culprit_detail = "the Python process of robots " + JoinIds(robot_ids_) + " ended between calls: " + exit_text +
                     " (os._exit, or a crash)";
  }
  const bool named = token != 0 && robot >= 0;
  others_detail =
      named ? "lost with its Python process, ended at robot " + std::to_string(robot) + "'s call: " + culprit_detail
            : culprit_detail;
  lock.unlock();  // the bus's handlers take it
  PublishFaults(culprit_detail, named ? robot : -1, others_detail);
}

void PythonHostProcess::PublishFaults(const std::string& culprit_detail, int64_t culprit,
                                      const std::string& others_detail) {
  spdlog::error("{}", culprit_detail);
  Step at;
  std::set<int> failed;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    // The run the process answered, at the world's latest step of it.
    at = answered_step_.run_id != 0 ? answered_step_ : world_step_;
    if (world_step_.run_id == at.run_id && world_step_.step > at.step) at = world_step_;
    failed = failed_;
    failed_.insert(robot_ids_.begin(), robot_ids_.end());
  }
  if (at.run_id == 0) {
    spdlog::error("no world was heard yet: robot(s) {} cannot be reported lost to it", JoinIds(robot_ids_));
    return;
  }
  for (int id : robot_ids_) {
    if (failed.count(id) != 0) continue;
    robot_fault_t fault;
    fault.utime = at.utime;
    fault.step = at.step;
    fault.run_id = at.run_id;
    fault.robot_id = id;
    fault.agent_id = agent_id_;
    fault.detail = (id == culprit ? culprit_detail : others_detail).substr(0, 60000);
    std::string bytes(static_cast<size_t>(fault.getEncodedSize()), '\0');
    fault.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    bus_.Publish(lcm::FaultChannel(id), bytes.data(), static_cast<int>(bytes.size()));
  }
}

bool PythonHostProcess::Run(lcm::LcmBus& bus, const std::atomic<bool>& stop, double /*idle_timeout_s*/) {
  std::optional<Clock::time_point> stopping;
  while (!Ended()) {
    bus.HandleSubscriptions(100);
    if (stop.load() && !stopping) {
      ::kill(pid_, SIGTERM);  // its watchdog interrupts the running call
      stopping = Clock::now();
    }
    if (stopping && Seconds(Clock::now() - *stopping) > kGraceS) break;  // the destructor kills it
  }
  return world_finished();
}

bool PythonHostProcess::world_finished() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return world_finished_;
}

int64_t PythonHostProcess::last_step_answered() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return last_step_answered_;
}

std::string PythonHostProcess::end_detail() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return end_detail_;
}

std::string PythonHostProcess::ReportJson() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return report_json_;
}

}  // namespace dream::python_host
