// dream calibrate's fit (LabCalibration) against a synthetic lab: the world's
// own lab model (RealisticWorld) with values unlike the lab preset's drives
// the calibration program, and every key the data determine comes back
// within its own 95 % interval. Also each refusal of calibrate's input.
#include "dream/calibration/lab_calibration.h"
#include "dream/calibration/lab_model_check.h"
#include "dream/calibration/calibration_picture.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "dream/calibration_drive/calibration_drive.h"
#include "dream/calibration/calibration_run.h"
#include "dream/formats/mat_file.h"
#include "dream/formats/npy_file.h"
#include "dream/files/atomic_file.h"
#include "dream/files/stop_token.h"
#include "dream/files/stopped.h"
#include "dream/robotarium/robotarium_constants.h"
#include "dream/world/printf_text.h"
#include "dream/world/realistic_world.h"
#include "run_arrays.h"

namespace dream::calibration {
namespace {

namespace fs = std::filesystem;
constexpr double kDt = robotarium::RobotariumConstants::kTimeStepSeconds;

// A lab unlike the preset: every fitted key differs from Lab()'s.
world::RealismParams SyntheticLab() {
  world::RealismParams lab = world::RealismParams::Lab();
  lab.pose_noise_m = 0.0005;
  lab.pose_noise_rad = 0.003;
  lab.pose_noise_moving_factor = 1.5;
  lab.pose_quantum_rad = 0.0001;
  lab.tracking_dropout_probability = 0.003;
  lab.tracking_dropout_at_rest_factor = 3.0;
  lab.tracking_dropout_mean_steps = 2.5;
  lab.command_latency_steps = 5;
  lab.motor_lag_s = 0.08;
  lab.motor_startup_m = 0.02;
  lab.linear_gain_mean = 1.03;
  lab.linear_gain_spread = 0.02;
  lab.angular_gain_mean = 0.85;
  lab.angular_gain_spread = 0.03;
  lab.heading_drift_mean_radps = 0.004;
  lab.heading_drift_spread_radps = 0.004;
  lab.step_overrun_mean_s = 0.002;
  lab.loop_stall_probability = 0.002;
  lab.loop_stall_max_s = 0.4;
  return lab;
}

using calibration_drive::CalibrationDrive;
using test_support::ArraysOf;

// The calibration program's start poses and commands as the world takes them.
std::vector<world::Pose2> StartPoses(int robots) {
  std::vector<world::Pose2> poses;
  for (const Eigen::Vector3d& pose : calibration_drive::CalibrationDrive::StartPoses(robots))
    poses.push_back({pose.x(), pose.y(), pose.z()});
  return poses;
}
world::UnicycleCommand CommandAt(int64_t step) {
  const agents::UnicycleCommand command = calibration_drive::CalibrationDrive::CommandAt(step);
  return {command.v_mps, command.w_radps};
}

// The calibration program twice on `robots` robots of a synthetic lab, as a
// lab run would record it: measured poses, commands sent, the step times.
CalibrationRun SyntheticRun(const world::RealismParams& lab, int robots, uint64_t seed, int repeats = 2) {
  world::RealisticWorld world(world::WorldParams{}, lab, seed, StartPoses(robots));
  CalibrationRun run;
  run.name = "synthetic lab (seed " + std::to_string(seed) + ")";
  run.timed = true;
  run.track.num_robots = robots;
  double time_s = 0;
  const int64_t steps = calibration_drive::CalibrationDrive::Steps() * repeats;
  for (int64_t k = 0; k < steps; ++k) {
    run.track.utime.push_back(std::llround(time_s * 1e6));
    const world::UnicycleCommand command = CommandAt(k % calibration_drive::CalibrationDrive::Steps());
    for (int i = 0; i < robots; ++i) {
      run.track.poses.push_back(world.poses()[static_cast<size_t>(i)]);
      run.track.commands.push_back(command);
      world.SetCommand(i, command);
    }
    world.Step();
    time_s += kDt + world.last_late_s();
  }
  run.track.obstacles.resize(run.track.utime.size());
  return run;
}

// Truth of `key` in a realism map.
double TruthOf(const world::RealismParams& lab, const std::string& key) {
  for (const world::RealismParams::Field& field : world::RealismParams::Fields()) {
    if (key == field.key) return field.number != nullptr ? lab.*field.number : lab.*field.steps;
  }
  return std::nan("");
}

// Three synthetic labs (seeds) of 12 robots each. A 95 % interval misses the
// truth one time in twenty, so a key must hold its truth in two of the three
// fits: a systematic bias misses in all three, chance in one at most (with
// 20 keys, some key misses once in most seeds; that is what 95 % means).
TEST(LabCalibrationTest, RecoversEveryDeterminedKeyOfASyntheticLabWithinItsInterval) {
  const world::RealismParams lab = SyntheticLab();
  const std::vector<std::string> must_determine = {"pose_noise_m",
                                                   "pose_noise_rad",
                                                   "pose_noise_moving_factor",
                                                   "pose_quantum_m",
                                                   "pose_quantum_rad",
                                                   "tracking_dropout_probability",
                                                   "tracking_dropout_at_rest_factor",
                                                   "tracking_dropout_mean_steps",
                                                   "command_latency_steps",
                                                   "motor_lag_s",
                                                   "motor_startup_m",
                                                   "linear_gain_mean",
                                                   "linear_gain_spread",
                                                   "angular_gain_mean",
                                                   "angular_gain_spread",
                                                   "heading_drift_mean_radps",
                                                   "heading_drift_spread_radps",
                                                   "step_overrun_mean_s",
                                                   "loop_stall_probability",
                                                   "loop_stall_max_s"};
  std::map<std::string, int> held;
  std::map<std::string, std::string> misses;
  for (uint64_t seed : {5, 6, 7}) {
    const CalibrationReport report = LabCalibration().Fit({SyntheticRun(lab, 12, seed, 3)});
    ASSERT_EQ(report.keys.size(), world::RealismParams::Fields().size());
    for (const std::string& key : must_determine) {
      const FittedKey* fitted = report.Find(key);
      ASSERT_NE(fitted, nullptr) << key;
      EXPECT_TRUE(fitted->determined) << key << ": " << fitted->support;
    }
    for (const FittedKey& fitted : report.keys) {
      const double truth = TruthOf(lab, fitted.key);
      if (!fitted.determined) {
        EXPECT_EQ(fitted.value, truth) << fitted.key << " kept, so the base's (the lab preset's here)";
        continue;
      }
      if (fitted.key == "loop_stall_max_s") {  // the longest stall seen: a lower bound
        held[fitted.key] += fitted.value <= truth + 1e-9 && fitted.value > 0.5 * truth;
        continue;
      }
      if (fitted.low <= truth && truth <= fitted.high) {
        ++held[fitted.key];
      } else {
        misses[fitted.key] += world::PrintfText(" seed %d: %.6g [%.6g, %.6g];", static_cast<int>(seed), fitted.value,
                                                fitted.low, fitted.high);
      }
    }
    std::string error;
    EXPECT_TRUE(report.params.IsValid(&error)) << error;
    EXPECT_GE(report.step_responses.size(), 3U);
    EXPECT_NE(report.Text().find("motor_lag_s"), std::string::npos);
    EXPECT_NE(report.RealismYaml().find("command_latency_steps: 5"), std::string::npos) << report.RealismYaml();
  }
  for (const std::string& key : must_determine) {
    EXPECT_GE(held[key], 2) << key << " (truth " << TruthOf(lab, key) << ") missed:" << misses[key];
  }
}

// The lab preset driven through the calibration program answers steps in v
// with the real robots' effective delays (issue 32's open-loop drives: 0.2
// m/s there, 0.19 in the program), as calibrate measures them from the
// poses, and calibrate gives its turning back.
TEST(LabCalibrationTest, LabPresetShowsTheRealRobotsDelays) {
  const CalibrationReport report = LabCalibration().Fit({SyntheticRun(world::RealismParams::Lab(), 8, 3)});
  const std::map<long, double> real_median = {{5, 0.635}, {10, 0.419}, {19, 0.337}};
  int checked = 0;
  for (const StepResponseCurve& curve : report.step_responses) {
    const auto median = real_median.find(std::lround(curve.speed_mps * 100));
    if (median == real_median.end()) continue;
    EXPECT_NEAR(curve.real_delay_s, median->second, 0.25 * median->second) << curve.speed_mps << " m/s";
    ++checked;
  }
  EXPECT_EQ(checked, 3);
  const FittedKey* turning = report.Find("angular_gain_mean");
  ASSERT_NE(turning, nullptr);
  EXPECT_NEAR(turning->value, world::RealismParams::Lab().angular_gain_mean, 0.05);
  const FittedKey* drift = report.Find("heading_drift_mean_radps");
  EXPECT_TRUE(drift->determined) << drift->support;
  EXPECT_NEAR(drift->value, world::RealismParams::Lab().heading_drift_mean_radps, 0.005);
  // The tracker's statistics against the measured table, within 30 %: noise
  // 0.30-0.35 mm at rest and 0.45-0.76 mm moving, headings on 1 mrad, 0.07-0.7 %
  // of moving poses repeated, in runs of 2.5-5.6 steps on average.
  auto value = [&report](const char* key) { return report.Find(key)->value; };
  EXPECT_NEAR(value("pose_noise_m"), 0.00033, 0.3 * 0.00033);
  EXPECT_NEAR(value("pose_noise_m") * value("pose_noise_moving_factor"), 0.0006, 0.3 * 0.0006);
  EXPECT_EQ(value("pose_quantum_rad"), 0.001);
  EXPECT_EQ(value("pose_quantum_m"), 0.0);
  double moving_stale = 0;
  for (int length : report.stale_bursts) moving_stale += length;
  double mean_run = moving_stale / static_cast<double>(report.stale_bursts.size());
  EXPECT_NEAR(mean_run, 4.0, 0.3 * 4.0);
  EXPECT_GE(value("tracking_dropout_probability") * mean_run, 0.0007 * 0.7);
  EXPECT_LE(value("tracking_dropout_probability") * mean_run, 0.007 * 1.3);
}

// Issue 34: Ctrl-C in a long fit was ignored until the fit ended, and the
// realism file written anyway. The fit polls its stop token inside its search
// (once per robot of each of its hundreds of evaluations), and stops at the
// first poll that says so, by files::Stopped.
TEST(LabCalibrationTest, AStopAskedForDuringTheFitEndsItAtTheNextPoll) {
  const std::vector<CalibrationRun> runs = {SyntheticRun(world::RealismParams::Lab(), 4, 3, 1)};
  int polls = 0;
  const CalibrationReport whole = LabCalibration(world::RealismParams::Lab(), files::StopToken([&polls] {
                                                   ++polls;
                                                   return false;
                                                 }))
                                      .Fit(runs);
  EXPECT_FALSE(whole.keys.empty());
  // 4 robots per evaluation, and hundreds of evaluations: never long between polls.
  EXPECT_GT(polls, 4 * 300);
  for (const int stop_at : {1, 50, polls / 2, polls}) {
    int asked = 0;
    const LabCalibration fit(world::RealismParams::Lab(),
                             files::StopToken([&asked, stop_at] { return ++asked >= stop_at; }));
    EXPECT_THROW(fit.Fit(runs), files::Stopped) << "stop at poll " << stop_at;
    EXPECT_EQ(asked, stop_at) << "nothing more is computed once asked";
  }
  std::atomic<bool> flag{true};
  EXPECT_THROW(LabModelCheck::Predict(runs, {{"ideal", world::RealismParams::Ideal()}}, files::StopToken(flag)),
               files::Stopped);
}

// Two halves of one lab (6 robots each, other seeds): each half's 95 %
// interval holds what the other half gives, for the keys fitted per robot
// and the wheels' (issue 32: intervals over pose pairs did not).
TEST(LabCalibrationTest, EachHalfsIntervalHoldsTheOtherHalfsValue) {
  const world::RealismParams lab = SyntheticLab();
  const CalibrationReport a = LabCalibration().Fit({SyntheticRun(lab, 6, 21, 2)});
  const CalibrationReport b = LabCalibration().Fit({SyntheticRun(lab, 6, 22, 2)});
  for (const char* key : {"command_latency_steps", "motor_lag_s", "motor_startup_m", "linear_gain_mean",
                          "angular_gain_mean", "heading_drift_mean_radps"}) {
    const FittedKey* in_a = a.Find(key);
    const FittedKey* in_b = b.Find(key);
    ASSERT_TRUE(in_a->determined && in_b->determined) << key;
    EXPECT_TRUE(in_a->low <= in_b->value && in_b->value <= in_a->high)
        << key << ": " << in_b->value << " outside [" << in_a->low << ", " << in_a->high << "]";
    EXPECT_TRUE(in_b->low <= in_a->value && in_a->value <= in_b->high)
        << key << ": " << in_a->value << " outside [" << in_b->low << ", " << in_b->high << "]";
  }
}

// --check: the model that made a run predicts it better than others do, and
// its steps from rest show the run's own delays.
TEST(LabCalibrationTest, TheTrueModelPredictsItsOwnRunsBest) {
  const world::RealismParams lab = SyntheticLab();
  const std::vector<CalibrationRun> runs = {SyntheticRun(lab, 6, 11, 1)};
  const std::vector<NamedModel> models = {
      {"ideal", world::RealismParams::Ideal()}, {"lab_v1", world::RealismParams::LabV1()}, {"truth", lab}};
  const std::vector<ModelPrediction> predictions = LabModelCheck::Predict(runs, models);
  ASSERT_EQ(predictions.size(), 3U);
  EXPECT_GT(predictions[2].predictions, 100);
  EXPECT_LT(predictions[2].position_error_m, 0.5 * predictions[0].position_error_m);
  EXPECT_LT(predictions[2].position_error_m, 0.5 * predictions[1].position_error_m);
  EXPECT_LT(predictions[2].heading_error_rad, predictions[0].heading_error_rad);
  for (const StepResponseCurve& curve : predictions[2].step_responses) {
    EXPECT_NEAR(curve.fitted_delay_s, curve.real_delay_s, 0.03) << curve.speed_mps;
  }
  for (const StepResponseCurve& curve : predictions[0].step_responses) {
    EXPECT_LT(curve.fitted_delay_s, curve.real_delay_s - 0.15) << "ideal answers at once; " << curve.speed_mps;
  }
  // Each error with an interval over the run's 6 robots; a ranking only
  // where the intervals separate.
  for (const ModelPrediction& prediction : predictions) {
    EXPECT_EQ(prediction.robots, 6);
    EXPECT_LT(prediction.position_error_low_m, prediction.position_error_m) << prediction.name;
    EXPECT_GT(prediction.position_error_high_m, prediction.position_error_m) << prediction.name;
  }
  ASSERT_LT(predictions[2].position_error_high_m, predictions[0].position_error_low_m);
  const std::string ranking = LabModelCheck::Ranking(predictions);
  EXPECT_NE(ranking.find("truth predicts better than ideal"), std::string::npos) << ranking;
  ModelPrediction twin = predictions[2];
  twin.name = "twin";
  EXPECT_NE(LabModelCheck::Ranking({predictions[2], twin}).find("not ranked (intervals overlap): truth / twin"),
            std::string::npos);
  const std::string table = LabModelCheck::Table(LabCalibration().Fit(runs), predictions, models);
  EXPECT_NE(table.find("| speed (starts) | real | ideal | lab_v1 | truth |"), std::string::npos) << table;
  EXPECT_NE(table.find("| motor_lag_s |"), std::string::npos) << table;
  EXPECT_NE(table.find("Steady turning seen"), std::string::npos) << table;
  EXPECT_NE(table.find("| heading_drift_mean_radps |"), std::string::npos) << table;
  const fs::path picture = fs::temp_directory_path() / ("dream_check_" + std::to_string(::getpid()) + ".png");
  RenderModelCheckPicture(predictions, picture.string(), render::RenderFormat::kPng);
  std::ifstream png(picture, std::ios::binary);
  std::string magic(4, '\0');
  png.read(magic.data(), 4);
  EXPECT_EQ(magic, "\x89PNG");
  fs::remove(picture);
}

CalibrationRun Still(int steps) {
  CalibrationRun run;
  run.name = "still.npz";
  run.track.num_robots = 1;
  for (int k = 0; k < steps; ++k) {
    run.track.utime.push_back(k * 33000);
    run.track.poses.push_back({0.1, 0.2, 0.3});
    run.track.commands.push_back({});
  }
  run.track.obstacles.resize(static_cast<size_t>(steps));
  return run;
}

TEST(LabCalibrationTest, RefusesDataItCannotUse) {
  auto message = [](const std::vector<CalibrationRun>& runs) {
    try {
      LabCalibration().Fit(runs);
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({Still(50)}).find("too short"), std::string::npos) << message({Still(50)});
  EXPECT_NE(message({Still(500)}).find("no motion"), std::string::npos);
  CalibrationRun not_moving = Still(500);
  for (auto& command : not_moving.track.commands) command = {0.1, 0.0};
  EXPECT_NE(message({not_moving}).find("never move"), std::string::npos) << message({not_moving});
  CalibrationRun nan = SyntheticRun(world::RealismParams::Lab(), 2, 1, 1);
  nan.track.poses[301].y_m = std::nan("");
  EXPECT_NE(message({nan}).find("robot 1 at step 150 is not a finite number"), std::string::npos) << message({nan});
  CalibrationRun backwards = SyntheticRun(world::RealismParams::Lab(), 1, 1, 1);
  backwards.track.utime[10] = backwards.track.utime[9];
  EXPECT_NE(message({backwards}).find("time does not increase at step 10"), std::string::npos);
  EXPECT_NE(message({}).find("at least one"), std::string::npos);
}

class CalibrationFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("dream_calibration_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string Path(const std::string& name) const { return (dir_ / name).string(); }
  static std::string Error(const std::string& path, const CalibrationInputOptions& options = {}) {
    try {
      ReadCalibrationRun(path, options);
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "no error";
  }
  fs::path dir_;
};

TEST_F(CalibrationFileTest, ReadsMatFilesAndRefusesShapesThatDisagree) {
  const CalibrationRun run = SyntheticRun(world::RealismParams::Lab(), 3, 2, 1);
  formats::NpyArray poses, commands;
  ArraysOf(run, &poses, &commands);
  formats::WriteMatMatrix(Path("lab.mat"), "poses", poses);
  // A .mat file with poses but no commands is named; WriteMatMatrix writes
  // one variable per file, so the arrays' reading is shown on the .npy form.
  EXPECT_NE(Error(Path("lab.mat")).find("no variable 'commands'"), std::string::npos) << Error(Path("lab.mat"));
  formats::NpyArray stacked;
  stacked.shape = {5, 3, static_cast<int64_t>(run.track.utime.size())};
  stacked.values = poses.values;
  stacked.values.insert(stacked.values.end(), commands.values.begin(), commands.values.end());
  files::WriteFileAtomically(Path("lab.npy"), formats::EncodeNpy(stacked));
  const CalibrationRun read = ReadCalibrationRun(Path("lab.npy"), {});
  ASSERT_EQ(read.track.num_robots, 3);
  EXPECT_EQ(read.track.pose(100, 2).x_m, run.track.pose(100, 2).x_m);
  EXPECT_EQ(read.track.command(100, 2).w_radps, run.track.command(100, 2).w_radps);
  EXPECT_FALSE(read.timed);
  files::WriteFileAtomically(Path("poses_only.npy"), formats::EncodeNpy(poses));
  EXPECT_NE(Error(Path("poses_only.npy")).find("expected 5 x N x T"), std::string::npos)
      << Error(Path("poses_only.npy"));
  EXPECT_NE(Error(Path("lab.txt")).find("not a run folder"), std::string::npos);
  EXPECT_NE(Error(Path("nothing_here")).find("not a run folder"), std::string::npos);
}

}  // namespace
}  // namespace dream::calibration
