#include "dream/calibration/calibration_picture.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "dream/render/xy_plot.h"
#include "dream/world/printf_text.h"

namespace dream::calibration {
namespace {

using render::XyPanel;
using render::XySeries;

XyPanel StepPanel(const std::vector<StepResponseCurve>& curves, const std::string& title) {
  XyPanel panel{title, "time since the command (s)", "distance driven (m)", {}};
  int color = 0;
  for (const StepResponseCurve& curve : curves) {
    XySeries real{
        world::PrintfText("%.2f m/s (%d starts)", curve.speed_mps, curve.events), {}, XySeries::Style::kLine, color};
    XySeries fitted{"", {}, XySeries::Style::kDashedLine, color};
    for (size_t k = 0; k < curve.time_s.size(); ++k) {
      real.points.push_back({curve.time_s[k], curve.real_m[k]});
      fitted.points.push_back({curve.time_s[k], curve.fitted_m[k]});
    }
    panel.series.push_back(std::move(real));
    panel.series.push_back(std::move(fitted));
    ++color;
  }
  if (panel.series.empty())
    panel.series.push_back({"no start from rest in the data", {{0, 0}}, XySeries::Style::kDots, 0});
  return panel;
}

XyPanel TurningPanel(const CalibrationReport& report) {
  XyPanel panel{"Turning: measured against commanded rate", "commanded w (rad/s)", "measured w (rad/s)", {}};
  XySeries dots{"steps of steady turning", report.turning, XySeries::Style::kDots, 0};
  double lo = -1, hi = 1;
  for (const auto& p : report.turning) {
    lo = std::min(lo, p[0]);
    hi = std::max(hi, p[0]);
  }
  const FittedKey* gain = report.Find("angular_gain_mean");
  const FittedKey* drift = report.Find("heading_drift_mean_radps");
  const double g = gain != nullptr ? gain->value : 1.0;
  const double d = drift != nullptr ? drift->value : 0.0;
  panel.series.push_back(std::move(dots));
  // The model turns g w + d while its wheels turn.
  panel.series.push_back({world::PrintfText("fitted: gain %.3f, drift %.4f rad/s", g, d),
                          {{lo, g * lo + d}, {hi, g * hi + d}},
                          XySeries::Style::kLine,
                          1});
  panel.series.push_back({"gain 1", {{lo, lo}, {hi, hi}}, XySeries::Style::kDashedLine, 2});
  return panel;
}

// A histogram of `values` scaled by `scale`, and the Gaussian of deviation
// `sigma` (same scale) with the same count.
void AddHistogram(const std::vector<double>& values, double scale, double sigma, const std::string& label, int color,
                  XyPanel* panel) {
  if (values.empty()) return;
  const double bin = std::max(sigma * scale / 3.0, 1e-9);
  std::map<long, double> counts;
  for (double v : values) counts[std::lround(v * scale / bin)] += 1;
  XySeries bars{label, {}, XySeries::Style::kBars, color};
  for (const auto& [index, count] : counts) {
    if (std::abs(index) <= 15) bars.points.push_back({static_cast<double>(index) * bin, count});
  }
  XySeries curve{"", {}, XySeries::Style::kLine, color};
  const double s = sigma * scale;
  for (int i = -60; i <= 60; ++i) {
    const double x = i * bin / 4.0;
    curve.points.push_back(
        {x, static_cast<double>(values.size()) * bin / (s * std::sqrt(2 * M_PI)) * std::exp(-x * x / (2 * s * s))});
  }
  panel->series.push_back(std::move(bars));
  if (s > 0) panel->series.push_back(std::move(curve));
}

XyPanel NoisePanel(const CalibrationReport& report) {
  XyPanel panel{"Position noise (x) with the fitted Gaussians", "noise (mm)", "measurements (count)", {}};
  const double rest = report.params.pose_noise_m;
  AddHistogram(report.rest_noise_m, 1e3, rest, world::PrintfText("at rest, sigma %.2f mm", rest * 1e3), 0, &panel);
  const double moving = rest * report.params.pose_noise_moving_factor;
  AddHistogram(report.moving_noise_m, 1e3, moving, world::PrintfText("moving, sigma %.2f mm", moving * 1e3), 1, &panel);
  if (panel.series.empty()) panel.series.push_back({"no steady measurements", {{0, 0}}, XySeries::Style::kDots, 0});
  return panel;
}

XyPanel StalePanel(const CalibrationReport& report) {
  XyPanel panel{"Runs of repeated poses", "length (steps)", "runs (count)", {}};
  std::map<int, double> counts;
  for (int length : report.stale_bursts) counts[std::min(length, 40)] += 1;
  XySeries bars{
      world::PrintfText("%zu runs seen (40: 40 or more)", report.stale_bursts.size()), {}, XySeries::Style::kBars, 0};
  for (const auto& [length, count] : counts) bars.points.push_back({static_cast<double>(length), count});
  // Geometric lengths with the fitted mean: P(L = l) = q^(l-1) (1 - q).
  const double mean = std::max(1.0, report.params.tracking_dropout_mean_steps /
                                        std::max(1e-9, 1.0 - report.params.tracking_dropout_probability));
  const double q = 1.0 - 1.0 / mean;
  XySeries model{world::PrintfText("fitted: mean %.1f steps", mean), {}, XySeries::Style::kLine, 1};
  for (int l = 1; l <= 40; ++l) {
    model.points.push_back(
        {static_cast<double>(l), static_cast<double>(report.stale_bursts.size()) * std::pow(q, l - 1) * (1 - q)});
  }
  if (!bars.points.empty()) panel.series.push_back(std::move(bars));
  panel.series.push_back(std::move(model));
  return panel;
}

}  // namespace

void RenderCalibrationPicture(const CalibrationReport& report, const std::string& path, render::RenderFormat format) {
  const std::vector<XyPanel> panels = {
      StepPanel(report.step_responses, "Steps in v from rest: real (solid) and fitted (dashed)"), TurningPanel(report),
      NoisePanel(report), StalePanel(report)};
  std::string title = "dream calibrate: ";
  title += report.sources.size() == 1 ? report.sources.front() : std::to_string(report.sources.size()) + " runs";
  render::XyPlot::Render(panels, 2, title, path, format);
}

void RenderModelCheckPicture(const std::vector<ModelPrediction>& predictions, const std::string& path,
                             render::RenderFormat format) {
  std::string models;
  for (size_t i = 0; i < predictions.size(); ++i) {
    models += (i == 0 ? "" : ", ") + std::to_string(i + 1) + " " + predictions[i].name;
  }
  XyPanel errors{"1 s open-loop prediction error, 95 % interval over robots",
                 "model (" + models + ")",
                 "RMS position error after 1 s (cm)",
                 {}};
  for (size_t i = 0; i < predictions.size(); ++i) {
    const ModelPrediction& p = predictions[i];
    const auto x = static_cast<double>(i + 1);
    errors.series.push_back({p.name, {{x, p.position_error_m * 100}}, XySeries::Style::kDots, static_cast<int>(i)});
    errors.series.push_back({"",
                             {{x, p.position_error_low_m * 100}, {x, p.position_error_high_m * 100}},
                             XySeries::Style::kLine,
                             static_cast<int>(i)});
  }
  std::vector<XyPanel> panels = {errors};
  for (const ModelPrediction& p : predictions) {
    panels.push_back(StepPanel(p.step_responses, "Steps in v from rest: real (solid), " + p.name + " (dashed)"));
  }
  render::XyPlot::Render(panels, 2, "dream calibrate --check", path, format);
}

}  // namespace dream::calibration
