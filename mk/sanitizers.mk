# The sanitizer builds: what they buy is checks, not speed. Each builds into its own tree, file
# by file (UNITY=0: every file compiles on its own includes), and runs what it checks there.

# make sanitize: address and undefined-behaviour sanitizers over the unit tests and every
# verification program (no figures).
# -Wno-maybe-uninitialized: with -fsanitize=address at -O1, GCC 12 warns inside libstdc++'s
# <regex>/<functional> (std::function in the regex NFA, used by tests/run/scene_file.cpp), a
# false positive in a system header; the -O2 build keeps the warning on and has none.
SAN_FLAGS := -O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=undefined \
             -Wno-maybe-uninitialized
SAN_MAKE = $(MAKE) --no-print-directory -j$(JOBS) BUILD=$(BUILD)/sanitize UNITY=0 OPT="$(SAN_FLAGS)" \
           EXTRA_LDFLAGS="-fsanitize=address,undefined"
sanitize:
	@$(SAN_MAKE) $(BUILD)/sanitize/tests/unit_tests $(patsubst $(BUILD)/%,$(BUILD)/sanitize/%,$(VERIFY_BIN) $(CLI))
	@tools/run_unit_tests.sh $(BUILD)/sanitize/tests/unit_tests $(BUILD)/sanitize/tests/report.xml
	@rm -f $(BUILD)/sanitize/results/*.rc
	@$(SAN_MAKE) -O GRANSEG_SANITIZE=1 run-verification
	@tools/verify_summary.sh $(BUILD)/sanitize "$(VERIFY_NAMES)" ""

# make tsan: the thread sanitizer over the unit tests and a short coupled drum on two threads
# (verification/scenes/tumbler_threads.toml). GCC's libgomp is not instrumented for it, so every
# OpenMP barrier and reduction would look like a race; clang's OpenMP runtime (libomp) tells the
# sanitizer about each of them through its tool Archer (libarcher.so, loaded by OMP_TOOL_LIBRARIES),
# so no report of our code needs suppressing. The runtime itself is not instrumented: the mutexes it
# hands between its threads through its own atomics looked like races inside libomp, which
# ignore_noninstrumented_modules=1 leaves out (it ignores only what uninstrumented libraries do;
# every access of our code is still checked). -ffp-contract=off: clang would fuse a*b + c where
# GCC does not, and the unit tests of exact zeros (the HLLC mirror state) need the unfused rounding.
# Debian packages of this target only: TSAN_PACKAGES.
TSAN_PACKAGES := clang libomp-dev
TSAN_FLAGS := -O1 -g -fno-omit-frame-pointer -fsanitize=thread -ffp-contract=off
TSAN_RUN := OMP_NUM_THREADS=2 OMP_TOOL_LIBRARIES=$$(ls /usr/lib/llvm-*/lib/libarcher.so | tail -n1) \
            TSAN_OPTIONS="halt_on_error=1 exitcode=66 ignore_noninstrumented_modules=1"
tsan:
	@tools/check_debian_packages.sh $(TSAN_PACKAGES)
	@$(MAKE) --no-print-directory -j$(JOBS) BUILD=$(BUILD)/tsan UNITY=0 CXX=clang++ OPT="$(TSAN_FLAGS)" \
	    EXTRA_LDFLAGS="-fsanitize=thread" $(BUILD)/tsan/tests/unit_tests $(BUILD)/tsan/granseg
	@$(TSAN_RUN) tools/run_unit_tests.sh $(BUILD)/tsan/tests/unit_tests $(BUILD)/tsan/tests/report.xml
	@rm -rf $(BUILD)/tsan/tumbler_threads; \
	$(TSAN_RUN) $(BUILD)/tsan/granseg run verification/scenes/tumbler_threads.toml \
	    --output-dir $(BUILD)/tsan/tumbler_threads > $(BUILD)/tsan/tumbler_threads.log 2>&1; rc=$$?; \
	tail -n 30 $(BUILD)/tsan/tumbler_threads.log; \
	echo "tsan: coupled drum (tumbler_threads.toml) exit $$rc"; exit $$rc
