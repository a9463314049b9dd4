#pragma once

#include <vector>

#include "dream/world/realistic_world.h"
#include "dream/node/run_recorder.h"

namespace dream::node {

/// How a run with world.realism keeps the truth in its log: the agents are
/// sent measured poses on DREAM_POSES, but the log records, for each recorded
/// DREAM_POSES, that message on DREAM_MEASURED_POSES and then the same message
/// with the world's true poses and velocities on DREAM_POSES. So every reader
/// of a run (metrics, pictures, export, compare, dream_log.py) judges what the
/// robots really did, and DREAM_MEASURED_POSES shows what the agents saw.
class TruePoseRecording {
 public:
  /// The channel of the poses the agents were sent.

  /// Rewrites `recorder`'s DREAM_POSES until destroyed. Both must outlive it.
  TruePoseRecording(RunRecorder& recorder, const world::RealisticWorld& world);
  ~TruePoseRecording();
  TruePoseRecording(const TruePoseRecording&) = delete;
  TruePoseRecording& operator=(const TruePoseRecording&) = delete;

 private:
  void Record(int64_t utime, const void* data, int size);

  RunRecorder& recorder_;
  const world::RealisticWorld& world_;
  std::vector<uint8_t> buffer_;  // the true message, reused
};

}  // namespace dream::node
