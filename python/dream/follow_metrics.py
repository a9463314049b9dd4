"""A Python controller's own metrics() followed while a run runs, for `dream view`'s plots.

A long-lived helper beside the view (one process a run, not one a step): it keeps every step's
poses it is sent and, when asked, evaluates the class's metrics() on the run so far, as
run_metrics.py does on the finished run (the same RunRecord, the same checks), so the answer
after the run's last step is what summary.json's metrics say.

    python3 -I follow_metrics.py

stdin: a JSON header line {"spec_bytes", "robots"}, the controller spec (JSON), then records:
  b"S" + uint32 count + count int64 step numbers + count x robots x 3 float64 poses (native order)
  b"E": evaluate metrics() on every step received so far
stdout: one JSON line per b"E": {"step": the last step, "figures": {name: number}} (of
run_metrics.py's entries, each number and each per-step series' last value), or {"step", "error": "..."} when the class's code failed on those steps. It ends at
the end of stdin. Not shipped in submissions.
"""

import json
import struct
import sys

import numpy as np

if __package__ in (None, ""):  # run as a script: the package is beside this file's folder
    import os
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    from dream.controller_spec import ControllerSpec
    from dream import run_metrics
else:
    from .controller_spec import ControllerSpec
    from . import run_metrics

MAX_POSE_NUMBERS = 6_000_000  # x, y, theta per robot and step: what the view's replay keeps too


class RunSoFar:
    """Every step received, in arrays that double as they fill."""

    def __init__(self, robots):
        self.robots = robots
        self.count = 0
        self.steps = np.zeros(1024, dtype=np.int64)
        self.poses = np.zeros((1024, robots, 3))

    def add(self, steps, poses):
        needed = self.count + steps.size
        if needed * self.robots * 3 > MAX_POSE_NUMBERS:
            raise ValueError(f"more than {MAX_POSE_NUMBERS} pose numbers: the run is too long to follow")
        if needed > self.steps.size:
            size = max(needed, 2 * self.steps.size)
            self.steps = np.resize(self.steps, size)
            grown = np.zeros((size, self.robots, 3))
            grown[:self.count] = self.poses[:self.count]
            self.poses = grown
        self.steps[self.count:needed] = steps
        self.poses[self.count:needed] = poses
        self.count = needed


def figures_of(metrics):
    """What the view plots of run_metrics.py's entries: each number, and each per-step series'
    last value ([step, value] pairs); flags and per-robot lists are no figure."""
    figures = {}
    for name, value in metrics.items():
        if isinstance(value, float):
            figures[name] = value
        elif isinstance(value, list) and value and isinstance(value[-1], list):
            figures[name] = value[-1][1]
    return figures


def _read_exactly(stream, size):
    data = stream.read(size)
    if data is None or len(data) != size:
        raise EOFError
    return data


def _answer(spec, run_so_far):
    steps, poses = run_so_far.steps[:run_so_far.count], run_so_far.poses[:run_so_far.count]
    last = int(steps[-1]) if steps.size else -1
    try:
        run = run_metrics.RunRecord(steps, poses, spec.config)
        run.goal_points = run_metrics._goal_points(spec.robot_class, spec.config, run.num_robots)
        metrics, _ = run_metrics.declared_metrics(spec.robot_class, run)
        return {"step": last, "figures": figures_of(metrics)}
    except Exception as error:  # the class's code on these steps: said, and the next steps tried
        where = f"{spec.module_path}: {spec.robot_class.__name__}"
        return {"step": last, "error": f"{where}: {type(error).__name__}: {error}"[:2000]}


def follow(stdin, stdout):
    header = run_metrics._read_header(stdin, "stdin", ("spec_bytes", "robots"))
    spec = ControllerSpec.from_json(_read_exactly(stdin, header["spec_bytes"]).decode("utf-8"))
    robots = header["robots"]
    run_so_far = RunSoFar(robots)
    while True:
        try:
            kind = _read_exactly(stdin, 1)
        except EOFError:
            return 0
        if kind == b"S":
            (count,) = struct.unpack("=I", _read_exactly(stdin, 4))
            if (run_so_far.count + count) * robots * 3 > MAX_POSE_NUMBERS:
                raise ValueError(f"more than {MAX_POSE_NUMBERS} pose numbers: the run is too long to follow")
            steps = np.frombuffer(_read_exactly(stdin, 8 * count), dtype=np.int64)
            poses = np.frombuffer(_read_exactly(stdin, 24 * count * robots), dtype=np.float64)
            run_so_far.add(steps, poses.reshape(count, robots, 3))
        elif kind == b"E":
            stdout.write((json.dumps(_answer(spec, run_so_far)) + "\n").encode("utf-8"))
            stdout.flush()
        else:
            raise ValueError(f"unknown record {kind!r}")


def main():
    try:
        return follow(sys.stdin.buffer, sys.stdout.buffer)
    except EOFError:
        print("follow_metrics.py: stdin ended inside a record", file=sys.stderr)
    except Exception as error:  # noqa: BLE001: what the view says when the plots stop
        print(f"{type(error).__name__}: {error}", file=sys.stderr)
    return 1


if __name__ == "__main__":
    sys.exit(main())
