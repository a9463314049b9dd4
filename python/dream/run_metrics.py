"""A Python controller's own metrics and goal, computed from a finished run's poses.

A controller class may declare, next to KEYS (all optional, all classmethods, never called
while the robots run, so a Robotarium submission ignores them):

    @classmethod
    def goal_points(cls, config, num_robots):   # where each robot should go: [[(x, y), ...], ...]
    @classmethod
    def metrics(cls, run):                      # {name: number | per-step values | per-robot values}
    @classmethod
    def goal(cls, run, metrics):                # True/False, or {"met", "completion_step", "detail"},
                                                # or None: no goal for this run (its config gave none);
                                                # `metrics`: what metrics() returned ({} without it)

`run` is a RunRecord: run.steps (T,), run.poses (T, N, 3) x, y, theta in metres and radians,
run.config (the checked KEYS values), run.num_robots, run.goal_points (the class's, or []).

The reporting tool (dream run, dream compare) runs this file as a short-lived process:

    python3 -I run_metrics.py INPUT OUTPUT

INPUT: a JSON header line {"spec_bytes", "steps", "robots"}, the controller spec (JSON, as for
the agents), then `steps` int64 step numbers and steps x robots x 3 float64 poses (native byte
order). OUTPUT receives {"declared": [...], "metrics": {...}, "goal": {...} | null,
"goal_points": [...]}; an error goes to stderr with exit status 1. Not shipped in submissions.

Before a run, `dream view` and `dream run --view` ask only for the goal points, to draw them:

    python3 -I run_metrics.py --goal-points INPUT OUTPUT

INPUT: a JSON header line {"spec_bytes", "robots"} and the controller spec; OUTPUT receives
{"declared": true | false, "goal_points": [...]}.
"""

import json
import math
import sys

import numpy as np

