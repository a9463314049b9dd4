#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "dream/agents/hrvo/hrvo_robot.h"
#include "dream/agents/fields/field_rule.h"
#include "dream/agents/geometry/reversible_si_to_uni.h"
#include "dream/robotarium/robotarium_constants.h"

namespace dream::affine_formation {

/// Parameters of AffineFollowerRobot.
struct AffineFollowerParams {
  enum class Law {
    /// Zhao 2018's normalised law with velocity feed-forward (the default):
    ///   dp_i = (1/gamma_i) sum_j w_ij (dp_j - gain (p_i - p_j)),  gamma_i = sum_j w_ij,
    /// with dp_j the velocity neighbour j's law asks for (its radio reports
    /// it) and p_j aged by it. At the target a follower moves exactly with
    /// the formation, and with instant exchange the stress residual decays
    /// at rate `gain`. Over a radio the dp_j are a step old, which closes a
    /// loop through the neighbours (spectral radius 0.93 for the thesis's
    /// weights): keep gain near 1 (measured on the Robotarium world: fine
    /// at 0.7-1.5, poor at 2; limit cycles from about 3 in a plain loop).
    kZhao,
    /// The thesis's eq. 3.9, dp_i = -gain sum_j w_ij (p_i - p_j): positions
    /// only, so it lags behind moving leaders, and with the thesis's weights
    /// its slowest mode decays at 0.024 gain.
    kThesis,
  };
  Law law = Law::kZhao;
  /// (j, w_ij) for every neighbour: this robot's row of the stress weights.
  std::vector<std::pair<int, double>> neighbours;
  double gain = 1.0;           ///< 1/s; > 0
  double max_speed_mps = 0.2;  ///< cap on the planar velocity; (0, 0.2]
  /// One step, s; used to age neighbours' positions; > 0.
  double time_step_s = robotarium::RobotariumConstants::kTimeStepSeconds;
  /// HRVO only considers a sensed robot that is closer than this, m (> 0),
  /// or that the law's velocity would bring within the safety radius inside
  /// hrvo_horizon_s. The others are the formation's own neighbours holding
  /// their spacing, and avoiding them would fight the formation (plain HRVO
  /// has no time horizon: at 0.3 m it forbids any approach, however slow).
  double hrvo_engage_distance_m = 0.27;
  double hrvo_horizon_s = 1.5;  ///< >= 0
  /// Drive with ReversibleSiToUni (default: a formation that squeezes and
  /// recovers keeps reversing direction) or the thesis's dxi_to_dxu.
  bool reversible_drive = true;
  /// A neighbour's state older than this many steps is too stale to use:
  /// the robot holds still until it hears again. >= 1.
  int max_message_age_steps = 30;

  /// False with a message naming the field, its value and the allowed range.
  bool IsValid(std::string* error) const;

  /// The config keys of `follower:` (kind affine_formation).
  template <typename Fields>
  void ListFields(Fields& fields) {
    fields.Choice("law", law, {{"zhao", Law::kZhao}, {"thesis", Law::kThesis}},
                  "follower law: `zhao` (normalised, the neighbours' velocities fed forward) or `thesis` (eq. 3.9, "
                  "positions only)");
    fields.Number("gain", gain, agents::FieldRule::Positive(),
                  "law gain (`zhao`: keep near 1; `thesis`: needs ~10 or more), 1/s");
    fields.Number("max_speed_mps", max_speed_mps, agents::FieldRule::RobotSpeed(), "cap on the law's velocity, m/s");
    fields.Number("hrvo_engage_distance_m", hrvo_engage_distance_m, agents::FieldRule::PositiveOrInfinite(),
                  "HRVO considers robots closer than this, m ...");
    fields.Number("hrvo_horizon_s", hrvo_horizon_s, agents::FieldRule::NonNegative(),
                  "... or that the law's velocity would bring within the safety radius in this time, s");
    fields.Whole("max_message_age_steps", max_message_age_steps, agents::FieldRule::AtLeast(1),
                 "older neighbour news is not used (the follower only avoids collisions), steps");
  }
};

/// A follower of the affine formation (thesis section 3.4, Zhao 2018): it
/// hears its graph neighbours' positions and velocities on the follower
/// radio, runs the stress-based law on them and its own odometry, and drives
/// the result through HRVO (the thesis's followers inherit Robot_hrvo), then
/// ReversibleSiToUni (or the thesis's dxi_to_dxu) and the actuator limits.
/// The law is integrated by the world one robot period at a time: forward
/// Euler with the step. Its radio reports its position and the velocity its
/// law asks for at that step, computed from what it has just heard.
///
/// Until it has heard every neighbour (and while any neighbour's last word is
/// older than max_message_age_steps) the law has no input: the robot only
/// avoids collisions. Malformed payloads are counted and dropped.
class AffineFollowerRobot final : public agents::HrvoRobot {
 public:
  /// @throws std::invalid_argument when params are invalid.
  AffineFollowerRobot(int id, const agents::RobotParams& robot_params, const agents::HrvoRobotParams& hrvo,
                      const AffineFollowerParams& params);

  void OnOdometry(const agents::OdometryReading& reading) override;
  /// Kept until Update, which hands HRVO the robots that matter (see
  /// hrvo_engage_distance_m).
  void OnMovement(const agents::MovementReading& reading) override;
  std::optional<std::vector<uint8_t>> OnRadio(const std::vector<agents::RadioMessage>& heard) override;
  agents::UnicycleCommand Update(int64_t step) override;

  /// The law's velocity at the last update, before collision avoidance.
  const Eigen::Vector2d& preferred_velocity_mps() const { return preferred_mps_; }
  /// The velocity commanded at the last update (after HRVO).
  const Eigen::Vector2d& commanded_velocity_mps() const { return dxi(); }
  /// How many sensed robots HRVO considered at the last update.
  int hrvo_engaged() const { return hrvo_engaged_; }
  /// True once every neighbour has been heard.
  bool knows_all_neighbours() const;

 private:
  struct Neighbour {
    int id = 0;
    double weight = 0.0;
    bool known = false;
    int64_t last_heard_step = -1;  // newest message seen, valid or not
    int64_t sent_step = 0;         // of the state below
    Eigen::Vector2d position_m = Eigen::Vector2d::Zero();
    Eigen::Vector2d velocity_mps = Eigen::Vector2d::Zero();
  };

  /// The law's velocity (capped at max speed), or nothing when some
  /// neighbour is unknown or stale.
  std::optional<Eigen::Vector2d> LawVelocity(int64_t step) const;

  AffineFollowerParams params_;
  double gamma_ = 0.0;
  std::vector<Neighbour> neighbours_;
  Eigen::Vector2d preferred_mps_ = Eigen::Vector2d::Zero();
  int64_t odometry_step_ = 0;
  double safety_radius_m_;
  agents::ReversibleSiToUni drive_;
  agents::MovementReading sensed_;  // the movement sensor's latest, unfiltered
  int hrvo_engaged_ = 0;
};

}  // namespace dream::affine_formation
