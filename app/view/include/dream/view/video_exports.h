#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>

#include "dream/view/video_export_request.h"
#include "dream/world/arena.h"

namespace dream::view {

/// The view's video exports of one run: one at a time (a second is refused
/// as busy while one is drawn), drawn on a thread of its own by a function
/// the caller gives (`dream render`'s RenderWorkflow: the same drawing as the
/// command), with its progress for the page, the finished video kept in
/// memory for the download until the next export. Thread-safe.
class VideoExports {
 public:
  /// Draws `request` into `out_path` (a file in a private temporary folder),
  /// telling `progress` the frames drawn of those to draw; returns early when
  /// `stop` is set. Throws what is wrong (its message goes to the page).
  using Render =
      std::function<void(const VideoExportRequest& request, const std::string& out_path,
                         const std::function<void(int drawn, int total)>& progress, const std::atomic<bool>& stop)>;

  struct Run {
    std::string name;            ///< the run's name, for the download's file name ("" : "run")
    std::string render_command;  ///< "dream render runs/x", shell-quoted: the printed command's start
    world::Arena arena;          ///< bounds the viewport
    int64_t first_step = 0;      ///< the run's steps: bound the step range
    int64_t last_step = 0;
  };

  /// Videos larger than this are refused rather than held in memory.
  static constexpr int64_t kMaxVideoBytes = int64_t{512} << 20;

  VideoExports(Run run, Render render);
  /// Stops a render in progress and waits for it.
  ~VideoExports();
  VideoExports(const VideoExports&) = delete;
  VideoExports& operator=(const VideoExports&) = delete;

  /// The answer to one request: an HTTP status and a JSON body.
  struct Answer {
    int status = 200;
    std::string json;
  };
  /// /export/start?`query`: 202 and the job's status when it starts; 400
  /// naming the bad parameter; 409 while another export is drawn.
  Answer Start(std::string_view query);
  /// /export/status: {"state": "idle"|"running"|"done"|"failed", "job", "drawn",
  /// "total", "error", "file", "bytes", "command"}.
  std::string StatusJson() const;
  /// The finished video (null when none is done) and its file name.
  struct Video {
    std::shared_ptr<const std::string> bytes;
    std::string file_name;
  };
  Video Finished() const;
  /// The video's file name for `request`: "<run>_steps_<a>-<b>.mp4", safe characters only.
  std::string FileName(const VideoExportRequest& request) const;

 private:
  enum class State { kIdle, kRunning, kDone, kFailed };
  void Draw(VideoExportRequest request, std::string file_name);
  std::string StatusJsonLocked() const;

  const Run run_;
  const Render render_;
  mutable std::mutex mutex_;
  State state_ = State::kIdle;
  int64_t job_ = 0;
  int drawn_ = 0;
  int total_ = 0;
  std::string error_;
  std::string command_;
  Video video_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace dream::view
