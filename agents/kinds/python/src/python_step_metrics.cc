#include "dream/python/python_step_metrics.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>

extern char** environ;

namespace dream::python {
namespace {

namespace fs = std::filesystem;

constexpr size_t kMaxAnswerBytes = 1 << 20;  // figures only: a few hundred bytes
constexpr size_t kMaxErrorChars = 2000;

template <typename T>
void Append(std::string* bytes, const T* values, size_t count) {
  bytes->append(reinterpret_cast<const char*>(values), count * sizeof(T));
}

/// What the helper wrote on its stderr (the end of it), for the message that says it stopped.
std::string ErrorsIn(int fd) {
  std::string text(kMaxErrorChars, '\0');
  const off_t size = ::lseek(fd, 0, SEEK_END);
  const off_t from = std::max<off_t>(0, size - static_cast<off_t>(kMaxErrorChars));
  const ssize_t got = ::pread(fd, text.data(), text.size(), from);
  text.resize(got > 0 ? static_cast<size_t>(got) : 0);
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  return text;
}

}  // namespace

PythonStepMetrics::PythonStepMetrics(const std::string& runtime_dir, const std::string& spec_json, int num_robots)
    : num_robots_(num_robots) {
  const std::string script = (fs::path(runtime_dir) / "dream" / "follow_metrics.py").string();
  if (!fs::is_regular_file(script)) {
    throw std::runtime_error(script + ": missing; it follows a Python controller's metrics() while a run runs");
  }
  if (num_robots < 1) throw std::runtime_error("a run of " + std::to_string(num_robots) + " robots has no metrics");
  int ends[2];
  // A socket, not pipes: sent with MSG_NOSIGNAL, a helper that died is an error here, never a SIGPIPE.
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, ends) != 0) {
    throw std::runtime_error(std::string("cannot make a socket for the metrics helper: ") + std::strerror(errno));
  }
  char errors_path[] = "/tmp/dream-follow-metrics-XXXXXX";
  errors_ = ::mkostemp(errors_path, O_CLOEXEC);
  if (errors_ >= 0) ::unlink(errors_path);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, ends[1], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, ends[1], STDOUT_FILENO);
  if (errors_ >= 0) {
    posix_spawn_file_actions_adddup2(&actions, errors_, STDERR_FILENO);
  } else {
    posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  }
  std::vector<std::string> args = {DREAM_PYTHON3_EXECUTABLE, "-I", "-B", script};
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);
  const int spawn_error = ::posix_spawn(&pid_, DREAM_PYTHON3_EXECUTABLE, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(ends[1]);
  socket_ = ends[0];
  if (spawn_error != 0) {
    pid_ = -1;
    throw std::runtime_error(std::string("cannot start ") + DREAM_PYTHON3_EXECUTABLE + " for " + script);
  }
  outgoing_ = nlohmann::json{{"spec_bytes", spec_json.size()}, {"robots", num_robots}}.dump() + "\n" + spec_json;
}

PythonStepMetrics::~PythonStepMetrics() {
  if (socket_ >= 0) ::close(socket_);
  if (pid_ > 0) {
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
  }
  if (errors_ >= 0) ::close(errors_);
}

void PythonStepMetrics::Observe(const kind_api::RunPoses::Step& step) {
  if (step.poses.size() != static_cast<size_t>(num_robots_)) {
    throw std::runtime_error("step " + std::to_string(step.step) + " has " + std::to_string(step.poses.size()) +
                             " robots, the run " + std::to_string(num_robots_));
  }
  pose_numbers_ += 3 * num_robots_;
  if (pose_numbers_ > kMaxPoseNumbers) {
    throw std::runtime_error("the run passed " + std::to_string(kMaxPoseNumbers) + " pose numbers at step " +
                             std::to_string(step.step) + ": too long to follow live");
  }
  batch_steps_.push_back(step.step);
  for (const Eigen::Vector3d& pose : step.poses)
    batch_poses_.insert(batch_poses_.end(), {pose.x(), pose.y(), pose.z()});
  observed_step_ = step.step;
  observed_any_ = true;
}

