# Import Robotarium
import rps.robotarium as robotarium
from rps.utilities.transformations import *
from rps.utilities.graph import *
from rps.utilities.barrier_certificates import *
from rps.utilities.misc import *
from rps.utilities.controllers import *

# Import numpy for array manipulation and patches for extra plotting
import numpy as np
import matplotlib.patches as patches
import matplotlib.pyplot as plt  # CHANGED (README.md, 1): the thesis's rps.utilities.misc exported plt; V2.0.0's does not

# Import DREAM
from dream import *

class Robot_c(Robot_hrvo):
    def __init__(self, robot_id, tag, goal_points = np.array([[0.0],[0.0]]), vel_gain = 0.8, ang_gain = 3, safety = 0.24, color='k'):
        """
        Robot circle class.
        When its goal position has been reached, state += 1
        Send and receive robot_states by radio communications
        When all robot_states are the same, go to next goal point
        """

        self.robot_id = robot_id
        self.tag = tag
        self.goal_points = goal_points
        self.current_goal = self.goal_points[:, 0]

        self.vel_gain = vel_gain
        self.ang_gain = ang_gain

        self.delta_x = 0
        self.delta_y = 0

        self.desired_velocity = np.array((0.0, 0.0))

        self.robot_states = [0,0,0,0,0,0,0,0,0,0]
        self.state = 0
        self.change_state = True

        # Plot goal point and current velocity over the terrain
        self.color = color
        self.finalgoal = None
        self.target = None
        self.line1 = None
        self.line2 = None

        super().__init__(self.robot_id, self.tag, vel_gain=vel_gain, ang_gain=ang_gain, safety=safety)

    def update_radio(self, radio_data):
        self.radio_data = radio_data

        # Update variable with current robot states
        for i in range(len(self.radio_data)):
            for j in range(len(self.robot_states)):
                if self.radio_data[i][j] > self.robot_states[j]:
                    self.robot_states[j] = self.radio_data[i][j]

        self.robot_states[self.robot_id] = self.state

        # Check if all robots has reached its goal
        if all(flag == self.state for flag in self.robot_states):
            if self.state < 3:
                self.current_goal = self.goal_points[:, self.state]
                self.change_state = True

        # Send message to radio
        return self.robot_states

    def update_sensor(self, detections):
        self.detections = detections

    def update_odom(self, pos):
        self.pos_x = pos[0]
        self.pos_y = pos[1]
        self.rot_w = pos[2]

    def update(self, dxu_):

        # Compute desired velocity to reach the goal
        self.delta_x = self.current_goal[0] - self.pos_x
        self.delta_y = self.current_goal[1] - self.pos_y

        dist_error = np.sqrt(self.delta_x ** 2 + self.delta_y ** 2)
        angle_error = np.arctan2(self.delta_y, self.delta_x)

        if dist_error < 0.05:
            dist_error = 0
            self.desired_velocity = np.array((0.0, 0.0))

            if self.change_state:
                self.state += 1
                self.change_state = False

        else:
            self.desired_velocity[0] = self.v_max * self.delta_x / dist_error
            self.desired_velocity[1] = self.v_max * self.delta_y / dist_error

        # Compute HRVO to avoid obstacles
        self.HRVO(self.detections, self.desired_velocity)

        # Convert dxi velocities from HRVO to dxu
        self.dxi_to_dxu()

        # Limit velocity to not exceed actuator limits
        self.actuator_limit()

        # Return self.dxu
        dxu_[0][self.robot_id] = self.dxu[0]
        dxu_[1][self.robot_id] = self.dxu[1]

        # Plot goal points and hrvo points
        if self.finalgoal is not None:
            self.finalgoal.remove()
            self.target.remove()
            self.line1.remove()
            self.line2.remove()

        # CHANGED (README.md, 2): r.axes is r._axes_handle in V2.0.0 (four times below)
        self.finalgoal = plt.Circle((self.current_goal[0], self.current_goal[1]), 0.04, color=self.color)
        r._axes_handle.add_patch(self.finalgoal)
        self.target = plt.Circle((self.dxi[0]+self.pos_x, self.dxi[1]+self.pos_y), 0.02, color=self.color)
        r._axes_handle.add_patch(self.target)
        vertices=[(self.pos_x, self.pos_y), (self.dxi[0]+self.pos_x, self.dxi[1]+self.pos_y), (self.dxi[0]+self.pos_x, self.dxi[1]+self.pos_y), (self.pos_x, self.pos_y)]
        self.line1 = patches.Polygon(vertices, fill=False, lw=0.5, ls='-', color=self.color)
        r._axes_handle.add_patch(self.line1)
        vertices=[(self.dxi[0]+self.pos_x, self.dxi[1]+self.pos_y), (self.current_goal[0], self.current_goal[1]), (self.current_goal[0], self.current_goal[1]), (self.dxi[0]+self.pos_x, self.dxi[1]+self.pos_y)]
        self.line2 = patches.Polygon(vertices, fill=False, lw=0.5, ls='-', color=self.color)
        r._axes_handle.add_patch(self.line2)

