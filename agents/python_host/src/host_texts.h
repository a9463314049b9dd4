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

inline std::string StuckTextOf(int64_t token, int64_t robot, int64_t step, const PythonHostProcess::Limits& limits) {
  const double limit_s = token > 0 ? limits.agent_timeout_s : limits.start_timeout_s;
  char text[400];
  std::snprintf(text, sizeof text,
                "%s did not return within %g s (%g x the world's %s of %g s), nor stop when dream's watchdog "
                "raised ControllerTimeout in it (a call blocked outside Python, in time.sleep, a blocking read or "
                "C code, cannot): its Python process was killed",
                CallTextOf(robot, token > 0 ? step : -1).c_str(), PythonHostProcess::kKillFraction * limit_s,
                PythonHostProcess::kKillFraction, token > 0 ? "agent_timeout_s" : "start_timeout_s", limit_s);
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
