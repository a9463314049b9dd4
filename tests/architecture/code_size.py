#!/usr/bin/python3
"""code_size: no function over 80 lines and no file over 500 lines, C++ or Python, outside a reviewed list.

Size creeps one commit at a time; this check notices (issue 24; Python since issue 35). It covers
the libraries and programs, not tests/:
- C++ (.h, .cc) in lcmtypes/, base/, agents/, sim/, bridge/, app/. Functions are found by Universal
  Ctags (their first and last line); a function's size is its lines from the signature to the
  closing brace.
- Python (.py) in the same folders and in python/ (the controller runtime, dream_log.py) and
  config/ (the example controllers): what ships, to users or to the lab (bridge/python: the
  submission template, its runner and the stand-in simulator). Functions and methods are found by
  Python's own parser (ast); a function's size is its lines from `def` to its body's last line,
  nested functions included (a nested function is also checked on its own). A file that does not
  parse is a breach, named with its line.
  The tests' Python drivers (tests/**.py) are scripts of scenarios, like the C++ tests not checked.

The exceptions live in code_size_exceptions.txt beside this script, one per line:
    <path>                 <max lines>  # why it may be this long
    <path>::<function>     <max lines>  # why (C++: `Class::Method`; Python: `Class.method`, or
                                        # the bare name for either)
An exception allows up to its number, no more (so an excepted function cannot keep growing), and an
exception that is no longer needed fails the check too (so the list only shrinks).

Before the sources, the checker must flag a made-up long function and file in each language, so a
checker that accepts everything fails here.

Usage: code_size.py --source DIR
"""

import argparse
import ast
import json
import os
import re
import shutil
import subprocess
import sys

MAX_FUNCTION_LINES = 80
MAX_FILE_LINES = 500
CHECKED_FOLDERS = ("lcmtypes/", "base/", "agents/", "sim/", "bridge/", "app/")
CPP_SUFFIXES = (".h", ".cc")
# Python that ships lives in the C++ folders (bridge/python/, agents/hrvo/reference/) and in these two.
PYTHON_FOLDERS = CHECKED_FOLDERS + ("python/", "config/")
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


def cpp_function_sizes(source, paths):
    """(path, qualified name, first line, lines) of every C++ function defined in `paths`."""
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


class PythonParseError(Exception):
    """A checked .py file that Python's parser refuses: a breach, named with its line."""


def python_function_sizes(source, path):
    """(path, qualified name, first line, lines) of every function and method in the Python file
    `path`, named as Python's __qualname__ is without `<locals>` (`Class.method`, `outer.inner`)."""
    with open(os.path.join(source, path), encoding="utf-8", errors="replace") as f:
        text = f.read()
    try:
        tree = ast.parse(text, filename=path)
    except (SyntaxError, ValueError) as error:
        raise PythonParseError(f"{path}:{getattr(error, 'lineno', None) or 1}: does not parse as Python: "
                               f"{getattr(error, 'msg', error)}") from None
    sizes = []

    def visit(node, scope):
        for child in ast.iter_child_nodes(node):
            if isinstance(child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
                name = f"{scope}{child.name}"
                if not isinstance(child, ast.ClassDef):
                    sizes.append((path, name, child.lineno, child.end_lineno - child.lineno + 1))
                visit(child, name + ".")
            else:
                visit(child, scope)

    visit(tree, "")
    return sizes


def function_sizes(source, paths):
    """(path, qualified name, first line, lines) of every function in `paths`, C++ and Python, and
    the Python files that do not parse (one line each)."""
    sizes = cpp_function_sizes(source, [p for p in paths if p.endswith(CPP_SUFFIXES)])
    unparsed = []
    for path in (p for p in paths if p.endswith(".py")):
        try:
            sizes += python_function_sizes(source, path)
        except PythonParseError as error:
            unparsed.append(str(error))
    return sizes, unparsed


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
    sizes, found_unparsed = function_sizes(source, paths)
    found += found_unparsed
    for path, name, first, lines in sizes:
        short_name = re.split(r"::|\.", name)[-1]
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
    """A made-up long function and file must be flagged, in C++ and in Python, a short one not."""
    import tempfile
    with tempfile.TemporaryDirectory() as scratch:
        long_body = "\n".join(f"  x += {i};" for i in range(MAX_FUNCTION_LINES))
        long_python_body = "\n".join(f"        x += {i}" for i in range(MAX_FUNCTION_LINES))
        texts = {
            "app/long_function.cc": "int Long(int x) {\n" + long_body + "\n  return x;\n}\n",
            "app/long_file.cc": "\n".join(f"int v{i} = {i};" for i in range(MAX_FILE_LINES + 1)) + "\n",
            "app/short.cc": "int Short(int x) {\n  return x + 1;\n}\n",
            "python/long_method.py": "class Walker:\n    @staticmethod\n    def walk(x):\n" + long_python_body + "\n"
                                     "        return x\n",
            "python/long_file.py": "\n".join(f"v{i} = {i}" for i in range(MAX_FILE_LINES + 1)) + "\n",
            "python/short.py": "def short(x):\n    def inner(y):\n        return y\n    return inner(x) + 1\n",
            "python/broken.py": "def broken(:\n    pass\n",
        }
        for path, text in texts.items():
            os.makedirs(os.path.join(scratch, os.path.dirname(path)), exist_ok=True)
            with open(os.path.join(scratch, path), "w", encoding="utf-8") as f:
                f.write(text)
        found = breaches(scratch, sorted(texts), {"app/short.cc::Short": 10, "python/short.py::short.inner": 10},
                         lambda p: texts[p].count("\n"))
        for expected in ("app/long_function.cc:1: Long", "app/long_file.cc:",
                         "code_size_exceptions.txt: app/short.cc::Short",
                         f"python/long_method.py:3: Walker.walk has {MAX_FUNCTION_LINES + 2} lines",
                         "python/long_file.py:", "code_size_exceptions.txt: python/short.py::short.inner",
                         "python/broken.py:1: does not parse as Python"):
            if not any(line.startswith(expected) for line in found):
                raise SystemExit(f"FAIL: self test: {expected} was not flagged ({found})")
        if any(line.startswith(("app/short.cc:", "python/short.py:")) for line in found):
            raise SystemExit(f"FAIL: self test: app/short.cc and python/short.py keep the limits but were flagged "
                             f"({found})")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--source", required=True, help="the repository's root")
    args = parser.parse_args()
    if shutil.which("ctags") is None:
        raise SystemExit("FAIL: ctags not found: apt-get install universal-ctags (.ci/debian-packages.txt)")
    self_test(args.source)
    listed = subprocess.run(["git", "-C", args.source, "ls-files"], stdout=subprocess.PIPE, text=True, check=True)
    paths = [p for p in listed.stdout.splitlines()
             if ((p.startswith(CHECKED_FOLDERS) and p.endswith(CPP_SUFFIXES))
                 or (p.startswith(PYTHON_FOLDERS) and p.endswith(".py")))
             and os.path.isfile(os.path.join(args.source, p))]
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
    python_files = sum(1 for p in paths if p.endswith(".py"))
    print(f"PASS: {len(paths) - python_files} C++ and {python_files} Python files within {MAX_FILE_LINES} lines "
          f"and their functions within {MAX_FUNCTION_LINES}, "
          f"{len(exceptions)} reviewed exception(s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
