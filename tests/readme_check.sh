#!/bin/sh
# readme_check.sh BUILD_DIR SOURCE_DIR: README.md says what the program does;
# run what it shows and compare.  The same for every page of docs/ that
# carries the line "<!-- checked by tests/readme_check.sh -->".  Each page
# runs in a scratch directory of its own, in document order:
#  - "$ COMMAND" lines (indented, `\` continues a line) are run with the
#    built fliplab first on PATH; the indented lines right below a command
#    are its expected output, matched in order against the real output:
#    a line must be there exactly, except that a line with "..." matches any
#    line starting with the text before the "...", a line starting with
#    "..." matches nothing (an elision) and "time:" lines are not compared;
#  - <!-- check: COMMAND --> ... <!-- /check -->: the lines between (blank
#    ones dropped) are the expected output of COMMAND, by the same rules;
#  - <!-- file: NAME --> before a fenced block: the block is written to NAME
#    (a program that a later command runs);
#  - <!-- check-file: PRODUCED REFERENCE -->: a file made by an earlier
#    command must equal the repository's file byte for byte (the figures).
# In the scratch directory `build` is the build directory (its plugins), and
# Debian's /usr/bin/python3 finds the package of python/ and the build's
# libfliplab.so as after `pip install`.  Without numpy and matplotlib there,
# the Python commands and the files they make are skipped, saying so.
# The README stays a front door: under 300 lines.
set -eu
build=$(cd "$1" && pwd)
src=$(cd "$2" && pwd)
tmp=$build/testtmp/readme_check
rm -rf "$tmp"
mkdir -p "$tmp/bin"
ln -s "$build/fliplab" "$tmp/bin/fliplab"
PATH="$tmp/bin:$PATH"
PYTHONPATH=$src/python
FLIPLAB_LIBRARY=$build/libfliplab.so
MPLBACKEND=Agg
PYTHONDONTWRITEBYTECODE=1
export PATH PYTHONPATH FLIPLAB_LIBRARY MPLBACKEND PYTHONDONTWRITEBYTECODE
python=yes
/usr/bin/python3 -c 'import numpy, matplotlib' 2>/dev/null || python=no
status=0
say() { echo "readme_check: $*"; status=1; }

lines=$(wc -l < "$src/README.md")
[ "$lines" -lt 300 ] || say "README.md has $lines lines: a front door has fewer than 300"

# cases PAGE DIR: the page's commands, expected outputs, files and figures,
# as DIR/N.cmd, DIR/N.exp, DIR/N.body and the list DIR/list.
cases() {
  awk -v out="$2" '
    function start(cmd) { n++; printf "%s", cmd > (out "/" n ".cmd"); close(out "/" n ".cmd");
                          printf "" > (out "/" n ".exp"); print "cmd " n > (out "/list") }
    function expect(line) { print line >> (out "/" n ".exp"); close(out "/" n ".exp") }
    infile == 2 && /^```/ { close(body); print "write " n " " name > (out "/list"); infile = 0; next }
    infile == 2 { print >> body; next }
    infile == 1 && /^```/ { n++; body = out "/" n ".body"; printf "" > body; infile = 2; next }
    incheck && /^<!-- \/check -->/ { incheck = 0; next }
    incheck { if ($0 != "") expect($0); next }
    /^<!-- check: / { c = $0; sub(/^<!-- check: /, "", c); sub(/ -->$/, "", c);
                      start(c); incheck = 1; inblock = 0; next }
    /^<!-- check-file: / { c = $0; sub(/^<!-- check-file: /, "", c); sub(/ -->$/, "", c);
                           print "file " c > (out "/list"); inblock = 0; next }
    /^<!-- file: / { name = $0; sub(/^<!-- file: /, "", name); sub(/ -->$/, "", name);
                     infile = 1; inblock = 0; next }
    {
      if (match($0, /^ +\$ /)) {
        indent = RLENGTH - 2; cmd = substr($0, RLENGTH + 1)
        while (cmd ~ /\\$/) { sub(/\\$/, "", cmd); getline; sub(/^ +/, " ", $0); cmd = cmd $0 }
        start(cmd); inblock = 1; next
      }
      pad = sprintf("%" indent "s", "")
      if (inblock && $0 != "" && substr($0, 1, indent) == pad) { expect(substr($0, indent + 1)); next }
      inblock = 0
    }
  ' "$1"
  touch "$2/list"
}

# matches EXPECTED ACTUAL: every expected line found, in order.
matches() {
  awk -v actual="$2" '
    BEGIN { while ((getline l < actual) > 0) a[na++] = l; i = 0 }
    /^\.\.\./ || /^time:/ { next }
    {
      want = $0; prefix = 0
      if (index(want, "...") > 0) { want = substr(want, 1, index(want, "...") - 1); sub(/ +$/, "", want); prefix = 1 }
      while (i < na && !(prefix ? index(a[i], want) == 1 : a[i] == want)) i++
      if (i == na) { print "readme_check: expected line not found: " $0; bad = 1; exit }
      i++
    }
    END { exit bad }' "$1"
}

# check PAGE: run its cases in a fresh directory.
check() {
  page=$1
  d=$tmp/$(echo "$page" | tr / _)
  mkdir -p "$d/cases" "$d/work"
  ln -s "$build" "$d/work/build"
  cases "$src/$page" "$d/cases"
  count=0
  while read -r kind a b; do
    count=$((count + 1))
    c=$d/cases/$a
    case $kind in
    write) (cd "$d/work" && cp "$c.body" "$b") ;;
    cmd)
      if [ $python = no ] && grep -q python3 "$c.cmd"; then
        echo "readme_check: $page: skipped (no numpy and matplotlib for /usr/bin/python3): $(cat "$c.cmd")"
      elif ! (cd "$d/work" && sh -c "$(cat "$c.cmd")" < /dev/null > "$c.out" 2> "$c.err"); then
        say "$page: failed: $(cat "$c.cmd")"; cat "$c.err"
      elif ! matches "$c.exp" "$c.out"; then
        say "$page: in the output of: $(cat "$c.cmd")"
      fi ;;
    file)
      if [ $python = no ] && [ ! -e "$d/work/$a" ]; then
        echo "readme_check: $page: skipped: $a (not made)"
      elif [ ! -e "$d/work/$a" ]; then
        say "$page: $a was not made"
      elif ! cmp "$d/work/$a" "$src/$b" >/dev/null 2>&1; then
        say "$page: $a differs from $b"
      fi ;;
    esac
  done < "$d/cases/list"
  echo "readme_check: $page: $count checks"
}

check README.md
for page in $(cd "$src" && grep -lx '<!-- checked by tests/readme_check.sh -->' docs/*.md); do
  check "$page"
done
[ $status -eq 0 ] && echo "readme_check: ok"
exit $status
