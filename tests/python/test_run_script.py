#!/usr/bin/python3
"""python/rps_dream/run_script.py, the process `dream run SCRIPT.py` starts: a Python without numpy
(the python3 first on a newcomer's PATH, often) is named in one line with what to do, before any
traceback from deep in rps.
"""

import os
import subprocess
import sys
import tempfile
import unittest

from unit_setup import SOURCE_DIR

RUN_SCRIPT = os.path.join(SOURCE_DIR, "python", "rps_dream", "run_script.py")


class WithoutNumpyTest(unittest.TestCase):
    def test_a_python_without_numpy_is_named_with_what_to_do(self):
        with tempfile.TemporaryDirectory() as folder:
            # A numpy that cannot be imported stands for a Python that has none.
            os.makedirs(os.path.join(folder, "numpy"))
            with open(os.path.join(folder, "numpy", "__init__.py"), "w") as f:
                f.write("raise ImportError('No module named numpy')\n")
            script = os.path.join(folder, "s.py")
            with open(script, "w") as f:
                f.write("import rps.robotarium\n")
            env = dict(os.environ, PYTHONPATH=folder)
            env.pop("DREAM_SCRIPT_TERMINAL_FD", None)
            ran = subprocess.run([sys.executable, RUN_SCRIPT, script], env=env, capture_output=True, text=True,
                                 timeout=60)
        self.assertEqual(ran.returncode, 1, ran.stderr)
        self.assertEqual(ran.stderr.strip(),
                         f"dream run: {sys.executable} cannot import numpy (No module named numpy), which rps "
                         f"needs: install it for that Python, or name one that has it in DREAM_PYTHON (e.g. "
                         f"DREAM_PYTHON=/usr/bin/python3)")


if __name__ == "__main__":
    unittest.main()
