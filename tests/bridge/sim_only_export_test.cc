// A run declared `sim_only: true` never goes to the lab: dream export refuses
// it whatever its robot count, before anything is written, and an export
// folder whose config says so (changed by hand) is refused by check-submission
// and import, which read it through ExportedSubmission::Read.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <functional>
#include <string>

#include "bridge_test_support.h"
#include "dream/bridge/lab_import.h"
#include "dream/bridge/submission_exporter.h"

namespace dream::bridge {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

// The shipped go_to_goal config (8 robots, which the lab takes) with
// `sim_only: true` after `robots:`; `line` is set to that line's number.
std::string SimOnlyGoToGoal(int* line) {
  std::string config = testing::ShippedConfig("go_to_goal");
  const size_t after_robots = config.find('\n', config.find("\nrobots: 8")) + 1;
  config.insert(after_robots, "sim_only: true\n");
  *line = 1 + static_cast<int>(std::count(config.begin(), config.begin() + static_cast<long>(after_robots), '\n'));
  return config;
}

std::string ErrorOf(const std::function<void()>& action) {
  try {
    action();
  } catch (const ExportRefused& e) {
    return std::string("refused by the lab's rules: ") + e.what();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(SimOnlyExportTest, ASimOnlyRunIsNeverExportedWhateverItsRobotCount) {
  int line = 0;
  const std::string run = testing::MakeRunFolder("sim_only_run", SimOnlyGoToGoal(&line));
  const std::string out = testing::NewFolder("sim_only_export") + "/out";
  const std::string error = ErrorOf([&] { ExportSubmission(run, out, ExportOptions{}); });
  EXPECT_EQ(error, run + "/config.yaml:" + std::to_string(line) +
                       ": sim_only: true — this run was declared simulation-only; remove `sim_only` (and use at most "
                       "20 robots) to export it");
  EXPECT_FALSE(fs::exists(out));  // nothing written
  // --force exports a run with lost robots, never a sim-only one.
  ExportOptions forced;
  forced.force = true;
  EXPECT_EQ(ErrorOf([&] { ExportSubmission(run, out, forced); }), error);
}

TEST(SimOnlyExportTest, AnExportFolderWhoseConfigSaysSimOnlyIsRefused) {
  int line = 0;
  std::string config = SimOnlyGoToGoal(&line);
  config.erase(config.find("sim_only: true\n"), 15);
  const std::string run = testing::MakeRunFolder("sim_only_plain_run", config);
  const std::string out = testing::NewFolder("sim_only_plain_export") + "/out";
  ExportSubmission(run, out, ExportOptions{});
  EXPECT_FALSE(ExportedSubmission::Read(out).config.sim_only);
  // Declared simulation-only by hand after the export: what check-submission and import read refuses it.
  testing::WriteText(out + "/config.yaml", testing::ReadText(out + "/config.yaml") + "sim_only: true\n");
  const std::string error = ErrorOf([&] { ExportedSubmission::Read(out); });
  EXPECT_THAT(error, HasSubstr(out + "/config.yaml:"));
  EXPECT_THAT(error, HasSubstr(": sim_only: true — this run was declared simulation-only; remove `sim_only`"));
  EXPECT_THAT(error, HasSubstr("was changed by hand: export the run again"));
}

}  // namespace
}  // namespace dream::bridge
