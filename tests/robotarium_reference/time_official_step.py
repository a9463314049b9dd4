#!/usr/bin/python3
"""Time one step() of the official Robotarium V2 simulator (no figure, no
real-time throttle, robots driving small circles).

Usage: /usr/bin/python3 time_official_step.py <robotarium_python_simulator checkout> [N ...]

V2.0.0 cannot be constructed with more than 22 robots (its constructor samples
N of 22 charger poses even when initial_conditions are given); for larger N
this script replaces that sampler with one that returns N dummy poses, which
the given initial conditions then override, and says so.
"""

import os
import sys
import time


def main(argv):
    if len(argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    os.environ.setdefault("MPLBACKEND", "Agg")
    sys.path.insert(0, os.path.abspath(argv[1]))
    import numpy as np
    import rps.robotarium as robotarium_module
    from rps.utilities.misc import generate_random_poses

    for n in [int(a) for a in argv[2:]] or [20, 50]:
        patched = n > 22
        if patched:
            robotarium_module.generate_initial_poses = lambda count, **_: np.zeros((3, count))
        np.random.seed(1)
        x0 = generate_random_poses(n, spacing=0.2, width=3.0, height=1.8)
        r = robotarium_module.Robotarium(number_of_robots=n, show_figure=False, initial_conditions=x0,
                                         sim_in_real_time=False, skip_initialization=True)
        dxu = np.vstack([np.full(n, 0.1), np.linspace(-2.0, 2.0, n)])
        steps = 300
        start = time.perf_counter()
        for _ in range(steps):
            r.get_poses()
            r.set_velocities(np.arange(n), dxu)
            r.step()
        per_step_ms = (time.perf_counter() - start) / steps * 1e3
        note = " (constructor's 22-robot sampler patched)" if patched else ""
        print(f"{n} robots: {per_step_ms:.2f} ms per step{note}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
