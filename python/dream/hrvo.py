"""HRVO collision avoidance for Python controllers: both of the project's variants, ported
operation for operation so that a Python robot picks the same velocity as its C++ twin (to
~1e-12; tests/python/test_hrvo.py checks it against answers of the C++ code):

- exact (the default): agents/hrvo/hrvo_exact.cc with hrvo_cone.cc and hrvo_params.cc. The
  velocity nearest the preferred one (or, when a neighbour blocks that, the preferred one turned
  keep_right_rad clockwise) that is outside every neighbour's hybrid reciprocal velocity
  obstacle, within max speed and keeps the robot in the arena for boundary_horizon_s.
- thesis: agents/hrvo/hrvo_thesis.cc, the thesis's Robot_hrvo.HRVO with its 201 sampled
  velocities, for comparisons.

docs/hrvo.md explains both. The exact solve is written for a handful of neighbours: plain
floats and tuples, no numpy (a numpy call costs more than one cone's whole arithmetic; a
numpy version of the blocked-interval search measured slower up to 9 neighbours), no
trigonometry. The thesis's filter over its 201 samples is where numpy pays.
"""

import math

import numpy as np

from .robot import did_you_mean

# Slack, m/s, for points computed on a wedge leg or box edge (rounding may put them a few ulps
# inside the wedge they border).
_TOLERANCE = 1e-9
# Squared distances (m/s)^2 this close count as a tie.
_TIE_SQ = 1e-12
# The arena test is strict; keep this far inside, m/s.
_BOX_MARGIN = 2e-9
_IN_BOX_SLACK = 1e-12
_INF = math.inf

# The keys of a config's `hrvo:` section (agents/kind_api/src/hrvo_config.cc).
HRVO_CONFIG_KEYS = ("variant", "safety_radius_m", "check_boundaries", "boundary_horizon_s")
VARIANTS = ("exact", "thesis")


def _number_text(value):
    """A double as C++'s ostream writes it (%g), for messages that read like the C++ ones."""
    return f"{value:g}"


def _in_range(value, lo_exclusive, hi_inclusive):
    return math.isfinite(value) and lo_exclusive < value <= hi_inclusive


