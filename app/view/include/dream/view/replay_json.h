#pragma once

#include <cstddef>
#include <string>

#include "dream/run_log/run_log.h"
#include "dream/view/metric_timeline.h"
#include "dream/view/view_setup.h"

namespace dream::view {

/// A finished run for the page's timeline (dream view RUN_FOLDER): every
/// step's poses (and measured poses), obstacles, radio senders, radio links
/// when the setup knows who hears whom, and each violation located by the
/// world's checks, with the counts so far at each change. One JSON object,
/// {"type":"run", ...}, served once; the page plays, pauses, steps, scrubs
/// and changes speed on its own, so each browser has its own timeline.
///
/// Robot pose numbers (x, y, theta per robot and step) the replay sends at
/// most: a 15-minute lab run of 20 robots (27,000 steps) fits whole.
inline constexpr size_t kMaxPoseValues = 6'000'000;

/// A run larger than `max_pose_values` numbers keeps every k-th step (the
/// first and the last always), and says so ("stride"); at most
/// kMaxReplayMarks violations are listed (the first ones), the counts stay exact.
/// `metrics`, when given: the run's metrics over time, as "metrics":
/// {"stride", "series": [{"name", "steps", "values", "threshold", "label"}]}.
std::string RunReplayJson(const run_log::RunLog& log, const ViewSetup& setup, size_t max_pose_values = kMaxPoseValues,
                          const MetricTimeline* metrics = nullptr);
/// Violations the replay lists at most.
inline constexpr size_t kMaxReplayMarks = 2000;

}  // namespace dream::view
