// world.realism in a run config: presets, maps, defaults, and an error naming
// file, line and key for every bad value.
#include <gtest/gtest.h>

#include <string>

#include "dream/config/run_config.h"
#include "dream/config/world_of_config.h"
#include "dream/world/realism_params.h"
#include "dream/world/realistic_world.h"
#include "dream/world/unicycle_world.h"

namespace dream::config {
namespace {

std::string ConfigWith(const std::string& world_lines) {
  return "name: demo\nrobots: 1\nsteps: 10\ninitial_poses:\n  - [0.0, 0.0, 0.0]\n"
         "world:\n  mode: lockstep\n" + world_lines +
         "controller:\n  kind: go_to_goal\n  goals: [[0.1, 0.1]]\n";
}

RunConfig Load(const std::string& text) { return LoadRunConfig(ConfigNode::LoadString(text, "test.yaml")); }

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
  const std::unique_ptr<sim::World> ideal = WorldOfConfig(Load(ConfigWith("")));
  EXPECT_NE(dynamic_cast<const sim::UnicycleWorld*>(ideal.get()), nullptr);
  const std::unique_ptr<sim::World> lab = WorldOfConfig(Load(ConfigWith("  realism: lab\n")));
  ASSERT_NE(dynamic_cast<const sim::RealisticWorld*>(lab.get()), nullptr);
  EXPECT_EQ(lab->num_robots(), 1);
}

TEST(RealismConfigTest, PresetNameGivesThePreset) {
  EXPECT_EQ(Load(ConfigWith("  realism: lab\n")).realism, sim::RealismParams::Lab());
}

TEST(RealismConfigTest, MapStartsFromItsPresetOrIdeal) {
  const sim::RealismParams lab_with_noise =
      Load(ConfigWith("  realism:\n    preset: lab\n    pose_noise_m: 0.003\n    pose_delay_steps: 2\n")).realism;
  sim::RealismParams expected = sim::RealismParams::Lab();
  expected.pose_noise_m = 0.003;
  expected.pose_delay_steps = 2;
  EXPECT_EQ(lab_with_noise, expected);

  const sim::RealismParams noise_only = Load(ConfigWith("  realism: {pose_noise_m: 0.002}\n")).realism;
  expected = sim::RealismParams::Ideal();
  expected.pose_noise_m = 0.002;
  EXPECT_EQ(noise_only, expected);
  EXPECT_FALSE(noise_only.IsIdeal());
}

TEST(RealismConfigTest, TrackerDropAndDropoutBurstsAreRead) {
  EXPECT_EQ(sim::RealismParams::Lab().tracker_drop_s, 5.0);
  EXPECT_EQ(sim::RealismParams::Ideal().tracker_drop_s, 0.0);
  const sim::RealismParams read =
      Load(ConfigWith("  realism:\n    preset: lab\n    tracker_drop_s: 2.5\n    tracking_dropout_mean_steps: 30\n"))
          .realism;
  sim::RealismParams expected = sim::RealismParams::Lab();
  expected.tracker_drop_s = 2.5;
  expected.tracking_dropout_mean_steps = 30.0;
  EXPECT_EQ(read, expected);
  EXPECT_NE(read, sim::RealismParams::Lab());
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
  for (const sim::RealismParams::Field& field : sim::RealismParams::Fields()) {
    SCOPED_TRACE(field.key);
    ASSERT_TRUE((field.number == nullptr) != (field.steps == nullptr));
    // Ideal()'s value plus a half (plus one step): valid for every field.
    sim::RealismParams expected = sim::RealismParams::Ideal();
    std::string value;
    if (field.steps != nullptr) {
      expected.*field.steps += 1;
      value = std::to_string(expected.*field.steps);
    } else {
      expected.*field.number += 0.5;
      value = std::to_string(expected.*field.number);
    }
    const sim::RealismParams read =
        Load(ConfigWith("  realism:\n    " + std::string(field.key) + ": " + value + "\n")).realism;
    EXPECT_EQ(read, expected);
    EXPECT_NE(read, sim::RealismParams::Ideal());
  }
  // A member added to RealismParams without its entry in Fields() makes the
  // struct larger than the fields listed: each takes a double's room (the two
  // step counts sit between doubles, so each is padded to 8 bytes).
  EXPECT_EQ(sim::RealismParams::Fields().size() * sizeof(double), sizeof(sim::RealismParams));
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
                        "(did you mean 'lab'?); known presets: ideal, lab"), std::string::npos) << preset;

  const std::string map_preset = ErrorOf(ConfigWith("  realism: {preset: real}\n"));
  EXPECT_NE(map_preset.find("known presets: ideal, lab"), std::string::npos) << map_preset;

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

}  // namespace
}  // namespace dream::config
