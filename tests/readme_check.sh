#!/bin/sh
# readme_check.sh BUILD_DIR SOURCE_DIR: README.md says what the program does;
# run what it shows and compare, in a scratch directory, in document order.
#  - "$ COMMAND" lines (indented, `\` continues a line) are run with the
#    built fliplab first on PATH; the indented lines right below a command
#    are its expected output, matched in order against the real output:
#    a line must be there exactly, except that a line with "..." matches any
#    line starting with the text before the "...", a line starting with
#    "..." matches nothing (an elision) and "time:" lines are not compared;
#  - <!-- check: COMMAND --> ... <!-- /check -->: the lines between (blank
#    ones dropped) are the expected output of COMMAND, by the same rules;
#  - <!-- check-file: PRODUCED REFERENCE -->: a file made by an earlier
#    command must equal the repository's file byte for byte (the figures).
set -eu
build=$(cd "$1" && pwd)
src=$(cd "$2" && pwd)
tmp=$build/testtmp/readme_check
rm -rf "$tmp"
mkdir -p "$tmp/bin" "$tmp/work" "$tmp/cases"
ln -s "$build/fliplab" "$tmp/bin/fliplab"
PATH="$tmp/bin:$PATH"
export PATH

awk -v out="$tmp/cases" '
  function start(cmd) { n++; printf "%s", cmd > (out "/" n ".cmd"); close(out "/" n ".cmd");
                        printf "" > (out "/" n ".exp"); print "cmd " n > (out "/list") }
  function expect(line) { print line >> (out "/" n ".exp"); close(out "/" n ".exp") }
  incheck && /^<!-- \/check -->/ { incheck = 0; next }
  incheck { if ($0 != "") expect($0); next }
  /^<!-- check: / { c = $0; sub(/^<!-- check: /, "", c); sub(/ -->$/, "", c);
                    start(c); incheck = 1; inblock = 0; next }
  /^<!-- check-file: / { c = $0; sub(/^<!-- check-file: /, "", c); sub(/ -->$/, "", c);
                         print "file " c > (out "/list"); inblock = 0; next }
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
' "$src/README.md"

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

cd "$tmp/work"
status=0
while read -r kind a b; do
  if [ "$kind" = cmd ]; then
    if ! sh -c "$(cat "$tmp/cases/$a.cmd")" > "$tmp/cases/$a.out" 2> "$tmp/cases/$a.err"; then
      echo "readme_check: failed: $(cat "$tmp/cases/$a.cmd")"; cat "$tmp/cases/$a.err"; status=1
    elif ! matches "$tmp/cases/$a.exp" "$tmp/cases/$a.out"; then
      echo "readme_check: in the output of: $(cat "$tmp/cases/$a.cmd")"; status=1
    fi
  else
    cmp "$a" "$src/$b" >/dev/null 2>&1 || { echo "readme_check: $a differs from $b"; status=1; }
  fi
done < "$tmp/cases/list"
[ $status -eq 0 ] && echo "readme_check: ok ($(grep -c . "$tmp/cases/list") checks)"
exit $status
