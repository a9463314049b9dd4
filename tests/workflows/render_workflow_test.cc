// RenderWorkflow: a run folder drawn as a picture and as a plot, what it
// prints, options that do not go together, and a stop before anything is written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <sstream>

#include "../bridge/bridge_test_support.h"
#include "dream/files/stopped.h"
#include "dream/view/video_export_request.h"
#include "dream/workflows/render_workflow.h"
#include "workflow_test_support.h"

namespace dream::workflows {
namespace {

namespace fs = std::filesystem;
using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::StartsWith;

TEST(RenderWorkflowTest, ARunFolderIsDrawnAsAPictureWithItsRobotsAndSteps) {
  std::ostringstream out;
  RenderWorkflow::Options options;
  options.run_or_log = testing::SimulatedRun();
  options.out = bridge::testing::NewFolder("render_workflow") + "/picture.svg";
  const RenderWorkflow::Result result = RenderWorkflow(out).Render(options);
  EXPECT_FALSE(result.interrupted);
  EXPECT_EQ(result.out, options.out);
  EXPECT_GT(fs::file_size(options.out), 0u);
  EXPECT_THAT(out.str(), StartsWith("picture: " + options.out + " (8 robots, "));
}

TEST(RenderWorkflowTest, APlotDrawsTheSeriesAskedForAndRefusesOneTheRunHasNot) {
  std::ostringstream out;
  RenderWorkflow::Options options;
  options.run_or_log = testing::SimulatedRun();
  options.out = bridge::testing::NewFolder("render_workflow") + "/plot.png";
  options.metrics = {"min_distance_m"};  // implies the plot
  RenderWorkflow(out).Render(options);
  EXPECT_TRUE(fs::is_regular_file(options.out));
  EXPECT_EQ(out.str(), "plot:    " + options.out + " (1 series)\n");

  options.metrics = {"no_such_series"};
  try {
    RenderWorkflow(out).Render(options);
    FAIL() << "plotted a series the run does not have";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("--metric no_such_series: not a series of this run; it has: "));
  }
}

TEST(RenderWorkflowTest, OptionsThatDoNotGoTogetherAreAUsageError) {
  RenderWorkflow::Options options;
  options.run_or_log = testing::SimulatedRun();
  options.plot = true;
  options.video = true;
  EXPECT_THROW(RenderWorkflow().Render(options), RenderWorkflow::UsageError);
  options.plot = false;
  options.out = "picture.bmp";
  EXPECT_THROW(RenderWorkflow().Render(options), RenderWorkflow::UsageError);
}

TEST(RenderWorkflowTest, VideoOnlyOptionsAreRefusedForPicturesAndPlots) {
  for (const char* out : {"picture.svg", "picture.png"}) {
    for (int option = 0; option < 3; ++option) {
      RenderWorkflow::Options options;
      options.run_or_log = testing::SimulatedRun();
      options.out = out;
      options.plot = out == std::string("picture.png");
      if (option == 0) options.viewport = "0,0,1,1";
      if (option == 1) options.steps = "1-2";
      if (option == 2) options.robot_ids = false;
      try {
        RenderWorkflow().Render(options);
        ADD_FAILURE() << out << ": option " << option << " accepted";
      } catch (const RenderWorkflow::UsageError& e) {
        EXPECT_THAT(e.what(), HasSubstr("is for videos (.mp4, .gif)"));
      }
    }
  }
}

TEST(RenderWorkflowTest, AStepRangeIsFirstDashLastInWholeSteps) {
  EXPECT_EQ(RenderWorkflow::ParseStepRange("120-480"), (std::pair<int64_t, int64_t>{120, 480}));
  EXPECT_EQ(RenderWorkflow::ParseStepRange("7-7"), (std::pair<int64_t, int64_t>{7, 7}));
  for (const char* bad : {"", "120", "-480", "120-", "a-b", "1-2-3", "-1-5", "1.5-3", "9999999999999-1"}) {
    try {
      RenderWorkflow::ParseStepRange(bad);
      ADD_FAILURE() << bad << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_THAT(e.what(), StartsWith(std::string("--steps ") + bad));
    }
  }
  EXPECT_THROW(RenderWorkflow::ParseStepRange("480-120"), std::invalid_argument);
}

TEST(RenderWorkflowTest, AStopBeforeDrawingWritesNothing) {
  const std::atomic<bool> stop{true};
  RenderWorkflow::Options options;
  options.run_or_log = testing::SimulatedRun();
  options.out = bridge::testing::NewFolder("render_workflow") + "/stopped.svg";
  options.stop = &stop;
  EXPECT_THROW(RenderWorkflow().Render(options), files::Stopped);
  EXPECT_FALSE(fs::exists(options.out));
}

// dream view's Export video draws what `dream render` makes of the command the
// page prints: every field of a request reaches the options through it.
TEST(RenderWorkflowTest, AVideoExportRequestMeansWhatItsPrintedCommandMeans) {
  const std::string query =
      "format=gif&width=640&fps=12.5&speed=2&trail=3&x0=-1&y0=-0.5&x1=0.5&y1=0.5&from=10&to=200"
      "&goals=0&violations=0&ids=0&drawings=0&radio=1&sensors=1";
  for (const std::string& asked : {std::string(), query}) {
    SCOPED_TRACE(asked);
    const view::VideoExportRequest request = view::VideoExportRequest::Parse(asked, {}, 0, 300);
    std::vector<std::string> words = request.RenderArguments();
    words.insert(words.end(), {"--out=-odd/run.gif", "--", "-odd/run"});
    const RenderWorkflow::Options options = RenderWorkflow::OptionsOfCommand(words);
    EXPECT_EQ(options.run_or_log, "-odd/run");
    EXPECT_EQ(options.out, "-odd/run.gif");
    EXPECT_EQ(options.width_px, request.width_px);
    EXPECT_EQ(options.fps, request.fps);
    EXPECT_EQ(options.speed, request.speed);
    EXPECT_EQ(options.trail_s, request.trail_s);
    EXPECT_EQ(options.viewport, request.viewport ? request.viewport->Text() : "");
    EXPECT_EQ(options.steps, request.first_step >= 0 ? "10-200" : "");
    EXPECT_EQ(options.goals, request.goals);
    EXPECT_EQ(options.violations, request.violations);
    EXPECT_EQ(options.robot_ids, request.robot_ids);
    EXPECT_EQ(options.drawings, request.drawings);
    EXPECT_EQ(options.radio_links, request.radio_links);
    EXPECT_EQ(options.sensor_ranges, request.sensor_ranges);
  }
}

TEST(RenderWorkflowTest, WordsDreamRenderRefusesAreRefusedNamingThem) {
  auto refusal = [](const std::vector<std::string>& words) {
    try {
      RenderWorkflow::OptionsOfCommand(words);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_THAT(refusal({"run", "--fps", "500"}), AllOf(StartsWith("dream render run --fps 500: "), HasSubstr("--fps")));
  EXPECT_THAT(refusal({"run", "--frames", "5"}), HasSubstr("--frames"));
  EXPECT_THAT(refusal({}), HasSubstr("run"));
}

}  // namespace
}  // namespace dream::workflows
