"""DREAM over LCM: a Robotarium submission written by `dream export`.

Mark THIS file as main and upload it with the .npy files beside it.

This script is a fixed template: the same text for every run. It contains no
name, path or any other value of the run it reproduces; everything it needs is
read from the .npy files beside it, which hold only float64 numbers and are
loaded with allow_pickle=False. It uses only numpy, the Python standard library
and the Robotarium package (rps), as the lab provides them.

What it does:
  1. Robotarium(number_of_robots=N, initial_conditions=X0): the lab drives the
     robots to the plan's start poses (within its own tolerance).
  2. Settle: a short pose-control phase (bounded; dream_params.npy says how
     long) that brings every robot exactly onto its start pose.
  3. The experiment, one iteration per step: get_poses(), then either
     the recorded command (strategy "replay", open loop) or the recorded
     command plus feedback on the error to the recorded pose (strategy
     "track"), optionally passed through the Robotarium's barrier
     certificates, always scaled so no wheel exceeds its speed limit;
     or (strategy "controller") every robot's Python controller, shipped
     beside this script with DREAM's runtime (dream*.py), run on the poses
     just read, its commands sent as given; set_velocities(), step().
  4. Every pose read, every command sent and a wall-clock stamp per iteration go
     to dream_result.npy, rewritten every few hundred steps (a cut-short run
     still returns data), then debug() and one closing line.

Bring dream_result.npy back with `dream import` (see docs/robotarium.md).
"""

import json
import os
import re
import sys
import time

import numpy as np

import rps.robotarium as robotarium

# --- file names (fixed) -----------------------------------------------------
PARAMS_FILE = "dream_params.npy"
INITIAL_POSES_FILE = "dream_initial_poses.npy"
REFERENCE_POSES_FILE = "dream_reference_poses.npy"
REFERENCE_COMMANDS_FILE = "dream_reference_commands.npy"
CONTROLLER_SPEC_FILE = "dream_controller_spec.npy"
OBSTACLES_FILE = "dream_obstacles.npy"
RESULT_FILE = "dream_result.npy"
RESULT_PARTIAL_FILE = "dream_result.partial.npy"

# --- layout of dream_params.npy (bridge/include/dream/bridge/submission_format.h) ---
P_MAGIC = 0
P_FORMAT_VERSION = 1
P_NUM_ROBOTS = 2
P_STEPS = 3
P_STRATEGY = 4
P_BARRIERS = 5
P_SETTLE_MAX_STEPS = 6
P_SETTLE_POSITION_TOLERANCE = 7
P_SETTLE_HEADING_TOLERANCE = 8
P_SETTLE_GAIN_V = 9
P_SETTLE_GAIN_W = 10
P_GAIN_X = 11
P_GAIN_Y = 12
P_GAIN_THETA = 13
P_SAVE_EVERY_STEPS = 14
P_WHEEL_RADIUS = 15
P_BASE_LENGTH = 16
P_MAX_WHEEL_SPEED = 17
P_STOP_WHEN_DONE = 18
P_MAX_ABS_V = 19
P_MAX_ABS_W = 20
P_BARRIER_SAFETY_RADIUS = 21
P_BARRIER_GAIN = 22
P_BARRIER_PROJECTION_DISTANCE = 23
P_BARRIER_MAGNITUDE_LIMIT = 24
P_BARRIER_HAS_BOUNDARY = 25
# The certificate's boundary: x_min, x_max, y_min, y_max from here.
P_BARRIER_BOUNDARY = 26
P_COUNT = 30

MAGIC = 1146242369.0  # "DREA"
FORMAT_VERSION = 3.0
STRATEGY_REPLAY = 0.0
STRATEGY_TRACK = 1.0
STRATEGY_CONTROLLER = 2.0

# --- layout of dream_obstacles.npy: (steps + 1) x obstacles x O_COUNT ----------
# id, centre x and y, width and height, velocity x and y
O_ID = 0
O_CENTER = 1
O_SIZE = 3
O_VELOCITY = 5
O_COUNT = 7

# --- layout of dream_result.npy: one row per get_poses() ---------------------
# [phase, step, wall-clock s, x_0..x_N-1, y_0.., theta_0.., v_0.., w_0..]
# phase 0 = settle, 1 = experiment, 2 = the pose after the last step.
PHASE_SETTLE = 0.0
PHASE_EXPERIMENT = 1.0
PHASE_FINAL = 2.0
FIXED_COLUMNS = 3

