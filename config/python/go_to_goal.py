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
            "tolerance_m": key(0.03, above=0.0),
            # the goal: every robot within this of its goal at once; 0: within tolerance_m (as C++)
            "goal_tolerance_m": key(0.0, at_least=0.0)}

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

    # The goal, judged after the run on the logged poses as the C++ kind's GoToGoalMetrics judges it.
    @classmethod
    def goal_points(cls, config, num_robots):
        return [[tuple(config["goals"][i])] for i in range(num_robots)]

    @classmethod
    def metrics(cls, run):
        errors = run.distances_to([points[0] for points in run.goal_points])   # (steps, robots)
        tolerance = run.config["goal_tolerance_m"] or run.config["tolerance_m"]
        all_in = (errors <= tolerance).all(axis=1)
        arrived = [int(step) for step, inside in zip(run.steps, all_in) if inside][:1]
        return {"final_max_goal_error_m": float(errors[-1].max()) if len(errors) else 0.0,
                "all_arrived_step": arrived[0] if arrived else -1}

    @classmethod
    def goal(cls, run, metrics):
        step = metrics["all_arrived_step"]
        tolerance = run.config["goal_tolerance_m"] or run.config["tolerance_m"]
        detail = ("all at their goals" if step >= 0 else
                  f"not all at their goals, worst {metrics['final_max_goal_error_m']:.7g} m on the logged poses "
                  f"(tolerance {tolerance:g} m, compared unrounded)")
        return {"met": step >= 0, "completion_step": step, "detail": detail}
