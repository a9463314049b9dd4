import numpy as np

from dream_sensor import *
from dream_radio import *
from dream_timer import *
from dream_specs import *

class Robot:
    def __init__(self, robot_id, tag = 'robot', vel_gain = 0.8, ang_gain = 3.0):
        """
        Main robot class.

        robot_id : int    -> id of robot
        tag       : str    -> name tag of the robot
        vel_gain  : float  -> velocity gain
        ang_gain  : float  -> angular gain

        """
        self.robot_id = robot_id
        self.tag = tag

        self.pos_x = 0
        self.pos_y = 0
        self.rot_w = 0

        self.vel_gain = vel_gain
        self.ang_gain = ang_gain

        # Robot velocities and dynamics
        self.dxi = np.array((0.0, 0.0))
        self.dxu = np.array((0.0, 0.0))

        # Real robot specs
        self.v_max = R_V_MAX           # max linear velocity
        self.w_max = R_W_MAX           # max angular velocity
        self.ac_max = R_AC_MAX         # max actuator velocity
        self.r_wheel = R_R_WHEEL       # robot wheel radius
        self.r_length = R_R_LENGTH     # robot length

        self.rr = 1 / self.r_wheel
        self.ll = self.r_length / (2 * self.r_wheel)
        self.rr_ = self.ac_max / self.rr
        self.ll_ = self.ll / self.rr

    def actuator_limit(self):
        """
        Call this function to reduce the linear velocity and avoid exceeding the actuator limits.
        Angular velocity is maintained.
        """

        self.v_ = max(-self.v_max, min(self.v_max, self.dxu[0]))
        self.w_ = max(-self.w_max, min(self.w_max, self.dxu[1]))
        if self.rr * abs(self.v_) + self.ll * abs(self.w_) > self.ac_max:
            self.v_ = (self.rr_ - self.ll_ * abs(self.w_)) * np.sign(self.dxu[0])
        self.dxu[0] = self.v_
        self.dxu[1] = self.w_

    def dxi_to_dxu(self):
        """
        Transform self.dxi velocities into self.dxu dynamics
        """

        a = np.cos(self.rot_w)
        b = np.sin(self.rot_w)

        self.dxu[0] = self.vel_gain*(a * self.dxi[0] + b * self.dxi[1])
        self.dxu[1] = self.ang_gain*np.arctan2(-b * self.dxi[0] + a * self.dxi[1], self.dxu[0])/(np.pi/2)