# Wheel speeds are kept this far under the lab's limit, so the lab never sees
# an actuator error, whatever rounding the lab's own arithmetic does.
WHEEL_LIMIT_MARGIN = 1e-9


def fail(message):
    raise SystemExit("DREAM: " + message)


def data_path(name):
    """The data file `name`: in the working folder, else beside this script."""
    candidates = [name]
    try:
        candidates.append(os.path.join(os.path.dirname(os.path.abspath(__file__)), name))
    except NameError:
        pass
    for path in candidates:
        if os.path.isfile(path):
            return path
    fail("cannot find " + name + "; upload every .npy file of the export's upload/ folder with this script")


def read_npy(name):
    """The array in the data file `name`; a DREAM: message, not a traceback, when the file is
    damaged, cut short or no .npy at all. Never a pickle: one would run code."""
    try:
        return np.load(data_path(name), allow_pickle=False)
    except (ValueError, OSError, EOFError, MemoryError) as error:
        fail(name + " cannot be read as a .npy file of numbers (damaged, cut short, or a pickle, which is "
             "never loaded): " + str(error) + "; upload the export's file unchanged, or export the run again")


def load(name, shape):
    """A float64 array of exactly `shape`, all finite (never a pickle)."""
    array = read_npy(name)
    if array.dtype != np.float64 or array.shape != shape:
        fail(name + " has dtype " + str(array.dtype) + " and shape " + str(array.shape) +
             ", expected float64 " + str(shape) + "; export the run again")
    if not np.all(np.isfinite(array)):
        fail(name + " holds values that are not finite; export the run again")
    return array


def wrap(angle):
    return np.arctan2(np.sin(angle), np.cos(angle))


params = read_npy(PARAMS_FILE)
if params.dtype != np.float64 or params.shape != (P_COUNT,) or not np.all(np.isfinite(params)):
    fail(PARAMS_FILE + " is not a parameter file of this script version; export the run again")
if params[P_MAGIC] != MAGIC or params[P_FORMAT_VERSION] != FORMAT_VERSION:
    fail(PARAMS_FILE + " was written for another version of this script; export the run again")

N = int(params[P_NUM_ROBOTS])
STEPS = int(params[P_STEPS])
TRACK = params[P_STRATEGY] == STRATEGY_TRACK
CONTROLLER = params[P_STRATEGY] == STRATEGY_CONTROLLER
STOP_WHEN_DONE = params[P_STOP_WHEN_DONE] != 0.0
MAX_ABS_V = params[P_MAX_ABS_V]
MAX_ABS_W = params[P_MAX_ABS_W]
USE_BARRIERS = params[P_BARRIERS] != 0.0
BARRIER_SAFETY_RADIUS = params[P_BARRIER_SAFETY_RADIUS]
BARRIER_GAIN = params[P_BARRIER_GAIN]
BARRIER_PROJECTION_DISTANCE = params[P_BARRIER_PROJECTION_DISTANCE]
BARRIER_MAGNITUDE_LIMIT = params[P_BARRIER_MAGNITUDE_LIMIT]
BARRIER_BOUNDARY = (params[P_BARRIER_BOUNDARY:P_BARRIER_BOUNDARY + 4].copy()
                    if params[P_BARRIER_HAS_BOUNDARY] != 0.0 else None)
