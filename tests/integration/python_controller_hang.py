#!/usr/bin/python3
"""python_controller_hang: a Python controller that never returns, exits or escapes, under `dream run`.

`dream run` embedded Python and ran every controller call on the world's own thread, so a
controller that blocks used to hang the run for ever, deaf to Ctrl-C and SIGTERM (only kill -9
ended it, leaving run.lcmlog.part and no summary), and `sys.exit()` in update() was printed as
"Exception ignored on calling ctypes callback function" and taken for a silent agent.

1. A controller whose update() loops for ever at step 3 (robot 0 only), world.agent_timeout_s
   1.0 (given by --set over the file's 60): the run ends by itself, within seconds, at its step limit; robot 0's call was stopped
   (ControllerTimeout, naming the module's file:line) and the robot failed at step 3: exit 4,
   robot_faults names only robot 0, verdict reason controller_failed; robot 1 was never lost.
2. The same with agent_timeout_s 60 (so the watchdog would not stop it yet): SIGINT while the
   controller is stuck ends the run promptly with exit 130, summary end "interrupted", no
   run.lcmlog.part, a log `dream log info` reads whole, holding the events the summary counts.
   Then SIGTERM in real time (--mode realtime) while the controller sleeps in a loop
   (time.sleep(0.5)): the same.
3. A controller that calls sys.exit(3) in update() (robot 0, step 3): handled like any raising
   controller: exit 4, robot_faults names exit.py:LINE: in update: SystemExit: 3, verdict reason
   controller_failed (not lost_robots), and no "Exception ignored" printed.

4. Controllers that end or escape their Python process (it is dream's child, in its own process
   group; robot 0 at step 3 unless said): os._exit(0) (exit 4, both robots lost with faults naming
   escapes.py:LINE and "exit code 0"; it used to end `dream run` itself with exit 0, no summary and
   run.lcmlog.part); os.fork() and a fork through ctypes whose copy sleeps (the run is clean, exit 0,
   no copy outlives the run and a second run into the folder is not refused; the copy used to
   deadlock holding the folder's lock); SIG_IGN for SIGINT and SIGTERM in setup() (SIGTERM still ends
   the run at once, exit 130; it used to take SIGKILL, and dream launch called the run clean);
   time.sleep(600) in update() (exit 4 within
   seconds, robot 0's fault names the line and "did not return"; it used to hang); a setup() that
   never returns, only in the run (exit 4 within world.start_timeout_s, robot 1's fault names its
   setup() line) or already in the check before it (exit 1, the message names the line); a
   recursion 200,000 deep (exit 4, robot 0's fault names the line; it used to print "Exception
   ignored on calling ctypes callback", leave robot_faults empty and lose every robot as silent); bytes that are
   no message written on the process's link to dream (exit 4, robot 0's fault says so); a
   SIGSEGV in C code (exit 4, the fault names the line and the signal; it used to crash dream run). Every process
   the controllers ran in is gone when the command ends. (The setup() cases only under dream run:
   dream launch starts its agents while its simulator checks the config.)

With --launch, the same under `dream launch` (one `dream agent` process per robot, udpm; run in
a private network namespace): the agent's own watchdog stops the stuck call, so the world hears
the same fault instead of a silent agent, and an interrupted launch ends as promptly (the
sleeping variant there runs in lockstep too).

Usage: python_controller_hang.py --dream BIN --source DIR [--launch]
"""

import json
import os
import re
import resource
import signal
import time

from dreamtest import argument_parser, check, main, read_summary, require_private_netns

# Each command here takes 1-10 s on a quiet machine; this bound only turns a hang into a failure,
# and is far above what a hog on every core makes of them (docs/reliability.md, "Under load").
HANG_BOUND_S = 120

HANG = '''\
import os
import time

from dream import Robot


class Hang(Robot):
    """Robot 0 never returns from update() at step 3 (busy, or sleeping in a loop)."""

    def update(self, step):
        if step == 3 and self.id == 0:
            open(os.path.join(os.path.dirname(__file__), "stuck"), "w").close()
            while True:
                if SLEEP:
                    time.sleep(0.5)
        return (0.0, 0.0)


SLEEP = False
'''

