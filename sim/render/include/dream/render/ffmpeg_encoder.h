#pragma once

#include <sys/types.h>

#include <cstddef>
#include <string>
#include <vector>

namespace dream::render {

/// Encodes video frames with the `ffmpeg` program (Debian package `ffmpeg`):
/// starts it with raw frames on a pipe as its input, in cairo's RGB24 layout
/// (32 bits per pixel, native-endian xRGB), and `output_args` after the input
/// (filters, codec, format, output file). Its error output goes to a
/// temporary file and is quoted when it fails.
class FfmpegEncoder {
 public:
  /// The frames fed in.
  struct Input {
    int width_px = 0;
    int height_px = 0;
    double fps = 30.0;
  };

  /// Starts ffmpeg (found on PATH).
  /// @throws std::runtime_error "ffmpeg not found ... apt-get install ffmpeg"
  ///         when it is not installed, or when it cannot be started.
  FfmpegEncoder(const Input& input, const std::vector<std::string>& output_args);
  /// Stops ffmpeg if Finish() was not called (its output is then incomplete).
  ~FfmpegEncoder();
  FfmpegEncoder(const FfmpegEncoder&) = delete;
  FfmpegEncoder& operator=(const FfmpegEncoder&) = delete;

  /// One frame: height_px rows of width_px * 4 bytes, `stride_bytes` apart.
  /// @throws std::runtime_error quoting ffmpeg when it stopped early.
  void WriteFrame(const unsigned char* pixels, int stride_bytes);
  /// Ends the input and waits for ffmpeg.
  /// @throws std::runtime_error quoting ffmpeg's errors when it exits non-zero.
  void Finish();

  /// True when an executable `ffmpeg` is on PATH (checked before a long render starts).
  static bool IsInstalled();
  /// The message for a machine without ffmpeg.
  static std::string NotInstalledMessage();

 private:
  [[noreturn]] void FailWithErrors(const std::string& what);
  int WaitForExit();

  Input input_;
  pid_t pid_ = -1;
  int stdin_fd_ = -1;
  std::string stderr_path_;
  void (*previous_sigpipe_)(int) = nullptr;  // restored by the destructor
  bool sigpipe_changed_ = false;
};

}  // namespace dream::render