if __package__ in (None, ""):  # run as a script: the package is beside this file's folder
    import os
    sys.path.insert(0, os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    from dream.controller_spec import ControllerSpec
else:
    from .controller_spec import ControllerSpec

MAX_HEADER_BYTES = 4096
MAX_DETAIL_CHARS = 200
MAX_GOAL_POINTS_PER_ROBOT = 1000  # a drawing's worth; more is a mistake, not a goal
MAX_ROBOTS = 1000
# Names summary.json's metrics already use for their own fields.
RESERVED_NAMES = ("kind", "goal", "goal_points", "error")


class MetricsDeclarationError(ValueError):
    """A class's metrics(), goal() or goal_points() returned something DREAM cannot use."""


class RunRecord:
    """A finished run as numpy arrays, handed to a controller's metrics() and goal()."""

    def __init__(self, steps, poses, config, goal_points=()):
        self.steps = np.asarray(steps, dtype=np.int64)
        self.poses = np.asarray(poses, dtype=float)
        if self.poses.ndim != 3 or self.poses.shape[2] != 3 or self.poses.shape[0] != self.steps.shape[0]:
            raise ValueError(f"poses must be (steps, robots, 3) with one row per step, got {self.poses.shape}")
        self.config = config
        self.num_robots = int(self.poses.shape[1])
        self.goal_points = [list(points) for points in goal_points]

    def positions(self):
        """(T, N, 2): x, y of every robot at every step."""
        return self.poses[:, :, :2]

    def distances_to(self, points):
        """(T, N): each robot's distance to its own point, points: N (x, y)."""
        target = np.asarray(points, dtype=float).reshape(1, self.num_robots, 2)
        return np.linalg.norm(self.positions() - target, axis=2)

    def first_step_where(self, condition):
        """The first step from which `condition` ((T,) booleans) holds to the end, or -1."""
        condition = np.asarray(condition, dtype=bool)
        if condition.size == 0 or not condition[-1]:
            return -1
        false_at = np.flatnonzero(~condition)
        index = 0 if false_at.size == 0 else int(false_at[-1]) + 1
        return int(self.steps[index])


def _finite(value, where):
    number = float(value)
    if not math.isfinite(number):
        raise MetricsDeclarationError(f"{where}: not a finite number: {value!r}")
    return number


def _metric_entries(name, value, run):
    """metrics.json entries for one declared metric: a figure, a series over steps (for
    dream render --plot) or one figure per robot."""
    where = f"metrics()['{name}']"
    if isinstance(value, (bool, np.bool_)):
        return {name: bool(value)}
    if np.isscalar(value):
        return {name: _finite(value, where)}
    values = np.asarray(value, dtype=float)
    if values.ndim != 1:
        raise MetricsDeclarationError(f"{where}: expected a number, one value per step or one per robot, "
                                      f"got shape {values.shape}")
    if values.size == run.steps.size:
        return {name: [[int(step), _finite(v, where)] for step, v in zip(run.steps, values)]}
    if values.size == run.num_robots:
        return {name: [_finite(v, where) for v in values]}
    raise MetricsDeclarationError(f"{where}: {values.size} values, but the run has {run.steps.size} steps and "
                                  f"{run.num_robots} robots")


def _goal_entry(answer):
    if isinstance(answer, (bool, np.bool_)):
        return {"met": bool(answer), "completion_step": -1, "detail": "met" if answer else "not met"}
    if not isinstance(answer, dict) or "met" not in answer:
        raise MetricsDeclarationError(f"goal(): expected True/False or {{'met': ..., 'completion_step': ..., "
                                      f"'detail': ...}}, got {answer!r}")
    unknown = set(answer) - {"met", "completion_step", "detail"}
    if unknown:
        raise MetricsDeclarationError(f"goal(): unknown keys {sorted(unknown)}; allowed: met, completion_step, detail")
    met = bool(answer["met"])
    step = answer.get("completion_step", -1)
    step = -1 if step is None else int(step)
    detail = str(answer.get("detail", "met" if met else "not met"))[:MAX_DETAIL_CHARS]
    return {"met": met, "completion_step": step if met else -1, "detail": detail}


def _goal_points(robot_class, config, num_robots):
    if not callable(getattr(robot_class, "goal_points", None)):
        return []
    points = robot_class.goal_points(config, num_robots)
    if len(points) != num_robots:
        raise MetricsDeclarationError(f"goal_points(): expected one list of (x, y) per robot ({num_robots}), "
                                      f"got {len(points)}")
    result = []
    for robot, robot_points in enumerate(points):
        pairs = np.asarray(robot_points, dtype=float).reshape(-1, 2)
        if pairs.shape[0] > MAX_GOAL_POINTS_PER_ROBOT:
            raise MetricsDeclarationError(f"goal_points()[{robot}]: {pairs.shape[0]} points; at most "
                                          f"{MAX_GOAL_POINTS_PER_ROBOT} a robot")
        result.append([[_finite(x, f"goal_points()[{robot}]"), _finite(y, f"goal_points()[{robot}]")]
                       for x, y in pairs])
    return result


def evaluate(robot_class, config, steps, poses):
    """What the class declares, evaluated on one run: the OUTPUT document."""
    declared = [name for name in ("goal_points", "metrics", "goal") if callable(getattr(robot_class, name, None))]
    run = RunRecord(steps, poses, config)
    run.goal_points = _goal_points(robot_class, config, run.num_robots)
    metrics, answer = declared_metrics(robot_class, run)
    judged = robot_class.goal(run, answer) if "goal" in declared else None
    goal = None if judged is None else _goal_entry(judged)  # None: no goal declared for this run
    return {"declared": declared, "metrics": metrics, "goal": goal, "goal_points": run.goal_points}


def declared_metrics(robot_class, run):
    """The class's metrics() on `run`: (metrics.json's entries, what metrics() returned); ({}, {})
    when it declares none."""
    metrics, answer = {}, {}
    if callable(getattr(robot_class, "metrics", None)):
        answer = robot_class.metrics(run)
        if not isinstance(answer, dict):
            raise MetricsDeclarationError(f"metrics(): expected a dict of name -> value, got {answer!r}")
        for name, value in answer.items():
            if not isinstance(name, str) or not name.replace("_", "").isalnum():
                raise MetricsDeclarationError(f"metrics(): names are identifiers like 'final_error_m', got {name!r}")
            if name in RESERVED_NAMES:
                raise MetricsDeclarationError(f"metrics(): '{name}' is taken by summary.json's own fields "
                                              f"({', '.join(RESERVED_NAMES)}); pick another name")
            metrics.update(_metric_entries(name, value, run))
    return metrics, answer


def declared_goal_points(robot_class, config, num_robots):
    """Only the goal points (before a run, to draw them): the --goal-points OUTPUT document."""
    declared = callable(getattr(robot_class, "goal_points", None))
    return {"declared": declared, "goal_points": _goal_points(robot_class, config, num_robots)}


def _read_header(file, path, keys):
    header_line = file.readline(MAX_HEADER_BYTES)
    try:
        header = json.loads(header_line)
        values = {name: int(header[name]) for name in keys}
    except (ValueError, KeyError, TypeError) as error:
        raise ValueError(f"{path}: bad header line {header_line[:200]!r}: {error}") from None
    if values["spec_bytes"] < 0 or not 1 <= values["robots"] <= MAX_ROBOTS:
        raise ValueError(f"{path}: bad header {header}")
    return values


def _read_goal_points_input(path):
    with open(path, "rb") as file:
        header = _read_header(file, path, ("spec_bytes", "robots"))
        spec = file.read(header["spec_bytes"])
        if len(spec) != header["spec_bytes"]:
            raise ValueError(f"{path}: cut short: expected {header['spec_bytes']} bytes of spec")
    return spec.decode("utf-8"), header["robots"]


def _read_input(path):
    with open(path, "rb") as file:
        header = _read_header(file, path, ("spec_bytes", "steps", "robots"))
        spec_text = file.read(header["spec_bytes"]).decode("utf-8")
        count, robots = header["steps"], header["robots"]
        if count < 0:
            raise ValueError(f"{path}: bad header {header}")
        steps = np.frombuffer(file.read(8 * count), dtype=np.int64)
        poses = np.frombuffer(file.read(8 * count * robots * 3), dtype=np.float64)
        if steps.size != count or poses.size != count * robots * 3:
            raise ValueError(f"{path}: cut short: expected {count} steps of {robots} robots")
    return spec_text, steps, poses.reshape(count, robots, 3)


def _document(argv):
    """What OUTPUT receives, for either mode."""
    if argv[1] == "--goal-points":
        spec_text, robots = _read_goal_points_input(argv[2])
        spec = ControllerSpec.from_json(spec_text)
        work = lambda: declared_goal_points(spec.robot_class, spec.config, robots)  # noqa: E731
    else:
        spec_text, steps, poses = _read_input(argv[1])
        spec = ControllerSpec.from_json(spec_text)
        work = lambda: evaluate(spec.robot_class, spec.config, steps, poses)  # noqa: E731
    try:
        return work()
    except MetricsDeclarationError as error:
        raise MetricsDeclarationError(f"{spec.module_path}: {spec.robot_class.__name__}.{error}") from None


def main(argv):
    if len(argv) != 3 and not (len(argv) == 4 and argv[1] == "--goal-points"):
        print("usage: run_metrics.py [--goal-points] INPUT OUTPUT", file=sys.stderr)
        return 2
    try:
        document = _document(argv)
    except Exception as error:  # every failure becomes metrics.error in summary.json
        import traceback
        frames = [f for f in traceback.extract_tb(error.__traceback__) if not f.filename.endswith("run_metrics.py")]
        where = f" ({frames[-1].filename}:{frames[-1].lineno})" if frames else ""
        print(f"{type(error).__name__}: {error}{where}", file=sys.stderr)
        return 1
    with open(argv[-1], "w", encoding="utf-8") as out:
        json.dump(document, out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
