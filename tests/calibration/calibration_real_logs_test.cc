// dream calibrate on synthetic labs that look like the real logs of issue 32
// (one test per row of its table, and the other quirks of real files):
// arrays in Fortran order as scipy.io.loadmat gives them, an open-loop circle
// whose heading wraps, straight drives that show drift, closed-loop turning
// and few starts from rest that cannot pin drift or start-up, a time array
// that is not a clock, one-robot arrays, robots that never move.
#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "../bridge/bridge_test_support.h"
#include "run_arrays.h"
#include "dream/calibration/calibration_run.h"
#include "dream/calibration/lab_calibration.h"
#include "dream/formats/npy_file.h"
#include "dream/calibration/open_loop_drive_measure.h"
#include "dream/robotarium/robotarium_constants.h"
#include "dream/world/realistic_world.h"

namespace dream::calibration {
namespace {

namespace testing = bridge::testing;  // the bridge tests' folders and files
using test_support::ArraysOf;

constexpr double kDt = robotarium::RobotariumConstants::kTimeStepSeconds;
constexpr size_t kRestSteps = 30;  // every drive starts from rest, as the real ones did

using CommandOf = std::function<world::UnicycleCommand(int robot, int64_t step)>;

// `robots` robots of the lab model `lab` driven by `command` for `steps`
// steps, recorded as a lab run: measured poses, commands sent, the clock.
CalibrationRun Drive(const world::RealismParams& lab, uint64_t seed, int robots, int64_t steps,
                     const CommandOf& command, std::vector<world::RobotTraits>* traits = nullptr) {
  std::vector<world::Pose2> start;
  for (int i = 0; i < robots; ++i) start.push_back({-1.2 + 0.5 * (i % 5), -0.6 + 0.6 * (i / 5), 0.0});
  world::RealisticWorld world(world::WorldParams{}, lab, seed, start);
  if (traits != nullptr) *traits = world.robot_traits();
  CalibrationRun run;
  run.name = "lab_" + std::to_string(seed) + ".npz";
  run.timed = true;
  run.track.num_robots = robots;
  double time_s = 0;
  for (int64_t k = 0; k < steps; ++k) {
    run.track.utime.push_back(std::llround(time_s * 1e6));
    for (int i = 0; i < robots; ++i) {
      const world::UnicycleCommand c = static_cast<size_t>(k) < kRestSteps ? world::UnicycleCommand{} : command(i, k);
      run.track.poses.push_back(world.poses()[static_cast<size_t>(i)]);
      run.track.commands.push_back(c);
      world.SetCommand(i, c);
    }
    world.Step();
    time_s += kDt + world.last_late_s();
  }
  run.track.obstacles.resize(run.track.utime.size());
  return run;
}

// The lab preset with every robot alike: the truth is then one number.
world::RealismParams UniformLab() {
  world::RealismParams lab = world::RealismParams::Lab();
  lab.linear_gain_spread = 0.0;
  lab.angular_gain_spread = 0.0;
  lab.heading_drift_spread_radps = 0.0;
  lab.loop_stall_probability = 0.0;
  return lab;
}

const FittedKey& Key(const CalibrationReport& report, const std::string& key) {
  const FittedKey* found = report.Find(key);
  if (found == nullptr) throw std::logic_error("no key " + key);
  return *found;
}

bool AnyNoteHas(const CalibrationReport& report, const std::string& text) {
  for (const std::string& note : report.notes) {
    if (note.find(text) != std::string::npos) return true;
  }
  return false;
}

// --- files as they come ---------------------------------------------------

// A .npy of `array` in Fortran order (the first index fastest), as np.save
// writes an array scipy.io.loadmat returned.
std::string FortranNpy(const formats::NpyArray& array) {
  std::string shape;
  for (int64_t d : array.shape) shape += std::to_string(d) + ", ";
  std::string header = "{'descr': '<f8', 'fortran_order': True, 'shape': (" + shape + "), }";
  header.append((64 - (10 + header.size() + 1) % 64) % 64, ' ');
  header += '\n';
  std::string bytes("\x93NUMPY\x01\x00", 8);
  bytes += static_cast<char>(header.size() & 0xff);
  bytes += static_cast<char>(header.size() >> 8);
  bytes += header;
  std::vector<double> fortran(array.values.size());
  std::vector<int64_t> index(array.shape.size(), 0);
  for (size_t c = 0; c < array.values.size(); ++c) {
    int64_t at = 0;
    for (size_t d = array.shape.size(); d-- > 0;) at = at * array.shape[d] + index[d];
    fortran[static_cast<size_t>(at)] = array.values[c];
    for (size_t d = array.shape.size(); d-- > 0;) {
      if (++index[d] < array.shape[d]) break;
      index[d] = 0;
    }
  }
  const size_t data = bytes.size();
  bytes.resize(data + fortran.size() * 8);
  std::memcpy(&bytes[data], fortran.data(), fortran.size() * 8);
  return bytes;
}

void Put16(std::string* out, uint32_t v) {
  out->push_back(static_cast<char>(v & 0xff));
  out->push_back(static_cast<char>((v >> 8) & 0xff));
}
void Put32(std::string* out, uint32_t v) {
  Put16(out, v & 0xffff);
  Put16(out, v >> 16);
}

// A .npz as numpy.savez writes it: a zip archive of stored NAME.npy members.
std::string Npz(const std::vector<std::pair<std::string, std::string>>& members) {
  std::string zip, directory;
  for (const auto& [name, bytes] : members) {
    const std::string file = name + ".npy";
    const auto crc =
        static_cast<uint32_t>(crc32(0, reinterpret_cast<const Bytef*>(bytes.data()), static_cast<uInt>(bytes.size())));
    const auto offset = static_cast<uint32_t>(zip.size());
    auto common = [&](std::string* out) {
      Put16(out, 20);    // version needed
      Put16(out, 0);     // flags
      Put16(out, 0);     // stored
      Put16(out, 0);     // time
      Put16(out, 0x21);  // date
      Put32(out, crc);
      Put32(out, static_cast<uint32_t>(bytes.size()));
      Put32(out, static_cast<uint32_t>(bytes.size()));
      Put16(out, static_cast<uint32_t>(file.size()));
      Put16(out, 0);  // extra
    };
    Put32(&zip, 0x04034b50);
    common(&zip);
    zip += file + bytes;
    Put32(&directory, 0x02014b50);
    Put16(&directory, 20);  // made by
    common(&directory);
    Put16(&directory, 0);  // comment
    Put16(&directory, 0);  // disk
    Put16(&directory, 0);  // internal attributes
    Put32(&directory, 0);  // external attributes
    Put32(&directory, offset);
    directory += file;
  }
  const auto directory_offset = static_cast<uint32_t>(zip.size());
  zip += directory;
  Put32(&zip, 0x06054b50);
  Put16(&zip, 0);
  Put16(&zip, 0);
  Put16(&zip, static_cast<uint32_t>(members.size()));
  Put16(&zip, static_cast<uint32_t>(members.size()));
  Put32(&zip, static_cast<uint32_t>(directory.size()));
  Put32(&zip, directory_offset);
  Put16(&zip, 0);
  return zip;
}

formats::NpyArray TimeOf(const CalibrationRun& run) {
  formats::NpyArray time;
  time.shape = {1, static_cast<int64_t>(run.track.utime.size())};
  for (int64_t us : run.track.utime) time.values.push_back(static_cast<double>(us) * 1e-6 + 1700000000.0);
  return time;
}

std::string ReadError(const std::string& path) {
  try {
    ReadCalibrationRun(path, {});
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "no error";
}

world::UnicycleCommand Wiggle(int robot, int64_t step) {
  return {0.1, 0.4 * std::sin(0.02 * static_cast<double>(step) + robot)};
}

// Row 1: arrays as scipy.io.loadmat (or MATLAB) give them, saved by numpy:
// Fortran order, read as numpy reads them, also a time row 1 x T.
TEST(CalibrationRealLogsTest, ReadsFortranOrderArraysAsNumpyDoes) {
  const CalibrationRun run = Drive(world::RealismParams::Lab(), 2, 3, 400, Wiggle);
  formats::NpyArray poses, commands;
  ArraysOf(run, &poses, &commands);
  const std::string dir = testing::NewFolder("calibration_fortran");
  testing::WriteText(
      dir + "/lab.npz",
      Npz({{"poses", FortranNpy(poses)}, {"commands", FortranNpy(commands)}, {"t", FortranNpy(TimeOf(run))}}));
  const CalibrationRun read = ReadCalibrationRun(dir + "/lab.npz", {});
  ASSERT_EQ(read.track.num_robots, 3);
  ASSERT_EQ(read.track.utime.size(), run.track.utime.size());
  EXPECT_TRUE(read.timed);
  for (int64_t k : {0, 57, 399}) {
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(read.track.pose(k, i).x_m, run.track.pose(k, i).x_m);
      EXPECT_EQ(read.track.pose(k, i).theta_rad, run.track.pose(k, i).theta_rad);
      EXPECT_EQ(read.track.command(k, i).w_radps, run.track.command(k, i).w_radps);
    }
    EXPECT_NEAR(static_cast<double>(read.track.utime[static_cast<size_t>(k)] - run.track.utime[static_cast<size_t>(k)]),
                0.0, 1.0);
  }
  // The one-array form, 5 x N x T, in Fortran order too.
  formats::NpyArray stacked;
  stacked.shape = {5, 3, static_cast<int64_t>(run.track.utime.size())};
  stacked.values = poses.values;
  stacked.values.insert(stacked.values.end(), commands.values.begin(), commands.values.end());
  testing::WriteText(dir + "/lab.npy", FortranNpy(stacked));
  EXPECT_EQ(ReadCalibrationRun(dir + "/lab.npy", {}).track.pose(200, 1).y_m, run.track.pose(200, 1).y_m);
}

// Runs of one robot come as 3 x T and 2 x T as often as 3 x 1 x T.
TEST(CalibrationRealLogsTest, ReadsOneRobotArraysOfTwoDimensions) {
  const CalibrationRun run = Drive(world::RealismParams::Lab(), 4, 1, 300, Wiggle);
  formats::NpyArray poses, commands;
  ArraysOf(run, &poses, &commands);
  poses.shape = {3, 300};
  commands.shape = {2, 300};
  const std::string dir = testing::NewFolder("calibration_one_robot");
  testing::WriteText(dir + "/one.npz", Npz({{"poses", formats::EncodeNpy(poses)}, {"commands", FortranNpy(commands)}}));
  const CalibrationRun read = ReadCalibrationRun(dir + "/one.npz", {});
  EXPECT_EQ(read.track.num_robots, 1);
  EXPECT_EQ(read.track.pose(250, 0).x_m, run.track.pose(250, 0).x_m);
  EXPECT_EQ(read.track.command(250, 0).w_radps, run.track.command(250, 0).w_radps);
  poses.shape = {300, 3};  // transposed: named, with what was expected
  testing::WriteText(dir + "/transposed.npz",
                     Npz({{"poses", formats::EncodeNpy(poses)}, {"commands", formats::EncodeNpy(commands)}}));
  const std::string error = ReadError(dir + "/transposed.npz");
  EXPECT_NE(error.find(dir + "/transposed.npz: array 'poses' is 300 x 3; expected 3 x N x T"), std::string::npos)
      << error;
}

// A `time` array of per-step compute times (~1e-5 s) is no clock: calibrate
// says so, takes nominal steps and fits no step timing from it. A clock that
// goes back is refused, naming the file and the array.
TEST(CalibrationRealLogsTest, ATimeArrayThatIsNotAClockIsNamedAndIgnored) {
  const CalibrationRun run = Drive(world::RealismParams::Lab(), 5, 2, 400, Wiggle);
  formats::NpyArray poses, commands;
  ArraysOf(run, &poses, &commands);
  formats::NpyArray compute;
  compute.shape = {400};
  for (int k = 0; k < 400; ++k) compute.values.push_back(1e-5 * (1.0 + 0.3 * std::sin(k)));
  const std::string dir = testing::NewFolder("calibration_time");
  testing::WriteText(dir + "/compute.npz", Npz({{"poses", formats::EncodeNpy(poses)},
                                                {"commands", formats::EncodeNpy(commands)},
                                                {"t", formats::EncodeNpy(compute)}}));
  const CalibrationRun read = ReadCalibrationRun(dir + "/compute.npz", {});
  EXPECT_FALSE(read.timed);
  EXPECT_EQ(read.track.utime[10], 10 * 33000);
  ASSERT_EQ(read.notes.size(), 1U);
  EXPECT_NE(read.notes[0].find(dir + "/compute.npz: the time vector 't' is not a clock"), std::string::npos)
      << read.notes[0];
  EXPECT_NE(read.notes[0].find("compute times"), std::string::npos) << read.notes[0];
  const CalibrationReport report = LabCalibration().Fit({read});
  EXPECT_FALSE(Key(report, "step_overrun_mean_s").determined);
  EXPECT_TRUE(AnyNoteHas(report, "is not a clock"));
  formats::NpyArray backwards = TimeOf(run);
  backwards.values[200] = backwards.values[100];
  testing::WriteText(dir + "/backwards.npz", Npz({{"poses", formats::EncodeNpy(poses)},
                                                  {"commands", formats::EncodeNpy(commands)},
                                                  {"t", formats::EncodeNpy(backwards)}}));
  const std::string error = ReadError(dir + "/backwards.npz");
  EXPECT_NE(error.find(dir + "/backwards.npz: the time vector 't' does not increase at step 200"), std::string::npos)
      << error;
}

// --- what the data can pin ------------------------------------------------

world::UnicycleCommand Circle(double v, double w) { return {v, w}; }

// Row 2: one open-loop circle of one robot, 5,000 steps at v 0.05, w 0.1:
// the heading wraps three times. It gave an angular gain of -28 (a gain and
// a drift cannot be told apart turning at one rate). Now the drift keeps the
// base's (the report says why) and the gain is the robot's; headings in
// [0, 2 pi) give the same fit.
TEST(CalibrationRealLogsTest, AnOpenLoopCircleThatWrapsGivesItsTurningGain) {
  const world::RealismParams lab = UniformLab();
  CalibrationRun run = Drive(lab, 6, 1, 5000, [](int, int64_t) { return Circle(0.05, 0.1); });
  int wraps = 0;
  for (size_t k = 1; k < run.track.poses.size(); ++k) {
    wraps += std::abs(run.track.poses[k].theta_rad - run.track.poses[k - 1].theta_rad) > M_PI;
  }
  ASSERT_GE(wraps, 2);
  const CalibrationReport report = LabCalibration().Fit({run});
  const FittedKey& gain = Key(report, "angular_gain_mean");
  ASSERT_TRUE(gain.determined) << gain.support;
  EXPECT_NEAR(gain.value, lab.angular_gain_mean, 0.02) << gain.support;
  EXPECT_LE(gain.low, lab.angular_gain_mean);
  EXPECT_GE(gain.high, lab.angular_gain_mean);
  const FittedKey& drift = Key(report, "heading_drift_mean_radps");
  EXPECT_FALSE(drift.determined);
  EXPECT_NE(drift.support.find("drove straight"), std::string::npos) << drift.support;
  EXPECT_EQ(Key(report, "pose_quantum_rad").value, 0.001) << Key(report, "pose_quantum_rad").support;
  // The same headings in [0, 2 pi).
  for (world::Pose2& pose : run.track.poses) {
    if (pose.theta_rad < 0) pose.theta_rad += 2 * M_PI;
  }
  const CalibrationReport shifted = LabCalibration().Fit({run});
  EXPECT_NEAR(Key(shifted, "angular_gain_mean").value, gain.value, 1e-9);
  EXPECT_NEAR(Key(shifted, "motor_lag_s").value, Key(report, "motor_lag_s").value, 1e-9);
}

// Row 2, the three circles together (different robots, rates and speeds).
TEST(CalibrationRealLogsTest, ThreeCirclesTogetherGiveTheirTurningGain) {
  const world::RealismParams lab = UniformLab();
  std::vector<CalibrationRun> runs;
  runs.push_back(Drive(lab, 7, 1, 3000, [](int, int64_t) { return Circle(0.05, 0.1); }));
  runs.push_back(Drive(lab, 8, 1, 3000, [](int, int64_t) { return Circle(0.15, 0.3); }));
  runs.push_back(Drive(lab, 9, 1, 3000, [](int, int64_t) { return Circle(0.1, 0.2); }));
  const CalibrationReport report = LabCalibration().Fit(runs);
  EXPECT_NEAR(Key(report, "angular_gain_mean").value, lab.angular_gain_mean, 0.02);
  EXPECT_TRUE(Key(report, "angular_gain_spread").determined);
  EXPECT_LT(Key(report, "angular_gain_spread").value, 0.03);
}

// Row 3: straight drives (w = 0, 3 runs x 5 robots at 0.05, 0.1 and 0.2 m/s)
// are where drift shows: fitted, per robot, either sign, within its interval.
TEST(CalibrationRealLogsTest, StraightDrivesShowTheDrift) {
  world::RealismParams lab = world::RealismParams::Lab();
  lab.heading_drift_mean_radps = 0.004;
  lab.heading_drift_spread_radps = 0.006;
  std::vector<CalibrationRun> runs;
  double truth = 0;
  int robots = 0;
  uint64_t seed = 20;
  for (double v : {0.05, 0.1, 0.2}) {
    std::vector<world::RobotTraits> traits;
    runs.push_back(Drive(
        lab, seed++, 5, 500,
        [v](int, int64_t) {
          return world::UnicycleCommand{v, 0.0};
        },
        &traits));
    for (const world::RobotTraits& t : traits) {
      truth += t.heading_drift_radps;
      ++robots;
    }
  }
  truth /= robots;
  const CalibrationReport report = LabCalibration().Fit(runs);
  const FittedKey& drift = Key(report, "heading_drift_mean_radps");
  ASSERT_TRUE(drift.determined) << drift.support;
  EXPECT_LE(drift.low, truth) << drift.value;
  EXPECT_GE(drift.high, truth) << drift.value;
  EXPECT_NE(drift.support.find("15 robots driving straight"), std::string::npos) << drift.support;
  const FittedKey& spread = Key(report, "heading_drift_spread_radps");
  ASSERT_TRUE(spread.determined);
  EXPECT_LE(spread.low, lab.heading_drift_spread_radps);
  EXPECT_GE(spread.high, lab.heading_drift_spread_radps);
  EXPECT_FALSE(Key(report, "angular_gain_mean").determined) << "nothing turned";
}

// Row 4: closed-loop runs that never drive straight cannot tell drift from
// the angular gain: the drift keeps the base's, and the gain is fitted with
// it. Row 5: they hold no slow starts from rest, so start-up keeps the
// base's (the lag is fitted with it), and the report says so.
TEST(CalibrationRealLogsTest, ClosedLoopTurningPinsNeitherDriftNorStartUp) {
  const world::RealismParams lab = UniformLab();
  auto closed_loop = [](int robot, int64_t step) {
    const double phase = 0.013 * static_cast<double>(step) + robot;
    return world::UnicycleCommand{0.08 + 0.04 * std::sin(phase), 0.5 + 0.3 * std::sin(1.7 * phase)};
  };
  const CalibrationReport report =
      LabCalibration().Fit({Drive(lab, 31, 5, 3000, closed_loop), Drive(lab, 32, 5, 3000, closed_loop)});
  const FittedKey& drift = Key(report, "heading_drift_mean_radps");
  EXPECT_FALSE(drift.determined);
  EXPECT_EQ(drift.value, lab.heading_drift_mean_radps);
  EXPECT_NEAR(Key(report, "angular_gain_mean").value, lab.angular_gain_mean, 0.02);
  const FittedKey& startup = Key(report, "motor_startup_m");
  EXPECT_FALSE(startup.determined);
  EXPECT_EQ(startup.value, lab.motor_startup_m);
  EXPECT_NE(startup.support.find("starts from rest at low speed"), std::string::npos) << startup.support;
  EXPECT_TRUE(AnyNoteHas(report, "motor_startup_m kept"));
  const FittedKey& lag = Key(report, "motor_lag_s");
  ASSERT_TRUE(lag.determined);
  EXPECT_LE(lag.low, lab.motor_lag_s);
  EXPECT_GE(lag.high, lab.motor_lag_s);
}

// The measure of success: a model fitted on closed-loop runs alone
// predicts open-loop drives (OpenLoopDriveMeasure, seeded): effective
// delays within 25 % of the lab's own, turning within 0.05.
TEST(CalibrationRealLogsTest, AFitOnClosedLoopRunsPredictsOpenLoopDrives) {
  const world::RealismParams lab = world::RealismParams::Lab();
  auto closed_loop = [](int robot, int64_t step) {
    const double phase = 0.011 * static_cast<double>(step) + 0.7 * robot;
    return world::UnicycleCommand{0.1 + 0.05 * std::sin(phase), 0.6 * std::sin(1.9 * phase)};
  };
  const CalibrationReport report =
      LabCalibration().Fit({Drive(lab, 51, 6, 3000, closed_loop), Drive(lab, 52, 6, 3000, closed_loop)});
  auto delay = [](const world::RealismParams& model, double v) {
    const OpenLoopDriveMeasure::Drive drive = OpenLoopDriveMeasure::Simulate(model, 3, 20, 500, {v, 0.0});
    double sum = 0;
    for (const auto& poses : drive.poses) sum += OpenLoopDriveMeasure::EffectiveDelay(poses, drive.time_s);
    return sum / static_cast<double>(drive.poses.size());
  };
  auto turning = [](const world::RealismParams& model, double v, double w) {
    const OpenLoopDriveMeasure::Drive drive = OpenLoopDriveMeasure::Simulate(model, 3, 40, 1500, {v, w});
    double sum = 0;
    for (const auto& poses : drive.poses) sum += OpenLoopDriveMeasure::TurningRatio(poses, drive.time_s, w);
    return sum / static_cast<double>(drive.poses.size());
  };
  for (double v : {0.05, 0.1, 0.2}) {
    const double truth = delay(lab, v);
    EXPECT_NEAR(delay(report.params, v), truth, 0.25 * truth) << v << " m/s";
  }
  for (const auto& [v, w] : std::vector<std::pair<double, double>>{{0.05, 0.1}, {0.15, 0.3}, {0.1, 0.2}}) {
    EXPECT_NEAR(turning(report.params, v, w), turning(lab, v, w), 0.05) << "v " << v << ", w " << w;
  }
}

// Runs where some robots never move (off, or held) although commanded: they
// are left out of the fits of motion, and the report names them.
TEST(CalibrationRealLogsTest, RobotsThatNeverMoveAreLeftOutAndNamed) {
  const world::RealismParams lab = UniformLab();
  CalibrationRun run = Drive(lab, 41, 3, 1500, Wiggle);
  for (size_t k = 0; k < run.track.utime.size(); ++k) run.track.poses[k * 3 + 2] = {0.4, 0.5, 1.0};
  const CalibrationReport report = LabCalibration().Fit({run});
  EXPECT_TRUE(AnyNoteHas(report, "robot 2 was commanded to move but never moved 2 cm")) << report.Text();
  const FittedKey& gain = Key(report, "linear_gain_mean");
  EXPECT_NE(gain.support.find("2 robots"), std::string::npos) << gain.support;
  EXPECT_NEAR(gain.value, lab.linear_gain_mean, 0.03);
  EXPECT_NE(report.Text().find("Notes"), std::string::npos);
}

}  // namespace
}  // namespace dream::calibration
