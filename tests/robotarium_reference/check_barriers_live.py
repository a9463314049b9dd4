#!/usr/bin/python3
"""ctest barriers_reference_live: record the official barrier certificates on
other random states than the committed fixture's (another seed, more cases)
and run barriers_test's reference check on them.

Skips (exit 77, ctest SKIP_RETURN_CODE) when ROBOTARIUM_PYTHON_SIMULATOR does
not name a checkout of robotarium/robotarium_python_simulator, or when the
reference Python lacks numpy or cvxopt (Debian: python3-cvxopt).
"""

import argparse
import os
import subprocess
import sys
import tempfile

SKIP = 77


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--python", required=True, help="a Python with numpy and cvxopt")
    parser.add_argument("--generator", required=True)
    parser.add_argument("--test-binary", required=True)
    parser.add_argument("--seed", type=int, default=7)
    parser.add_argument("--cases", type=int, default=200)
    args = parser.parse_args()
    checkout = os.environ.get("ROBOTARIUM_PYTHON_SIMULATOR", "")
    if not checkout or not os.path.isfile(os.path.join(checkout, "rps", "utilities", "barrier_certificates.py")):
        print("SKIP: ROBOTARIUM_PYTHON_SIMULATOR does not name a checkout of robotarium_python_simulator "
              "(see tests/robotarium_reference/README.md)")
        return SKIP
    probe = subprocess.run([args.python, "-c", "import numpy, cvxopt"], capture_output=True, text=True)
    if probe.returncode != 0:
        print(f"SKIP: {args.python} cannot import numpy and cvxopt (apt-get install python3-cvxopt): "
              f"{probe.stderr.strip().splitlines()[-1] if probe.stderr.strip() else ''}")
        return SKIP
    with tempfile.TemporaryDirectory() as folder:
        fixture = os.path.join(folder, "barriers.json")
        subprocess.run([args.python, args.generator, checkout, fixture, "--seed", str(args.seed),
                        "--cases", str(args.cases)], check=True)
        env = dict(os.environ, DREAM_BARRIER_REFERENCE=fixture)
        return subprocess.run([args.test_binary, "--gtest_filter=BarriersReferenceTest.*"], env=env).returncode


if __name__ == "__main__":
    sys.exit(main())
