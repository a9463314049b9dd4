#!/usr/bin/python3
"""Regenerates tests/data/hrvo_python_reference.json: seeded HRVO situations and the C++
HrvoExact's and HrvoThesis's answers to them, which test_hrvo.py requires python/dream/hrvo.py to reproduce.

The C++ side is hrvo_reference_driver.cc, compiled straight from the sources (no build tree):

  g++ -O2 -std=c++17 -I agents/include -I /usr/include/eigen3 tests/python/hrvo_reference_driver.cc \
      agents/hrvo/hrvo_exact.cc agents/hrvo/hrvo_thesis.cc agents/hrvo/hrvo_cone.cc agents/hrvo/hrvo_params.cc \
      -o /tmp/hrvo_driver
  /usr/bin/python3 tests/python/make_hrvo_reference.py /tmp/hrvo_driver

Inputs are rounded to 4 decimals (short file, and exactly symmetric layouts stay symmetric);
answers are kept to the last bit.
"""

import json
import math
import os
import subprocess
import sys

import numpy as np

SEED = 20261121
OUTPUT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "data", "hrvo_python_reference.json")
DEFAULT_PARAMS = [0.24, 0.2, 1, 1.0, 0.7, 0.05]  # safety, max speed, check boundaries, horizon, keep right, margin


def rounded(values):
    return [round(float(v), 4) for v in values]


def random_params(rng):
    if rng.random() < 0.6:
        return list(DEFAULT_PARAMS)
    return [round(rng.uniform(0.15, 0.35), 3), round(rng.uniform(0.1, 0.3), 3), int(rng.random() < 0.7),
            round(rng.uniform(0.5, 2.0), 2), round(rng.choice([0.0, 0.35, 0.7, 1.2]), 2),
            round(rng.uniform(0.0, 0.1), 3)]


def in_disc(rng, radius):
    r = radius * math.sqrt(rng.random())
    a = rng.uniform(-math.pi, math.pi)
    return [r * math.cos(a), r * math.sin(a)]


def random_case(rng, crowded):
    """Anywhere in the arena; `crowded`: 5-9 neighbours within 0.2-0.55 m all round (the
    least-penetrating fallback's territory), else 0-9 within 0.9 m."""
    params = random_params(rng)
    wall = rng.random()
    if wall < 0.15:  # at (or past) a side wall
        position = [rng.choice([-1, 1]) * rng.uniform(1.4, 1.65), rng.uniform(-1.05, 1.05)]
    elif wall < 0.3:  # at the top or bottom wall
        position = [rng.uniform(-1.65, 1.65), rng.choice([-1, 1]) * rng.uniform(0.8, 1.05)]
    else:
        position = [rng.uniform(-1.55, 1.55), rng.uniform(-0.95, 0.95)]
    neighbours = []
    for _ in range(int(rng.integers(5, 10)) if crowded else int(rng.integers(0, 10))):
        distance = rng.uniform(0.2, 0.55) if crowded else rng.uniform(0.05, 0.9)
        bearing = rng.uniform(-math.pi, math.pi)
        neighbours.append(rounded([distance * math.cos(bearing), distance * math.sin(bearing), *in_disc(rng, 0.2)]))
    speed = rng.choice([0.0, rng.uniform(0.0, 0.35), 0.2])
    heading = rng.uniform(-math.pi, math.pi)
    return {"params": params, "position": rounded(position), "current": rounded(in_disc(rng, 0.2)),
            "preferred": rounded([speed * math.cos(heading), speed * math.sin(heading)]),
            "neighbours": neighbours}


