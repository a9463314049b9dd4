"""Radios, the mailbox and the seed mixer (agents/src/radios.cc, noise_source.h).

Every agent receives every broadcast; the receiving radio decides which senders it hears, as
a real radio would. Loss is decided by a hash of (seed, sender, step), not by arrival order,
so a run repeats exactly across process layouts and matches the C++ agents bit for bit.
"""

import bisect
import math
from collections import namedtuple

import numpy as np

from .robot import number_text

# The largest payload a broadcast may carry, in bytes (lcm::MessageLimits::kRadioPayloadBytes):
# every receiver, and the world, refuses a radio message with more.
MAX_PAYLOAD_BYTES = 1 << 16

_MASK64 = (1 << 64) - 1


def mix_seed(run_seed, a, b=0):
    """NoiseSource::MixSeed: SplitMix64 of the run seed and two small integers (robot id,
    component index), with C++'s uint64_t wraparound."""
    z = ((run_seed & _MASK64) + 0x9E3779B97F4A7C15 * ((a & _MASK64) + 1) + 0xBF58476D1CE4E5B9 * ((b & _MASK64) + 1)) & _MASK64
    z = ((z ^ (z >> 30)) * 0xBF58476D1CE4E5B9) & _MASK64
    z = ((z ^ (z >> 27)) * 0x94D049BB133111EB) & _MASK64
    return z ^ (z >> 31)


class RadioMessage(namedtuple("RadioMessage", ("sender_id", "sent_step", "payload"))):
    """One broadcast: who sent it, at which step, and the controller's own payload (bytes)."""

    __slots__ = ()

    def __repr__(self):
        return f"RadioMessage({self.sender_id}, {self.sent_step}, {self.payload!r})"


def pack_floats(values):
    """`values` (any shape) as little-endian float64 bytes, a radio payload."""
    return np.asarray(values, dtype="<f8").tobytes()


def unpack_floats(payload):
    """The float64 array in a pack_floats payload; ValueError when its length is not a multiple of 8."""
    if len(payload) % 8 != 0:
        raise ValueError(f"a payload of floats has a multiple of 8 bytes, got {len(payload)}")
    return np.frombuffer(payload, dtype="<f8").copy()


class RangeRadio:
    """Hears every robot within range_m (centre to centre) at the current step."""

    __slots__ = ("range_m",)
    receives = True
    publishes = True

    def __init__(self, range_m):
        if not (range_m > 0.0 and math.isfinite(range_m)):
            raise ValueError(f"range_m must be > 0, got {number_text(range_m)}")
        self.range_m = range_m

    def can_hear(self, self_id, sender_id, world):
        poses = world.pose_rows
        if self_id == sender_id or sender_id < 0 or sender_id >= len(poses):
            return False
        own = poses[self_id]
        other = poses[sender_id]
        dx = own[0] - other[0]
        dy = own[1] - other[1]
        return math.sqrt(dx * dx + dy * dy) <= self.range_m


def _adjacency_rows(graph):
    rows = [[float(x) for x in row] for row in graph]
    if any(len(row) != len(rows) for row in rows):
        raise ValueError(f"a communication graph must be square, got {len(rows)} rows of lengths "
                         f"{', '.join(str(len(row)) for row in rows)}")
    return rows


class GraphRadio:
    """Hears exactly its neighbours in a communication graph, wherever they are: robot i hears
    robot j when graph[i][j] is non-zero."""

    __slots__ = ("graph",)
    receives = True
    publishes = True

    def __init__(self, graph):
        self.graph = _adjacency_rows(graph)

    def can_hear(self, self_id, sender_id, world):
        size = len(self.graph)
        if self_id == sender_id or sender_id < 0 or sender_id >= size or self_id >= size:
            return False
        return self.graph[self_id][sender_id] != 0.0


class RoleRadio:
    """Leader/follower radios (affine formation): a leader only publishes; a follower publishes
    and hears its graph neighbours, leaders and followers alike."""

    __slots__ = ("leader", "graph", "receives")
    publishes = True

    def __init__(self, leader, graph):
        self.leader = leader
        self.graph = _adjacency_rows(graph)
        self.receives = not leader

    def can_hear(self, self_id, sender_id, world):
        size = len(self.graph)
        if self.leader or self_id == sender_id or sender_id < 0 or sender_id >= size or self_id >= size:
            return False
        return self.graph[self_id][sender_id] != 0.0


class Mailbox:
    """A robot's incoming radio traffic: the newest messages of every sender. A message sent at
    step k can be heard from step k + 1 + delay_steps; each is lost with loss_probability, decided
    by mix_seed(seed, sender, step) as agents/src/radios.cc does."""

    __slots__ = ("loss_probability", "delay_steps", "seed", "lost_messages", "_by_sender", "_senders")

    def __init__(self, loss_probability=0.0, delay_steps=0, seed=0):
        if not (0.0 <= loss_probability < 1.0):
            raise ValueError(f"loss_probability must be in [0, 1), got {number_text(loss_probability)}")
        if delay_steps < 0:
            raise ValueError(f"delay_steps must be >= 0, got {delay_steps}")
        self.loss_probability = loss_probability
        self.delay_steps = delay_steps
        self.seed = seed
        self.lost_messages = 0
        self._by_sender = {}  # sender id -> {sent step: message}, the newest delay_steps + 2
        self._senders = []    # sender ids, sorted

    def post(self, message):
        """Stores `message` unless the link loses it."""
        if self.loss_probability > 0.0:
            draw = mix_seed(self.seed, message.sender_id, message.sent_step)
            if (draw >> 11) * 2.0 ** -53 < self.loss_probability:
                self.lost_messages += 1
                return
        messages = self._by_sender.get(message.sender_id)
        if messages is None:
            messages = self._by_sender[message.sender_id] = {}
            bisect.insort(self._senders, message.sender_id)
        messages[message.sent_step] = message
        # Keep what a delay could still need, plus the newest audible one.
        while len(messages) > self.delay_steps + 2:
            del messages[min(messages)]

    def heard(self, radio, self_id, world):
        """The newest audible message from each sender `radio` hears at `world`'s step, by sender id."""
        if not radio.receives:
            return []
        newest_audible = world.step - 1 - self.delay_steps
        heard = []
        for sender in self._senders:
            if not radio.can_hear(self_id, sender, world):
                continue
            messages = self._by_sender[sender]
            audible_steps = [step for step in messages if step <= newest_audible]
            if audible_steps:
                heard.append(messages[max(audible_steps)])
        return heard
