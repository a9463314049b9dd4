"""What a Robotarium script imports, and what of it the Robotarium lacks: `dream export SCRIPT.py`.

python3 -I check_imports.py SCRIPT [LIBRARIES_TXT]

Reads SCRIPT's import statements (Python's own parser: every `import X` and `from X import ...`,
also inside functions and `try`; relative imports and `__import__` calls are not imports of a
package) and prints one JSON object: {"imports": [top-level names], "not_on_robotarium": [names]}.
On the Robotarium are Python's standard library, `rps` (the official simulator's package) and the
packages of the official simulator's libraries.txt (LIBRARIES_TXT, "name==version" per line, the
distribution names mapped to what they are imported as); without LIBRARIES_TXT, the simulator's
own requirements: numpy, scipy, matplotlib, cvxopt. A script that cannot be parsed exits 1 with
Python's message naming the line.
"""

import ast
import json
import sys

# Distributions whose import name is not their name (libraries.txt lists distributions).
IMPORTED_AS = {"opencv-python": "cv2", "pillow": "PIL", "scikit-learn": "sklearn", "pyyaml": "yaml",
               "python-dateutil": "dateutil", "gtsam-develop": "gtsam", "pyocclient": "owncloud",
               "typing_extensions": "typing_extensions", "importlib_metadata": "importlib_metadata"}
REQUIRED = ("numpy", "scipy", "matplotlib", "cvxopt")


def available(libraries_path):
    names = {"rps"} | set(sys.stdlib_module_names)
    if not libraries_path:
        return names | set(REQUIRED)
    with open(libraries_path, encoding="utf-8") as f:
        for line in f:
            distribution = line.split("==")[0].strip().lower()
            if distribution and not distribution.startswith("#"):
                names.add(IMPORTED_AS.get(distribution, distribution.replace("-", "_")))
    return names


def imports_of(path):
    with open(path, "rb") as f:
        tree = ast.parse(f.read(), filename=path)
    found = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found += [alias.name.split(".")[0] for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.level == 0 and node.module:
            found.append(node.module.split(".")[0])
    return sorted(set(found))


def main():
    if len(sys.argv) not in (2, 3):
        print(__doc__, file=sys.stderr)
        return 2
    try:
        found = imports_of(sys.argv[1])
    except (OSError, SyntaxError, ValueError) as error:
        print(f"{sys.argv[1]}: {error}", file=sys.stderr)
        return 1
    on_robotarium = available(sys.argv[2] if len(sys.argv) == 3 else "")
    print(json.dumps({"imports": found, "not_on_robotarium": [name for name in found if name not in on_robotarium]}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
