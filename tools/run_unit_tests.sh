#!/usr/bin/env bash
# Runs the unit tests and prints how many test cases passed and failed (aborted ones count as
# failed; a non-zero exit without a failed case counts as one), from Boost.Test's XML report.
#   tools/run_unit_tests.sh UNIT_TESTS REPORT.xml
set -u
bin=$1 report=$2
rm -f "$report"
"$bin" --report_format=XML --report_level=detailed --report_sink="$report"; rc=$?
count() { grep -o "$1=\"[0-9]*\"" "$report" 2>/dev/null | head -n1 | tr -dc 0-9; }
pass=$(count test_cases_passed) fail=$(count test_cases_failed) abort=$(count test_cases_aborted)
fail=$(( ${fail:-0} + ${abort:-0} ))
if [ $rc != 0 ] && [ $fail = 0 ]; then fail=1; fi
echo "test: ${pass:-0} passed, $fail failed"
exit $rc
