#include "calibration_evidence.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace dream::calibration {
namespace {

constexpr size_t kRestBefore = 20;       // steps at rest before a start
constexpr size_t kMinHold = 45;          // a start's command holds 1.5 s at least
constexpr size_t kMaxHold = 90;          // and is followed for 3 s at most
constexpr double kFirstMotionM = 0.003;  // "moving": over 3 mm from the start
constexpr size_t kMaxTurningSamples = 3000;

struct Start {
  size_t series = 0;
  size_t step = 0;
  size_t hold = 0;
  double speed = 0;
};

std::vector<Start> StartsFromRest(const std::vector<CalibrationSeries>& series) {
  std::vector<Start> starts;
  for (size_t r = 0; r < series.size(); ++r) {
    const CalibrationSeries& s = series[r];
    if (s.stuck) continue;
    for (size_t e = kRestBefore; e + kMinHold < s.steps(); ++e) {
      const world::UnicycleCommand& c = s.commands[e];
      if (std::abs(c.v_mps) < 0.02 || std::abs(c.w_radps) > 0.05 || !IsRestCommand(s.commands[e - 1])) continue;
      bool rested = true;
      for (size_t j = e - kRestBefore; j < e && rested; ++j) rested = IsRestCommand(s.commands[j]);
      size_t hold = 0;
      while (e + hold < s.steps() && hold < kMaxHold && std::abs(s.commands[e + hold].v_mps - c.v_mps) < 1e-3 &&
             std::abs(s.commands[e + hold].w_radps - c.w_radps) < 1e-2) {
        ++hold;
      }
      if (rested && hold >= kMinHold) starts.push_back({r, e, hold, std::abs(c.v_mps)});
    }
  }
  return starts;
}

size_t FirstMotion(const std::vector<double>& distance) {
  for (size_t k = 0; k < distance.size(); ++k) {
    if (distance[k] > kFirstMotionM) return k;
  }
  return distance.size();
}

}  // namespace

int StartsFromRestAtOrBelow(const std::vector<CalibrationSeries>& series, double max_speed_mps, int* speeds) {
  int slow = 0;
  std::map<long, int> by_speed;
  for (const Start& start : StartsFromRest(series)) {
    ++by_speed[std::lround(start.speed * 100)];
    slow += start.speed <= max_speed_mps + 1e-9 ? 1 : 0;
  }
  *speeds = static_cast<int>(by_speed.size());
  return slow;
}

double EffectiveDelay(const std::vector<double>& distance_m, const std::vector<double>& time_s) {
  const size_t n = distance_m.size();
  const size_t from = std::max<size_t>(n / 2, std::min<size_t>(30, n - 2));
  double st = 0, ss = 0, stt = 0, sts = 0, count = 0;
  for (size_t k = from; k < n; ++k) {
    const double t = time_s[k];
    st += t;
    ss += distance_m[k];
    stt += t * t;
    sts += t * distance_m[k];
    count += 1;
  }
  const double slope = (count * sts - st * ss) / (count * stt - st * st);
  const double intercept = (ss - slope * st) / count;
  return slope != 0.0 ? -intercept / slope : 0.0;
}

void FillCalibrationEvidence(const std::vector<CalibrationSeries>& series, const CalibrationDynamics& dynamics,
                             const DynamicsParams& params, const DynamicsEvaluation& fitted,
                             CalibrationReport* report) {
  std::vector<std::vector<world::UnicycleCommand>> driven(series.size());
  std::vector<std::vector<double>> motion(series.size());
  for (size_t r = 0; r < series.size(); ++r) dynamics.Predict(series[r], params, &driven[r], &motion[r]);

  // Starts grouped by speed (to the centimetre per second).
  std::map<long, std::vector<Start>> by_speed;
  for (const Start& start : StartsFromRest(series)) by_speed[std::lround(start.speed * 100)].push_back(start);
  for (const auto& [centi, starts] : by_speed) {
    size_t length = kMaxHold;
    for (const Start& start : starts) length = std::min(length, start.hold);
    StepResponseCurve curve;
    curve.speed_mps = static_cast<double>(centi) / 100.0;
    curve.events = static_cast<int>(starts.size());
    curve.real_m.assign(length, 0.0);
    curve.fitted_m.assign(length, 0.0);
    curve.time_s.assign(length, 0.0);
    for (const Start& start : starts) {
      const CalibrationSeries& s = series[start.series];
      const world::Pose2& origin = s.poses[start.step];
      const double gain = fitted.gains[start.series].linear;
      const double sign = s.commands[start.step].v_mps < 0 ? -1.0 : 1.0;  // backwards counts forward
      std::vector<double> real(length), model(length);
      double travelled = 0;
      double elapsed = 0;
      for (size_t k = 0; k < length; ++k) {
        // Time on the run's clock (a lab's steps are late now and then).
        curve.time_s[k] += elapsed / static_cast<double>(starts.size());
        if (start.step + k < s.step_s.size()) elapsed += s.step_s[start.step + k];
        const world::Pose2& p = s.poses[start.step + k];
        real[k] = sign * ((p.x_m - origin.x_m) * std::cos(origin.theta_rad) +
                          (p.y_m - origin.y_m) * std::sin(origin.theta_rad));
        model[k] = travelled;
        const size_t at = start.step + k;
        if (at < driven[start.series].size())
          travelled += sign * gain * driven[start.series][at].v_mps * motion[start.series][at];
        curve.real_m[k] += real[k] / static_cast<double>(starts.size());
        curve.fitted_m[k] += model[k] / static_cast<double>(starts.size());
      }
      curve.real_first_motion_step += static_cast<double>(FirstMotion(real)) / static_cast<double>(starts.size());
      curve.fitted_first_motion_step += static_cast<double>(FirstMotion(model)) / static_cast<double>(starts.size());
    }
    curve.real_delay_s = EffectiveDelay(curve.real_m, curve.time_s);
    curve.fitted_delay_s = EffectiveDelay(curve.fitted_m, curve.time_s);
    report->step_responses.push_back(std::move(curve));
  }

  // Steady turning: the commanded rate (as delayed) against the measured one.
  size_t candidates = 0;
  for (const CalibrationSeries& s : series) candidates += s.steps();
  const size_t stride = std::max<size_t>(1, candidates / (kMaxTurningSamples * 4));
  for (const CalibrationSeries& s : series) {
    for (size_t k = 30; k + 1 < s.steps(); k += stride) {
      if (s.stale[k] || s.stale[k + 1] || s.near_late[k] || k < static_cast<size_t>(params.delay_steps) + 25) continue;
      const size_t sent = k - static_cast<size_t>(params.delay_steps);
      const double w = s.commands[sent].w_radps;
      if (std::abs(w) < 0.2 || std::abs(s.commands[sent - 25].w_radps - w) > 1e-2) continue;
      const double measured =
          WrappedAngle(s.poses[k + 1].theta_rad - s.poses[k].theta_rad) / std::max(s.step_s[k], 1e-3);
      if (report->turning.size() < kMaxTurningSamples) report->turning.push_back({w, measured});
    }
  }
}

}  // namespace dream::calibration
