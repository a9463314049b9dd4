#include "dream/workflows/shell_quoted.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <string>

namespace dream::workflows {
namespace {

TEST(ShellQuotedTest, PlainWordsStayAsTheyAre) {
  EXPECT_EQ(ShellQuoted("/opt/dream/bin/dream"), "/opt/dream/bin/dream");
  EXPECT_EQ(ShellQuoted("--set=controller.max_speed_mps=0.1"), "--set=controller.max_speed_mps=0.1");
}

TEST(ShellQuotedTest, AnythingAShellWouldReadOtherwiseIsQuoted) {
  EXPECT_EQ(ShellQuoted(""), "''");
  EXPECT_EQ(ShellQuoted("udpm://239.255.76.67:7667?ttl=0"), "'udpm://239.255.76.67:7667?ttl=0'");
  EXPECT_EQ(ShellQuoted("my runs/a b"), "'my runs/a b'");
  EXPECT_EQ(ShellQuoted("it's"), "'it'\\''s'");
  EXPECT_EQ(ShellCommandLine({"dream", "sweep", "table", "my runs"}), "dream sweep table 'my runs'");
}

// What a sweep's run.sh and Slurm jobs rely on: /bin/sh reads each word back as it was.
TEST(ShellQuotedTest, TheShellReadsEveryWordBack) {
  const std::string word = "a 'b' \"c\" $HOME `x` \\ & ; ?*";
  FILE* shell = popen(("printf '%s' " + ShellQuoted(word)).c_str(), "r");
  ASSERT_NE(shell, nullptr);
  std::string back;
  char buffer[256];
  for (size_t n; (n = fread(buffer, 1, sizeof(buffer), shell)) > 0;) back.append(buffer, n);
  EXPECT_EQ(pclose(shell), 0);
  EXPECT_EQ(back, word);
}

}  // namespace
}  // namespace dream::workflows
