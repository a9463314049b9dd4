// world.realism in a run config: presets, maps, defaults, and an error naming
// file, line and key for every bad value.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "dream/run_config/run_config.h"
#include "dream/run_config/world_of_config.h"
#include "dream/world/realism_params.h"
#include "dream/world/realistic_world.h"
#include "dream/world/unicycle_world.h"

namespace dream::config {
namespace {

std::string ConfigWith(const std::string& world_lines) {
  return "name: demo\nrobots: 1\nsteps: 10\ninitial_poses:\n  - [0.0, 0.0, 0.0]\n"
         "world:\n  mode: lockstep\n" +
         world_lines + "controller:\n  kind: go_to_goal\n  goals: [[0.1, 0.1]]\n";
}

run_config::RunConfig Load(const std::string& text) {
  return run_config::LoadRunConfig(ConfigNode::LoadString(text, "test.yaml"));
}

std::string ErrorOf(const std::string& text) {
  try {
    Load(text);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(RealismConfigTest, AbsentIsTheOfficialSimulator) {
  EXPECT_TRUE(Load(ConfigWith("")).realism.IsIdeal());
  EXPECT_TRUE(Load(ConfigWith("  realism: ideal\n")).realism.IsIdeal());
  EXPECT_TRUE(Load(ConfigWith("  realism: {preset: ideal}\n")).realism.IsIdeal());
}

// Ideal is the official simulator itself, with nothing in between; any
// other realism wraps it in a RealisticWorld.
TEST(RealismConfigTest, TheWorldOfAConfigIsTheOfficialOneUnlessRealismAsksOtherwise) {
  const std::unique_ptr<world::World> ideal = run_config::WorldOfConfig(Load(ConfigWith("")));
  EXPECT_NE(dynamic_cast<const world::UnicycleWorld*>(ideal.get()), nullptr);
  const std::unique_ptr<world::World> lab = run_config::WorldOfConfig(Load(ConfigWith("  realism: lab\n")));
  ASSERT_NE(dynamic_cast<const world::RealisticWorld*>(lab.get()), nullptr);
  EXPECT_EQ(lab->num_robots(), 1);
}

TEST(RealismConfigTest, PresetNameGivesThePreset) {
  EXPECT_EQ(Load(ConfigWith("  realism: lab\n")).realism, world::RealismParams::Lab());
}

TEST(RealismConfigTest, MapStartsFromItsPresetOrIdeal) {
  const world::RealismParams lab_with_noise =
      Load(ConfigWith("  realism:\n    preset: lab\n    pose_noise_m: 0.003\n    pose_delay_steps: 2\n")).realism;
  world::RealismParams expected = world::RealismParams::Lab();
  expected.pose_noise_m = 0.003;
  expected.pose_delay_steps = 2;
  EXPECT_EQ(lab_with_noise, expected);

  const world::RealismParams noise_only = Load(ConfigWith("  realism: {pose_noise_m: 0.002}\n")).realism;
  expected = world::RealismParams::Ideal();
  expected.pose_noise_m = 0.002;
  EXPECT_EQ(noise_only, expected);
  EXPECT_FALSE(noise_only.IsIdeal());
}

TEST(RealismConfigTest, TrackerDropAndDropoutBurstsAreRead) {
  EXPECT_EQ(world::RealismParams::Lab().tracker_drop_s, 5.0);
  EXPECT_EQ(world::RealismParams::Ideal().tracker_drop_s, 0.0);
  const world::RealismParams read =
      Load(ConfigWith("  realism:\n    preset: lab\n    tracker_drop_s: 2.5\n    tracking_dropout_mean_steps: 30\n"))
          .realism;
  world::RealismParams expected = world::RealismParams::Lab();
  expected.tracker_drop_s = 2.5;
  expected.tracking_dropout_mean_steps = 30.0;
  EXPECT_EQ(read, expected);
  EXPECT_NE(read, world::RealismParams::Lab());
  EXPECT_FALSE(Load(ConfigWith("  realism: {tracker_drop_s: 1}\n")).realism.IsIdeal());

  const std::string negative = ErrorOf(ConfigWith("  realism:\n    preset: lab\n    tracker_drop_s: -5\n"));
  EXPECT_NE(negative.find("test.yaml:10"), std::string::npos) << negative;
  EXPECT_NE(negative.find("tracker_drop_s = -5 is out of range"), std::string::npos) << negative;
  EXPECT_NE(negative.find(">= 0 s"), std::string::npos) << negative;

  const std::string short_burst = ErrorOf(ConfigWith("  realism:\n    tracking_dropout_mean_steps: 0\n"));
  EXPECT_NE(short_burst.find("test.yaml:9"), std::string::npos) << short_burst;
  EXPECT_NE(short_burst.find("tracking_dropout_mean_steps"), std::string::npos) << short_burst;
  EXPECT_NE(short_burst.find(">= 1 step"), std::string::npos) << short_burst;

  const std::string text = ErrorOf(ConfigWith("  realism:\n    tracker_drop_s: soon\n"));
  EXPECT_NE(text.find("test.yaml:9"), std::string::npos) << text;
  EXPECT_NE(text.find("tracker_drop_s"), std::string::npos) << text;
}

// RealismParams::Fields() is the one list of the models' keys: each entry is
// read from the config by its key into its own member, and operator== sees it.
TEST(RealismConfigTest, EveryFieldIsReadByItsKeyAndCompared) {
  for (const world::RealismParams::Field& field : world::RealismParams::Fields()) {
    SCOPED_TRACE(field.key);
    ASSERT_TRUE((field.number == nullptr) != (field.steps == nullptr));
    // Ideal()'s value plus a half (plus one step): valid for every field.
    world::RealismParams expected = world::RealismParams::Ideal();
    std::string value;
    if (field.steps != nullptr) {
      expected.*field.steps += 1;
      value = std::to_string(expected.*field.steps);
    } else {
      expected.*field.number += 0.5;
      value = std::to_string(expected.*field.number);
    }
    const world::RealismParams read =
        Load(ConfigWith("  realism:\n    " + std::string(field.key) + ": " + value + "\n")).realism;
    EXPECT_EQ(read, expected);
    EXPECT_NE(read, world::RealismParams::Ideal());
  }
  // A member added to RealismParams without its entry in Fields() makes the
  // struct larger than the fields listed: each takes a double's room (the two
  // step counts sit between doubles, so each is padded to 8 bytes).
  EXPECT_EQ(world::RealismParams::Fields().size() * sizeof(double), sizeof(world::RealismParams));
}

TEST(RealismConfigTest, BadValuesNameFileLineAndKey) {
  const std::string negative = ErrorOf(ConfigWith("  realism:\n    pose_noise_m: -0.001\n"));
  EXPECT_NE(negative.find("test.yaml:9"), std::string::npos) << negative;
  EXPECT_NE(negative.find("pose_noise_m"), std::string::npos) << negative;
  EXPECT_NE(negative.find(">= 0"), std::string::npos) << negative;

  const std::string probability =
      ErrorOf(ConfigWith("  realism:\n    preset: lab\n    tracking_dropout_probability: 1.5\n"));
  EXPECT_NE(probability.find("test.yaml:10"), std::string::npos) << probability;
  EXPECT_NE(probability.find("[0, 1]"), std::string::npos) << probability;

  const std::string preset = ErrorOf(ConfigWith("  realism: labb\n"));
  EXPECT_NE(preset.find("test.yaml:8"), std::string::npos) << preset;
  EXPECT_NE(preset.find("unknown realism preset 'labb' "
                        "(did you mean 'lab'?); known presets: ideal, lab, lab_v1"),
            std::string::npos)
      << preset;

  const std::string map_preset = ErrorOf(ConfigWith("  realism: {preset: real}\n"));
  EXPECT_NE(map_preset.find("known presets: ideal, lab, lab_v1"), std::string::npos) << map_preset;

  const std::string unknown = ErrorOf(ConfigWith("  realism:\n    pose_nosie_m: 0.001\n"));
  EXPECT_NE(unknown.find("pose_nosie_m"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("test.yaml:9"), std::string::npos) << unknown;

  const std::string delay = ErrorOf(ConfigWith("  realism:\n    command_latency_steps: 1000\n"));
  EXPECT_NE(delay.find("command_latency_steps"), std::string::npos) << delay;
  EXPECT_NE(delay.find("0..300"), std::string::npos) << delay;

  const std::string not_number = ErrorOf(ConfigWith("  realism:\n    axle_length_m: wide\n"));
  EXPECT_NE(not_number.find("axle_length_m"), std::string::npos) << not_number;

  const std::string zero_axle = ErrorOf(ConfigWith("  realism:\n    axle_length_m: 0\n"));
  EXPECT_NE(zero_axle.find("axle_length_m"), std::string::npos) << zero_axle;
}

// `file: PATH`: a realism file (what dream calibrate writes) as the base,
// relative to the config's folder, with the config's own keys over it.
class RealismFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() / ("dream_realism_file_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir_ / "labs");
    Write("labs/mylab.yaml", "preset: lab\nmotor_lag_s: 0.2  # fitted\ncommand_latency_steps: 6\n");
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  void Write(const std::string& name, const std::string& text) const { std::ofstream(dir_ / name) << text; }
  run_config::RunConfig LoadFile(const std::string& world_lines) const {
    Write("run.yaml", ConfigWith(world_lines));
    return run_config::LoadRunConfigFile((dir_ / "run.yaml").string());
  }
  std::string FileError(const std::string& world_lines) const {
    try {
      LoadFile(world_lines);
    } catch (const ConfigError& e) {
      return e.what();
    }
    return "";
  }
  std::filesystem::path dir_;
};

TEST_F(RealismFileTest, AFileIsTheBaseAndTheConfigsKeysGoOverIt) {
  const run_config::RunConfig config = LoadFile("  realism: {file: labs/mylab.yaml, pose_noise_m: 0.002}\n");
  world::RealismParams expected = world::RealismParams::Lab();
  expected.motor_lag_s = 0.2;
  expected.command_latency_steps = 6;
  expected.pose_noise_m = 0.002;
  EXPECT_EQ(config.realism, expected);
  EXPECT_EQ(config.realism_file_as_written, "labs/mylab.yaml");
  EXPECT_EQ(config.realism_file, (dir_ / "labs/mylab.yaml").lexically_normal().string());
  // An absolute path works from anywhere.
  EXPECT_EQ(LoadFile("  realism: {file: " + (dir_ / "labs/mylab.yaml").string() + "}\n").realism.motor_lag_s, 0.2);
}

TEST_F(RealismFileTest, BadFilesAreNamed) {
  EXPECT_NE(FileError("  realism: {file: labs/none.yaml}\n").find("no realism file"), std::string::npos);
  EXPECT_NE(FileError("  realism: {file: ../elsewhere.yaml}\n").find("leaves the config's folder"), std::string::npos);
  // preset:, then the file, then the config's keys; the file's own preset replaces the config's.
  Write("labs/partial.yaml", "motor_lag_s: 0.3\n");
  EXPECT_EQ(LoadFile("  realism: {preset: ideal, file: labs/partial.yaml}\n").realism.linear_gain_spread, 0.0);
  EXPECT_EQ(LoadFile("  realism: {preset: lab, file: labs/partial.yaml}\n").realism.linear_gain_spread,
            world::RealismParams::Lab().linear_gain_spread);
  EXPECT_EQ(LoadFile("  realism: {preset: ideal, file: labs/mylab.yaml}\n").realism.linear_gain_spread,
            world::RealismParams::Lab().linear_gain_spread);
  Write("labs/typo.yaml", "motor_lag: 0.2\n");
  const std::string typo = FileError("  realism: {file: labs/typo.yaml}\n");
  EXPECT_NE(typo.find("typo.yaml"), std::string::npos) << typo;
  EXPECT_NE(typo.find("motor_lag"), std::string::npos) << typo;
  Write("labs/bad.yaml", "preset: lab\nmotor_lag_s: -1\n");
  const std::string bad = FileError("  realism: {file: labs/bad.yaml}\n");
  EXPECT_NE(bad.find("bad.yaml:2"), std::string::npos) << bad;
  EXPECT_NE(bad.find("motor_lag_s"), std::string::npos) << bad;
  Write("labs/list.yaml", "- 1\n- 2\n");
  EXPECT_NE(FileError("  realism: {file: labs/list.yaml}\n").find("a realism file is a map"), std::string::npos);
}

TEST(RealismConfigTest, LabModelKeysAreReadAndChecked) {
  const world::RealismParams params =
      Load(ConfigWith(
               "  realism:\n    motor_lag_s: 0.1\n    motor_startup_m: 0.01\n    linear_gain_mean: 0.95\n"
               "    angular_gain_spread: 0.02\n    heading_drift_spread_radps: 0.005\n    step_overrun_mean_s: 0.001\n"
               "    loop_stall_probability: 0.001\n    loop_stall_max_s: 0.5\n    pose_noise_moving_factor: 2\n"
               "    tracking_dropout_at_rest_factor: 4\n"))
          .realism;
  EXPECT_EQ(params.motor_lag_s, 0.1);
  EXPECT_EQ(params.motor_startup_m, 0.01);
  EXPECT_EQ(params.linear_gain_mean, 0.95);
  EXPECT_EQ(params.angular_gain_spread, 0.02);
  EXPECT_EQ(params.heading_drift_spread_radps, 0.005);
  EXPECT_EQ(params.loop_stall_max_s, 0.5);
  EXPECT_EQ(params.tracking_dropout_at_rest_factor, 4.0);
  EXPECT_NE(ErrorOf(ConfigWith("  realism: {linear_gain_mean: 2}\n")).find("linear_gain_mean"), std::string::npos);
  EXPECT_NE(ErrorOf(ConfigWith("  realism: {pose_noise_moving_factor: 0.5}\n")).find("pose_noise_moving_factor"),
            std::string::npos);
  const std::string stall = ErrorOf(ConfigWith("  realism: {loop_stall_probability: 0.1, loop_stall_max_s: 11}\n"));
  EXPECT_NE(stall.find("loop_stall_max_s = 11"), std::string::npos) << stall;
}

}  // namespace
}  // namespace dream::config
