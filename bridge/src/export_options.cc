#include "dream/bridge/export_options.h"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace dream::bridge {
namespace {

bool Check(bool ok, const std::string& message, std::string* error) {
  if (!ok && error != nullptr) *error = message;
  return ok;
}

std::string Field(const char* name, double value, const char* range) {
  return std::string(name) + " = " + std::to_string(value) + " is out of range; allowed: " + range;
}

// Each strategy and its name on the command line, in the order help lists them.
constexpr std::pair<Strategy, const char*> kStrategyNames[] = {
    {Strategy::kTrack, "track"}, {Strategy::kReplay, "replay"}, {Strategy::kController, "controller"}};

}  // namespace

const char* StrategyName(Strategy strategy) {
  for (const auto& [named, name] : kStrategyNames) {
    if (named == strategy) return name;
  }
  return "?";
}

Strategy ParseStrategy(const std::string& text) {
  std::string allowed;
  for (const auto& [strategy, name] : kStrategyNames) {
    if (text == name) return strategy;
    allowed += (allowed.empty() ? "" : ", ") + std::string(name);
  }
  throw std::invalid_argument("unknown strategy '" + text + "'; allowed: " + allowed);
}

bool ExportOptions::IsValid(std::string* error) const {
  auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  return Check(settle_max_steps >= 0 && settle_max_steps <= 3000,
               Field("settle_max_steps", settle_max_steps, "0..3000"), error) &&
         Check(positive(settle_position_tolerance_m) && settle_position_tolerance_m <= 0.05,
               Field("settle_position_tolerance_m", settle_position_tolerance_m, "(0, 0.05]"), error) &&
         Check(positive(settle_heading_tolerance_rad) && settle_heading_tolerance_rad <= 0.5,
               Field("settle_heading_tolerance_rad", settle_heading_tolerance_rad, "(0, 0.5]"), error) &&
         Check(positive(settle_gain_v_per_s) && settle_gain_v_per_s <= 10,
               Field("settle_gain_v_per_s", settle_gain_v_per_s, "(0, 10]"), error) &&
         Check(positive(settle_gain_w_per_s) && settle_gain_w_per_s <= 20,
               Field("settle_gain_w_per_s", settle_gain_w_per_s, "(0, 20]"), error) &&
         Check(std::isfinite(gain_x_per_s) && gain_x_per_s >= 0 && gain_x_per_s <= 20,
               Field("gain_x_per_s", gain_x_per_s, "[0, 20]"), error) &&
         Check(std::isfinite(gain_y_per_m2) && gain_y_per_m2 >= 0 && gain_y_per_m2 <= 1000,
               Field("gain_y_per_m2", gain_y_per_m2, "[0, 1000]"), error) &&
         Check(std::isfinite(gain_theta_per_s) && gain_theta_per_s >= 0 && gain_theta_per_s <= 20,
               Field("gain_theta_per_s", gain_theta_per_s, "[0, 20]"), error) &&
         Check(save_every_steps >= 1, Field("save_every_steps", save_every_steps, ">= 1"), error);
}

}  // namespace dream::bridge
