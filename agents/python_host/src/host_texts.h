#pragma once

// PythonHostProcess's helpers, apart so its file reads as the relay it is: the
// start frame, the limits' defaults and the texts of a stuck call.

#include <spdlog/spdlog.h>

#include <chrono>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dream/config/sim_node_options.h"
#include "dream/python_host/python_host_process.h"

namespace dream::python_host::host_texts {

// Frames for the process beyond this are dropped: it is far behind, i.e. stuck.
inline constexpr size_t kMaxOutboxBytes = size_t{1} << 28;
inline double Seconds(std::chrono::steady_clock::duration duration) {
  return std::chrono::duration<double>(duration).count();
}
inline std::chrono::steady_clock::duration DurationOf(double seconds) {
  return std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds));
}

// The start frame: what the process hosts, and how.
inline std::string StartFrame(const std::string& spec_json, const std::vector<int>& robot_ids, int64_t agent_id,
                              const PythonHostProcess::Limits& limits, bool check_only) {
  nlohmann::json start;
  start["spec"] = spec_json;
  start["robots"] = robot_ids;
  start["agent_id"] = agent_id;
  start["agent_timeout_s"] = limits.agent_timeout_s;
  start["start_timeout_s"] = limits.start_timeout_s;
  start["idle_timeout_s"] = limits.idle_timeout_s;
  start["check_only"] = check_only;
  start["log_level"] = static_cast<int>(spdlog::get_level());
  return start.dump();
}

inline PythonHostProcess::Limits WithDefaults(PythonHostProcess::Limits limits) {
  const config::SimNodeOptions defaults;
  if (!(limits.agent_timeout_s > 0)) limits.agent_timeout_s = defaults.agent_timeout_s;
  if (!(limits.start_timeout_s > 0)) limits.start_timeout_s = defaults.start_timeout_s;
  return limits;
}

// What the call in the cell was: loading the module (robot -1), a robot's
// setup() (step < 0) or its step's call.
inline std::string CallTextOf(int64_t robot, int64_t step) {
  if (robot < 0) return "loading the controller's module";
  return "robot " + std::to_string(robot) + "'s " +
         (step < 0 ? std::string("setup()") : "call at step " + std::to_string(step));
}

// A call ended by killing its process: in the check before a run, at
// kKillFraction of its limit; in a run, kKillAfterRaiseFraction of the limit
// after the process's watchdog raised ControllerTimeout in it (`raised`), or
// at kKillUnraisedFraction when the watchdog never could.
inline std::string StuckTextOf(int64_t token, int64_t robot, int64_t step, const PythonHostProcess::Limits& limits,
                               bool in_run, bool raised) {
  const double limit_s = token > 0 ? limits.agent_timeout_s : limits.start_timeout_s;
  const char* limit_name = token > 0 ? "agent_timeout_s" : "start_timeout_s";
  const std::string call = CallTextOf(robot, token > 0 ? step : -1);
  const char* cannot = "a call blocked outside Python, in time.sleep, a blocking read or C code, cannot";
  char text[500];
  if (!in_run) {
    std::snprintf(text, sizeof text,
                  "%s did not return within %g s (%g x the world's %s of %g s), nor stop when dream's watchdog "
                  "raised ControllerTimeout in it (%s): its Python process was killed",
                  call.c_str(), PythonHostProcess::kKillFraction * limit_s, PythonHostProcess::kKillFraction,
                  limit_name, limit_s, cannot);
  } else if (raised) {
    std::snprintf(text, sizeof text,
                  "%s did not return, nor stop when dream's watchdog raised ControllerTimeout in it at 0.8 x the "
                  "world's %s of %g s (%s): its Python process was killed %g s later",
                  call.c_str(), limit_name, limit_s, cannot, PythonHostProcess::kKillAfterRaiseFraction * limit_s);
  } else {
    std::snprintf(text, sizeof text,
                  "%s did not return within %g s (%g x the world's %s of %g s), and dream's watchdog could not raise "
                  "ControllerTimeout in it (its process starved of CPU, or Python's threads blocked): its Python "
                  "process was killed",
                  call.c_str(), PythonHostProcess::kKillUnraisedFraction * limit_s,
                  PythonHostProcess::kKillUnraisedFraction, limit_name, limit_s);
  }
  return text;
}

inline std::string ModulePathOf(const std::string& spec_json) {
  try {
    const nlohmann::json spec = nlohmann::json::parse(spec_json);
    return spec.value("module", std::string());
  } catch (const std::exception&) {
    return "";
  }
}

inline std::string JoinIds(const std::vector<int>& ids) {
  std::string text;
  for (int id : ids) text += (text.empty() ? "" : ", ") + std::to_string(id);
  return text;
}

}  // namespace dream::python_host::host_texts
