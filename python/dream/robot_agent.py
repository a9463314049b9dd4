"""One robot's agent, free of any transport (agents/src/robot_agent.cc): feed it the world each
step and the others' radio messages; it runs its parts when its Timer says so and returns the
command (the last one again when update did not run) and, if the radio spoke, the payload.

Both routes drive it: the LCM agent host and a Robotarium submission's main loop.
"""

import math
import os
import signal
import sys
import traceback

from .radios import MAX_PAYLOAD_BYTES, Mailbox
from .robot import Robot
from .timer import Timer


class ControllerFault(Exception):
    """A controller raised inside one of its callbacks; the text says where (see controller_error_text)."""


class RunInterrupted(BaseException):
    """The whole run is being interrupted (Ctrl-C / SIGTERM to the tool that embeds Python): raised
    inside a running controller by the embedding agent host (agents/python_embedded), it is never the
    controller's fault and passes through RobotAgent to end the run."""


class ControllerTimeout(BaseException):
    """Raised inside a controller callback that ran too long for the world (0.8 x its
    agent_timeout_s), by the embedding agent host's watchdog: the controller failed. A
    BaseException, so that a controller's own `except Exception` does not swallow it."""


def is_run_interrupt(exc):
    """True when `exc`, raised while a controller ran, ends the whole run rather than failing the
    controller: RunInterrupted, or a KeyboardInterrupt where Ctrl-C reaches Python as one (its
    default SIGINT handler: a plain script, such as a Robotarium submission). Where Python has no
    such handler (embedded in `dream run` / `dream agent`, whose Ctrl-C is the tool's), a
    KeyboardInterrupt can only be the controller's own doing, and fails it like SystemExit does."""
    if isinstance(exc, RunInterrupted):
        return True
    if not isinstance(exc, KeyboardInterrupt):
        return False
    try:
        return signal.getsignal(signal.SIGINT) is signal.default_int_handler
    except (ValueError, AttributeError):  # no signal support here
        return True


def controller_error_text(exc, user_file=None):
    """The text of a ControllerFault, `FILE:LINE: in FUNCTION: ExcType: message`, for the
    innermost traceback frame of `exc` in `user_file` (the controller's module), else for the
    innermost frame overall: the line a controller's author has to look at."""
    frames = traceback.extract_tb(exc.__traceback__)
    frame = frames[-1] if frames else None
    if user_file is not None:
        wanted = os.path.realpath(user_file)
        for candidate in reversed(frames):
            if os.path.realpath(candidate.filename) == wanted:
                frame = candidate
                break
    where = f"{frame.filename}:{frame.lineno}: in {frame.name}: " if frame is not None else ""
    return f"{where}{type(exc).__name__}: {exc}"


class AgentOutput:
    """What one step gives the host: command (v m/s, w rad/s), done, the payload the radio
    broadcast this step (bytes) or None, and what the robot drew (a dream.drawing.Drawing) when
    its update() ran, else None."""

    __slots__ = ("v", "w", "done", "broadcast", "drawing")

    def __init__(self, v, w, done, broadcast, drawing=None):
        self.v = v
        self.w = w
        self.done = done
        self.broadcast = broadcast
        self.drawing = drawing


