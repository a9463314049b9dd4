#!/usr/bin/python3
"""view_export: dream view's "Export video" (issue 37 item 6) gives what `dream render` gives.

A run of config/go_to_goal.yaml is replayed by `dream view RUN --port 0`. Over HTTP, as the page
asks: /export/start without the page's X-Dream-Export header is refused (403); hostile queries
(unknown names, repeated names, a viewport reaching far off the arena or too small, a step range
past the run, a width, fps or speed out of bounds, more frames than the view draws) are refused
with 400 naming the parameter; a valid export (a zoomed viewport, a step range, layers off) is
polled on /export/status to its end and downloaded from /export/video, as an attachment. The
`dream render` command the server prints for it, run as printed, writes a video of the same frame
count and size whose decoded frames are the same, frame for frame (ffmpeg's framemd5).

What controllers draw (DREAM_DRAW_<id>, drawing_run's three-robot Python controller): exported
with the page's drawings layer on and off, each equals its printed command's video (off: with
--no-drawings), and the two differ in every frame.

`dream run --view --view-wait`: while live, /export/start is refused (409, saying to export the
replay); once the run is over the same URL is its replay, and an export of it works.

With --browser: headless Chromium opens the replay, the user zooms with the keyboard, picks a
step range with the timeline's "here" buttons and clicks "Export video" with the mouse; the page
shows the progress, downloads the video (Chromium's download folder) and prints the command; the
video has the frames the page said and equals that command's video. The drawings layer, unticked
with the mouse before the export, is left out (--no-drawings). A screenshot is kept.

Usage: view_export.py --dream BIN --source DIR [--browser --artifacts DIR]
"""

import json
import os
import re
import shlex
import shutil
import subprocess
import time
import urllib.error
import urllib.request

from drawing_run import CONFIG as DRAWING_CONFIG, CONTROLLER as DRAWING_CONTROLLER
from dreamtest import argument_parser, check, fail, main

URL = re.compile(r"open (http://127\.0\.0\.1:\d+/)")


def get(url, export_header=False):
    """(status, headers, body bytes) of a GET."""
    request = urllib.request.Request(url, headers={"X-Dream-Export": "1"} if export_header else {})
    try:
        with urllib.request.urlopen(request, timeout=30) as response:
            return response.status, dict(response.headers), response.read()
    except urllib.error.HTTPError as error:
        return error.code, dict(error.headers), error.read()


def ffprobe(path):
    out = subprocess.run(["ffprobe", "-v", "error", "-count_frames", "-select_streams", "v:0", "-show_entries",
                          "stream=nb_read_frames,width,height", "-of", "json", path],
                         capture_output=True, text=True, check=True).stdout
    stream = json.loads(out)["streams"][0]
    return int(stream["nb_read_frames"]), int(stream["width"]), int(stream["height"])


def frame_hashes(path):
    out = subprocess.run(["ffmpeg", "-v", "error", "-i", path, "-f", "framemd5", "-"], capture_output=True, text=True,
                         check=True).stdout
    return [line.split(",")[-1].strip() for line in out.splitlines() if line and not line.startswith("#")]


def same_as_command(ctx, dream, cwd, video, status):
    """Runs the printed `dream render` command (dream as built) and compares the two videos."""
    words = shlex.split(status["command"])
    check(words[:2] == ["dream", "render"], f"the printed command is not dream render: {status['command']}")
    check(status["file"] in words, f"the printed command does not write {status['file']}: {status['command']}")
    folder = ctx.path("cli")
    os.makedirs(folder, exist_ok=True)
    ctx.run([dream] + [w if w != status["file"] else os.path.join(folder, w) for w in words[1:]], timeout=120,
            expect=0, cwd=cwd)
    cli_video = os.path.join(folder, status["file"])
    exported = ffprobe(video)
    printed = ffprobe(cli_video)
    check(exported == printed, f"the export has (frames, width, height) {exported}, its command's video {printed}")
    check(exported[0] == status["total"], f"the export has {exported[0]} frames, the page was told {status['total']}")
    check(frame_hashes(video) == frame_hashes(cli_video),
          "the export's decoded frames differ from those of the command it printed")
    return exported