SETTLE_MAX_STEPS = int(params[P_SETTLE_MAX_STEPS])
SETTLE_POSITION_TOLERANCE = params[P_SETTLE_POSITION_TOLERANCE]
SETTLE_HEADING_TOLERANCE = params[P_SETTLE_HEADING_TOLERANCE]
SETTLE_GAIN_V = params[P_SETTLE_GAIN_V]
SETTLE_GAIN_W = params[P_SETTLE_GAIN_W]
GAIN_X = params[P_GAIN_X]
GAIN_Y = params[P_GAIN_Y]
GAIN_THETA = params[P_GAIN_THETA]
SAVE_EVERY_STEPS = max(int(params[P_SAVE_EVERY_STEPS]), 1)
WHEEL_RADIUS = params[P_WHEEL_RADIUS]
BASE_LENGTH = params[P_BASE_LENGTH]
WHEEL_LIMIT = params[P_MAX_WHEEL_SPEED] * (1.0 - WHEEL_LIMIT_MARGIN)
if not (1 <= N <= 50 and STEPS >= 1 and SETTLE_MAX_STEPS >= 0 and WHEEL_RADIUS > 0 and BASE_LENGTH > 0 and
        WHEEL_LIMIT > 0 and (not CONTROLLER or (MAX_ABS_V > 0 and MAX_ABS_W > 0)) and
        (not USE_BARRIERS or (BARRIER_SAFETY_RADIUS > 0 and BARRIER_GAIN > 0 and BARRIER_PROJECTION_DISTANCE > 0 and
                              BARRIER_MAGNITUDE_LIMIT > 0))):
    fail(PARAMS_FILE + " holds values out of range; export the run again")

x0 = load(INITIAL_POSES_FILE, (3, N))
if not CONTROLLER:
    reference_poses = load(REFERENCE_POSES_FILE, (STEPS + 1, 3, N))
    reference_commands = load(REFERENCE_COMMANDS_FILE, (STEPS, 2, N))


def limit_wheels(dxu):
    """Scales each robot's (v, w) so neither wheel exceeds the limit (keeps the curvature)."""
    left = (1.0 / (2.0 * WHEEL_RADIUS)) * (2.0 * dxu[0, :] - BASE_LENGTH * dxu[1, :])
    right = (1.0 / (2.0 * WHEEL_RADIUS)) * (2.0 * dxu[0, :] + BASE_LENGTH * dxu[1, :])
    fastest = np.maximum(np.abs(left), np.abs(right))
    scale = np.where(fastest > WHEEL_LIMIT, WHEEL_LIMIT / np.maximum(fastest, WHEEL_LIMIT), 1.0)
    return dxu * scale


def saturate(dxu):
    """The velocities a robot drives with for a command: the Robotarium's _threshold (wheel
    speeds clipped one by one), the same arithmetic as the official simulator and DREAM's."""
    left = (1 / (2 * WHEEL_RADIUS)) * (2 * dxu[0, :] - BASE_LENGTH * dxu[1, :])
    right = (1 / (2 * WHEEL_RADIUS)) * (2 * dxu[0, :] + BASE_LENGTH * dxu[1, :])
    limit = params[P_MAX_WHEEL_SPEED]
    left = np.where(np.abs(left) > limit, limit * np.sign(left), left)
    right = np.where(np.abs(right) > limit, limit * np.sign(right), right)
    return np.vstack([(WHEEL_RADIUS / 2) * (left + right), (WHEEL_RADIUS / BASE_LENGTH) * (right - left)])


def settle_commands(x):
    """Pose control onto x0: drive to the point (forwards or backwards), then turn on the spot."""
    dx = x0[0, :] - x[0, :]
    dy = x0[1, :] - x[1, :]
    distance = np.hypot(dx, dy)
    alpha = wrap(np.arctan2(dy, dx) - x[2, :])
    backwards = np.abs(alpha) > np.pi / 2.0
    alpha = np.where(backwards, wrap(alpha + np.pi), alpha)
    heading_error = wrap(x0[2, :] - x[2, :])
    near = distance <= SETTLE_POSITION_TOLERANCE
    v = np.where(near, 0.0, np.where(backwards, -1.0, 1.0) * SETTLE_GAIN_V * distance * np.cos(alpha))
    w = np.where(near, SETTLE_GAIN_W * heading_error, SETTLE_GAIN_W * alpha)
    settled = near & (np.abs(heading_error) <= SETTLE_HEADING_TOLERANCE)
    v = np.where(settled, 0.0, v)
    w = np.where(settled, 0.0, w)
    return np.vstack([v, w]), bool(np.all(settled))


def track_commands(x, k):
    """Recorded command plus feedback on the error to the recorded pose (Kanayama et al. 1990)."""
    reference = reference_poses[k]
    v_ref = reference_commands[k, 0, :]
    w_ref = reference_commands[k, 1, :]
    dx = reference[0, :] - x[0, :]
    dy = reference[1, :] - x[1, :]
    cos_theta = np.cos(x[2, :])
    sin_theta = np.sin(x[2, :])
    error_x = cos_theta * dx + sin_theta * dy
    error_y = -sin_theta * dx + cos_theta * dy
    error_theta = wrap(reference[2, :] - x[2, :])
    v = v_ref * np.cos(error_theta) + GAIN_X * error_x
    w = w_ref + GAIN_Y * v_ref * error_y + GAIN_THETA * np.sin(error_theta)
    return np.vstack([v, w])