class RobotAgent:
    """A Robot with its sensors, radio, mailbox and Timer.

    `sensors` is a sequence of (sensor, period_steps). Timer components, in order: the sensors,
    the radio, the control law. Calls robot.setup() now; an exception there, or later in any
    callback, becomes a ControllerFault that every later step() raises again (`fault`): any
    exception, SystemExit and ControllerTimeout included, except an interrupt of the whole run
    (is_run_interrupt), which passes through.
    """

    def __init__(self, robot, sensors=(), radio=None, robot_period_steps=1, start_delay_steps=0,
                 radio_period_steps=1, loss_probability=0.0, delay_steps=0, seed=0):
        self.robot = robot
        self.id = robot.id
        self.radio = radio
        self.mailbox = Mailbox(loss_probability, delay_steps, seed)
        self._sensors = [sensor for sensor, _ in sensors]
        periods = [period for _, period in sensors] + [radio_period_steps, robot_period_steps]
        self._timer = Timer(start_delay_steps, periods)
        self._user_file = getattr(sys.modules.get(type(robot).__module__), "__file__", None)
        self._last_command = (0.0, 0.0)
        self.fault = None
        try:
            robot.setup()
        except BaseException as exc:  # SystemExit too: a controller never ends the run
            if is_run_interrupt(exc):
                raise
            self.fault = ControllerFault(controller_error_text(exc, self._user_file))
        if self.fault is None and type(robot).update is Robot.update:
            # A fault now, which the pre-run check reports (controller_spec.check), not at every robot's first step.
            methods = sorted(name for name, value in vars(type(robot)).items()
                             if callable(value) and not name.startswith("_"))
            self.fault = ControllerFault(f"{self._user_file}: {type(robot).__name__} has no update(self, step) method, "
                                         f"the control law returning (v, w); its methods: {', '.join(methods) or 'none'}")

    def step(self, world):
        """Runs the parts due at world.step: sensors in list order, then the radio (heard
        messages -> on_radio), then update; returns an AgentOutput."""
        if self.fault is not None:
            raise self.fault.with_traceback(None)  # not one more frame on its traceback per step
        due = self._timer.tick(world.step)
        robot = self.robot
        radio_slot = len(self._sensors)
        broadcast = None
        drawing = None
        try:
            for sensor, sensor_due in zip(self._sensors, due):
                if sensor_due:
                    sensor.sense(world, robot)
            if due[radio_slot] and self.radio is not None:
                payload = robot.on_radio(self.mailbox.heard(self.radio, self.id, world))
                if payload is not None and self.radio.publishes:
                    broadcast = self._payload(payload)
            if due[radio_slot + 1]:
                self._last_command = self._command(robot.update(world.step))
                drawing = robot.take_drawing()
            done = bool(robot.done())
        except ControllerFault as fault:
            self.fault = fault
            raise
        except BaseException as exc:  # SystemExit, KeyboardInterrupt, ...: the controller failed
            if is_run_interrupt(exc):
                raise
            self.fault = ControllerFault(controller_error_text(exc, self._user_file))
            raise self.fault from exc
        v, w = self._last_command
        return AgentOutput(v, w, done, broadcast, drawing)

    def receive(self, message):
        """A message another robot broadcast; heard (or not) at later steps. Own messages are ignored."""
        if message.sender_id != self.id:
            self.mailbox.post(message)

    def _payload(self, payload):
        """on_radio()'s payload as bytes; a ControllerFault at the user's on_radio when it is no
        bytes or larger than a radio message carries (every receiver would drop it)."""
        on_radio = type(self.robot).on_radio
        code = on_radio.__code__
        where = f"{code.co_filename}:{code.co_firstlineno}: in {on_radio.__name__}: "
        try:
            data = bytes(payload)
        except (TypeError, ValueError) as exc:
            raise ControllerFault(f"{where}TypeError: on_radio() must return bytes or None, got "
                                  f"{type(payload).__name__}: {exc}") from None
        if len(data) > MAX_PAYLOAD_BYTES:
            raise ControllerFault(f"{where}ValueError: a radio payload of {len(data)} bytes is over the limit of "
                                  f"{MAX_PAYLOAD_BYTES} bytes: every receiver would drop it. Send less, e.g. "
                                  f"fewer or smaller fields") from None
        return data

    def _command(self, command):
        """update()'s (v, w) as two floats; a ControllerFault at the user's update otherwise."""
        try:
            v, w = command
            v, w = float(v), float(w)
        except (TypeError, ValueError):
            raise ControllerFault(f"{self._update_location()}TypeError: update() must return (v, w), two numbers, "
                                  f"got {command!r}") from None
        if not (math.isfinite(v) and math.isfinite(w)):
            # The world would refuse every such command and the robot would hold still, unexplained.
            raise ControllerFault(f"{self._update_location()}ValueError: update() must return finite numbers, "
                                  f"got v={v}, w={w}")
        return (v, w)

    def _update_location(self):
        """Where the user's update() is, as a fault names it (worked out only for a fault: _command runs every step)."""
        update = type(self.robot).update
        return f"{update.__code__.co_filename}:{update.__code__.co_firstlineno}: in {update.__name__}: "
