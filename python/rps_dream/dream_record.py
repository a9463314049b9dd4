"""DREAM's recorder for a Robotarium script: the main file of `dream export SCRIPT.py`'s upload
(docs/robotarium-scripts.md#the-upload-dream-export-and-dream-check-submission).

It runs the script beside it, unchanged, as __main__, and saves every pose the script read
(get_poses()) with the command it sent at the step() after it to dream_result.npy, in the rows of
every DREAM export's result (docs/robotarium.md): phase (0 the start-up drive, 1 the experiment, 2
the pose after the last step), step, wall-clock seconds, then x, y, theta, v, w of every robot.
The file is rewritten every SAVE_EVERY rows and when the script ends (its end, sys.exit, or an
exception), so a run the lab stops still returns its rows. Beside it, dream_goal.json keeps the
script's last at_pose/at_position check (its targets, tolerances and robots), the goal DREAM judges a
script's run by (docs/robotarium-scripts.md#the-goal). `dream import dream_result.npy --export
EXPORT_DIR` reads both. It needs numpy and the lab's own rps only.
"""

import atexit
import inspect
import json
import runpy
import sys
import time

import numpy as np
import rps.robotarium as robotarium
import rps.utilities.misc as misc

SCRIPT = "__DREAM_SCRIPT__"  # dream export writes the script's file name here
RESULT = "dream_result.npy"
GOAL = "dream_goal.json"
SAVE_EVERY = 900

_rows = []
_steps = {0: 0, 1: 0}  # rows of each phase so far
_seen = {"poses": None, "robotarium": None, "last_poses": None}
_goal = {"last_check": None, "checks": 0}
_get_poses = robotarium.Robotarium.get_poses
_step = robotarium.Robotarium.step


def _attribute(robotarium_instance, name):
    """The official class's `poses` / `velocities` (a stand-in's `_poses` / `_velocities`), 3 x N / 2 x N."""
    value = getattr(robotarium_instance, name, None)
    if value is None:
        value = getattr(robotarium_instance, "_" + name)
    return np.array(value, dtype=float)


def _row(phase, step, poses, velocities):
    return np.concatenate(([phase, step, time.time()], poses[0], poses[1], poses[2], velocities[0], velocities[1]))


def _recorded_get_poses(self):
    poses = _get_poses(self)
    _seen["poses"] = np.array(poses, dtype=float)
    _seen["last_poses"] = _seen["poses"]
    _seen["robotarium"] = self
    return poses


def _recorded_step(self):
    if _seen["poses"] is not None:
        phase = 0 if getattr(self, "initializing", False) else 1
        _rows.append(_row(phase, _steps[phase], _seen["poses"], _attribute(self, "velocities")))
        _steps[phase] += 1
        _seen["poses"] = None
        if len(_rows) % SAVE_EVERY == 0:
            _save(final=False)
    _step(self)


def _robots_of(states):
    """The robot of each column of a check's states: the column of the last poses read it equals, else
    robots 0..N-1 when it has one column per robot, else None (as DREAM's rps ties them)."""
    poses = _seen["last_poses"]
    if poses is None:
        return None
    robots = []
    for column in range(states.shape[1]):
        same = np.flatnonzero((poses[0] == states[0, column]) & (poses[1] == states[1, column]))
        if same.size != 1:
            break
        robots.append(int(same[0]))
    if len(robots) == states.shape[1] and len(set(robots)) == len(robots):
        return robots
    return list(range(states.shape[1])) if poses.shape[1] == states.shape[1] else None


def _listening(make, check_name):
    """create_at_pose / create_at_position whose checks are kept: the script's last one is its goal."""
    signature = inspect.signature(make)

    def made(*args, **kwargs):
        bound = signature.bind(*args, **kwargs)
        bound.apply_defaults()
        check = make(*args, **kwargs)

        def checked(states, targets):
            answer = check(states, targets)
            made_by = _seen["robotarium"]
            if made_by is not None and not getattr(made_by, "initializing", False):
                _goal["checks"] += 1
                states, targets = np.asarray(states, dtype=float), np.asarray(targets, dtype=float)
                robots = _robots_of(states)
                rows = 3 if check_name == "at_pose" else 2
                _goal["last_check"] = None if robots is None else {
                    "check": check_name, "robots": robots,
                    "targets": [[float(v) for v in targets[:rows, k]] for k in range(targets.shape[1])],
                    "position_error": float(bound.arguments["position_error"]),
                    "rotation_error": float(bound.arguments["rotation_error"]) if rows == 3 else None}
            return answer

        return checked

    return made


def _save(final=True):
    rows = list(_rows)
    made = _seen["robotarium"]
    if final and made is not None and _steps[1] > 0:
        poses = _attribute(made, "poses")  # where the last step() took the robots
        rows.append(_row(2, _steps[1], poses, np.zeros((2, poses.shape[1]))))
    if rows:
        np.save(RESULT, np.array(rows, dtype=float))
    if final:
        with open(GOAL, "w") as file:
            json.dump(_goal, file)


misc.create_at_pose = _listening(misc.create_at_pose, "at_pose")
misc.create_at_position = _listening(misc.create_at_position, "at_position")
robotarium.Robotarium.get_poses = _recorded_get_poses
robotarium.Robotarium.step = _recorded_step
atexit.register(_save)

if __name__ == "__main__":
    sys.argv = [SCRIPT] + sys.argv[1:]
    runpy.run_path(SCRIPT, run_name="__main__")