class HrvoParams:
    """What every HRVO needs (agents/include/dream/agents/hrvo/hrvo_params.h); defaults are the
    thesis's Robot_hrvo values on the Robotarium. `check()` applies the C++ IsValid rules."""

    __slots__ = ("safety_radius_m", "max_speed_mps", "check_boundaries", "x_min_m", "x_max_m", "y_min_m",
                 "y_max_m", "boundary_horizon_s")

    def __init__(self, safety_radius_m=0.24, max_speed_mps=0.2, check_boundaries=True, x_min_m=-1.6,
                 x_max_m=1.6, y_min_m=-1.0, y_max_m=1.0, boundary_horizon_s=1.0):
        self.safety_radius_m = safety_radius_m        # centre to centre, m; (0, 10]
        self.max_speed_mps = max_speed_mps            # largest speed returned; (0, 10]
        self.check_boundaries = check_boundaries      # refuse velocities leaving the arena
        self.x_min_m = x_min_m                        # arena, world frame
        self.x_max_m = x_max_m
        self.y_min_m = y_min_m
        self.y_max_m = y_max_m
        self.boundary_horizon_s = boundary_horizon_s  # look-ahead of the arena check, s; (0, 100]

    def check(self):
        """Raises ValueError naming the field, its value and the allowed range."""
        def fail(field, value, allowed):
            raise ValueError(f"HrvoParams.{field} = {_number_text(value)} is outside {allowed}")
        if not _in_range(self.safety_radius_m, 0.0, 10.0):
            fail("safety_radius_m", self.safety_radius_m, "(0, 10] m")
        if not _in_range(self.max_speed_mps, 0.0, 10.0):
            fail("max_speed_mps", self.max_speed_mps, "(0, 10] m/s")
        if not math.isfinite(self.x_min_m):
            fail("x_min_m", self.x_min_m, "finite values")
        if not (math.isfinite(self.x_max_m) and self.x_max_m > self.x_min_m):
            fail("x_max_m", self.x_max_m, "(x_min_m, inf) m")
        if not math.isfinite(self.y_min_m):
            fail("y_min_m", self.y_min_m, "finite values")
        if not (math.isfinite(self.y_max_m) and self.y_max_m > self.y_min_m):
            fail("y_max_m", self.y_max_m, "(y_min_m, inf) m")
        if not _in_range(self.boundary_horizon_s, 0.0, 100.0):
            fail("boundary_horizon_s", self.boundary_horizon_s, "(0, 100] s")
        return self

    @classmethod
    def from_config(cls, section, max_speed_mps=0.2):
        """Checked params from a config's `hrvo:` mapping (keys HRVO_CONFIG_KEYS, as
        ReadHrvoRobotParams reads them, the variant only checked; None or {} gives the
        defaults). Raises ValueError."""
        section = {} if section is None else section
        if not isinstance(section, dict):
            raise ValueError(f"hrvo: expected a mapping, got {section!r}")
        for name in section:
            if name not in HRVO_CONFIG_KEYS:
                raise ValueError(f"hrvo.{name}: unknown key{did_you_mean(name, HRVO_CONFIG_KEYS)}; allowed keys here: "
                                 f"{', '.join(HRVO_CONFIG_KEYS)}")
        variant = section.get("variant", "exact")
        if variant not in VARIANTS:
            suggestion = did_you_mean(variant, VARIANTS) if isinstance(variant, str) else ""
            raise ValueError(f"hrvo.variant: unknown HRVO variant '{variant}'{suggestion}; allowed: exact, thesis")
        params = cls(max_speed_mps=max_speed_mps)
        for name in ("safety_radius_m", "boundary_horizon_s"):
            if name in section:
                value = section[name]
                if isinstance(value, bool) or not isinstance(value, (int, float)):
                    raise ValueError(f"hrvo.{name}: expected a number, got {value!r}")
                setattr(params, name, float(value))
        if "check_boundaries" in section:
            if not isinstance(section["check_boundaries"], bool):
                raise ValueError(f"hrvo.check_boundaries: expected true or false, got {section['check_boundaries']!r}")
            params.check_boundaries = section["check_boundaries"]
        try:
            return params.check()
        except ValueError as error:
            raise ValueError(f"hrvo: {error}") from None


def _finite2(x, y):
    return math.isfinite(x) and math.isfinite(y)


def _cone(rel_x, rel_y, other_vx, other_vy, own_vx, own_vy, radius):
    """HrvoCone::Hybrid with HrvoCone::PassesLeft's side: (apex_x, apex_y, right_x, right_y,
    left_x, left_y). The wedge is Cross(right, v - apex) > 0 and Cross(left, v - apex) < 0."""
    distance = math.sqrt(rel_x * rel_x + rel_y * rel_y)
    if distance > 1e-12:
        bx = rel_x / distance
        by = rel_y / distance
    else:
        bx, by = 1.0, 0.0
    # Legs at +/- asin(R / d) about the bearing, without trigonometry.
    sine = radius / distance if distance > radius else 1.0
    cos_sq = 1.0 - sine * sine
    cosine = math.sqrt(cos_sq if cos_sq > 0.0 else 0.0)
    rx = cosine * bx + sine * by
    ry = -sine * bx + cosine * by
    lx = cosine * bx - sine * by
    ly = sine * bx + cosine * by
    recip_x = 0.5 * (own_vx + other_vx)
    recip_y = 0.5 * (own_vy + other_vy)
    if distance <= radius:
        # Overlapping: neither may approach faster than the mean velocity.
        return (recip_x, recip_y, rx, ry, lx, ly)
    pass_left = rel_x * (own_vy - other_vy) - rel_y * (own_vx - other_vx) > 0.0
    # Intersect(a, u, b, v) = a + s u with s = Cross(b - a, v) / Cross(u, v): the reciprocal
    # leg on the side passed, the plain VO's other leg.
    if pass_left:
        ux, uy, vx, vy = lx, ly, rx, ry
    else:
        ux, uy, vx, vy = rx, ry, lx, ly
    dx = other_vx - recip_x
    dy = other_vy - recip_y
    s = (dx * vy - dy * vx) / (ux * vy - uy * vx)
    return (recip_x + s * ux, recip_y + s * uy, rx, ry, lx, ly)


