// dream-agent: the agents of some robots, as a lean process. `dream agent`
// and `dream launch` start it; its options are those of `dream agent`.
#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>

#include "commands.h"
#include "dream/config/config_error.h"
#include "dream/process/data_files.h"
#include "dream/python_host/python_host_child.h"
#include "shared_options.h"

namespace {

// dream-agent holds its own copy of the dream libraries (static archives,
// app/cli/CMakeLists.txt), so a library that links the shared ones must not
// be loaded into it: the same words go to dream-agent-shared instead.
[[noreturn]] void ExecSharedAgent(char** argv) {
  const std::string binary = dream::process::DataFiles::SharedAgentBinary();
  argv[0] = const_cast<char*>(binary.c_str());
  ::execv(binary.c_str(), argv);
  throw std::runtime_error("cannot start " + binary + " for the config's controller plugins (" + std::strerror(errno) +
                           "); it is built and installed next to dream-agent");
}

#ifdef DREAM_AGENT_HOLDS_DREAM_LIBRARIES
constexpr bool kHoldsDreamLibraries = true;
#else
constexpr bool kHoldsDreamLibraries = false;
#endif

}  // namespace

int main(int argc, char** argv) {
  using namespace dream::cli;
  // Started by PythonHostProcess, not by a user: no options of its own.
  if (argc == 2 && std::string(argv[1]) == "--python-host") {
    spdlog::set_pattern("[%H:%M:%S.%e] [%^%l%$] %v");
    if (kHoldsDreamLibraries) {
      try {
        ExecSharedAgent(argv);
      } catch (const std::exception& e) {
        std::cerr << "dream-agent --python-host: " << e.what() << '\n';
        return kExitInputError;
      }
    }
    InstallStopSignals();
    dream::python_host::PythonHostChild::Run(StopFlag(), {kExitOk, kExitUsage, kExitInputError, kExitRunFailed});
  }
  CLI::App app{
      "Run the agents of some robots against whichever world is on the bus.\n"
      "Example: dream agent config/go_to_goal.yaml --robots 0-2",
      "dream agent"};
  AgentArgs args;
  bool quiet = false;
  bool verbose = false;
  AddAgentOptions(&app, &args);  // the same as `dream agent`'s, which hands its words over
  app.add_flag("-q,--quiet", quiet, "Only warnings and errors");
  app.add_flag("-v,--verbose", verbose, "Debug output");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? kExitOk : kExitUsage;
  }
  spdlog::set_pattern("[%H:%M:%S.%e] [%^%l%$] %v");
  spdlog::set_level(quiet ? spdlog::level::warn : verbose ? spdlog::level::debug : spdlog::level::info);
  InstallStopSignals();
  try {
    std::function<void()> hand_over_plugins;
    if (kHoldsDreamLibraries) hand_over_plugins = [argv] { ExecSharedAgent(argv); };
    return RunAgents(args, hand_over_plugins);
  } catch (const std::exception& e) {
    std::cerr << "dream agent: " << e.what() << '\n';
    return kExitInputError;
  }
}
