#!/usr/bin/env bash
# Prints the make rules that say which results each figure is drawn from. Every figures/*.gp
# names the programs whose data it plots in a line '# needs: NAME ...': a verification program
# (its BUILD/results/NAME.rc), a scene run by make (run_SCENE: RUNS/SCENE.seconds) or a benchmark
# (bench_*: no prerequisite, see the Makefile).
#   tools/figure_deps.sh BUILD RUNS FIGURE.gp...
set -eu
build=$1 runs=$2; shift 2
for gp in "$@"; do
  deps=""
  for n in $(sed -n 's/^# needs://p' "$gp"); do
    case $n in
      bench_*) ;;
      run_*) deps="$deps $runs/${n#run_}.seconds" ;;
      *) deps="$deps $build/results/$n.rc" ;;
    esac
  done
  echo "$build/figures/$(basename "$gp" .gp).png:$deps"
done
