#include <csignal>

#include "commands.h"

namespace dream::cli {

std::atomic<bool>& StopFlag() {
  static std::atomic<bool> stop{false};
  return stop;
}

namespace {
extern "C" void OnStopSignal(int) { StopFlag().store(true); }
}  // namespace

void InstallStopSignals() {
  std::signal(SIGINT, OnStopSignal);
  std::signal(SIGTERM, OnStopSignal);
  // A closed terminal or dropped SSH session ends the run as Ctrl-C does,
  // with its log and summary whole, instead of killing it mid-write.
  std::signal(SIGHUP, OnStopSignal);
  // Past a file size limit (ulimit -f) write() then fails with EFBIG, which
  // the recorder handles (the log cut back to its last whole event, the run
  // "failed"), instead of the signal killing the process with a .part file.
  std::signal(SIGXFSZ, SIG_IGN);
}

}  // namespace dream::cli
