#!/usr/bin/python3
"""render_cli: `dream render` draws a recorded run as a picture, a video or metric plots, and
refuses bad input with one line, a documented exit code and nothing written.

1. A 300-step HRVO circle run (it has radio messages, sensors and goals in its config):
   - no --out: trajectories.svg beside the log, a complete SVG;
   - --out x.png with --radio-links --sensor-ranges: a PNG of the default 1280 px width;
   - --video: run.mp4 beside the log; --out x.gif --fps 10 --width 320: both have exactly the
     frames `dream render` reported (counted by ffprobe), ceil(9.9 s * fps / speed) + 1 of the run
     plus one second holding the last, and that duration;
   - --plot: metrics.png; --metric min_distance_m --out x.svg: an SVG;
   - a bare copy of the log (no config.yaml beside it) still renders, <stem>_trajectories.svg, and
     so does a log beside a broken config.yaml (with a warning: the config only adds goals).
2. Bad input, each one line naming the culprit, and no file (or temporary file) written:
   unknown extension (exit 2, listing the allowed ones), --out in a missing folder (1), a log with
   no DREAM_POSES ("no poses in <log>: nothing to render", 1), a missing run (1), --radio-links
   without a config (1), an unknown --metric (1, listing the run's series), --plot with .mp4 (2),
   ffmpeg missing from PATH (1, "apt-get install ffmpeg").
3. SIGINT while a video is encoding: exit 130 and no video or temporary file.

Usage: render_cli.py --dream BIN --source DIR
"""

import math
import os
import re
import shutil
import signal
import struct
import subprocess

from dreamtest import arguments, check, main

EXIT_INPUT = 1
EXIT_USAGE = 2
EXIT_INTERRUPTED = 130
STEPS = 300
STEP_S = 0.033


def ffprobe(path, entries):
    """{key: value} of ffprobe's -show_entries for the first video stream (counting frames)."""
    result = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                             entries, "-of", "default=noprint_wrappers=1", path],
                            capture_output=True, text=True, check=False)
    check(result.returncode == 0, f"ffprobe {path}: {result.stderr.strip()}")
    return dict(line.split("=", 1) for line in result.stdout.split())