MODULE_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*[.]py")


class Controllers:
    """Every robot's RobotAgent from DREAM's runtime (the dream*.py files beside this script),
    built from dream_controller_spec.npy: the same agents, seeds and parts as in the simulated
    run. step(k, x) runs them all on the poses x and returns their commands (2 x N)."""

    def __init__(self):
        spec_array = read_npy(CONTROLLER_SPEC_FILE)
        if spec_array.dtype != np.uint8 or spec_array.ndim != 1:
            fail(CONTROLLER_SPEC_FILE + " is not the bytes of a controller spec; export the run again")
        try:
            spec = json.loads(spec_array.tobytes().decode("utf-8"))
            module = spec["module"]
        except (ValueError, KeyError, TypeError):
            fail(CONTROLLER_SPEC_FILE + " does not hold a controller spec; export the run again")
        except RecursionError:  # JSON nested deeper than Python's recursion limit
            fail(CONTROLLER_SPEC_FILE + " holds JSON nested too deeply to be a controller spec; export the run again")
        # The module is a file beside this script, under a plain name the export checked.
        if not isinstance(module, str) or not MODULE_NAME.fullmatch(module) or module.startswith("dream"):
            fail(CONTROLLER_SPEC_FILE + " names a controller module that is not a plain module file name")
        spec["module"] = os.path.abspath(data_path(module))
        folder = os.path.dirname(spec["module"])
        if folder not in sys.path:
            sys.path.insert(0, folder)  # DREAM's runtime (dream.py, dream_*.py) sits beside the module
        import dream
        self.dream = dream
        try:
            controller_spec = dream.ControllerSpec.from_json(json.dumps(spec))
        except dream.ConfigError as error:
            fail("the controller's config: %s" % error)
        if controller_spec.num_robots != N:
            fail(CONTROLLER_SPEC_FILE + " is for %d robots, not %d; export the run again" %
                 (controller_spec.num_robots, N))
        obstacles = read_npy(OBSTACLES_FILE)
        if (obstacles.dtype != np.float64 or obstacles.ndim != 3 or obstacles.shape[0] != STEPS + 1 or
                obstacles.shape[2] != O_COUNT or not np.all(np.isfinite(obstacles))):
            fail(OBSTACLES_FILE + " is not (steps + 1) x obstacles x %d finite numbers; export the run again" %
                 O_COUNT)
        self.obstacles = obstacles
        self.agents = []
        self.faults = [None] * N
        for i in range(N):
            try:
                self.agents.append(controller_spec.make_agent(i))
            except dream.ControllerFault as fault:
                self.agents.append(None)
                self.fail_robot(i, 0, fault)
        self.done = [False] * N
        self.velocities = np.zeros((N, 2))  # driven during the previous step, after saturation

    def fail_robot(self, i, k, fault):
        self.faults[i] = str(fault)
        print("DREAM: robot %d holds still from step %d on: its controller failed: %s" % (i, k, fault))

    def obstacle_views(self, k):
        return [self.dream.ObstacleView(int(o[O_ID]), o[O_CENTER:O_CENTER + 2], o[O_SIZE:O_SIZE + 2],
                                        o[O_VELOCITY:O_VELOCITY + 2]) for o in self.obstacles[k]]

    def step(self, k, x):
        """Every live robot's command for step k; radio broadcasts reach the others for step k + 1."""
        snapshot = self.dream.WorldSnapshot(k, x[:3, :].T.copy(), self.velocities.copy(), self.obstacle_views(k))
        dxu = np.zeros((2, N))
        broadcasts = []
        for i, agent in enumerate(self.agents):
            if self.faults[i] is not None:
                continue
            try:
                out = agent.step(snapshot)
            except self.dream.ControllerFault as fault:
                self.fail_robot(i, k, fault)
                continue
            self.done[i] = out.done
            # As the simulator: a command that is not finite or beyond its limits holds the robot still.
            if np.isfinite(out.v) and np.isfinite(out.w) and abs(out.v) <= MAX_ABS_V and abs(out.w) <= MAX_ABS_W:
                dxu[0, i] = out.v
                dxu[1, i] = out.w
            if out.broadcast is not None:
                broadcasts.append(self.dream.RadioMessage(i, k, out.broadcast))
        for message in broadcasts:
            for agent in self.agents:
                if agent is not None:
                    agent.receive(message)
        return dxu

    def drove(self, dxu):
        self.velocities = saturate(dxu).T

    def all_done(self):
        return all(self.done)


