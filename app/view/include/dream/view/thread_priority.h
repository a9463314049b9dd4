#pragma once

namespace dream::view {

/// The view is best effort: its threads (the frame pump, the server) run at
/// a lower priority (nice +10) than the run they watch, so on a busy machine
/// the scheduler gives the run's threads the cores first and the view loses
/// frames instead. Quietly does nothing where the system refuses.
void LowerThisThreadsPriority();

/// The same for the calling thread and every thread it starts from then on
/// (on Linux a nice value is per thread, inherited): `dream view`'s main
/// thread, before it starts the others, as it watches runs in other processes.
void LowerThisProcesssPriority();

}  // namespace dream::view
