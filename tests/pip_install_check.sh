#!/bin/sh
# pip_install_check.sh [BUILD_DIR [SOURCE_DIR]]: docs/python.md's "Installing
# with pip", offline, with Debian's tools only.
#  - a copy of the source tree (without build folders and .git, so that the
#    tree is not written to) is installed with
#    `pip install --no-build-isolation --no-index` into a fresh venv of
#    Debian's interpreter (FLIPLAB_PYTHON, default /usr/bin/python3) made
#    with --system-site-packages (numpy, setuptools' wheel: Debian's);
#    setup.py builds libfliplab.so with cmake and ships it in the package;
#  - from another folder, without FLIPLAB_LIBRARY, the venv's python imports
#    fliplab from the venv, loads the library shipped in the package and
#    triangulates; py.typed is installed, the version is __version__;
#  - `pip wheel --no-build-isolation --no-deps` of the same copy gives a
#    py3-none-PLATFORM wheel holding the library and py.typed.
# Exit 77 (skipped, saying why) only when python3-venv, python3-pip,
# python3-setuptools or python3-wheel is missing.  The scratch folder is
# BUILD_DIR/testtmp/pip_install_check (a temporary one without BUILD_DIR),
# removed when the check passes.
set -eu
py=${FLIPLAB_PYTHON:-/usr/bin/python3}
here=$(cd "$(dirname "$0")" && pwd)
src=$(cd "${2:-$here/..}" && pwd)
if [ -n "${1:-}" ]; then
  tmp=$(cd "$1" && pwd)/testtmp/pip_install_check
  rm -rf "$tmp"
  mkdir -p "$tmp"
else
  tmp=$(mktemp -d)
fi
fail() { echo "pip_install_check: $* (scratch folder: $tmp)" >&2; exit 1; }
skip() { echo "pip_install_check: skipped: $*"; rm -rf "$tmp"; exit 77; }

"$py" -c 'import venv, ensurepip' 2>/dev/null || skip "$py has no venv/ensurepip (python3-venv)"
"$py" -m pip --version >/dev/null 2>&1 || skip "$py has no pip (python3-pip)"
"$py" -c 'import setuptools' 2>/dev/null || skip "$py has no setuptools (python3-setuptools)"
"$py" -c 'import wheel' 2>/dev/null || skip "$py has no wheel (python3-wheel)"
"$py" -c 'import numpy' 2>/dev/null || fail "$py has no numpy (python3-numpy)"

# The tree as it is, build folders, .git and bytecode left out.
mkdir "$tmp/src"
# A build folder of any name (one holding CMakeCache.txt) is left out too:
# the scratch folder lies inside the build folder, which may lie in the tree.
(cd "$src" && tar -cf - --exclude='./build*' --exclude-tag-all=CMakeCache.txt --exclude=./.git \
   --exclude=__pycache__ --exclude=./testtmp --exclude=./dist --exclude='*.egg-info' .) |
  tar -xf - -C "$tmp/src" ||
  fail "cannot copy $src"

"$py" -m venv --system-site-packages "$tmp/venv" > "$tmp/venv.log" 2>&1 ||
  { cat "$tmp/venv.log" >&2; fail "python3 -m venv failed"; }
vpy=$tmp/venv/bin/python
export PIP_DISABLE_PIP_VERSION_CHECK=1 PIP_NO_CACHE_DIR=1 PIP_NO_INPUT=1 PYTHONDONTWRITEBYTECODE=1
unset FLIPLAB_LIBRARY PYTHONPATH PIP_INDEX_URL PIP_EXTRA_INDEX_URL PIP_FIND_LINKS || true
(cd "$tmp" && "$vpy" -m pip install --no-build-isolation --no-index "$tmp/src") \
  > "$tmp/install.log" 2>&1 || { tail -n 40 "$tmp/install.log" >&2; fail "pip install failed"; }

# From a folder that is neither tree: the venv's package, its own library.
mkdir "$tmp/elsewhere"
(cd "$tmp/elsewhere" && "$vpy" -c "import fliplab; t = fliplab.lot(fliplab.samplers.points(100,'uniform',seed=1),'DT'); assert len(t.triangles) > 0") ||
  fail "the pip-installed package does not triangulate"
(cd "$tmp/elsewhere" && "$vpy" -c '
import os, sys, importlib.metadata as md, fliplab
pkg = os.path.dirname(fliplab.__file__)
assert pkg.startswith(sys.prefix + os.sep), "fliplab imported from %s, not the venv" % pkg
assert fliplab.library_path == os.path.join(pkg, fliplab._lib.SONAME), fliplab.library_path
assert os.path.isfile(os.path.join(pkg, "py.typed")), "no py.typed"
from fliplab import explorer
assert explorer.web_dir() == os.path.join(pkg, "web"), explorer.web_dir()
assert md.version("fliplab") == fliplab.__version__, (md.version("fliplab"), fliplab.__version__)
t = fliplab.lot(fliplab.samplers.points(100, "uniform", seed=1), "P_1", check=True)
assert t.status == "converged" and len(t.triangles) == 2 * 100 - len(t.hull) - 2
') || fail "the pip-installed package is not what docs/python.md says"

# The wheel, from the same copy (cmake's tree in build-pip/ is reused).
(cd "$tmp" && "$vpy" -m pip wheel --no-build-isolation --no-deps -w "$tmp/wheels" "$tmp/src") \
  > "$tmp/wheel.log" 2>&1 || { tail -n 40 "$tmp/wheel.log" >&2; fail "pip wheel failed"; }
"$vpy" - "$tmp/wheels" <<'EOF' || fail "the wheel is not what docs/python.md says"
import os, sys, zipfile
import fliplab
(name,) = os.listdir(sys.argv[1])
want = "fliplab-%s-py3-none-" % fliplab.__version__
assert name.startswith(want) and name.endswith(".whl") and "linux" in name, name
names = zipfile.ZipFile(os.path.join(sys.argv[1], name)).namelist()
for f in ("fliplab/__init__.py", "fliplab/_lib.py", "fliplab/py.typed",
          "fliplab/" + fliplab._lib.SONAME, "fliplab/web/index.html", "fliplab/web/explorer.js"):
    assert f in names, (f, name)
assert not any(n.startswith(("tests/", "fliplab/tests/")) for n in names), names
EOF
rm -rf "$tmp"
echo "pip_install_check: ok"
