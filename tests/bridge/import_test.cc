// dream import: a lab result (.npy or .mat) becomes a run log on the same
// channels and types as a simulated run; every kind of bad result file is
// refused with a message naming the file and the problem, and nothing is
// written.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>

#include "bridge_test_support.h"
#include "dream/bridge/lab_import.h"
#include "dream/formats/mat_file.h"
#include "dream/formats/npy_file.h"
#include "dream/bridge/submission_exporter.h"
#include "dream/bridge/submission_format.h"
#include "dream/lcm/log_reader.h"
#include "dream/run_status_t.hpp"
#include "dream/world/printf_text.h"
#include "dream/robotarium/robotarium_constants.h"

namespace dream::bridge {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

class ImportTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    run_dir_ = new std::string(testing::MakeRunFolder("import_run", testing::ShippedConfig("go_to_goal")));
    export_dir_ = new std::string(testing::NewFolder("import_export"));
    ExportSubmission(*run_dir_, *export_dir_, ExportOptions{});
  }
  static void TearDownTestSuite() {
    delete run_dir_;
    delete export_dir_;
  }

  /// Writes `rows` as a result file and imports it into a fresh folder.
  /// `declared`: what the user declared on the lab's form (absent: UPLOAD.txt's).
  static ImportedRun Import(const formats::NpyArray& rows, const std::string& name,
                            const std::optional<world::LabVerifierRules::Declaration>& declared = {}) {
    const std::string dir = testing::NewFolder("import_" + name);
    testing::WriteText(dir + "/dream_result.npy", formats::EncodeNpy(rows));
    return ImportLabRun(dir + "/dream_result.npy", *export_dir_, dir + "/out", declared);
  }

  /// Expects the import of `bytes` to fail with `message` naming the file, writing nothing.
  static void ExpectRefused(const std::string& bytes, const std::string& message, const std::string& name) {
    const std::string dir = testing::NewFolder("import_bad_" + name);
    const std::string file = dir + "/dream_result.npy";
    testing::WriteText(file, bytes);
    try {
      ImportLabRun(file, *export_dir_, dir + "/out");
      ADD_FAILURE() << name << ": imported";
    } catch (const std::runtime_error& e) {
      EXPECT_THAT(e.what(), HasSubstr(file + ": ")) << name;
      EXPECT_THAT(e.what(), HasSubstr(message)) << name;
    }
    EXPECT_FALSE(fs::exists(dir + "/out")) << name << ": wrote something";
  }

  static std::string* run_dir_;
  static std::string* export_dir_;
};
std::string* ImportTest::run_dir_ = nullptr;
std::string* ImportTest::export_dir_ = nullptr;

TEST_F(ImportTest, PerfectLabResultGivesTheSimulatedRunBack) {
  const ImportedRun imported = Import(testing::PerfectLabResult(*export_dir_), "perfect");
  EXPECT_TRUE(imported.lab.complete);
  EXPECT_EQ(imported.violations.hard_errors(), 0);
  const RunTrack sim = ReadRunTrack(*run_dir_ + "/run.lcmlog");
  RunEnd end;
  const RunTrack lab = ReadRunTrack(imported.log_path, &end);
  ASSERT_EQ(lab.last_step(), sim.last_step());
  EXPECT_EQ(end.state, run_status_t::FINISHED);
  for (int64_t k = 0; k <= sim.last_step(); k += 37) {
    for (int i = 0; i < sim.num_robots; ++i) {
      EXPECT_EQ(lab.pose(k, i).x_m, sim.pose(k, i).x_m);
      EXPECT_EQ(lab.pose(k, i).theta_rad, sim.pose(k, i).theta_rad);
      EXPECT_EQ(lab.command(k, i).v_mps, sim.command(k, i).v_mps);
    }
    EXPECT_EQ(lab.utime[static_cast<size_t>(k)], k * 33000);
    // The virtual obstacles are where the simulator had them.
    ASSERT_EQ(lab.obstacles[static_cast<size_t>(k)].size(), sim.obstacles[static_cast<size_t>(k)].size());
    EXPECT_NEAR(lab.obstacles[static_cast<size_t>(k)][1].center_x_m,
                sim.obstacles[static_cast<size_t>(k)][1].center_x_m, 1e-12);
  }
  // The commands as sent are on DREAM_CMD_<id>, like a simulated run's.
  int64_t commands = 0;
  lcm::LogReader reader(imported.log_path);
  lcm::LogRecord record;
  while (reader.Next(&record)) commands += record.channel.rfind("DREAM_CMD_", 0) == 0 ? 1 : 0;
  EXPECT_EQ(commands, sim.last_step() * sim.num_robots);
  EXPECT_THAT(testing::FilesIn(fs::path(imported.log_path).parent_path().string()),
              ::testing::ElementsAre(".dream.lock", "config.yaml", "run.lcmlog"));  // the report: ImportWorkflow's
  EXPECT_EQ(imported.lab_json["complete"], true);
  EXPECT_EQ(imported.outcome.steps, sim.last_step());
  EXPECT_EQ(imported.world->step(), sim.last_step());
}

