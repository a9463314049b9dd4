"""Entry points for the C++ tool that embeds Python (agents/python_embedded/PythonAgentHost).

`dream-agent-shared --python-host`, the process `dream run`, `dream agent` (so also `dream launch`) and
`dream lab-replay` start for their Python controllers, hosts the agents on its own memq:// bus
through these calls, and the command relays the run's messages to it; the work is done by
AgentHost and ControllerSpec, the same code a Robotarium submission runs.
"""

import importlib
import logging
import os
import sys

from .agent_host import CELL_ROBOT, CELL_STEP, CELL_TOKEN, AgentHost, call_cell, next_call_token, set_call_cell
from .controller_spec import ControllerSpec, check as check_spec
from .lcm import Lcm
from .robot_agent import ControllerTimeout, RunInterrupted  # noqa: F401 - the watchdog raises them

_log = logging.getLogger("dream")


class _ToolFormatter(logging.Formatter):
    """The tool's own log lines ('[12:00:01.250] [warning] ...'), so Python's mix in unnoticed."""

    def format(self, record):
        record.levelname = record.levelname.lower()
        return super().format(record)


def setup(lcmtypes_dir, log_level, watchdog_cell=None):
    """Makes lcm-gen's Python types (package dream) importable as dream.<type>, and logs
    like the tool, on stderr at the tool's level. `watchdog_cell`: the tool's watchdog's
    memory (three int64), where every controller call is marked (agent_host.set_call_cell)."""
    _watched_by_parent()
    if watchdog_cell is not None:
        set_call_cell(watchdog_cell.cast("q") if watchdog_cell.format != "q" else watchdog_cell)
    package = sys.modules[__package__]
    types_package = os.path.join(lcmtypes_dir, "dream")
    if not os.path.isfile(os.path.join(types_package, "robot_poses_t.py")):
        raise RuntimeError(f"lcm-gen's Python types are not in {types_package} (build the project first)")
    if types_package not in package.__path__:
        package.__path__.append(types_package)
    # As lcm-gen's own __init__.py does: dream.<type> is the class, which its generated
    # decoders rely on (dream.rectangle_obstacle_t._decode_one inside obstacles_t).
    for file_name in sorted(os.listdir(types_package)):
        name, extension = os.path.splitext(file_name)
        if extension == ".py" and name.endswith("_t"):
            module = importlib.import_module(f"{__package__}.{name}")
            setattr(package, name, getattr(module, name))
    if not _log.handlers:
        handler = logging.StreamHandler(sys.stderr)
        handler.setFormatter(_ToolFormatter("[%(asctime)s.%(msecs)03d] [%(levelname)s] %(message)s", "%H:%M:%S"))
        _log.addHandler(handler)
        _log.propagate = False
    _log.setLevel(log_level)


TRACE_FD_VARIABLE = "DREAM_PYTHON_TRACE_FD"
_trace_file = None  # kept open: faulthandler writes to it


def _watched_by_parent():
    """In the process that hosts the controllers for dream (PythonHostProcess, which names a
    descriptor in DREAM_PYTHON_TRACE_FD): Python's traceback goes there when the process
    crashes, or on SIGUSR1, which dream sends before it ends a call stuck outside Python, so
    the fault names the line; and when a controller calls os._exit. A copy of this process made
    by a controller's os.fork() ends at once: it would answer for the robots a second time, on
    the same link."""
    global _trace_file
    trace_fd = os.environ.pop(TRACE_FD_VARIABLE, None)
    if trace_fd is None or _trace_file is not None:
        return
    import faulthandler
    import signal
    _trace_file = os.fdopen(int(trace_fd), "w")
    faulthandler.enable(file=_trace_file, all_threads=True)
    faulthandler.register(signal.SIGUSR1, file=_trace_file, all_threads=True)
    exit_now = os._exit

    def traced_exit(code):
        """os._exit, with the line that called it for dream's report."""
        faulthandler.dump_traceback(file=_trace_file, all_threads=False)
        exit_now(code)

    os._exit = traced_exit
    os.register_at_fork(after_in_child=lambda: exit_now(0))


_checked = {}  # spec text -> its ControllerSpec, so attach() does not load the module again


def _starting(work, robot_id=-1):
    """work() marked as a start-up call (a negative token) of robot `robot_id` (-1: loading the
    module): it loads the module or runs setup(), which Ctrl-C interrupts (RunInterrupted) and
    the world's start_timeout_s bounds, not its agent_timeout_s."""
    cell = call_cell()
    try:
        cell[CELL_ROBOT] = robot_id
        cell[CELL_STEP] = 0
        cell[CELL_TOKEN] = -next_call_token()
        return work()
    finally:
        cell[CELL_TOKEN] = 0


def check(spec_json):
    """Raises ConfigError when the controller's module, class or own keys are wrong."""
    _checked[spec_json] = check_spec(spec_json, _starting)


class _EmbeddedHost(AgentHost):
    """An AgentHost on a bus the C++ side opened and keeps."""

    def close(self):
        self.bus.close()


def attach(lcm_address, url, spec_json, robot_ids, agent_id):
    """The agents of `robot_ids`, subscribed on the lcm_t at `lcm_address`."""
    spec = _checked.get(spec_json) or _starting(lambda: ControllerSpec.from_json(spec_json))
    agents = [_starting(lambda robot_id=robot_id: spec.make_agent(robot_id), robot_id) for robot_id in robot_ids]
    return _EmbeddedHost(Lcm.wrap(lcm_address, url), agents, agent_id, spec.num_robots)
