"""The controller's side of the runtime: the Robot base class, its parameters, the readings its
sensors hand it, and `key()` for declaring its own config keys.

Mirrors agents/include/dream/agents/{robot.h, robot_params.h, sensor_readings.h,
world_snapshot.h}. A Robot never sees the world: it knows only what its sensors report
through the on_* callbacks. Vectors a controller reads (poses, positions, velocities) are
numpy arrays, as Eigen vectors are in C++.
"""

import math
from collections import namedtuple

import numpy as np

from .drawing import NOTHING_DRAWN, Drawing
from .motion import ActuatorLimits, RobotLimits, dxi_to_dxu


class _Required:
    """The default of a key that has none: the config must give it."""

    __slots__ = ()

    def __repr__(self):
        return "REQUIRED"


REQUIRED = _Required()

KEY_KINDS = ("number", "int", "bool", "string", "points", "matrix", "list", "any")


class Key:
    """One own config key of a Robot subclass: its default, kind and allowed range (see `key`)."""

    __slots__ = ("default", "kind", "above", "at_least", "at_most", "below", "per_robot", "choices")

    def __init__(self, default, kind, above, at_least, at_most, below, per_robot, choices):
        if kind not in KEY_KINDS:
            raise ValueError(f"key kind must be one of {', '.join(KEY_KINDS)}, got {kind!r}")
        self.default = default
        self.kind = kind
        self.above = above
        self.at_least = at_least
        self.at_most = at_most
        self.below = below
        self.per_robot = per_robot
        self.choices = tuple(choices) if choices is not None else None

    @property
    def required(self):
        return self.default is REQUIRED


def key(default=REQUIRED, kind="number", above=None, at_least=None, at_most=None, below=None,
        per_robot=False, choices=None):
    """Declares an own config key in a Robot subclass's KEYS.

    `above`/`at_least`/`at_most`/`below` bound numbers (>, >=, <=, <); `per_robot` asks for a
    list with one entry per robot (for "points": one [x, y] per robot); `choices` lists the
    allowed values. Without a default the key is required.
    """
    return Key(default, kind, above, at_least, at_most, below, per_robot, choices)


def number_text(value):
    """A number as a person writes it ("-1", "0.2", "1e-07") for error messages, as C++'s NumberText."""
    if isinstance(value, float) and value.is_integer() and abs(value) < 1e16:
        return str(int(value))
    return repr(value)


def _edit_distance(a, b):
    """Insertions, deletions, replacements and swaps of neighbours from a to b."""
    d = [[i + j if i * j == 0 else 0 for j in range(len(b) + 1)] for i in range(len(a) + 1)]
    for i in range(1, len(a) + 1):
        for j in range(1, len(b) + 1):
            d[i][j] = min(d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1]))
            if i > 1 and j > 1 and a[i - 1] == b[j - 2] and a[i - 2] == b[j - 1]:
                d[i][j] = min(d[i][j], d[i - 2][j - 2] + 1)
    return d[len(a)][len(b)]


def did_you_mean(given, names):
    """" (did you mean 'x'?)" when `given` looks like a typo of one of `names`, else "": the same
    rules as C++'s config::DidYouMean (case, up to two edits, one for names of five letters or
    fewer, or the start of a name), so both languages answer a typo alike."""
    longest = 64
    if not given or len(given) > longest:
        return ""
    lower = given.lower()
    best, best_distance = None, None
    for name in names:
        if name == given or len(name) > longest:
            continue
        distance = _edit_distance(lower, name.lower())
        if distance <= (1 if min(len(given), len(name)) <= 5 else 2) and (best is None or distance < best_distance):
            best, best_distance = name, distance
    if best is None and len(given) >= 3:
        best = next((name for name in names if len(name) > len(given) and name.lower().startswith(lower)), None)
    return "" if best is None else f" (did you mean '{best}'?)"


