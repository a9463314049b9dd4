"""The Python agent host: Python controllers as agents on the bus, as agents/agent_host's AgentHost.

Reads DREAM_POSES (the step trigger), DREAM_OBSTACLES, DREAM_STATUS and every
DREAM_RADIO_<id>; writes DREAM_RADIO_<id>, DREAM_DRAW_<id> (what the robot drew, when it
changed; each clip reason logged once per robot) and DREAM_CMD_<id> for each hosted robot, with
the same lockstep contract as the C++ host (docs/architecture.md): each DREAM_POSES of
step k is answered with every hosted robot's command for step k, its radio message (if
any) just before; a resent step gets the same messages again without running the robot
twice. Messages are lcm-gen's Python types.

A controller that raises is reported once on DREAM_FAULT_<id> (robot_fault_t: the error's
file:line), logged, and its robot is no longer answered: the world marks it lost and stops
it, and the run goes on. Any exception counts, SystemExit included, and so does a call the
embedding tool's watchdog stopped for running too long (ControllerTimeout). Undecodable or
inconsistent messages are counted per channel and dropped; nothing from the bus can raise out
of a handler. An interrupt of the whole run (RunInterrupted, raised by that watchdog on Ctrl-C)
ends the step's handling at once: `interrupted` is set, and nothing is answered any more.

Each controller call is marked in the call cell (set_call_cell): a token unique to the call
while it runs, 0 otherwise, then the robot and the step, which the embedding tool's watchdog
thread reads (agents/python_embedded), and the process that hosts this one (PythonHostProcess).
"""

import itertools
import logging
import re
import struct
import time

import numpy as np

from .drawing import EMPTY_KEY, NOTHING_DRAWN
from .radios import MAX_PAYLOAD_BYTES, RadioMessage
from .robot import ObstacleView, WorldSnapshot
from .robot_agent import ControllerFault, RunInterrupted
from .world_follower import IGNORE, NEW_STEP, WorldFollower

log = logging.getLogger("dream")

SUBSCRIPTION_REGEX = "DREAM_(POSES|OBSTACLES|STATUS|RADIO_[0-9]+)"
# The bus's bound (lcm::MessageLimits::kRobots): a sim_only run has up to 128 robots; the config
# (ControllerConfig) holds other runs to the Robotarium simulator's 50. Larger counts are refused.
MAX_ROBOTS = 128
MAX_OBSTACLES = 10000    # far beyond any config; bounds the decode of a forged message
MAX_RADIO_PAYLOAD = MAX_PAYLOAD_BYTES
MAX_DETAIL_BYTES = 1 << 16  # lcm::MessageLimits::kDetailBytes: a longer fault text is refused
_RADIO_CHANNEL = re.compile(r"DREAM_RADIO_([0-9]{1,6})$")
_FINISHED, _ABORTED = 2, 3
# Byte offsets after the 8-byte fingerprint (lcmtypes/dream/*.lcm): utime, step, run_id first.
_POSES_COUNT_AT = 8 + 24
_OBSTACLES_COUNT_AT = 8 + 24
_RADIO_COUNT_AT = 8 + 36        # ... sender_id (int32), agent_id (int64), payload_size
_STATUS_COUNT_AT = 8 + 29 + 48  # ... state, num_robots, six int64 counts, num_lost


CELL_TOKEN, CELL_ROBOT, CELL_STEP = 0, 1, 2
_call_cell = memoryview(bytearray(24)).cast("q")  # no watchdog: marks go nowhere
_call_tokens = itertools.count(1)


def set_call_cell(cell):
    """Where hosts made from now on mark their controller calls: a writable memoryview of three
    int64 (format "q": token, robot, step) that the embedding tool's watchdog reads."""
    global _call_cell
    _call_cell = cell


def call_cell():
    return _call_cell


def next_call_token():
    """A token no other controller call of this process had (> 0)."""
    return next(_call_tokens)


def _types():
    """lcm-gen's Python types (package dream), found through dream.__path__ (see embedded.py)."""
    from .drawing_t import drawing_t
    from .obstacles_t import obstacles_t
    from .radio_message_t import radio_message_t
    from .robot_fault_t import robot_fault_t
    from .robot_poses_t import robot_poses_t
    from .run_status_t import run_status_t
    from .velocity_command_t import velocity_command_t
    return obstacles_t, radio_message_t, robot_fault_t, robot_poses_t, run_status_t, velocity_command_t, drawing_t