def _penetration(cone, vx, vy):
    """HrvoCone::Penetration: distance from v to the nearest point outside the wedge; 0 outside."""
    ax, ay, rx, ry, lx, ly = cone
    wx = vx - ax
    wy = vy - ay
    if not (rx * wy - ry * wx > 0.0 and lx * wy - ly * wx < 0.0):
        return 0.0
    norm = math.sqrt(wx * wx + wy * wy)
    to_right = abs(rx * wy - ry * wx) if wx * rx + wy * ry >= 0.0 else norm
    to_left = abs(lx * wy - ly * wx) if wx * lx + wy * ly >= 0.0 else norm
    return to_left if to_left < to_right else to_right


class HrvoAvoidance:
    """HRVO: a collision-free velocity near the preferred one. One instance per robot; between
    calls it keeps only `last_was_safe` and `last_cones` (the exact variant's; the thesis
    variant leaves them True and []).

    variant "exact" is HrvoExact, "thesis" HrvoThesis. `keep_right_rad` and `wall_margin_m`
    are HrvoExactTuning's (defaults 0.7 rad and 0.05 m, the tuned values of docs/hrvo.md); the
    thesis variant has neither. Raises ValueError for invalid params, variant or tuning.
    """

    __slots__ = ("params", "variant", "keep_right_rad", "wall_margin_m", "last_was_safe", "last_cones", "_cos",
                 "_sin", "_samples")

    def __init__(self, params=None, variant="exact", keep_right_rad=0.7, wall_margin_m=0.05):
        self.params = (params if params is not None else HrvoParams()).check()
        if variant not in VARIANTS:
            raise ValueError(f"unknown HRVO variant {variant!r}; allowed: {', '.join(VARIANTS)}")
        self.variant = variant
        if not (math.isfinite(keep_right_rad) and 0.0 <= keep_right_rad < math.pi / 2.0):
            raise ValueError(f"HrvoExactTuning.keep_right_rad = {_number_text(keep_right_rad)} "
                             "is outside [0, pi/2) rad")
        if not (math.isfinite(wall_margin_m) and 0.0 <= wall_margin_m <= 0.5):
            raise ValueError(f"HrvoExactTuning.wall_margin_m = {_number_text(wall_margin_m)} is outside [0, 0.5] m")
        self.keep_right_rad = keep_right_rad
        self.wall_margin_m = wall_margin_m
        self._cos = math.cos(keep_right_rad)
        self._sin = math.sin(keep_right_rad)
        self.last_was_safe = True
        self.last_cones = []
        self._samples = _thesis_samples(self.params.max_speed_mps) if variant == "thesis" else None

    @classmethod
    def from_config(cls, section):
        """An HrvoAvoidance for a config's `hrvo:` mapping (see HrvoParams.from_config), with
        the default tuning. Raises ValueError."""
        params = HrvoParams.from_config(section)
        return cls(params, variant=(section or {}).get("variant", "exact"))

    def safe_velocity(self, position_m, current_velocity_mps, preferred_velocity_mps, neighbours=()):
        """The new velocity, np.array [vx, vy] m/s of norm <= max speed (SafeVelocity).

        position_m: own centre (the arena check uses it). current_velocity_mps: pass the
        previous answer, as the thesis does (the reciprocal apex and the side depend on it).
        neighbours: rows [rel_x, rel_y, vx, vy] (a list of 4-sequences or an (n, 4) array):
        neighbour centre minus own centre and the neighbour's world-frame velocity, as
        HrvoNeighbour. The exact variant skips non-finite rows and reads non-finite vectors as
        zero; the thesis variant, like its C++, does not look.
        """
        vx, vy = self.solve(*_two_floats(position_m), *_two_floats(current_velocity_mps),
                            *_two_floats(preferred_velocity_mps), _rows(neighbours))
        return np.array((vx, vy))

    def solve(self, pos_x, pos_y, current_x, current_y, preferred_x, preferred_y, neighbours):
        """safe_velocity on plain floats: `neighbours` a list of (rel_x, rel_y, vx, vy) float
        tuples; returns (vx, vy). For controllers that already hold floats (no numpy at all)."""
        if self.variant == "thesis":
            return self._solve_thesis(pos_x, pos_y, current_x, current_y, preferred_x, preferred_y, neighbours)
        params = self.params
        v_max = params.max_speed_mps
        self.last_was_safe = True
        if not _finite2(preferred_x, preferred_y):
            preferred_x = preferred_y = 0.0
        if not _finite2(current_x, current_y):
            current_x = current_y = 0.0
        radius = params.safety_radius_m
        cones = [_cone(rx, ry, nvx, nvy, current_x, current_y, radius)
                 for rx, ry, nvx, nvy in neighbours
                 if math.isfinite(rx) and math.isfinite(ry) and math.isfinite(nvx) and math.isfinite(nvy)]
        self.last_cones = cones
        box = self._velocity_box(pos_x, pos_y) if _finite2(pos_x, pos_y) else self._velocity_box(0.0, 0.0)

        # Usually the preferred velocity (at most max speed) is already safe.
        clipped_x, clipped_y = _clip_to_disc(preferred_x, preferred_y, v_max)
        clipped_free = _free(cones, clipped_x, clipped_y)
        if clipped_free and _in_box(box, clipped_x, clipped_y):
            return clipped_x, clipped_y
        # Keep right when a neighbour is in the way (not a wall).
        target_x, target_y = preferred_x, preferred_y
        if not clipped_free:
            target_x = self._cos * preferred_x + self._sin * preferred_y
            target_y = -self._sin * preferred_x + self._cos * preferred_y
            clipped_x, clipped_y = _clip_to_disc(target_x, target_y, v_max)
            if _in_box(box, clipped_x, clipped_y) and _free(cones, clipped_x, clipped_y):
                return clipped_x, clipped_y

        # Every leg and box edge, nearest first: one whose nearest point is farther than the
        # best safe velocity found cannot improve on it.
        segments = []
        for index, (ax, ay, rx, ry, lx, ly) in enumerate(cones):
            _add_segment(segments, ax, ay, rx, ry, 0.0, index, box, v_max, target_x, target_y)
            _add_segment(segments, ax, ay, lx, ly, 0.0, index, box, v_max, target_x, target_y)
        if params.check_boundaries:
            lo_x, lo_y, hi_x, hi_y = box
            for edge in (lo_x, hi_x):
                _add_segment(segments, edge, 0.0, 0.0, 1.0, -_INF, -1, box, v_max, target_x, target_y)
            for edge in (lo_y, hi_y):
                _add_segment(segments, 0.0, edge, 1.0, 0.0, -_INF, -1, box, v_max, target_x, target_y)
        segments.sort(key=_bound_sq)
        best = [False, 0.0, 0.0, 0.0, 0.0]  # found, vx, vy, distance_sq, rightness
        for bound_sq, ox, oy, ux, uy, lo, hi, skip in segments:
            if best[0] and bound_sq > best[3] + _TIE_SQ:
                break
            _search_line(cones, ox, oy, ux, uy, lo, hi, skip, target_x, target_y, best)
        candidates = _circle_candidates(cones, box, v_max, target_x, target_y)
        for cx, cy in candidates:
            if best[0]:
                dx = cx - target_x
                dy = cy - target_y
                if dx * dx + dy * dy > best[3] + _TIE_SQ:
                    continue
            if _in_box(box, cx, cy) and _free(cones, cx, cy):
                _offer(cx, cy, target_x, target_y, best)
        if best[0]:
            return best[1], best[2]
        self.last_was_safe = False
        return _least_penetrating(cones, candidates, box, v_max, target_x, target_y)

    def _solve_thesis(self, pos_x, pos_y, current_x, current_y, preferred_x, preferred_y, neighbours):
        """HrvoThesis::SafeVelocity: per neighbour, two leg lines through its velocity (VO), the
        one whose reciprocal line is nearer the current velocity moved to it (HRVO); samples
        strictly inside any wedge dropped, then those leaving the arena within the horizon;
        an emptied set becomes {zero}; the first sample nearest the preferred velocity.
        Differences below 1e-12 count as ties, as in C++ (docs/hrvo.md: numpy's own sin/cos
        decide them in the thesis). Trigonometry through math (libm), as C++, not numpy's."""
        params = self.params
        safety = params.safety_radius_m
        samples_x, samples_y = self._samples
        keep = np.ones(samples_x.shape, dtype=bool)
        any_left = True
        for rel_x, rel_y, obst_velx, obst_vely in neighbours:
            # The thesis's sensor angle points from the neighbour to this robot; its
            # half-plane signs then select the wedge around angle + pi (docs/hrvo.md).
            obst_dist = math.sqrt(rel_x * rel_x + rel_y * rel_y)
            obst_angl = math.atan2(-rel_y, -rel_x)
            obst_dist = obst_dist if obst_dist > safety else safety
            obst_phi = math.asin(safety / obst_dist)
            phi_l = obst_angl + obst_phi
            phi_r = obst_angl - obst_phi
            # Leg lines a x + b y + c = 0 through an apex; the wedge is mat . v < vec for both rows.
            a_l = -math.sin(phi_l)
            b_l = math.cos(phi_l)
            a_r = -math.sin(phi_r)
            b_r = math.cos(phi_r)
            left = (-a_l, -b_l, -obst_velx * a_l + -obst_vely * b_l)
            right = (a_r, b_r, -(-obst_velx * a_r + -obst_vely * b_r))
            rvo_x = (obst_velx + current_x) / 2.0
            rvo_y = (obst_vely + current_y) / 2.0
            c_l = -rvo_x * a_l + -rvo_y * b_l
            c_r = -rvo_x * a_r + -rvo_y * b_r
            dist_l = abs(a_l * current_x + b_l * current_y + c_l) / math.sqrt(a_l * a_l + b_l * b_l)
            dist_r = abs(a_r * current_x + b_r * current_y + c_r) / math.sqrt(a_r * a_r + b_r * b_r)
            tie = 1e-12 * max(1.0, dist_l + dist_r)
            if dist_l < dist_r - tie:
                left = (-a_l, -b_l, c_l)
            if dist_l > dist_r + tie:
                right = (a_r, b_r, -c_r)
            if not any_left:
                continue  # (the thesis would raise IndexError here)
            inside = ((left[0] * samples_x + left[1] * samples_y < left[2])
                      & (right[0] * samples_x + right[1] * samples_y < right[2]))
            keep &= ~inside
            any_left = bool(keep.any())
        if not any_left:
            keep[-1] = True  # the last sample is zero
        if params.check_boundaries:
            h = params.boundary_horizon_s
            ahead_x = samples_x * h + pos_x
            ahead_y = samples_y * h + pos_y
            keep &= ((params.x_min_m < ahead_x) & (ahead_x < params.x_max_m)
                     & (params.y_min_m < ahead_y) & (ahead_y < params.y_max_m))
            if not keep.any():
                keep[-1] = True
        # The first sample nearest the preferred velocity, norms within rounding counting as equal.
        dx = samples_x - preferred_x
        dy = samples_y - preferred_y
        norms = np.sqrt(dx * dx + dy * dy).tolist()
        best = len(norms) - 1
        best_norm = _INF
        for index in np.flatnonzero(keep).tolist():
            norm = norms[index]
            if best_norm == _INF or norm < best_norm - 1e-12 * max(1.0, best_norm):
                best_norm = norm
                best = index
        out_x = float(samples_x[best])
        out_y = float(samples_y[best])
        limit_norm = math.sqrt(out_x * out_x + out_y * out_y)
        if limit_norm > params.max_speed_mps:
            scale = params.max_speed_mps / limit_norm
            out_x *= scale
            out_y *= scale
        return out_x, out_y

    def _velocity_box(self, pos_x, pos_y):
        """Velocities keeping position + horizon * v wall_margin_m inside the arena, as
        (lo_x, lo_y, hi_x, hi_y); always holds zero (a robot past the line may stop or head back)."""
        params = self.params
        if not params.check_boundaries:
            return (-_INF, -_INF, _INF, _INF)
        h = params.boundary_horizon_s
        m = self.wall_margin_m
        lo_x = (params.x_min_m + m - pos_x) / h + _BOX_MARGIN
        lo_y = (params.y_min_m + m - pos_y) / h + _BOX_MARGIN
        hi_x = (params.x_max_m - m - pos_x) / h - _BOX_MARGIN
        hi_y = (params.y_max_m - m - pos_y) / h - _BOX_MARGIN
        return (lo_x if lo_x < 0.0 else 0.0, lo_y if lo_y < 0.0 else 0.0,
                hi_x if hi_x > 0.0 else 0.0, hi_y if hi_y > 0.0 else 0.0)


