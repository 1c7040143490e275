#!/bin/sh
# install_check.sh BUILD_DIR SOURCE_DIR: what docs/api.md (the C API)
# promises, checked on an installed copy (`cmake --install` into a scratch
# prefix):
#  - only public headers are installed, and each compiles on its own;
#  - the shared library is installed beside the static one, with its SONAME,
#    and exports only what the installed headers declare (nm -D);
#  - docs/api.md's example program builds through plain pkg-config (the
#    shared library), through pkg-config --static, and through
#    find_package(fliplab) with both fliplab::fliplab (static) and
#    fliplab::fliplab_shared, runs, and prints exactly the output docs/api.md
#    shows;
#  - docs/api.md's plugin build line works and the installed program loads
#    the plugin;
#  - the Python package, installed under the prefix, loads in a fresh
#    interpreter (FLIPLAB_PYTHON, Debian's) from there with the installed
#    library, not the build tree's.
set -eu
# The compiler the library was built with (a clang-built libfliplab needs
# clang's OpenMP runtime): CC from ctest, else cc.
cc=${CC:-cc}
build=$(cd "$1" && pwd)
src=$(cd "$2" && pwd)
tmp=$build/testtmp/install_check
prefix=$tmp/prefix
rm -rf "$tmp"
mkdir -p "$tmp"
cmake --install "$build" --prefix "$prefix" >/dev/null
test -x "$prefix/bin/fliplab"
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
export PATH="$prefix/bin:$PATH"
fail() { echo "install_check: $*" >&2; exit 1; }

