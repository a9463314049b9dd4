#!/usr/bin/python3
"""hostile_files_cli: issue 34's attacks on the files dream reads and writes, through the real `dream`.

1. A FIFO given as the lab file (`dream calibrate f.npy / f.mat / f.npz`, `dream import
   dream_result.npy / .mat`, `dream render`, `dream replay` of a FIFO log): exit 1 at once, naming
   the FIFO (it used to block in open(), deaf to Ctrl-C, until SIGKILL).
2. Ctrl-C (SIGINT) once `dream calibrate` says it is fitting 20 robots x 60,000 steps, and SIGTERM
   once `dream render --video` says it is rendering: exit 130, nothing written (no realism file,
   picture, video or temporary file); the fit used to go on for 45-54 s, then exit 0 and write.
   The test waits on those progress lines, not on time; its timeouts only stop a hang.
3. Links planted at lab.yaml.tmp.<pid> for the next 3000 process ids in a shared folder, then
   `dream calibrate small.npz --out shared/lab.yaml`: the victim behind them is untouched, lab.yaml
   written.

Usage: hostile_files_cli.py --dream BIN --source DIR
"""

import array
import math
import os
import shutil
import signal
import struct
import zipfile

from dreamtest import arguments, check, main

EXIT_INPUT = 1
EXIT_INTERRUPTED = 130


def npy_bytes(shape, values):
    """A little-endian float64 .npy of `shape` (C order) holding `values` (an array('d'))."""
    header = "{'descr': '<f8', 'fortran_order': False, 'shape': (%s), }" % ", ".join(str(d) for d in shape)
    header += " " * (63 - (len(header) + 10) % 64) + "\n"
    return b"\x93NUMPY\x01\x00" + struct.pack("<H", len(header)) + header.encode() + values.tobytes()