def _thesis_samples(max_speed_mps):
    """The thesis's 201 candidates as arrays (x, y): linspace(0, 2 pi, 20) headings (0 and 2 pi
    both) x linspace(0, v_max, 10) speeds, heading-major, then zero; libm's cos and sin."""
    def linspace(stop, num, i):
        return stop if i == num - 1 else i * (stop / (num - 1)) + 0.0
    xs = []
    ys = []
    for h in range(20):
        heading = linspace(2.0 * math.pi, 20, h)
        for s in range(10):
            speed = linspace(max_speed_mps, 10, s)
            xs.append(speed * math.cos(heading))
            ys.append(speed * math.sin(heading))
    xs.append(0.0)
    ys.append(0.0)
    return np.array(xs), np.array(ys)


def _two_floats(vector):
    return float(vector[0]), float(vector[1])


def _rows(neighbours):
    if isinstance(neighbours, np.ndarray):
        return [tuple(row) for row in neighbours.reshape(-1, 4).tolist()]
    return [(float(r[0]), float(r[1]), float(r[2]), float(r[3])) for r in neighbours]


def _bound_sq(segment):
    return segment[0]


def _clip_to_disc(x, y, radius):
    norm = math.sqrt(x * x + y * y)
    if norm > radius:
        scale = radius / norm
        return x * scale, y * scale
    return x, y