class RobotParams:
    """Parameters every Robot has (agents/include/dream/agents/framework/robot_params.h)."""

    __slots__ = ("vel_gain", "ang_gain", "limits")

    def __init__(self, vel_gain=0.8, ang_gain=3.0, limits=None):
        self.vel_gain = vel_gain
        self.ang_gain = ang_gain
        self.limits = limits if limits is not None else RobotLimits()

    def check(self):
        """Raises ValueError naming the gain that is not a finite positive number."""
        for name in ("vel_gain", "ang_gain"):
            value = getattr(self, name)
            if not (value > 0.0 and math.isfinite(value)):
                raise ValueError(f"{name} must be > 0, got {number_text(value)}")


# The readings (but NeighbourDetection) and RadioMessage (radios.py) are namedtuples: read-only
# records, built by a sensor or radio and only read by the controller.
class OdometryReading(namedtuple("OdometryReading", ("step", "pose"))):
    """Own pose with the odometry's noise: np.array [x m, y m, theta rad]."""

    __slots__ = ()


class NeighbourDetection:
    """One neighbour a movement sensor saw: centre-to-centre distance, world-frame bearing from
    this robot to it, and the world-frame velocity (np.array) of its point 0.05 m ahead."""

    # A plain __slots__ class, not a namedtuple as the other readings: one is built per neighbour
    # per sensing and read by every HRVO update, and as a namedtuple sensing and reading them
    # measured 4-6% slower.
    __slots__ = ("distance_m", "bearing_rad", "velocity_mps")

    def __init__(self, distance_m, bearing_rad, velocity_mps):
        self.distance_m = distance_m
        self.bearing_rad = bearing_rad
        self.velocity_mps = velocity_mps

    def relative_position(self):
        """Neighbour centre minus own centre, world frame."""
        return np.array((self.distance_m * math.cos(self.bearing_rad), self.distance_m * math.sin(self.bearing_rad)))


class MovementReading(namedtuple("MovementReading", ("step", "neighbours"))):
    """Neighbours within range and field of view, in robot id order."""

    __slots__ = ()


class ObstacleRectangle(namedtuple("ObstacleRectangle", ("center_m", "size_m"))):
    """An obstacle's axis-aligned rectangle as an obstacle sensor sees it (np.arrays)."""

    __slots__ = ()


class ObstacleReading(namedtuple("ObstacleReading", ("step", "closest_points_m", "rectangles"))):
    """Closest point (np.array) of each obstacle within range, and its rectangle shifted by the
    same noise, in the same order."""

    __slots__ = ()


class ObstacleView:
    """A virtual rectangular obstacle as the world reports it (plain (x, y) pairs)."""

    __slots__ = ("id", "center_m", "size_m", "velocity_mps")

    def __init__(self, id, center_m, size_m, velocity_mps=(0.0, 0.0)):
        self.id = id
        self.center_m = (float(center_m[0]), float(center_m[1]))
        self.size_m = (float(size_m[0]), float(size_m[1]))
        self.velocity_mps = (float(velocity_mps[0]), float(velocity_mps[1]))


class WorldSnapshot:
    """The world at one step: poses (n, 3) [x, y, theta], velocities (n, 2) [v, w] driven during
    the previous step, obstacles (ObstacleView). Only sensors and radios read it.

    `pose_rows` and `velocity_rows` are the same numbers as lists of plain floats, made once per
    snapshot so that every agent's sensors index floats, not numpy scalars.
    """

    __slots__ = ("step", "poses", "velocities", "obstacles", "pose_rows", "velocity_rows")

    def __init__(self, step, poses, velocities, obstacles=()):
        self.step = step
        self.poses = poses
        self.velocities = velocities
        self.obstacles = obstacles
        self.pose_rows = _float_rows(poses)
        self.velocity_rows = _float_rows(velocities)

    @property
    def num_robots(self):
        return len(self.pose_rows)


def _float_rows(rows):
    if isinstance(rows, np.ndarray):
        return rows.tolist()
    return [[float(x) for x in row] for row in rows]