def calibration_values(robots, steps):
    """5 x N x T (x, y, theta, v, w): robots answering steps in v and w a few steps late."""
    dt, delay = 0.033, 5
    rows = [array.array("d", bytes(8 * robots * steps)) for _ in range(5)]
    for i in range(robots):
        x, y, theta = -1.0 + 0.1 * i, -0.5, 0.0
        base = i * steps
        for k in range(steps):
            phase = (k // 90) % 4
            v = 0.1 if phase == 1 else 0.05 if phase == 3 else 0.0
            w = 0.8 if phase == 2 else 0.0
            rows[0][base + k], rows[1][base + k], rows[2][base + k] = x, y, theta
            rows[3][base + k], rows[4][base + k] = v, w
            j = k - delay
            if j >= 0:
                dv, dw = rows[3][base + j], rows[4][base + j]
                x += dv * math.cos(theta) * dt
                y += dv * math.sin(theta) * dt
                theta += dw * dt
            if abs(x) > 1.4 or abs(y) > 0.9:  # back to the start, as a lab run would be restarted
                x, y = -1.0 + 0.1 * i, -0.5
    values = array.array("d")
    for row in rows:
        values.extend(row)
    return values


def calibration_npy(path, robots, steps):
    with open(path, "wb") as f:
        f.write(npy_bytes((5, robots, steps), calibration_values(robots, steps)))


def calibration_npz(path, robots, steps):
    """numpy.savez_compressed's layout: poses.npy (3 x N x T) and commands.npy (2 x N x T) in a zip."""
    values = calibration_values(robots, steps)
    split = 3 * robots * steps
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as archive:
        archive.writestr("poses.npy", npy_bytes((3, robots, steps), values[:split]))
        archive.writestr("commands.npy", npy_bytes((2, robots, steps), values[split:]))


def leftovers(folder):
    return sorted(name for name in os.listdir(folder) if ".tmp." in name)


def test(ctx):
    args = arguments()
    dream = args.dream
    config = os.path.join(args.source, "config", "go_to_goal.yaml")
    run = ctx.path("run")
    ctx.run([dream, "run", config, "--out", run], timeout=120, expect=0)
    export = ctx.path("export")
    ctx.run([dream, "export", run, "--out", export], timeout=60, expect=0)

    # 1. FIFOs where a lab file, result or log is read.
    refused = []
    for name in ["f.npy", "f.mat", "f.npz"]:
        fifo = ctx.path(name)
        os.mkfifo(fifo)
        refused.append((f"calibrate {name}", [dream, "calibrate", fifo, "--out", ctx.path("fifo_lab.yaml")], fifo))
    for name in ["dream_result.npy", "dream_result.mat"]:
        os.makedirs(ctx.path("fifo_result"), exist_ok=True)
        fifo = ctx.path("fifo_result", name)
        os.mkfifo(fifo)
        refused.append((f"import {name}", [dream, "import", fifo, "--export", export, "--out", ctx.path("fifo_import")],
                        fifo))
    fifo_log = ctx.path("fifo.lcmlog")
    os.mkfifo(fifo_log)
    refused.append(("render of a FIFO log", [dream, "render", fifo_log, "--out", ctx.path("fifo.png")], fifo_log))
    refused.append(("calibrate of a FIFO log", [dream, "calibrate", fifo_log, "--out", ctx.path("fifo_lab.yaml")],
                    fifo_log))
    for what, argv, fifo in refused:
        code, out = ctx.run(argv, timeout=30)
        check(code == EXIT_INPUT and fifo in out and "FIFO" in out,
              f"{what}: exit {code}, expected {EXIT_INPUT} naming {fifo} as a FIFO: {out[-400:]}")
    check(not os.path.exists(ctx.path("fifo_lab.yaml")) and not os.path.exists(ctx.path("fifo.png")),
          "a refused FIFO input still wrote an output")

    # 2. Ctrl-C in a long fit; SIGTERM in a long render.
    big = ctx.path("long_fit.npy")
    calibration_npy(big, 20, 60000)
    out_dir = ctx.path("interrupted")
    os.mkdir(out_dir)
    ctx.start("calibrate", [dream, "calibrate", big, "--out", os.path.join(out_dir, "lab.yaml")])
    ctx.wait_for_output("calibrate", r"fitting the lab model to 1 run", timeout=300)
    ctx.procs["calibrate"][0].send_signal(signal.SIGINT)
    code = ctx.wait("calibrate", timeout=120)
    out = ctx.output("calibrate")
    check(code == EXIT_INTERRUPTED and "interrupted" in out,
          f"calibrate after Ctrl-C: exit {code}, expected {EXIT_INTERRUPTED}: {out[-400:]}")
    check(os.listdir(out_dir) == [], f"calibrate stopped by Ctrl-C still wrote: {os.listdir(out_dir)}")

    if shutil.which("ffmpeg"):
        video = os.path.join(run, "slow.mp4")
        ctx.start("render", [dream, "render", run, "--out", video, "--speed", "0.01"])
        ctx.wait_for_output("render", r"rendering \d+ frames", timeout=120)
        ctx.procs["render"][0].send_signal(signal.SIGTERM)
        code = ctx.wait("render", timeout=120)
        check(code == EXIT_INTERRUPTED, f"render after SIGTERM: exit {code}: {ctx.output('render')[-400:]}")
        check(not os.path.exists(video) and leftovers(run) == [],
              f"render stopped by SIGTERM left {video} or temporary files: {leftovers(run)}")

    # 3. Links planted at the temporary names the next process ids would have used.
    shared = ctx.path("shared")
    os.mkdir(shared)
    victim = ctx.path("victim.txt")
    with open(victim, "w") as f:
        f.write("the victim's own text\n")
    small = ctx.path("small_fit.npz")  # an .npz: read by libzip from the descriptor checked
    calibration_npz(small, 3, 1500)
    with open("/proc/sys/kernel/ns_last_pid") as f:
        last_pid = int(f.read())
    target = os.path.join(shared, "lab.yaml")
    for pid in range(last_pid + 1, last_pid + 3001):
        for name in [target, os.path.join(shared, "lab.png")]:
            os.symlink(victim, f"{name}.tmp.{pid}")
    ctx.run([dream, "calibrate", small, "--out", target], timeout=120, expect=0)
    with open(victim) as f:
        check(f.read() == "the victim's own text\n", "the victim behind a planted link was written")
    with open(target) as f:
        check("pose_noise_m" in f.read(), f"{target} holds no realism keys")
    check(not os.path.islink(target), f"{target} is a link")


if __name__ == "__main__":
    main(test)
