#pragma once

#include "dream/node/run_outcome.h"
#include "dream/session/exit_code.h"
#include "dream/session/run_result.h"
#include "dream/world/run_judgement.h"
#include "dream/world/run_verdict.h"

namespace dream::session {

/// The one judge's exit code of a verdict, for a run that finished: clean and
/// warning 0, not_ready 5, rejected 3.
ExitCode ExitCodeOf(world::RunVerdict verdict);

/// A run's exit code from how it ended and its verdict: interrupted 130, not
/// finished or a controller failed 4, else ExitCodeOf(verdict). A run that
/// failed logs why, unless `log_failure` is false (the code asked again).
ExitCode ExitCodeOf(const node::RunOutcome& outcome, const world::RunJudgement& judgement, bool log_failure = true);

/// As above, and 4 when summary.json or a due picture could not be written.
ExitCode ExitCodeOf(const RunResult& result, bool log_failure = true);

/// Whether `code` says the run finished and was judged (0, 3 or 5), so its
/// summary.json holds its verdict; any other code says it did not run to a
/// verdict (1 input, 4 failed, 130 interrupted, above 128 a signal).
bool RanToAVerdict(int code);

}  // namespace dream::session
