#include "dream/bridge/export_options.h"

#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace dream::bridge {
namespace {

bool Check(bool ok, const std::string& message, std::string* error) {
  if (!ok && error != nullptr) *error = message;
  return ok;
}

std::string Field(const char* name, double value, const char* range) {
  return std::string(name) + " = " + std::to_string(value) + " is out of range; allowed: " + range;
}

// Each strategy: its name on the command line and in manifests, and what it
// does in words (upload.txt), in the order help lists them.
struct StrategyEntry {
  Strategy strategy;
  const char* name;
  const char* description;
};
constexpr StrategyEntry kStrategies[] = {
    {Strategy::kTrack, "track", "recorded commands plus feedback on the pose error"},
    {Strategy::kReplay, "replay", "recorded commands, open loop"},
    {Strategy::kController, "controller", "the Python controller runs every step on the lab's poses"},
};

const StrategyEntry* EntryOf(Strategy strategy) {
  for (const StrategyEntry& entry : kStrategies) {
    if (entry.strategy == strategy) return &entry;
  }
  return nullptr;
}

}  // namespace

const char* StrategyName(Strategy strategy) {
  const StrategyEntry* entry = EntryOf(strategy);
  return entry != nullptr ? entry->name : "?";
}

const char* StrategyDescription(Strategy strategy) {
  const StrategyEntry* entry = EntryOf(strategy);
  return entry != nullptr ? entry->description : "?";
}

std::vector<std::string> StrategyNames() {
  std::vector<std::string> names;
  for (const StrategyEntry& entry : kStrategies) names.emplace_back(entry.name);
  return names;
}

Strategy ParseStrategy(const std::string& text) {
  std::string allowed;
  for (const StrategyEntry& entry : kStrategies) {
    if (text == entry.name) return entry.strategy;
    allowed += (allowed.empty() ? "" : ", ") + std::string(entry.name);
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
