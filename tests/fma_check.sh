#!/bin/sh
# fma_check.sh LIBRARY: the floating-point contract holds in the machine code.
# No fused multiply-add (vfmadd*, vfmsub*, vfnmadd*, vfnmsub*, vfmaddsub*,
# vfmsubadd*) may appear in the library whatever -march it was built for:
# a fused operation rounds once where the source rounds twice, and the
# output would depend on the target (CMakeLists.txt says where gcc made some).
set -eu
lib=$1
command -v objdump >/dev/null 2>&1 || { echo "fma_check: objdump not found, skipped"; exit 0; }
found=$(objdump -d --no-show-raw-insn "$lib" | awk '
  /^[0-9a-f]+ <.*>:$/ { fn = $2 }
  /\tv?fn?m(add|sub)|\tvfm(addsub|subadd)/ { print fn ": " $0 }' | head -20)
if [ -n "$found" ]; then
  echo "fma_check: fused multiply-adds in $lib:" >&2
  echo "$found" >&2
  exit 1
fi
echo "fma_check: no fused multiply-add in $lib"
