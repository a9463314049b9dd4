#!/usr/bin/python3
"""robotarium_script_sweep: `dream sweep SCRIPT.py` runs a Robotarium script once per seed, under
`--set world.realism=lab`, two runs at a time, and tabulates them as any sweep
(docs/robotarium-scripts.md#sweeps).

The script (written here, DREAM's rps only) draws its goals from numpy's global stream, drives three
robots toward them for a fixed number of steps, saves the goals (np.save, into its run folder) and ends
with debug(). Checked: the sweep exits 0; sweep.csv has one row per seed, each ran, to its
end, with a verdict; each run folder holds the script's goals.npy, different for every seed (the run's
seed seeds numpy's stream), and a config.yaml naming the script with that seed and realism lab; and
`dream run` of one run's config.yaml runs the script again into another folder with the same poses at
every step (`dream log diff` on DREAM_POSES): the runs at once, each on its own bus (--private-bus),
never heard each other, and a run folder's config alone repeats the run.

Skipped (77) without numpy or cvxopt.
Usage: robotarium_script_sweep.py --dream BIN --source DIR
"""

import csv
import os

from dreamtest import argument_parser, check, main, script_under_test, tail

SCRIPT = """
import numpy as np
import rps.robotarium as robotarium
from rps.utilities.misc import generate_random_positions
from rps.utilities.transformations import create_si_to_uni_dynamics

N = 3
goals = generate_random_positions(N, spacing=0.4)[:2, :]
np.save("goals.npy", goals)
r = robotarium.Robotarium(number_of_robots=N, show_figure=False, sim_in_real_time=False,
                          initial_conditions=np.array([[-0.8, 0.0, 0.8], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]]))
si_to_uni = create_si_to_uni_dynamics()
for _ in range(STEPS):
    x = r.get_poses()
    r.set_velocities(np.arange(N), si_to_uni(0.5 * (goals - x[:2, :]), x))
    r.step()
r.debug()
"""
STEPS = 60
SEEDS = [1, 2, 3]


def read_csv(path):
    check(os.path.isfile(path), f"{path} is missing")
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def check_runs(ctx, out):
    import numpy as np
    rows = read_csv(os.path.join(out, "sweep.csv"))
    check([row["seed"] for row in rows] == [str(s) for s in SEEDS], f"sweep.csv seeds: {rows}")
    goals = []
    for row in rows:
        check(row["status"] == "ran" and row["end"] == "finished" and row["verdict"] != "",
              f"sweep.csv row of seed {row['seed']}: {row}")
        check(int(row["steps"]) >= STEPS, f"seed {row['seed']}: {row['steps']} steps, the script took {STEPS}")
        run_dir = os.path.join(out, "runs", row["run"])
        goals.append(np.load(os.path.join(run_dir, "goals.npy")).tolist())
        with open(os.path.join(run_dir, "config.yaml")) as f:
            config = f.read()
        check("script: " in config and "robotarium_script_sweep_demo.py" in config,
              f"{run_dir}/config.yaml does not name the script: {tail(config, 800)}")
        check(f"seed: {row['seed']}" in config and "realism: lab" in config,
              f"{run_dir}/config.yaml: not seed {row['seed']} under realism lab: {tail(config, 800)}")
    check(len({str(g) for g in goals}) == len(SEEDS), f"the seeds gave the same numpy draws: {goals}")
    return rows


def test(ctx):
    args = argument_parser().parse_args()
    script = script_under_test(ctx, "robotarium_script_sweep_demo.py", SCRIPT.replace("STEPS", str(STEPS)))
    out = ctx.path("sweep")
    code, output = ctx.run([args.dream, "sweep", script, "--seeds", "1-3", "--set", "world.realism=lab",
                            "--jobs", "2", "--out", out], timeout=900)
    check(code == 0, f"dream sweep SCRIPT.py exited {code}: {tail(output, 2000)}")
    rows = check_runs(ctx, out)

    # One run's config.yaml alone runs the script again: the same poses, step for step.
    run_dir = os.path.join(out, "runs", rows[1]["run"])
    again = ctx.path("again")
    code, output = ctx.run([args.dream, "run", os.path.join(run_dir, "config.yaml"), "--out", again, "-q"],
                           timeout=600)
    check(code == int(rows[1]["exit_code"]), f"dream run of {run_dir}/config.yaml exited {code}, the sweep's run "
                                             f"{rows[1]['exit_code']}: {tail(output, 1500)}")
    code, output = ctx.run([args.dream, "log", "diff", os.path.join(run_dir, "run.lcmlog"),
                            os.path.join(again, "run.lcmlog"), "--channels", "DREAM_POSES"], timeout=120)
    check(code == 0, f"the rerun of {rows[1]['run']}'s config.yaml gave other poses: {tail(output, 1500)}")


if __name__ == "__main__":
    main(test)