EXIT = '''\
import sys

from dream import Robot


class Exits(Robot):
    def update(self, step):
        if step == 3 and self.id == 0:
            sys.exit(3)
        return (0.01, 0.0)
'''

CONFIG = '''\
name: {name}
robots: 2
steps: 40
stop_when_done: false
initial_poses: [[0.5, 0.5, 0], [-0.5, 0.5, 0]]
world: {{agent_timeout_s: {timeout}}}
controller: {{kind: python, module: {module}, class: {class_name}}}
'''


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)
    return path


def line_of(text, needle):
    return next(n for n, line in enumerate(text.splitlines(), 1) if needle in line)


def stopped_by_watchdog(ctx, args):
    folder = ctx.path("timeout")
    write(os.path.join(folder, "hang.py"), HANG)
    # The file says 60 s and --set 1 s, which the watchdog must follow (the world's limit,
    # overrides included; under dream launch, in every agent process).
    config = write(os.path.join(folder, "hang.yaml"),
                   CONFIG.format(name="hang", timeout=60, module="hang.py", class_name="Hang"))
    override = ["--set", "world.agent_timeout_s=1"]
    out = ctx.path("timeout_out")
    started = time.monotonic()
    code, output = ctx.run([args.dream, args.command, config, "--out", out] + override, timeout=HANG_BOUND_S)
    took = time.monotonic() - started
    # Ending at all (within ctx.run's bound) is the point; the fault below says it was the watchdog.
    check(code == 4, f"a controller stopped for running too long: exit {code}, expected 4: {output[-600:]}")
    summary = read_summary(out)
    check(summary["end"] == "finished" and summary["steps"] == 40,
          f"the run should go on to its step limit: end {summary['end']}, steps {summary['steps']}")
    faults = summary["robot_faults"]
    loop_lines = "|".join(str(line_of(HANG, "while True:") + n) for n in range(3))  # in the loop
    check(list(faults) == ["0"], f"robot_faults should name robot 0 only: {faults}")
    check(re.match(rf"step 3: .*hang\.py:({loop_lines}): in update: ControllerTimeout: still running after 0\.8 s "
                   rf"of the world's agent_timeout_s of 1 s", faults["0"]) is not None,
          f"robot 0's fault does not say where and why: {faults['0']!r}")
    check(summary["robots_ever_lost"] == [0], f"only robot 0 should be lost: {summary['robots_ever_lost']}")
    rules = [reason["rule"] for reason in summary["verdict_reasons"]]
    check(rules == ["controller_failed"], f"verdict reasons {rules}, expected controller_failed only")
    check("ControllerTimeout" in output and "Exception ignored" not in output,
          f"the report should name the timeout: {output[-600:]}")
    busy_notes_held_the_world(ctx, args, out)
    return f"stopped after {took:.1f} s"


def busy_notes_held_the_world(ctx, args, out):
    """While robot 0's call was stuck at step 3, its host said so on DREAM_BUSY_<id> (under dream
    run for robot 1 too: it waits behind robot 0's call in the same process; under dream launch it
    has a process of its own), so the world waited for the host's fault instead of racing the
    watchdog with its own clock; the log keeps one note per robot and step, and `dream log echo`
    decodes them."""
    code, output = ctx.run([args.dream, "log", "echo", out, "DREAM_BUSY_.*"], timeout=60)
    check(code == 0, f"dream log echo of the busy notes: exit {code}: {output[-600:]}")
    notes = [json.loads(line) for line in output.splitlines() if line.startswith("{")]
    robots = sorted(note["message"]["robot_id"] for note in notes)
    expected = [0] if args.launch else [0, 1]
    check(robots == expected and all(note["message"]["step"] == 3 for note in notes),
          f"the log should hold one busy note at step 3 for robots {expected}: {notes}")
    check(all(note["type"] == "robot_busy_t" and note["message"]["call_robot_id"] in (0, -1) for note in notes),
          f"the notes should name robot 0's call: {notes}")