# Headers: no private ones (CMakeLists.txt: *_internal.h and fliplab_private_headers),
# nothing but headers, each compiles alone.
for f in "$prefix"/include/fliplab/*; do
  h=$(basename "$f")
  case $h in
    *_internal.h|mesh.h|order.h) fail "private header installed: $h" ;;
    *.h) ;;
    *) fail "not a header in include/fliplab: $h" ;;
  esac
  printf '#include <fliplab/%s>\n#include <fliplab/%s>\nint fliplab_header_check;\n' "$h" "$h" |
    "$cc" -std=c11 -Wall -Wextra -Wpedantic -Werror -fsyntax-only -x c - \
      $(pkg-config --cflags fliplab) || fail "<fliplab/$h> does not compile on its own"
done
test -z "$(find "$prefix/include" -type d -empty)" || fail "empty folder installed"
# The documentation the headers point to (docs/*.md) is installed with them.
for ref in $(grep -ho 'docs/[A-Za-z0-9_-]*\.md' "$prefix"/include/fliplab/*.h | sort -u); do
  test -f "$prefix/share/doc/fliplab/${ref#docs/}" || fail "$ref named in a header, not installed"
done
pkg-config --cflags fliplab | grep -q -- -fopenmp && fail "-fopenmp in Cflags"

# The shared library: libfliplab.so -> libfliplab.so.MAJOR.MINOR (the SONAME)
# -> libfliplab.so.VERSION, beside libfliplab.a.  Every symbol it exports is
# a name of an installed header (what *_internal.h declares is hidden,
# FLIPLAB_INTERNAL).  Names that are not C identifiers are the compilers'
# own (gcc's NAME.resolver of a target_clones function, clang's
# .gomp_critical_user_.reduction.var of an OpenMP reduction): nothing a
# user can call or clash with, left out.
lib=$prefix/lib
test -f "$lib/libfliplab.a" || fail "libfliplab.a not installed"
soname=$(readelf -d "$lib/libfliplab.so" | sed -n 's/.*(SONAME).*\[\(.*\)\]/\1/p')
case $soname in
  libfliplab.so.[0-9]*.[0-9]*) ;;
  *) fail "libfliplab.so: SONAME '$soname', expected libfliplab.so.MAJOR.MINOR" ;;
esac
test -e "$lib/$soname" || fail "$soname (the SONAME) not installed"
cat "$prefix"/include/fliplab/*.h | grep -o '[A-Za-z_][A-Za-z0-9_]*' | sort -u > "$tmp/idents.txt"
nm -D --defined-only "$lib/libfliplab.so" | awk '{print $3}' | grep -E '^[A-Za-z_][A-Za-z0-9_]*$' |
  sort -u > "$tmp/exported.txt"
test -s "$tmp/exported.txt" || fail "libfliplab.so exports nothing"
comm -23 "$tmp/exported.txt" "$tmp/idents.txt" > "$tmp/unexpected.txt"
test -s "$tmp/unexpected.txt" &&
  fail "libfliplab.so exports names no installed header declares: $(tr '\n' ' ' < "$tmp/unexpected.txt")"
for f in geom_tri_make rule_parse lot_build got_solve flipgraph_tally plugin_load; do
  grep -qx "$f" "$tmp/exported.txt" || fail "libfliplab.so does not export $f"
done
# needs FILE SONAME: the program loads that library (yes or no).
needs() { readelf -d "$1" | grep -q "(NEEDED).*\[$2\]"; }

# docs/api.md's blocks: the fenced block after a marker, or its indented lines.
block() {
  awk -v m="<!-- $1" 'index($0, m) == 1 {on = 1; next}
    on == 1 && /^```/ {on = 2; next}
    on == 2 && /^```/ {exit}
    on == 2 {print}' "$src/docs/api.md"
}
indented() {
  awk -v m="<!-- $1" 'index($0, m) == 1 {on = 1; next}
    on && /^    / {print substr($0, 5); seen = 1; next}
    on && seen {exit}' "$src/docs/api.md"
}
block api-example > "$tmp/example.c"
block api-example-output > "$tmp/expected.txt"
test -s "$tmp/example.c" && test -s "$tmp/expected.txt" || fail "docs/api.md example not found"

# Through pkg-config: plainly (docs/api.md's line, the shared library, found at
# run time through LD_LIBRARY_PATH as docs/api.md says), and with --static.
"$cc" -std=c11 -Wall -Wextra -Wpedantic -Werror "$tmp/example.c" \
   $(pkg-config --cflags --libs fliplab) -o "$tmp/example_pc"
needs "$tmp/example_pc" "$soname" || fail "pkg-config --libs: not linked to $soname"
LD_LIBRARY_PATH="$lib" "$tmp/example_pc" > "$tmp/got_pc.txt"
diff "$tmp/expected.txt" "$tmp/got_pc.txt" || fail "pkg-config build: output differs from docs/api.md"
"$cc" -std=c11 -Wall -Wextra -Wpedantic -Werror "$tmp/example.c" \
   $(pkg-config --cflags --static --libs fliplab) -o "$tmp/example_pcs"
LD_LIBRARY_PATH="$lib" "$tmp/example_pcs" > "$tmp/got_pcs.txt"
diff "$tmp/expected.txt" "$tmp/got_pcs.txt" || fail "pkg-config --static build: output differs from docs/api.md"

# Through CMake's find_package: docs/api.md's fliplab::fliplab (static: the
# program needs no libfliplab.so), and fliplab::fliplab_shared (CMake's rpath).
for target in fliplab fliplab_shared; do
  d=$tmp/cmake_$target
  mkdir -p "$d"
  block api-cmake | sed "s/fliplab::fliplab)/fliplab::$target)/" > "$d/CMakeLists.txt"
  grep -q "fliplab::$target)" "$d/CMakeLists.txt" || fail "docs/api.md's api-cmake block: no fliplab::fliplab"
  cp "$tmp/example.c" "$d/example.c"
  cmake -S "$d" -B "$d/build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_C_COMPILER="$cc" \
        -DCMAKE_BUILD_TYPE=Release >/dev/null || fail "find_package(fliplab) failed"
  cmake --build "$d/build" >/dev/null || fail "CMake build against fliplab::$target failed"
  if [ $target = fliplab ]; then
    needs "$d/build/example" "$soname" && fail "fliplab::fliplab: linked to $soname, not static"
  else
    needs "$d/build/example" "$soname" || fail "fliplab::fliplab_shared: not linked to $soname"
  fi
  "$d/build/example" > "$d/got.txt"
  diff "$tmp/expected.txt" "$d/got.txt" || fail "CMake build ($target): output differs from docs/api.md"
done

# The plugin build line, run from a copy of plugins/, then loaded.
mkdir -p "$tmp/plugin"
cp -r "$src/plugins" "$tmp/plugin/plugins"
indented plugin-build > "$tmp/plugin/commands.sh"
test -s "$tmp/plugin/commands.sh" || fail "docs/api.md plugin lines not found"
(cd "$tmp/plugin" && sh -e commands.sh > out.txt) || fail "docs/api.md plugin lines failed"
grep -q "^rule rule109: quadrilateral rule" "$tmp/plugin/out.txt" || fail "plugin not used"

# The Python package: a fresh interpreter, no FLIPLAB_LIBRARY, only the
# prefix's site directory on its path, finds the prefix's library.
py=${FLIPLAB_PYTHON:-/usr/bin/python3}
if "$py" -c "import numpy" 2>/dev/null; then
  site=$prefix/${FLIPLAB_PYTHON_SITEDIR:?FLIPLAB_PYTHON_SITEDIR not set}
  test -f "$site/fliplab/__init__.py" || fail "Python package not installed in $site"
  (cd "$tmp" && env -u FLIPLAB_LIBRARY PYTHONPATH="$site" PYTHONDONTWRITEBYTECODE=1 "$py" -c '
import sys, fliplab
p = fliplab.samplers.points(100, "uniform", 1)
t = fliplab.lot(p, "P_1", check=True)
assert t.status == "converged" and len(t.triangles) == 2 * 100 - len(t.hull) - 2
from fliplab import explorer
import os
assert explorer.web_dir() == os.path.join(os.path.dirname(fliplab.__file__), "web")
print(fliplab.__file__, fliplab.library_path, sep="\n")') > "$tmp/py.txt" ||
    fail "the installed Python package does not load"
  sed -n 1p "$tmp/py.txt" | grep -q "^$site/fliplab/" || fail "Python loaded fliplab from elsewhere: $(cat "$tmp/py.txt")"
  lp=$(sed -n 2p "$tmp/py.txt")
  test "$(readlink -f "$lp")" = "$(readlink -f "$lib/$soname")" ||
    fail "the installed Python package loaded $lp, not $lib/$soname"
else
  echo "install_check: $py has no numpy: Python package not checked"
fi
echo "install_check: ok"