TEST_F(ImportTest, CutShortRunIsImportedAsSuch) {
  formats::NpyArray rows = testing::PerfectLabResult(*export_dir_);
  const int64_t columns = rows.shape[1];
  rows.shape[0] = 100;  // the lab stopped after 100 steps: no final row
  rows.values.resize(static_cast<size_t>(100 * columns));
  const ImportedRun imported = Import(rows, "cut_short");
  EXPECT_FALSE(imported.lab.complete);
  EXPECT_EQ(imported.lab.track.last_step(), 99);
  RunEnd end;
  ReadRunTrack(imported.log_path, &end);
  EXPECT_EQ(end.state, run_status_t::ABORTED);
  EXPECT_THAT(end.detail, HasSubstr("stopped after 99 of"));
}

TEST_F(ImportTest, SettleRowsAreSkippedAndClockJumpsHeld) {
  formats::NpyArray rows = testing::PerfectLabResult(*export_dir_, [](int64_t k, double* row) {
    if (k == 50) row[ResultLayout::kWallTimeColumn] -= 1.0;  // the lab's clock stepped back
  });
  const int64_t columns = rows.shape[1];
  std::vector<double> settle(rows.values.begin(), rows.values.begin() + 2 * columns);
  for (int s = 0; s < 2; ++s) {
    settle[static_cast<size_t>(s * columns + ResultLayout::kPhaseColumn)] = ResultLayout::kPhaseSettle;
    settle[static_cast<size_t>(s * columns + ResultLayout::kStepColumn)] = s;
  }
  rows.values.insert(rows.values.begin(), settle.begin(), settle.end());
  rows.shape[0] += 2;
  const ImportedRun imported = Import(rows, "settle");
  EXPECT_EQ(imported.lab.settle_steps, 2);
  EXPECT_EQ(imported.lab.clock_steps_back, 1);
  EXPECT_EQ(imported.lab.track.utime[50], imported.lab.track.utime[49]);
}

// The lab verifier's rules on an imported run, against what was declared:
// UPLOAD.txt's values by default, or what the user says was declared.

std::string Seconds(double seconds) { return world::PrintfText("%.2f s", seconds); }

/// `rows` with `count` settle rows in front (copies of the first rows).
formats::NpyArray WithSettleRows(formats::NpyArray rows, int count) {
  const int64_t columns = rows.shape[1];
  std::vector<double> settle(rows.values.begin(), rows.values.begin() + count * columns);
  for (int s = 0; s < count; ++s) {
    settle[static_cast<size_t>(s * columns + ResultLayout::kPhaseColumn)] = ResultLayout::kPhaseSettle;
    settle[static_cast<size_t>(s * columns + ResultLayout::kStepColumn)] = s;
  }
  rows.values.insert(rows.values.begin(), settle.begin(), settle.end());
  rows.shape[0] += count;
  return rows;
}

