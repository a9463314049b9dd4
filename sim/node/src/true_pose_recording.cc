#include "dream/node/true_pose_recording.h"

#include "dream/lcm/channels.h"
#include "dream/lcm/lcm_typed.h"
#include "dream/robot_poses_t.hpp"

namespace dream::node {

TruePoseRecording::TruePoseRecording(RunRecorder& recorder, const world::RealisticWorld& world)
    : recorder_(recorder), world_(world) {
  recorder_.RewriteChannel(lcm::kPosesChannel,
                           [this](int64_t utime, const void* data, int size) { Record(utime, data, size); });
}

TruePoseRecording::~TruePoseRecording() { recorder_.RewriteChannel("", nullptr); }

void TruePoseRecording::Record(int64_t utime, const void* data, int size) {
  recorder_.Write(lcm::kMeasuredPosesChannel, utime, data, size);
  robot_poses_t poses;
  // The world encoded it a moment ago; a message that does not decode stays
  // measured only (nothing to put the truth into).
  if (!lcm::Decode(data, size, &poses)) return;
  const std::vector<world::Pose2>& truth = world_.true_poses();
  const std::vector<world::UnicycleCommand>& velocities = world_.true_velocities();
  if (poses.x.size() != truth.size() || poses.v.size() != velocities.size()) return;
  for (size_t i = 0; i < truth.size(); ++i) {
    poses.x[i] = truth[i].x_m;
    poses.y[i] = truth[i].y_m;
    poses.theta[i] = truth[i].theta_rad;
    // As the world publishes them: zero before the first step.
    poses.v[i] = poses.step > 0 ? velocities[i].v_mps : 0.0;
    poses.w[i] = poses.step > 0 ? velocities[i].w_radps : 0.0;
  }
  const int true_size = poses.getEncodedSize();
  buffer_.resize(static_cast<size_t>(true_size));
  poses.encode(buffer_.data(), 0, true_size);
  recorder_.Write(lcm::kPosesChannel, utime, buffer_.data(), true_size);
}

}  // namespace dream::node
