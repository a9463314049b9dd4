#pragma once

namespace dream::session {

/// Exit codes scripts can rely on, one list for every command that runs or
/// judges a run (run, sim, launch, check-submission, import, lab-replay, view,
/// sweep; also in `dream --help`). Header only and free of the simulator, so
/// dream-agent's processes use the same list without linking this library;
/// what a run's verdict and end give is run_exit_code.h.
enum ExitCode : int {
  kExitOk = 0,             ///< the run finished; the Robotarium would accept it
  kExitInputError = 1,     ///< bad config, file or argument; nothing was run
  kExitUsage = 2,          ///< unknown subcommand or option
  kExitRejected = 3,       ///< the run finished but has hard errors (the Robotarium would reject it)
  kExitRunFailed = 4,      ///< the run did not finish (agents missing, lost world, I/O error) or a controller failed
  kExitNotReady = 5,       ///< the run finished and the lab's checks pass, but it is not ready: robots lost, command
                           ///< conflicts, bad messages, its goal missed (summary.json verdict_reasons)
  kExitInterrupted = 130,  ///< Ctrl-C / SIGTERM; outputs are complete up to the interruption
};

}  // namespace dream::session