def wait_done(base, job, timeout=120):
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        code, _, body = get(base + "export/status")
        check(code == 200, f"/export/status: {code}")
        status = json.loads(body)
        if status["job"] == job and status["state"] in ("done", "failed"):
            check(status["state"] == "done", f"the export failed: {status}")
            return status
        time.sleep(0.1)
    fail(f"export {job} not done within {timeout} s")


def check_refusals(base):
    code, _, body = get(base + "export/start?format=mp4")
    check(code == 403 and b"X-Dream-Export" in body, f"/export/start without the page's header: {code} {body!r}")
    hostile = {
        "bogus=1": "bogus",
        "fps=10&fps=20": "fps",
        "width=100000": "width",
        "width=720.5": "width",
        "fps=0": "fps",
        "speed=-4": "speed",
        "speed=nan": "speed",
        "trail=1e9": "trail",
        "x0=-50&y0=-1&x1=1&y1=1": "past the arena",
        "x0=0&y0=0&x1=0.01&y1=1": "at least 0.1 m",
        "x0=0&y0=0": "all four",
        "from=10": "both",
        "from=0&to=99999": "not in the run",
        "from=100&to=5": "after",
        "from=-3&to=5": "from",
        "speed=0.01&fps=60": "frames",
        "format=avi": "format",
        "goals=yes": "goals",
        "drawings=2": "drawings",
    }
    for query, named in hostile.items():
        code, _, body = get(base + "export/start?" + query, export_header=True)
        text = body.decode(errors="replace")
        check(code == 400 and named in text, f"/export/start?{query}: {code} {text}; expected 400 naming {named}")
    code, _, body = get(base + "export/start?" + "a" * 300, export_header=True)
    check(code == 414, f"a 300-character query: {code}")
    code, _, body = get(base + "export/video")
    check(code == 404, f"/export/video before any export: {code}")


def check_http_export(ctx, dream, base):
    check_refusals(base)
    query = "format=mp4&width=480&speed=8&x0=-1.2&y0=-0.8&x1=0.3&y1=0.4&from=30&to=150&goals=0&ids=0&trail=5"
    code, _, body = get(base + "export/start?" + query, export_header=True)
    check(code == 202, f"/export/start?{query}: {code} {body!r}")
    started = json.loads(body)
    status = wait_done(base, started["job"])
    check("--viewport=-1.2,-0.8,0.3,0.4" in status["command"] and "--steps 30-150" in status["command"] and
          "--no-goals" in status["command"] and "--no-ids" in status["command"],
          f"the printed command does not say what was asked: {status['command']}")
    code, headers, video = get(base + "export/video")
    check(code == 200 and headers.get("Content-Type") == "video/mp4", f"/export/video: {code} {headers}")
    check(f'attachment; filename="{status["file"]}"' == headers.get("Content-Disposition"),
          f"/export/video is not an attachment named {status['file']}: {headers.get('Content-Disposition')}")
    check(len(video) == status["bytes"], f"/export/video sent {len(video)} bytes, the status said {status['bytes']}")
    path = ctx.path("http_" + status["file"])
    with open(path, "wb") as f:
        f.write(video)
    same_as_command(ctx, dream, ctx.path(), path, status)


def export_over_http(ctx, dream, base, query):
    """Asks /export/start?query, waits for it, downloads it and checks it against its printed command:
    (the status, the video's path, its frames' hashes)."""
    code, _, body = get(base + "export/start?" + query, export_header=True)
    check(code == 202, f"/export/start?{query}: {code} {body!r}")
    status = wait_done(base, json.loads(body)["job"])
    code, _, video = get(base + "export/video")
    check(code == 200 and len(video) == status["bytes"], f"/export/video: {code}, {len(video)} bytes")
    path = ctx.path(f"export_{status['job']}_" + status["file"])
    with open(path, "wb") as f:
        f.write(video)
    same_as_command(ctx, dream, ctx.path(), path, status)
    return status, path, frame_hashes(path)


