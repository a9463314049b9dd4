"""rps.robotarium for `dream run SCRIPT.py`: the official V2.0.0 Robotarium, backed by DREAM's world.

The constructor does what the official one does, in the script's process and in the official
order: it draws the charger slots (Python's `random`), the default initial conditions (numpy's
global stream) and drives the robots onto the initial conditions (the start-up drive, with the
sensors' readings of every step, with their draws from numpy's stream) on the stand-in's step, which is the
official one (bridge/python/standin/rps). Then it tells `dream run` the number of robots and
where the drive ended (a JSON line on the descriptor DREAM_SCRIPT_FD), and DREAM's world takes
over from those poses: get_poses() returns the world's poses of the next step (the lab's, with
world.realism), step() sends every robot's command of that step (DREAM_CMD_<id>).

The official checks and error counts are kept in the script too (the stand-in's: the poses the
script saw, the velocities it set), so debug() prints the official text; DREAM's verdict, on
the world's own poses, is what `dream run` prints and writes to summary.json.
"""

import atexit
import importlib.util
import json
import os

import numpy as np

import rps
from rps._script_goal import ScriptGoal
from rps._world_link import WorldGone, WorldLink
from rps.robotarium_constants import RobotariumConstants

HELLO_FD_VARIABLE = "DREAM_SCRIPT_FD"
_made = []  # the one Robotarium of this script


class NotInDream(RuntimeError):
    """A call of the official API that DREAM's rps does not provide."""


def _standin_class():
    """The stand-in's Robotarium (its official step, checks and start-up drive), privately loaded."""
    path = os.path.join(rps.STANDIN_DIR, "robotarium.py")
    spec = importlib.util.spec_from_file_location("rps._standin_robotarium", path)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module.Robotarium


class _NoFigure:
    """What show_figure=True gives without matplotlib (r._fig, r._axes_handle): every attribute, call, index and
    arithmetic accepted (a script's own marker sizes from fig.dpi and friends), nothing drawn.
    It unpacks as one artist (`line, = ax.plot(...)`)."""

    def __getattr__(self, _name):
        return self

    def __call__(self, *_args, **_kwargs):
        return self

    def __getitem__(self, _key):
        return self

    def __iter__(self):
        return iter((self,))

    def __format__(self, _spec):
        return ""

    def _same(self, *_args):
        return self

    __add__ = __radd__ = __sub__ = __rsub__ = __mul__ = __rmul__ = _same
    __truediv__ = __rtruediv__ = __floordiv__ = __rfloordiv__ = __pow__ = __rpow__ = __neg__ = _same


def _offscreen_figure(boundaries):
    """r._fig and r._axes_handle for show_figure=True: the official figure's size, axes and limits, on
    matplotlib's Agg canvas, never shown (a script's artists, sizes and redraws work as with the official,
    nothing reaches the screen); without matplotlib, stand-ins that accept everything."""
    try:
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure
    except ImportError:
        return _NoFigure(), _NoFigure()
    padding, scale = 0.05, 2.5  # the official _initialize_visualization's
    b = boundaries
    figure = Figure(figsize=((b[1] - b[0] + 2 * padding) * scale, (b[3] - b[2] + 2 * padding) * scale))
    FigureCanvasAgg(figure)
    axes = figure.add_subplot()
    axes.set_aspect("equal")
    axes.set_xlim([b[0] - padding, b[1] + padding])
    axes.set_ylim([b[2] - padding, b[3] + padding])
    axes.axis("off")
    figure.subplots_adjust(left=0.01, right=0.99, bottom=0.01, top=0.99)
    return figure, axes


