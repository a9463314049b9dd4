#!/usr/bin/python3
"""barriers_run: a run config's `barriers: {kind: unicycle}` is part of the run, in the simulator
and in the export (config/README.md#barrier-certificates-barriers).

1. `dream run` of six robots crossing a circle to the opposite side (go_to_goal, which avoids
   nobody) with the certificate applied in the world: at every step whose certificate output is
   within the wheels' limits (so the world did not saturate it), the velocities the robots drove
   with are dream.barriers' certificate (cvxopt, rps's settings) of the commands the agents sent
   on the poses of that step, to 1e-5; the certificate bent many of them; no collision. With
   ROBOTARIUM_PYTHON_SIMULATOR naming a checkout of the official simulator, the same against
   rps's own create_uni_barrier_certificate_with_boundary().
2. The same run without `barriers:` collides: the certificate is what kept them apart.
3. `dream export` of the run: export.json names the certificate and its parameters, taken from
   the config, and dream_params.npy carries them for the script.

Skipped (77) without numpy or cvxopt (Debian: python3-cvxopt).
Usage: barriers_run.py --dream BIN --source DIR --types-dir DIR
"""

import json
import math
import os
import sys
import warnings

from dreamtest import arguments, check, main, read_summary

TOLERANCE = 1e-5
WHEEL_RADIUS = 0.016
BASE_LENGTH = 0.11
MAX_WHEEL = 0.2 / 0.016


def config_text(barriers):
    n = 6
    poses, goals = [], []
    for i in range(n):
        a = 2 * math.pi * i / n
        poses.append("  - [%.4f, %.4f, %.4f]" % (0.6 * math.cos(a), 0.6 * math.sin(a), a + math.pi))
        goals.append("    - [%.4f, %.4f]" % (-0.6 * math.cos(a), -0.6 * math.sin(a)))
    return ("name: crossing\nseed: 1\nrobots: %d\nsteps: 400\nstop_when_done: true\nworld:\n  mode: lockstep\n"
            "initial_poses:\n%s\n%scontroller:\n  kind: go_to_goal\n  gain: 0.8\n  max_speed_mps: 0.15\n"
            "  tolerance_m: 0.05\n  goals:\n%s\n") % (n, "\n".join(poses), barriers, "\n".join(goals))


def within_wheels(dxu):
    left = (dxu[0] - dxu[1] * BASE_LENGTH / 2) / WHEEL_RADIUS
    right = (dxu[0] + dxu[1] * BASE_LENGTH / 2) / WHEEL_RADIUS
    return max(abs(left).max(), abs(right).max()) <= MAX_WHEEL * (1 - 1e-9)


def compare(run, certificate, name):
    import numpy as np
    compared = bent = 0
    worst = 0.0
    for row in range(run.num_steps - 1):
        wanted = run.commands[row].T
        if not np.all(np.isfinite(wanted)):
            continue
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            expected = certificate(wanted.copy(), run.poses[row].T.copy())
        if not within_wheels(expected):
            continue
        drove = run.velocities[row + 1].T
        worst = max(worst, float(np.abs(drove - expected).max()))
        compared += 1
        bent += float(np.abs(expected - wanted).max()) > 1e-3
    check(compared >= run.num_steps // 2, f"{name}: only {compared} of {run.num_steps} steps compared")
    check(bent >= 20, f"{name}: the certificate bent only {bent} steps' commands; the test does not exercise it")
    check(worst <= TOLERANCE, f"{name}: the world's velocities differ from the certificate's by {worst:.3g}")
    print(f"{name}: {compared} steps compared, {bent} bent, largest difference {worst:.3g}")


def test(ctx):
    args = arguments(types_dir=True)
    try:
        import numpy as np
        import cvxopt  # noqa: F401
    except ImportError as error:
        print(f"SKIP: {error} (Debian: python3-cvxopt)")
        sys.exit(77)
    sys.path.insert(0, os.path.join(args.source, "python"))
    import importlib.util
    import dream_log
    # python/dream/barriers.py as a module of its own: the package name `dream` is the LCM types'
    # here (dream_log), and barriers.py imports nothing of the runtime (as in a submission).
    spec = importlib.util.spec_from_file_location(
        "dream_barriers", os.path.join(args.source, "python", "dream", "barriers.py"))
    barriers = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(barriers)

    config = ctx.path("crossing.yaml")
    with open(config, "w") as f:
        f.write(config_text("barriers:\n  kind: unicycle\n"))
    out = ctx.path("crossing")
    code, output = ctx.run([args.dream, "-q", "run", config, "--out", out], timeout=120)
    check(code in (0, 5), f"dream run exit {code}: {output[-400:]}")
    run = dream_log.load(out, types_dir=args.types_dir)
    check(int(run.status["collision_errors"][-1]) == 0, "robots collided with the certificate on")
    compare(run, barriers.create_uni_barrier_certificate_with_boundary(), "dream.barriers")
    official = os.environ.get("ROBOTARIUM_PYTHON_SIMULATOR", "")
    if official and os.path.isfile(os.path.join(official, "rps", "utilities", "barrier_certificates.py")):
        sys.path.insert(0, official)
        from rps.utilities import barrier_certificates as rps_barriers
        compare(run, rps_barriers.create_uni_barrier_certificate_with_boundary(), "rps")
    else:
        print("rps: not compared (ROBOTARIUM_PYTHON_SIMULATOR names no checkout of the official simulator)")

    bare_config = ctx.path("bare.yaml")
    with open(bare_config, "w") as f:
        f.write(config_text(""))
    bare_out = ctx.path("bare")
    ctx.run([args.dream, "-q", "run", bare_config, "--out", bare_out], timeout=120)
    bare = dream_log.load(bare_out, types_dir=args.types_dir)
    check(int(bare.status["collision_errors"][-1]) > 0, "without the certificate the robots should collide")

    exported = ctx.path("export")
    ctx.run([args.dream, "-q", "export", out, "--out", exported, "--force"], timeout=120, expect=0)
    with open(os.path.join(exported, "export.json")) as f:
        manifest = json.load(f)
    check(manifest.get("barriers") is True, f"export.json barriers: {manifest.get('barriers')}")
    params = manifest.get("barrier_params", {})
    check(params.get("from") == "config" and params.get("safety_radius_m") == 0.12 and
          params.get("barrier_gain") == 150.0 and params.get("boundary_m") == [-1.6, 1.6, -1.0, 1.0],
          f"export.json barrier_params: {params}")
    values = np.load(os.path.join(exported, "upload", "dream_params.npy"))
    check(values.shape == (30,) and values[5] == 1.0 and values[21] == 0.12 and values[22] == 150.0 and
          values[23] == 0.03 and values[24] == 0.2 and values[25] == 1.0, f"dream_params.npy: {values.tolist()}")


if __name__ == "__main__":
    main(test)