def _in_box(box, x, y):
    lo_x, lo_y, hi_x, hi_y = box
    return (lo_x - _IN_BOX_SLACK <= x <= hi_x + _IN_BOX_SLACK
            and lo_y - _IN_BOX_SLACK <= y <= hi_y + _IN_BOX_SLACK)


def _free(cones, vx, vy):
    """Outside every wedge by more than _TOLERANCE (HrvoCone::Contains negated)."""
    for ax, ay, rx, ry, lx, ly in cones:
        wx = vx - ax
        wy = vy - ay
        if rx * wy - ry * wx > _TOLERANCE and lx * wy - ly * wx < -_TOLERANCE:
            return False
    return True


def _offer(vx, vy, target_x, target_y, best):
    """Keeps v in `best` if nearer the target, or equally near and more to the right."""
    dx = vx - target_x
    dy = vy - target_y
    distance_sq = dx * dx + dy * dy
    rightness = target_x * vy - target_y * vx  # negative: v is clockwise of the target
    if (not best[0] or distance_sq < best[3] - _TIE_SQ
            or (distance_sq <= best[3] + _TIE_SQ and rightness < best[4])):
        best[0] = True
        best[1] = vx
        best[2] = vy
        best[3] = distance_sq
        best[4] = rightness


def _line_range(ox, oy, ux, uy, t_min, box, v_max):
    """The t of o + t u (u unit) inside the speed disc and the box with t >= t_min, as
    (lo, hi), or None when there are none (HrvoExact::LineRange)."""
    lo = t_min
    hi = _INF
    b = ox * ux + oy * uy
    discriminant = b * b - ((ox * ox + oy * oy) - v_max * v_max)
    if discriminant < 0.0:
        return None
    root = math.sqrt(discriminant)
    t = -b - root
    if lo < t:
        lo = t
    t = -b + root
    if t < hi:
        hi = t
    lo_x, lo_y, hi_x, hi_y = box
    for o, u, box_lo, box_hi in ((ox, ux, lo_x, hi_x), (oy, uy, lo_y, hi_y)):
        if u != 0.0:
            t1 = (box_lo - o) / u
            t2 = (box_hi - o) / u
            if t2 < t1:
                t1, t2 = t2, t1
            if lo < t1:
                lo = t1
            if t2 < hi:
                hi = t2
        elif o < box_lo or o > box_hi:
            return None
    return (lo, hi) if lo <= hi else None


