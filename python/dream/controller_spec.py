"""From the controller spec (JSON text C++ makes from a config's `kind: python` section) to
RobotAgents: checks the spec strictly, loads the user's module, checks the controller's own
keys against its class's KEYS and builds each robot's parts as
agents/kind_api/src/agent_parts_config.cc and agents/agent_host/src/controller_factory.cc do (same seeds).

Config mistakes raise ConfigError("FILE:LINE: controller.KEY: problem"), FILE being the
config file, so that a Python controller's keys are reported like a C++ one's.
"""

import copy
import importlib.util
import itertools
import json
import math
import os
import sys
from collections import namedtuple

import numpy as np

from .radios import GraphRadio, RangeRadio, RoleRadio, mix_seed
from .robot import Key, Robot, RobotParams, did_you_mean, key, number_text
from .robot_agent import ControllerFault, RobotAgent, controller_error_text, is_run_interrupt
from .sensors import MovementSensor, ObstacleSensor, OdometrySensor

SPEC_FORMAT = 1
SECTION_KEYS = ("kind", "module", "class", "robot", "sensors", "radio")  # the section's keys that are not params
SPEC_KEYS = ("format", "name", "config_file", "robots", "seed", "module", "class", "section_line", "module_line",
             "class_line", "params", "parts")
# Per sensor kind its fields; movement's are everyone's.
SENSOR_KEYS = {"odometry": ("kind", "period_steps", "noise_std"),
               "movement": ("kind", "period_steps", "range_m", "direction_rad", "field_of_view_rad", "noise_std"),
               "obstacle": ("kind", "period_steps", "range_m", "noise_std")}
RADIO_KINDS = ("none", "range", "graph", "role")
RADIO_KEYS = ("kind", "period_steps", "range_m", "graph", "leaders", "loss_probability", "delay_steps")

# The deepest nesting a spec may have: a config's (ConfigNode::kMaxDepth, 100) and the spec's own
# few levels around it. Deeper JSON is refused before it is parsed (Python's parser would recurse).
MAX_SPEC_DEPTH = 128

_MATRIX = key(None, kind="matrix")
_module_counter = itertools.count()


def _json_depth(text, limit):
    """The deepest nesting of [ and { in the JSON `text`, counted outside strings, up to limit + 1
    (the scan stops there): a bound checked before json.loads recurses into it."""
    depth = deepest = 0
    in_string = escaped = False
    for char in text:
        if in_string:
            if escaped:
                escaped = False
            elif char == "\\":
                escaped = True
            elif char == '"':
                in_string = False
        elif char == '"':
            in_string = True
        elif char in "[{":
            depth += 1
            if depth > deepest:
                deepest = depth
                if deepest > limit:
                    break
        elif char in "]}":
            depth -= 1
    return deepest


def _at(config_file, line):
    """Where a key stands, as C++'s ConfigNode says it: "file:line", or just "file" for a key with
    no line (one a --set added)."""
    return f"{config_file}:{line}" if line else config_file


class ConfigError(Exception):
    """A mistake in the config or the spec, with the file, line and key it is at."""


class _Problem(Exception):
    """A value's problem, raised by the checkers; `where` is the path below the key ("[2]")."""

    def __init__(self, message, where=""):
        super().__init__(message)
        self.where = where


