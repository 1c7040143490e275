"""run.py: ctest's python_tests: pytest over python/tests, or exit 77
(ctest's skip) with a message when the interpreter has no numpy (then the
package cannot work at all).  Every other missing piece (pytest,
hypothesis, scipy, matplotlib) is a failure: scripts/deps installs them."""
import os
import sys

try:
    import numpy  # noqa: F401
except ImportError:
    print("python_tests: skipped: %s has no numpy (apt-get install python3-numpy; "
          "scripts/deps installs it)" % sys.executable)
    sys.exit(77)
import pytest

here = os.path.dirname(os.path.abspath(__file__))
sys.exit(pytest.main(["-q", "-p", "no:cacheprovider", here] + sys.argv[1:]))
