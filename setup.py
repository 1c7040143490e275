"""setup.py: the build step of pyproject.toml that setuptools cannot say in
TOML.  The package is pure Python over libfliplab.so (ctypes), so the one
thing to compile is that library: build_py configures this tree with cmake
(no tests, no benchmarks, Release) in setuptools' temporary folder, builds
the target fliplab_shared and copies the library into the built package as
fliplab/libfliplab.so.0.1 (_lib.SONAME), where _lib._find() looks after
FLIPLAB_LIBRARY and a cmake --install's _install.py.  The wheel is then
specific to the platform (it holds machine code) but not to the Python
version or ABI (nothing is linked against Python): py3-none-PLATFORM.

Everything setuptools writes stays in build-pip/ (gitignored by build*/):
the build tree, the temporary cmake tree and the egg-info; build/ is left to
cmake.  FLIPLAB_CMAKE_ARGS adds arguments to the cmake configuration (e.g.
"-DCMAKE_C_COMPILER=clang"); CMAKE_BUILD_PARALLEL_LEVEL sets the build's
jobs (default: the number of processors).  docs/python.md, "Installing with
pip".
"""
import os
import re
import shlex
import shutil

from setuptools import Distribution as _Distribution, setup
from setuptools.command.build_py import build_py as _build_py

try:   # setuptools >= 70.1 has its own; before, the wheel package's
    from setuptools.command.bdist_wheel import bdist_wheel as _bdist_wheel
except ImportError:
    try:
        from wheel.bdist_wheel import bdist_wheel as _bdist_wheel
    except ImportError:
        _bdist_wheel = None

HERE = os.path.dirname(os.path.abspath(__file__))
BUILD_BASE = "build-pip"
WEB_FILES = ("index.html", "explorer.js", "explorer.css")   # the explorer's page


def _grep(path, pattern):
    """The first group of the first match of pattern in the file path (of this tree)."""
    with open(os.path.join(HERE, path), encoding="utf-8") as f:
        m = re.search(pattern, f.read(), re.M)
    if not m:
        raise SystemExit("fliplab setup.py: %s has no line matching %r" % (path, pattern))
    return m.group(1)


SONAME = _grep("python/fliplab/_lib.py", r'^SONAME = "([^"]+)"')
VERSION = _grep("python/fliplab/__init__.py", r'^__version__ = "([^"]+)"')
CMAKE_VERSION = _grep("CMakeLists.txt", r"^project\(fliplab VERSION ([0-9.]+)")
if VERSION != CMAKE_VERSION:
    raise SystemExit("fliplab setup.py: python/fliplab/__init__.py's __version__ %s differs "
                     "from CMakeLists.txt's project version %s" % (VERSION, CMAKE_VERSION))


class build_py(_build_py):
    """build_py, then libfliplab.so built by cmake and copied into the package."""

    def run(self):
        super().run()
        self.build_library()
        self.copy_web()

    def copy_web(self):
        """The explorer's page (web/) into the package as fliplab/web, where
        fliplab.explorer serves it from (docs/explorer.md)."""
        for name in WEB_FILES:
            out = os.path.join(self.build_lib, "fliplab", "web", name)
            self.mkpath(os.path.dirname(out))
            self.copy_file(os.path.join(HERE, "web", name), out)

    def library_output(self):
        return os.path.join(self.build_lib, "fliplab", SONAME)

    def build_library(self):
        cmake = shutil.which(os.environ.get("CMAKE", "cmake"))
        if not cmake:
            raise SystemExit("fliplab setup.py: cmake not found (Debian: apt-get install "
                             "cmake build-essential; scripts/deps installs what the build needs)")
        tree = os.path.join(self.get_finalized_command("build").build_temp, "cmake")
        self.spawn([cmake, "-S", HERE, "-B", tree, "-DFLIPLAB_TESTS=OFF", "-DFLIPLAB_BENCH=OFF",
                    "-DCMAKE_BUILD_TYPE=Release"]
                   + shlex.split(os.environ.get("FLIPLAB_CMAKE_ARGS", "")))
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL") or str(os.cpu_count() or 1)
        self.spawn([cmake, "--build", tree, "--target", "fliplab_shared", "-j", jobs])
        built = os.path.realpath(os.path.join(tree, SONAME))   # -> libfliplab.so.VERSION
        if not os.path.isfile(built):
            raise SystemExit("fliplab setup.py: cmake built no %s in %s" % (SONAME, tree))
        out = self.library_output()
        self.mkpath(os.path.dirname(out))
        self.copy_file(built, out, preserve_mode=True)

    def get_outputs(self, include_bytecode=1):
        return super().get_outputs(include_bytecode) + [self.library_output()] + [
            os.path.join(self.build_lib, "fliplab", "web", n) for n in WEB_FILES]


class Distribution(_Distribution):
    """A distribution with machine code (libfliplab.so): installed into platlib,
    its wheel specific to the platform."""

    def has_ext_modules(self):
        return True


cmdclass = {"build_py": build_py}
if _bdist_wheel is not None:
    class bdist_wheel(_bdist_wheel):
        """A platform wheel (it holds libfliplab.so) for any Python 3: py3-none-PLATFORM."""

        def get_tag(self):
            return ("py3", "none") + tuple(super().get_tag()[2:])

    cmdclass["bdist_wheel"] = bdist_wheel

os.makedirs(os.path.join(HERE, BUILD_BASE), exist_ok=True)
setup(distclass=Distribution, cmdclass=cmdclass,
      options={"build": {"build_base": BUILD_BASE}, "egg_info": {"egg_base": BUILD_BASE}})
