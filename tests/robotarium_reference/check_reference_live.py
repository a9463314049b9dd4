#!/usr/bin/python3
"""ctest robotarium_reference_live: regenerate the reference fixture from the
official simulator and compare it with the committed one.

Skips (exit 77, ctest SKIP_RETURN_CODE) unless ROBOTARIUM_PYTHON_SIMULATOR
names a checkout of robotarium/robotarium_python_simulator. Integers, commands
and debug() text must match exactly; poses within 1e-12 (numpy's sin/cos
differ by an ulp between machines, see tests/world/robotarium_reference_test.cc).
"""

import argparse
import os
import subprocess
import sys
import tempfile

SKIP = 77
POSE_TOLERANCE = 1e-12


def records(path):
    header, body = {}, []
    with open(path, encoding="utf-8") as f:
        for line in f:
            line = line.rstrip("\n")
            if line.startswith("# official commit: "):
                header["commit"] = line[len("# official commit: "):]
            elif line.startswith("# python "):
                header["versions"] = line[2:]
            elif line and not line.startswith("#"):
                body.append(line)
    return header, body


def compare(committed, fresh):
    if len(committed) != len(fresh):
        return f"record counts differ: committed {len(committed)}, regenerated {len(fresh)}"
    for number, (a, b) in enumerate(zip(committed, fresh), start=1):
        if a == b:
            continue
        fa, fb = a.split(","), b.split(",")
        if fa[0] != "pose" or fb[0] != "pose" or fa[:3] != fb[:3] or len(fa) != len(fb):
            return f"record {number} differs:\n  committed:   {a}\n  regenerated: {b}"
        worst = max(abs(float(x) - float(y)) for x, y in zip(fa[3:], fb[3:]))
        if worst > POSE_TOLERANCE:
            return (f"record {number}: pose differs by {worst:g} > {POSE_TOLERANCE:g}:\n"
                    f"  committed:   {a}\n  regenerated: {b}")
    return None


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--python", default="/usr/bin/python3")
    parser.add_argument("--generator", required=True)
    parser.add_argument("--fixture", required=True)
    args = parser.parse_args()

    checkout = os.environ.get("ROBOTARIUM_PYTHON_SIMULATOR", "")
    if not checkout:
        print("SKIP: set ROBOTARIUM_PYTHON_SIMULATOR to a checkout of "
              "robotarium/robotarium_python_simulator to regenerate and compare the fixture")
        return SKIP

    with tempfile.TemporaryDirectory() as tmp:
        fresh_path = os.path.join(tmp, "robotarium_v2_reference.csv")
        result = subprocess.run([args.python, args.generator, checkout, fresh_path])
        if result.returncode != 0:
            print(f"FAIL: {args.generator} exited with {result.returncode}")
            return 1
        committed_header, committed = records(args.fixture)
        fresh_header, fresh = records(fresh_path)

    print(f"committed fixture: commit {committed_header.get('commit')}, {committed_header.get('versions')}")
    print(f"regenerated:       commit {fresh_header.get('commit')}, {fresh_header.get('versions')}")
    problem = compare(committed, fresh)
    if problem:
        print("FAIL: the official simulator no longer produces the committed fixture.\n" + problem)
        print("If the official simulator changed on purpose, regenerate the fixture "
              "(tests/robotarium_reference/README.md) and check the world still matches.")
        return 1
    print(f"OK: {len(committed)} records match (poses within {POSE_TOLERANCE:g})")
    return 0


if __name__ == "__main__":
    sys.exit(main())
