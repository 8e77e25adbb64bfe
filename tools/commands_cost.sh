#!/usr/bin/env bash
# make commands-cost: what the README's two commands cost. A fresh clone of the commit checked out
# (in a scratch directory, removed after) runs `make verify`, then `make test`, each timed by the
# shell: its wall time and the CPU time of all its processes. Writes the table README.md shows
# (docs/generated/commands_cost.md once `make docs-refresh` copies it) with its provenance record,
# printed by the clone's own verify_docs (so it names the commit and the physics that were timed).
# Timings are the machine's that ran it, with its load: run it on a quiet machine.
#   tools/commands_cost.sh OUTPUT.md
set -eu
out=$1
top=$(git rev-parse --show-toplevel)
commit=$(git -C "$top" rev-parse HEAD)
[ -z "$(git -C "$top" status --porcelain --untracked-files=no)" ] ||
  echo "commands-cost: uncommitted changes are not in the clone; it times commit ${commit:0:12}" >&2
scratch=$(mktemp -d "${TMPDIR:-/tmp}/granseg_cost.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
git clone -q --no-local --no-checkout "$top" "$scratch/clone"
git -C "$scratch/clone" checkout -q "$commit"
cores=$(env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc)
load=$(cut -d' ' -f1 /proc/loadavg)

# Wall and CPU seconds (user + system, children included) of one make target in the clone.
timed() {
  local TIMEFORMAT='%R %U %S' log="$scratch/$1.log"
  echo "commands-cost: make $1 on a fresh clone of ${commit:0:12} (output in $log)" >&2
  { time make -C "$scratch/clone" "$1" > "$log" 2>&1; } 2> "$scratch/$1.time" ||
    { tail -n 20 "$log" >&2; echo "commands-cost: make $1 failed" >&2; exit 1; }
  awk '{ printf "%.0f %.0f\n", $1, $2 + $3 }' "$scratch/$1.time"
}
read -r verify_wall verify_cpu < <(timed verify)
read -r test_wall test_cpu < <(timed test)
{
  echo "| command, on a fresh clone | wall time | CPU time, all processes |"
  echo "|---|---|---|"
  printf "| make verify | %d min %02d s | %d min %02d s |\n" $((verify_wall / 60)) $((verify_wall % 60)) $((verify_cpu / 60)) $((verify_cpu % 60))
  printf "| make test, after make verify | %d min %02d s | %d min %02d s |\n" $((test_wall / 60)) $((test_wall % 60)) $((test_cpu / 60)) $((test_cpu % 60))
  echo
  echo "Written by \`make commands-cost\`: the two commands one after the other on a fresh clone, $cores cores, the 1-minute load before them $load; the cost on the computer that ran them."
  "$scratch/clone/build/verification/verify_docs" --provenance "make commands-cost" \
    "tools/commands_cost.sh: make verify, then make test, on a fresh clone" flow drum segregation closures
} > "$out.tmp"
mv "$out.tmp" "$out"
cat "$out"