def _count_field(data, offset, size_per_item, fixed_size, limit, what):
    """The int32 count at `offset` after the 8-byte fingerprint, checked against the bytes.

    lcm-gen's decoders trust the count; bounding it by the datagram's length first keeps a
    forged count from costing more than the datagram justifies.
    """
    if len(data) < offset + 4:
        raise ValueError(f"{len(data)} bytes: too short for a {what}")
    (count,) = struct.unpack_from(">i", data, offset)
    if count < 0 or count > limit:
        raise ValueError(f"{what} count {count} out of range 0..{limit}")
    if size_per_item is not None and len(data) != fixed_size + size_per_item * count:
        raise ValueError(f"{len(data)} bytes do not hold a {what} of {count} items")
    return count


def _status_bounds(data):
    """run_status_t's lost-robot count and detail length, checked against the bytes first."""
    count = _count_field(data, _STATUS_COUNT_AT, None, 0, MAX_ROBOTS, "run_status_t")
    detail_at = _STATUS_COUNT_AT + 4 + 4 * count
    if len(data) < detail_at + 4:
        raise ValueError(f"{len(data)} bytes: too short for a run_status_t of {count} lost robots")
    (length,) = struct.unpack_from(">i", data, detail_at)
    if length < 1 or len(data) != detail_at + 4 + length:
        raise ValueError(f"run_status_t detail length {length} does not fit its {len(data)} bytes")


class _RobotSlot:
    def __init__(self, agent):
        self.agent = agent
        self.command_channel = f"DREAM_CMD_{agent.id}"
        self.radio_channel = f"DREAM_RADIO_{agent.id}"
        self.last_command = None
        self.last_radio = None
        self.draw_channel = f"DREAM_DRAW_{agent.id}"
        self.last_drawing = None  # this step's drawing_t bytes, sent with its command (and resends)
        self.drawn_key = EMPTY_KEY  # what the robot drew last: the same is not sent again
        self.clip_reasons_logged = set()
        self.fault = None


