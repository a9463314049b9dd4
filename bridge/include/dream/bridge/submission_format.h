#pragma once

#include <cstdint>

namespace dream::bridge {

// The contract between `dream export`, the submission script
// (bridge/python/dream_main.py, a fixed template) and `dream import`. The
// script holds no data of the run: every number comes from these .npy files
// (float64, C order). bridge_test checks that the template's P_* constants
// match ParamIndex.

/// File names, all flat (the Robotarium takes files, no folders).
struct SubmissionFiles {
  static constexpr const char* kMainScript = "dream_main.py";
  /// ParamIndex::kCount numbers: what the script needs besides the arrays.
  static constexpr const char* kParams = "dream_params.npy";
  /// 3 x N: the initial conditions handed to Robotarium(...).
  static constexpr const char* kInitialPoses = "dream_initial_poses.npy";
  /// (K + 1) x 3 x N: the recorded pose of every robot at every step.
  static constexpr const char* kReferencePoses = "dream_reference_poses.npy";
  /// K x 2 x N: the velocities (v, w) every robot drove with during step k.
  static constexpr const char* kReferenceCommands = "dream_reference_commands.npy";
  /// Strategy controller: the controller spec (JSON, docs/python-runtime-contract.md)
  /// as uint8 bytes, its `module` the bare file name of the controller module.
  static constexpr const char* kControllerSpec = "dream_controller_spec.npy";
  /// Strategy controller: (K + 1) x M x ObstacleColumns, every virtual obstacle at every step.
  static constexpr const char* kObstacles = "dream_obstacles.npy";
  /// What the script saves: ResultLayout rows.
  static constexpr const char* kResult = "dream_result.npy";
  /// The same array saved from MATLAB (variable kResultMatVariable).
  static constexpr const char* kResultMat = "dream_result.mat";
  static constexpr const char* kResultMatVariable = "dream_result";
};

/// Index of each number in dream_params.npy.
enum ParamIndex : int {
  kParamMagic = 0,
  kParamFormatVersion = 1,
  kParamNumRobots = 2,
  kParamSteps = 3,
  kParamStrategy = 4,
  kParamBarriers = 5,
  kParamSettleMaxSteps = 6,
  kParamSettlePositionTolerance = 7,
  kParamSettleHeadingTolerance = 8,
  kParamSettleGainV = 9,
  kParamSettleGainW = 10,
  kParamGainX = 11,
  kParamGainY = 12,
  kParamGainTheta = 13,
  kParamSaveEverySteps = 14,
  kParamWheelRadius = 15,
  kParamBaseLength = 16,
  kParamMaxWheelSpeed = 17,
  /// Strategy controller: 1 when the run stops once every robot reports done.
  kParamStopWhenDone = 18,
  /// Strategy controller: a command beyond these (or not finite) is refused
  /// and the robot holds still for the step, as the simulator's world does
  /// (config world.max_abs_v_mps / max_abs_w_radps).
  kParamMaxAbsV = 19,
  kParamMaxAbsW = 20,
  /// With barriers: the unicycle certificate's parameters (config `barriers:`),
  /// and whether it keeps the robots inside kParamBoundary* (1: rps's
  /// create_uni_barrier_certificate_with_boundary, 0: create_uni_barrier_certificate).
  kParamBarrierSafetyRadius = 21,
  kParamBarrierGain = 22,
  kParamBarrierProjectionDistance = 23,
  kParamBarrierMagnitudeLimit = 24,
  kParamBarrierHasBoundary = 25,
  kParamBarrierBoundaryXMin = 26,
  kParamBarrierBoundaryXMax = 27,
  kParamBarrierBoundaryYMin = 28,
  kParamBarrierBoundaryYMax = 29,
  kParamCount = 30,
};

/// Format 1 (before the controller strategy) had the first 18 numbers; its
/// exports are still imported.
inline constexpr int kParamCountFormat1 = 18;
/// Format 2 (before the barriers' parameters) had the first 21; its exports
/// are still imported, their barriers rps's defaults.
inline constexpr int kParamCountFormat2 = 21;

/// One obstacle at one step in dream_obstacles.npy, as DREAM_OBSTACLES carries it.
enum ObstacleColumn : int {
  kObstacleId = 0,
  kObstacleCenterX = 1,
  kObstacleCenterY = 2,
  kObstacleWidth = 3,
  kObstacleHeight = 4,
  kObstacleVelocityX = 5,
  kObstacleVelocityY = 6,
  kObstacleColumns = 7,
};

/// "DREA" as a number: dream_params.npy starts with it.
inline constexpr double kParamsMagic = 1146242369.0;
inline constexpr double kFormatVersion = 3.0;
inline constexpr double kStrategyReplay = 0.0;
inline constexpr double kStrategyTrack = 1.0;
inline constexpr double kStrategyController = 2.0;

/// dream_result.npy: rows x (kFixedColumns + 5 N), one row per get_poses():
/// phase, step within the phase, wall-clock time (s, time.time()), then
/// x_0..x_{N-1}, y_*, theta_*, and the command sent at that row v_*, w_*.
struct ResultLayout {
  static constexpr int kPhaseColumn = 0;
  static constexpr int kStepColumn = 1;
  static constexpr int kWallTimeColumn = 2;
  static constexpr int kFixedColumns = 3;
  /// Phases: the script's settle phase, the experiment, the pose after its last step.
  static constexpr double kPhaseSettle = 0.0;
  static constexpr double kPhaseExperiment = 1.0;
  static constexpr double kPhaseFinal = 2.0;

  static constexpr int64_t Columns(int num_robots) { return kFixedColumns + 5 * int64_t{num_robots}; }
  static constexpr int64_t X(int num_robots, int robot) { return kFixedColumns + robot + 0 * int64_t{num_robots}; }
  static constexpr int64_t Y(int num_robots, int robot) { return kFixedColumns + robot + 1 * int64_t{num_robots}; }
  static constexpr int64_t Theta(int num_robots, int robot) { return kFixedColumns + robot + 2 * int64_t{num_robots}; }
  static constexpr int64_t V(int num_robots, int robot) { return kFixedColumns + robot + 3 * int64_t{num_robots}; }
  static constexpr int64_t W(int num_robots, int robot) { return kFixedColumns + robot + 4 * int64_t{num_robots}; }
};

}  // namespace dream::bridge
