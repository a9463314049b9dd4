"""The goal of a script's run as the script itself checks it (docs/robotarium-scripts.md#the-goal).

Robotarium scripts end their main loop on an at_pose or at_position check
(`while not at_position(x, goal_points)[0]: ...`). DREAM's Robotarium hears every such check
(dream.misc.listen_to_checks) and keeps the last one: which robots, their targets and the
tolerances. When the script ends the run (debug(), call_at_scripts_end(), its exit or its error)
that check is written to RECORD_NAME in the run folder, before the world hears the end, and the
run's judge (robotarium_script.py's RobotariumScript.goal) holds the robots' logged poses to it
(the same point of each robot the script checked: its centre, or the point uni_to_si_states puts
ahead of it).
"""

import json
import os

import numpy as np

RECORD_NAME = "script_goal.json"  # workflows::ScriptRunWorkflow::kGoalRecordName


OFFSET_AGREEMENT_M = 1e-9  # the same point of every robot: rps's projections are exact, estimates are not


def _point_offset(states, poses, robots):
    """The point of each robot the check's states are, in the robot's own frame (forward, left), when
    it is the same point for every robot and not its centre: the checks scripts make on
    uni_to_si_states(x), a point projection_distance ahead. None: the states are the robots' centres,
    or estimates of them (judged on the centres, as the script meant)."""
    if poses is None or poses.shape[0] < 3 or states.shape[0] < 2:
        return None
    centre = poses[:2, robots]
    heading = poses[2, robots]
    dx, dy = states[0] - centre[0], states[1] - centre[1]
    forward = np.cos(heading) * dx + np.sin(heading) * dy
    left = -np.sin(heading) * dx + np.cos(heading) * dy
    if not (np.ptp(forward) <= OFFSET_AGREEMENT_M and np.ptp(left) <= OFFSET_AGREEMENT_M):
        return None
    offset = [round(float(np.mean(forward)), 9) + 0.0, round(float(np.mean(left)), 9) + 0.0]  # 0.05, not 0.04999..
    return None if np.hypot(*offset) <= OFFSET_AGREEMENT_M else offset


def _robots_of(states, poses):
    """The robot of each column of `states` (the check's first argument): the column of the poses
    get_poses() last gave that it equals; failing that, robots 0..N-1 when it has one column per
    robot (an estimate of every robot, in order); else None (the check cannot be tied to robots)."""
    columns = states.shape[1]
    if poses is not None and poses.shape[0] >= 2:
        robots = []
        for column in range(columns):
            same = np.flatnonzero((poses[0] == states[0, column]) & (poses[1] == states[1, column]))
            if same.size != 1:
                break
            robots.append(int(same[0]))
        if len(robots) == columns and len(set(robots)) == columns:
            return robots
        if poses.shape[1] == columns:
            return list(range(columns))
    return None


class ScriptGoal:
    """The script's last at_pose/at_position check, written to the run folder at the run's end."""

    def __init__(self, run_dir):
        self.path = os.path.join(run_dir, RECORD_NAME) if run_dir else ""
        self.poses = None   # what get_poses() gave last
        self.last = None    # the last check, as written
        self.checks = 0
        if self.path and os.path.lexists(self.path):
            os.remove(self.path)  # an earlier run's, in a folder run again

    def on_check(self, check, states, targets, position_error, rotation_error):
        """dream.misc's listener: keeps the check when it can be tied to the run's robots."""
        self.checks += 1
        robots = _robots_of(np.asarray(states, dtype=float), self.poses)
        if robots is None:
            self.last = None
            return
        rows = 3 if check == "at_pose" else 2
        targets = np.asarray(targets, dtype=float)
        offset = _point_offset(np.asarray(states, dtype=float), self.poses, robots) if rows == 2 else None
        self.last = {"check": check, "robots": robots, "point_offset_m": offset,
                     "targets": [[float(v) for v in targets[:rows, k]] for k in range(targets.shape[1])],
                     "position_error": float(position_error),
                     "rotation_error": None if rotation_error is None else float(rotation_error),
                     "checks": self.checks}

    def save(self):
        """Writes the last check (none: the script made none DREAM could tie to its robots), atomically."""
        if not self.path:
            return
        record = {"last_check": self.last, "checks": self.checks}
        temporary = self.path + ".partial"
        with open(temporary, "w", encoding="utf-8") as file:
            json.dump(record, file)
        os.replace(temporary, self.path)
