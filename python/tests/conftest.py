"""conftest.py: how the Python tests find the library and the program.

Run by ctest (tests/CMakeLists.txt: python_tests) with FLIPLAB_LIBRARY (the
build's libfliplab.so), FLIPLAB_BIN (the build's fliplab), FLIPLAB_LAYOUT
(the build's python/fliplab_py_layout, for test_layout.py) and PYTHONPATH
(python/) set.  By hand, from the repository, with Debian's interpreter:
    FLIPLAB_LIBRARY=build/libfliplab.so FLIPLAB_BIN=build/fliplab \\
        FLIPLAB_LAYOUT=build/python/fliplab_py_layout \\
        PYTHONPATH=python /usr/bin/python3 -m pytest python/tests
"""
import csv
import io
import os
import subprocess

import numpy as np
import pytest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def _bin():
    b = os.environ.get("FLIPLAB_BIN", os.path.join(ROOT, "build", "fliplab"))
    if not os.path.exists(b):
        pytest.skip("the fliplab program is not built (set FLIPLAB_BIN)")
    return b


class Cli:
    """The built program: run(args) -> CompletedProcess (text), csv rows."""

    def __init__(self, path, tmp):
        self.path = path
        self.tmp = tmp

    def run(self, *args, ok=True):
        p = subprocess.run([self.path] + [str(a) for a in args], capture_output=True, text=True)
        if ok and p.returncode != 0:
            raise AssertionError("fliplab %s: exit %d: %s" % (" ".join(map(str, args)),
                                                            p.returncode, p.stderr))
        return p

    def file(self, name):
        return os.path.join(self.tmp, name)

    def rows(self, name):
        with open(self.file(name), newline="") as f:
            return list(csv.reader(f))


@pytest.fixture
def cli(tmp_path):
    return Cli(_bin(), str(tmp_path))


def write_points(path, p):
    with open(path, "w") as f:
        f.write("x,y\n")
        for x, y in p:
            f.write("%r,%r\n" % (float(x), float(y)))


def stdout_field(text, key):
    """The value after 'key: ' on the program's standard output."""
    for line in text.splitlines():
        if line.startswith(key + ": "):
            return line[len(key) + 2:]
    raise AssertionError("no '%s:' line in:\n%s" % (key, text))


# hypothesis: the same examples on every run (CI), no example database in
# the build tree, no per-example deadline (the machine is shared).
try:
    from hypothesis import settings
    settings.register_profile("fliplab", derandomize=True, database=None, deadline=None,
                              max_examples=60)
    settings.load_profile("fliplab")
except ImportError:
    pass
