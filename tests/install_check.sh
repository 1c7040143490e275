#!/bin/sh
# install_check.sh BUILD_DIR SOURCE_DIR: what README.md's "C API" section
# promises, checked on an installed copy (`cmake --install` into a scratch
# prefix):
#  - only public headers are installed, and each compiles on its own;
#  - the README's example program builds through pkg-config (--static) and
#    through find_package(fliplab), runs, and prints exactly the output the
#    README shows;
#  - the README's plugin build line works and the installed program loads
#    the plugin.
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
    *_internal.h|plugin_loader.h|mesh.h|order.h) fail "private header installed: $h" ;;
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

# The README's blocks: the fenced block after a marker, or its indented lines.
block() {
  awk -v m="<!-- $1" 'index($0, m) == 1 {on = 1; next}
    on == 1 && /^```/ {on = 2; next}
    on == 2 && /^```/ {exit}
    on == 2 {print}' "$src/README.md"
}
indented() {
  awk -v m="<!-- $1" 'index($0, m) == 1 {on = 1; next}
    on && /^    / {print substr($0, 5); seen = 1; next}
    on && seen {exit}' "$src/README.md"
}
block api-example > "$tmp/example.c"
block api-example-output > "$tmp/expected.txt"
test -s "$tmp/example.c" && test -s "$tmp/expected.txt" || fail "README example not found"

# Through pkg-config.
"$cc" -std=c11 -Wall -Wextra -Wpedantic -Werror "$tmp/example.c" \
   $(pkg-config --cflags --static --libs fliplab) -o "$tmp/example_pc"
"$tmp/example_pc" > "$tmp/got_pc.txt"
diff "$tmp/expected.txt" "$tmp/got_pc.txt" || fail "pkg-config build: output differs from README.md"

# Through CMake's find_package.
mkdir -p "$tmp/cmake_user"
block api-cmake > "$tmp/cmake_user/CMakeLists.txt"
cp "$tmp/example.c" "$tmp/cmake_user/example.c"
cmake -S "$tmp/cmake_user" -B "$tmp/cmake_user/build" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_C_COMPILER="$cc" \
      -DCMAKE_BUILD_TYPE=Release >/dev/null || fail "find_package(fliplab) failed"
cmake --build "$tmp/cmake_user/build" >/dev/null || fail "CMake build against fliplab::fliplab failed"
"$tmp/cmake_user/build/example" > "$tmp/got_cmake.txt"
diff "$tmp/expected.txt" "$tmp/got_cmake.txt" || fail "CMake build: output differs from README.md"

# The plugin build line, run from a copy of plugins/, then loaded.
mkdir -p "$tmp/plugin"
cp -r "$src/plugins" "$tmp/plugin/plugins"
indented plugin-build > "$tmp/plugin/commands.sh"
test -s "$tmp/plugin/commands.sh" || fail "README plugin lines not found"
(cd "$tmp/plugin" && sh -e commands.sh > out.txt) || fail "README plugin lines failed"
grep -q "^rule rule109: quadrilateral rule" "$tmp/plugin/out.txt" || fail "plugin not used"
echo "install_check: ok"
