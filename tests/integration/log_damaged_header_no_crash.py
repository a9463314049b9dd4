#!/usr/bin/python3
"""log_damaged_header_no_crash: `dream log info` and `dream log diff` refuse a log whose event
header is damaged (absurd or negative lengths, a broken sync word) with exit 1 (log diff: 2, "not
compared", as diff(1)) and a message naming the file, and never crash; the Python reader (python/dream_log.py) refuses them too.

Each damaged copy of a real run log changes one field of the header of event 100.

Usage: log_damaged_header_no_crash.py --dream BIN --source DIR
"""

import os
import struct

from dreamtest import LogFormatError, arguments, check, main, read_all, read_events

EVENT = 100
# Field offsets inside an event header: sync word 0, event number 4, timestamp 12,
# channel length 20, data length 24.
DAMAGE = [
    ("data length 0x7fffffff", 24, struct.pack(">i", 0x7FFFFFFF)),
    ("data length -5", 24, struct.pack(">i", -5)),
    ("data length 1 GB", 24, struct.pack(">i", 1 << 30)),
    ("channel length 0x7fffffff", 20, struct.pack(">i", 0x7FFFFFFF)),
    ("channel length -1", 20, struct.pack(">i", -1)),
    ("sync word zeroed", 0, b"\0\0\0\0"),
]


def test(ctx):
    args = arguments()

    out = ctx.path("run")
    ctx.run([args.dream, "-q", "run", os.path.join(args.source, "config", "go_to_goal.yaml"), "--out", out],
            expect=0)
    with open(os.path.join(out, "run.lcmlog"), "rb") as f:
        data = f.read()
    offset = sum(28 + len(e.channel) + len(e.data) for e in read_all(os.path.join(out, "run.lcmlog"))[:EVENT])

    problems = []
    for name, field, value in DAMAGE:
        path = ctx.path(name.replace(" ", "_") + ".lcmlog")
        with open(path, "wb") as f:
            f.write(data[:offset + field] + value + data[offset + field + len(value):])
        for argv in (["log", "info", path], ["log", "diff", path, os.path.join(out, "run.lcmlog")]):
            code, text = ctx.run([args.dream] + argv, timeout=30)
            last = text.strip().splitlines()[-1] if text.strip() else ""
            if code >= 128 or code < 0:
                problems.append(f"{name}: `dream {argv[0]} {argv[1]}` died from signal {abs(code) % 128}")
            elif code != (2 if argv[1] == "diff" else 1) or path not in last:
                problems.append(f"{name}: `dream {argv[0]} {argv[1]}` exit {code}, expected 1 (diff: 2) and a message "
                                f"naming the file: {last!r}")
        try:
            for _ in read_events(path):
                pass
            problems.append(f"{name}: the Python reader accepted the damaged log")
        except LogFormatError:
            pass
        print(f"{name}: checked")
    check(not problems, "; ".join(problems))


if __name__ == "__main__":
    main(test)