class Robot_hrvo(Robot):
    def __init__(self, robot_id, tag, vel_gain = 0.8, ang_gain = 3.0, safety = 0.24, check_boundaries = True):
        """
        Robot class with HRVO function to be used to avoid other robots

        robot_id          : int      -> id of robot
        tag                : str      -> name tag of the robot
        vel_gain           : float    -> velocity gain
        ang_gain           : float    -> angular gain
        safety              : float    -> safety radius of the robots
        check_boundaries   : bool     -> check limits of the environment

        """

        self.robot_id = robot_id
        self.tag = tag
        self.safety = safety #if safety > 0.24 else 0.24 # safety radius

        self.detections = [[30, 0, 0, 0]]

        self.check_boundaries = check_boundaries
        self.bound_x = [T_MIN_WIDTH, T_MAX_WIDTH]
        self.bound_y = [T_MIN_HEIGHT, T_MAX_HEIGHT]

        super().__init__(self.robot_id, self.tag, vel_gain, ang_gain)

    def HRVO(self, detections, desired_velocity):
        """
        Apply HRVO to the current desired velocity in order to modify it's path to avoid other robots

        Args:
            detections      : np.array[float, float, float, float] ->
                Nx4 array as N = number of detected robots. If A is this robot and B the detected robot:
                [Distance from A to B, angle from A to B, B x_velocity, B y_velocity]

            desired_velocity : np.array[float, float] ->
                1x2 array with the desired velocity [desired_x_velocity, desired_y_velocity]

        Return:
            None, the super().dxi parameter is updated with the resulting value
        """

        detections = np.asarray(detections)
        n_detections = len(detections)
        hrvo_mat = np.empty((n_detections * 2, 2))
        hrvo_vec = np.empty((n_detections * 2))

        for i in range(n_detections):

            obst_dist = detections[i, 0]
            obst_angl = detections[i, 1]
            obst_velx = detections[i, 2]
            obst_vely = detections[i, 3]

            obst_dist = obst_dist if obst_dist > self.safety else self.safety
            obst_phi = np.arcsin(self.safety / obst_dist)
            obst_phi_l = obst_angl + obst_phi
            obst_phi_r = obst_angl - obst_phi

            # Create VO triangle
            temp_mat_ = np.array([[1., 0., 0.], [0., 1., 0.], [-obst_velx, -obst_vely, 1.]])

            temp_lin_l = np.cross(np.array([0, 0, 1]), np.array([np.cos(obst_phi_l), np.sin(obst_phi_l)]))
            temp_lin_l = temp_mat_ @ temp_lin_l

            hrvo_mat[i*2, :] = -temp_lin_l[:2]
            hrvo_vec[i*2] = temp_lin_l[2]

            temp_lin_r = np.cross(np.array([0, 0, 1]), np.array([np.cos(obst_phi_r), np.sin(obst_phi_r)]))
            temp_lin_r = temp_mat_ @ temp_lin_r

            hrvo_mat[i*2 + 1, :] = temp_lin_r[:2]
            hrvo_vec[i*2 + 1] = -temp_lin_r[2]

            # RVO
            temp_mat_ = np.array([[1., 0., 0.], [0., 1., 0.], [-(obst_velx+self.dxi[0])/2, -(obst_vely+self.dxi[1])/2, 1.]])

            # HRVO
            temp_lin_l = np.cross(np.array([0, 0, 1]), np.array([np.cos(obst_phi_l), np.sin(obst_phi_l)]))
            temp_lin_l = temp_mat_ @ temp_lin_l
            dist_l = abs(temp_lin_l[0]*self.dxi[0]+temp_lin_l[1]*self.dxi[1]+temp_lin_l[2])/np.sqrt(temp_lin_l[0]**2 + temp_lin_l[1]**2)

            temp_lin_r = np.cross(np.array([0, 0, 1]), np.array([np.cos(obst_phi_r), np.sin(obst_phi_r)]))
            temp_lin_r = temp_mat_ @ temp_lin_r
            dist_r = abs(temp_lin_r[0]*self.dxi[0]+temp_lin_r[1]*self.dxi[1]+temp_lin_r[2])/np.sqrt(temp_lin_r[0]**2 + temp_lin_r[1]**2)

            if dist_l < dist_r:
                hrvo_mat[i*2, :] = -temp_lin_l[:2]
                hrvo_vec[i*2] = temp_lin_l[2]

            if dist_l > dist_r:
                hrvo_mat[i*2 + 1, :] = temp_lin_r[:2]
                hrvo_vec[i*2 + 1] = -temp_lin_r[2]

        # Search for valid velocities
        th = np.linspace(0, 2 * np.pi, 20)
        vel = np.linspace(0.0, self.v_max, 10)

        vv, thth = np.meshgrid(vel, th)

        vx_sample = np.append((vv * np.cos(thth)).flatten(), 0)
        vy_sample = np.append((vv * np.sin(thth)).flatten(), 0)

        v_sample = np.stack((vx_sample, vy_sample))

        for i in range(n_detections):
            hrvo_mat_ = hrvo_mat[2*i:2*i+2, :]
            hrvo_vec_ = hrvo_vec[2*i:2*i+2]

            v_out = []
            for i in range(np.shape(v_sample)[1]):
                if not ((hrvo_mat_ @ v_sample[:, i] < hrvo_vec_).all()):
                    v_out.append(v_sample[:, i])

            v_sample = np.array(v_out).T

            if np.shape(v_sample)[0] == 0:
                v_sample=np.array([[0.0], [0.0]])

        if self.check_boundaries:

            v_out = []
            for i in range(np.shape(v_sample)[1]):
                if self.bound_x[0] < v_sample[0, i] + self.pos_x < self.bound_x[1] and self.bound_y[0] < v_sample[1, i] + self.pos_y < self.bound_y[1]:
                    v_out.append(v_sample[:, i])
            v_sample = np.array(v_out).T

            if np.shape(v_sample)[0] == 0:
                v_sample=np.array([[0.0], [0.0]])

        size = np.shape(v_sample)[1]
        diffs = v_sample - ((desired_velocity).reshape(2, 1) @ np.ones(size).reshape(1, size))
        norm = np.linalg.norm(diffs, axis=0)
        min_index = np.where(norm == np.amin(norm))[0][0]
        self.dxi = (v_sample[:, min_index])

        limit_norm = np.linalg.norm(self.dxi)
        if limit_norm > self.v_max:
            self.dxi *= self.v_max/limit_norm

if __name__ == "__main__":
    print("DREAM Robot class")
