#!/usr/bin/python3
"""code_size: no C++ function over 80 lines and no C++ file over 500 lines, outside a reviewed list.

Size creeps one commit at a time; this check notices (issue 24). It covers the libraries and
programs (lcmtypes/, base/, agents/, sim/, bridge/, app/), not tests/. Functions are found by
Universal Ctags (their first and last line); a function's size is its lines from the signature to
the closing brace.

The exceptions live in code_size_exceptions.txt beside this script, one per line:
    <path>                 <max lines>  # why it may be this long
    <path>::<function>     <max lines>  # why
An exception allows up to its number, no more (so an excepted function cannot keep growing), and an
exception that is no longer needed fails the check too (so the list only shrinks).

Before the sources, the checker must flag a made-up long function and file, so a checker that
accepts everything fails here.

Usage: code_size.py --source DIR
"""

import argparse
import json
import os
import re
import shutil
import subprocess
import sys

MAX_FUNCTION_LINES = 80
MAX_FILE_LINES = 500
CHECKED_FOLDERS = ("lcmtypes/", "base/", "agents/", "sim/", "bridge/", "app/")
EXCEPTION_LINE = re.compile(r"^(\S+)\s+(\d+)\s*(#.*)?$")


def read_exceptions(path):
    exceptions = {}
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            match = EXCEPTION_LINE.match(line)
            if not match or not match.group(3):
                raise SystemExit(f"FAIL: {path}:{number}: want '<path>[::<function>] <max lines>  # why', got: {line}")
            exceptions[match.group(1)] = int(match.group(2))
    return exceptions


def function_sizes(source, paths):
    """(path, qualified name, first line, lines) of every function defined in `paths`."""
    if not paths:
        return []
    listed = subprocess.run(["ctags", "--output-format=json", "--fields=+neK", "--c++-kinds=f", "--language-force=C++",
                             "-f", "-"] + paths, cwd=source, stdout=subprocess.PIPE, text=True, check=True)
    sizes = []
    for line in listed.stdout.splitlines():
        tag = json.loads(line)
        if "end" not in tag:
            continue
        scope = tag.get("scope", "")
        scope = re.sub(r"(^|::)__anon\w+", r"\1(anonymous)", scope)
        name = tag["name"] if not scope else f"{scope}::{tag['name']}"
        sizes.append((tag["path"], name, tag["line"], tag["end"] - tag["line"] + 1))
    return sizes


def breaches(source, paths, exceptions, read_lines):
    """What is too long and not excepted, and exceptions nothing needs, one line each."""
    found, used = [], set()
    for path in paths:
        lines = read_lines(path)
        allowed = exceptions.get(path, MAX_FILE_LINES)
        if lines > MAX_FILE_LINES:
            used.add(path)
        if lines > allowed:
            found.append(f"{path}: {lines} lines (at most {allowed}): split it by what its parts do")
    for path, name, first, lines in function_sizes(source, paths):
        short_name = name.split("::")[-1]
        key = next((k for k in (f"{path}::{name}", f"{path}::{short_name}") if k in exceptions), None)
        allowed = exceptions[key] if key else MAX_FUNCTION_LINES
        if lines > MAX_FUNCTION_LINES and key:
            used.add(key)
        if lines > allowed:
            found.append(f"{path}:{first}: {name} has {lines} lines (at most {allowed}): split it into steps with names")
    for key in sorted(set(exceptions) - used):
        if key.split("::")[0] in paths:
            found.append(f"code_size_exceptions.txt: {key} is within the limits now: remove its exception")
    return found


def self_test(source):
    """A made-up long function and file must be flagged, a short one not."""
    import tempfile
    with tempfile.TemporaryDirectory() as scratch:
        long_body = "\n".join(f"  x += {i};" for i in range(MAX_FUNCTION_LINES))
        texts = {
            "app/long_function.cc": "int Long(int x) {\n" + long_body + "\n  return x;\n}\n",
            "app/long_file.cc": "\n".join(f"int v{i} = {i};" for i in range(MAX_FILE_LINES + 1)) + "\n",
            "app/short.cc": "int Short(int x) {\n  return x + 1;\n}\n",
        }
        for path, text in texts.items():
            os.makedirs(os.path.join(scratch, os.path.dirname(path)), exist_ok=True)
            with open(os.path.join(scratch, path), "w", encoding="utf-8") as f:
                f.write(text)
        found = breaches(scratch, sorted(texts), {"app/short.cc::Short": 10},
                         lambda p: texts[p].count("\n"))
        for expected in ("app/long_function.cc:1: Long", "app/long_file.cc:", "code_size_exceptions.txt: app/short.cc::Short"):
            if not any(line.startswith(expected) for line in found):
                raise SystemExit(f"FAIL: self test: {expected} was not flagged ({found})")
        if any(line.startswith("app/short.cc:") for line in found):
            raise SystemExit(f"FAIL: self test: app/short.cc keeps the limits but was flagged ({found})")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source", required=True, help="the repository's root")
    args = parser.parse_args()
    if shutil.which("ctags") is None:
        raise SystemExit("FAIL: ctags not found: apt-get install universal-ctags (.ci/debian-packages.txt)")
    self_test(args.source)
    listed = subprocess.run(["git", "-C", args.source, "ls-files"], stdout=subprocess.PIPE, text=True, check=True)
    paths = [p for p in listed.stdout.splitlines()
             if p.startswith(CHECKED_FOLDERS) and p.endswith((".h", ".cc")) and os.path.isfile(os.path.join(args.source, p))]
    exceptions = read_exceptions(os.path.join(os.path.dirname(os.path.abspath(__file__)), "code_size_exceptions.txt"))

    def read_lines(path):
        with open(os.path.join(args.source, path), encoding="utf-8", errors="replace") as f:
            return sum(1 for _ in f)

    found = breaches(args.source, paths, exceptions, read_lines)
    for line in found:
        print(line)
    if found:
        print(f"FAIL: {len(found)} size breach(es); limits {MAX_FUNCTION_LINES} lines per function, "
              f"{MAX_FILE_LINES} per file (tests/architecture/code_size.py)")
        return 1
    print(f"PASS: {len(paths)} files within {MAX_FILE_LINES} lines and their functions within {MAX_FUNCTION_LINES}, "
          f"{len(exceptions)} reviewed exception(s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
