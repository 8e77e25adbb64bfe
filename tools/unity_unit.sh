#!/usr/bin/env bash
# Writes the unity unit of one folder (mk/unity.mk): a C++ source that #includes the folder's
# .cpp files in the order given. The file is rewritten only when that list changes, so that its
# object is rebuilt only when a file of the folder is (its header dependencies come from -MMD).
#   tools/unity_unit.sh OUTPUT.cpp FILE.cpp...
set -eu
out=$1; shift
mkdir -p "$(dirname "$out")"
printf '#include "%s"\n' "${@/#/$PWD/}" | cmp -s - "$out" 2>/dev/null || printf '#include "%s"\n' "${@/#/$PWD/}" > "$out"
