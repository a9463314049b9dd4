// KeepControllerModule copies the file a run's kind names by its
// ControllerKind::file_key (the python kind's module) beside the copy of the
// config, asking the kind, not its name.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "bridge_test_support.h"
#include "dream/bridge/controller_module_copy.h"
#include "dream/config/config_error.h"
#include "dream/files/output_folder.h"

namespace dream::bridge {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

std::string PythonConfig(const std::string& module) {
  return "name: m\nrobots: 1\ninitial_poses: [[0, 0, 0]]\n"
         "controller: {kind: python, module: " +
         module + ", class: Still}\n";
}

TEST(ControllerModuleCopyTest, ThePythonKindsModuleIsKeptAtItsRelativePath) {
  const std::string source = testing::NewFolder("module_copy_source");
  fs::create_directories(source + "/ctl");
  testing::WriteText(source + "/ctl/still.py", "class Still:\n    pass\n");
  const run_config::RunConfig config = testing::LoadConfigText(PythonConfig("ctl/still.py"), source + "/c.yaml");
  const std::string out = testing::NewFolder("module_copy_out");
  KeepControllerModule(config, files::OutputFolder(out));
  EXPECT_EQ(testing::ReadText(out + "/ctl/still.py"), "class Still:\n    pass\n");
}

TEST(ControllerModuleCopyTest, AKindWithoutAFileKeepsNothing) {
  const std::string source = testing::NewFolder("module_copy_cpp");
  const run_config::RunConfig config =
      testing::LoadConfigText(testing::ShippedConfig("go_to_goal"), source + "/c.yaml");
  const std::string out = testing::NewFolder("module_copy_cpp_out");
  KeepControllerModule(config, files::OutputFolder(out));
  EXPECT_TRUE(fs::is_empty(out));
}

TEST(ControllerModuleCopyTest, AMissingModuleIsTheKindsErrorNamingTheKey) {
  const std::string source = testing::NewFolder("module_copy_missing");
  const run_config::RunConfig config = testing::LoadConfigText(PythonConfig("gone.py"), source + "/c.yaml");
  try {
    KeepControllerModule(config, files::OutputFolder(testing::NewFolder("module_copy_missing_out")));
    FAIL() << "a missing module was copied";
  } catch (const config::ConfigError& e) {
    EXPECT_THAT(e.what(), HasSubstr("controller.module"));
    EXPECT_THAT(e.what(), HasSubstr("cannot read"));
  }
}

}  // namespace
}  // namespace dream::bridge
