#include "dream/calibration/lab_model_check.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "calibration_dynamics.h"
#include "calibration_evidence.h"
#include "calibration_series.h"
#include "dream/world/printf_text.h"

namespace dream::calibration {
namespace {

constexpr size_t kHorizonSteps = 30;  // 1 s of 0.033 s steps
constexpr size_t kEvery = 15;         // a prediction from every 15th pose
constexpr size_t kWarmUp = 60;        // the model's wheels settle on the run's commands first

constexpr int kResamples = 1000;

// The RMS error's 95 % interval over robots: resample the robots (with all
// their start points) with replacement. The same seed for every model, so
// their resamples match.
void RobotBootstrap(const std::vector<double>& robot_sq, const std::vector<double>& robot_count,
                    ModelPrediction* prediction) {
  std::vector<size_t> robots;
  for (size_t r = 0; r < robot_count.size(); ++r) {
    if (robot_count[r] > 0) robots.push_back(r);
  }
  prediction->robots = static_cast<int>(robots.size());
  prediction->position_error_low_m = prediction->position_error_high_m = prediction->position_error_m;
  if (robots.size() < 2) return;
  std::mt19937_64 random(20260322);
  std::uniform_int_distribution<size_t> pick(0, robots.size() - 1);
  std::vector<double> rms;
  for (int b = 0; b < kResamples; ++b) {
    double sq = 0, count = 0;
    for (size_t i = 0; i < robots.size(); ++i) {
      const size_t r = robots[pick(random)];
      sq += robot_sq[r];
      count += robot_count[r];
    }
    rms.push_back(std::sqrt(sq / count));
  }
  std::sort(rms.begin(), rms.end());
  prediction->position_error_low_m = rms[static_cast<size_t>(0.025 * kResamples)];
  prediction->position_error_high_m = rms[static_cast<size_t>(0.975 * kResamples) - 1];
}

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
    const DynamicsParams dynamics_params{p.pose_delay_steps + p.command_latency_steps, p.motor_lag_s,
                                         p.motor_startup_m};
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
    std::vector<double> robot_sq(series.size(), 0.0);
    std::vector<double> robot_count(series.size(), 0.0);
    std::vector<world::UnicycleCommand> driven;
    std::vector<double> motion_s;
    for (size_t r = 0; r < series.size(); ++r) {
      const CalibrationSeries& s = series[r];
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
        const double sq = std::pow(pose.x_m - real.x_m, 2) + std::pow(pose.y_m - real.y_m, 2);
        position_sq += sq;
        robot_sq[r] += sq;
        robot_count[r] += 1;
        heading_sq += std::pow(WrappedAngle(pose.theta_rad - real.theta_rad), 2);
        ++prediction.predictions;
      }
    }
    if (prediction.predictions > 0) {
      prediction.position_error_m = std::sqrt(position_sq / prediction.predictions);
      prediction.heading_error_rad = std::sqrt(heading_sq / prediction.predictions);
      RobotBootstrap(robot_sq, robot_count, &prediction);
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
  out << "\n1 s open-loop prediction from the real poses (RMS error; 95 % interval over robots and start points)\n\n";
  header("error");
  out << "| position (cm) | 0 |";
  for (const ModelPrediction& prediction : predictions) {
    out << world::PrintfText(" %.2f [%.2f, %.2f] |", prediction.position_error_m * 100,
                             prediction.position_error_low_m * 100, prediction.position_error_high_m * 100);
  }
  out << "\n| heading (rad) | 0 |";
  for (const ModelPrediction& prediction : predictions)
    out << world::PrintfText(" %.3f |", prediction.heading_error_rad);
  out << "\n\n" << Ranking(predictions);
  out << "\nSteady turning seen (measured / commanded rate, median of the steady turning steps) against each model's "
         "(angular gain + drift / w at the same median |w|)\n\n";
  header("turning");
  std::vector<double> ratios, rates;
  for (const auto& [w, measured] : real.turning) {
    ratios.push_back(measured / w);
    rates.push_back(std::abs(w));
  }
  auto median = [](std::vector<double> values) {
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2), values.end());
    return values[values.size() / 2];
  };
  if (ratios.empty()) {
    out << "| (no steady turning in the runs) | - |";
    for (size_t i = 0; i < models.size(); ++i) out << " - |";
  } else {
    const double w = median(rates);
    out << world::PrintfText("| at |w| %.2f rad/s (%zu steps) | %.3f |", w, ratios.size(), median(ratios));
    for (const NamedModel& model : models) {
      out << world::PrintfText(" %.3f |", model.params.angular_gain_mean + model.params.heading_drift_mean_radps / w);
    }
  }
  out << "\n\nWhat the runs show (a fit of them) against each model; a key the runs cannot pin is marked so\n\n";
  header("key");
  for (const FittedKey& key : real.keys) {
    const bool turning = key.key.rfind("angular_gain", 0) == 0 || key.key.rfind("heading_drift", 0) == 0;
    if (!key.determined && !turning) continue;
    out << "| " << key.key << " | "
        << (key.determined ? world::PrintfText("%.4g", key.value) : std::string("not pinned: ") + key.support) << " |";
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

std::string LabModelCheck::Ranking(const std::vector<ModelPrediction>& predictions) {
  std::string ranked, overlapping;
  for (size_t a = 0; a < predictions.size(); ++a) {
    for (size_t b = a + 1; b < predictions.size(); ++b) {
      const ModelPrediction& p = predictions[a];
      const ModelPrediction& q = predictions[b];
      if (p.predictions == 0 || q.predictions == 0) continue;
      if (p.position_error_high_m < q.position_error_low_m) {
        ranked += "  " + p.name + " predicts better than " + q.name + "\n";
      } else if (q.position_error_high_m < p.position_error_low_m) {
        ranked += "  " + q.name + " predicts better than " + p.name + "\n";
      } else {
        overlapping += (overlapping.empty() ? "" : ", ") + p.name + " / " + q.name;
      }
    }
  }
  std::string text = "Ranking by the 1 s position error, only where the intervals separate:\n";
  text += ranked.empty() ? "  (none: every interval overlaps another)\n" : ranked;
  if (!overlapping.empty()) text += "  not ranked (intervals overlap): " + overlapping + "\n";
  return text;
}

}  // namespace dream::calibration
