#!/usr/bin/python3
"""Record reference trajectories from the official Robotarium V2 Python simulator.

Usage:
    /usr/bin/python3 generate_reference.py <robotarium_python_simulator checkout> [output]

Drives rps.robotarium.Robotarium (show_figure=False, sim_in_real_time=False,
skip_initialization=True) through a few scripted scenarios whose commands
depend only on the step number (open loop), and writes every set_velocities
call, every get_poses() result, the cumulative error counts after every step
and the final debug() text to a plain-text fixture (default: stdout).
tests/world/robotarium_reference_test.cc replays the commands through
dream::world::UnicycleWorld and compares.

Needs numpy, matplotlib and cvxopt (the official package imports
them); on Debian use /usr/bin/python3. See README.md next to this file.
"""

import contextlib
import io
import math
import os
import platform
import random
import subprocess
import sys

# A pose this close to a rule's threshold could be judged differently by two
# correct implementations whose sin/cos differ in the last bit (numpy's SIMD
# versus glibc), so scenarios must keep clear of it. Poses agree to ~1e-13.
THRESHOLD_MARGIN = 1e-10


def official_commit(checkout):
    try:
        return subprocess.run(["git", "-C", checkout, "rev-parse", "HEAD"], check=True,
                              capture_output=True, text=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return os.environ.get("ROBOTARIUM_PYTHON_SIMULATOR_COMMIT", "unknown (not a git checkout)")


def check_margins(name, step, poses, abc):
    """Fail loudly if a pose sits within THRESHOLD_MARGIN of a rule threshold."""
    b = abc.BOUNDARIES
    n = poses.shape[1]
    for i in range(n):
        x, y = poses[0, i], poses[1, i]
        for value, bound in ((x, b[0]), (x, b[1]), (y, b[2]), (y, b[3])):
            if abs(value - bound) <= THRESHOLD_MARGIN:
                raise SystemExit(f"{name}: step {step}: robot {i} is within {THRESHOLD_MARGIN} of the "
                                 f"boundary; change the scenario")
    cx = [poses[0, i] + abc.COLLISION_OFFSET * math.cos(poses[2, i]) for i in range(n)]
    cy = [poses[1, i] + abc.COLLISION_OFFSET * math.sin(poses[2, i]) for i in range(n)]
    for i in range(n - 1):
        for j in range(i + 1, n):
            d = math.hypot(cx[i] - cx[j], cy[i] - cy[j])
            if abs(d - abc.COLLISION_DIAMETER) <= THRESHOLD_MARGIN:
                raise SystemExit(f"{name}: step {step}: robots {i},{j} are within {THRESHOLD_MARGIN} "
                                 f"of the collision distance; change the scenario")


# --- scenarios: (initial 3xN poses, steps, commands(step) -> [(ids, 2xk array)]) ---

def mixed_scenario(np):
    """Saturation of every kind, turning through +-pi, leaving the arena, collisions."""
    x0 = np.array([
        [1.2, -1.0, -1.0, 0.0, 0.5, 0.8, -0.4, 0.3],
        [0.6, 0.5, -0.5, 0.0, 0.0, -0.6, 0.7, -0.35],
        [0.0, 3.0, 2.9, 0.0, math.pi, -1.2, 3.1, 0.5],
    ])
    steps = 420

    def commands(k):
        calls = []
        # r0: forward over the limit out through x = 1.6, then back in, then turn.
        v0 = 0.3 if k < 150 else (-0.25 if k < 260 else 0.05)
        w0 = 0.0 if k < 260 else 1.5
        # r1: pure rotation over the limit, one way then the other.
        w1 = 6.0 if k < 200 else -6.0
        # r2: one wheel saturates (left 2.5, right 16.25 rad/s).
        # r3/r4: head-on at 0.1 m/s, stop while overlapping, back off.
        v34 = 0.1 if k < 70 else (0.0 if k < 100 else -0.1)
        if k % 2 == 0:
            ids = np.array([4, 0, 3, 1])
            calls.append((ids, np.array([[v34, v0, v34, 0.0], [0.0, w0, 0.0, w1]])))
        else:
            # Odd steps set r0 twice in one call order: the last value wins.
            ids = np.array([0, 1, 3, 4])
            calls.append((ids, np.array([[0.0, 0.0, v34, v34], [0.0, w1, 0.0, 0.0]])))
            calls.append((np.array([0]), np.array([[v0], [w0]])))
        if k == 0:
            # r2 and r5 are commanded once and then hold their (saturated) velocity.
            calls.append((np.array([2, 5]), np.array([[0.15, 0.25], [2.0, 2.5]])))
        if k == 300:
            calls.append((np.array([2]), np.array([[-0.12], [-3.0]])))
        # r6: slow reverse turning through +pi.
        if k % 5 == 0:
            calls.append((np.array([6]), np.array([[-0.05], [0.4 if k < 210 else -0.9]])))
        # r7: smooth but changing every step, over the limit part of the time.
        calls.append((np.array([7]), np.array([[0.18 * math.sin(0.05 * k)], [3.0 * math.cos(0.07 * k)]])))
        return calls

    return x0, steps, commands


def warning_only_scenario(np):
    """Only actuator-limit errors: debug() prints the WARNING branch."""
    x0 = np.array([[-0.8, 0.0, 0.8], [0.0, 0.3, -0.2], [0.5, -2.0, 3.0]])
    steps = 61

    def commands(k):
        w0 = 5.0 if k % 3 == 0 else 1.0
        return [(np.array([0, 1, 2]), np.array([[0.05, 0.1, -0.1], [w0, -0.5, 0.7]]))]

    return x0, steps, commands


def clean_scenario(np):
    """No errors at all: debug() prints the clean branch."""
    x0 = np.array([[-0.3, 0.3], [0.0, 0.0], [math.pi / 2, -math.pi / 2]])
    steps = 30

    def commands(k):
        return [(np.array([0, 1]), np.array([[0.1, 0.1], [0.5, -0.5]]))]

    return x0, steps, commands


def random20_scenario(np):
    """20 robots (hardware maximum) at random, random held commands: dense interactions.

    Not 50: V2.0.0's constructor samples N of its 22 charger poses
    (generate_initial_poses) even when initial_conditions are given, so it
    raises ValueError for N > 22.
    """
    from rps.utilities.misc import generate_random_poses
    np.random.seed(20260401)
    x0 = generate_random_poses(20, spacing=0.2, width=2.0, height=1.2)
    steps = 300
    rng = np.random.default_rng(7)
    script = []
    for _ in range(steps):
        ids = np.flatnonzero(rng.random(20) < 0.3)
        rng.shuffle(ids)
        dxu = np.vstack([rng.uniform(-0.25, 0.25, ids.size), rng.uniform(-4.5, 4.5, ids.size)])
        script.append((ids, dxu))

    def commands(k):
        return [script[k]] if script[k][0].size else []

    return x0, steps, commands


SCENARIOS = [
    ("mixed", mixed_scenario),
    ("warning_only", warning_only_scenario),
    ("clean", clean_scenario),
    ("random20", random20_scenario),
]


def run_scenario(name, build, out):
    import numpy as np
    from rps.robotarium import Robotarium
    from rps.robotarium_abc import ARobotarium

    x0, steps, commands = build(np)
    n = x0.shape[1]
    r = Robotarium(number_of_robots=n, show_figure=False, initial_conditions=x0.copy(),
                   sim_in_real_time=False, skip_initialization=True)
    out.append(f"scenario,{name},{n},{steps}")

    def record_poses(step, poses):
        check_margins(name, step, poses, ARobotarium)
        for i in range(n):
            out.append(f"pose,{step},{i},{poses[0, i]!r},{poses[1, i]!r},{poses[2, i]!r}")

    for k in range(steps):
        record_poses(k, r.get_poses())
        for ids, dxu in commands(k):
            r.set_velocities(ids, dxu)
            for column, robot in enumerate(ids):
                out.append(f"cmd,{k},{int(robot)},{float(dxu[0, column])!r},{float(dxu[1, column])!r}")
        r.step()
        e = r._errors  # private, but the only place the per-step counts live
        out.append(f"errors,{k},{e.get('robots_outside_boundaries', 0)},"
                   f"{e.get('robots_too_close', 0)},{e.get('exceeded_actuator_limits', 0)}")
    record_poses(steps, r.get_poses())

    captured = io.StringIO()
    with contextlib.redirect_stdout(captured):
        r.debug()
    text = captured.getvalue()
    assert text.endswith("\n")
    for line in text[:-1].split("\n"):
        out.append(f"debug,{line}")
    out.append("end")


def main(argv):
    if len(argv) not in (2, 3):
        print(__doc__, file=sys.stderr)
        return 2
    checkout = os.path.abspath(argv[1])
    if not os.path.isfile(os.path.join(checkout, "rps", "robotarium.py")):
        print(f"{checkout} has no rps/robotarium.py; pass a robotarium_python_simulator checkout",
              file=sys.stderr)
        return 2
    os.environ.setdefault("MPLBACKEND", "Agg")
    sys.path.insert(0, checkout)
    import numpy as np
    random.seed(0)
    np.random.seed(0)

    out = [
        "# Robotarium V2 reference trajectories, replayed by tests/world/robotarium_reference_test.cc.",
        "# Generated by tests/robotarium_reference/generate_reference.py from",
        "# https://github.com/robotarium/robotarium_python_simulator",
        f"# official commit: {official_commit(checkout)}",
        f"# python {platform.python_version()}, numpy {np.__version__}, machine {platform.machine()}",
        "# Records (floats are Python repr, i.e. shortest round-trip):",
        "#   scenario,<name>,<num_robots>,<num_steps>",
        "#   pose,<step>,<robot>,<x>,<y>,<theta>   get_poses() at <step>, before its commands",
        "#   cmd,<step>,<robot>,<v>,<w>            set_velocities() at <step>, in call order",
        "#   errors,<step>,<boundary>,<collision>,<actuator>   cumulative _errors after step()",
        "#   debug,<text>                           one line of debug() output",
        "#   end",
    ]
    for name, build in SCENARIOS:
        run_scenario(name, build, out)

    text = "\n".join(out) + "\n"
    if len(argv) == 3:
        with open(argv[2], "w", encoding="utf-8") as f:
            f.write(text)
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