def interrupted(ctx, args, name, sleep, mode, stop_signal):
    folder = ctx.path(name)
    write(os.path.join(folder, "hang.py"), HANG.replace("SLEEP = False", f"SLEEP = {sleep}"))
    config = write(os.path.join(folder, "hang.yaml"),
                   CONFIG.format(name=name, timeout=60, module="hang.py", class_name="Hang"))
    out = ctx.path(name + "_out")
    run = ctx.start(name, [args.dream, args.command, config, "--out", out, "--mode", mode])
    deadline = time.monotonic() + 20
    while not os.path.exists(os.path.join(folder, "stuck")):
        check(run.poll() is None, f"{name}: dream run ended ({run.returncode}) before the controller got stuck")
        check(time.monotonic() < deadline, f"{name}: the controller did not get stuck within 20 s")
        time.sleep(0.02)
    time.sleep(0.5)
    check(run.poll() is None, f"{name}: dream run ended by itself ({run.returncode})")
    sent = time.monotonic()
    run.send_signal(stop_signal)
    code = ctx.wait(name, timeout=HANG_BOUND_S)
    took = time.monotonic() - sent
    check(code == 130, f"{name}: exit {code} after {signal.Signals(stop_signal).name}, expected 130")
    summary = read_summary(out)
    check(summary["end"] == "interrupted", f"{name}: summary end {summary['end']!r}, expected 'interrupted'")
    check(summary["robot_faults"] == {}, f"{name}: an interrupt is no controller's fault: {summary['robot_faults']}")
    check(not os.path.exists(os.path.join(out, "run.lcmlog.part")), f"{name}: run.lcmlog.part left behind")
    code, text = ctx.run([args.dream, "log", "info", os.path.join(out, "run.lcmlog")])
    check(code == 0, f"{name}: dream log info refuses the log: {text.strip()}")
    events = re.search(r": (\d+) events", text)
    check(events is not None and int(events.group(1)) == summary["log_events"],
          f"{name}: the log holds {events.group(1) if events else '?'} events, the summary counts "
          f"{summary['log_events']}")
    check("Exception ignored" not in ctx.output(name), f"{name}: {ctx.output(name)[-600:]}")
    return f"{name} ended {took:.2f} s after the signal"


def exits(ctx, args):
    folder = ctx.path("exits")
    write(os.path.join(folder, "exit.py"), EXIT)
    config = write(os.path.join(folder, "exit.yaml"),
                   CONFIG.format(name="exits", timeout=1.0, module="exit.py", class_name="Exits"))
    out = ctx.path("exits_out")
    code, output = ctx.run([args.dream, args.command, config, "--out", out], timeout=HANG_BOUND_S)
    check(code == 4, f"sys.exit(3) in update(): exit {code}, expected 4: {output[-600:]}")
    check("Exception ignored" not in output, f"SystemExit escaped to ctypes: {output[-800:]}")
    summary = read_summary(out)
    faults = summary["robot_faults"]
    exit_line = line_of(EXIT, "sys.exit(3)")
    check(list(faults) == ["0"] and re.match(rf"step 3: .*exit\.py:{exit_line}: in update: SystemExit: 3$",
                                             faults["0"]) is not None,
          f"robot_faults should name exit.py:{exit_line} and SystemExit: {faults}")
    rules = [reason["rule"] for reason in summary["verdict_reasons"]]
    check(rules == ["controller_failed"], f"verdict reasons {rules}, expected controller_failed only")
    check(summary["steps"] == 40, f"the run should go on to its end: {summary['steps']} steps")
    return "sys.exit: controller_failed"


