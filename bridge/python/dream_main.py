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
  3. The experiment, one iteration per recorded step: get_poses(), then either
     the recorded command (strategy "replay", open loop) or the recorded
     command plus feedback on the error to the recorded pose (strategy
     "track"), optionally passed through the Robotarium's barrier
     certificates, always scaled so no wheel exceeds its speed limit;
     set_velocities(), step().
  4. Every pose read, every command sent and a wall-clock stamp per iteration go
     to dream_result.npy, rewritten every few hundred steps (a cut-short run
     still returns data), then debug() and one closing line.

Bring dream_result.npy back with `dream import` (see docs/robotarium.md).
"""

import os
import time

import numpy as np

import rps.robotarium as robotarium

# --- file names (fixed) -----------------------------------------------------
PARAMS_FILE = "dream_params.npy"
INITIAL_POSES_FILE = "dream_initial_poses.npy"
REFERENCE_POSES_FILE = "dream_reference_poses.npy"
REFERENCE_COMMANDS_FILE = "dream_reference_commands.npy"
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
P_COUNT = 18

MAGIC = 1146242369.0  # "DREA"
FORMAT_VERSION = 1.0
STRATEGY_REPLAY = 0.0
STRATEGY_TRACK = 1.0

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


def load(name, shape):
    """A float64 array of exactly `shape`, all finite (never a pickle)."""
    array = np.load(data_path(name), allow_pickle=False)
    if array.dtype != np.float64 or array.shape != shape:
        fail(name + " has dtype " + str(array.dtype) + " and shape " + str(array.shape) +
             ", expected float64 " + str(shape) + "; export the run again")
    if not np.all(np.isfinite(array)):
        fail(name + " holds values that are not finite; export the run again")
    return array


def wrap(angle):
    return np.arctan2(np.sin(angle), np.cos(angle))


params = np.load(data_path(PARAMS_FILE), allow_pickle=False)
if params.dtype != np.float64 or params.shape != (P_COUNT,) or not np.all(np.isfinite(params)):
    fail(PARAMS_FILE + " is not a parameter file of this script version; export the run again")
if params[P_MAGIC] != MAGIC or params[P_FORMAT_VERSION] != FORMAT_VERSION:
    fail(PARAMS_FILE + " was written for another version of this script; export the run again")

N = int(params[P_NUM_ROBOTS])
STEPS = int(params[P_STEPS])
TRACK = params[P_STRATEGY] == STRATEGY_TRACK
USE_BARRIERS = params[P_BARRIERS] != 0.0
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
        WHEEL_LIMIT > 0):
    fail(PARAMS_FILE + " holds values out of range; export the run again")

x0 = load(INITIAL_POSES_FILE, (3, N))
reference_poses = load(REFERENCE_POSES_FILE, (STEPS + 1, 3, N))
reference_commands = load(REFERENCE_COMMANDS_FILE, (STEPS, 2, N))


def limit_wheels(dxu):
    """Scales each robot's (v, w) so neither wheel exceeds the limit (keeps the curvature)."""
    left = (1.0 / (2.0 * WHEEL_RADIUS)) * (2.0 * dxu[0, :] - BASE_LENGTH * dxu[1, :])
    right = (1.0 / (2.0 * WHEEL_RADIUS)) * (2.0 * dxu[0, :] + BASE_LENGTH * dxu[1, :])
    fastest = np.maximum(np.abs(left), np.abs(right))
    scale = np.where(fastest > WHEEL_LIMIT, WHEEL_LIMIT / np.maximum(fastest, WHEEL_LIMIT), 1.0)
    return dxu * scale


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
    from rps.utilities.barrier_certificates import create_uni_barrier_certificate_with_boundary
    barrier = create_uni_barrier_certificate_with_boundary()

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
        dxu = track_commands(x, k) if TRACK else reference_commands[k].copy()
        if barrier is not None:
            dxu = barrier(dxu, x)
        dxu = limit_wheels(dxu)
        r.set_velocities(ids, dxu)
        record(PHASE_EXPERIMENT, k, x, dxu)
        r.step()
        completed = k + 1
        x = r.get_poses()
        if completed % SAVE_EVERY_STEPS == 0:
            save()
    record(PHASE_FINAL, STEPS, x, no_command)
finally:
    save()

r.debug()
print("DREAM: finished: %d robots, %d experiment steps after %d settle steps; poses saved to %s" %
      (N, completed, settle_steps, RESULT_FILE))
