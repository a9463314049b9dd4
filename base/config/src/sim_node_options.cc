#include "dream/config/sim_node_options.h"

#include <cmath>
#include <stdexcept>

namespace dream::config {

WorldMode ParseWorldMode(const std::string& text) {
  if (text == "lockstep") return WorldMode::kLockstep;
  if (text == "realtime") return WorldMode::kRealTime;
  throw std::invalid_argument("unknown world mode '" + text + "'; allowed: lockstep, realtime");
}

const char* WorldModeName(WorldMode mode) { return mode == WorldMode::kLockstep ? "lockstep" : "realtime"; }

bool SimNodeOptions::IsValid(std::string* error) const {
  auto fail = [error](const std::string& message) {
    if (error != nullptr) *error = message;
    return false;
  };
  auto positive = [](double value) { return std::isfinite(value) && value > 0.0; };
  if (max_steps < 1) return fail("max_steps must be >= 1, got " + std::to_string(max_steps));
  if (!positive(agent_timeout_s)) return fail("agent_timeout_s must be > 0, got " + std::to_string(agent_timeout_s));
  if (!positive(start_timeout_s)) return fail("start_timeout_s must be > 0, got " + std::to_string(start_timeout_s));
  if (!(std::isfinite(resend_interval_s) && resend_interval_s >= kMinResendIntervalS)) {
    return fail("resend_interval_s must be >= " + std::to_string(kMinResendIntervalS) + " s, got " +
                std::to_string(resend_interval_s));
  }
  if (!positive(max_abs_v_mps)) return fail("max_abs_v_mps must be > 0, got " + std::to_string(max_abs_v_mps));
  if (!positive(max_abs_w_radps)) return fail("max_abs_w_radps must be > 0, got " + std::to_string(max_abs_w_radps));
  if (!(progress_interval_s >= 0.0)) {
    return fail("progress_interval_s must be >= 0, got " + std::to_string(progress_interval_s));
  }
  if (!(std::isfinite(pace) && pace >= 0.0 && pace <= kMaxPace)) {
    return fail("pace must be from 0 (unpaced) to " + std::to_string(kMaxPace) + ", got " + std::to_string(pace));
  }
  return true;
}

}  // namespace dream::config
