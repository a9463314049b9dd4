// The controller strategy's C++ parts: the flat runtime files, the checks on
// the controller module's name, the obstacle schedule against the world that
// moves the obstacles in a simulated run, the spec's uint8 .npy and the
// parameter file formats.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <set>

#include "bridge_test_support.h"
#include "dream/bridge/flat_python_runtime.h"
#include "dream/formats/npy_file.h"
#include "dream/bridge/obstacle_schedule.h"
#include "dream/bridge/submission_format.h"
#include "dream/bridge/submission_params.h"
#include "dream/world/unicycle_world.h"
#include "../support/source_tree.h"

namespace dream::bridge {
namespace {

using ::testing::HasSubstr;

std::string ErrorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(FlatPythonRuntimeTest, RewritesRelativeImportsToFlatModules) {
  const std::string text =
      "\"\"\"Doc.\"\"\"\nimport math\n\nfrom .robot import Robot, key\n    from .timer import Timer\nx = 1\n";
  EXPECT_EQ(FlatPythonRuntime::Flatten("sensors", text, "sensors.py"),
            "\"\"\"Doc.\"\"\"\nimport math\n\nfrom dream_robot import Robot, key\n    from dream_timer import Timer\nx "
            "= 1\n");
}

TEST(FlatPythonRuntimeTest, RefusesImportsTheFlatLayoutCannotFollowNamingFileAndLine) {
  auto error = [](const std::string& line) {
    return ErrorOf([&] { FlatPythonRuntime::Flatten("robot", "import os\n" + line + "\n", "robot.py"); });
  };
  EXPECT_THAT(error("from .lcm import Lcm"),
              HasSubstr("robot.py:2: imports .lcm, which a Robotarium submission does not ship"));
  EXPECT_THAT(error("from . import timer"), HasSubstr("robot.py:2: 'from . import timer'"));
  EXPECT_THAT(error("import dream.timer"), HasSubstr("robot.py:2:"));
  EXPECT_THAT(error("from .timer import (Timer,"), HasSubstr("robot.py:2: a relative import spans lines"));
}

TEST(FlatPythonRuntimeTest, ShipsTheRuntimeFlatWithoutItsTransport) {
  const FlatPythonRuntime runtime = FlatPythonRuntime::Read(dream::testing::SourceDir() + "/python");
  std::vector<std::string> names;
  for (const FlatPythonRuntime::File& file : runtime.files()) {
    names.push_back(file.name);
    EXPECT_EQ(file.text.find("from ."), std::string::npos) << file.name;
  }
  EXPECT_THAT(names, ::testing::UnorderedElementsAre(
                         "dream.py", "dream_robot.py", "dream_motion.py", "dream_drawing.py", "dream_sensors.py",
                         "dream_radios.py", "dream_timer.py", "dream_robot_agent.py", "dream_controller_spec.py",
                         "dream_hrvo.py", "dream_barriers.py", "dream_toolbox_checks.py", "dream_transformations.py",
                         "dream_controllers.py", "dream_graph.py", "dream_misc.py"));
  const std::set<std::string> imported = runtime.ImportedModules({"import rps.robotarium as r\n"});
  for (const char* name : {"numpy", "json", "os", "rps"}) EXPECT_EQ(imported.count(name), 1u) << name;
  EXPECT_THAT(ErrorOf([] { FlatPythonRuntime::Read("/nonexistent"); }),
              HasSubstr("/nonexistent/dream/motion.py: missing"));
}

TEST(FlatPythonRuntimeTest, ControllerModuleNamesThatCannotSitBesideTheScriptAreRefused) {
  const std::set<std::string> taken = {"numpy", "json", "rps"};
  const std::string code = "from dream import Robot\nimport math\n";
  EXPECT_EQ(FlatPythonRuntime::ControllerFileName("/x/my_robot.py", code, taken, "c.yaml"), "my_robot.py");
  for (const char* bad : {"/x/dream_robot.py", "/x/dream.py", "/x/numpy.py", "/x/class.py", "/x/my-robot.py"}) {
    const std::string error = ErrorOf([&] { FlatPythonRuntime::ControllerFileName(bad, code, taken, "c.yaml"); });
    EXPECT_THAT(error, HasSubstr(std::string("c.yaml: controller.module: '") + bad + "'")) << bad;
  }
  // A helper beside the module would not be shipped.
  const std::string dir = ::testing::TempDir() + "controller_helper";
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/helpers.py") << "X = 1\n";
  EXPECT_THAT(ErrorOf([&] {
                FlatPythonRuntime::ControllerFileName(dir + "/mine.py", "from helpers import X\n", taken, "c.yaml");
              }),
              HasSubstr("it imports 'helpers', which sits beside it"));
  EXPECT_THAT(ErrorOf([&] {
                FlatPythonRuntime::ControllerFileName("/x/mine.py", "from .helpers import X\n", taken, "c.yaml");
              }),
              HasSubstr("it imports relatively"));
}

TEST(ObstacleScheduleTest, EveryStepEqualsWhatTheWorldReports) {
  world::RectangleObstacleSpec moving;
  moving.id = 4;
  moving.center_m = {-1.3, 0.9};
  moving.width_m = 0.3;
  moving.height_m = 0.1;
  moving.path = world::ObstaclePath{
      {Eigen::Vector2d(1.3, 0.9), Eigen::Vector2d(1.3, -0.9)}, 0.7, world::ObstaclePathMode::kPingPong};
  world::RectangleObstacleSpec still;
  still.id = 9;
  still.center_m = {0.0, 0.0};
  still.width_m = 0.2;
  still.height_m = 0.2;
  const std::vector<world::RectangleObstacleSpec> specs = {moving, still};
  const int64_t steps = 600;  // several laps, corners included
  const formats::NpyArray schedule = ObstacleSchedule(specs, 0.033, steps);
  ASSERT_EQ(schedule.shape, (std::vector<int64_t>{steps + 1, 2, kObstacleColumns}));
  world::UnicycleWorld world(world::WorldParams{}, {world::Pose2{0.5, 0.5, 0.0}}, specs);
  std::vector<world::ObstacleState> states;
  for (int64_t k = 0; k <= steps; ++k) {
    world.GetObstacleStates(&states);
    for (size_t m = 0; m < states.size(); ++m) {
      const double* row = &schedule.values[static_cast<size_t>((k * 2 + static_cast<int64_t>(m)) * kObstacleColumns)];
      const world::ObstacleState& s = states[m];
      const std::vector<double> expected = {
          static_cast<double>(s.id), s.center_x_m, s.center_y_m, s.width_m, s.height_m, s.vx_mps, s.vy_mps};
      ASSERT_EQ(std::vector<double>(row, row + kObstacleColumns), expected) << "step " << k << ", obstacle " << m;
    }
    world.Step();
  }
}

// A config may have 10,000 obstacles; their schedule over the lab's 15
// minutes would be 15 GB. Sizes saturate, and the bound is checked before
// anything is allocated.
TEST(ObstacleScheduleTest, SizeIsBoundedBeforeAllocating) {
  EXPECT_EQ(ObstacleScheduleBytes(2, 600), 601 * 2 * kObstacleColumns * 8);
  EXPECT_EQ(ObstacleScheduleBytes(0, INT64_MAX), 0);
  EXPECT_EQ(ObstacleScheduleBytes(10000, INT64_MAX - 1), INT64_MAX);
  EXPECT_GT(ObstacleScheduleBytes(10000, 27272), kMaxObstacleScheduleBytes);
  world::RectangleObstacleSpec still;
  still.width_m = still.height_m = 0.1;
  const std::vector<world::RectangleObstacleSpec> many(10000, still);
  EXPECT_THAT(ErrorOf([&] { ObstacleSchedule(many, 0.033, 27272); }),
              HasSubstr("an obstacle schedule of 10000 obstacles over 27272 steps would exceed 256 MiB"));
  EXPECT_THAT(ErrorOf([&] { ObstacleSchedule({still}, 0.033, -1); }), HasSubstr("needs steps >= 0, got -1"));
}

TEST(ControllerSpecFileTest, TextTravelsAsUint8Npy) {
  const std::string bytes = formats::EncodeNpyBytes("{\"a\": 1}");
  EXPECT_EQ(bytes.rfind("\x93NUMPY\x01\x00", 0), 0u);
  EXPECT_THAT(bytes, HasSubstr("{'descr': '|u1', 'fortran_order': False, 'shape': (8,), }"));
  EXPECT_EQ(bytes.size() % 64, 8u);  // the header is padded to 64 bytes, then the 8 bytes of text
  EXPECT_EQ(bytes.substr(bytes.size() - 8), "{\"a\": 1}");
}

TEST(SubmissionParamsTest, ControllerStrategyRoundTripsAndFormatOneIsStillRead) {
  SubmissionParams params;
  params.num_robots = 3;
  params.steps = 80;
  params.options.strategy = Strategy::kController;
  params.wheel_radius_m = 0.016;
  params.base_length_m = 0.11;
  params.max_wheel_speed_radps = 12.5;
  params.stop_when_done = true;
  params.max_abs_v_mps = 10.0;
  params.max_abs_w_radps = 100.0;
  const SubmissionParams read = SubmissionParams::FromNpy(params.ToNpy(), "p.npy");
  EXPECT_EQ(read.options.strategy, Strategy::kController);
  EXPECT_TRUE(read.stop_when_done);
  EXPECT_EQ(read.max_abs_w_radps, 100.0);

  // An export made before the controller strategy: 18 numbers, format 1.
  params.options.strategy = Strategy::kTrack;
  formats::NpyArray old = params.ToNpy();
  old.shape = {kParamCountFormat1};
  old.values.resize(kParamCountFormat1);
  old.values[kParamFormatVersion] = 1.0;
  const SubmissionParams old_read = SubmissionParams::FromNpy(old, "old.npy");
  EXPECT_EQ(old_read.options.strategy, Strategy::kTrack);
  EXPECT_FALSE(old_read.stop_when_done);
  old.values[kParamStrategy] = kStrategyController;  // format 1 had no controller strategy
  EXPECT_THAT(ErrorOf([&] { SubmissionParams::FromNpy(old, "old.npy"); }), HasSubstr("old.npy: unknown strategy"));
}

TEST(SubmissionParamsTest, TheBarrierCertificateRoundTripsAndFormatTwoGetsRpsDefaults) {
  SubmissionParams params;
  params.num_robots = 4;
  params.steps = 50;
  params.wheel_radius_m = 0.016;
  params.base_length_m = 0.11;
  params.max_wheel_speed_radps = 12.5;
  params.options.barriers = true;
  params.options.barrier_params = barriers::UnicycleBarrierParams::Rps();  // create_uni_barrier_certificate()
  const SubmissionParams read = SubmissionParams::FromNpy(params.ToNpy(), "p.npy");
  EXPECT_TRUE(read.options.barriers);
  EXPECT_EQ(read.options.barrier_params.safety_radius_m, 0.15);
  EXPECT_EQ(read.options.barrier_params.barrier_gain, 100.0);
  EXPECT_EQ(read.options.barrier_params.projection_distance_m, 0.05);
  EXPECT_FALSE(read.options.barrier_params.boundary.has_value());

  params.options.barrier_params = barriers::UnicycleBarrierParams::RpsWithBoundary();
  params.options.barrier_params.boundary->x_max_m = 1.4;
  const SubmissionParams boxed = SubmissionParams::FromNpy(params.ToNpy(), "p.npy");
  ASSERT_TRUE(boxed.options.barrier_params.boundary.has_value());
  EXPECT_EQ(boxed.options.barrier_params.boundary->x_max_m, 1.4);

  // An export made before the barriers' parameters: 21 numbers, format 2, rps's defaults.
  formats::NpyArray old = params.ToNpy();
  old.shape = {kParamCountFormat2};
  old.values.resize(kParamCountFormat2);
  old.values[kParamFormatVersion] = 2.0;
  const SubmissionParams old_read = SubmissionParams::FromNpy(old, "old.npy");
  EXPECT_TRUE(old_read.options.barriers);
  EXPECT_EQ(old_read.options.barrier_params.barrier_gain, 150.0);
  EXPECT_EQ(old_read.options.barrier_params.boundary->x_max_m, 1.6);

  formats::NpyArray bad = params.ToNpy();
  bad.values[kParamBarrierHasBoundary] = 2.0;
  EXPECT_THAT(ErrorOf([&] { SubmissionParams::FromNpy(bad, "bad.npy"); }), HasSubstr("bad.npy: barrier boundary"));
  bad = params.ToNpy();
  bad.values[kParamBarrierSafetyRadius] = 0.0;
  EXPECT_THAT(ErrorOf([&] { SubmissionParams::FromNpy(bad, "bad.npy"); }),
              HasSubstr("bad.npy: barriers: safety_radius_m = 0"));
}

}  // namespace
}  // namespace dream::bridge