TEST_F(ImportTest, RunWithinOneAndAHalfTimesTheDeclaredDurationIsClean) {
  const ExportedSubmission exported = ExportedSubmission::Read(*export_dir_);
  const int64_t steps = exported.params.steps;
  const double dt = robotarium::RobotariumConstants::kTimeStepSeconds;
  const world::LabVerifierRules::Declaration upload = exported.UploadDeclaration();
  EXPECT_EQ(upload.num_robots, exported.params.num_robots);
  EXPECT_DOUBLE_EQ(upload.duration_s, static_cast<double>(steps + exported.params.options.settle_max_steps) * dt);

  const formats::NpyArray rows = testing::PerfectLabResult(*export_dir_);
  const ImportedRun as_uploaded = Import(rows, "declared_as_uploaded");
  EXPECT_EQ(as_uploaded.lab.iterations, steps);  // one step() per experiment row, no settle rows
  EXPECT_EQ(as_uploaded.declared.duration_s, upload.duration_s);
  EXPECT_EQ(as_uploaded.verdict(), world::RunVerdict::kClean);
  EXPECT_EQ(as_uploaded.lab_json["declared_from"], "export");

  // Declared shorter than UPLOAD.txt says, but the run takes under 1.5 x of it.
  world::LabVerifierRules::Declaration shorter = upload;
  shorter.duration_s = static_cast<double>(steps) * dt / 1.45;
  const ImportedRun within = Import(rows, "declared_within", shorter);
  EXPECT_EQ(within.verdict(), world::RunVerdict::kClean);
  EXPECT_TRUE(within.verdict_reasons().empty());
  EXPECT_EQ(within.lab_json["declared_from"], "options");
}

TEST_F(ImportTest, RunLongerThanOneAndAHalfTimesTheDeclaredDurationIsRejected) {
  const ExportedSubmission exported = ExportedSubmission::Read(*export_dir_);
  const int64_t steps = exported.params.steps;
  const double dt = robotarium::RobotariumConstants::kTimeStepSeconds;
  world::LabVerifierRules::Declaration declared = exported.UploadDeclaration();
  declared.duration_s = static_cast<double>(steps) * dt / 1.6;
  const ImportedRun too_long = Import(testing::PerfectLabResult(*export_dir_), "declared_too_short", declared);
  EXPECT_EQ(too_long.verdict(), world::RunVerdict::kRejected);
  ASSERT_EQ(too_long.verdict_reasons().size(), 1u);
  const world::VerdictReason& reason = too_long.verdict_reasons()[0];
  EXPECT_EQ(reason.rule, "verifier_duration");
  EXPECT_EQ(reason.verdict, world::RunVerdict::kRejected);
  // The measured and the declared value.
  EXPECT_THAT(reason.problem,
              HasSubstr(std::to_string(steps) + " iterations take " + Seconds(static_cast<double>(steps) * dt)));
  EXPECT_THAT(reason.problem, HasSubstr("over 1.5 x the declared " + Seconds(declared.duration_s)));

  // The verifier counts the settle phase's steps too: two settle rows take
  // a run that fits 1.5 x the declaration without them over it.
  declared.duration_s = static_cast<double>(steps + 1) * dt / 1.5;
  EXPECT_EQ(Import(testing::PerfectLabResult(*export_dir_), "declared_fits", declared).verdict(),
            world::RunVerdict::kClean);
  const ImportedRun settled =
      Import(WithSettleRows(testing::PerfectLabResult(*export_dir_), 2), "declared_settle_over", declared);
  EXPECT_EQ(settled.lab.iterations, steps + 2);
  ASSERT_EQ(settled.verdict_reasons().size(), 1u);
  EXPECT_EQ(settled.verdict_reasons()[0].rule, "verifier_duration");
  EXPECT_THAT(settled.verdict_reasons()[0].problem, HasSubstr(std::to_string(steps + 2) + " iterations"));
}