ESCAPES = '''\
import ctypes
import os
import signal
import sys
import time

from dream import Robot

HERE = os.path.dirname(os.path.abspath(__file__))


def note(name, value):
    with open(os.path.join(HERE, name), "a") as f:
        f.write(f"{value}\\n")


def deep(n):
    return deep(n + 1) + 1


class Escapes(Robot):
    """Robot 0 at step 3 (robot 1 in setup) does ATTACK; each robot notes its process."""

    def setup(self):
        note("hosts", os.getpid())
        if ATTACK == "ignore_signals":
            signal.signal(signal.SIGINT, signal.SIG_IGN)
            signal.signal(signal.SIGTERM, signal.SIG_IGN)
            note("ignoring", os.getpid())
        if ATTACK in ("setup_sleeps", "check_sleeps") and self.id == 1:
            marker = os.path.join(HERE, "checked")
            if ATTACK == "check_sleeps" or os.path.exists(marker):
                time.sleep(600)
            open(marker, "w").close()

    def update(self, step):
        if step == 3 and self.id == 0:
            if ATTACK == "exit":
                os._exit(0)
            if ATTACK == "fork":
                pid = os.fork()
                if pid:
                    note("forked", pid)
            if ATTACK == "ctypes_fork":
                pid = ctypes.CDLL(None).fork()
                if pid == 0:
                    time.sleep(600)
                note("forked", pid)
            if ATTACK == "sleep":
                time.sleep(600)
            if ATTACK == "recursion":
                sys.setrecursionlimit(200000)
                deep(0)
            if ATTACK == "crash":
                ctypes.string_at(0)  # SIGSEGV
            if ATTACK == "garbage":  # on the descriptor of the process's link to dream
                os.write(3, b"M" + b"\\xff" * 64)
        return (0.01, 0.0)


ATTACK = None
'''


def pids_in(folder, name):
    path = os.path.join(folder, name)
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [int(line) for line in f if line.strip()]


def running(pid):
    """True while `pid` runs (a zombie has ended)."""
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().rsplit(")", 1)[1].split()[0] != "Z"
    except FileNotFoundError:
        return False


def escape_case(ctx, args, attack, timeout=1, start_timeout=20):
    """ESCAPES with ATTACK and its config: (its folder, the config, the run's folder)."""
    folder = ctx.path("escape_" + attack)
    write(os.path.join(folder, "escapes.py"), ESCAPES.replace("ATTACK = None", f"ATTACK = {attack!r}"))
    config = write(os.path.join(folder, "escapes.yaml"),
                   CONFIG.format(name=attack, timeout=timeout, module="escapes.py", class_name="Escapes")
                   .replace("world: {", f"world: {{start_timeout_s: {start_timeout}, "))
    out = ctx.path("escape_" + attack + "_out")
    return folder, config, out


def no_process_left(folder, attack):
    """The processes the controllers noted are gone: waited for (a SIGKILL takes effect when the
    process next runs, later on a loaded machine); 30 s only turns one that lives on into a failure."""
    deadline = time.monotonic() + 30
    while True:
        left = {name: [pid for pid in pids_in(folder, name) if pid > 0 and running(pid)]
                for name in ("hosts", "forked", "ignoring")}
        left = {name: pids for name, pids in left.items() if pids}
        if not left:
            return
        check(time.monotonic() < deadline, f"{attack}: process(es) {left} outlived the command")
        time.sleep(0.05)


def faults_of(summary, attack):
    check(summary is not None, f"{attack}: no summary.json")
    return summary["robot_faults"]


