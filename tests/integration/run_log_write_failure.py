#!/usr/bin/python3
"""run_log_write_failure: a run whose log cannot be written stops cleanly, never truncated.

Runs `dream run config/go_to_goal.yaml` under `ulimit -f` (dream ignores SIGXFSZ itself; a shell
or Python's subprocess leaves it at its default, which would kill the process), so the kernel
refuses the run log's writes with EFBIG partway through the run (a full disk, reproducibly), and
requires: exit 4 (a run that did not finish), summary.json with end "failed" and a reason naming
the log and the error, a run.lcmlog that python/dream_log.py reads to its last event and `dream log
info` accepts, holding exactly the events the summary counts, and no .part or .tmp files left.

Then a summary.json that cannot be written (a folder is in its way) gives one line naming it and
exit 4, never a crash.

Usage: run_log_write_failure.py --dream BIN --source DIR
"""

import os

from dreamtest import LogFormatError, arguments, check, main, read_events, read_summary, tail

LIMIT_KB = 64  # ulimit -f counts 1024-byte blocks; a whole go_to_goal run log is several times this


def check_limited_run(ctx, args):
    config = os.path.join(args.source, "config", "go_to_goal.yaml")
    out = ctx.path("limited")
    # As a user would see it in a shell: `ulimit -f`, SIGXFSZ at its default (it kills a process
    # that does not ignore it).
    shell = f'ulimit -f {LIMIT_KB} && trap - XFSZ && exec "$0" "$@"'
    code, text = ctx.run(["bash", "-c", shell, args.dream, "run", config, "--out", out], timeout=60)
    check(code == 4, f"dream run with a {LIMIT_KB} kB file size limit exited {code}, expected 4: {tail(text)}")
    check("File too large" in text and "run.lcmlog" in text,
          f"dream run did not say that writing the log failed: {tail(text)}")

    summary = read_summary(out)
    check(summary["end"] == "failed", f"summary end is {summary['end']!r}, expected 'failed'")
    reason = summary["reason"]
    check("run.lcmlog" in reason and "File too large" in reason and f"at step {summary['steps']}" in reason,
          f"summary reason does not name the log, the step and the error: {reason!r}")
    check(0 < summary["steps"] < summary["max_steps"], f"summary steps {summary['steps']}: the run did not stop early")
    check(summary["handler_failures"] == 0, f"handler_failures {summary['handler_failures']}, expected 0")

    log = os.path.join(out, "run.lcmlog")
    try:
        events = list(read_events(log))
    except LogFormatError as error:
        check(False, f"the Python reader refuses the log of the failed run: {error}")
    check(len(events) == summary["log_events"],
          f"the log holds {len(events)} events, the summary counts {summary['log_events']}")
    check(sum(28 + len(e.channel) + len(e.data) for e in events) == os.path.getsize(log),
          "the log has bytes after its last whole event")
    check(os.path.getsize(log) <= LIMIT_KB * 1024, f"the log is larger than the {LIMIT_KB} kB limit")
    check(any(e.channel == "DREAM_POSES" for e in events), "the log holds no DREAM_POSES")
    code, text = ctx.run([args.dream, "log", "info", log])
    check(code == 0, f"dream log info refuses the log of the failed run: {tail(text)}")

    leftovers = [name for name in os.listdir(out) if name.endswith(".part") or ".tmp" in name]
    check(not leftovers, f"left behind in the run folder: {leftovers}")
    return f"stopped at step {summary['steps']} of {summary['max_steps']}; the log keeps {len(events)} whole events"


def check_unwritable_summary(ctx, args):
    config = os.path.join(args.source, "config", "go_to_goal.yaml")
    out = ctx.path("blocked")
    os.makedirs(os.path.join(out, "summary.json"))
    code, text = ctx.run([args.dream, "-q", "run", config, "--out", out, "--steps", "20"], timeout=60)
    check(code == 4, f"dream run with summary.json blocked exited {code}, expected 4: {tail(text)}")
    lines = [line for line in text.strip().splitlines() if "summary.json" in line]
    check(len(lines) == 1 and "cannot write" in lines[0], f"expected one line naming summary.json: {tail(text)}")
    check(os.path.isfile(os.path.join(out, "run.lcmlog")), "the run log is missing when only the summary failed")
    leftovers = [name for name in os.listdir(out) if name.endswith(".part") or ".tmp" in name]
    check(not leftovers, f"left behind in the run folder: {leftovers}")
    return "an unwritable summary.json: one line, exit 4"


def test(ctx):
    args = arguments()
    print(check_limited_run(ctx, args))
    print(check_unwritable_summary(ctx, args))


if __name__ == "__main__":
    main(test)
