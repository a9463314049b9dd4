#!/usr/bin/python3
"""library_rules: each library includes only what docs/architecture.md says it may use.

docs/architecture.md's library table has, for each library folder, the include path its own
headers live under (`dream/world/`) and the libraries it may use, named by their include
paths (`world`, `lcm`, ...; `msgs` for lcm-gen's types, `dream/<type>.hpp`; `lcm` also
covers LCM's own headers, `<lcm/...>`). This test reads that table, not a copy of it, so the
document and the code cannot drift apart:

- every folder that holds an `include/dream/<name>/` directory is a row of the table;
- every `#include` of a dream header in a row's sources (its folder, minus the folders of
  other rows below it) names its own library or one it may use;
- a row's folder, include path, namespace and CMake target agree (`sim/world/`,
  `dream/world/`, `dream::world`, `dream::world`), its folder's CMakeLists.txt defines that
  target, and its sources open no namespace but `dream::<name>` (and ones nested in it);
- a row's folder lies on its floor (the folder's first part), and a row may use only
  libraries of its own floor or of floors below it (the doc's "Floors, bottom up:" line);
- no two libraries may use each other, directly or through others (inside a floor too).

A row with no include path and a `dream::<name>` namespace is a program's folder (the command
line, `app/cli/`): it has no target of its own, but its sources' includes and namespaces are
checked against its "may use" as a library's are, unless that says `all`.

A row whose folder is `<parent>/<kind>/` stands for one library per folder of `<parent>/` that
has a CMakeLists.txt (the built-in experiment kinds, `agents/kinds/<kind>/`): each is checked
as a row of its own with `<kind>` replaced by the folder's name, and `<kind>` in another row's
"may use" names every one of them.

Before the sources, the checker must flag a synthetic row that breaks each rule, so a checker
that accepts everything fails here.

Usage: library_rules.py --source DIR
"""

import argparse
import os
import re
import subprocess
import sys

TABLE_HEADER = re.compile(r"^\|\s*floor\s*\|\s*folder\s*\|.*\|\s*include path\s*\|\s*namespace\s*\|\s*may use\s*\|",
                          re.IGNORECASE)
FLOORS_LINE = re.compile(r"^Floors, bottom up: (.*)\.$")
NAMESPACE_OPEN = re.compile(r"^\s*namespace\s+(dream(?:::\w+)*)\s*\{", re.MULTILINE)
FORWARD_DECLARATIONS = re.compile(r"(\s*(class|struct)\s+\w+;[ \t]*(//[^\n]*)?)*\s*")
TARGET_DEFINITION = re.compile(r"(?:dream_add_library\(|add_library\(dream_)(\w+)[\s)]")
DREAM_INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]dream/([A-Za-z0-9_]+)(/|\.hpp)', re.MULTILINE)
LCM_INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]lcm/', re.MULTILINE)
SOURCE_SUFFIXES = (".h", ".hpp", ".cc", ".cpp")


def cell_words(cell):
    """`dream/world/` -> world; "`world`, `lcm`" -> {world, lcm}; "none" or "-" -> {}."""
    words = {w.strip().strip("/").removeprefix("dream/").strip("/") for w in re.findall(r"`([^`]+)`", cell)}
    return {w for w in words if re.fullmatch(r"[a-z_]+", w)}  # library names, not the prose's other code


class Row:
    """One library of the table."""

    def __init__(self, floor, folder, own, namespace, targets, may_use, program=False):
        self.floor, self.folder, self.own = floor, folder, own
        self.namespace, self.targets, self.may_use = namespace, targets, may_use
        self.program = program  # a program's folder: no target or public headers of its own


PLACEHOLDER = "<kind>"


def template_parent(line):
    """`agents/kinds` for a template row (folder `agents/kinds/<kind>/`), else None."""
    folder = re.match(r"^\|[^|]*\|\s*`([^`]*)`", line)
    if not line.startswith("|") or not folder or PLACEHOLDER not in folder.group(1):
        return None
    return folder.group(1).split(PLACEHOLDER)[0].strip("/")


