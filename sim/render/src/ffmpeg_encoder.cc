#include "dream/render/ffmpeg_encoder.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

extern char** environ;

namespace dream::render {
namespace {

// cairo's RGB24 pixel is a native-endian 32-bit xRGB word.
const char* RawPixelFormat() {
  const uint32_t probe = 1;
  unsigned char first_byte = 0;
  std::memcpy(&first_byte, &probe, 1);
  return first_byte == 1 ? "bgr0" : "0rgb";
}

std::string FormatFps(double fps) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.6g", fps);
  return text;
}

}  // namespace

bool FfmpegEncoder::IsInstalled() {
  const char* path = std::getenv("PATH");
  std::stringstream folders(path != nullptr ? path : "");
  std::string folder;
  while (std::getline(folders, folder, ':')) {
    const std::string program = (folder.empty() ? std::string(".") : folder) + "/ffmpeg";
    if (::access(program.c_str(), X_OK) == 0) return true;
  }
  return false;
}

std::string FfmpegEncoder::NotInstalledMessage() {
  return "ffmpeg not found on PATH: videos (.mp4, .gif) need it; install it with `apt-get install ffmpeg`";
}

FfmpegEncoder::FfmpegEncoder(const Input& input, const std::vector<std::string>& output_args) : input_(input) {
  char stderr_template[] = "/tmp/dream-ffmpeg-XXXXXX";
  const int stderr_fd = ::mkstemp(stderr_template);
  if (stderr_fd < 0)
    throw std::runtime_error(std::string("cannot create a temporary file for ffmpeg: ") + std::strerror(errno));
  stderr_path_ = stderr_template;
  int pipe_fds[2];
  if (::pipe2(pipe_fds, O_CLOEXEC) != 0) {
    ::close(stderr_fd);
    throw std::runtime_error(std::string("cannot create a pipe for ffmpeg: ") + std::strerror(errno));
  }

  std::vector<std::string> args = {
      "ffmpeg",      "-hide_banner",
      "-nostats",    "-loglevel",
      "error",       "-y",
      "-f",          "rawvideo",
      "-pix_fmt",    RawPixelFormat(),
      "-video_size", std::to_string(input.width_px) + "x" + std::to_string(input.height_px),
      "-framerate",  FormatFps(input.fps),
      "-i",          "-"};
  args.insert(args.end(), output_args.begin(), output_args.end());
  std::vector<char*> argv;
  for (std::string& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, pipe_fds[0], STDIN_FILENO);
  posix_spawn_file_actions_adddup2(&actions, stderr_fd, STDERR_FILENO);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  // This process ignores SIGPIPE while it writes; ffmpeg gets the default back.
  sigset_t default_signals;
  sigemptyset(&default_signals);
  sigaddset(&default_signals, SIGPIPE);
  posix_spawnattr_setsigdefault(&attributes, &default_signals);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF);
  const int error = ::posix_spawnp(&pid_, "ffmpeg", &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  ::close(pipe_fds[0]);
  ::close(stderr_fd);
  if (error != 0) {
    pid_ = -1;
    ::close(pipe_fds[1]);
    ::unlink(stderr_path_.c_str());
    if (error == ENOENT) throw std::runtime_error(NotInstalledMessage());
    throw std::runtime_error(std::string("cannot start ffmpeg: ") + std::strerror(error));
  }
  stdin_fd_ = pipe_fds[1];
  // A write to a pipe whose reader died raises SIGPIPE, which would end this
  // process without a word; as EPIPE it becomes an error quoting ffmpeg.
  previous_sigpipe_ = ::signal(SIGPIPE, SIG_IGN);
  sigpipe_changed_ = previous_sigpipe_ != SIG_ERR;
}

FfmpegEncoder::~FfmpegEncoder() {
  if (stdin_fd_ >= 0) ::close(stdin_fd_);
  if (pid_ > 0) {
    ::kill(pid_, SIGTERM);
    WaitForExit();
  }
  if (!stderr_path_.empty()) ::unlink(stderr_path_.c_str());
  if (sigpipe_changed_) ::signal(SIGPIPE, previous_sigpipe_);
}

void FfmpegEncoder::WriteFrame(const unsigned char* pixels, int stride_bytes) {
  const size_t row_bytes = static_cast<size_t>(input_.width_px) * 4;
  const bool packed = static_cast<size_t>(stride_bytes) == row_bytes;
  const int blocks = packed ? 1 : input_.height_px;
  const size_t block_bytes = packed ? row_bytes * static_cast<size_t>(input_.height_px) : row_bytes;
  for (int block = 0; block < blocks; ++block) {
    const unsigned char* data = pixels + static_cast<size_t>(block) * static_cast<size_t>(stride_bytes);
    size_t written = 0;
    while (written < block_bytes) {
      const ssize_t n = ::write(stdin_fd_, data + written, block_bytes - written);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) FailWithErrors(std::string("ffmpeg stopped reading frames (") + std::strerror(errno) + ")");
      written += static_cast<size_t>(n);
    }
  }
}

void FfmpegEncoder::Finish() {
  ::close(stdin_fd_);
  stdin_fd_ = -1;
  const int status = WaitForExit();
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    const std::string how = WIFEXITED(status) ? "exit " + std::to_string(WEXITSTATUS(status))
                                              : "signal " + std::to_string(WIFSIGNALED(status) ? WTERMSIG(status) : 0);
    FailWithErrors("ffmpeg failed (" + how + ")");
  }
}

int FfmpegEncoder::WaitForExit() {
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  pid_ = -1;
  return status;
}

void FfmpegEncoder::FailWithErrors(const std::string& what) {
  if (pid_ > 0) {
    if (stdin_fd_ >= 0) ::close(stdin_fd_);
    stdin_fd_ = -1;
    WaitForExit();
  }
  std::ifstream in(stderr_path_);
  std::stringstream text;
  text << in.rdbuf();
  std::string errors = text.str();
  while (!errors.empty() && (errors.back() == '\n' || errors.back() == ' ')) errors.pop_back();
  for (char& c : errors) {
    if (c == '\n') c = ' ';
  }
  if (errors.size() > 600) errors = "..." + errors.substr(errors.size() - 600);
  throw std::runtime_error(what + (errors.empty() ? std::string() : ": " + errors));
}

}  // namespace dream::render
