"""The controller a script run's config names (`dream run SCRIPT.py` writes it): the robots of such
a run are driven by the script itself, one agent for all of them, never by this class. A config
of a script run given to `dream run CONFIG` gets its robots stopped with this message.

It is also where the run's goal is judged (docs/robotarium-scripts.md#the-goal), after the run,
on its logged (true) poses, as every Python controller's goal is (python/dream/run_metrics.py):

- `goal_points: [[x, y], ...]` or `goal_poses: [[x, y, theta], ...]`, one per robot, with
  `position_error` (and for poses `rotation_error`), the official at_position / at_pose
  defaults (0.05 m, 0.2 rad): the robots must end within them, as those checks decide;
- else the script's own last at_pose / at_position check (its targets, robots and tolerances),
  which DREAM's rps writes to `goal_record` in the run folder when the script ends the run;
- else (no key, no check) no goal is declared.
"""

import json
import math
import os

import numpy as np

from dream import Robot, key

MAX_RECORD_BYTES = 1 << 20  # 50 robots' targets take a few kB


class GoalError(ValueError):
    """A goal key, or the script's goal record, DREAM cannot judge by."""


def _targets(value, name, num_robots, width):
    if not isinstance(value, list) or len(value) != num_robots:
        count = len(value) if isinstance(value, list) else repr(value)
        raise GoalError(f"controller.{name}: expected one {'[x, y, theta]' if width == 3 else '[x, y]'} per robot "
                        f"({num_robots}), got {count}")
    for i, target in enumerate(value):
        ok = isinstance(target, (list, tuple)) and len(target) == width and all(
            isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) for v in target)
        if not ok:
            raise GoalError(f"controller.{name}[{i}]: expected {width} finite numbers, got {target!r}")
    return [[float(v) for v in target] for target in value]


def _recorded_goal(path, num_robots):
    """The script's last check as DREAM's rps wrote it (None: it made none), checked."""
    if not path or not os.path.isfile(path):
        return None
    if os.path.getsize(path) > MAX_RECORD_BYTES:
        raise GoalError(f"{path}: over {MAX_RECORD_BYTES} bytes: not a goal record")
    with open(path, encoding="utf-8") as file:
        try:
            last = json.load(file).get("last_check")
        except (ValueError, AttributeError) as error:
            raise GoalError(f"{path}: not a goal record: {error}") from None
    if last is None:
        return None
    try:
        check, robots = last["check"], [int(r) for r in last["robots"]]
        width = {"at_pose": 3, "at_position": 2}[check]
        targets = _targets(last["targets"], "targets", len(robots), width)
        position_error = float(last["position_error"])
        rotation_error = float(last["rotation_error"]) if width == 3 else None
        offset = last.get("point_offset_m")
        offset = None if offset is None else [float(v) for v in offset]
        if offset is not None and (len(offset) != 2 or not all(np.isfinite(v) and abs(v) <= 1.0 for v in offset)):
            raise ValueError(f"point_offset_m {offset}: expected two finite numbers within 1 m")
    except (KeyError, TypeError, ValueError) as error:
        raise GoalError(f"{path}: not a goal record: {error!r}") from None
    if not robots or any(r < 0 or r >= num_robots for r in robots) or len(set(robots)) != len(robots):
        raise GoalError(f"{path}: robots {robots} are not distinct robots of this run (0..{num_robots - 1})")
    source = f"the script's last {check} check"
    if offset is not None:
        source += f" (of the point {offset[0]:g} m ahead, {offset[1]:g} m left of each robot, as it checked)"
    return {"source": source, "robots": robots, "targets": np.array(targets),
            "position_error": position_error, "rotation_error": rotation_error, "point_offset_m": offset}


def _checked_points(poses, offset):
    """(steps, k, 2): the point of each pose the goal holds, its centre or `offset` (forward, left) from it."""
    if offset is None:
        return poses[:, :, :2]
    cos, sin = np.cos(poses[:, :, 2]), np.sin(poses[:, :, 2])
    return np.stack([poses[:, :, 0] + offset[0] * cos - offset[1] * sin,
                     poses[:, :, 1] + offset[0] * sin + offset[1] * cos], axis=2)