def png_size(path):
    with open(path, "rb") as f:
        head = f.read(24)
    check(head[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG")
    return struct.unpack(">II", head[16:24])


def check_svg(path):
    check(os.path.isfile(path), f"{path} is missing")
    with open(path) as f:
        text = f.read()
    check(text.startswith("<?xml") and "<svg" in text and text.rstrip().endswith("</svg>"),
          f"{path} is not a complete SVG ({len(text)} bytes)")


def write_log(path, events):
    """An LCM event log of (channel, payload bytes) events."""
    with open(path, "wb") as f:
        for number, (channel, data) in enumerate(events):
            name = channel.encode()
            f.write(struct.pack(">IqqII", 0xEDA1DA01, number, number * 33000, len(name), len(data)) + name + data)


def leftovers(folder):
    return [name for name in os.listdir(folder) if ".tmp." in name]


def check_video(ctx, dream, run, out, extra, fps, speed):
    code, text = ctx.run([dream, "render", run, "--out", out] + extra, timeout=120, expect=0)
    check(os.path.isfile(out), f"{out} is missing: {text}")
    reported = int(text.split("(")[-1].split(" frames")[0]) if " frames" in text else -1
    # Durations for people: "10.93 s", never a raw float such as "6.66667 s".
    check(re.search(r"frames, \d+\.\d\d s at \d+ fps, \d+x\d+, \d+\.\d\d s\)", text),
          f"dream render's video line does not give its durations to 0.01 s: {text.strip()}")
    expected = math.ceil(STEPS * STEP_S * fps / speed - 1e-9) + 1 + round(fps)
    info = ffprobe(out, "stream=nb_read_frames:format=duration")
    frames = int(info["nb_read_frames"])
    check(frames == expected == reported,
          f"{out}: ffprobe counts {frames} frames, dream render reported {reported}, expected {expected}")
    duration = float(info["duration"])
    check(abs(duration - expected / fps) < 1.5 / fps, f"{out}: {duration} s, expected {expected / fps:.2f} s")


def test(ctx):
    args = arguments()
    dream = args.dream
    check(shutil.which("ffmpeg") and shutil.which("ffprobe"),
          "ffmpeg/ffprobe not found: apt-get install ffmpeg (it is in .ci/debian-packages.txt)")

    run = ctx.path("run")
    ctx.run([dream, "-q", "run", os.path.join(args.source, "config", "hrvo_circle.yaml"), "--steps", str(STEPS),
             "--all-steps", "--out", run], timeout=60, expect=0)
    log = os.path.join(run, "run.lcmlog")

    # 1. Pictures, videos, plots.
    ctx.run([dream, "render", run], expect=0)
    check_svg(os.path.join(run, "trajectories.svg"))
    png = ctx.path("links.png")
    ctx.run([dream, "render", run, "--out", png, "--radio-links", "--sensor-ranges"], expect=0)
    check(png_size(png)[0] == 1280, f"{png}: {png_size(png)}")

    check_video(ctx, dream, run, os.path.join(run, "run.mp4"), ["--radio-links"], fps=30, speed=4)
    ctx.run([dream, "render", run, "--video", "--speed", "8"], expect=0)  # the default name, replaced atomically
    check(ffprobe(os.path.join(run, "run.mp4"), "stream=width")["width"] == "720", "run.mp4 is not 720 px wide")
    check_video(ctx, dream, run, ctx.path("run.gif"), ["--fps", "10", "--width", "320", "--sensor-ranges"],
                fps=10, speed=4)

    ctx.run([dream, "render", run, "--plot"], expect=0)
    check(png_size(os.path.join(run, "metrics.png"))[0] == 1000, "metrics.png is not 1000 px wide")
    ctx.run([dream, "render", run, "--metric", "min_distance_m", "--out", ctx.path("closest.svg")], expect=0)
    check_svg(ctx.path("closest.svg"))

    bare = ctx.path("bare")
    os.mkdir(bare)
    shutil.copy(log, os.path.join(bare, "lab1.lcmlog"))
    ctx.run([dream, "render", os.path.join(bare, "lab1.lcmlog")], expect=0)
    check_svg(os.path.join(bare, "lab1_trajectories.svg"))

    broken = ctx.path("broken")
    os.mkdir(broken)
    shutil.copy(log, os.path.join(broken, "run.lcmlog"))
    with open(os.path.join(broken, "config.yaml"), "w") as f:
        f.write("name: x\nrobots: [10\n")
    code, text = ctx.run([dream, "render", broken], expect=0)
    check("warn" in text and "config.yaml" in text, f"a broken config.yaml beside the log: no warning in {text!r}")
    check_svg(os.path.join(broken, "trajectories.svg"))

    # 2. Bad input.
    empty_log = ctx.path("empty", "status_only.lcmlog")
    os.mkdir(ctx.path("empty"))
    write_log(empty_log, [("DREAM_STATUS", b"\x00" * 8), ("OTHER", b"abc")])
    with open(ctx.path("a_file"), "w") as f:
        f.write("not a folder")
    cases = [
        ([run, "--out", ctx.path("x.bmp")], EXIT_USAGE, ["x.bmp", ".png, .svg, .mp4, .gif"]),
        ([run, "--out", ctx.path("no_folder", "x.png")], EXIT_INPUT, ["no_folder", "does not exist"]),
        ([run, "--out", ctx.path("a_file", "x.png")], EXIT_INPUT, ["a_file is a file, not a folder"]),
        ([run, "--config", os.path.join(args.source, "config", "go_to_goal.yaml"), "--out", ctx.path("other.png")],
         EXIT_INPUT, ["go_to_goal.yaml has 8 robots", "not this run's config"]),
        ([empty_log], EXIT_INPUT, [f"no poses in {empty_log}: nothing to render"]),
        ([ctx.path("no_such_run")], EXIT_INPUT, ["no_such_run"]),
        ([os.path.join(bare, "lab1.lcmlog"), "--radio-links", "--out", ctx.path("bare", "x.png")], EXIT_INPUT,
         ["--radio-links", "config"]),
        ([run, "--metric", "nope", "--out", ctx.path("nope.png")], EXIT_INPUT, ["nope", "min_distance_m"]),
        ([run, "--plot", "--out", ctx.path("plot.mp4")], EXIT_USAGE, ["--plot", "plot.mp4"]),
        ([run, "--out", ctx.path("x.mp4"), "--fps", "0"], EXIT_USAGE, ["--fps"]),
    ]
    for argv, expected, fragments in cases:
        code, text = ctx.run([dream, "render"] + argv)
        lines = text.strip().splitlines()
        check(code == expected and len(lines) == 1 and all(f in lines[0] for f in fragments),
              f"dream render {' '.join(argv)}: exit {code} (expected {expected}), output {text.strip()!r}, "
              f"expected one line with {fragments}")
    check(not os.path.exists(ctx.path("no_folder")), "the missing folder was created")
    for name in ("x.bmp", "nope.png", "plot.mp4", "x.mp4"):
        check(not os.path.exists(ctx.path(name)), f"{name} was written by a refused command")
    check(sorted(os.listdir(bare)) == ["lab1.lcmlog", "lab1_trajectories.svg"], f"bare: {os.listdir(bare)}")

    no_ffmpeg = dict(os.environ, PATH=ctx.path("empty"))
    result = subprocess.run([os.path.abspath(dream), "render", run, "--out", ctx.path("x.mp4")], env=no_ffmpeg,
                            capture_output=True, text=True, check=False)
    lines = (result.stdout + result.stderr).strip().splitlines()
    check(result.returncode == EXIT_INPUT and len(lines) == 1 and "apt-get install ffmpeg" in lines[-1],
          f"without ffmpeg: exit {result.returncode}, output {lines}")
    check(not os.path.exists(ctx.path("x.mp4")), "x.mp4 written without ffmpeg")

    # 3. Ctrl-C while encoding a long video (0.25x speed: 40 s of video, 1,200+ frames).
    slow = ctx.path("slow.mp4")
    proc = ctx.start("slow", [dream, "render", run, "--out", slow, "--speed", "0.25"])
    ctx.wait_for_output("slow", r"rendering \d+ frames", timeout=30)
    proc.send_signal(signal.SIGINT)
    code = ctx.wait("slow", timeout=30)
    check(code == EXIT_INTERRUPTED, f"interrupted render exited {code}: {ctx.output('slow')}")
    check(not os.path.exists(slow), "slow.mp4 exists after Ctrl-C")
    for folder in (ctx.dir, run, bare):
        check(not leftovers(folder), f"temporary files left in {folder}: {leftovers(folder)}")


if __name__ == "__main__":
    main(test)