def expand_templates(lines, subfolders):
    """The table's lines with each template row (folder `<parent>/<kind>/`) made one row per
    folder `subfolders(parent)` names, and `<kind>` in other rows standing for all of them."""
    names = [name for line in lines if template_parent(line) is not None for name in subfolders(template_parent(line))]
    out = []
    for line in lines:
        parent = template_parent(line)
        if parent is not None:
            out += [line.replace(PLACEHOLDER, name) for name in subfolders(parent)]
        elif line.startswith("|"):
            out.append(line.replace(f"`{PLACEHOLDER}`", ", ".join(f"`{name}`" for name in names) or "none"))
        else:
            out.append(line)
    return out


def read_table(doc_path, subfolders=lambda parent: []):
    """The floors, bottom up, and the rows of the library table: {folder: Row}; a row without
    public headers (the command line, lcm-gen's types) only names its library's floor.
    `subfolders(parent)`: the library folders a template row's `<parent>/<kind>/` stands for."""
    rows, floor_of = {}, {}
    with open(doc_path, encoding="utf-8") as doc:
        lines = expand_templates(doc.read().splitlines(), subfolders)
    floors = next((re.findall(r"`([a-z_]+)`", m.group(1)) for m in map(FLOORS_LINE.match, lines) if m), None)
    if not floors:
        raise SystemExit(f"FAIL: {doc_path}: no line 'Floors, bottom up: `a`, `b`, ....'")
    start = next((i for i, line in enumerate(lines) if TABLE_HEADER.match(line)), None)
    if start is None:
        raise SystemExit(f"FAIL: {doc_path}: no table whose header starts "
                         "'| floor | folder | ... | include path | namespace | may use |'")
    header = [c.strip().lower() for c in lines[start].strip().strip("|").split("|")]
    col = {name: header.index(name) for name in ("floor", "folder", "cmake target", "include path", "namespace", "may use")}
    for line in lines[start + 2:]:
        if not line.startswith("|"):
            break
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        folders = re.findall(r"`([^`]+)`", cells[col["folder"]])
        targets = set(re.findall(r"`dream::(\w+)`", cells[col["cmake target"]]))
        for target in targets:
            floor_of[target] = cells[col["floor"]]
        own = cell_words(cells[col["include path"]])
        namespaces = re.findall(r"`([^`]+)`", cells[col["namespace"]])
        if not own:
            # No public headers: lcm-gen's types (nothing to check), or a program's folder whose
            # "may use" is a list (the command line): its sources are checked as a library's.
            program = re.fullmatch(r"dream::(\w+)", namespaces[0]) if len(namespaces) == 1 else None
            if program and len(folders) == 1 and cells[col["may use"]].strip() != "all":
                rows[folders[0].strip("/")] = Row(cells[col["floor"]], folders[0].strip("/"), program.group(1),
                                                   namespaces[0], set(), cell_words(cells[col["may use"]]), True)
            continue
        if len(folders) != 1 or len(own) != 1 or len(namespaces) != 1:
            raise SystemExit(f"FAIL: {doc_path}: row needs one `folder/`, one `dream/<name>/` and one `dream::<name>`: {line}")
        name = own.pop()
        floor_of[name] = cells[col["floor"]]
        rows[folders[0].strip("/")] = Row(cells[col["floor"]], folders[0].strip("/"), name, namespaces[0], targets,
                                           cell_words(cells[col["may use"]]))
    return floors, floor_of, rows


def row_violations(floors, floor_of, rows, read):
    """What a row itself breaks: its four names disagree, its folder is off its floor, its
    target is not defined in its folder, or it may use a library of a higher floor."""
    found = []
    for folder, row in rows.items():
        where = f"docs/architecture.md: {folder}/"
        if os.path.basename(folder) != row.own:
            found.append(f"{where}: the folder's name is not its include path's (dream/{row.own}/)")
        if row.namespace != f"dream::{row.own}":
            found.append(f"{where}: namespace {row.namespace} is not dream::{row.own}")
        if not row.program and row.own not in row.targets:
            found.append(f"{where}: CMake target is not dream::{row.own}")
        if row.floor not in floors or folder.split("/")[0] != row.floor:
            found.append(f"{where}: not on its floor {row.floor!r} (floors: {floors})")
        cmake = read(f"{folder}/CMakeLists.txt") or ""
        if not row.program and row.own not in TARGET_DEFINITION.findall(cmake):
            found.append(f"{folder}/CMakeLists.txt: defines no target dream_{row.own} (dream::{row.own})")
        for used in sorted(row.may_use):
            if used in floor_of and floor_of[used] in floors and row.floor in floors \
                    and floors.index(floor_of[used]) > floors.index(row.floor):
                found.append(f"{where}: may use {used}, of the higher floor {floor_of[used]}")
    return found