controllers = Controllers() if CONTROLLER else None
log = np.zeros((SETTLE_MAX_STEPS + STEPS + 1, FIXED_COLUMNS + 5 * N))
rows = 0


def record(phase, step, x, dxu):
    global rows
    row = log[rows]
    row[0] = phase
    row[1] = step
    row[2] = time.time()
    row[FIXED_COLUMNS:FIXED_COLUMNS + 3 * N] = x[:3, :].reshape(-1)
    row[FIXED_COLUMNS + 3 * N:] = dxu.reshape(-1)
    rows += 1


def save():
    """Writes the rows so far; a reader sees the previous file or the new one, never half of one."""
    np.save(RESULT_PARTIAL_FILE, log[:rows])
    os.replace(RESULT_PARTIAL_FILE, RESULT_FILE)


ids = np.arange(N)
no_command = np.zeros((2, N))
r = robotarium.Robotarium(number_of_robots=N, show_figure=False, initial_conditions=x0.copy(),
                          sim_in_real_time=False)
barrier = None
if USE_BARRIERS:
    # The certificate the simulated run applied (config barriers:, or dream export --barriers).
    from rps.utilities import barrier_certificates
    if BARRIER_BOUNDARY is not None:
        barrier = barrier_certificates.create_uni_barrier_certificate_with_boundary(
            safety_radius=BARRIER_SAFETY_RADIUS, barrier_gain=BARRIER_GAIN,
            projection_distance=BARRIER_PROJECTION_DISTANCE, velocity_magnitude_limit=BARRIER_MAGNITUDE_LIMIT,
            boundary_points=BARRIER_BOUNDARY)
    else:
        barrier = barrier_certificates.create_uni_barrier_certificate(
            barrier_gain=BARRIER_GAIN, safety_radius=BARRIER_SAFETY_RADIUS,
            projection_distance=BARRIER_PROJECTION_DISTANCE, velocity_magnitude_limit=BARRIER_MAGNITUDE_LIMIT)

settle_steps = 0
completed = 0
try:
    x = r.get_poses()
    while settle_steps < SETTLE_MAX_STEPS:
        dxu, settled = settle_commands(x)
        if settled:
            break
        dxu = limit_wheels(dxu)
        r.set_velocities(ids, dxu)
        record(PHASE_SETTLE, settle_steps, x, dxu)
        r.step()
        settle_steps += 1
        x = r.get_poses()

    for k in range(STEPS):
        if CONTROLLER:
            # As the controllers gave them: the Robotarium saturates the wheels as the simulator did.
            dxu = controllers.step(k, x)
        else:
            dxu = track_commands(x, k) if TRACK else reference_commands[k].copy()
        if barrier is not None:
            dxu = barrier(dxu, x)
        if not CONTROLLER or barrier is not None:
            dxu = limit_wheels(dxu)
        r.set_velocities(ids, dxu)
        record(PHASE_EXPERIMENT, k, x, dxu)
        r.step()
        completed = k + 1
        if CONTROLLER:
            controllers.drove(dxu)
        x = r.get_poses()
        if completed % SAVE_EVERY_STEPS == 0:
            save()
        if CONTROLLER and STOP_WHEN_DONE and controllers.all_done():
            break
    record(PHASE_FINAL, completed, x, no_command)
finally:
    save()

r.debug()
if CONTROLLER and any(fault is not None for fault in controllers.faults):
    print("DREAM: held still after their controller failed (see above): robots %s" %
          ", ".join(str(i) for i, fault in enumerate(controllers.faults) if fault is not None))
print("DREAM: finished: %d robots, %d experiment steps after %d settle steps; poses saved to %s" %
      (N, completed, settle_steps, RESULT_FILE))
