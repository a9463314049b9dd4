#pragma once

#include <string>
#include <vector>

#include "dream/robotarium/robotarium_constants.h"

namespace dream::world {

// How far the simulated world departs from the official (ideal) simulator
// towards the real lab: what the tracker measures and what the GTernal
// firmware does with a command. `world.realism` in a run config
// (docs/experiments.md lists each lab value and its source). Ideal() is the
// official simulator: a run whose params equal it gets no RealisticWorld at
// all, so it stays the official simulator step for step.
struct RealismParams {
  // Tracker (Vicon over MQTT). Gaussian noise, standard deviations, of a
  // robot at rest; a moving robot's noise is pose_noise_moving_factor times it.
  double pose_noise_m = 0.0;
  double pose_noise_rad = 0.0;
  double pose_noise_moving_factor = 1.0;
  // Measured x, y (theta) rounded to a multiple of this; 0 = not rounded.
  double pose_quantum_m = 0.0;
  double pose_quantum_rad = 0.0;
  // Agents are sent the poses of step k - pose_delay_steps at step k.
  int pose_delay_steps = 0;
  // Chance per robot and step that a dropout starts: the tracker reports
  // nothing new, and the robot's last measured pose is sent again.
  double tracking_dropout_probability = 0.0;
  // A robot at rest starts dropouts this many times as often (the lab's
  // repeated poses are mostly of robots at rest); the result is capped at 1.
  double tracking_dropout_at_rest_factor = 1.0;
  // Dropouts come in bursts of this many steps on average (geometric: a
  // dropped robot stays dropped the next step with probability 1 - 1/this,
  // or when a new dropout starts); 1 = each step on its own.
  double tracking_dropout_mean_steps = 1.0;
  // A robot with no new measurement for longer than this (simulated time) is
  // dropped by the tracker and stays untracked for the rest of the run: its
  // agents are sent its last measured pose; 0 = never.
  double tracker_drop_s = 0.0;

  // Robot. A command answering step k reaches the robot at step k + latency.
  int command_latency_steps = 0;
  // A robot whose newest command reached it longer ago than this (simulated
  // time) brakes to a stop; 0 = never. The official world has the same 0.5 s.
  double command_brake_s = robotarium::RobotariumConstants::kCommandTimeoutSeconds;
  // The firmware coasts the motors when |v| < dead_zone_v_mps and
  // |w| < dead_zone_w_radps; 0, 0 = no dead zone.
  double dead_zone_v_mps = 0.0;
  double dead_zone_w_radps = 0.0;
  // Each wheel's speed changes by at most this per second; 0 = at once.
  double wheel_accel_limit_radps2 = 0.0;
  // Each wheel follows its target speed with a first-order lag of this time
  // constant; 0 = at once (then wheel_accel_limit_radps2 applies).
  double motor_lag_s = 0.0;
  // A wheel speeding up towards a target rim speed u (m/s) lags by
  // motor_lag_s + motor_startup_m / |u| instead: the wheel's PID winds up
  // against static friction, so slow commands start later. 0 = no extra.
  double motor_startup_m = 0.0;
  // Per robot, drawn once from the seed (Gaussian, mean and spread = standard
  // deviation): the linear and angular speed the robot drives per unit
  // commanded (wheel radii, axle and tyres differ), and a heading drift
  // (rad/s, counter-clockwise) added while its wheels turn.
  double linear_gain_mean = 1.0;
  double linear_gain_spread = 0.0;
  double angular_gain_mean = 1.0;
  double angular_gain_spread = 0.0;
  double heading_drift_mean_radps = 0.0;
  double heading_drift_spread_radps = 0.0;

  // The experiment script's loop. Each step lasts the time step plus an
  // exponentially distributed overrun of this mean (s); 0 = exactly on time.
  double step_overrun_mean_s = 0.0;
  // Chance per step that the loop stalls, for a time drawn uniformly from
  // [kMinStallS, loop_stall_max_s] (kMinStallS when the maximum is below it):
  // the robots keep driving on their last wheel speeds until their brake
  // (command_brake_s). 0 = never.
  double loop_stall_probability = 0.0;
  double loop_stall_max_s = 0.0;
  // The robot's axle length: the firmware's conversion to wheel speeds and the
  // wheel saturation use it. (The Robotarium's checks keep the official one.)
  double axle_length_m = robotarium::RobotariumConstants::kBaseLengthMeters;

  // One field by its config key (world.realism.<key>, summary.json's realism.<key>):
  // a number, or a step count in 0..kMaxDelaySteps. Exactly one of number and
  // steps is set; a number's rule is `allows`, in words `allowed`.
  struct Field {
    const char* key;
    double RealismParams::*number;
    int RealismParams::*steps;
    bool (*allows)(double value);
    const char* allowed;
  };
  // Every field above, in the order above, with its rule: the one list the
  // config reader, IsValid, summary.json and operator== go through, so a new
  // model is added here once.
  static const std::vector<Field>& Fields();

  static RealismParams Ideal();
  static RealismParams Lab();
  // `lab_v1`: the lab preset before it was fitted to real runs (estimates:
  // 1 + 1 steps of delay, 100 rad/s^2 wheels), kept for comparison.
  static RealismParams LabV1();
  // The preset called `name` into *params; false when there is none.
  static bool FromPreset(const std::string& name, RealismParams* params);
  static const std::vector<std::string>& PresetNames();

  // Equal to Ideal(): the run uses the official world, no RealisticWorld.
  bool IsIdeal() const;
  // Checks every field; on failure writes a message naming the field, its
  // value and the allowed range into *error (if error is not null).
  bool IsValid(std::string* error) const;

  // Bounds on the step counts (10 s of 0.033 s steps), so a typo cannot make
  // the history buffers huge.
  static constexpr int kMaxDelaySteps = 300;
  // Bounds that keep a drawn gain physical and a stall shorter than a run
  // could ever wait for.
  static constexpr double kMinGain = 0.5;
  static constexpr double kMaxGain = 1.5;
  static constexpr double kMaxStallS = 10.0;
  static constexpr double kMinStallS = 2 * robotarium::RobotariumConstants::kTimeStepSeconds;
};

bool operator==(const RealismParams& a, const RealismParams& b);
inline bool operator!=(const RealismParams& a, const RealismParams& b) { return !(a == b); }

}  // namespace dream::world