def _add_segment(segments, ox, oy, ux, uy, t_min, cone_index, box, v_max, target_x, target_y):
    """Appends (bound_sq, ox, oy, ux, uy, lo, hi, cone_index) for the allowed part of the line."""
    allowed = _line_range(ox, oy, ux, uy, t_min, box, v_max)
    if allowed is None:
        return
    lo, hi = allowed
    t = (target_x - ox) * ux + (target_y - oy) * uy
    t = lo if t < lo else (hi if hi < t else t)
    dx = ox + t * ux - target_x
    dy = oy + t * uy - target_y
    segments.append((dx * dx + dy * dy, ox, oy, ux, uy, lo, hi, cone_index))


def _search_line(cones, ox, oy, ux, uy, lo, hi, skip_cone, target_x, target_y, best):
    """Offers the nearest free points of o + t u, t in [lo, hi], on either side of the point
    nearest the target (HrvoExact::SearchLine)."""
    t_nearest = (target_x - ox) * ux + (target_y - oy) * uy
    t_nearest = lo if t_nearest < lo else (hi if hi < t_nearest else t_nearest)
    # The open stretch (a, b) of the line inside each other wedge, shrunk by the tolerance.
    # The clip against the wedge's right side and then its left side is written out, not
    # called: this loop is the solver's hot path, and a call per side costs more than it.
    # A loop over the two sides or a clip helper measured 6-8% slower per exact solve (Python
    # 3.11, the 10- and 20-robot circles of tests/benchmarks/python_hrvo_benchmark.py).
    intervals = []
    for index, (ax, ay, rx, ry, lx, ly) in enumerate(cones):
        if index == skip_cone:  # the line is this wedge's own edge
            continue
        a = -_INF
        b = _INF
        w0x = ox - ax
        w0y = oy - ay
        c = rx * w0y - ry * w0x
        d = rx * uy - ry * ux
        if d > 0.0:
            t = -c / d
            if a < t:
                a = t
        elif d < 0.0:
            t = -c / d
            if t < b:
                b = t
        elif c <= 0.0:
            continue
        # The left side bounds the other way: its c and d are the right side's with the sign
        # flipped, so its branches are mirrored (t = -c / d is the same either way).
        c = lx * w0y - ly * w0x
        d = lx * uy - ly * ux
        if d < 0.0:
            t = -c / d
            if a < t:
                a = t
        elif d > 0.0:
            t = -c / d
            if t < b:
                b = t
        elif c >= 0.0:
            continue
        a += _TOLERANCE
        b -= _TOLERANCE
        if a < b and b > lo and a < hi:
            intervals.append((a, b))
    up = _walk(intervals, t_nearest, True)
    if up == t_nearest:
        _offer(ox + t_nearest * ux, oy + t_nearest * uy, target_x, target_y, best)
        return
    if up <= hi:
        _offer(ox + up * ux, oy + up * uy, target_x, target_y, best)
    down = _walk(intervals, t_nearest, False)
    if down >= lo:
        _offer(ox + down * ux, oy + down * uy, target_x, target_y, best)


