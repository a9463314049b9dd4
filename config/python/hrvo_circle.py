"""The thesis's HRVO circle swap in Python: the C++ kind hrvo_circle (agents/src/hrvo_robot.cc,
agents/kinds/hrvo_circle/: circle_formation_robot.cc, hrvo_circle_builder.cc) written as a dream.Robot, so
config/hrvo_circle_python.yaml runs the experiment of config/hrvo_circle.yaml.

Robot i drives at min(max_speed_mps, gain * distance) towards its point of the current
formation (formation k: angle 2 pi i / N, plus pi when k is odd, on a circle of radius_m),
through HRVO (dream.HrvoAvoidance: the exact variant, or the thesis's sampled one with
`hrvo: {variant: thesis}`), and counts the point reached within tolerance_m (holding still from
within stop_m until pushed out of tolerance_m). It moves on to
the next point only once the radio has brought news that every robot reached the current one:
each robot rebroadcasts the highest state it knows of everybody, so the news travels hop by
hop (payload as C++'s FormationProgress: int32 count, then one int32 state per robot,
little-endian). Like the C++ robot it moves on when every known state is *at least* its own
(the thesis's "equal" deadlocks when a faster robot is already further on). Done while it holds
its last point (reached, came within stop_m, not out of tolerance_m since), as the C++ kind.
"""

import math
import struct

from dream import HrvoAvoidance, Robot, key

ARENA = (-1.6, 1.6, -1.0, 1.0)
GOAL_WALL_MARGIN_M = 0.1   # every point this far inside the arena, or HRVO's arena check keeps a robot off it
WALL_GUARD_MARGIN_M = 0.02  # UnicycleWallGuard's: less than HRVO's 0.05, so a robot on HRVO's line can still turn


