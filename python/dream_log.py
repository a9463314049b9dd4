"""Read DREAM run logs from Python: every event, or the whole run as numpy arrays.

    import sys; sys.path.insert(0, "python")       # or share/dream/python once installed
    import dream_log

    run = dream_log.load("runs/go_to_goal")          # a run folder or a .lcmlog file
    run.poses[-1]                                    # (N, 3) x, y, theta of every robot at the end
    run.commands[10, 3]                              # (v, w) robot 3 answered step 10 with

Two layers:

- read_events(path): the events of any LCM log, with nothing but the standard library. The
  file format (LCM's, every number big-endian) is a sequence of events, each
      uint32 sync word 0xEDA1DA01, int64 event number, int64 timestamp (us),
      int32 channel length, int32 data length, channel bytes, data bytes.
- load(path): a DREAM run as arrays (class Run), decoded with the types lcm-gen writes for
  Python (build/python/dream/, installed as share/dream/python/dream/). They need only
  `struct`, so no LCM Python runtime is needed (Debian ships none); the arrays need numpy
  (Debian's python3-numpy).

Errors name the file: LogFormatError when the file is not an LCM log or is cut short or
damaged, RunLogError when it is a log but not a usable run (no poses, undecodable messages).
Both are ValueErrors.
"""

import json
import os
import re
import struct
import sys
from typing import Iterator, NamedTuple

SYNC_WORD = 0xEDA1DA01
_HEADER = struct.Struct(">Iqqii")  # sync word, event number, timestamp, channel length, data length

POSES_CHANNEL = "DREAM_POSES"
STATUS_CHANNEL = "DREAM_STATUS"
OBSTACLES_CHANNEL = "DREAM_OBSTACLES"
_COMMAND_CHANNEL = re.compile(r"DREAM_CMD_([0-9]+)")
_RADIO_CHANNEL = re.compile(r"DREAM_RADIO_([0-9]+)")

# Columns of each step's array in Run.obstacles.
OBSTACLE_COLUMNS = ("id", "center_x", "center_y", "width", "height", "vx", "vy")
# run_status_t.state values, by name.
STATE_NAMES = {0: "WAITING_FOR_AGENTS", 1: "RUNNING", 2: "FINISHED", 3: "ABORTED"}


class LogEvent(NamedTuple):
    """One event of an LCM log."""

    eventnum: int  # event number as written by the logger
    utime: int  # timestamp, microseconds (simulated time in dream run logs)
    channel: str  # channel name, e.g. DREAM_POSES
    data: bytes  # the encoded message: 8-byte type fingerprint, then the fields


class LogFormatError(ValueError):
    """The file is not an LCM log, or it is cut short or damaged."""


class RunLogError(ValueError):
    """The file is an LCM log but not a DREAM run that can be loaded (no poses, bad messages)."""


def read_events(path: str) -> Iterator[LogEvent]:
    """Yields every event of the LCM log at `path`, in file order.

    Raises LogFormatError, naming the file, the event and the byte offset, when
    the file does not start with an event, is cut short in the middle of an
    event, or an event header is damaged. An empty file is an empty log.
    """
    with open(path, "rb") as log:
        offset = 0
        count = 0
        while True:
            header = log.read(_HEADER.size)
            if not header:
                return
            where = f"{path}: event {count} at byte {offset}"
            if count == 0 and len(header) >= 4 and struct.unpack(">I", header[:4])[0] != SYNC_WORD:
                raise LogFormatError(f"{where}: not an LCM log: it starts with {header[:4]!r}, "
                                     f"not the sync word {SYNC_WORD:#010x}")
            if len(header) < _HEADER.size:
                raise LogFormatError(f"{where}: cut short inside the event header "
                                     f"({len(header)} of {_HEADER.size} bytes)")
            sync, eventnum, utime, channel_len, data_len = _HEADER.unpack(header)
            if sync != SYNC_WORD:
                what = "not an LCM log" if count == 0 else "damaged"
                raise LogFormatError(f"{where}: {what}: sync word is {sync:#010x}, expected {SYNC_WORD:#010x}")
            if channel_len <= 0 or data_len < 0:
                raise LogFormatError(f"{where}: damaged header: channel length {channel_len}, "
                                     f"data length {data_len}")
            body = log.read(channel_len + data_len)
            if len(body) < channel_len + data_len:
                raise LogFormatError(f"{where}: cut short: the header announces {channel_len + data_len} "
                                     f"bytes of channel and data, the file holds {len(body)}")
            try:
                channel = body[:channel_len].decode("utf-8")
            except UnicodeDecodeError as error:
                raise LogFormatError(f"{where}: damaged channel name: {error}") from None
            yield LogEvent(eventnum, utime, channel, body[channel_len:])
            offset += _HEADER.size + channel_len + data_len
            count += 1