def _walk(intervals, t, upwards):
    """From t, steps over every blocked stretch holding the current point until none does."""
    moved = True
    while moved:
        moved = False
        for a, b in intervals:
            if a < t < b:
                t = b if upwards else a
                moved = True
    return t


def _circle_candidates(cones, box, v_max, target_x, target_y):
    """Points of the speed circle where the answer may lie: the target's direction and the
    circle's crossings with the legs and box edges (HrvoExact::CircleCandidates)."""
    candidates = []
    norm = math.sqrt(target_x * target_x + target_y * target_y)
    if norm > 0.0:
        scale = v_max / norm
        candidates.append((target_x * scale, target_y * scale))
    v_max_sq = v_max * v_max
    for ax, ay, rx, ry, lx, ly in cones:
        apex_sq = ax * ax + ay * ay
        for ux, uy in ((rx, ry), (lx, ly)):
            b = ax * ux + ay * uy
            discriminant = b * b - (apex_sq - v_max_sq)
            if discriminant < 0.0:
                continue
            root = math.sqrt(discriminant)
            t = -b - root
            if t >= 0.0:
                candidates.append((ax + t * ux, ay + t * uy))
            t = -b + root
            if t >= 0.0:
                candidates.append((ax + t * ux, ay + t * uy))
    lo_x, lo_y, hi_x, hi_y = box
    for edge in (lo_x, hi_x):
        if abs(edge) <= v_max:  # also skips infinite edges
            other = math.sqrt(v_max_sq - edge * edge)
            candidates.append((edge, -other))
            candidates.append((edge, other))
    for edge in (lo_y, hi_y):
        if abs(edge) <= v_max:
            other = math.sqrt(v_max_sq - edge * edge)
            candidates.append((-other, edge))
            candidates.append((other, edge))
    return candidates


