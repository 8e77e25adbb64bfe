#!/usr/bin/env bash
# The last lines of make verify: how many verification programs passed (BUILD/results/NAME.rc
# holds each one's exit status) and how many figures were rendered (a PNG that is missing or
# empty failed); exits 1 if anything failed.
#   tools/verify_summary.sh BUILD "NAME..." "FIGURE.png..."
set -u
build=$1 names=$2 pngs=$3
pass=0 fail=0 failed=""
for n in $names; do
  if [ "$(cat "$build/results/$n.rc" 2>/dev/null)" = 0 ]; then pass=$((pass + 1)); else fail=$((fail + 1)); failed="$failed $n"; fi
done
for png in $pngs; do
  if [ -s "$png" ]; then pass=$((pass + 1)); else fail=$((fail + 1)); failed="$failed $(basename "$png")"; fi
done
echo "verify: $(wc -w <<< "$names") verification programs and $(wc -w <<< "$pngs") figures in $build/figures"
[ -z "$failed" ] || echo "verify: failed:$failed"
echo "verify: $pass passed, $fail failed"
[ "$fail" = 0 ]
