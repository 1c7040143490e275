#!/bin/sh
# tests/funclen_check.sh: no function of the library or the program is longer
# than 60 lines (the style rule of the project: a function is read at once).
# A function is a definition that starts in column 0 and ends at the first
# "}" in column 0 after it (the layout every file of the tree follows).
# tests/ and bench/ are exempt.  Prints each offender and fails if any.
#   tests/funclen_check.sh SOURCE_DIR [MAX]
set -u
src=$1
max=${2:-60}
cd "$src" || exit 2
files=$(ls geom/*.[ch] badness/*.[ch] joints/*.[ch] samplers/*.[ch] shapes/*.[ch] \
  cpdt/*.[ch] linf/*.[ch] fliprules/*.[ch] lot/*.[ch] classify/*.[ch] got/*.[ch] studies/*.[ch] reports/*.[ch] \
  cli/*.[ch] plugins/*.c fuzz/*.c 2>/dev/null)
out=$(awk -v max="$max" '
FNR == 1 { infn = 0; sig = "" }
!infn && /^[A-Za-z_]/ && !/;[ \t]*$/ { sig = $0 }
!infn && sig != "" && /\{[ \t]*$/ && !/=[ \t]*\{/ {
  if (sig ~ /\(/) { infn = 1; start = FNR; name = sig }
  sig = ""; next
}
infn && /^\}/ {
  if (FNR - start - 1 > max) printf "%s:%d: %d lines: %s\n", FILENAME, start, FNR - start - 1, name
  infn = 0
}' $files)
if [ -n "$out" ]; then
  echo "funclen_check: functions longer than $max lines:"
  echo "$out"
  exit 1
fi
echo "funclen_check: every function of $(echo $files | wc -w) files is at most $max lines"
