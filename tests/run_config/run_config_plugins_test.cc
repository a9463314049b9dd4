#include <gtest/gtest.h>

#include <filesystem>

#include "dream/run_config/run_config.h"

namespace dream::config {
namespace {

namespace fs = std::filesystem;

const char* kBase = "name: p\nrobots: 1\ninitial_poses: [[0, 0, 0]]\ncontroller: {kind: orbit}\n";

run_config::RunConfig Load(const std::string& extra, const std::string& source = "experiments/p.yaml") {
  return run_config::LoadRunConfig(ConfigNode::LoadString(kBase + extra, source));
}

std::string ErrorOf(const std::string& extra) {
  try {
    Load(extra);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(RunConfigPluginsTest, RelativePathsStartAtTheConfigFilesFolder) {
  const run_config::RunConfig config = Load("plugins: [build/liba.so, /opt/x/libb.so, ../libc.so]\n");
  const fs::path folder = fs::absolute("experiments");
  ASSERT_EQ(config.plugins.size(), 3u);
  EXPECT_EQ(config.plugins[0], (folder / "build/liba.so").lexically_normal().string());
  EXPECT_EQ(config.plugins[1], "/opt/x/libb.so");
  EXPECT_EQ(config.plugins[2], (folder / "../libc.so").lexically_normal().string());
  ASSERT_EQ(config.plugin_nodes.size(), 3u);
  EXPECT_EQ(config.plugin_nodes[2].key(), "plugins[2]");
  EXPECT_TRUE(Load("").plugins.empty());
}

TEST(RunConfigPluginsTest, PluginDirMovesTheStartAndMustBeAbsolute) {
  EXPECT_EQ(Load("plugin_dir: /srv/plugins\nplugins: [build/liba.so]\n").plugins.at(0), "/srv/plugins/build/liba.so");
  EXPECT_NE(ErrorOf("plugin_dir: here\nplugins: [a.so]\n").find("p.yaml:5: plugin_dir: must be an absolute path"),
            std::string::npos);
  EXPECT_NE(ErrorOf("plugins: build/liba.so\n").find("plugins: expected a list of plugin files"), std::string::npos);
  EXPECT_NE(ErrorOf("plugins: ['']\n").find("plugins[0]: expected the path of a plugin file"), std::string::npos);
}

TEST(RunConfigPluginsTest, TheRunFoldersCopyFindsTheSamePlugins) {
  const std::string text = std::string(kBase) + "plugins: [build/liba.so]  # the plugin";
  const run_config::RunConfig config = run_config::LoadRunConfig(ConfigNode::LoadString(text, "experiments/p.yaml"));
  const std::string copy = run_config::RunFolderConfigText(config, text);
  EXPECT_EQ(copy.rfind(text + "\n", 0), 0u) << "the original text comes first, unchanged";
  // Read back from another folder, the copy still names the same file.
  const run_config::RunConfig reread = run_config::LoadRunConfig(ConfigNode::LoadString(copy, "runs/p/config.yaml"));
  EXPECT_EQ(reread.plugins, config.plugins);
  // Nothing to add without relative plugin paths, or with plugin_dir already there.
  const std::string plain = std::string(kBase) + "plugins: [/opt/liba.so]\n";
  EXPECT_EQ(run_config::RunFolderConfigText(run_config::LoadRunConfig(ConfigNode::LoadString(plain, "p.yaml")), plain),
            plain);
  EXPECT_EQ(run_config::RunFolderConfigText(reread, copy), copy);
  EXPECT_EQ(run_config::RunFolderConfigText(Load(""), kBase), kBase);
}

}  // namespace
}  // namespace dream::config