def check_drawings_export(ctx, dream):
    """A run whose controllers drew, exported with the drawings layer on and off."""
    with open(ctx.path("painter.py"), "w") as f:
        f.write(DRAWING_CONTROLLER)
    with open(ctx.path("drawing.yaml"), "w") as f:
        f.write(DRAWING_CONFIG)
    ctx.run([dream, "run", ctx.path("drawing.yaml"), "--out", ctx.path("runs", "drawing"), "--set",
             "controller.draw=true"], timeout=120, expect=0, cwd=ctx.path())
    ctx.start("drawing_view", [dream, "view", os.path.join("runs", "drawing"), "--port", "0"], cwd=ctx.path())
    ctx.wait_for_output("drawing_view", URL.pattern, 20)
    base = URL.search(ctx.output("drawing_view")).group(1)
    query = "format=mp4&width=480&speed=2&trail=0"
    shown, _, with_drawings = export_over_http(ctx, dream, base, query + "&drawings=1")
    hidden, _, without = export_over_http(ctx, dream, base, query + "&drawings=0")
    check("--no-drawings" not in shown["command"] and "--no-drawings" in hidden["command"],
          f"the printed commands do not say the drawings layer: {shown['command']!r} / {hidden['command']!r}")
    check(len(with_drawings) == len(without) > 2, f"frames: {len(with_drawings)} with drawings, {len(without)} without")
    # Every frame shows the robots' drawings (each robot's latest), in one and not the other.
    same = [k for k in range(len(without)) if with_drawings[k] == without[k]]
    check(not same, f"with and without drawings, frames {same[:10]} are equal")
    ctx.stop("drawing_view")


def check_browser(ctx, args, base):
    from devtools import Page, chromium_argv, devtools_port, wait_for_view

    downloads = ctx.path("downloads")
    os.makedirs(downloads)
    ctx.start("chromium", chromium_argv(ctx.path("chrome"), base), own_group=True)
    page = Page(devtools_port(ctx.path("chrome")))
    page.call("Page.setDownloadBehavior", behavior="allow", downloadPath=downloads)
    wait_for_view(page, "the replay loaded", lambda s: s["mode"] == "replay" and "replay" in s, 30)
    deadline = time.monotonic() + 30
    while page.evaluate("document.getElementById('export-to').value") in ("", None):
        check(time.monotonic() < deadline, "the export's step range was never filled")
        time.sleep(0.05)

    def key(name, code):
        for kind in ("keyDown", "keyUp"):
            page.call("Input.dispatchKeyEvent", type=kind, key=name, code=code, text=name)

    def click(element_id):
        box = page.evaluate(f"(() => {{ const e = document.getElementById('{element_id}');"
                            " e.scrollIntoView({block: 'center'}); const r = e.getBoundingClientRect();"
                            " return [r.x + r.width / 2, r.y + r.height / 2]; })()")
        for kind in ("mousePressed", "mouseReleased"):
            page.call("Input.dispatchMouseEvent", type=kind, x=box[0], y=box[1], button="left", clickCount=1)

    def seek(step_index):
        page.evaluate(f"(() => {{ const s = document.getElementById('scrub'); s.value = '{step_index}';"
                      " s.dispatchEvent(new Event('input')); })()")
        wait_for_view(page, f"step {step_index}", lambda s: s["step"] == step_index, 20)

    key("+", "Equal")
    key("+", "Equal")
    wait_for_view(page, "zoomed in", lambda s: s["camera"]["zoom"] > 1.5, 20)
    seek(40)
    click("export-from-here")
    seek(160)
    click("export-to-here")
    click("show-drawings")
    check(page.evaluate("document.getElementById('show-drawings').checked") is False, "the drawings layer is still on")
    click("export-start")
    deadline = time.monotonic() + 120
    state = {}
    while time.monotonic() < deadline:
        state = page.evaluate("window.dreamView.export")
        if state.get("state") in ("done", "failed"):
            break
        time.sleep(0.1)
    check(state.get("state") == "done", f"the page's export did not finish: {state}")
    check("--steps 40-160" in state["command"] and "--viewport=" in state["command"] and
          "--no-drawings" in state["command"],
          f"the page's export is not of the steps, viewport and layers shown: {state['command']}")
    # The viewport is the world the arena's plot area shows (arena.js's margins: 52, 14, 14, 40 px).
    seen = page.evaluate("(() => { const T = dreamView.T, c = document.getElementById('arena');"
                         " return [T.wx(52), T.wy(c.height - 40), T.wx(c.width - 14), T.wy(14)]; })()")
    asked = [float(v) for v in re.search(r"--viewport=(\S+)", state["command"]).group(1).split(",")]
    check(all(abs(a - b) < 0.002 for a, b in zip(asked, seen)),
          f"the export's viewport {asked} is not what the page shows {[round(v, 3) for v in seen]}")
    shown = page.evaluate("document.getElementById('export-command').textContent")
    check(shown == state["command"], f"the page prints {shown!r}, the server said {state['command']!r}")
    path = os.path.join(downloads, state["file"])
    deadline = time.monotonic() + 60
    while not os.path.isfile(path) or os.path.getsize(path) != state["bytes"]:
        check(time.monotonic() < deadline, f"Chromium did not download {state['file']}: {os.listdir(downloads)}")
        time.sleep(0.1)
    if args.artifacts:
        os.makedirs(args.artifacts, exist_ok=True)
        page.screenshot(os.path.join(args.artifacts, "export.png"))
    same_as_command(ctx, args.dream, ctx.path(), path, state)
    page.close()