class Robotarium(RobotariumConstants):
    """Robotarium(number_of_robots=N, show_figure=..., initial_conditions=3xN, sim_in_real_time=..., ...)."""

    def __init__(self, **kwargs):
        if _made:
            raise NotInDream("Robotarium(...) a second time: `dream run` runs one Robotarium per script")
        local_class = _standin_class()
        self._local = local_class(number_of_robots=kwargs.get("number_of_robots", -1),
                                  show_figure=kwargs.get("show_figure", False),
                                  initial_conditions=kwargs.get("initial_conditions", np.array([])),
                                  sim_in_real_time=kwargs.get("sim_in_real_time", True),
                                  skip_initialization=kwargs.get("skip_initialization", False),
                                  use_distance_sensors=kwargs.get("use_distance_sensors", False),
                                  obstacles=kwargs.get("obstacles", None))
        _made.append(self)
        self.number_of_robots = self._local.number_of_robots
        self.show_figure = kwargs.get("show_figure", False)
        self.obstacles = self._local.obstacles
        self.initializing = False
        if self.show_figure:
            self._fig, self._axes_handle = _offscreen_figure(self.BOUNDARIES)
        self._link = WorldLink(self.number_of_robots)
        self._finished = False
        # The script's checks from here on (not the start-up drive's): its last one is the run's goal.
        # Made before the hello, so an earlier run's record in the folder is gone before the world starts.
        self._goal = ScriptGoal(os.environ.get("DREAM_RUN_DIR", ""))
        _toolbox_misc().listen_to_checks(self._goal.on_check)
        _tell_dream_run(self.number_of_robots, self._local._poses, self._local._iteration)
        atexit.register(self._finish)

    @property
    def velocities(self):
        return self._local._velocities

    @property
    def poses(self):
        return self._local._poses

    def get_poses(self):
        local = self._local
        if local._poses_read:
            raise AssertionError("Can only call get_poses() once per call of step()!")
        if self._finished:
            raise NotInDream("get_poses() after debug(): the run has ended")
        local._poses = self._link.next_poses()
        self._goal.poses = local._poses
        local._poses_read = True
        local._stepped = False
        return local._poses.copy()

    def set_velocities(self, ids, velocities):
        self._local.set_velocities(ids, velocities)

    def step(self):
        local = self._local
        if local._stepped:
            raise AssertionError("Make sure you call get_poses before calling step()!")
        local._stepped = True
        local._poses_read = False
        local._validate()
        local._iteration += 1
        # The command as set: the world saturates the wheels and counts actuator errors itself.
        self._link.send(local._velocities)
        local._velocities = local._saturate(local._velocities)
        # The sensors read where this step takes the robots by the official step from the poses the
        # script saw (under `ideal` the world's next poses), drawing their noise now, as the official;
        # those poses are worked out only if a getter needs them.
        seen, held = local._poses, local._velocities.copy()
        local._sensors.after_step(lambda: local._integrated(seen, held), held)

    def debug(self):
        self._local.debug()
        self._finish()

    def call_at_scripts_end(self):
        self.debug()

    def robot_colormap(self):
        """The official's: matplotlib's "tab20" colormap (a stand-in without matplotlib)."""
        try:
            from matplotlib import colormaps
        except ImportError:
            return _NoFigure()
        return colormaps["tab20"]

    def _finish(self):
        """Ends the run: the world's next step is answered with every robot done, standing still."""
        if self._finished:
            return
        self._finished = True
        self._save_goal()
        try:
            if self._link.answered:  # else the script read a step's poses and stopped before step()
                self._link.next_poses()
            self._link.send(np.zeros((2, self.number_of_robots)), done=True)
        except WorldGone:
            pass

    def fail(self, detail):
        """The script failed: the world is told every robot's controller failed."""
        self._finished = True
        self._save_goal()
        self._link.fail(detail)

    def _save_goal(self):
        """The script's last check, in the run folder before the world hears the end (it judges then)."""
        try:
            self._goal.save()
        except OSError as error:
            print(f"dream run: the script's goal could not be written ({error}); the run declares none")

    def get_distances(self):
        return self._local.get_distances()

    def get_distance_endpoints(self):
        return self._local.get_distance_endpoints()

    def get_accelerations(self):
        return self._local.get_accelerations()

    def get_orientations(self):
        return self._local.get_orientations()

    def get_magnetic_fields(self):
        return self._local.get_magnetic_fields()

    def get_gyros(self):
        return self._local.get_gyros()

    def get_encoders(self):
        return self._local.get_encoders()


def _toolbox_misc():
    """DREAM's one toolbox's misc module (python/dream/misc.py), which every rps.utilities.misc check runs."""
    from rps.utilities._dream_toolbox import dream_package
    return dream_package().misc


def made():
    """The script's Robotarium, or None."""
    return _made[0] if _made else None


def _tell_dream_run(n, poses, startup_steps):
    """The JSON line `dream run` builds the run from: the robots and where the start-up drive ended."""
    fd_text = os.environ.get(HELLO_FD_VARIABLE, "")
    if not fd_text.isdigit():
        raise NotInDream(f"no {HELLO_FD_VARIABLE}: DREAM's rps runs under `dream run SCRIPT.py`")
    hello = {"robots": n, "startup_steps": int(startup_steps),
             "initial_poses": [[float(v) for v in poses[:, i]] for i in range(n)]}
    with os.fdopen(int(fd_text), "w") as pipe:
        pipe.write(json.dumps(hello) + "\n")