class HrvoCircleRobot(Robot):
    KEYS = {"radius_m": key(0.85, above=0.0),
            "center": key([0.0, 0.0], kind="list"),          # [x m, y m]
            "formations": key(3, kind="int", at_least=1, at_most=100),
            "tolerance_m": key(0.05, above=0.0),
            "max_speed_mps": key(0.2, above=0.0, at_most=0.2),
            # preferred speed = min(max_speed_mps, gain * distance), 1/s: slow down before the
            # point so the loop delay does not carry the robot past it (C++: CircleFormationParams::gain)
            "gain": key(0.8, above=0.0),
            # reached within tolerance_m, it drives on to within stop_m and holds there until pushed
            # out of tolerance_m, so it settles inside the line the goal is judged by, not on it
            "stop_m": key(0.025, above=0.0),
            # {variant: exact|thesis, safety_radius_m, check_boundaries, boundary_horizon_s}
            "hrvo": key({}, kind="any")}

    def setup(self):
        config = self.config
        center = config["center"]
        if not (len(center) == 2 and all(isinstance(c, (int, float)) and math.isfinite(c) for c in center)):
            raise ValueError(f"center: expected [x, y] in metres, got {center!r}")
        self.goals = [_circle_point(center, config["radius_m"], self.id, self.num_robots, formation)
                      for formation in range(config["formations"])]
        for x, y in self.goals:
            if abs(x) > ARENA[1] - GOAL_WALL_MARGIN_M or abs(y) > ARENA[3] - GOAL_WALL_MARGIN_M:
                raise ValueError(f"the circle (center {center}, radius_m {config['radius_m']}) leaves the arena: every "
                                 f"point must be {GOAL_WALL_MARGIN_M} m inside x in [-1.6, 1.6], y in [-1, 1]")
        if config["stop_m"] > config["tolerance_m"]:
            raise ValueError(f"stop_m must be > 0 and <= tolerance_m ({config['tolerance_m']}), "
                             f"got {config['stop_m']}")
        self.hrvo = HrvoAvoidance.from_config(config["hrvo"])
        self.guard_walls = self.hrvo.params.check_boundaries
        self.states = [0] * self.num_robots  # highest number of points each robot is known to have reached
        self.reached = 0
        self.goal_index = 0
        self.holding = False  # came within stop_m and has not left tolerance_m since
        self.dxi = (0.0, 0.0)  # the last safe velocity: HRVO's current velocity next time
        self._payload = struct.Struct(f"<{self.num_robots + 1}i")

    def on_radio(self, heard):
        formations = len(self.goals)
        for message in heard:
            states = self._decode(message.payload, formations)
            if states is None:
                self.count_bad_radio_message(message)
                continue
            self.states = [a if a > b else b for a, b in zip(self.states, states)]
        self.states[self.id] = self.reached
        # Everyone (as far as we know) has reached the point we hold: go to the next.
        holding = self.reached == self.goal_index + 1
        if holding and self.reached < formations and min(self.states) >= self.reached:
            self.goal_index = self.reached
        return self._payload.pack(self.num_robots, *self.states)

    def update(self, step):
        if not self.has_odometry:
            return (0.0, 0.0)
        x, y, theta = self.pose.tolist()
        goal_x, goal_y = self.goals[self.goal_index]
        dx = goal_x - x
        dy = goal_y - y
        distance = math.sqrt(dx * dx + dy * dy)
        preferred = (0.0, 0.0)
        at_goal = distance < self.config["tolerance_m"]
        if at_goal and self.reached == self.goal_index:
            self.reached += 1
        if distance < self.config["stop_m"]:
            self.holding = True
        elif not at_goal:
            self.holding = False
        if not self.holding:
            # Slow down before the point: at full speed the loop delay carries the robot past it.
            speed = min(self.config["max_speed_mps"], self.config["gain"] * distance)
            preferred = (speed * dx / distance, speed * dy / distance)
        # HRVO even when holding still: a passing robot may need us to step aside.
        neighbours = [(n.distance_m * math.cos(n.bearing_rad), n.distance_m * math.sin(n.bearing_rad),
                       float(n.velocity_mps[0]), float(n.velocity_mps[1])) for n in self.movement.neighbours]
        self.dxi = self.hrvo.solve(x, y, self.dxi[0], self.dxi[1], preferred[0], preferred[1], neighbours)
        command = self.limit_actuators(self.dxi_to_dxu(self.dxi))
        return self._guard_walls(x, y, theta, command) if self.guard_walls else command

    def done(self):
        return self.reached == len(self.goals) and self.holding

    # The goal, judged after the run as the C++ kind's FormationSequenceMetrics judges it: formation
    # k is complete at the first step (after formation k-1's) where every robot is within
    # tolerance_m of its point; the goal is every formation complete.
    @classmethod
    def goal_points(cls, config, num_robots):
        return [[_circle_point(config["center"], config["radius_m"], i, num_robots, formation)
                 for formation in range(config["formations"])] for i in range(num_robots)]

    @classmethod
    def metrics(cls, run):
        completed = []
        for formation in range(run.config["formations"]):
            points = [robot_points[formation] for robot_points in run.goal_points]
            formed = (run.distances_to(points) <= run.config["tolerance_m"]).all(axis=1)
            after = 0 if not completed else completed[-1][0] + 1
            at = [index for index in range(after, len(formed)) if formed[index]][:1]
            if not at:
                break
            completed.append((at[0], int(run.steps[at[0]])))
        figures = {"formations_completed": len(completed)}
        for formation in range(run.config["formations"]):
            figures[f"formation_{formation + 1}_completed_step"] = (completed[formation][1] if formation < len(completed)
                                                                    else -1)
        all_done = len(completed) == run.config["formations"]
        figures["all_formations_completed_step"] = completed[-1][1] if all_done else -1
        return figures

    @classmethod
    def goal(cls, run, metrics):
        step = metrics["all_formations_completed_step"]
        return {"met": step >= 0, "completion_step": step,
                "detail": f"{metrics['formations_completed']} of {run.config['formations']} formations"}

    def _decode(self, payload, formations):
        """The states in a neighbour's payload, or None when it is not a valid progress message."""
        if len(payload) != self._payload.size:
            return None
        count, *states = self._payload.unpack(payload)
        if count != self.num_robots or any(s < 0 or s > formations for s in states):
            return None
        return states

    def _guard_walls(self, x, y, theta, command):
        """UnicycleWallGuard (agents/src/unicycle_wall_guard.cc): a unicycle drives along its
        heading, not along the velocity HRVO chose, so while it turns it may head over a wall.
        Scale the forward speed down (never the turn rate) until position + horizon * the
        motion actually driven stays WALL_GUARD_MARGIN_M inside the arena, or, for a robot
        already past that line, does not move further out."""
        v, w = command
        params = self.hrvo.params
        h = params.boundary_horizon_s
        m = WALL_GUARD_MARGIN_M
        scale = 1.0
        for position, driven, lo_edge, hi_edge in ((x, v * math.cos(theta), params.x_min_m, params.x_max_m),
                                                   (y, v * math.sin(theta), params.y_min_m, params.y_max_m)):
            lo = min(0.0, (lo_edge + m - position) / h)
            hi = max(0.0, (hi_edge - m - position) / h)
            if driven < lo:
                scale = min(scale, lo / driven)
            if driven > hi:
                scale = min(scale, hi / driven)
        return (max(0.0, scale) * v, w)


def _circle_point(center, radius_m, robot_id, num_robots, formation):
    """Appendix B's p_circ: robot i at angle 2 pi i / N, the opposite point in odd formations."""
    angle = 2.0 * math.pi * robot_id / num_robots + (math.pi if formation % 2 == 1 else 0.0)
    return (center[0] + radius_m * math.cos(angle), center[1] + radius_m * math.sin(angle))