def _least_penetrating(cones, candidates, box, v_max, target_x, target_y):
    """Boxed in: the candidate (made to respect speed and arena) whose deepest penetration into
    any wedge is smallest, nearest the target among equals (HrvoExact::LeastPenetrating)."""
    lo_x, lo_y, hi_x, hi_y = box
    best = [0.0, 0.0, _INF, _INF]  # vx, vy, score, distance_sq

    def consider(x, y):
        # The box holds zero and is convex: shrinking towards zero after clamping stays inside.
        x = lo_x if x < lo_x else x
        x = hi_x if hi_x < x else x
        y = lo_y if y < lo_y else y
        y = hi_y if hi_y < y else y
        x, y = _clip_to_disc(x, y, v_max)
        score = 0.0
        for cone in cones:
            depth = _penetration(cone, x, y)
            if depth > score:
                score = depth
            if score > best[2] + _TIE_SQ:
                return  # cannot win
        dx = x - target_x
        dy = y - target_y
        distance_sq = dx * dx + dy * dy
        if score < best[2] - _TIE_SQ or (score <= best[2] + _TIE_SQ and distance_sq < best[3]):
            best[0] = x
            best[1] = y
            best[2] = score
            best[3] = distance_sq

    consider(target_x, target_y)
    consider(0.0, 0.0)
    for x, y in candidates:
        consider(x, y)
    for ax, ay, rx, ry, lx, ly in cones:
        consider(ax, ay)
        for ux, uy in ((rx, ry), (lx, ly)):
            allowed = _line_range(ax, ay, ux, uy, 0.0, box, v_max)
            if allowed is None:
                continue
            lo, hi = allowed
            t = (target_x - ax) * ux + (target_y - ay) * uy
            t = lo if t < lo else (hi if hi < t else t)
            consider(ax + t * ux, ay + t * uy)
            consider(ax + lo * ux, ay + lo * uy)
            consider(ax + hi * ux, ay + hi * uy)
    return best[0], best[1]