class AgentHost:
    """Hosts `agents` (dream.robot_agent.RobotAgent) of a run of `num_robots` robots on `bus`
    (dream.lcm.Lcm). Radio messages from senders outside the run are dropped, so forged
    sender ids cannot grow the mailboxes."""

    def __init__(self, bus, agents, agent_id, num_robots):
        (self._obstacles_t, self._radio_message_t, self._robot_fault_t, self._robot_poses_t,
         self._run_status_t, self._velocity_command_t, self._drawing_t) = _types()
        ids = [agent.id for agent in agents]
        if len(set(ids)) != len(ids):
            raise ValueError(f"a robot is listed twice for one agent host: {ids}")
        self.bus = bus
        self.agent_id = int(agent_id)
        self.num_robots = int(num_robots)
        self.robots = [_RobotSlot(agent) for agent in agents]
        self.follower = WorldFollower()
        self.obstacles = []
        self._obstacles_run_id = 0
        self._radio_before_joining = []
        self.world_finished = False
        self.end_detail = ""
        self.last_step_answered = -1
        self.poses_seen = 0
        self.other_world_robots = None  # the robot count of the last world refused for it
        self.bad_messages = {}
        self.interrupted = False
        self._call_cell = _call_cell
        self._handlers = {"DREAM_POSES": self._on_poses, "DREAM_OBSTACLES": self._on_obstacles,
                          "DREAM_STATUS": self._on_status}
        bus.subscribe(SUBSCRIPTION_REGEX, self._on_message)

    # --- dispatch -------------------------------------------------------------------------

    def _on_message(self, channel, data):
        """Never raises: LCM's C code is below this frame."""
        if self.interrupted:
            return
        try:
            handler = self._handlers.get(channel)
            if handler is not None:
                handler(channel, data)
            elif channel.startswith("DREAM_RADIO_"):
                self._on_radio(channel, data)
        except Exception as error:  # a forged message must not stop the agents
            self._report_bad(channel, f"{type(error).__name__}: {error}")
        except RunInterrupted:  # Ctrl-C while a controller ran: the tool ends the run
            self.interrupted = True
            log.info("interrupted while a controller ran: no more answers")

    def _report_bad(self, channel, reason):
        count = self.bad_messages.get(channel, 0) + 1
        self.bad_messages[channel] = count
        if count == 1 or count % 100 == 0:
            log.warning("%s: dropped bad message #%d: %s", channel, count, reason)

    def _on_obstacles(self, channel, data):
        _count_field(data, _OBSTACLES_COUNT_AT, 52, _OBSTACLES_COUNT_AT + 4, MAX_OBSTACLES, "obstacles_t")
        message = self._obstacles_t.decode(data)
        # Step 0's obstacles come before the first DREAM_POSES: kept, dropped on joining if of another run.
        if self.follower.joined and not self.follower.in_run(message.run_id):
            raise ValueError("obstacles of another run")
        self._obstacles_run_id = message.run_id
        views = []
        for o in message.obstacles:
            values = (o.center_x, o.center_y, o.width, o.height, o.vx, o.vy)
            if not np.all(np.isfinite(values)):
                self._report_bad(channel, f"non-finite obstacle {o.id}")
                continue
            views.append(ObstacleView(o.id, np.array(values[0:2]), np.array(values[2:4]), np.array(values[4:6])))
        self.obstacles = views

    def _on_radio(self, channel, data):
        match = _RADIO_CHANNEL.match(channel)
        _count_field(data, _RADIO_COUNT_AT, 1, _RADIO_COUNT_AT + 4, MAX_RADIO_PAYLOAD, "radio_message_t")
        message = self._radio_message_t.decode(data)
        if match is None or int(match.group(1)) != message.sender_id:
            raise ValueError("radio message does not match its channel")
        if not self.follower.joined:
            # A neighbour's answer to step 0 may come first; bounded.
            if len(self._radio_before_joining) >= 2 * MAX_ROBOTS:
                raise ValueError("radio message before the world's first step, beyond the queue's bound")
            self._radio_before_joining.append((channel, message))
            return
        if not self.follower.in_run(message.run_id):
            raise ValueError("radio message of another run")
        self._deliver(message)

    def _deliver(self, message):
        if not 0 <= message.sender_id < self.num_robots:
            raise ValueError(f"sender {message.sender_id} is not a robot of this run (0..{self.num_robots - 1})")
        # Sent while answering step k, so heard at k or k + 1; a later step is a forgery that
        # would shadow the sender's real messages in the mailboxes.
        if not 0 <= message.step <= self.follower.step + 1:
            raise ValueError(f"radio message sent at step {message.step} while the world is at step "
                             f"{self.follower.step}")
        heard = RadioMessage(message.sender_id, message.step, bytes(message.payload))
        for robot in self.robots:
            robot.agent.receive(heard)

    def _on_status(self, channel, data):
        _status_bounds(data)
        message = self._run_status_t.decode(data)
        if message.state in (_FINISHED, _ABORTED) and self.follower.ends_run(message.run_id, message.step):
            self.world_finished = True
            self.end_detail = message.detail

    def _on_poses(self, channel, data):
        n = _count_field(data, _POSES_COUNT_AT, 40, _POSES_COUNT_AT + 4, MAX_ROBOTS, "robot_poses_t")
        if n != self.num_robots:
            # Agents started with another experiment's config would drive its robots: never joined.
            self.other_world_robots = n
            raise ValueError(f"a world of {n} robots; this agent's config has {self.num_robots}")
        poses = self._robot_poses_t.decode(data)
        if poses.step < 0:
            raise ValueError(f"step {poses.step} is negative")
        pose_array = np.column_stack((poses.x, poses.y, poses.theta)) if n else np.zeros((0, 3))
        velocities = np.column_stack((poses.v, poses.w)) if n else np.zeros((0, 2))
        if not (np.all(np.isfinite(pose_array)) and np.all(np.isfinite(velocities))):
            raise ValueError("non-finite pose or velocity")
        joining = not self.follower.joined
        decision = self.follower.on_poses(poses.run_id, poses.step)
        if decision == IGNORE:
            return
        self.poses_seen += 1  # only the followed run's steps keep this host waiting
        if joining:
            if self._obstacles_run_id != poses.run_id:
                self.obstacles = []
            queued, self._radio_before_joining = self._radio_before_joining, []
            for radio_channel, radio in queued:
                if radio.run_id == poses.run_id:
                    try:
                        self._deliver(radio)
                    except ValueError as error:
                        self._report_bad(radio_channel, str(error))
        snapshot = WorldSnapshot(poses.step, pose_array, velocities, self.obstacles)
        for robot in self.robots:
            if robot.fault is not None:
                continue
            if robot.agent.id >= n:
                self._report_bad(channel, f"robot {robot.agent.id} is not in this run: "
                                          f"DREAM_POSES carries {n} robots")
                continue
            if decision == NEW_STEP and not self._answer(robot, poses, snapshot):
                continue
            if robot.last_command is None:
                continue
            if robot.last_radio is not None:
                self.bus.publish(robot.radio_channel, robot.last_radio)
            if robot.last_drawing is not None:
                self.bus.publish(robot.draw_channel, robot.last_drawing)
            self.bus.publish(robot.command_channel, robot.last_command)

    def _answer(self, robot, poses, snapshot):
        """Runs the robot for this step; False when its controller failed."""
        cell = self._call_cell
        try:
            cell[CELL_ROBOT] = robot.agent.id
            cell[CELL_STEP] = poses.step
            cell[CELL_TOKEN] = next(_call_tokens)  # the watchdog's mark: this call runs (set last)
            output = robot.agent.step(snapshot)
        except ControllerFault as fault:
            cell[0] = 0  # reporting it is not the controller's call
            self._fail(robot, poses, str(fault))
            return False
        except RunInterrupted:
            raise
        except BaseException as error:  # noqa: B036 - the watchdog's repeat, while the fault was written
            cell[0] = 0
            self._fail(robot, poses, f"{type(error).__name__}: {error} (raised again while its controller's "
                                     "error was being reported)")
            return False
        finally:
            cell[0] = 0
        command = self._velocity_command_t()
        command.utime, command.step, command.run_id = poses.utime, poses.step, poses.run_id
        command.robot_id, command.agent_id = robot.agent.id, self.agent_id
        command.v, command.w, command.done = float(output.v), float(output.w), bool(output.done)
        robot.last_command = command.encode()
        robot.last_radio = None
        if output.broadcast is not None:
            radio = self._radio_message_t()
            radio.utime, radio.step, radio.run_id = poses.utime, poses.step, poses.run_id
            radio.sender_id, radio.agent_id = robot.agent.id, self.agent_id
            radio.payload = bytes(output.broadcast)
            radio.payload_size = len(radio.payload)
            robot.last_radio = radio.encode()
        robot.last_drawing = None
        if output.drawing is not None:
            self._take_drawing(robot, poses, output.drawing)
        self.last_step_answered = max(self.last_step_answered, poses.step)
        return True

    def _take_drawing(self, robot, poses, drawing):
        """Keeps `drawing` as the robot's drawing_t for this step when it differs from its last."""
        if drawing is NOTHING_DRAWN and robot.drawn_key == EMPTY_KEY:
            return  # the common case: nothing drawn, nothing shown
        for reason, count in drawing.clip_reasons.items():
            if reason not in robot.clip_reasons_logged:
                robot.clip_reasons_logged.add(reason)
                log.warning("robot %d drew past its bounds at step %d: %s x%d (counted in each %s's `clipped` "
                            "from now on)", robot.agent.id, poses.step, reason, count, robot.draw_channel)
        key = drawing.key()
        if key == robot.drawn_key:
            return
        message = drawing.message(self._drawing_t)
        message.utime, message.step, message.run_id = poses.utime, poses.step, poses.run_id
        message.robot_id, message.agent_id = robot.agent.id, self.agent_id
        robot.last_drawing = message.encode()
        robot.drawn_key = key

    @staticmethod
    def _wire_text(text):
        """`text` as the world accepts a string: UTF-8 with no NUL, at most MAX_DETAIL_BYTES
        (cut on a character boundary), a NUL written \\0 as lcm::WireText::Of writes it.
        An exception's text may hold anything."""
        data = text.replace("\x00", "\\0").encode("utf-8", "replace")[:MAX_DETAIL_BYTES]
        return data.decode("utf-8", "ignore")

    def _fail(self, robot, poses, detail):
        robot.fault = detail
        log.error("robot %d stops at step %d: its controller failed: %s", robot.agent.id, poses.step, detail)
        fault = self._robot_fault_t()
        fault.utime, fault.step, fault.run_id = poses.utime, poses.step, poses.run_id
        fault.robot_id, fault.agent_id = robot.agent.id, self.agent_id
        fault.detail = self._wire_text(detail)
        self.bus.publish(f"DREAM_FAULT_{robot.agent.id}", fault.encode())

    # --- for processes that own their loop -----------------------------------------------

    def run(self, idle_timeout_s, should_stop=lambda: False):
        """Handles messages until the world ends the run (True), or stop / silence (False)."""
        last_activity = time.monotonic()
        seen = self.poses_seen
        while not self.world_finished and not self.interrupted and not should_stop():
            self.bus.handle_timeout(100)
            if self.poses_seen != seen:
                seen = self.poses_seen
                last_activity = time.monotonic()
            elif time.monotonic() - last_activity > idle_timeout_s:
                log.error("%s", self.silence_text(idle_timeout_s, self.bus.url))
                return False
        return self.world_finished

    def silence_text(self, idle_timeout_s, url):
        """Why this host gives up after idle_timeout_s without a step of its run."""
        if not self.follower.joined and self.other_world_robots is not None:
            return (f"DREAM_POSES on {url} came from a world of {self.other_world_robots} robots, but this agent's "
                    f"config has {self.num_robots}: start the agents with the config the simulator (dream sim) runs")
        return (f"no DREAM_POSES for {idle_timeout_s:g} s on {url}: is the simulator (dream sim) running on the "
                f"same LCM URL?")

    def report_json(self):
        """What this host refused, as JSON for `dream launch`'s summary (AgentReport in C++)."""
        import json
        from .world_follower import run_id_text
        return json.dumps({"bad_messages": self.bad_messages,
                           "other_runs": sorted(run_id_text(r) for r in self.follower.other_runs),
                           "steps_out_of_sequence": self.follower.steps_out_of_sequence})

    def faults(self):
        """{robot id: error text} of the robots whose controller failed."""
        return {robot.agent.id: robot.fault for robot in self.robots if robot.fault is not None}
