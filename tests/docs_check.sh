#!/bin/sh
# docs_check.sh SOURCE_DIR: the repository explains itself.
#  - every relative link of README.md and docs/*.md leads to a file;
#  - every docs/NAME.md named in a source comment, a help text or the README exists;
#  - every docs/*.md is listed in the index docs/README.md;
#  - every path docs/architecture.md names exists (the parts, their files);
#  - nothing refers to material outside the repository (the developers'
#    reference folder beside the clone).
set -eu
src=$(cd "$1" && pwd)
cd "$src"
bad=0
say() { echo "docs_check: $*" >&2; bad=1; }

for md in README.md docs/*.md; do
  dir=$(dirname "$md")
  for link in $(grep -o '\]([^)#]*' "$md" | sed 's/^](//' | grep -v '^[a-z]*:' || true); do
    [ -n "$link" ] || continue
    [ -e "$dir/$link" ] || say "$md links to $link, which does not exist"
  done
done

for ref in $(grep -rhoE 'docs/[A-Za-z0-9_-]+\.md' --include='*.c' --include='*.h' \
               --include='*.md' --include='*.sh' --include='CMakeLists.txt' \
               --exclude-dir='build*' --exclude-dir='.git' --exclude=docs_check.sh . | sort -u); do
  [ -e "$ref" ] || say "$ref is named in the sources but does not exist"
done

for f in docs/*.md; do
  n=$(basename "$f")
  [ "$n" = README.md ] && continue
  grep -q "($n)" docs/README.md || say "docs/$n is not listed in docs/README.md"
done

# paths FILE: the repository paths a page names, `in/backticks` (a folder
# ends with /; NAME stands for a file an extension adds).  Those on a line
# marked "(planned)" belong to a part still being made: listed apart.
paths() {
  awk -v want="$2" '
    { planned = index($0, "(planned)") > 0; s = $0
      while (match(s, /`[^` ]*`/)) {
        t = substr(s, RSTART + 1, RLENGTH - 2); s = substr(s, RSTART + RLENGTH)
        if (t ~ /^[A-Za-z0-9_.-]+\/[A-Za-z0-9_.\/-]*$/ && t !~ /NAME/ && planned == want) print t
      } }' "$1" | sort -u
}
for p in $(paths docs/architecture.md 0); do
  [ -e "$p" ] || say "docs/architecture.md names $p, which does not exist"
done
for p in $(paths docs/architecture.md 1); do
  if [ -e "$p" ]; then echo "docs_check: $p exists now: drop its (planned) in docs/architecture.md"
  else echo "docs_check: planned, not in the tree yet: $p"; fi
done

if grep -rnE '\.\./shar[e]d|/work/shar[e]d' --include='*.c' --include='*.h' --include='*.md' \
     --include='*.txt' --include='*.sh' --include='CMakeLists.txt' --include='*.in' \
     --exclude-dir='build*' --exclude-dir='.git' . ; then
  say "the lines above refer to files outside the repository"
fi
[ $bad -eq 0 ] && echo "docs_check: ok"
exit $bad