def ring_case(rng):
    """The circle swap's crowded centre: robots on a ring heading for the opposite point,
    seen from one of them (exact mirror symmetries when unperturbed)."""
    count = int(rng.integers(4, 11))
    radius = rng.uniform(0.2, 0.6)
    jitter = 0.0 if rng.random() < 0.4 else 0.01
    points = [[radius * math.cos(2 * math.pi * i / count) + rng.uniform(-jitter, jitter),
               radius * math.sin(2 * math.pi * i / count) + rng.uniform(-jitter, jitter)] for i in range(count)]
    speed = rng.uniform(0.0, 0.2)
    velocities = [[-speed * p[0] / radius, -speed * p[1] / radius] for p in points]
    own = int(rng.integers(0, count))
    neighbours = [rounded([p[0] - points[own][0], p[1] - points[own][1], *v])
                  for i, (p, v) in enumerate(zip(points, velocities)) if i != own]
    preferred = [-0.2 * points[own][0] / radius, -0.2 * points[own][1] / radius]
    return {"params": list(DEFAULT_PARAMS), "position": rounded(points[own]), "current": rounded(velocities[own]),
            "preferred": rounded(preferred), "neighbours": neighbours}


def head_on_case(rng):
    """An exactly symmetric head-on pair: the tie goes to the right."""
    gap = rng.uniform(0.3, 0.9)
    speed = rng.uniform(0.05, 0.2)
    angle = rng.choice([0.0, math.pi / 2, rng.uniform(-math.pi, math.pi)])
    c, s = math.cos(angle), math.sin(angle)
    return {"params": [0.24, 0.2, 0, 1.0, rng.choice([0.0, 0.7]), 0.05], "position": [0.0, 0.0],
            "current": rounded([speed * c, speed * s]), "preferred": rounded([0.2 * c, 0.2 * s]),
            "neighbours": [rounded([gap * c, gap * s, -speed * c, -speed * s])]}


def make_cases():
    rng = np.random.default_rng(SEED)
    cases = [random_case(rng, crowded=False) for _ in range(200)]
    cases += [random_case(rng, crowded=True) for _ in range(100)]
    cases += [ring_case(rng) for _ in range(60)]
    cases += [head_on_case(rng) for _ in range(20)]
    for case in cases:
        case["variant"] = "exact"
    # The thesis variant on a fresh draw of the same kinds.
    thesis = [random_case(rng, crowded=False) for _ in range(60)]
    thesis += [random_case(rng, crowded=True) for _ in range(30)]
    thesis += [ring_case(rng) for _ in range(20)] + [head_on_case(rng) for _ in range(10)]
    for case in thesis:
        case["variant"] = "thesis"
    return cases + thesis


def driver_input(cases):
    lines = []
    for case in cases:
        values = ([int(case["variant"] == "thesis")] + case["params"] + case["position"] + case["current"]
                  + case["preferred"] + [len(case["neighbours"])])
        for row in case["neighbours"]:
            values += row
        lines.append(" ".join(repr(v) for v in values))
    return "\n".join(lines) + "\n"


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    cases = make_cases()
    answers = subprocess.run([sys.argv[1]], input=driver_input(cases), capture_output=True, text=True,
                             check=True).stdout.split("\n")
    for case, line in zip(cases, answers):
        vx, vy, safe = line.split()
        case["expected"] = [float(vx), float(vy)]
        case["safe"] = safe == "1"
    document = {
        "comment": "HRVO situations and the C++ answers (agents/hrvo/hrvo_exact.cc for variant exact, "
                   "hrvo_thesis.cc for thesis), made by "
                   "tests/python/make_hrvo_reference.py with tests/python/hrvo_reference_driver.cc; params: "
                   "[safety_radius_m, max_speed_mps, check_boundaries, boundary_horizon_s, keep_right_rad, "
                   "wall_margin_m] (the thesis variant ignores the last two); neighbours: [rel_x, rel_y, vx, vy]; "
                   "safe: last_was_safe (always true for the thesis).",
        "seed": SEED,
        "cases": cases,
    }
    with open(OUTPUT, "w") as out:
        out.write("{" + f'"comment": {json.dumps(document["comment"])},\n"seed": {SEED},\n"cases": [\n')
        out.write(",\n".join(json.dumps(case, separators=(",", ":")) for case in cases))
        out.write("\n]}\n")
    unsafe = sum(not case["safe"] for case in cases)
    print(f"{len(cases)} cases ({unsafe} with no safe velocity) -> {os.path.normpath(OUTPUT)}")


if __name__ == "__main__":
    main()
