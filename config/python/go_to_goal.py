"""Go to goal in Python: the same law as the C++ go_to_goal (agents/kinds/go_to_goal/src/go_to_goal_robot.cc),
so that config/go_to_goal_python.yaml drives the robots along the same paths as
config/go_to_goal.yaml.

Proportional single-integrator law dxi = gain (goal - p), capped at max_speed_mps, mapped to
the unicycle as the Robotarium's si_to_uni does, limited to what the wheels can do. Stops and
reports done within tolerance_m; holds still before its first odometry reading.
"""

import math

from dream import Robot, SingleIntegratorToUnicycle, key


class GoToGoal(Robot):
    KEYS = {"goals": key(kind="points", per_robot=True),      # [x m, y m] per robot
            "gain": key(0.8, above=0.0),                        # 1/s
            "max_speed_mps": key(0.15, above=0.0, at_most=0.2),
            "tolerance_m": key(0.03, above=0.0)}

    def setup(self):
        self.goal_x, self.goal_y = self.config["goals"][self.id].tolist()
        self.si_to_uni = SingleIntegratorToUnicycle()
        self.arrived = False

    def update(self, step):
        if not self.has_odometry:
            return (0.0, 0.0)
        x, y, theta = self.pose.tolist()
        error_x = self.goal_x - x
        error_y = self.goal_y - y
        self.arrived = math.sqrt(error_x * error_x + error_y * error_y) <= self.config["tolerance_m"]
        if self.arrived:
            return (0.0, 0.0)
        gain = self.config["gain"]
        velocity = [gain * error_x, gain * error_y]
        speed = math.sqrt(velocity[0] * velocity[0] + velocity[1] * velocity[1])
        max_speed = self.config["max_speed_mps"]
        if speed > max_speed:
            scale = max_speed / speed
            velocity = [velocity[0] * scale, velocity[1] * scale]
        return self.limit_actuators(self.si_to_uni.map(velocity, theta))

    def done(self):
        return self.arrived
