#!/usr/bin/env bash
# make exercises: the exercises of docs/tutorial.md judged as the page says they are. Each
# reference solution verification/exercises/NAME.patch is applied to one scratch copy of the tree
# (the tracked files as they are now, and the build's objects, so that a patch recompiles only
# what it touches), built, and judged by the checks the page's verdict tables name,
#     | `verification/exercises/NAME.patch` | `CHECK` | pass or FAIL |
# where CHECK is a verification program (run with --data) or `make TARGET`; then the patch is
# taken back. Prints a row per check, the failing rows of each failing program, and exits 1 when a
# verdict differs from the page's (or a patch does not apply or build).
#   tools/exercises.sh BUILD JOBS
set -u
build=$1 jobs=$2 page=docs/tutorial.md
root=$(pwd)
scratch=$(mktemp -d "${TMPDIR:-/tmp}/granseg_exercises.XXXXXX")
trap 'rm -rf "$scratch"' EXIT
git ls-files -z | xargs -0 tar -cf - | tar -xf - -C "$scratch"
mkdir -p "$scratch/build"
[ -d "$build" ] && tar -C "$build" --exclude=./runs --exclude=./data --exclude=./bench-data --exclude=./results \
  --exclude=./bench-results -cf - . | tar -xf - -C "$scratch/build"
rows=$(sed -n 's/^| *`\(verification\/exercises\/[^`]*\.patch\)` *| *`\([^`]*\)` *| *\([A-Za-z]*\) *|$/\1|\2|\3/p' "$page")
[ -n "$rows" ] || { echo "exercises: no verdict rows in $page"; exit 1; }
mismatches=0 checks=0
printf '%-45s | %-28s | %-7s | %-7s | %s\n' "reference solution" "check" "page" "run" "agrees"
for patch in $(echo "$rows" | cut -d'|' -f1 | awk '!seen[$0]++'); do
  log=$scratch/out/$(basename "$patch" .patch)
  mkdir -p "$log"
  if ! (cd "$scratch" && git apply "$root/$patch"); then
    echo "exercises: $patch does not apply"; mismatches=$((mismatches + 1)); continue
  fi
  programs=$(echo "$rows" | awk -F'|' -v p="$patch" '$1 == p && $2 ~ /^verify_/ {print "build/verification/" $2}')
  if ! make -C "$scratch" --no-print-directory -j"$jobs" BUILD=build build/granseg $programs > "$log/build.log" 2>&1; then
    echo "exercises: $patch does not build:"; grep -m5 'error' "$log/build.log"; mismatches=$((mismatches + 1))
  else
    grep -m3 'warning' "$log/build.log" | sed "s|^|exercises: $patch: |"
    while IFS='|' read -r p check expected; do
      [ "$p" = "$patch" ] || continue
      checks=$((checks + 1))
      case $check in
        make\ *) (cd "$scratch" && $check BUILD=build) > "$log/${check#make }.log" 2>&1 ;;
        *) (cd "$scratch" && "build/verification/$check" --data "$log/data") > "$log/$check.log" 2>&1 ;;
      esac
      status=$?
      verdict=$([ $status -eq 0 ] && echo pass || echo FAIL)
      agrees=$([ "$verdict" = "$expected" ] && echo yes || echo NO)
      [ "$agrees" = yes ] || mismatches=$((mismatches + 1))
      printf '%-45s | %-28s | %-7s | %-7s | %s\n' "$patch" "$check" "$expected" "$verdict" "$agrees"
      [ "$verdict" = FAIL ] && grep -E '\| FAIL$' "$log/${check#make }.log" | head -6 | sed 's/^/      /'
    done <<< "$rows"
  fi
  (cd "$scratch" && git apply -R "$root/$patch") || { echo "exercises: $patch cannot be taken back"; exit 1; }
done
echo "exercises: $checks checks, $mismatches differing from $page"
[ "$mismatches" -eq 0 ]
