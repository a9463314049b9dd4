#include "dream/bridge/lab_model_check.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "calibration_dynamics.h"
#include "calibration_evidence.h"
#include "calibration_series.h"
#include "dream/world/printf_text.h"

namespace dream::bridge {
namespace {

constexpr size_t kHorizonSteps = 30;  // 1 s of 0.033 s steps
constexpr size_t kEvery = 15;         // a prediction from every 15th pose
constexpr size_t kWarmUp = 60;        // the model's wheels settle on the run's commands first

}  // namespace

std::vector<ModelPrediction> LabModelCheck::Predict(const std::vector<CalibrationRun>& runs,
                                                    const std::vector<NamedModel>& models,
                                                    const files::StopToken& stop) {
  for (const CalibrationRun& run : runs) CheckCalibrationRun(run);
  const std::vector<CalibrationSeries> series = CalibrationSeries::Of(runs);
  std::vector<ModelPrediction> predictions;
  for (const NamedModel& model : models) {
    const world::RealismParams& p = model.params;
    const CalibrationDynamics dynamics(series, p, std::max(p.pose_noise_m, 1e-4), std::max(p.pose_noise_rad, 1e-3),
                                       stop);
    const DynamicsParams dynamics_params{p.pose_delay_steps + p.command_latency_steps, p.motor_lag_s, p.motor_startup_m};
    DynamicsEvaluation gains;
    RobotGains mean_robot;
    mean_robot.linear = p.linear_gain_mean;
    mean_robot.angular = p.angular_gain_mean;
    mean_robot.drift_radps = p.heading_drift_mean_radps;
    gains.gains.assign(series.size(), mean_robot);
    CalibrationReport evidence;
    FillCalibrationEvidence(series, dynamics, dynamics_params, gains, &evidence);
    ModelPrediction prediction;
    prediction.name = model.name;
    prediction.step_responses = std::move(evidence.step_responses);
    double position_sq = 0, heading_sq = 0;
    std::vector<world::UnicycleCommand> driven;
    std::vector<double> motion_s;
    for (const CalibrationSeries& s : series) {
      stop.ThrowIfRequested();
      dynamics.Predict(s, dynamics_params, &driven, &motion_s);
      for (size_t k = kWarmUp; k + kHorizonSteps < s.steps(); k += kEvery) {
        const size_t end = k + kHorizonSteps;
        if (s.stale[k] || s.stale[end] || s.near_late[k] || s.near_late[end]) continue;
        world::Pose2 pose = s.poses[k];
        for (size_t j = k; j < end; ++j) {
          const double v = driven[j].v_mps * p.linear_gain_mean;
          double w = driven[j].w_radps * p.angular_gain_mean;
          if (driven[j].v_mps != 0.0 || driven[j].w_radps != 0.0) w += p.heading_drift_mean_radps;
          pose.x_m += motion_s[j] * v * std::cos(pose.theta_rad);
          pose.y_m += motion_s[j] * v * std::sin(pose.theta_rad);
          pose.theta_rad += motion_s[j] * w;
        }
        const world::Pose2& real = s.poses[end];
        position_sq += std::pow(pose.x_m - real.x_m, 2) + std::pow(pose.y_m - real.y_m, 2);
        heading_sq += std::pow(WrappedAngle(pose.theta_rad - real.theta_rad), 2);
        ++prediction.predictions;
      }
    }
    if (prediction.predictions > 0) {
      prediction.position_error_m = std::sqrt(position_sq / prediction.predictions);
      prediction.heading_error_rad = std::sqrt(heading_sq / prediction.predictions);
    }
    predictions.push_back(std::move(prediction));
  }
  return predictions;
}

std::string LabModelCheck::Table(const CalibrationReport& real, const std::vector<ModelPrediction>& predictions,
                                 const std::vector<NamedModel>& models) {
  std::ostringstream out;
  auto header = [&](const std::string& first) {
    out << "| " << first << " | real |";
    for (const NamedModel& model : models) out << " " << model.name << " |";
    out << "\n|---|---:|";
    for (size_t i = 0; i < models.size(); ++i) out << "---:|";
    out << "\n";
  };
  out << "Steps in v from rest: effective delay (ms) / first step over 3 mm\n\n";
  header("speed (starts)");
  if (!predictions.empty()) {
    for (size_t c = 0; c < predictions.front().step_responses.size(); ++c) {
      const StepResponseCurve& measured = predictions.front().step_responses[c];
      out << world::PrintfText("| %.2f m/s (%d) | %.0f / %.1f |", measured.speed_mps, measured.events,
                             measured.real_delay_s * 1e3, measured.real_first_motion_step);
      for (const ModelPrediction& prediction : predictions) {
        const StepResponseCurve& curve = prediction.step_responses[c];
        out << world::PrintfText(" %.0f / %.1f |", curve.fitted_delay_s * 1e3, curve.fitted_first_motion_step);
      }
      out << "\n";
    }
  }
  out << "\n1 s open-loop prediction from the real poses (RMS error)\n\n";
  header("error");
  out << "| position (cm) | 0 |";
  for (const ModelPrediction& prediction : predictions) out << world::PrintfText(" %.2f |", prediction.position_error_m * 100);
  out << "\n| heading (rad) | 0 |";
  for (const ModelPrediction& prediction : predictions) out << world::PrintfText(" %.3f |", prediction.heading_error_rad);
  out << "\n\nWhat the runs show (a fit of them; kept keys are not shown) against each model\n\n";
  header("key");
  for (const FittedKey& key : real.keys) {
    if (!key.determined) continue;
    out << "| " << key.key << " | " << world::PrintfText("%.4g", key.value) << " |";
    for (const NamedModel& model : models) {
      for (const world::RealismParams::Field& field : world::RealismParams::Fields()) {
        if (key.key != field.key) continue;
        const double value = field.number != nullptr ? model.params.*field.number : model.params.*field.steps;
        out << " " << world::PrintfText("%.4g", value) << " |";
      }
    }
    out << "\n";
  }
  return out.str();
}

}  // namespace dream::bridge