def read_all(path: str) -> list:
    """All events of the log at `path` (see read_events)."""
    return list(read_events(path))


def _types_dir_candidates(types_dir):
    if types_dir is not None:
        return [types_dir]
    here = os.path.dirname(os.path.abspath(__file__))
    candidates = []
    if os.environ.get("DREAM_PYTHON_TYPES_DIR"):
        candidates.append(os.environ["DREAM_PYTHON_TYPES_DIR"])
    candidates.append(here)  # installed: share/dream/python holds dream_log.py and dream/
    candidates.append(os.path.join(here, "..", "build", "python"))  # a source checkout built in build/
    return candidates


def import_types(types_dir=None):
    """The package `dream` of types lcm-gen wrote for Python.

    Looked for in `types_dir` when given; else in $DREAM_PYTHON_TYPES_DIR, beside this file
    (the installed layout) and in build/python of the checkout this file is in. Raises
    ImportError naming the folders searched.
    """
    candidates = [os.path.abspath(c) for c in _types_dir_candidates(types_dir)]
    for folder in candidates:
        # robot_poses_t.py, not just __init__.py: in a checkout, python/dream/ beside this file
        # is the controller runtime (a package dream without the types), not lcm-gen's output.
        if os.path.isfile(os.path.join(folder, "dream", "robot_poses_t.py")):
            loaded = sys.modules.get("dream")
            if loaded is not None and hasattr(loaded, "robot_poses_t"):
                return loaded  # already imported (from here or elsewhere): one set of types per process
            if folder not in sys.path:
                sys.path.insert(0, folder)
            import dream  # noqa: E402

            return dream
    raise ImportError("the Python types of DREAM (a folder dream/ written by lcm-gen) are not in "
                      + ", ".join(candidates) + "; build the project, or pass types_dir=.../build/python")


def log_path_of(path):
    """The log file of `path`: the file itself, or run.lcmlog in a run folder."""
    if os.path.isdir(path):
        log = os.path.join(path, "run.lcmlog")
        if not os.path.isfile(log):
            raise RunLogError(f"{path}: a folder without run.lcmlog; give a run folder (dream run --out) "
                              f"or an .lcmlog file")
        return log
    if not os.path.exists(path):
        raise FileNotFoundError(f"{path}: no such file or folder")
    return path


class Run:
    """A DREAM run as numpy arrays, aligned on the steps of its DREAM_POSES messages.

    K steps, N robots; row i of every per-step array is step steps[i].

    steps        (K,) int64, the step index k of each DREAM_POSES message (0, 1, 2, ... for
                 simulated runs)
    t_s          (K,) float, the message's time stamp, seconds (simulated: k * 0.033)
    poses        (K, N, 3) float, x (m), y (m), theta (rad) of every robot
    velocities   (K, N, 2) float, v (m/s), w (rad/s) each robot drove with into that step
    commands     (K, N, 2) float, the (v, w) each robot's agent answered that step with (the
                 first command for the step, as the world takes it in lockstep); NaN where
                 none was recorded (a lost robot, the last step)
    done         (K, N) bool, that command's done flag (False where none)
    status       structured array, one row per recorded DREAM_STATUS message, in log order:
                 step, t_s, state (see STATE_NAMES), boundary_errors, collision_errors,
                 actuator_errors, obstacle_collisions, rejected_commands, num_lost (the
                 counts are running totals)
    final_state  name of the last status's state, e.g. "FINISHED"; final_detail its reason
    obstacles    list of K float arrays (M, 7), columns OBSTACLE_COLUMNS, the virtual
                 obstacles at each step (M = 0 when none)
    radio_counts {robot id: radio messages it sent} (DREAM_RADIO_<id>)
    channels     {channel: events} for the whole log
    summary      summary.json of the run folder as a dict, or None when there is none
    log_path     the log file read
    run_id       the run the log is of; a recording of the bus (lcm-logger) is read as the run's
                 own log: resends counts the world's resends of a step left out, other_run_ids
                 the other worlds heard (a `dream sim` idling beside the run), left out
    """

    def __init__(self):
        self.log_path = ""
        self.num_robots = 0
        self.steps = None
        self.t_s = None
        self.poses = None
        self.velocities = None
        self.commands = None
        self.done = None
        self.status = None
        self.final_state = None
        self.final_detail = ""
        self.obstacles = []
        self.radio_counts = {}
        self.channels = {}
        self.run_id = 0
        self.resends = 0          # the world's resends of a step left out (an lcm-logger recording has them)
        self.other_run_ids = []   # other worlds heard in the log, left out
        self.summary = None

    @property
    def num_steps(self):
        """K, the number of DREAM_POSES steps."""
        return len(self.steps)

    def row_of_step(self, step):
        """Row index of step k in the per-step arrays. Raises KeyError when the run has no such step."""
        row = int(step) - int(self.steps[0])
        if 0 <= row < len(self.steps) and self.steps[row] == step:
            return row
        raise KeyError(f"{self.log_path}: no DREAM_POSES step {step} (steps {self.steps[0]}..{self.steps[-1]})")

    def __repr__(self):
        return (f"Run({self.log_path!r}: {self.num_robots} robots, steps {self.steps[0]}..{self.steps[-1]}, "
                f"final state {self.final_state})")