def check_run_view(ctx, args):
    """dream run --view: live (waiting for a browser before step 0) an export is refused, saying
    why; at the run's end the same URL is the replay, and its export works."""
    from devtools import WebSocket

    ctx.start("run_view", [args.dream, "run", os.path.join(args.source, "config", "go_to_goal.yaml"), "--out",
                           ctx.path("runs", "watched"), "--view", "--view-port", "0", "--view-wait", "--pace", "0",
                           "--view-keep", "ctrl-c"], cwd=ctx.path())
    ctx.wait_for_output("run_view", URL.pattern, 30)
    base = URL.search(ctx.output("run_view")).group(1)
    code, _, body = get(base + "export/start", export_header=True)
    check(code == 409 and b"this view is live" in body, f"a live view's /export/start: {code} {body!r}")
    socket = WebSocket(base.replace("http://", "ws://") + "ws")  # the browser --view-wait waits for
    ctx.wait_for_output("run_view", r"replays it", 120)
    code, _, body = get(base + "export/start?speed=16", export_header=True)
    check(code == 202, f"the replay's /export/start at the end of dream run --view: {code} {body!r}")
    status = wait_done(base, json.loads(body)["job"])
    check(status["command"].startswith("dream render " + ctx.path("runs", "watched") + " --out watched_steps_0-"),
          f"the printed command is not of the run folder: {status['command']}")
    socket.close()
    ctx.stop("run_view")


def test(ctx):
    parser = argument_parser()
    parser.add_argument("--browser", action="store_true")
    parser.add_argument("--artifacts", default="")
    args = parser.parse_args()
    if not shutil.which("ffmpeg") or not shutil.which("ffprobe"):
        print("SKIP: ffmpeg/ffprobe not installed")
        return
    os.makedirs(ctx.path("runs"))
    run_dir = ctx.path("runs", "go_to_goal")
    ctx.run([args.dream, "run", os.path.join(args.source, "config", "go_to_goal.yaml"), "--out", run_dir],
            timeout=120, expect=0)
    # Relative to the folder the printed command is run in, as a user would type it.
    ctx.start("view", [args.dream, "view", os.path.join("runs", "go_to_goal"), "--port", "0"], cwd=ctx.path())
    ctx.wait_for_output("view", URL.pattern, 20)
    base = URL.search(ctx.output("view")).group(1)
    # The steps it announces are summary.json's (the log's pose frames are one more: step 0's).
    with open(os.path.join(run_dir, "summary.json")) as f:
        steps = json.load(f)["steps"]
    check(f", steps 0-{steps});" in ctx.output("view"),
          f"dream view does not announce summary.json's {steps} steps as 'steps 0-{steps}': {ctx.output('view')}")
    if args.browser:
        check_browser(ctx, args, base)
    else:
        check_http_export(ctx, args.dream, base)
        check_drawings_export(ctx, args.dream)
        check_run_view(ctx, args)


if __name__ == "__main__":
    main(test)
