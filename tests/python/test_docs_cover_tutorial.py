#!/usr/bin/python3
"""Every method of the dream runtime that docs/tutorial.md's controller calls is documented in
docs/python-controllers.md, the page the tutorial sends its reader to for the API (issue 25:
`HrvoAvoidance.solve` and `relative_position()` were used and nowhere described)."""

import ast
import os
import re
import unittest

SOURCE = os.environ.get("DREAM_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))


def read(relative):
    with open(os.path.join(SOURCE, relative), encoding="utf-8") as f:
        return f.read()


def runtime_methods():
    """The public methods and functions defined in python/dream/*.py."""
    names = set()
    folder = os.path.join(SOURCE, "python", "dream")
    for name in sorted(os.listdir(folder)):
        if name.endswith(".py"):
            for node in ast.walk(ast.parse(read(os.path.join("python", "dream", name)))):
                if isinstance(node, ast.FunctionDef) and not node.name.startswith("_"):
                    names.add(node.name)
    return names


def tutorial_calls():
    """The names the tutorial's Python blocks call as attributes (x.name(...))."""
    calls = set()
    for block in re.findall(r"```python\n(.*?)```", read("docs/tutorial.md"), re.DOTALL):
        for node in ast.walk(ast.parse(block)):
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Attribute):
                calls.add(node.func.attr)
    return calls


class DocsCoverTutorial(unittest.TestCase):
    def test_every_runtime_method_the_tutorial_calls_is_documented(self):
        calls = tutorial_calls() & runtime_methods()
        self.assertIn("solve", calls)  # the tutorial's own controller: the check looks at it
        reference = read("docs/python-controllers.md")
        missing = sorted(name for name in calls if not re.search(r"\b" + re.escape(name) + r"\(", reference))
        self.assertEqual(missing, [], "docs/python-controllers.md does not describe these, which docs/tutorial.md "
                                      "calls: " + ", ".join(missing))


if __name__ == "__main__":
    unittest.main()