class Robot:
    """The thesis's Robot: one robot's controller (agents/include/dream/agents/framework/robot.h).

    The runtime builds it as Robot(robot_id, params, config, num_robots) and calls setup() once;
    subclasses implement update(step) -> (v, w) and, optionally, setup(), done(), on_radio() and
    the on_* sensor callbacks (whose defaults keep the latest reading). Per step the agent calls,
    only when due: sensors, then on_radio, then update. Own config keys are declared in KEYS
    with `key()`; their checked values are in self.config.
    """

    KEYS = {}

    UNKNOWN_SENDER = -1  # bad_radio_messages_by_sender's key for messages not at hand

    def __init__(self, robot_id, params, config, num_robots):
        if robot_id < 0:
            raise ValueError(f"robot id must be >= 0, got {robot_id}")
        params.check()
        self.id = robot_id
        self.num_robots = num_robots
        self.params = params
        self.config = config
        self.movement = MovementReading(0, [])
        self.obstacles = ObstacleReading(0, [], [])
        self.bad_radio_messages_by_sender = {}
        self._odometry = None
        self._actuator_limits = ActuatorLimits(params.limits)

    def setup(self):
        """Called once after construction; self.config holds the checked keys."""

    def on_odometry(self, reading):
        self._odometry = reading

    def on_movement(self, reading):
        self.movement = reading

    def on_obstacles(self, reading):
        self.obstacles = reading

    def on_radio(self, heard):
        """The latest message from each sender the radio hears (by sender id); returns the
        payload (bytes) to broadcast, or None to stay silent (the default)."""
        return None

    def update(self, step):
        """The control law: (v m/s, w rad/s) for this step."""
        raise NotImplementedError(f"{type(self).__name__} must implement update(step) -> (v, w)")

    def done(self):
        """True once the robot considers its task complete."""
        return False

    @property
    def bad_radio_messages(self):
        """Radio payloads this robot could not decode: the sum over bad_radio_messages_by_sender."""
        return sum(self.bad_radio_messages_by_sender.values())

    @property
    def has_odometry(self):
        return self._odometry is not None

    @property
    def pose(self):
        """Latest own pose np.array [x, y, theta]; zeros before the first odometry reading."""
        return self._odometry.pose if self._odometry is not None else np.zeros(3)

    def dxi_to_dxu(self, dxi):
        """The thesis's dxi_to_dxu at the latest odometry heading, with this robot's gains."""
        theta = float(self._odometry.pose[2]) if self._odometry is not None else 0.0
        return dxi_to_dxu(dxi, theta, self.params)

    def limit_actuators(self, command):
        """The thesis's actuator_limit for (v, w): a command the wheels can drive."""
        return self._actuator_limits.apply(command)

    # --- drawing: shown by dream view and dream render until the next update(); the world never reads it

    def _drawing(self):
        drawing = self.__dict__.get("_drawing_now")
        if drawing is None:
            drawing = self.__dict__["_drawing_now"] = Drawing()
        return drawing

    def take_drawing(self):
        """What the robot drew since the last call, handed over and cleared (the agent takes it
        each time update() runs)."""
        return self.__dict__.pop("_drawing_now", None) or NOTHING_DRAWN

    def draw_line(self, start, end, color="k", width=0.01, alpha=None):
        """A line from `start` to `end` ([x, y], metres, world frame); `color` a name, '#rrggbb[aa]'
        or (r, g, b[, a]); `width` in metres."""
        self._drawing().line(start, end, color, width, alpha)

    def draw_arrow(self, start, end, color="k", width=0.01, alpha=None):
        """An arrow from `start` to `end`, its head at `end`."""
        self._drawing().arrow(start, end, color, width, alpha)

    def draw_circle(self, center, radius, color="k", width=0.01, fill=False, alpha=None):
        self._drawing().circle(center, radius, color, width, fill, alpha)

    def draw_polygon(self, points, color="k", width=0.01, fill=False, alpha=None):
        """A closed polygon through `points` (3 to 64 corners)."""
        self._drawing().polygon(points, color, width, fill, alpha)

    def draw_text(self, at, text, color="k", height=0.06, alpha=None):
        """`text` with its lower left corner at `at`, `height` metres tall (96 UTF-8 bytes at most)."""
        self._drawing().text(at, text, color, height, alpha)

    def count_bad_radio_message(self, message=None):
        """Counts a radio message this robot could not decode (it is dropped); by its sender
        when the message is given."""
        sender = message.sender_id if message is not None else Robot.UNKNOWN_SENDER
        self.bad_radio_messages_by_sender[sender] = self.bad_radio_messages_by_sender.get(sender, 0) + 1
