#include "dream/view/video_exports.h"

#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <fstream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <thread>

namespace dream::view {
namespace {

/// A render the test holds until it says go: each frame a byte, progress told.
class FakeRender {
 public:
  VideoExports::Render Function() {
    return [this](const VideoExportRequest& request, const std::string& out,
                  const std::function<void(int, int)>& progress, const std::atomic<bool>& stop) {
      std::unique_lock<std::mutex> lock(mutex_);
      asked_ = request;
      started_ = true;
      changed_.notify_all();
      // stop is an atomic the exports set without this lock: looked at again every millisecond.
      while (!changed_.wait_for(lock, std::chrono::milliseconds(1), [&] { return go_ || stop.load(); })) {
      }
      if (stop.load()) {
        stopped_ = true;
        return;
      }
      if (!failure_.empty()) throw std::runtime_error(failure_);
      progress(1, 2);
      progress(2, 2);
      std::ofstream(out) << "video of " << request.width_px;
    };
  }
  void WaitStarted() {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return started_; });
  }
  void Go(const std::string& failure = "") {
    std::lock_guard<std::mutex> lock(mutex_);
    go_ = true;
    failure_ = failure;
    changed_.notify_all();
  }
  bool stopped() {
    std::lock_guard<std::mutex> lock(mutex_);
    return stopped_;
  }
  VideoExportRequest asked() {
    std::lock_guard<std::mutex> lock(mutex_);
    return asked_;
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  bool started_ = false;
  bool go_ = false;
  bool stopped_ = false;
  std::string failure_;
  VideoExportRequest asked_;
};

VideoExports::Run GoToGoal() {
  VideoExports::Run run;
  run.name = "go to/goal";
  run.render_command = "dream render runs/go_to_goal";
  run.first_step = 0;
  run.last_step = 206;
  return run;
}

nlohmann::json Status(const VideoExports& exports) { return nlohmann::json::parse(exports.StatusJson()); }

/// The status once its state is `state` (the render thread gets there on its own; the deadline
/// only turns a hang into a failure).
nlohmann::json WaitFor(const VideoExports& exports, const std::string& state) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
  while (Status(exports)["state"] != state && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  return Status(exports);
}

TEST(VideoExportsTest, OneExportAtATimeWithItsProgressAndTheVideoForDownload) {
  FakeRender render;
  VideoExports exports(GoToGoal(), render.Function());
  EXPECT_EQ(Status(exports)["state"], "idle");
  EXPECT_FALSE(exports.Finished().bytes);

  const VideoExports::Answer started = exports.Start("width=480&from=10&to=100");
  EXPECT_EQ(started.status, 202);
  const nlohmann::json running = nlohmann::json::parse(started.json);
  EXPECT_EQ(running["state"], "running");
  EXPECT_EQ(running["job"], 1);
  EXPECT_EQ(running["command"],
            "dream render runs/go_to_goal --out go_to_goal_steps_10-100.mp4 --width 480 --fps 30 --speed 4 --trail 10 "
            "--steps 10-100");
  render.WaitStarted();
  EXPECT_EQ(render.asked().width_px, 480);

  const VideoExports::Answer busy = exports.Start("");
  EXPECT_EQ(busy.status, 409);
  EXPECT_NE(busy.json.find("busy: export 1 is being drawn"), std::string::npos) << busy.json;
  EXPECT_EQ(exports.Start("fps=1000").status, 400);  // checked before busy: says what is wrong

  render.Go();
  const nlohmann::json done = WaitFor(exports, "done");
  EXPECT_EQ(done["drawn"], 2);
  EXPECT_EQ(done["total"], 2);
  EXPECT_EQ(done["file"], "go_to_goal_steps_10-100.mp4");
  EXPECT_EQ(done["bytes"], 12);
  const VideoExports::Video video = exports.Finished();
  ASSERT_TRUE(video.bytes);
  EXPECT_EQ(*video.bytes, "video of 480");
  EXPECT_EQ(video.file_name, "go_to_goal_steps_10-100.mp4");
}

TEST(VideoExportsTest, AFailedRenderSaysWhyAndTheNextExportStarts) {
  FakeRender failing;
  VideoExports exports(GoToGoal(), failing.Function());
  EXPECT_EQ(exports.Start("format=gif").status, 202);
  failing.Go("ffmpeg is not installed");
  const nlohmann::json failed = WaitFor(exports, "failed");
  EXPECT_EQ(failed["error"], "ffmpeg is not installed");
  EXPECT_FALSE(exports.Finished().bytes);
  EXPECT_EQ(exports.Start("format=gif").status, 202);  // not busy: the failed one is over
  EXPECT_EQ(Status(exports)["job"], 2);
}

TEST(VideoExportsTest, ABadQueryIsRefusedWithTheReason) {
  FakeRender render;
  VideoExports exports(GoToGoal(), render.Function());
  const VideoExports::Answer refused = exports.Start("from=0&to=999");
  EXPECT_EQ(refused.status, 400);
  EXPECT_EQ(nlohmann::json::parse(refused.json)["error"], "from=0&to=999: not in the run (steps 0-206)");
  EXPECT_EQ(Status(exports)["state"], "idle");
}

TEST(VideoExportsTest, GoingAwayStopsTheRenderInProgress) {
  FakeRender render;
  {
    VideoExports exports(GoToGoal(), render.Function());
    EXPECT_EQ(exports.Start("").status, 202);
    render.WaitStarted();
  }  // the destructor sets stop and joins: the held render returns
  EXPECT_TRUE(render.stopped());
}

TEST(VideoExportsTest, FileNamesHoldSafeCharactersOnly) {
  FakeRender render;
  VideoExports::Run run = GoToGoal();
  run.name = "../\"evil\";\r\nname";
  VideoExports exports(run, render.Function());
  EXPECT_EQ(exports.FileName(VideoExportRequest{}), "run..__evil____name_steps_0-206.mp4");
  run.name = "";
  EXPECT_EQ(VideoExports(run, render.Function()).FileName(VideoExportRequest{}), "run_steps_0-206.mp4");
}

}  // namespace
}  // namespace dream::view
