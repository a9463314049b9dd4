#!/usr/bin/python3
"""library_rules: each library includes only what docs/architecture.md says it may use.

docs/architecture.md's library table has, for each library folder, the include path its own
headers live under (`dream/world/`) and the libraries it may use, named by their include
paths (`world`, `lcm`, ...; `msgs` for lcm-gen's types, `dream/<type>.hpp`; `lcm` also
covers LCM's own headers, `<lcm/...>`). This test reads that table, not a copy of it, so the
document and the code cannot drift apart:

- every folder that holds an `include/dream/<name>/` directory is a row of the table;
- every `#include` of a dream header in a row's sources (its folder, minus the folders of
  other rows below it) names its own library or one it may use.

Before the sources, the checker must flag a synthetic row that breaks each rule, so a checker
that accepts everything fails here.

Usage: library_rules.py --source DIR
"""

import argparse
import os
import re
import subprocess
import sys

TABLE_HEADER = re.compile(r"^\|\s*folder\s*\|.*\|\s*include path\s*\|\s*may use\s*\|", re.IGNORECASE)
DREAM_INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]dream/([A-Za-z0-9_]+)(/|\.hpp)', re.MULTILINE)
LCM_INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]lcm/', re.MULTILINE)
SOURCE_SUFFIXES = (".h", ".hpp", ".cc", ".cpp")


def cell_words(cell):
    """`dream/world/` -> world; "`world`, `lcm`" -> {world, lcm}; "none" or "-" -> {}."""
    words = {w.strip().strip("/").removeprefix("dream/").strip("/") for w in re.findall(r"`([^`]+)`", cell)}
    return {w for w in words if re.fullmatch(r"[a-z_]+", w)}  # library names, not the prose's other code


def read_table(doc_path):
    """Rows of the library table: {folder: (own include name, may-use names)}."""
    rows = {}
    with open(doc_path, encoding="utf-8") as doc:
        lines = doc.read().splitlines()
    start = next((i for i, line in enumerate(lines) if TABLE_HEADER.match(line)), None)
    if start is None:
        raise SystemExit(f"FAIL: {doc_path}: no table whose header starts '| folder | ... | include path | may use |'")
    header = [c.strip().lower() for c in lines[start].strip().strip("|").split("|")]
    folder_col, path_col, use_col = header.index("folder"), header.index("include path"), header.index("may use")
    for line in lines[start + 2:]:
        if not line.startswith("|"):
            break
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        folders = re.findall(r"`([^`]+)`", cells[folder_col])
        own = cell_words(cells[path_col])
        if not own:
            continue  # no public headers (the command line, the Python package): nothing to check
        if len(folders) != 1 or len(own) != 1:
            raise SystemExit(f"FAIL: {doc_path}: row needs one `folder/` and one `dream/<name>/`: {line}")
        rows[folders[0].strip("/")] = (own.pop(), cell_words(cells[use_col]))
    return rows


def tracked_files(source):
    listed = subprocess.run(["git", "-C", source, "ls-files"], stdout=subprocess.PIPE, text=True, check=True)
    return [f for f in listed.stdout.splitlines() if os.path.isfile(os.path.join(source, f))]


def owner_of(path, folders):
    """The row whose folder holds `path` most closely (None: no library's source)."""
    best = None
    for folder in folders:
        if path.startswith(folder + "/") and (best is None or len(folder) > len(best)):
            best = folder
    return best


def violations(rows, files, read):
    """What breaks the rules, one line each. `read(path)` gives a file's text."""
    found = []
    for path in files:
        parts = path.split("/")
        if "include" in parts:
            at = parts.index("include")
            if len(parts) > at + 2 and parts[at + 1] == "dream" and not path.startswith("tests/"):
                folder = "/".join(parts[:at])
                if folder not in rows:
                    found.append(f"{path}: {folder}/ has public headers but is no row of the library table")
    for path in files:
        if not path.endswith(SOURCE_SUFFIXES) or path.startswith(("tests/", "docs/")):
            continue
        folder = owner_of(path, rows)
        if folder is None:
            continue
        own, may_use = rows[folder]
        text = read(path)
        for match in DREAM_INCLUDE.finditer(text):
            name = "msgs" if match.group(2) == ".hpp" else match.group(1)
            if name != own and name not in may_use:
                found.append(f"{path}: includes dream/{match.group(1)}{match.group(2)}, "
                             f"but {folder}/ (dream/{own}/) may use only {sorted(may_use) or 'nothing'}")
        if LCM_INCLUDE.search(text) and "lcm" not in may_use and own != "lcm":
            found.append(f"{path}: includes LCM, but {folder}/ (dream/{own}/) may not use lcm")
    return found


def self_test():
    """The checker must flag each kind of breach in a made-up tree."""
    rows = {"lib/a": ("a", {"b"}), "lib/b": ("b", set())}
    texts = {
        "lib/a/src/x.cc": '#include "dream/a/x.h"\n#include "dream/b/y.h"\n',     # allowed
        "lib/b/src/y.cc": '#include "dream/a/x.h"\n',                             # b may not use a
        "lib/b/src/z.cc": "#include <lcm/lcm-cpp.hpp>\n",                         # nor LCM
        "lib/b/src/t.cc": '#include "dream/robot_poses_t.hpp"\n',                 # nor msgs
        "lib/c/include/dream/c/c.h": "",                                          # not in the table
    }
    found = violations(rows, list(texts), texts.__getitem__)
    expected = ["lib/b/src/y.cc", "lib/b/src/z.cc", "lib/b/src/t.cc", "lib/c/include/dream/c/c.h"]
    for path in expected:
        if not any(line.startswith(path + ":") for line in found):
            raise SystemExit(f"FAIL: self test: {path} breaks a rule but was not flagged ({found})")
    if any(line.startswith("lib/a/") for line in found):
        raise SystemExit(f"FAIL: self test: lib/a/src/x.cc keeps the rules but was flagged ({found})")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source", required=True, help="the repository's root")
    args = parser.parse_args()
    self_test()
    rows = read_table(os.path.join(args.source, "docs", "architecture.md"))

    def read(path):
        with open(os.path.join(args.source, path), encoding="utf-8", errors="replace") as f:
            return f.read()

    found = violations(rows, tracked_files(args.source), read)
    for line in found:
        print(line)
    if found:
        print(f"FAIL: {len(found)} include(s) break docs/architecture.md's library table")
        return 1
    print(f"PASS: {len(rows)} libraries include only what docs/architecture.md allows")
    return 0


if __name__ == "__main__":
    sys.exit(main())
