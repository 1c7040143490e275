#!/bin/sh
# install_check.sh BUILD_DIR SOURCE_DIR: `cmake --install` into a scratch
# prefix, then build and run a small program against the installed headers
# and library through the installed pkg-config file.
set -eu
build=$1
src=$2
prefix=$build/testtmp/install
rm -rf "$prefix"
cmake --install "$build" --prefix "$prefix" >/dev/null
test -x "$prefix/bin/fliplab"
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
cc -std=c11 "$src/tests/support/install_user.c" $(pkg-config --cflags --libs fliplab) \
   -o "$prefix/install_user"
"$prefix/install_user"