TEST_F(ImportTest, RobotCountOtherThanDeclaredIsRejected) {
  const ExportedSubmission exported = ExportedSubmission::Read(*export_dir_);
  const int robots = exported.params.num_robots;
  world::LabVerifierRules::Declaration declared = exported.UploadDeclaration();
  declared.num_robots = robots + 2;
  const ImportedRun mismatch = Import(testing::PerfectLabResult(*export_dir_), "declared_robots", declared);
  EXPECT_EQ(mismatch.verdict(), world::RunVerdict::kRejected);
  ASSERT_EQ(mismatch.verdict_reasons().size(), 1u);
  EXPECT_EQ(mismatch.verdict_reasons()[0].rule, "verifier_robot_count");
  EXPECT_THAT(mismatch.verdict_reasons()[0].problem,
              HasSubstr("the script asks for " + std::to_string(robots) + " robots but " + std::to_string(robots + 2) +
                        " are declared"));
  EXPECT_EQ(mismatch.lab_json["declared_robots"], robots + 2);
}

TEST_F(ImportTest, MatFileFromMatlabImportsLikeTheNpy) {
  const formats::NpyArray rows = testing::PerfectLabResult(*export_dir_);
  const std::string dir = testing::NewFolder("import_mat");
  formats::WriteMatMatrix(dir + "/dream_result.mat", SubmissionFiles::kResultMatVariable, rows);
  const ImportedRun from_mat = ImportLabRun(dir + "/dream_result.mat", *export_dir_, dir + "/out");
  const ImportedRun from_npy = Import(rows, "mat_reference");
  EXPECT_EQ(testing::ReadText(from_mat.log_path), testing::ReadText(from_npy.log_path));
  // MATLAB's -v7.3 files are HDF5.
  formats::WriteMatMatrix(dir + "/dream_result_v73.mat", SubmissionFiles::kResultMatVariable, rows, true);
  const ImportedRun from_v73 = ImportLabRun(dir + "/dream_result_v73.mat", *export_dir_, dir + "/out_v73");
  EXPECT_EQ(testing::ReadText(from_v73.log_path), testing::ReadText(from_npy.log_path));
  // A .mat without the variable, or with the wrong one, is refused by name.
  formats::WriteMatMatrix(dir + "/other.mat", "poses", rows);
  try {
    ImportLabRun(dir + "/other.mat", *export_dir_, dir + "/out2");
    ADD_FAILURE() << "imported a .mat without dream_result";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr(dir + "/other.mat: has no variable 'dream_result'"));
  }
  testing::WriteText(dir + "/fake.mat", "MATLAB 5.0 MAT-file, but cut right here");
  EXPECT_THROW(ImportLabRun(dir + "/fake.mat", *export_dir_, dir + "/out3"), std::runtime_error);
  EXPECT_FALSE(fs::exists(dir + "/out2"));
  EXPECT_FALSE(fs::exists(dir + "/out3"));
}

