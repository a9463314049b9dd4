#pragma once

#include <string>

namespace dream::process {

/// Files the dream tools need at run time besides the libraries: the Java
/// types jar (dream spy), the bridge's Python runner (dream
/// check-submission), the dream-agent program and what it loads to host
/// Python controllers. A tool in the build tree it was built in uses the build
/// and source trees' files; an installed tool those under
/// <prefix>/share/dream, found relative to its own location so the prefix
/// can move. Paths are returned whether or not the file exists.
class DataFiles {
 public:
  static std::string TypesJar();
  /// The folder of run_submission.py and the stand-in simulator.
  static std::string BridgePythonDir();
  /// The folder holding the Python controller runtime, package `dream` (python/).
  static std::string PythonRuntimeDir();
  /// The folder holding lcm-gen's Python types, their package `dream`.
  static std::string PythonTypesDir();
  /// The embedded Python module (libdream_python_embedded.so), in lib/ when installed.
  static std::string PythonHostModule();
  /// The dream-agent program, next to the running one (dream and dream-agent
  /// are built and installed side by side).
  static std::string AgentBinary();
  /// dream-agent-shared, next to the running program: dream-agent linked
  /// against the shared dream libraries, for what loads a library that links
  /// them (controller plugins, the embedded Python module); dream-agent holds
  /// its own copy of the dream code.
  static std::string SharedAgentBinary();
  /// True when the running executable is the one in its build tree.
  static bool RunningFromBuildTree();

 private:
  static std::string Locate(const std::string& installed_relative_path, const std::string& build_tree_path);
};

}  // namespace dream::process
