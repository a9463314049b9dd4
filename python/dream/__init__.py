"""DREAM's Python controller runtime: write a Robot subclass, run it as LCM agents or in a
Robotarium submission (docs/python-runtime-contract.md). Controllers import from here:
`from dream import Robot, key`. Single-line relative imports only: the submission exporter
flattens this package into dream_*.py files."""

from .motion import ActuatorLimits, RobotLimits, SingleIntegratorToUnicycle, dxi_to_dxu
from .robot import REQUIRED, Key, MovementReading, NeighbourDetection, ObstacleReading, ObstacleRectangle, ObstacleView, OdometryReading, Robot, RobotParams, WorldSnapshot, key
from .radios import GraphRadio, Mailbox, RadioMessage, RangeRadio, RoleRadio, mix_seed, pack_floats, unpack_floats
from .sensors import MovementSensor, ObstacleSensor, OdometrySensor, wrap_angle
from .timer import Timer
from .robot_agent import AgentOutput, ControllerFault, ControllerTimeout, RobotAgent, RunInterrupted, controller_error_text, is_run_interrupt
from .controller_spec import ConfigError, ControllerSpec, check
from .hrvo import HrvoAvoidance, HrvoParams
from .barriers import create_si_barrier_certificate, create_si_barrier_certificate_with_boundary, create_uni_barrier_certificate, create_uni_barrier_certificate_with_boundary
