"""The script's side of the bus: one agent for every robot of the run, in lockstep with DREAM's world.

`dream run SCRIPT.py` gives the LCM URL (DREAM_LCM_URL) and the folder of lcm-gen's Python types
(DREAM_PYTHON_TYPES_DIR). next_poses() waits for the world's next step (DREAM_POSES); send()
answers it with every robot's command in one DREAM_CMDS message (robot_commands_t: one datagram a
step, where one per robot woke every listener's receive thread once per robot), which the world
takes and records entry by entry as each robot's DREAM_CMD_<id>. A step the world sends again (it
resends while it waits) gets the same commands again. Messages are checked before they are decoded (sizes, counts,
finite values), as the Python agent host checks them.
"""

import collections
import importlib
import os
import random
import struct
import time

import numpy as np

from rps.utilities._dream_toolbox import dream_package

URL_VARIABLE = "DREAM_LCM_URL"
TYPES_VARIABLE = "DREAM_PYTHON_TYPES_DIR"
# A world silent this long while the script waits for a step has gone (the command ended).
SILENCE_LIMIT_S = 120.0
_POSES_COUNT_AT = 8 + 24  # the fingerprint, then utime, step, run_id
_STATUS_STATE_AT = 8 + 24  # the fingerprint, then utime, step, run_id
_FINISHED, _ABORTED = 2, 3
_Step = collections.namedtuple("_Step", "utime step run_id")  # what an answer needs of a step


class WorldGone(RuntimeError):
    """The world ended the run, or fell silent, while the script waited for a step."""


def _types():
    """lcm-gen's Python types, joined to the toolbox's `dream` package as dream.embedded does."""
    package = dream_package()
    types_dir = os.environ.get(TYPES_VARIABLE, "")
    types_package = os.path.join(types_dir, "dream")
    if not os.path.isfile(os.path.join(types_package, "robot_poses_t.py")):
        raise RuntimeError(f"{TYPES_VARIABLE}={types_dir!r} holds no lcm-gen Python types; "
                           "run the script with `dream run SCRIPT.py`")
    if types_package not in package.__path__:
        package.__path__.append(types_package)
    names = ("robot_poses_t", "robot_commands_t", "robot_fault_t", "run_status_t")
    return [getattr(importlib.import_module(f"{package.__name__}.{name}"), name) for name in names]