void PythonStepMetrics::QueueBatch() {
  if (batch_steps_.empty()) return;
  const uint32_t count = static_cast<uint32_t>(batch_steps_.size());
  outgoing_.push_back('S');
  Append(&outgoing_, &count, 1);
  Append(&outgoing_, batch_steps_.data(), batch_steps_.size());
  Append(&outgoing_, batch_poses_.data(), batch_poses_.size());
  batch_steps_.clear();
  batch_poses_.clear();
}

[[noreturn]] void PythonStepMetrics::Stopped(const std::string& why) {
  const std::string errors = errors_ >= 0 ? ErrorsIn(errors_) : std::string();
  throw std::runtime_error("the controller's metrics() helper stopped (" + why + ")" +
                           (errors.empty() ? std::string() : ": " + errors));
}

void PythonStepMetrics::Send() {
  size_t sent = 0;
  while (sent < outgoing_.size()) {
    const ssize_t n = ::send(socket_, outgoing_.data() + sent, outgoing_.size() - sent, MSG_NOSIGNAL | MSG_DONTWAIT);
    if (n > 0) {
      sent += static_cast<size_t>(n);
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      break;  // the helper is busy: the rest waits here
    } else {
      Stopped(std::strerror(errno));
    }
  }
  outgoing_.erase(0, sent);
}

void PythonStepMetrics::Receive() {
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::recv(socket_, buffer, sizeof(buffer), MSG_DONTWAIT);
    if (n > 0) {
      incoming_.append(buffer, static_cast<size_t>(n));
      for (size_t end; (end = incoming_.find('\n')) != std::string::npos;) {
        TakeAnswer(incoming_.substr(0, end));
        incoming_.erase(0, end + 1);
      }
      if (incoming_.size() > kMaxAnswerBytes) Stopped("an answer of over 1 MiB");
    } else if (n == 0) {
      Stopped("it ended");
    } else if (errno == EINTR) {
      continue;
    } else if (errno == EAGAIN || errno == EWOULDBLOCK) {
      return;
    } else {
      Stopped(std::strerror(errno));
    }
  }
}

void PythonStepMetrics::TakeAnswer(const std::string& line) {
  const nlohmann::json answer = nlohmann::json::parse(line, nullptr, false);
  if (!answer.is_object() || !answer.contains("step") || !answer["step"].is_number_integer()) {
    Stopped("it wrote " + line.substr(0, 80));
  }
  const auto now = std::chrono::steady_clock::now();
  asked_ = false;
  // The first answer's wait holds the helper's start-up too (Python, numpy, the class's module),
  // seconds on a loaded machine at the view's lowered priority: not what an evaluation costs, so
  // it does not space the next ones (it did, past the end of a short run).
  const auto evaluation = answered_first_ ? now - asked_at_ : std::chrono::steady_clock::duration::zero();
  answered_first_ = true;
  next_due_ = now + std::max<std::chrono::steady_clock::duration>(kMinInterval, 3 * evaluation);
  if (answer.contains("error") && answer["error"].is_string()) {
    last_error_ = answer["error"].get<std::string>();  // the figures stay the last computed; the next steps are tried
    answered_step_ = asked_step_;
    return;
  }
  if (!answer.contains("figures") || !answer["figures"].is_object()) Stopped("it wrote " + line.substr(0, 80));
  figures_.clear();
  for (const auto& [name, value] : answer["figures"].items()) {
    if (value.is_number()) figures_.emplace_back(name, value.get<double>());
  }
  figures_step_ = answer["step"].get<int64_t>();
  answered_step_ = asked_step_;
  answered_any_ = true;
}

int64_t PythonStepMetrics::Read(std::vector<Figure>* figures) {
  QueueBatch();
  if (asked_ && std::chrono::steady_clock::now() - asked_at_ > kMaxEvaluation) {
    Stopped("metrics() took more than " + std::to_string(kMaxEvaluation.count()) + " s");
  }
  if (!asked_ && observed_any_ && observed_step_ != asked_step_ && std::chrono::steady_clock::now() >= next_due_) {
    outgoing_.push_back('E');  // after every step queued: the answer is of all of them
    asked_ = true;
    asked_step_ = observed_step_;
    asked_at_ = std::chrono::steady_clock::now();
  }
  Send();
  Receive();
  *figures = figures_;
  return answered_any_ ? figures_step_ : -1;
}

bool PythonStepMetrics::Pending() const { return observed_any_ && answered_step_ != observed_step_; }

}  // namespace dream::python
