// RenderWorkflow: a run folder drawn as a picture and as a plot, what it
// prints, options that do not go together, and a stop before anything is written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <sstream>

#include "../bridge/bridge_test_support.h"
#include "dream/files/stopped.h"
#include "dream/workflows/render_workflow.h"
#include "workflow_test_support.h"

namespace dream::workflows {
namespace {

namespace fs = std::filesystem;
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

}  // namespace
}  // namespace dream::workflows
