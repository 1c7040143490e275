#!/bin/sh
# tests/golden.sh: the refactoring guard.  Runs a fixed set of fliplab
# commands (table34, classify, census, merge, lot, got, flipgraph, rule, flip,
# list, sample, user formulas and plugins) and compares every byte of their
# standard output and of every file they write with the SHA-256 sums of
# tests/golden.sha256, recorded from the program before a refactoring began.
# Lines reporting wall time ("time: ...") are left out, as they differ from run
# to run; nothing else is.
#
#   tests/golden.sh BUILD_DIR check        compare with tests/golden.sha256
#   tests/golden.sh BUILD_DIR save DIR     keep the outputs in DIR (for diff)
#   tests/golden.sh BUILD_DIR record       rewrite tests/golden.sha256
#
# A change that means to alter an output records the new sums in the same
# commit and says why.
set -u
build=$(cd "$1" && pwd) || exit 2   # absolute: the commands run in a work folder
mode=$2
here=$(cd "$(dirname "$0")" && pwd)
bin=$build/fliplab
plug=$build/plugins
manifest=$here/golden.sha256
if [ "$mode" = save ]; then out=$3; mkdir -p "$out"; else out=$(mktemp -d); fi
work=$(mktemp -d)
trap 'rm -rf "$work"; [ "$mode" = save ] || rm -rf "$out"' EXIT
export OMP_NUM_THREADS=2

# run NAME ARGS...: stdout (timing lines dropped) and exit status into NAME.
run() {
  name=$1
  shift
  rc=0
  (cd "$work" && "$bin" "$@") > "$work/stdout" 2>/dev/null || rc=$?
  grep -v -E '^(# )?time:' "$work/stdout" > "$out/$name.out"
  echo "exit $rc" >> "$out/$name.out"
}
# keep NAME FILE: a file a command wrote, into the outputs.
keep() { cp "$work/$2" "$out/$1"; }

printf 'x,y\n0,0\n1,0\n2,1\n1,3\n0,2\n0.5,1\n' > "$work/s6.csv"
printf 'x,y\n0,0\n3,0\n6,1\n7,4\n5,7\n1,6\n-1,3\n2,2\n4,3\n' > "$work/s9.csv"

# table 3.4: samplers, formats, measure sets, shards and merge, a formula
run t34_text table34 --samples 3000 --seed 7
run t34_md table34 --samples 1000 --seed 2 --format md
run t34_csv table34 --samples 3000 --seed 7 --format csv --measures all --out t34.csv --plot t34.svg
keep t34.csv t34.csv; keep t34.svg t34.svg
for s in vector circle disc-hull; do
  run t34_$s table34 --samples 800 --seed 3 --sampler $s --format csv
done
run t34_tie table34 --samples 800 --seed 4 --tie-eps 1e-6 --measures R,-alpha,P --format csv
run t34_sh1 table34 --samples 3000 --seed 7 --format csv --measures all --shard 1/2 --out sh1.csv
run t34_sh2 table34 --samples 3000 --seed 7 --format csv --measures all --shard 2/2 --out sh2.csv
run t34_merge merge sh1.csv sh2.csv --out merged.csv
keep t34_merged.csv merged.csv
run t34_merge_text merge sh1.csv sh2.csv --format text
run t34_formula --define 'q = a*b*c' --define 'w <= 0 : -A/(a*a)' table34 --samples 600 --measures q,w,R --format csv
run t34_plugin --plugin "$plug/rule109.so" table34 --samples 600 --measures R --format csv

# samples and classify
run sample sample --count 40 --seed 5 --out pent.csv
keep pent.csv pent.csv
run classify classify --input pent.csv
run classify_rules classify --input pent.csv --rule R_inf,-alpha_inf,P_2,sigma_0,DT
run classify_plugin --plugin "$plug/rule156.so" classify --input pent.csv --rule rule156,P_1

# census: samplers, formats, shards and merge
for s in convex disc square normal; do
  run census_$s census --sites 6 --sampler $s --samples 150 --seed 2 --format csv
