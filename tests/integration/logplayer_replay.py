#!/usr/bin/python3
"""logplayer_replay: LCM's own tools carry a dream run log without loss.

Makes a run log (dream run), starts lcm-logger on udpm in a private network namespace, waits until
it records (a probe message shows up in its file), plays the run log with lcm-logplayer at 2x,
stops the logger with SIGINT, and requires the captured log to hold every DREAM_* message of the
original, in order (dream log diff --channels 'DREAM_.*'; the capture also holds the probe and
udpm's LCM_SELF_TEST, which are not part of the run).

Usage: netns.sh logplayer_replay.py --dream BIN --source DIR [--log RUN.lcmlog] [--speed S]
(--log plays that log instead of a fresh run; the bridge test passes a log imported from the lab.)
"""

import os

from dreamtest import argument_parser, check, main, read_all, require_private_netns, start_lcm_logger, stop_lcm_logger


def test(ctx):
    parser = argument_parser()
    parser.add_argument("--log", default="", help="play this run log instead of making one")
    parser.add_argument("--speed", default="1", help="lcm-logplayer -s (default 1)")
    args = parser.parse_args()
    require_private_netns()
    url = os.environ["LCM_DEFAULT_URL"]

    if args.log:
        original = os.path.abspath(args.log)
    else:
        run = ctx.path("run")
        ctx.run([args.dream, "-q", "run", os.path.join(args.source, "config", "go_to_goal.yaml"), "--out", run],
                expect=0)
        original = os.path.join(run, "run.lcmlog")
    captured = ctx.path("captured.lcmlog")

    # lcm-logger must not lose a burst while it waits for a CPU (ctest -j on 2 cores): it gets 4 MB.
    start_lcm_logger(ctx, "logger", captured)

    # Real time (1x), as a user replays: lcm-logger 1.3.1 keeps LCM's default 30-message
    # subscription queue and silently drops a step's burst of 11 messages when it misses a few ms
    # of CPU (seen at 20x with ctest -j on 2 cores, at 5x beside another CPU-bound program, and
    # once at 2x in a fresh-clone CI on an otherwise idle 2-core machine); at 1x it tolerates
    # ~66 ms stalls.
    ctx.start("player", ["lcm-logplayer", "-s", args.speed, "--lcm-url=" + url, original])
    # The player takes the log's span over the speed; the rest of the bound only turns a hang into a failure.
    stamps = [event.utime for event in read_all(original)]
    playing_s = (max(stamps) - min(stamps)) / 1e6 / float(args.speed) if stamps else 0.0
    code = ctx.wait("player", timeout=playing_s + 60)
    check(code == 0, f"lcm-logplayer exited {code}: {ctx.output('player').strip()}")
    stop_lcm_logger(ctx, "logger", captured)

    code, text = ctx.run([args.dream, "log", "diff", original, captured, "--channels", "DREAM_.*"])
    check(code == 0, "the captured log does not hold every DREAM_* message of the original (lcm-logger "
                     "drops when its 30-message queue overflows under CPU load): "
                     + " ".join(text.strip().splitlines()[-4:]))
    played = sum(1 for e in read_all(original))
    recorded = sum(1 for e in read_all(captured) if e.channel.startswith("DREAM_"))
    check(played == recorded, f"played {played} events, the logger recorded {recorded} DREAM_* events")
    print(f"lcm-logplayer -> lcm-logger carried all {played} events")


if __name__ == "__main__":
    main(test)
