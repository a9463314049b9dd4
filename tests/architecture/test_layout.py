#!/usr/bin/env python3
"""The tests mirror the libraries (issue 35 item 5): each folder of tests/ is named after the
library it tests, as docs/architecture.md's table names it (`base/config/` -> tests/config,
`agents/kinds/<kind>/` -> tests/kinds), or is one of the few folders that test across libraries,
listed below with what they hold. A new folder must be one or the other."""
import argparse
import pathlib
import re
import sys

ACROSS_LIBRARIES = {
    "architecture": "the rules of the tree itself (this test, library_rules, code_size, code_format)",
    "benchmarks": "speed and memory, measured, never asserted by a timed test",
    "data": "reference data the tests share (the official simulator's outputs)",
    "fuzz": "fuzz targets over every reader of hostile input",
    "install": "the installed tree, used from outside",
    "integration": "the programs, run as a user runs them",
    "java": "lcm-spy's side: the generated Java types",
    "plugins": "controller plugins built out of tree against the kind API",
    "python": "the Python runtime (python/dream) and its twin of the C++ semantics",
    "reliability": "hostile files, configs and messages across every reader",
    "robotarium_reference": "scripts that record the official simulator's answers",
    "support": "helpers the tests share",
}


def library_names(architecture: str):
    names = set()
    for match in re.finditer(r"^\| [a-z()A-Z]+ \| `([^`]+)` \|", architecture, re.MULTILINE):
        folder = match.group(1).rstrip("/")
        if folder.endswith("<kind>"):
            names.add("kinds")
        else:
            names.add(folder.split("/")[-1])
    return names


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--source", required=True, type=pathlib.Path)
    args = parser.parse_args()
    names = library_names((args.source / "docs" / "architecture.md").read_text())
    if len(names) < 20:
        print(f"test_layout: read only {len(names)} libraries from docs/architecture.md's table", file=sys.stderr)
        return 1
    folders = sorted(p.name for p in (args.source / "tests").iterdir() if p.is_dir() and not p.name.startswith("."))
    stray = [f for f in folders if f not in names and f not in ACROSS_LIBRARIES]
    for folder in stray:
        print(f"tests/{folder}: names no library of docs/architecture.md's table and is not one of the folders "
              f"that test across libraries ({', '.join(sorted(ACROSS_LIBRARIES))}); name it after the library "
              f"it tests")
    missing = [f for f in ACROSS_LIBRARIES if f not in folders]
    for folder in missing:
        print(f"tests/{folder}: listed as a folder across libraries but not there; drop it from the list")
    print(f"test_layout: {len(folders)} folders, {len(stray) + len(missing)} out of place")
    return 1 if stray or missing else 0


if __name__ == "__main__":
    sys.exit(main())