done
run census_text census --sites 5 --samples 200 --measures R,P,-alpha
run census_rules census --sites 7 --sampler disc --samples 40 --rules R_1,P_2,sigma_inf,DT --format md
run census_sh1 census --sites 6 --sampler disc --samples 150 --seed 2 --format csv --shard 1/2 --out c1.csv
run census_sh2 census --sites 6 --sampler disc --samples 150 --seed 2 --format csv --shard 2/2 --out c2.csv
run census_merge merge c1.csv c2.csv

# lot: rules, samplers, both algorithms, orders, compare, check, SVG
for r in DT P_1 R_inf -alpha_inf sigma_2 -r2/A_0 beta_-1 gamma_1 lambda_1; do
  f=$(echo "$r" | tr '/' 'o')
  for s in uniform normal disc grid parabola circle clustered jittered lines dups; do
    run lot_${f}_$s lot --rule "$r" --random 700 --sampler $s --seed 3 --out l.csv
    keep lot_${f}_$s.csv l.csv
  done
  run lot_${f}_flip lot --rule "$r" --random 700 --algorithm flip --seed 4 --out l.csv --check
  keep lot_${f}_flip.csv l.csv
done
for o in random input; do
  run lot_order_$o lot --rule P_1 --random 900 --order $o --out l.csv --compare DT
  keep lot_order_$o.csv l.csv
done
run lot_pts lot --rule R_1 --points s9.csv --out l.csv --svg l.svg --shade --compare DT
keep lot_pts.csv l.csv; keep lot_pts.svg l.svg
run lot_got lot --rule P_1 --random 40 --sampler circle --compare GOT
run lot_formula --define 'q = a*b*c' lot --rule q_1 --random 500 --out l.csv
keep lot_formula.csv l.csv
run lot_plugin --plugin "$plug/rule109.so" lot --rule rule109 --random 300 --out l.csv
keep lot_plugin.csv l.csv

# got: convex and simple polygons, rules, CSV, SVG
for r in P_1 R_inf -alpha_-inf sigma_2 -r2/A_0 d_-1 P_0; do
  f=$(echo "$r" | tr '/' 'o')
  for s in vector circle star monotone; do
    run got_${f}_$s got --rule "$r" --random 25 --sampler $s --seed 6 --csv g.csv
    keep got_${f}_$s.csv g.csv
  done
done
run got_svg got --rule P_1 --random 14 --svg g.svg --shade --compare DT
keep got_svg.svg g.svg
run got_big got --rule R_1 --random 120 --sampler star

# flip graphs of small site sets
for r in R_1 DT P_inf -alpha_-inf; do
  run flipgraph_$r flipgraph --rule "$r" --points s6.csv
done
run flipgraph_big flipgraph --rule R_1 --points s9.csv
run flipgraph_svg flipgraph --rule R_1 --points s6.csv --svg fg.svg
keep flipgraph.svg fg.svg

# rule verdicts, single flips, the catalogue
run rule_R1 rule R_1,-alpha_inf --samples 2000 --quads 2000 --site-samples 200
run rule_plugin --plugin "$plug/rule156.so" rule rule156 --samples 1000 --quads 1000 --site-samples 100
for r in P_1 DT R_inf -r2/A_0 sigma_0; do
  f=$(echo "$r" | tr '/' 'o')
  run flip_$f flip "$r" 1 0 0.5 0.8660254037844386 -1 0 0.5 -0.8660254037844386
  run flip_${f}_cw flip "$r" 0 0 0 1 1.1 1.2 1 0
done
run list list

if [ "$mode" = record ]; then
  (cd "$out" && sha256sum $(ls | LC_ALL=C sort)) > "$manifest"
  echo "golden: recorded $(wc -l < "$manifest") outputs in $manifest"
  exit 0
fi
[ "$mode" = save ] && exit 0
status=0
(cd "$out" && sha256sum --quiet -c "$manifest") || status=1
extra=$(cd "$out" && ls | LC_ALL=C sort | while read -r f; do
  grep -q "  $f\$" "$manifest" || echo "$f"; done)
[ -z "$extra" ] || { echo "golden: outputs missing from the manifest: $extra"; status=1; }
[ $status -eq 0 ] && echo "golden: $(wc -l < "$manifest") outputs reproduced byte for byte"
exit $status
