#include "parallel_runner.h"

#include <signal.h>

#include <chrono>
#include <optional>
#include <stdexcept>
#include <thread>

#include "dream/process/process_group.h"

namespace dream::cli {
namespace {

using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point start, Clock::time_point now) {
  return std::chrono::duration<double>(now - start).count();
}

struct Running {
  size_t index = 0;
  pid_t pid = 0;
  Clock::time_point started;
  std::optional<Clock::time_point> interrupted_at;
  bool timed_out = false;
  bool killed = false;
};

}  // namespace

ParallelRunner::ParallelRunner(int max_parallel, double timeout_s, double grace_s)
    : max_parallel_(max_parallel), timeout_s_(timeout_s), grace_s_(grace_s) {
  if (max_parallel < 1) throw std::invalid_argument("at least one job must run at a time");
  if (!(timeout_s > 0.0) || !(grace_s > 0.0)) throw std::invalid_argument("timeouts must be > 0");
}

bool ParallelRunner::Run(size_t count, const std::atomic<bool>& stop, const PrepareFn& prepare,
                         const FinishedFn& finished) {
  process::ProcessGroup children;  // whatever is left when this returns or throws gets SIGTERM
  std::vector<Running> running;
  size_t next = 0;
  bool stopping = false;
  while (true) {
    if (stop.load() && !stopping) {
      stopping = true;
      for (Running& job : running) {
        ::kill(job.pid, SIGINT);
        job.interrupted_at = Clock::now();
      }
    }
    while (!stopping && running.size() < static_cast<size_t>(max_parallel_) && next < count) {
      const size_t index = next++;
      Running job;
      job.index = index;
      job.started = Clock::now();
      try {
        const Job what = prepare(index);
        job.pid = children.Start(what.argv, what.output_path);
      } catch (const std::exception& e) {
        Finished failed;
        failed.index = index;
        failed.start_error = e.what();
        finished(failed);
        continue;
      }
      running.push_back(job);
    }
    if (running.empty() && (stopping || next >= count)) return !stopping;

    const Clock::time_point now = Clock::now();
    for (auto it = running.begin(); it != running.end();) {
      const int code = children.TryWait(it->pid);
      if (code >= 0) {
        Finished done;
        done.index = it->index;
        done.exit_code = code;
        done.timed_out = it->timed_out;
        done.wall_time_s = SecondsSince(it->started, now);
        it = running.erase(it);
        finished(done);
        continue;
      }
      if (!it->interrupted_at && SecondsSince(it->started, now) > timeout_s_) {
        ::kill(it->pid, SIGINT);
        it->interrupted_at = now;
        it->timed_out = true;
      } else if (it->interrupted_at && !it->killed && SecondsSince(*it->interrupted_at, now) > grace_s_) {
        ::kill(it->pid, SIGKILL);
        it->killed = true;
      }
      ++it;
    }
    // Runs take tenths of a second at least; a 5 ms poll costs nothing and
    // needs no SIGCHLD handling.
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

}  // namespace dream::cli