def cycles(rows):
    """Libraries that may use themselves through others (an arrow running back up, also
    inside a floor: agents -> kind_api -> <kind> -> agent_host), one line each."""
    uses = {row.own: row.may_use for row in rows.values()}
    found = []
    for start in sorted(uses):
        path, todo, seen = {start: [start]}, [start], set()
        while todo:
            name = todo.pop()
            for used in sorted(uses.get(name, ())):
                if used == start:
                    found.append(f"docs/architecture.md: {' -> '.join(path[name] + [start])}: the libraries use each other")
                    todo = []
                    break
                if used in uses and used not in seen:
                    seen.add(used)
                    path[used] = path[name] + [used]
                    todo.append(used)
    return found


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
        own, may_use = rows[folder].own, rows[folder].may_use
        text = read(path)
        for match in NAMESPACE_OPEN.finditer(text):
            opened, body = match.group(1), text[match.end():text.find("}", match.end())]
            if FORWARD_DECLARATIONS.fullmatch(body):
                continue  # `namespace dream::world { class World; }` declares, it does not define
            if opened != f"dream::{own}" and not opened.startswith(f"dream::{own}::"):
                found.append(f"{path}: opens namespace {opened}, but {folder}/ is dream::{own}")
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
    floors = ["low", "high"]
    rows = {"low/a": Row("low", "low/a", "a", "dream::a", {"a"}, {"b"}),
            "low/b": Row("low", "low/b", "b", "dream::b", {"b"}, set()),
            "low/c": Row("low", "low/c", "cc", "dream::c", {"c"}, {"h"}),     # four names disagree, uses up
            "high/d": Row("low", "high/d", "d", "dream::d", {"d"}, set()),    # off its floor
            "high/h": Row("high", "high/h", "h", "dream::h", {"h"}, {"a"}),
            "high/p": Row("high", "high/p", "p", "dream::p", set(), {"h"}, True)}  # a program: may use h only
    floor_of = {"a": "low", "b": "low", "cc": "low", "d": "low", "h": "high"}
    texts = {
        "low/a/src/x.cc": '#include "dream/a/x.h"\n#include "dream/b/y.h"\nnamespace dream::a {\nnamespace dream::a::detail {\n',
        "low/b/src/y.cc": '#include "dream/a/x.h"\n',                             # b may not use a
        "low/b/src/z.cc": "#include <lcm/lcm-cpp.hpp>\n",                         # nor LCM
        "low/b/src/t.cc": '#include "dream/robot_poses_t.hpp"\n',                 # nor msgs
        "low/b/src/n.cc": "namespace dream::a {\nint f();\n}\n",                   # nor open a's namespace
        "low/b/src/f.cc": "namespace dream::a {\nclass X;  // declared only\n}\n",  # (a declaration may)
        "high/p/src/main.cc": '#include "dream/h/h.h"\n#include "dream/a/x.h"\n',  # the program may not use a
        "lib/c/include/dream/c/c.h": "",                                          # not in the table
        "low/a/CMakeLists.txt": "dream_add_library(a\n", "low/b/CMakeLists.txt": "add_library(dream_b STATIC\n",
        "low/c/CMakeLists.txt": "dream_add_library(c\n", "high/d/CMakeLists.txt": "dream_add_library(d\n",
        "high/h/CMakeLists.txt": "dream_add_library(hh\n",                       # the wrong target
    }
    found = violations(rows, list(texts), texts.__getitem__) + row_violations(floors, floor_of, rows, texts.get)
    looped = {"x": Row("low", "low/x", "x", "dream::x", {"x"}, {"y"}), "y": Row("low", "low/y", "y", "dream::y", {"y"}, {"x"})}
    if not cycles(looped) or cycles(rows):
        raise SystemExit(f"FAIL: self test: x and y use each other, a and b do not ({cycles(looped)}, {cycles(rows)})")
    expected = ["low/b/src/y.cc:", "low/b/src/z.cc:", "low/b/src/t.cc:", "low/b/src/n.cc:", "lib/c/include/dream/c/c.h:",
                "docs/architecture.md: low/c/: the folder's name", "docs/architecture.md: low/c/: namespace",
                "docs/architecture.md: low/c/: CMake target", "docs/architecture.md: low/c/: may use h",
                "docs/architecture.md: high/d/: not on its floor", "high/h/CMakeLists.txt: defines no target",
                "high/p/src/main.cc: includes dream/a/"]
    for prefix in expected:
        if not any(line.startswith(prefix) for line in found):
            raise SystemExit(f"FAIL: self test: {prefix} breaks a rule but was not flagged ({found})")
    table = ["| low | `low/k/<kind>/` | `dream::<kind>` | `dream/<kind>/` | `dream::<kind>` | `b` | |",
             "| high | `high/h/` | `dream::h` | `dream/h/` | `dream::h` | `<kind>`, `a` | |"]
    expanded = expand_templates(table, lambda parent: ["p", "q"] if parent == "low/k" else [])
    if expanded != ["| low | `low/k/p/` | `dream::p` | `dream/p/` | `dream::p` | `b` | |",
                    "| low | `low/k/q/` | `dream::q` | `dream/q/` | `dream::q` | `b` | |",
                    "| high | `high/h/` | `dream::h` | `dream/h/` | `dream::h` | `p`, `q`, `a` | |"]:
        raise SystemExit(f"FAIL: self test: the template row `low/k/<kind>/` was not expanded per folder ({expanded})")
    import tempfile
    with tempfile.NamedTemporaryFile("w", suffix=".md", delete=False) as doc:
        doc.write("Floors, bottom up: `low`, `high`.\n\n| floor | folder | CMake target | include path | namespace | may use |\n"
                  "|---|---|---|---|---|---|\n| high | `high/p/` | `p` (program) | (no public headers) | `dream::p` | `h` |\n"
                  "| high | `high/q/` | `q` (program) | (no public headers) | `dream::q` | all |\n")
    try:
        _, _, read_rows = read_table(doc.name)
    finally:
        os.unlink(doc.name)
    if set(read_rows) != {"high/p"} or not read_rows["high/p"].program or read_rows["high/p"].may_use != {"h"}:
        raise SystemExit(f"FAIL: self test: a program's row with a 'may use' list was not read as one "
                         f"({ {k: vars(v) for k, v in read_rows.items()} })")
    if any(line.startswith(("low/a/", "low/b/src/f.cc", "docs/architecture.md: low/a/", "docs/architecture.md: low/b/",
                            "docs/architecture.md: high/p/", "high/p/CMakeLists.txt", "high/p/src/main.cc: includes dream/h/"))
           for line in found):
        raise SystemExit(f"FAIL: self test: low/a and low/b keep the rules but were flagged ({found})")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source", required=True, help="the repository's root")
    args = parser.parse_args()
    self_test()
    def subfolders(parent):
        folder = os.path.join(args.source, parent)
        return sorted(name for name in (os.listdir(folder) if os.path.isdir(folder) else [])
                      if os.path.isfile(os.path.join(folder, name, "CMakeLists.txt")))

    floors, floor_of, rows = read_table(os.path.join(args.source, "docs", "architecture.md"), subfolders)

    def read(path):
        full = os.path.join(args.source, path)
        if not os.path.isfile(full):
            return None
        with open(full, encoding="utf-8", errors="replace") as f:
            return f.read()

    found = violations(rows, tracked_files(args.source), read) + row_violations(floors, floor_of, rows, read) + cycles(rows)
    for line in found:
        print(line)
    if found:
        print(f"FAIL: {len(found)} breach(es) of docs/architecture.md's library table")
        return 1
    print(f"PASS: {len(rows)} libraries on {len(floors)} floors: names agree, includes and namespaces as "
          "docs/architecture.md allows")
    return 0


if __name__ == "__main__":
    sys.exit(main())
