#include "dream/world/startup_drive_trials.h"

#include <algorithm>
#include <future>
#include <system_error>
#include <utility>
#include <vector>

#include "dream/robotarium/robotarium_constants.h"
#include "dream/world/printf_text.h"
#include "dream/world/startup_drive.h"

namespace dream::world {

uint64_t StartupDriveTrials::PlacementSeed(uint64_t run_seed, int placement) {
  // splitmix64 of (seed, placement): neighbouring run seeds give unrelated placements.
  uint64_t z = run_seed + 0x9e3779b97f4a7c15ULL * (static_cast<uint64_t>(placement) + 1);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

StartupDriveTrials StartupDriveTrials::Try(const WorldParams& world, const std::vector<Pose2>& start_poses,
                                           uint64_t run_seed, int placements) {
  const StartupDrive drive(world, start_poses);
  StartupDriveTrials trials;
  // More robots than charger slots fails every placement alike: once is enough.
  if (static_cast<int>(start_poses.size()) > StartupDrive::kChargerSlots) placements = std::min(placements, 1);
  // The placements are independent drives (Run builds its own world and barrier): one thread
  // each, so `dream run` waits for the slowest drive rather than for their sum.
  std::vector<std::future<StartupDriveResult>> drives;
  for (int i = 0; i < placements; ++i) {
    const auto run = [&drive, run_seed, i] { return drive.Run(PlacementSeed(run_seed, i)); };
    try {
      drives.push_back(std::async(std::launch::async, run));
    } catch (const std::system_error&) {
      drives.push_back(std::async(std::launch::deferred, run));  // no thread to be had: in this one, later
    }
  }
  for (std::future<StartupDriveResult>& result : drives) trials.results_.push_back(result.get());
  return trials;
}

StartupDriveTrials StartupDriveTrials::Of(std::vector<StartupDriveResult> results) {
  StartupDriveTrials trials;
  trials.results_ = std::move(results);
  return trials;
}

int StartupDriveTrials::settled() const {
  return static_cast<int>(
      std::count_if(results_.begin(), results_.end(), [](const StartupDriveResult& result) { return result.settled; }));
}

int StartupDriveTrials::MostSteps() const {
  int most = 0;
  for (const StartupDriveResult& result : results_) {
    if (result.settled) most = std::max(most, result.steps);
  }
  return most;
}

std::string StartupDriveTrials::Describe() const {
  for (const StartupDriveResult& result : results_) {
    if (!result.refusal.empty()) return "the Robotarium's start-up drive cannot start: " + result.refusal;
  }
  std::string text =
      PrintfText("the Robotarium's start-up drive settled from %d of %d random charger placements", settled(), tried());
  if (settled() > 0)
    text += PrintfText(" (at most %d steps, %.1f s)", MostSteps(),
                       MostSteps() * robotarium::RobotariumConstants::kTimeStepSeconds);
  for (const StartupDriveResult& result : results_) {
    if (result.settled) continue;
    text += PrintfText("; from placement seed %llu, after %d steps ", static_cast<unsigned long long>(result.seed),
                       result.steps) +
            "these robots were still off their start poses (distance / heading error): " + result.DescribeMisses();
    break;
  }
  return text;
}

}  // namespace dream::world
