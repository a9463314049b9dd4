#include "dream/calibration/calibration_report.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "dream/world/printf_text.h"

namespace dream::calibration {
namespace {

// The Robotarium's GRITSbot X on open-loop drives from rest (issue 32,
// docs/experiments.md): the effective delay by the maintainers' measure.
struct RealMedian {
  double speed_mps;
  double delay_s;
};
constexpr RealMedian kRealMedians[] = {{0.05, 0.635}, {0.1, 0.419}, {0.2, 0.337}};

std::string Number(double value) { return world::PrintfText("%.6g", value); }

}  // namespace

const FittedKey* CalibrationReport::Find(const std::string& key) const {
  for (const FittedKey& fitted : keys) {
    if (fitted.key == key) return &fitted;
  }
  return nullptr;
}

std::string CalibrationReport::Text() const {
  std::ostringstream out;
  out << "Lab model fitted to " << sources.size() << (sources.size() == 1 ? " run" : " runs") << ", " << robots
      << " robots, " << robot_steps << " robot-steps\n\n";
  size_t width = 0;
  for (const FittedKey& key : keys) width = std::max(width, key.key.size());
  for (const FittedKey& key : keys) {
    std::string interval;
    if (!key.determined) {
      interval = "kept";
    } else if (key.low == key.high && key.key.rfind("pose_quantum", 0) == 0) {
      interval = "exact";
    } else {
      interval = "[" + Number(key.low) + ", " + Number(key.high) + "]";
    }
    out << "  " << key.key << std::string(width - key.key.size() + 2, ' ')
        << world::PrintfText("%-12s", Number(key.value).c_str()) << world::PrintfText("%-28s", interval.c_str())
        << key.support << "\n";
  }
  if (!notes.empty()) {
    out << "\nNotes\n";
    for (const std::string& note : notes) out << "  - " << note << "\n";
  }
  if (!step_responses.empty()) {
    out << "\nSteps in v from rest (effective delay: where the steady line crosses 0; first motion: first step over 3 "
           "mm)\n";
    out << "  speed m/s  starts  delay real  fitted   first motion real  fitted   real robots (open loop)\n";
    for (const StepResponseCurve& curve : step_responses) {
      std::string median = "";
      for (const RealMedian& real : kRealMedians) {
        if (std::abs(curve.speed_mps - real.speed_mps) < 0.2 * real.speed_mps)
          median = world::PrintfText("%.0f ms", real.delay_s * 1e3);
      }
      out << world::PrintfText("  %9.2f  %6d  %7.0f ms  %4.0f ms  %14.1f  %7.1f   %s\n", curve.speed_mps, curve.events,
                               curve.real_delay_s * 1e3, curve.fitted_delay_s * 1e3, curve.real_first_motion_step,
                               curve.fitted_first_motion_step, median.c_str());
    }
  }
  return out.str();
}

std::string CalibrationReport::RealismYaml() const {
  std::ostringstream out;
  out << "# A lab model fitted by dream calibrate (docs/experiments.md, \"Calibrating the lab\").\n";
  out << "# Use it as   world: {realism: {file: THIS_FILE}}   or   --set world.realism.file=THIS_FILE\n";
  out << "# From:";
  for (const std::string& source : sources) out << " " << source;
  out << "\n# " << robots << " robots, " << robot_steps << " robot-steps. Each key: value, then in the comment\n";
  out << "# its 95 % interval and the data behind it, or why it keeps the base preset's value.\n";
  for (const std::string& note : notes) out << "# Note: " << note << "\n";
  for (const FittedKey& key : keys) {
    out << key.key << ": " << world::PrintfText("%.10g", key.value) << "  # ";
    if (key.determined) {
      out << (key.low == key.high && key.key.rfind("pose_quantum", 0) == 0
                  ? std::string("exact")
                  : "[" + Number(key.low) + ", " + Number(key.high) + "]")
          << "; " << key.support;
    } else {
      out << "kept: " << key.support;
    }
    out << "\n";
  }
  return out.str();
}

}  // namespace dream::calibration
