#!/usr/bin/python3
"""Wall time of `dream render` on a 10-robot, 3,000-step run: PNG and SVG pictures, MP4 and GIF videos.

    tests/benchmarks/render_benchmark.py --build build

Makes the run first (`dream run config/hrvo_circle.yaml --steps 3000 --all-steps`: 10 robots, every
step, with radio messages), then times each `dream render` command end to end (process start, reading
the 5 MB log, drawing, encoding, writing), best of --repeat. The issue's targets: PNG under 1 s, MP4
under 30 s. Numbers go to docs/performance.md; nothing here is a pass/fail test.
"""
import argparse
import os
import subprocess
import sys
import tempfile
import time


def timed(argv):
    start = time.monotonic()
    result = subprocess.run(argv, capture_output=True, text=True, check=False)
    elapsed = time.monotonic() - start
    if result.returncode != 0:
        sys.exit(f"{' '.join(argv)} failed ({result.returncode}): {(result.stdout + result.stderr).strip()[-300:]}")
    return elapsed, result.stdout.strip().splitlines()[-1]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default="build")
    parser.add_argument("--config", default="config/hrvo_circle.yaml")
    parser.add_argument("--steps", type=int, default=3000)
    parser.add_argument("--repeat", type=int, default=3, help="renders per output; the best is reported")
    args = parser.parse_args()
    dream = os.path.join(args.build, "dream")
    with tempfile.TemporaryDirectory() as tmp:
        run = os.path.join(tmp, "run")
        made = subprocess.run([dream, "-q", "run", args.config, "--steps", str(args.steps), "--all-steps", "--out", run],
                              capture_output=True, text=True, check=False)
        if made.returncode not in (0, 3):
            sys.exit(f"dream run failed ({made.returncode}): {made.stderr.strip()[-300:]}")
        cases = [
            ("PNG picture", ["--out", os.path.join(tmp, "t.png")], 1.0),
            ("SVG picture", ["--out", os.path.join(tmp, "t.svg")], None),
            ("PNG picture, radio links and sensor ranges",
             ["--out", os.path.join(tmp, "l.png"), "--radio-links", "--sensor-ranges"], None),
            ("metrics plot (PNG)", ["--plot", "--out", os.path.join(tmp, "m.png")], None),
            ("MP4 video (defaults: 720 px, 30 fps, 4x)", ["--out", os.path.join(tmp, "v.mp4")], 30.0),
            ("MP4 video, radio links and sensor ranges",
             ["--out", os.path.join(tmp, "l.mp4"), "--radio-links", "--sensor-ranges"], 30.0),
            ("GIF video (defaults: 480 px, 15 fps, 4x)", ["--out", os.path.join(tmp, "v.gif")], None),
        ]
        print(f"{args.steps} steps of {args.config}, {dream}; best of {args.repeat}")
        for name, extra, target in cases:
            best = min(timed([dream, "-q", "render", run] + extra) for _ in range(args.repeat))
            verdict = "" if target is None else f"  (target < {target:g} s: {'met' if best[0] < target else 'MISSED'})"
            print(f"{name:45s} {best[0]:7.2f} s{verdict}   {best[1]}")


if __name__ == "__main__":
    main()