def escapes(ctx, args):
    results = []

    # os._exit(0): the robots are lost, the run ends by itself with a verdict.
    folder, config, out = escape_case(ctx, args, "exit")
    code, output = ctx.run([args.dream, args.command, config, "--out", out], timeout=HANG_BOUND_S)
    check(code == 4, f"os._exit(0) in update(): exit {code}, expected 4: {output[-600:]}")
    check(not os.path.exists(os.path.join(out, "run.lcmlog.part")), "os._exit: run.lcmlog.part left behind")
    faults = faults_of(read_summary(out), "exit")
    check(re.match(rf"step 3: .*escapes\.py:{line_of(ESCAPES, 'os._exit(0)')}: in update: robot 0's call at step 3 "
                   r"ended its Python process: exit code 0", faults.get("0", "")) is not None,
          f"os._exit: robot 0's fault should name the line and the exit code: {faults}")
    # dream run hosts both robots in one Python process, dream launch one per robot.
    lost_with_it = ["0", "1"] if args.command == "run" else ["0"]
    check(sorted(faults) == lost_with_it, f"os._exit: robot_faults should name robots {lost_with_it}: {faults}")
    no_process_left(folder, "exit")
    results.append("os._exit: exit 4")

    # A crash in C code: the signal and the line.
    resource.setrlimit(resource.RLIMIT_CORE, (0, 0))  # no core file from the crash below
    folder, config, out = escape_case(ctx, args, "crash")
    code, output = ctx.run([args.dream, args.command, config, "--out", out], timeout=HANG_BOUND_S)
    check(code == 4, f"a SIGSEGV in update(): exit {code}, expected 4: {output[-600:]}")
    fault = faults_of(read_summary(out), "crash").get("0", "")
    check(re.match(rf"step 3: .*escapes\.py:{line_of(ESCAPES, 'ctypes.string_at(0)')}: in update: robot 0's call at "
                   r"step 3 ended its Python process: killed by signal 11 \(SIGSEGV\)", fault) is not None,
          f"crash: robot 0's fault should name the line and the signal: {fault!r}")
    no_process_left(folder, "crash")
    results.append("SIGSEGV: exit 4")

    # Bytes that are no frame, written on the link: the process is ended, its robots lost.
    folder, config, out = escape_case(ctx, args, "garbage")
    code, output = ctx.run([args.dream, args.command, config, "--out", out], timeout=HANG_BOUND_S)
    check(code == 4, f"garbage on the link: exit {code}, expected 4: {output[-600:]}")
    fault = faults_of(read_summary(out), "garbage").get("0", "")
    check("on its link" in fault, f"garbage: robot 0's fault should say what happened: {fault!r}")
    no_process_left(folder, "garbage")
    results.append("garbage on the link: exit 4")

    # fork, and a fork through ctypes that the runtime's fork hook cannot see: no copy outlives
    # the run, nothing holds the folder, the run is clean.
    for attack in ("fork", "ctypes_fork"):
        folder, config, out = escape_case(ctx, args, attack)
        code, output = ctx.run([args.dream, args.command, config, "--out", out], timeout=HANG_BOUND_S)
        check(code == 0, f"{attack}: exit {code}, expected 0: {output[-600:]}")
        check(pids_in(folder, "forked"), f"{attack}: the controller did not fork")
        no_process_left(folder, attack)
        code, output = ctx.run([args.dream, args.command, config, "--out", out, "--overwrite"], timeout=HANG_BOUND_S)
        check(code == 0, f"{attack}: a second run into the folder: exit {code}: {output[-600:]}")
        results.append(f"{attack}: clean, nothing left")

    # Signals ignored in setup(): SIGTERM still ends the run at once.
    folder, config, out = escape_case(ctx, args, "ignore_signals")
    run = ctx.start("ignore_signals", [args.dream, args.command, config, "--out", out, "--steps", "100000",
                                       "--mode", "realtime"])
    ctx.wait_for_output("ignore_signals", "robots have agents; running", 20)
    time.sleep(0.5)
    sent = time.monotonic()
    run.send_signal(signal.SIGTERM)
    code = ctx.wait("ignore_signals", timeout=HANG_BOUND_S)  # it used to wait for SIGKILL for ever
    took = time.monotonic() - sent
    check(code == 130, f"ignore_signals: exit {code} after SIGTERM, expected 130: {ctx.output('ignore_signals')[-600:]}")
    check(read_summary(out)["end"] == "interrupted", "ignore_signals: summary end is not 'interrupted'")
    no_process_left(folder, "ignore_signals")
    results.append(f"SIG_IGN: ended {took:.2f} s after SIGTERM")

    # A call stuck in C (time.sleep(600)), and a recursion so deep that writing its traceback
    # outlasts the step (the watchdog raised ControllerTimeout again inside the host).
    for attack, why in (("sleep", "did not return"), ("recursion", "")):
        folder, config, out = escape_case(ctx, args, attack)
        started = time.monotonic()
        code, output = ctx.run([args.dream, args.command, config, "--out", out], timeout=HANG_BOUND_S)
        took = time.monotonic() - started
        check(code == 4, f"{attack}: exit {code}, expected 4: {output[-600:]}")
        fault = faults_of(read_summary(out), attack).get("0", "")
        lines = [str(n) for n, line in enumerate(ESCAPES.splitlines(), 1)
                 if ("time.sleep(600)" in line and attack == "sleep") or
                 (attack == "recursion" and "deep(n + 1)" in line)]
        # The line of a recursion is named when Python's traceback holds it (its innermost 100 frames).
        named = re.match(rf"step 3: .*escapes\.py:({'|'.join(lines)}): in (update|deep): ", fault) is not None
        unnamed = attack == "recursion" and re.match(r"step 3: (robot 0's call|ControllerTimeout)", fault) is not None
        check((named or unnamed) and why in fault, f"{attack}: robot 0's fault should name the line: {fault!r}")
        no_process_left(folder, attack)
        results.append(f"{attack}: exit 4 in {took:.1f} s")

    # setup() that never returns in the run (the check before it passed), or already in the check.
    # (Not under dream launch, whose agents start while its simulator checks the config.)
    if args.command != "run":
        return "; ".join(results)
    folder, config, out = escape_case(ctx, args, "setup_sleeps", start_timeout=10)
    started = time.monotonic()
    code, output = ctx.run([args.dream, args.command, config, "--out", out], timeout=HANG_BOUND_S)
    took = time.monotonic() - started
    setup_line = line_of(ESCAPES, "time.sleep(600)")
    check(code == 4, f"setup_sleeps: exit {code}, expected 4: {output[-600:]}")
    fault = faults_of(read_summary(out), "setup_sleeps").get("1", "")
    check(re.match(rf".*escapes\.py:{setup_line}: in setup: robot 1's setup\(\) did not return, nor stop when dream's watchdog raised ControllerTimeout "
                   rf"in it at 0\.8 x the world's start_timeout_s of 10 s", fault)
          is not None, f"setup_sleeps: robot 1's fault: {fault!r}")
    no_process_left(folder, "setup_sleeps")
    results.append(f"setup() hangs in the run: exit 4 in {took:.1f} s")
    folder, config, out = escape_case(ctx, args, "check_sleeps", start_timeout=10)
    started = time.monotonic()
    code, output = ctx.run([args.dream, args.command, config, "--out", out], timeout=HANG_BOUND_S)
    took = time.monotonic() - started
    check(code == 1 and re.search(rf"escapes\.py:{setup_line}: in setup: robot 1's setup\(\) did not return",
                                  output) is not None,
          f"check_sleeps: exit {code}, expected 1 naming the line: {output[-600:]}")
    no_process_left(folder, "check_sleeps")
    results.append(f"setup() hangs in the check: exit 1 in {took:.1f} s")
    return "; ".join(results)


def test(ctx):
    parser = argument_parser()
    parser.add_argument("--launch", action="store_true", help="dream launch instead of dream run")
    args = parser.parse_args()
    args.command = "launch" if args.launch else "run"
    if args.launch:
        require_private_netns()
    print(stopped_by_watchdog(ctx, args))
    print(interrupted(ctx, args, "busy_sigint", False, "lockstep", signal.SIGINT))
    print(interrupted(ctx, args, "sleeping_sigterm", True, "lockstep" if args.launch else "realtime", signal.SIGTERM))
    print(exits(ctx, args))
    print(escapes(ctx, args))


if __name__ == "__main__":
    main(test)
