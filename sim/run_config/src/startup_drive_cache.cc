#include "dream/run_config/startup_drive_cache.h"

#include <spdlog/spdlog.h>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <utility>

#include "dream/files/atomic_file.h"
#include "dream/files/file_text.h"
#include "dream/world/startup_drive.h"

namespace dream::run_config {
namespace {

namespace fs = std::filesystem;

std::string Hex(double value) {
  char text[40];
  std::snprintf(text, sizeof(text), "%a", value);
  return text;
}

// FNV-1a, 64 bits: the file's name only; the file holds the whole key, compared on reading.
uint64_t Fnv1a(const std::string& text) {
  uint64_t hash = 0xcbf29ce484222325ULL;
  for (const char c : text) hash = (hash ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
  return hash;
}

std::string Env(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr ? value : "";
}

// One placement's result as Store writes it; throws naming what is wrong.
world::StartupDriveResult ResultOf(const nlohmann::json& entry) {
  world::StartupDriveResult result;
  if (!entry.is_object() || entry.size() != 5) {
    throw std::runtime_error("a result is not {seed, settled, steps, misses, refusal}");
  }
  const nlohmann::json& seed = entry.at("seed");
  const nlohmann::json& steps = entry.at("steps");
  if (!seed.is_number_unsigned() || !entry.at("settled").is_boolean() || !steps.is_number_integer() ||
      steps.get<int64_t>() < 0 || steps.get<int64_t>() > 1000000 || !entry.at("misses").is_array() ||
      !entry.at("refusal").is_string()) {
    throw std::runtime_error("a result's field has the wrong type or range");
  }
  result.seed = seed.get<uint64_t>();
  result.settled = entry.at("settled").get<bool>();
  result.steps = steps.get<int>();
  result.refusal = entry.at("refusal").get<std::string>();
  for (const nlohmann::json& miss : entry.at("misses")) {
    if (!miss.is_array() || miss.size() != 3 || !miss[0].is_number_integer() || !miss[1].is_number() ||
        !miss[2].is_number()) {
      throw std::runtime_error("a miss is not [robot, distance_m, heading_error_rad]");
    }
    result.misses.push_back({miss[0].get<int>(), miss[1].get<double>(), miss[2].get<double>()});
  }
  return result;
}

}  // namespace

std::string StartupDriveCache::DefaultFolder() {
  if (const char* own = std::getenv("DREAM_CACHE_DIR")) return own;
  if (const std::string xdg = Env("XDG_CACHE_HOME"); !xdg.empty()) return xdg + "/dream";
  if (const std::string home = Env("HOME"); !home.empty()) return home + "/.cache/dream";
  return "";
}

StartupDriveCache::StartupDriveCache(std::string folder) : folder_(std::move(folder)) {}

std::string StartupDriveCache::KeyText(const world::WorldParams& world, const std::vector<world::Pose2>& start_poses,
                                       const std::vector<uint64_t>& seeds) {
  std::string key = "startup drive revision " + std::to_string(world::StartupDrive::kRevision) + ", max steps " +
                    std::to_string(world::StartupDrive::MaxSteps()) + "; world";
  for (const double value : {world.arena.x_min_m, world.arena.x_max_m, world.arena.y_min_m, world.arena.y_max_m,
                             world.time_step_s, world.wheel_radius_m, world.base_length_m, world.max_wheel_speed_radps,
                             world.collision_diameter_m, world.collision_offset_m, world.command_timeout_s}) {
    key += " " + Hex(value);
  }
  key += "; poses";
  for (const world::Pose2& pose : start_poses)
    key += " " + Hex(pose.x_m) + "," + Hex(pose.y_m) + "," + Hex(pose.theta_rad);
  key += "; seeds";
  for (const uint64_t seed : seeds) key += " " + std::to_string(seed);
  return key;
}

std::string StartupDriveCache::FileOf(const std::string& key_text) const {
  char name[40];
  std::snprintf(name, sizeof(name), "%016llx.json", static_cast<unsigned long long>(Fnv1a(key_text)));
  return folder_ + "/startup_drive/" + name;
}

std::optional<world::StartupDriveTrials> StartupDriveCache::Find(const std::string& key_text) const {
  if (folder_.empty()) return std::nullopt;
  const std::string path = FileOf(key_text);
  std::error_code error;
  if (!fs::exists(path, error)) return std::nullopt;
  try {
    const nlohmann::json entry = nlohmann::json::parse(files::ReadFileText(path, kMaxFileBytes));
    if (!entry.is_object() || entry.size() != 2 || !entry.at("key").is_string() || !entry.at("results").is_array() ||
        entry.at("results").empty() || entry.at("results").size() > world::StartupDriveTrials::kPlacements) {
      throw std::runtime_error("not {key, results: 1-" + std::to_string(world::StartupDriveTrials::kPlacements) +
                               " placements}");
    }
    // Another key of the same name (a hash collision) is no entry of this one: run the drives.
    if (entry.at("key").get<std::string>() != key_text) return std::nullopt;
    std::vector<world::StartupDriveResult> results;
    for (const nlohmann::json& result : entry.at("results")) results.push_back(ResultOf(result));
    return world::StartupDriveTrials::Of(std::move(results));
  } catch (const std::exception& e) {
    spdlog::warn("{}: ignored, not a start-up drive cache entry ({}); the drives run again", path, e.what());
    return std::nullopt;
  }
}

void StartupDriveCache::Store(const std::string& key_text, const world::StartupDriveTrials& trials) const {
  if (folder_.empty()) return;
  nlohmann::json results = nlohmann::json::array();
  for (const world::StartupDriveResult& result : trials.results()) {
    nlohmann::json misses = nlohmann::json::array();
    for (const world::StartupDriveResult::Miss& miss : result.misses) {
      misses.push_back({miss.robot_id, miss.distance_m, miss.heading_error_rad});
    }
    results.push_back({{"seed", result.seed},
                       {"settled", result.settled},
                       {"steps", result.steps},
                       {"misses", misses},
                       {"refusal", result.refusal}});
  }
  const std::string path = FileOf(key_text);
  try {
    fs::create_directories(fs::path(path).parent_path());
    files::WriteFileAtomically(path, nlohmann::json{{"key", key_text}, {"results", results}}.dump() + "\n",
                               files::Durability::kRenamedOnly);
  } catch (const std::exception& e) {
    // A cache is a nicety: a read-only home must not add a line to every run.
    spdlog::debug("the start-up drive's result was not cached ({}): the next run drives again", e.what());
  }
}

world::StartupDriveTrials StartupDriveCache::Trials(const world::WorldParams& world,
                                                    const std::vector<world::Pose2>& start_poses,
                                                    uint64_t run_seed) const {
  std::vector<uint64_t> seeds;
  for (int i = 0; i < world::StartupDriveTrials::kPlacements; ++i) {
    seeds.push_back(world::StartupDriveTrials::PlacementSeed(run_seed, i));
  }
  const std::string key = KeyText(world, start_poses, seeds);
  if (std::optional<world::StartupDriveTrials> cached = Find(key)) return std::move(*cached);
  world::StartupDriveTrials trials = world::StartupDriveTrials::Try(world, start_poses, run_seed);
  Store(key, trials);
  return trials;
}

}  // namespace dream::run_config