STATUS_DTYPE = [("step", "i8"), ("t_s", "f8"), ("state", "i1"), ("boundary_errors", "i8"),
                ("collision_errors", "i8"), ("actuator_errors", "i8"), ("obstacle_collisions", "i8"),
                ("rejected_commands", "i8"), ("num_lost", "i4")]


def _followed_run(poses_rows):
    """The rows of the run a log is of, with the world's resends left out.

    A recording of the bus (lcm-logger) holds the world's resends of a step (the same message
    again while it waits for answers) and maybe a second world's messages (another run id, such
    as a `dream sim` waiting beside the run). As RunLog in C++: each run id's rows in log order,
    a row equal to the one before it dropped; the run with the most steps is the log's, the first
    heard on a tie. Returns (rows, run_id, resends, other_run_ids).
    """
    by_run = {}
    resends = {}
    for row in poses_rows:
        rows = by_run.setdefault(row[8], [])
        if rows and rows[-1][:7] == row[:7]:
            resends[row[8]] = resends.get(row[8], 0) + 1
            continue
        rows.append(row)
    run_id = max(by_run, key=lambda rid: len(by_run[rid]))  # max keeps the first heard on a tie
    return by_run[run_id], run_id, resends.get(run_id, 0), [rid for rid in by_run if rid != run_id]


