#include "dream/workflows/script_export.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace dream::workflows {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

class ScriptExportTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("script_export_test_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    script_ = (dir_ / "my_script.py").string();
    std::ofstream(script_) << "import numpy as np\nimport rps.robotarium\n";
    options_.script_path = script_;
    options_.out_dir = (dir_ / "export").string();
    options_.python = "/usr/bin/python3";
    // Its rps_dream/: check_imports.py (the checker is a fake here) and dream_record.py, the recorder shipped.
    options_.python_runtime_dir = (dir_ / "runtime").string();
    fs::create_directories(dir_ / "runtime" / "rps_dream");
    std::ofstream(dir_ / "runtime" / "rps_dream" / "dream_record.py") << "SCRIPT = \"__DREAM_SCRIPT__\"\nrun()\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// A checker that answers `output` with `code`, and keeps the argv it was given.
  ScriptExport::RunChecker Checker(int code, const std::string& output) {
    return [this, code, output](const std::vector<std::string>& argv) {
      argv_ = argv;
      return ScriptExport::Checked{code, output};
    };
  }

  fs::path dir_;
  std::string script_;
  ScriptExport::Options options_;
  std::vector<std::string> argv_;
};

std::string TextOf(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The upload: the script byte for byte, and DREAM's recorder as the main file, naming it.
TEST_F(ScriptExportTest, TheUploadIsTheScriptAndTheRecorderWithAManifestCheckSubmissionReads) {
  options_.libraries_path = "/sim/libraries.txt";
  // An earlier export's other file must not be uploaded too.
  fs::create_directories(dir_ / "export" / "upload");
  std::ofstream(dir_ / "export" / "upload" / "dream_main.py") << "old";
  const ScriptExport::Result result =
      ScriptExport().Export(options_, Checker(0, "{\"imports\": [\"numpy\", \"rps\"], \"not_on_robotarium\": []}\n"));
  EXPECT_FALSE(result.refused);
  EXPECT_EQ(argv_,
            (std::vector<std::string>{"/usr/bin/python3", options_.python_runtime_dir + "/rps_dream/check_imports.py",
                                      fs::absolute(script_).string(), "/sim/libraries.txt"}));
  EXPECT_EQ(result.main_file, "dream_record.py");
  EXPECT_EQ(result.script_file, "my_script.py");
  EXPECT_EQ(result.imports, (std::vector<std::string>{"numpy", "rps"}));
  std::vector<std::string> uploaded;
  for (const auto& entry : fs::directory_iterator(dir_ / "export" / "upload")) {
    uploaded.push_back(entry.path().filename().string());
  }
  std::sort(uploaded.begin(), uploaded.end());
  EXPECT_EQ(uploaded, (std::vector<std::string>{"dream_record.py", "my_script.py"}));
  EXPECT_EQ(TextOf(dir_ / "export" / "upload" / "my_script.py"), TextOf(script_));
  EXPECT_EQ(TextOf(dir_ / "export" / "upload" / "dream_record.py"), "SCRIPT = \"my_script.py\"\nrun()\n");
  const auto manifest = ScriptExport::Read(options_.out_dir);
  ASSERT_TRUE(manifest.has_value());
  EXPECT_EQ(manifest->main_file, "dream_record.py");
  EXPECT_EQ(manifest->script_file, "my_script.py");
  EXPECT_EQ(manifest->script_sha256.size(), 64u);
  EXPECT_NE(manifest->script_sha256, manifest->sha256);
  EXPECT_EQ(manifest->script, fs::absolute(script_).lexically_normal().string());
  EXPECT_EQ(manifest->sha256.size(), 64u);
  EXPECT_FALSE(ScriptExport::Read(dir_.string()).has_value());
}

TEST_F(ScriptExportTest, AnImportTheRobotariumLacksIsRefusedNamingItAndNothingIsWritten) {
  const ScriptExport::Result result = ScriptExport().Export(
      options_, Checker(0, "{\"imports\": [\"numpy\", \"torchy\"], \"not_on_robotarium\": [\"torchy\"]}"));
  EXPECT_TRUE(result.refused);
  EXPECT_THAT(result.refusal, HasSubstr("imports torchy, which the Robotarium does not have"));
  EXPECT_FALSE(fs::exists(options_.out_dir));
}

TEST_F(ScriptExportTest, AScriptTheCheckerCannotReadOrAnAnswerItCannotUseIsAnErrorNamingTheScript) {
  try {
    ScriptExport().Export(options_, Checker(1, "my_script.py: invalid syntax (line 3)\n"));
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("my_script.py: cannot read its imports: my_script.py: invalid syntax (line 3)"));
  }
  EXPECT_THROW(ScriptExport().Export(options_, Checker(0, "[1, 2]")), std::runtime_error);
  options_.script_path = (dir_ / "missing.py").string();
  EXPECT_THROW(ScriptExport().Export(options_, Checker(0, "")), std::runtime_error);
  EXPECT_FALSE(fs::exists(dir_ / "export"));
}

TEST_F(ScriptExportTest, ADamagedManifestIsNamed) {
  fs::create_directories(dir_ / "damaged");
  std::ofstream(dir_ / "damaged" / ScriptExport::kManifestName)
      << "{\"script\": \"/s.py\", \"main_file\": \"../x.py\", "
         "\"sha256\": \"00\"}";
  try {
    ScriptExport::Read((dir_ / "damaged").string());
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_THAT(e.what(), HasSubstr("main_file '../x.py' is no file name"));
  }
}

}  // namespace
}  // namespace dream::workflows