class WorldLink:
    """The robots 0..n-1 of the world at `url`, driven by one script."""

    def __init__(self, n, url=None):
        package = dream_package()
        lcm = importlib.import_module(f"{package.__name__}.lcm")
        follower = importlib.import_module(f"{package.__name__}.world_follower")
        self._poses_t, self._commands_t, self._fault_t, self._status_t = _types()
        self.n = n
        self.url = url or os.environ.get(URL_VARIABLE, "")
        if not self.url:
            raise RuntimeError(f"no LCM URL in {URL_VARIABLE}: run the script with `dream run SCRIPT.py`")
        # Not from `random`: the script's own stream stays the official simulator's.
        self.agent_id = random.SystemRandom().getrandbits(62) + 1
        self.follower = follower.WorldFollower()
        self.bus = lcm.Lcm(self.url)
        # Commands packed as lcm-gen's robot_commands_t.encode packs them, without its per-message
        # objects: the fingerprint, utime, step, run_id, agent_id, the count, then the robot ids, the
        # v's, the w's and the done flags, each array whole.
        self._commands_fingerprint = self._commands_t._get_packed_fingerprint()
        self._poses_fingerprint = self._poses_t._get_packed_fingerprint()
        self._commands_start = struct.Struct(">qqqqi")
        self._robot_ids = struct.pack(f">{n}i", *range(n))
        self._fresh = None       # (message, 3 x n poses) of a step not yet handed out
        self._current = None     # the message of the step handed out last
        self._answers = []       # that step's encoded DREAM_CMDS message, sent again on a resend
        self.answered = True     # whether the step handed out last has been answered
        self.ended = False
        self.end_detail = ""
        self.bus.subscribe("DREAM_POSES", self._on_poses)
        self.bus.subscribe("DREAM_STATUS", self._on_status)

    def _on_poses(self, _channel, data):
        if len(data) < _POSES_COUNT_AT + 4:
            return
        (count,) = struct.unpack_from(">i", data, _POSES_COUNT_AT)
        if count != self.n or len(data) != _POSES_COUNT_AT + 4 + 40 * count:
            return  # another world's, or forged
        if data[:8] != self._poses_fingerprint:
            return
        # The header and x, y, theta read in place (lcm-gen's decode builds five Python lists a step).
        message = _Step(*struct.unpack_from(">qqq", data, 8))
        poses = np.frombuffer(data, dtype=">f8", count=3 * count, offset=_POSES_COUNT_AT + 4).reshape(3, count)
        poses = poses.astype(float)
        if message.step < 0 or not np.all(np.isfinite(poses)):
            return
        decision = self.follower.on_poses(message.run_id, message.step)
        if decision == "new_step":
            self._fresh = (message, poses)
        elif decision == "resend" and self._current is not None and message.step == self._current.step:
            for channel, answer in self._answers:
                self.bus.publish(channel, answer)

    def _on_status(self, _channel, data):
        # Every step has a status; only an ending one (its state byte after the header) is decoded.
        if len(data) <= _STATUS_STATE_AT or data[_STATUS_STATE_AT] not in (_FINISHED, _ABORTED):
            return
        try:
            message = self._status_t.decode(data)
        except Exception:  # noqa: BLE001 - a forged status is not the script's problem
            return
        if message.state in (_FINISHED, _ABORTED) and self.follower.ends_run(message.run_id, message.step):
            self.ended = True
            self.end_detail = message.detail

    def next_poses(self):
        """The next step's poses (3 x n), waiting for the world."""
        last_heard = time.monotonic()
        while self._fresh is None:
            if self.ended:
                raise WorldGone(f"DREAM's world ended the run: {self.end_detail}")
            if self.bus.handle_timeout(100) > 0:
                last_heard = time.monotonic()
            elif time.monotonic() - last_heard > SILENCE_LIMIT_S:
                raise WorldGone(f"no step from DREAM's world for {SILENCE_LIMIT_S:g} s on {self.url}")
        self._current, poses = self._fresh
        self._fresh = None
        self.answered = False
        return poses

    def send(self, velocities, done=False):
        """Answers the current step: robot i drives velocities[:, i] (v m/s, w rad/s)."""
        step = self._current
        speeds_and_turns = np.asarray(velocities, dtype=float)[:2, :self.n]
        count = speeds_and_turns.shape[1]
        start = self._commands_start.pack(step.utime, step.step, step.run_id, self.agent_id, count)
        # Row by row, big-endian: every v, then every w, as lcm-gen writes the two arrays.
        values = speeds_and_turns.astype(">f8").tobytes()
        flags = (b"\x01" if done else b"\x00") * count
        message = self._commands_fingerprint + start + self._robot_ids[:4 * count] + values + flags
        self._answers = [("DREAM_CMDS", message)]
        self.answered = True
        for channel, answer in self._answers:
            self.bus.publish(channel, answer)

    def fail(self, detail):
        """Tells the world every robot's controller (the script) failed: it stops them."""
        step = self._current
        if step is None:
            return
        for i in range(self.n):
            fault = self._fault_t()
            fault.utime, fault.step, fault.run_id = step.utime, step.step, step.run_id
            fault.robot_id, fault.agent_id = i, self.agent_id
            fault.detail = detail.replace("\x00", "\\0").encode("utf-8", "replace")[:60000].decode("utf-8", "ignore")
            self.bus.publish(f"DREAM_FAULT_{i}", fault.encode())

    def close(self):
        self.bus.close()