def load(path, types_dir=None):
    """Loads a run folder (its run.lcmlog) or a .lcmlog file into a Run.

    types_dir: the folder holding the generated package dream/ (see import_types).
    Raises FileNotFoundError, LogFormatError (not an LCM log, cut short, damaged) or
    RunLogError (no DREAM_POSES, a message that does not decode as its channel's type,
    robots or steps that do not add up), each naming the file.
    """
    import numpy as np

    dream = import_types(types_dir)
    log_path = log_path_of(path)

    poses_rows = []  # (step, utime, x, y, theta, v, w)
    status_rows = []
    final_status = None
    obstacles_by_step = {}
    commands = {}  # (step, robot) -> (v, w, done), the first one
    radio_counts = {}
    channels = {}

    def decode(message_type, event, index):
        try:
            return message_type.decode(event.data)
        except Exception as error:  # ValueError("Decode error") on a wrong fingerprint, struct.error when short
            raise RunLogError(f"{log_path}: event {index} on {event.channel} does not decode as "
                              f"{message_type.__name__}: {error}") from None

    for index, event in enumerate(read_events(log_path)):
        channel = event.channel
        channels[channel] = channels.get(channel, 0) + 1
        if channel == POSES_CHANNEL:
            m = decode(dream.robot_poses_t, event, index)
            poses_rows.append((m.step, m.utime, m.x, m.y, m.theta, m.v, m.w, index, m.run_id))
        elif channel == STATUS_CHANNEL:
            m = decode(dream.run_status_t, event, index)
            status_rows.append((m.run_id, (m.step, m.utime * 1e-6, m.state, m.boundary_errors, m.collision_errors,
                                           m.actuator_errors, m.obstacle_collisions, m.rejected_commands, m.num_lost),
                                m))
        elif channel == OBSTACLES_CHANNEL:
            m = decode(dream.obstacles_t, event, index)
            obstacles_by_step.setdefault((m.run_id, m.step), [(o.id, o.center_x, o.center_y, o.width, o.height,
                                                               o.vx, o.vy) for o in m.obstacles])
        else:
            match = _COMMAND_CHANNEL.fullmatch(channel)
            if match:
                m = decode(dream.velocity_command_t, event, index)
                commands.setdefault((m.run_id, m.step, int(match.group(1))), (m.v, m.w, m.done))
                continue
            match = _RADIO_CHANNEL.fullmatch(channel)
            if match:
                sender = int(match.group(1))
                radio_counts[sender] = radio_counts.get(sender, 0) + 1

    if not poses_rows:
        raise RunLogError(f"{log_path}: no {POSES_CHANNEL} message in {sum(channels.values())} events: "
                          f"not a DREAM run log, or the run never published its first step")
    poses_rows, run_id, resends, other_run_ids = _followed_run(poses_rows)
    num_robots = len(poses_rows[0][2])
    previous_step = None
    for step, _, x, _, _, _, _, index, _ in poses_rows:
        if len(x) != num_robots:
            raise RunLogError(f"{log_path}: event {index}: {POSES_CHANNEL} step {step} has {len(x)} robots, "
                              f"step {poses_rows[0][0]} had {num_robots}")
        if previous_step is not None and step == previous_step:
            raise RunLogError(f"{log_path}: event {index}: two different {POSES_CHANNEL} for step {step} of one run "
                              f"(a resend is the same message again)")
        if previous_step is not None and step != previous_step + 1:
            raise RunLogError(f"{log_path}: event {index}: {POSES_CHANNEL} step {step} follows step "
                              f"{previous_step}; expected consecutive steps")
        previous_step = step
    statuses = [(row, m) for rid, row, m in status_rows if rid == run_id]
    # The world repeats its last status so agents hear it: a resend, once.
    statuses = [item for i, item in enumerate(statuses) if i == 0 or item[0] != statuses[i - 1][0]]
    final_status = statuses[-1][1] if statuses else None
    status_rows = [row for row, _ in statuses]
    obstacles_by_step = {step: rows for (rid, step), rows in obstacles_by_step.items() if rid == run_id}
    commands = {(step, robot): value for (rid, step, robot), value in commands.items() if rid == run_id}

    run = Run()
    run.log_path = log_path
    run.num_robots = num_robots
    run.steps = np.array([row[0] for row in poses_rows], dtype=np.int64)
    run.t_s = np.array([row[1] for row in poses_rows], dtype=np.float64) * 1e-6
    run.poses = np.array([row[2:5] for row in poses_rows], dtype=np.float64).transpose(0, 2, 1)
    run.velocities = np.array([row[5:7] for row in poses_rows], dtype=np.float64).transpose(0, 2, 1)
    first_step = int(run.steps[0])
    run.commands = np.full((len(run.steps), num_robots, 2), np.nan)
    run.done = np.zeros((len(run.steps), num_robots), dtype=bool)
    for (step, robot), (v, w, done) in commands.items():
        row = step - first_step
        if 0 <= row < len(run.steps) and 0 <= robot < num_robots:
            run.commands[row, robot] = (v, w)
            run.done[row, robot] = done
    run.status = np.array(status_rows, dtype=STATUS_DTYPE)
    if final_status is not None:
        run.final_state = STATE_NAMES.get(final_status.state, str(final_status.state))
        run.final_detail = final_status.detail
    empty = np.zeros((0, len(OBSTACLE_COLUMNS)))
    run.obstacles = [np.array(obstacles_by_step[int(k)], dtype=np.float64).reshape(-1, len(OBSTACLE_COLUMNS))
                     if int(k) in obstacles_by_step else empty for k in run.steps]
    run.radio_counts = radio_counts
    run.channels = channels
    run.run_id = run_id
    run.resends = resends
    run.other_run_ids = other_run_ids
    summary_path = os.path.join(os.path.dirname(log_path), "summary.json")
    if os.path.isfile(summary_path):
        with open(summary_path) as f:
            run.summary = json.load(f)
    return run


def main(argv):
    """`python3 dream_log.py RUN [TYPES_DIR]`: what load() makes of a run, in a few lines."""
    if len(argv) not in (2, 3):
        print("usage: dream_log.py RUN_FOLDER_OR_LOG [TYPES_DIR]", file=sys.stderr)
        return 2
    try:
        run = load(argv[1], argv[2] if len(argv) == 3 else None)
    except (ValueError, OSError, ImportError) as error:
        print(f"dream_log: {error}", file=sys.stderr)
        return 1
    print(run)
    print(f"poses {run.poses.shape}, commands {run.commands.shape}, {len(run.status)} status messages, "
          f"{max((len(o) for o in run.obstacles), default=0)} obstacles, "
          f"{sum(run.radio_counts.values())} radio messages")
    for channel, count in sorted(run.channels.items()):
        print(f"  {channel}: {count}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
