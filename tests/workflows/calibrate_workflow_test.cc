// CalibrateWorkflow: models held against a run (--check) with the picture
// asked for, and the options refused before anything is fitted or written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include "../bridge/bridge_test_support.h"
#include "dream/workflows/calibrate_workflow.h"
#include "workflow_test_support.h"

namespace dream::workflows {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

std::string ErrorOf(const CalibrateWorkflow::Options& options) {
  try {
    std::ostringstream out;
    CalibrateWorkflow(out).Calibrate(options);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(CalibrateWorkflowTest, WithoutOutOrCheckNothingIsRead) {
  CalibrateWorkflow::Options options;
  options.inputs = {"no/such/run"};
  EXPECT_THAT(ErrorOf(options), HasSubstr("give --out FILE.yaml"));
  options.out_path = "mylab.yaml";
  options.base = "nowhere";
  EXPECT_THAT(ErrorOf(options), HasSubstr("--base nowhere: not a realism preset"));
}

TEST(CalibrateWorkflowTest, ARealismFileIsYaml) {
  CalibrateWorkflow::Options options;
  options.inputs = {testing::SimulatedRun()};
  options.out_path = bridge::testing::NewFolder("calibrate_workflow") + "/mylab.txt";
  EXPECT_THAT(ErrorOf(options), HasSubstr("a realism file is YAML"));
  EXPECT_FALSE(fs::exists(options.out_path));
}

TEST(CalibrateWorkflowTest, CheckHoldsModelsAgainstTheRunsAndDrawsOnlyThePictureAsked) {
  const std::string folder = bridge::testing::NewFolder("calibrate_workflow_check");
  CalibrateWorkflow::Options options;
  options.inputs = {testing::SimulatedRun()};
  options.check_models = {"ideal", "lab"};
  options.picture_path = folder + "/check.png";
  std::ostringstream out;
  CalibrateWorkflow(out).Calibrate(options);
  EXPECT_THAT(out.str(), HasSubstr("\nWrote " + options.picture_path + "\n"));
  EXPECT_GT(fs::file_size(options.picture_path), 0u);
  EXPECT_EQ(std::distance(fs::directory_iterator(folder), fs::directory_iterator()), 1);  // no realism file

  options.check_models = {"no_such_model"};
  EXPECT_THAT(ErrorOf(options), HasSubstr("--check no_such_model: neither a realism preset"));
}

}  // namespace
}  // namespace dream::workflows
