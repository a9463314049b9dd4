#pragma once

#include <string>
#include <vector>

#include "dream/barriers/unicycle_barrier_params.h"
#include "dream/world/lab_verifier_rules.h"

namespace dream::bridge {

/// How the exported script drives the robots.
enum class Strategy {
  /// Follow the recorded trajectories in closed loop: the recorded command
  /// plus feedback on the error to the recorded pose (default).
  kTrack,
  /// Send the recorded commands, open loop.
  kReplay,
  /// Run the Python controller itself every step on the lab's poses, in
  /// closed loop (controller kind python only).
  kController,
};

/// "track" / "replay" / "controller"; ParseStrategy throws std::invalid_argument otherwise.
const char* StrategyName(Strategy strategy);
Strategy ParseStrategy(const std::string& text);
/// What the strategy does, in words ("recorded commands, open loop").
const char* StrategyDescription(Strategy strategy);
/// Every strategy's name, in the order help lists them.
std::vector<std::string> StrategyNames();

/// The tunable part of an export. Defaults suit the Robotarium: a settle
/// phase of at most 8 s brings each robot to within 5 mm and ~1 degree of
/// its start pose, and the tracking gains correct centimetre errors within
/// about a second at the lab's 0.033 s step.
struct ExportOptions {
  Strategy strategy = Strategy::kTrack;
  /// Pass every command through the Robotarium's own unicycle barrier
  /// certificate (`--barriers`, or the run config's `barriers:` with
  /// `apply_in: world`, so the lab applies what the simulator did).
  bool barriers = false;
  /// Its parameters: rps's create_uni_barrier_certificate_with_boundary()
  /// defaults, or the config's.
  barriers::UnicycleBarrierParams barrier_params = barriers::UnicycleBarrierParams::RpsWithBoundary();
  /// Settle phase before step 0: at most this many steps (0: none). Every
  /// run's verdict assumes this default (the duration its export declares).
  int settle_max_steps = static_cast<int>(world::LabVerifierRules::kExportSettleSteps);
  double settle_position_tolerance_m = 0.005;
  double settle_heading_tolerance_rad = 0.02;
  double settle_gain_v_per_s = 1.5;  ///< forward speed per metre of distance
  double settle_gain_w_per_s = 3.0;  ///< turn rate per radian of error
  /// Tracking (Kanayama): v = v_r cos(e_th) + k_x e_x,
  /// w = w_r + k_y v_r e_y + k_th sin(e_th), errors in the robot's frame.
  double gain_x_per_s = 3.0;
  double gain_y_per_m2 = 25.0;
  double gain_theta_per_s = 3.0;
  /// The script rewrites its result file every this many experiment steps.
  int save_every_steps = 900;
  /// Strategy controller: the folder holding the Python runtime's package
  /// `dream` (python/ of the source tree), whose modules the submission ships.
  std::string python_runtime_dir;
  /// Export although robots were lost at the end of the run (`lost_robot`):
  /// those problems become warnings in the output and UPLOAD.txt.
  bool force = false;
  /// The run is the calibration drive (`dream export --calibration`):
  /// UPLOAD.txt and export.json say so, and UPLOAD.txt ends with how to fit
  /// the lab model from what the lab returns (dream import, dream calibrate).
  bool calibration = false;

  /// False with a message naming the field, its value and the allowed range.
  bool IsValid(std::string* error) const;
};

}  // namespace dream::bridge
