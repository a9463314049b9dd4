#!/usr/bin/python3
"""One judge across the commands (issue 33 item 2): for shipped configs, the same run through every
command that judges it must give one verdict and one exit code.

    verdict_agreement.py --dream build/dream --source . [--configs go_to_goal,...]

For each config: `dream run`, `dream export` (track), `dream check-submission` in the official
Robotarium simulator ($ROBOTARIUM_PYTHON_SIMULATOR: a checkout or a bare git repository of
robotarium_python_simulator; without it the test prints SKIP and exits 77), `dream import` of the
result it saved and `dream lab-replay` of that lab run. check-submission, import and lab-replay judge
the same lab run: their verdicts (check.json, each summary.json) and exit codes must be one. The
shipped configs are deterministic and their lab runs track their plan within millimetres, so
`dream run`'s verdict and exit code must be theirs too.

Every shipped config that `dream export` takes (calibration.yaml is exported by
`dream export --calibration`, covered by bridge_calibration_export_official): eight configs, 175 s
on the 2-core machine beside three other builds (issue 33); --configs NAME,... takes fewer.
"""

import argparse
import glob
import json
import os
import sys
import time

from bridge_driver import check, drive, simulator_flags
from bridge_roundtrip import EXIT_OF_VERDICT, run, run_with_code

NOT_EXPORTED = {"calibration"}  # dream export --calibration's program, not a run to export


def verdict_of(folder, name="summary.json"):
    with open(os.path.join(folder, name)) as f:
        return json.load(f)["verdict"]


def judged(dream, source, tmp, name, simulator_flags):
    """Every command's (verdict, exit code) for one config, by command."""
    config = os.path.join(source, "config", name + ".yaml")
    where = lambda *parts: os.path.join(tmp, name, *parts)
    os.makedirs(where())
    verdicts = {}
    code, output, _ = run_with_code([dream, "run", config, "--out", where("sim"), "-q"], expect=None)
    verdicts["run"] = (verdict_of(where("sim")), code)
    run([dream, "export", where("sim"), "--out", where("export"), "-q"])
    code, output, _ = run_with_code([dream, "check-submission", where("export"), "--out", where("check")] +
                                    simulator_flags, expect=None, timeout=900)
    check(os.path.isfile(where("check", "check.json")), name + ": check-submission wrote no check.json:\n" +
          output[-2000:])
    verdicts["check-submission"] = (verdict_of(where("check"), "check.json"), code)
    verdicts["check-submission summary.json"] = (verdict_of(where("check")), code)
    result_file = where("check", "lab_files", "dream_result.npy")
    code, output, _ = run_with_code([dream, "import", result_file, "--export", where("export"), "--out",
                                     where("import"), "-q"], expect=None)
    verdicts["import"] = (verdict_of(where("import")), code)
    code, output, _ = run_with_code([dream, "lab-replay", where("check"), "--out", where("replay"), "-q"],
                                    expect=None)
    verdicts["lab-replay"] = (verdict_of(where("replay")), code)
    return verdicts


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--dream", required=True)
    parser.add_argument("--source", required=True)
    parser.add_argument("--configs", default="all", help="names in config/, or 'all'")
    args = parser.parse_args()
    started = time.monotonic()

    def body(tmp, report):
        flags, _ = simulator_flags("official", tmp, "to judge every config through it")
        if args.configs == "all":
            names = sorted(os.path.basename(p)[:-5] for p in glob.glob(os.path.join(args.source, "config", "*.yaml")))
            names = [n for n in names if n not in NOT_EXPORTED]
        else:
            names = args.configs.split(",")
        failures = []
        for name in names:
            verdicts = judged(args.dream, args.source, tmp, name, flags)
            report.append("%s: %s" % (name, ", ".join("%s %s (exit %d)" % (c, v, e) for c, (v, e) in verdicts.items())))
            for command, (verdict, code) in verdicts.items():
                if code != EXIT_OF_VERDICT[verdict]:
                    failures.append("%s: %s exited %d for a %s run" % (name, command, code, verdict))
            if len(set(verdicts.values())) != 1:
                failures.append("%s: the commands disagree: %s" % (name, verdicts))
        check(not failures, "\n      ".join(failures))
        return "%d configs, every command one verdict and exit code (%.1f s)" % (len(names), time.monotonic() - started)

    return drive("dream_verdict_agreement_", body)


if __name__ == "__main__":
    sys.exit(main())
