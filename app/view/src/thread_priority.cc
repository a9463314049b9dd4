#include "dream/view/thread_priority.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

namespace dream::view {
namespace {
constexpr int kNiceIncrement = 10;
}

void LowerThisThreadsPriority() {
  // On Linux a thread has its own nice value, set through its thread id.
  const auto thread_id = static_cast<id_t>(::syscall(SYS_gettid));
  const int now = ::getpriority(PRIO_PROCESS, thread_id);
  (void)::setpriority(PRIO_PROCESS, thread_id, now + kNiceIncrement);
}

void LowerThisProcesssPriority() { (void)::nice(kNiceIncrement); }

}  // namespace dream::view