#####################################################################

# Define number of robots and number of iterations of the simulation
N = 10
iterations = 1000

# Create a circular shape for the N robots
radius = 0.85
p_theta = 2 * np.pi * (np.arange(0, 2 * N, 2)/(2 * N))
p_circ = np.vstack([
            np.hstack([radius * np.cos(p_theta), radius * np.cos(p_theta+np.pi)]),
            np.hstack([radius * np.sin(p_theta), radius * np.sin(p_theta+np.pi)])
            ])

x_goal_1 = p_circ[:, :N]
x_goal_2 = p_circ[:, N:]

goal_points = np.vstack((x_goal_1[:, 0], x_goal_2[:, 0], x_goal_1[:, 0]))
for i in range(1, N):
    goal_points = np.vstack((goal_points, x_goal_1[:, i], x_goal_2[:, i], x_goal_1[:, i]))
goal_points = goal_points.T

# Create a Robotarium instance
r = robotarium.Robotarium(number_of_robots = N, show_figure = True, sim_in_real_time = False)

# Create tags for callback methods
robot_tag = 'robot'
movement_tag = 'movement'
odometry_tag = 'odom'
radio_tag = 'radio'

colors = ['black', 'red', 'gold', 'olive', 'yellow', 'lawngreen', 'lime', 'cyan', 'navy', 'magenta']

# Create N robots
for i in range(N):

    # Create a robot, a movement sensor, an odometry sensor and a radio
    rob = Robot_c(i, f'{robot_tag}_{i}', goal_points = goal_points[:, 3*i:3*i+3], color = colors[i])
    mov = Movement_sensor(i, f'{movement_tag}_{i}', rob.update_sensor)
    odo = Odometry_sensor(i, f'{odometry_tag}_{i}', rob.update_odom)
    rad = Radio_range(i, f'{radio_tag}_{i}', rob.update_radio)

    # Create list of timers
    list_timers = [
        {'delay': 4 + (i%2), 'tag': robot_tag, 'call': rob.update},
        {'delay': 3 + (i%2), 'tag': movement_tag, 'call': mov.update},
        {'delay': 2 + (i%2), 'tag': odometry_tag, 'call': odo.update},
        {'delay': 30, 'tag': radio_tag, 'call': rad.update}
    ]

    # Create Timer
    create_timer(i, 20 + i, list_timers)

# Simulation first step
dxu = np.zeros((2,N))
x = r.get_poses()
r.step()

# Rest of simulation steps
for i in range(iterations):

    # Get current poses from Robotarium
    x = r.get_poses()

    # Create dictionary of parameters for callback functions
    params = {movement_tag: (x, dxu), odometry_tag: (x,), radio_tag: (x,), robot_tag: (dxu,)}

    # Update Timer
    update_timers(i, params)

    # Send velocities to Robotarium
    r.set_velocities(np.arange(N), dxu)
    r.step()

r.debug()  # CHANGED (README.md, 3): call_at_scripts_end() is debug() in V2.0.0
