// dream --version / dream version: which build this is, for bug reports and
// for telling two installed copies apart.
#include <iostream>
#include <string>

#include "command_line.h"
#include "commands.h"
#include "dream_version.h"

namespace dream::cli {

std::string VersionLine() {
  const std::string commit = DREAM_GIT_COMMIT;
  return std::string("dream ") + DREAM_VERSION + (commit.empty() ? "" : " (git " + commit + ")");
}

void DeclareVersionCommand(CommandLine& line) {
  line.AddCommand("version", "Print the version (as dream --version) and exit.", [] {
    std::cout << VersionLine() << '\n';
    return kExitOk;
  });
}

}  // namespace dream::cli
