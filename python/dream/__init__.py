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
from .transformations import create_si_to_uni_dynamics, create_si_to_uni_dynamics_with_backwards_motion, create_si_to_uni_mapping, create_uni_to_si_mapping
from .controllers import create_pose_controller_clf, create_pose_controller_hybrid, create_pose_parking_controller_clf, create_pose_parking_controller_hybrid, create_si_position_controller, create_uni_position_controller
from .graph import completeGL, cycleGL, delta_disk_neighbors, lineGL, randomGL, random_connectedGL, topological_neighbors
from .misc import create_at_pose, create_at_position, determine_font_size, generate_initial_poses, generate_random_poses, generate_random_positions, rotation_matrix, unique_filename
from .toolbox_checks import ToolboxArgumentError
