#pragma once

#include <cstdint>
#include <string>

namespace dream::node {

/// Appends one event to a finished LCM log (a run's run.lcmlog, after its
/// recorder closed it): what the run's log gets once summary.json is written,
/// the run's DREAM_VERDICT. The event is written whole or not at all: on a
/// short write the file is cut back to its size before, so the log stays a
/// log of whole events. `event_number` is the event's number in the log (the
/// events already in it, as RunRecorder counted them).
/// @throws std::runtime_error naming the file and the OS error when the log
/// is missing, no regular file, or the disk refuses the event.
void AppendLogEvent(const std::string& path, int64_t event_number, const std::string& channel, int64_t utime,
                    const void* data, int size);

/// Replaces the last event of a finished LCM log, which must be on `channel`,
/// by one on `channel` carrying `data` (same event number): a run's
/// DREAM_VERDICT once summary.json's verdict changed after the world appended
/// it (dream launch's agents' reports). The log is copied beside itself with
/// the new event and renamed over, so a reader sees the old log or the new one.
/// @throws std::runtime_error naming the file when it cannot be read or
/// written, or its last event is on another channel (nothing is changed then).
void ReplaceLastLogEvent(const std::string& path, const std::string& channel, int64_t utime, const void* data,
                         int size);

}  // namespace dream::node