TEST_F(ImportTest, BadResultFilesAreRefusedByNameAndNothingIsWritten) {
  const formats::NpyArray good = testing::PerfectLabResult(*export_dir_);
  const int64_t rows = good.shape[0];
  const int64_t columns = good.shape[1];
  auto with = [&good](const std::function<void(formats::NpyArray*)>& change) {
    formats::NpyArray array = good;
    change(&array);
    return formats::EncodeNpy(array);
  };
  const std::string bytes = formats::EncodeNpy(good);

  // Shape and robot count.
  ExpectRefused(with([](formats::NpyArray* a) { a->shape = {a->shape[0] * a->shape[1]}; }), "has 1 dimensions", "1d");
  ExpectRefused(with([&](formats::NpyArray* a) { a->shape = {rows, 1, columns}; }), "has 3 dimensions", "3d");
  ExpectRefused(with([&](formats::NpyArray* a) {
                  a->shape = {rows, columns - 5};
                  a->values.resize(static_cast<size_t>(rows * (columns - 5)));
                }),
                "as a result of a 7-robot run; this export has 8 robots", "seven_robots");
  ExpectRefused(with([&](formats::NpyArray* a) {
                  a->shape = {rows, columns + 1};
                  a->values.resize(static_cast<size_t>(rows * (columns + 1)));
                }),
                "has 44 columns; this export has 8 robots", "odd_columns");
  ExpectRefused(with([](formats::NpyArray* a) {
                  a->shape = {0, a->shape[1]};
                  a->values.clear();
                }),
                "holds no rows", "empty");
  // Step count and order.
  ExpectRefused(with([&](formats::NpyArray* a) {
                  // The final row becomes experiment step K, and another final row follows.
                  double* last = &a->values[static_cast<size_t>((rows - 1) * columns)];
                  last[ResultLayout::kPhaseColumn] = ResultLayout::kPhaseExperiment;
                  std::vector<double> final_row(last, last + columns);
                  final_row[ResultLayout::kPhaseColumn] = ResultLayout::kPhaseFinal;
                  final_row[ResultLayout::kStepColumn] = static_cast<double>(rows);
                  a->values.insert(a->values.end(), final_row.begin(), final_row.end());
                  a->shape[0] += 1;
                }),
                "more experiment steps than the", "too_many_steps");
  ExpectRefused(with([&](formats::NpyArray* a) {
                  a->values[static_cast<size_t>(10 * columns + ResultLayout::kStepColumn)] = 11;
                }),
                "row 10: experiment step 11.000000, expected 10", "step_gap");
  ExpectRefused(with([&](formats::NpyArray* a) {
                  a->values[static_cast<size_t>(10 * columns + ResultLayout::kPhaseColumn)] = 7;
                }),
                "row 10: phase 7.000000 is not 0 (settle), 1 (experiment) or 2 (final)", "bad_phase");
  ExpectRefused(with([&](formats::NpyArray* a) {
                  a->shape[0] = 1;
                  a->values.resize(static_cast<size_t>(columns));
                }),
                "has 1 experiment poses; at least 2 are needed", "one_row");
  // NaN and infinity, named by row, quantity and robot.
  ExpectRefused(with([&](formats::NpyArray* a) {
                  a->values[static_cast<size_t>(20 * columns + ResultLayout::Y(8, 5))] =
                      std::numeric_limits<double>::quiet_NaN();
                }),
                "row 20: y of robot 5 is nan", "nan");
  ExpectRefused(with([&](formats::NpyArray* a) {
                  a->values[static_cast<size_t>(3 * columns + ResultLayout::kWallTimeColumn)] =
                      std::numeric_limits<double>::infinity();
                }),
                "row 3: the wall-clock column is inf", "inf");
  // Finite but absurd: 1e300 m made the comparison's squares overflow to inf.
  ExpectRefused(
      with([&](formats::NpyArray* a) { a->values[static_cast<size_t>(20 * columns + ResultLayout::X(8, 2))] = 1e300; }),
      "row 20: x of robot 2 is 1e+300; beyond 1000 in magnitude", "far_pose");
  ExpectRefused(with([&](formats::NpyArray* a) {
                  a->values[static_cast<size_t>(20 * columns + ResultLayout::Theta(8, 2))] = -2000.0;
                }),
                "row 20: theta of robot 2 is -2000; beyond 1000", "far_heading");
  // dtype, truncation, foreign files (Fortran order is read as numpy reads it: npy_file_test).
  std::string float32 = bytes;
  float32.replace(float32.find("'<f8'"), 5, "'<f4'");
  ExpectRefused(float32, "dtype '<f4'", "float32");
  ExpectRefused(bytes.substr(0, bytes.size() - 100), "is cut short", "truncated");
  ExpectRefused(bytes + "garbage", "bytes after the data", "trailing");
  ExpectRefused("\x89PNG\r\n\x1a\n not a result", "neither a .npy file nor a MATLAB .mat file", "png");
  ExpectRefused("", "neither a .npy file nor a MATLAB .mat file", "empty_file");
}

TEST_F(ImportTest, ForeignExportFolderIsRefused) {
  const std::string dir = testing::NewFolder("import_foreign_export");
  testing::WriteText(dir + "/dream_result.npy", formats::EncodeNpy(testing::PerfectLabResult(*export_dir_)));
  EXPECT_THROW(
      {
        try {
          ImportLabRun(dir + "/dream_result.npy", dir, dir + "/out");
        } catch (const std::runtime_error& e) {
          EXPECT_THAT(e.what(), HasSubstr("upload/dream_params.npy: missing"));
          throw;
        }
      },
      std::runtime_error);
}

}  // namespace
}  // namespace dream::bridge