class RobotariumScript(Robot):
    KEYS = {"goal_points": key([], kind="list"),     # [x m, y m] per robot: judged as at_position
            "goal_poses": key([], kind="list"),      # [x m, y m, theta rad] per robot: judged as at_pose
            "position_error": key(0.05, above=0.0),  # m, for goal_points / goal_poses
            "rotation_error": key(0.2, above=0.0),   # rad, for goal_poses
            "goal_record": key("", kind="string")}   # written by dream run: where the script's last check goes

    def setup(self):
        self.declared_goal(self.config, self.num_robots, keys_only=True)  # a bad goal key refused before the run

    def update(self, step):
        raise RuntimeError("this run's robots were driven by a Robotarium script: rerun it with "
                           "`dream run SCRIPT.py` (its config.yaml names the script under description)")

    @classmethod
    def declared_goal(cls, config, num_robots, keys_only=False):
        """The goal to judge by: {source, robots, targets (k x 2|3), position_error, rotation_error}, or None."""
        points, poses = config["goal_points"], config["goal_poses"]
        if points and poses:
            raise GoalError("controller.goal_points and controller.goal_poses: give one of them")
        if points or poses:
            name, width = ("goal_poses", 3) if poses else ("goal_points", 2)
            targets = _targets(poses or points, name, num_robots, width)
            return {"source": f"controller.{name}", "robots": list(range(num_robots)), "targets": np.array(targets),
                    "position_error": float(config["position_error"]),
                    "rotation_error": float(config["rotation_error"]) if poses else None}
        return None if keys_only else _recorded_goal(config["goal_record"], num_robots)

    @classmethod
    def goal_points(cls, config, num_robots):
        goal = cls.declared_goal(config, num_robots)
        points = [[] for _ in range(num_robots)]
        if goal is not None:
            for robot, target in zip(goal["robots"], goal["targets"]):
                points[robot] = [(target[0], target[1])]
        return points

    @classmethod
    def metrics(cls, run):
        goal = cls.declared_goal(run.config, run.num_robots)
        if goal is None:
            return {}
        poses = run.poses[:, goal["robots"], :]                                # (steps, k, 3)
        targets = goal["targets"]
        points = _checked_points(poses, goal.get("point_offset_m"))
        distance = np.linalg.norm(points - targets[np.newaxis, :, :2], axis=2)
        inside = distance <= goal["position_error"]
        metrics = {"goal_final_max_error_m": float(distance[-1].max())}
        if goal["rotation_error"] is not None:
            heading = np.abs(np.arctan2(np.sin(poses[:, :, 2] - targets[:, 2]), np.cos(poses[:, :, 2] - targets[:, 2])))
            inside &= heading <= goal["rotation_error"]
            metrics["goal_final_max_heading_error_rad"] = float(heading[-1].max())
        metrics["goal_reached_step"] = run.first_step_where(inside.all(axis=1))
        return metrics

    @classmethod
    def goal(cls, run, metrics):
        goal = cls.declared_goal(run.config, run.num_robots)
        if goal is None:
            return None  # no goal declared
        step = metrics["goal_reached_step"]
        within = f"{goal['position_error']:g} m"
        if goal["rotation_error"] is not None:
            within += f" and {goal['rotation_error']:g} rad"
        robots = len(goal["robots"])
        if step >= 0:
            detail = f"{goal['source']}: all {robots} robots within {within} from step {step} to the end"
        else:
            detail = (f"{goal['source']}: not all {robots} robots within {within} at the end, worst "
                      f"{metrics['goal_final_max_error_m']:.7g} m")
            if "goal_final_max_heading_error_rad" in metrics:
                detail += f" and {metrics['goal_final_max_heading_error_rad']:.4g} rad"
        detail += " on the logged (true) poses"
        return {"met": step >= 0, "completion_step": step, "detail": detail}