def value_text(value):
    """What an error says a value was, as C++'s ConfigNode does: 'text', a list, a mapping, ..."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, (int, float)):
        return number_text(value)
    if isinstance(value, str):
        return f"'{value}'"
    if isinstance(value, list):
        return "a list"
    if isinstance(value, dict):
        return "a mapping"
    return "nothing"


def _is_number(value):
    return isinstance(value, (int, float)) and not isinstance(value, bool)


def _finite_number(value, where=""):
    if not _is_number(value):
        raise _Problem(f"expected a number, got {value_text(value)}", where)
    if not math.isfinite(value):
        raise _Problem(f"expected a finite number, got {value_text(value)}", where)
    return float(value)


def _whole_number(value, where=""):
    if _is_number(value) and float(value).is_integer():
        return int(value)
    raise _Problem(f"expected a whole number, got {value_text(value)}", where)


def _range_text(spec):
    """The range a Key allows as the C++ messages write it: "> 0", "in (0, 0.2]"."""
    lower = ("(", spec.above) if spec.above is not None else ("[", spec.at_least) if spec.at_least is not None else None
    upper = (")", spec.below) if spec.below is not None else ("]", spec.at_most) if spec.at_most is not None else None
    if lower and upper:
        return f"in {lower[0]}{number_text(lower[1])}, {number_text(upper[1])}{upper[0]}"
    if lower:
        return f"{'>' if lower[0] == '(' else '>='} {number_text(lower[1])}"
    return f"{'<' if upper[0] == ')' else '<='} {number_text(upper[1])}"


def _in_range(value, spec):
    return ((spec.above is None or value > spec.above) and (spec.at_least is None or value >= spec.at_least)
            and (spec.at_most is None or value <= spec.at_most) and (spec.below is None or value < spec.below))


def _point(value, where):
    if not (isinstance(value, list) and len(value) == 2 and all(_is_number(x) and math.isfinite(x) for x in value)):
        raise _Problem(f"expected [x, y] in metres, finite numbers, got {value_text(value)}", where)
    return value


def _one_value(value, spec, where=""):
    """`value` checked and converted for one entry of kind spec.kind."""
    kind = spec.kind
    if kind == "number" or kind == "int":
        checked = _finite_number(value, where) if kind == "number" else _whole_number(value, where)
        if not _in_range(checked, spec):
            raise _Problem(f"must be {_range_text(spec)}, got {value_text(value)}", where)
    elif kind == "bool":
        if not isinstance(value, bool):
            raise _Problem(f"expected true or false, got {value_text(value)}", where)
        checked = value
    elif kind == "string":
        if not isinstance(value, str):
            raise _Problem(f"expected text, got {value_text(value)}", where)
        checked = value
    elif kind == "points":
        if not isinstance(value, list):
            raise _Problem(f"expected a list of [x, y] points, got {value_text(value)}", where)
        checked = np.array([_point(p, f"{where}[{i}]") for i, p in enumerate(value)], dtype=float).reshape(-1, 2)
    elif kind == "matrix":
        if not (isinstance(value, list) and value and all(isinstance(row, list) for row in value)):
            raise _Problem(f"expected a matrix as a list of rows like [[0, 1], [1, 0]], got {value_text(value)}", where)
        for i, row in enumerate(value):
            if len(row) != len(value[0]):
                raise _Problem(f"row {i} has {len(row)} entries, row 0 has {len(value[0])}", f"{where}[{i}]")
            for j, entry in enumerate(row):
                _finite_number(entry, f"{where}[{i}][{j}]")
        checked = np.array(value, dtype=float)
    elif kind == "list":
        if not isinstance(value, list):
            raise _Problem(f"expected a list, got {value_text(value)}", where)
        checked = value
    else:
        checked = value
    if spec.choices is not None and checked not in spec.choices:
        names = [c for c in spec.choices if isinstance(c, str)]
        suggestion = did_you_mean(value, names) if isinstance(value, str) else ""
        raise _Problem(f"must be one of {', '.join(value_text(c) for c in spec.choices)}, got "
                       f"{value_text(value)}{suggestion}", where)
    return checked


def check_key_value(value, spec, num_robots):
    """`value` of a key declared as `spec`, checked and converted (floats, np.arrays for points
    and matrices); per_robot values become one entry per robot (a single scalar is everyone's).
    Raises _Problem."""
    if not spec.per_robot:
        return _one_value(value, spec)
    if spec.kind == "points":
        if not isinstance(value, list) or len(value) != num_robots:
            count = len(value) if isinstance(value, list) else value_text(value)
            raise _Problem(f"expected one [x, y] per robot ({num_robots}), got {count}")
        return _one_value(value, spec)
    if not isinstance(value, list):
        if spec.kind in ("number", "int", "bool", "string"):
            return [_one_value(value, spec)] * num_robots
        raise _Problem(f"expected a list with one entry per robot ({num_robots}), got {value_text(value)}")
    if len(value) != num_robots:
        raise _Problem(f"expected one entry per robot ({num_robots}), got {len(value)}")
    return [_one_value(entry, spec, f"[{i}]") for i, entry in enumerate(value)]


def load_controller_class(module_path, class_name):
    """The Robot subclass `class_name` of the file `module_path`, imported under a unique name
    with its folder on sys.path (so that helpers beside it import). Raises _Problem whose
    `where` is the key at fault, module or class."""
    path = os.path.abspath(module_path)
    if not os.path.isfile(path):
        raise _Problem(f"no controller module at {path}", "module")
    folder = os.path.dirname(path)
    if folder not in sys.path:
        sys.path.insert(0, folder)
    stem = os.path.splitext(os.path.basename(path))[0]
    module_name = f"dream_controller_{next(_module_counter)}_{stem}"
    module_spec = importlib.util.spec_from_file_location(module_name, path)
    module = importlib.util.module_from_spec(module_spec)
    sys.modules[module_name] = module
    try:
        module_spec.loader.exec_module(module)
    except SyntaxError as exc:
        del sys.modules[module_name]
        raise _Problem(f"cannot load {path}: {exc.filename}:{exc.lineno}: SyntaxError: {exc.msg}", "module") from None
    except BaseException as exc:  # SystemExit at import too: a mistake in the module
        del sys.modules[module_name]
        if is_run_interrupt(exc):
            raise
        raise _Problem(f"cannot load {path}: {controller_error_text(exc, path)}", "module") from None
    robot_class = getattr(module, class_name, None)
    if not (isinstance(robot_class, type) and issubclass(robot_class, Robot)):
        found = sorted(name for name, value in vars(module).items()
                       if isinstance(value, type) and issubclass(value, Robot) and value is not Robot)
        problem = "is not a subclass of dream.Robot" if robot_class is not None else f"is not in {path}"
        raise _Problem(f"'{class_name}' {problem}; Robot subclasses there: {', '.join(found) or 'none'}", "class")
    return robot_class


class _SpecReader:
    """Reads one spec field after another, failing with the field's path."""

    def __init__(self, data, path, allowed):
        if not isinstance(data, dict):
            self.fail(path, f"expected a mapping, got {value_text(data)}")
        for name in data:
            if name not in allowed:
                self.fail(f"{path}{name}", f"unknown field; allowed fields here: {', '.join(allowed)}")
        self.data = data
        self.path = path

    @staticmethod
    def fail(path, message):
        raise ConfigError(f"controller spec: {path or '(top level)'}: {message}")

    def get(self, name, check):
        if name not in self.data:
            self.fail(self.path + name, "missing; this field is required")
        try:
            return check(self.data[name])
        except _Problem as problem:
            self.fail(self.path + name + problem.where, str(problem))

    def child(self, name, allowed):
        if name not in self.data:
            self.fail(self.path + name, "missing; this field is required")
        return _SpecReader(self.data[name], f"{self.path}{name}.", allowed)


def _text(value):
    if not isinstance(value, str):
        raise _Problem(f"expected text, got {value_text(value)}")
    return value


def _list(value):
    if not isinstance(value, list):
        raise _Problem(f"expected a list, got {value_text(value)}")
    return value


def _at_least(minimum):
    def check(value):
        number = _whole_number(value)
        if number < minimum:
            raise _Problem(f"must be >= {minimum}, got {number}")
        return number
    return check


def _per_robot_steps(num_robots, minimum):
    def check(value):
        if not isinstance(value, list) or len(value) != num_robots:
            count = len(value) if isinstance(value, list) else value_text(value)
            raise _Problem(f"expected a list with one entry per robot ({num_robots}), got {count}")
        steps = []
        for i, entry in enumerate(value):
            try:
                steps.append(_at_least(minimum)(entry))
            except _Problem as problem:
                raise _Problem(str(problem), f"[{i}]") from None
        return steps
    return check


class SensorSpec(namedtuple("SensorSpec", ("kind", "period_steps", "options"))):
    """One sensor of every robot: kind, per-robot periods and the sensor's keyword arguments."""

    __slots__ = ()

    def make(self, seed):
        sensor_class = {"odometry": OdometrySensor, "movement": MovementSensor, "obstacle": ObstacleSensor}[self.kind]
        return sensor_class(seed=seed, **self.options)


class RadioSpec(namedtuple("RadioSpec", ("kind", "period_steps", "range_m", "graph", "leaders", "loss_probability",
                                         "delay_steps"))):
    """Every robot's radio and link: kind, per-robot periods, range, graph, leaders, loss, delay."""

    __slots__ = ()

    def make(self, robot_id):
        """Robot `robot_id`'s radio, or None for kind none."""
        if self.kind == "range":
            return RangeRadio(self.range_m)
        if self.kind == "graph":
            return GraphRadio(self.graph)
        if self.kind == "role":
            return RoleRadio(robot_id in self.leaders, self.graph)
        return None


def _read_sensor(reader, num_robots):
    kind = reader.get("kind", _text)
    if kind not in SENSOR_KEYS:
        reader.fail(reader.path + "kind", f"unknown sensor kind '{kind}'; known kinds: {', '.join(SENSOR_KEYS)}")
    _SpecReader(reader.data, reader.path, SENSOR_KEYS[kind])  # rejects another kind's fields
    options = {name: reader.get(name, _finite_number) for name in SENSOR_KEYS[kind][2:]}
    spec = SensorSpec(kind, reader.get("period_steps", _per_robot_steps(num_robots, 1)), options)
    try:
        spec.make(seed=0)
    except ValueError as error:
        reader.fail(reader.path.rstrip("."), str(error))
    return spec


def _read_radio(reader, num_robots):
    kind = reader.get("kind", _text)
    if kind not in RADIO_KINDS:
        reader.fail(reader.path + "kind", f"unknown radio kind '{kind}'; known kinds: {', '.join(RADIO_KINDS)}")
    range_m = reader.get("range_m", _finite_number) if kind == "range" else None
    graph = None
    if kind in ("graph", "role"):
        graph = reader.get("graph", lambda value: _one_value(value, _MATRIX))
        if graph.shape != (num_robots, num_robots):
            reader.fail(reader.path + "graph", f"must be {num_robots}x{num_robots}, got {graph.shape[0]}x{graph.shape[1]}")
        graph = graph.tolist()
    leaders = ()
    if kind == "role":
        leaders = reader.get("leaders", _list)
        if not leaders or any(not (_is_number(i) and float(i).is_integer() and 0 <= i < num_robots) for i in leaders):
            reader.fail(reader.path + "leaders", f"expected a list of leader ids in 0..{num_robots - 1}")
    spec = RadioSpec(kind, reader.get("period_steps", _per_robot_steps(num_robots, 1)), range_m, graph,
                     frozenset(int(i) for i in leaders), reader.get("loss_probability", _finite_number),
                     reader.get("delay_steps", _at_least(0)))
    if not 0.0 <= spec.loss_probability < 1.0:
        reader.fail(reader.path + "loss_probability",
                    f"must be in [0, 1), got {number_text(spec.loss_probability)}")
    try:
        spec.make(0)
    except ValueError as error:
        reader.fail(reader.path.rstrip("."), str(error))
    return spec


class ControllerSpec:
    """A checked controller spec: the user's Robot class, its checked config and every robot's
    parts. make_agent(robot_id) builds one robot's RobotAgent."""

    def __init__(self, name, config_file, num_robots, seed, module_path, robot_class, section_line, config,
                 robot_parts, sensors, radio):
        self.name = name
        self.config_file = config_file
        self.num_robots = num_robots
        self.seed = seed
        self.module_path = module_path
        self.robot_class = robot_class
        self.section_line = section_line
        self.config = config
        self.robot_parts = robot_parts  # period_steps, start_delay_steps, vel_gain, ang_gain
        self.sensors = sensors
        self.radio = radio

    @classmethod
    def from_json(cls, text):
        """Parses and checks the spec, loads the controller class and checks its keys."""
        if _json_depth(text, MAX_SPEC_DEPTH) > MAX_SPEC_DEPTH:
            raise ConfigError(f"controller spec: nested more than {MAX_SPEC_DEPTH} levels deep; a spec written by "
                              f"DREAM never is (was it edited?)")
        try:
            data = json.loads(text)
        except ValueError as error:
            raise ConfigError(f"controller spec: not valid JSON: {error}") from None
        top = _SpecReader(data, "", SPEC_KEYS)
        if top.get("format", _whole_number) != SPEC_FORMAT:
            top.fail("format", f"this runtime reads format {SPEC_FORMAT}, got {value_text(data['format'])}")
        name = top.get("name", _text)
        config_file = top.get("config_file", _text)
        num_robots = top.get("robots", _at_least(1))
        seed = top.get("seed", _at_least(0))
        module_path = top.get("module", _text)
        class_name = top.get("class", _text)
        section_line = top.get("section_line", _at_least(0))
        lines = {"module": top.get("module_line", _at_least(0)), "class": top.get("class_line", _at_least(0))}
        params = top.get("params", _params)
        parts = top.child("parts", ("robot", "sensors", "radio"))
        robot = parts.child("robot", ("period_steps", "start_delay_steps", "vel_gain", "ang_gain"))
        robot_parts = {"period_steps": robot.get("period_steps", _per_robot_steps(num_robots, 1)),
                       "start_delay_steps": robot.get("start_delay_steps", _per_robot_steps(num_robots, 0)),
                       "vel_gain": robot.get("vel_gain", _finite_number),
                       "ang_gain": robot.get("ang_gain", _finite_number)}
        try:
            RobotParams(robot_parts["vel_gain"], robot_parts["ang_gain"]).check()
        except ValueError as error:
            robot.fail("parts.robot", str(error))
        sensors = [_read_sensor(_SpecReader(entry, f"parts.sensors[{i}].", SENSOR_KEYS["movement"]), num_robots)
                   for i, entry in enumerate(parts.get("sensors", _list))]
        radio = _read_radio(parts.child("radio", RADIO_KEYS), num_robots)
        try:
            robot_class = load_controller_class(module_path, class_name)
        except _Problem as problem:
            line = lines.get(problem.where, section_line)
            raise ConfigError(f"{_at(config_file, line)}: controller.{problem.where}: {problem}") from None
        config = check_params(robot_class, params, num_robots, config_file, section_line)
        return cls(name, config_file, num_robots, seed, os.path.abspath(module_path), robot_class, section_line,
                   config, robot_parts, sensors, radio)

    def make_agent(self, robot_id):
        """Robot `robot_id`'s RobotAgent, seeded as ControllerFactory::Make: sensor s from
        mix_seed(seed, robot_id, s + 1), the mailbox from mix_seed(seed, robot_id, 0). Its robot's
        setup() has run; a fault there is the agent's `fault`, raised by its first step()."""
        if not 0 <= robot_id < self.num_robots:
            raise IndexError(f"robot {robot_id} is not in this run (robots 0..{self.num_robots - 1})")
        parts = self.robot_parts
        params = RobotParams(parts["vel_gain"], parts["ang_gain"])
        try:
            robot = self.robot_class(robot_id, params, copy.deepcopy(self.config), self.num_robots)
        except BaseException as exc:  # as RobotAgent: anything but an interrupt of the run is a fault
            if is_run_interrupt(exc):
                raise
            raise ControllerFault(controller_error_text(exc, self.module_path)) from exc
        sensors = [(sensor.make(mix_seed(self.seed, robot_id, index + 1)), sensor.period_steps[robot_id])
                   for index, sensor in enumerate(self.sensors)]
        return RobotAgent(robot, sensors, self.radio.make(robot_id),
                          robot_period_steps=parts["period_steps"][robot_id],
                          start_delay_steps=parts["start_delay_steps"][robot_id],
                          radio_period_steps=self.radio.period_steps[robot_id],
                          loss_probability=self.radio.loss_probability, delay_steps=self.radio.delay_steps,
                          seed=mix_seed(self.seed, robot_id, 0))


def _params(value):
    if not isinstance(value, dict):
        raise _Problem(f"expected a mapping of key -> {{value, line}}, got {value_text(value)}")
    for name, entry in value.items():
        if not (isinstance(entry, dict) and set(entry) == {"value", "line"} and _is_number(entry["line"])):
            raise _Problem(f"expected {{\"value\": ..., \"line\": N}}, got {value_text(entry)}", f".{name}")
    return value


def check_params(robot_class, params, num_robots, config_file, section_line):
    """The controller's config: `params` ({key: {value, line}}) checked against
    robot_class.KEYS, defaults applied. Raises ConfigError at the key's line."""
    keys = robot_class.KEYS
    class_name = robot_class.__name__
    for name, spec in keys.items():
        if not isinstance(spec, Key):
            raise ConfigError(f"{_at(config_file, section_line)}: controller: {class_name}.KEYS['{name}'] must be "
                              f"made with dream.key(...), got {spec!r}")
        if name in SECTION_KEYS:
            raise ConfigError(f"{_at(config_file, section_line)}: controller: {class_name}.KEYS may not declare "
                              f"'{name}'; the section's own keys are {', '.join(SECTION_KEYS)}")
    for name, entry in params.items():
        if name not in keys:
            allowed = ", ".join(SECTION_KEYS + tuple(keys))
            suggestion = did_you_mean(name, SECTION_KEYS + tuple(keys))
            raise ConfigError(f"{_at(config_file, entry['line'])}: controller.{name}: unknown key for kind python "
                              f"class {class_name}{suggestion}; allowed keys here: {allowed}")
    config = {}
    for name, spec in keys.items():
        if name in params:
            line = params[name]["line"]
            value = params[name]["value"]
        elif spec.required:
            raise ConfigError(f"{_at(config_file, section_line)}: controller.{name}: required by class {class_name}; "
                              f"missing here")
        else:
            line = section_line
            value = copy.deepcopy(spec.default)
        try:
            config[name] = check_key_value(value, spec, num_robots)
        except _Problem as problem:
            origin = "" if name in params else f" (the default of {class_name}.KEYS['{name}'])"
            raise ConfigError(
                f"{_at(config_file, line)}: controller.{name}{problem.where}: {problem}{origin}") from None
    return config


def check(text, around=lambda work, robot_id=-1: work()):
    """Everything from_json checks, plus every robot's setup(): the spec, or ConfigError
    saying which robot's setup failed where. `around(work, robot_id)` runs each part (robot
    -1: loading the module), so that the embedding tool can watch them."""
    spec = around(lambda: ControllerSpec.from_json(text))
    for robot_id in range(spec.num_robots):
        try:
            fault = around(lambda robot_id=robot_id: spec.make_agent(robot_id), robot_id).fault
        except ControllerFault as construction_fault:
            fault = construction_fault
        if fault is not None:
            raise ConfigError(f"{_at(spec.config_file, spec.section_line)}: controller: robot {robot_id}'s "
                              f"{spec.robot_class.__name__} failed to set up: {fault}")
    return spec
