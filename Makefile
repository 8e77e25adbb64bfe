# granseg: build, verification, figures, tests, benchmarks.
#
# A newcomer runs exactly two commands (README.md):
#   make verify   build, run every verification program, render every figure
#   make test     Boost.Test unit tests
# Both first check the Debian packages below: as root they are installed, otherwise the one
# apt-get line to run is printed and make stops with exit status 2.
#
# Other targets: all (build only), figures, fig7, bench (BENCH=NAME to run one), figures-full,
# sanitize, tsan, clean, and for the pages: docs-figures (redraw the reference figures of
# docs/figures/), docs-refresh (copy fresh generated tables into docs/generated/ and the pages);
# docs/checked_pages.md explains both.
# Everything generated goes to $(BUILD) (default build/), which git ignores.

SHELL := /bin/bash
BUILD ?= build
# Programs run side by side, one per core: the cores themselves, not nproc's answer (nproc obeys
# OMP_NUM_THREADS and OMP_THREAD_LIMIT, so OMP_NUM_THREADS=1 would run one program at a time).
JOBS ?= $(shell env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc 2>/dev/null || echo 2)
# With several programs side by side each gets one OpenMP thread (more would oversubscribe the
# cores: docs/flow_solver_choices.md, "Threads"); one at a time it keeps the caller's setting.
RUN_THREADS = $(if $(filter 1,$(JOBS)),,OMP_NUM_THREADS=1)
# -j$(JOBS) for the sub-makes, unless the caller already runs a parallel make (its jobserver is shared).
PAR = $(if $(findstring jobserver,$(MAKEFLAGS)),,-j$(JOBS))

# The one place that lists the Debian packages the project needs.
DEBIAN_PACKAGES := g++ make libgsl-dev libeigen3-dev libboost-test-dev \
                   libboost-program-options-dev gnuplot-nox libtomlplusplus-dev libmuparser-dev

CXX := g++
OPT ?= -O2
CXXFLAGS := -std=c++17 $(OPT) -Wall -Wextra -Wpedantic -fopenmp $(EXTRA_CXXFLAGS)
CPPFLAGS := -Isrc -Iverification -I$(BUILD)/gen -isystem /usr/include/eigen3 \
            -DTOML_HEADER_ONLY=0 -DTOML_SHARED_LIB=1 -MMD -MP
LDFLAGS := -fopenmp $(EXTRA_LDFLAGS)
LDLIBS := -lgsl -lgslcblas -lmuparser -ltomlplusplus -lboost_program_options

# ---- sources -----------------------------------------------------------------------------------
LIB_SRC     := $(shell find src -name '*.cpp' -not -path 'src/cli/*' | sort)
DATA_FILES  := $(shell find src -name '*.dat' | sort)
CLI_SRC     := $(sort $(wildcard src/cli/*.cpp))
HARNESS_SRC := $(sort $(wildcard verification/harness/*.cpp))
STUDY_SRC   := $(sort $(wildcard verification/study/*.cpp))
VERIFY_SRC  := $(sort $(wildcard verification/verify_*.cpp))
BENCH_SRC   := $(sort $(wildcard verification/bench/bench_*.cpp))
TEST_SRC    := $(sort $(wildcard tests/*.cpp))

# ---- unity build -------------------------------------------------------------------------------
# By default every folder of sources (a "room": src/flow, src/cli, verification/harness, tests,
# ...) compiles as one translation unit that #includes the room's .cpp files in name order
# (generated into $(BUILD)/unity/). The headers a room shares (Eigen, Boost.Test, toml++, our own)
# are then parsed and their templates instantiated and optimised once per room instead of once
# per file: a clean build takes less than half the CPU time. The computed values are the same (no
# flag changes; inlining across files does not change IEEE arithmetic). A unit is rebuilt when
# any of its files changes: while editing one file, UNITY=0 compiles file by file (and without
# the verification programs' precompiled header). make sanitize and make tsan build with UNITY=0,
# so every file still compiles on its own includes. Inside a room, names in unnamed namespaces
# must differ between files (the compiler says so when they do not); a test file keeps its
# helpers inside its BOOST_AUTO_TEST_SUITE.
UNITY ?= 1
obj = $(patsubst %.cpp,$(BUILD)/obj/%.o,$(1))
# The rooms of a list of files (src/flow/time_step.cpp -> src/flow); a room's unit is named src-flow.
rooms = $(sort $(patsubst %/,%,$(dir $(1))))
unit_name = $(subst /,-,$(1))
# The unit's source for room $(1) of files $(2), rewritten only when its list of files changes.
define unity_unit
$(BUILD)/unity/$(call unit_name,$(1)).cpp: FORCE
	@mkdir -p $$(@D)
	@printf '#include "$(CURDIR)/%s"\n' $(2) | cmp -s - $$@ || printf '#include "$(CURDIR)/%s"\n' $(2) > $$@
endef
# The objects of a list of files: one per room (defining the room's unit), or one per file with
# UNITY=0.
unity_objects = $(if $(filter 1,$(UNITY)),$(foreach r,$(call rooms,$(1)),$(eval \
  $(call unity_unit,$(r),$(filter $(r)/%,$(1))))$(BUILD)/obj/unity/$(call unit_name,$(r)).o),$(call obj,$(1)))

LIB_OBJ     := $(call unity_objects,$(LIB_SRC)) $(BUILD)/obj/gen/embedded_data.o $(BUILD)/obj/gen/build_identity.o
CLI_OBJ     := $(call unity_objects,$(CLI_SRC))
HARNESS_OBJ := $(call unity_objects,$(HARNESS_SRC))
STUDY_OBJ   := $(call unity_objects,$(STUDY_SRC))
# test_main.cpp defines the test program's entry (BOOST_TEST_MODULE before Boost.Test's header):
# a unit of its own.
TEST_OBJ    := $(call unity_objects,$(filter-out tests/test_main.cpp,$(TEST_SRC))) $(call obj,tests/test_main.cpp)

LIB        := $(BUILD)/libgranseg.a
CLI        := $(BUILD)/granseg
VERIFY_BIN := $(patsubst verification/%.cpp,$(BUILD)/verification/%,$(VERIFY_SRC))
BENCH_BIN  := $(patsubst verification/bench/%.cpp,$(BUILD)/bench/%,$(BENCH_SRC))
TEST_BIN   := $(BUILD)/tests/unit_tests

# The longest programs (about a minute to half a minute each on one core) first: make starts
# them as soon as they are linked, and the last programs to finish are short ones, instead of a
# long one running alone at the end while the other core waits.
VERIFY_FIRST := verify_flow_rotation verify_flow_order verify_flow_tumbler verify_segregation_stress \
                verify_tumbler verify_flow_incline
VERIFY_NAMES := $(filter $(notdir $(VERIFY_BIN)),$(VERIFY_FIRST)) $(filter-out $(VERIFY_FIRST),$(notdir $(VERIFY_BIN)))
VERIFY_FIRST_BIN := $(filter $(VERIFY_FIRST:%=$(BUILD)/verification/%),$(VERIFY_BIN))
VERIFY_RC    := $(VERIFY_NAMES:%=$(BUILD)/results/%.rc)
FIG_GP       := $(sort $(wildcard figures/fig*.gp))
FIG_PNG      := $(FIG_GP:figures/%.gp=$(BUILD)/figures/%.png)
BENCH_GP     := $(sort $(wildcard figures/bench*.gp))
BENCH_PNG    := $(BENCH_GP:figures/%.gp=$(BUILD)/figures/%.png)
FULL_GP      := $(sort $(wildcard figures/full*.gp))
FULL_PNG     := $(FULL_GP:figures/%.gp=$(BUILD)/figures/%.png)

.PHONY: FORCE all verify test figures fig7 bench figures-full sanitize tsan clean deps \
        run-verification run-bench verify-summary test-run docs-figures docs-refresh
.DEFAULT_GOAL := all
.DELETE_ON_ERROR:
.SECONDARY:

all: $(LIB) $(CLI) $(VERIFY_BIN) $(TEST_BIN) $(BENCH_BIN)

# ---- Debian packages ---------------------------------------------------------------------------
# `make deps` (run first by verify, test, bench, sanitize) always checks; the stamp only orders
# compilation after a first check when a single target is built directly.
define check_debian_packages
	@missing=""; \
	for p in $(DEBIAN_PACKAGES); do \
	  dpkg-query -W -f='$${Status}' "$$p" 2>/dev/null | grep -q 'ok installed' || missing="$$missing $$p"; \
	done; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = 0 ]; then \
	    echo "deps: installing$$missing"; \
	    apt-get update && DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends $$missing || exit 2; \
	  else \
	    echo "deps: missing Debian packages; run this line, then the make command again:"; \
	    echo "sudo apt-get install -y$$missing"; \
	    exit 2; \
	  fi; \
	fi
	@mkdir -p $(BUILD) && touch $(BUILD)/.deps-ok
endef

deps:
	$(check_debian_packages)
$(BUILD)/.deps-ok:
	$(check_debian_packages)

# ---- compilation -------------------------------------------------------------------------------
# The flow solver's cell and face loops (src/flow*/) and the linear algebra under them (src/linalg/)
# vectorise only if sqrt need not set errno and FP operations may be executed speculatively (their
# discarded results change nothing): neither flag changes a computed value (docs/flow_solver.md,
# performance).
$(BUILD)/obj/src/flow%.o $(BUILD)/obj/src/linalg/%.o: CXXFLAGS += -fno-math-errno -fno-trapping-math
$(BUILD)/obj/unity/src-flow.o $(BUILD)/obj/unity/src-flow_%.o $(BUILD)/obj/unity/src-linalg.o: CXXFLAGS += -fno-math-errno -fno-trapping-math

# The library, where runs spend their time, at $(OPT); the programs that check it (verification
# programs, their harness, the benchmarks' drivers, the unit tests) at CHECK_OPT: they compile in
# about a fifth less time, and -O1 computes the same bits as -O2 (no fast-math, no contraction).
CHECK_OPT ?= -O1
$(BUILD)/obj/verification/%.o $(BUILD)/obj/tests/%.o: private CXXFLAGS += $(CHECK_OPT)
$(BUILD)/obj/unity/verification-%.o $(BUILD)/obj/unity/tests.o: private CXXFLAGS += $(CHECK_OPT)

$(BUILD)/obj/%.o: %.cpp | $(BUILD)/.deps-ok
	@mkdir -p $(@D)
	$(CXX) $(CPPFLAGS) $(CXXFLAGS) -c $< -o $@

$(BUILD)/obj/unity/%.o: $(BUILD)/unity/%.cpp | $(BUILD)/.deps-ok
	@mkdir -p $(@D)
	$(CXX) $(CPPFLAGS) $(CXXFLAGS) -c $< -o $@

# The verification programs compile with a precompiled header of what most of them include
# (verification/harness/precompiled.hpp, copied into the build tree beside its .gch, the copy
# used if the .gch cannot be): about 1 s less per program, a third of their compile time. Like
# the unity units, only with UNITY=1: UNITY=0 compiles every file on its own includes alone.
ifeq ($(UNITY),1)
VERIFY_PCH := $(BUILD)/obj/pch/precompiled.hpp
VERIFY_OBJ := $(call obj,$(VERIFY_SRC))
$(VERIFY_PCH).gch: CXXFLAGS += $(CHECK_OPT)
$(VERIFY_PCH).gch: verification/harness/precompiled.hpp | $(BUILD)/.deps-ok
	@mkdir -p $(@D)
	cp $< $(VERIFY_PCH)
	$(CXX) $(CPPFLAGS) -MT $@ $(CXXFLAGS) -x c++-header $(VERIFY_PCH) -o $@
$(VERIFY_OBJ): $(VERIFY_PCH).gch
$(VERIFY_OBJ): private CPPFLAGS += -include $(VERIFY_PCH) -Winvalid-pch
endif

# Data files under src/ (packing tables, ...) are compiled into the library, so the binaries
# do not depend on where the source tree is.
$(BUILD)/gen/embedded_data.cpp: $(DATA_FILES) Makefile
	@mkdir -p $(@D)
	@{ echo '// Generated by the Makefile from the .dat files under src/. Do not edit.'; \
	   echo '#include "core/embedded.hpp"'; \
	   echo '#include <map>'; echo '#include "core/error.hpp"'; echo '#include <string>'; \
	   echo 'namespace granseg {'; \
	   echo 'std::string_view embedded_file(std::string_view name) {'; \
	   echo '  static const std::map<std::string_view, std::string_view> files = {'; \
	   for f in $(DATA_FILES); do \
	     echo "    {\"$${f#src/}\", R\"granseg_embed($$(cat $$f)"; echo ')granseg_embed"},'; \
	   done; \
	   echo '  };'; \
	   echo '  auto it = files.find(name);'; \
	   echo '  if (it == files.end()) throw InvariantError("no embedded file " + std::string(name));'; \
	   echo '  return it->second;'; \
	   echo '}'; echo '}  // namespace granseg'; } > $@.tmp && mv $@.tmp $@

$(BUILD)/obj/gen/embedded_data.o: $(BUILD)/gen/embedded_data.cpp | $(BUILD)/.deps-ok
	@mkdir -p $(@D)
	$(CXX) $(CPPFLAGS) $(CXXFLAGS) -c $< -o $@

# The build's identity (src/core/build_identity.hpp), which checkpoints carry: a hash of the
# library's sources and data under src/, the compiler's version and the library's flags. Rewritten
# only when it changes, so an unchanged build does not recompile it.
$(BUILD)/gen/build_identity.cpp: FORCE
	@mkdir -p $(@D)
	@id=$$({ find src \( -name '*.cpp' -o -name '*.hpp' -o -name '*.dat' \) | LC_ALL=C sort | xargs cat; \
	         $(CXX) --version | head -n1; echo '$(CXXFLAGS)'; } | sha256sum | cut -c1-16); \
	printf '// Generated by the Makefile. Do not edit.\n#include "core/build_identity.hpp"\n%s\n' \
	  "const char* granseg::build_identity() { return \"$$id\"; }" > $@.tmp; \
	cmp -s $@.tmp $@ && rm $@.tmp || mv $@.tmp $@

$(BUILD)/obj/gen/build_identity.o: $(BUILD)/gen/build_identity.cpp | $(BUILD)/.deps-ok
	@mkdir -p $(@D)
	$(CXX) $(CPPFLAGS) $(CXXFLAGS) -c $< -o $@

# A removed source file must trigger a relink: these lists change when the object lists do.
$(BUILD)/lib-objects.list $(BUILD)/test-objects.list: FORCE
	@mkdir -p $(@D)
	@echo '$(if $(findstring lib-,$@),$(LIB_OBJ),$(TEST_OBJ))' | cmp -s - $@ || \
	  echo '$(if $(findstring lib-,$@),$(LIB_OBJ),$(TEST_OBJ))' > $@
FORCE:

$(LIB): $(LIB_OBJ) $(BUILD)/lib-objects.list
	@mkdir -p $(@D)
	@rm -f $@
	ar rcs $@ $(filter %.o,$^)

$(CLI): $(CLI_OBJ) $(LIB)
	$(CXX) $(LDFLAGS) $^ $(LDLIBS) -o $@

$(BUILD)/verification/%: $(BUILD)/obj/verification/%.o $(HARNESS_OBJ) $(LIB)
	@mkdir -p $(@D)
	$(CXX) $(LDFLAGS) $^ $(LDLIBS) -o $@

$(BUILD)/bench/%: $(BUILD)/obj/verification/bench/%.o $(STUDY_OBJ) $(HARNESS_OBJ) $(LIB)
	@mkdir -p $(@D)
	$(CXX) $(LDFLAGS) $^ $(LDLIBS) -o $@

$(TEST_BIN): $(TEST_OBJ) $(HARNESS_OBJ) $(LIB) $(BUILD)/test-objects.list
	@mkdir -p $(@D)
	$(CXX) $(LDFLAGS) $(filter %.o %.a,$^) $(LDLIBS) -lboost_unit_test_framework -o $@

$(TEST_OBJ): CPPFLAGS += -DBOOST_TEST_DYN_LINK

# ---- verification ------------------------------------------------------------------------------
# Each program prints its check table; its exit status goes to results/NAME.rc and make goes on,
# so one failure does not hide the others. Programs write their data to $(BUILD)/data.
$(BUILD)/results/%.rc: $(BUILD)/verification/% $(CLI)
	@mkdir -p $(@D) $(BUILD)/data
	@t0=$$(date +%s.%N); \
	$(RUN_THREADS) $< --data $(BUILD)/data > $(BUILD)/results/$*.log 2>&1; rc=$$?; \
	t1=$$(date +%s.%N); \
	cat $(BUILD)/results/$*.log; \
	printf "[%s: exit %d, %s s]\n\n" "$*" "$$rc" "$$(awk "BEGIN{printf \"%.1f\", $$t1 - $$t0}")"; \
	echo $$rc > $@

run-verification: $(VERIFY_RC)

# When all programs run: the list's order alone does not make the longest ones run first (make
# starts whatever is ready when a core frees up), so the other programs link only after them; and
# make verify's unit tests compile before the programs run (else make leaves them last, one unit
# alone on a core). A program built on its own waits for none of this.
ifneq ($(filter run-verification,$(MAKECMDGOALS)),)
$(filter-out $(VERIFY_FIRST_BIN),$(VERIFY_BIN)): | $(VERIFY_FIRST_BIN)
$(VERIFY_FIRST_BIN): | $(if $(filter $(TEST_BIN),$(MAKECMDGOALS)),$(TEST_OBJ))
endif

# verify_docs reads what the other programs wrote (their result logs, the data the reference
# figures were drawn from), so it runs after all of them.
$(BUILD)/results/verify_docs.rc: $(filter-out $(BUILD)/results/verify_docs.rc,$(VERIFY_RC))

# ---- figures -----------------------------------------------------------------------------------
# Every figures/*.gp names the programs whose data it plots in a line '# needs: NAME ...': a
# verification program, a benchmark (bench_*), or a scene run by make (run_SCENE: one run of
# verification/scenes/SCENE.toml into $(RUNS)/SCENE, its wall time in $(RUNS)/SCENE.seconds).
# A PNG is re-rendered only when its script or one of those programs' results is newer. A
# benchmark is no prerequisite: a changed program must never rerun an hour of benchmark to draw a
# figure; `make bench` draws the figures of what it ran, afresh.
$(BUILD)/figures.mk: $(FIG_GP) $(BENCH_GP) $(FULL_GP) Makefile
	@mkdir -p $(@D)
	@for gp in $(FIG_GP) $(BENCH_GP) $(FULL_GP); do \
	  png=$(BUILD)/figures/$$(basename $$gp .gp).png; \
	  needs=$$(sed -n 's/^# needs://p' $$gp); deps=""; \
	  for n in $$needs; do \
	    case $$n in bench_*) ;; \
	                run_*) deps="$$deps $(RUNS)/$${n#run_}.seconds";; \
	                *) deps="$$deps $(BUILD)/results/$$n.rc";; esac; \
	  done; echo "$$png:$$deps"; \
	done > $@

-include $(BUILD)/figures.mk

# gnuplot writes to a temporary file that is renamed on success; a failed render leaves no PNG,
# which the verify summary counts as a failure.
$(BUILD)/figures/%.png: figures/%.gp | $(BUILD)/.deps-ok
	@mkdir -p $(@D)
	@rm -f $@; \
	if gnuplot -e "datadir='$(BUILD)/data'; benchdir='$(BUILD)/bench-data'; rundir='$(RUNS)'; outfile='$@.tmp.png'" $< \
	     > $(BUILD)/figures/$*.log 2>&1 && [ -s $@.tmp.png ]; then \
	  mv $@.tmp.png $@; echo "figure: $@"; \
	else \
	  rm -f $@.tmp.png; echo "figure FAILED: $@ (see $(BUILD)/figures/$*.log)"; cat $(BUILD)/figures/$*.log; \
	fi

figures: $(FIG_PNG)

# ---- the pages' reference figures and generated tables (docs/checked_pages.md) ----------------
# The figures the pages show on a fresh clone, committed under docs/figures/: drawn by the same
# scripts as build/figures/ (with small=1: 800 pixels wide) from the data of the verification
# programs, which run first if their results are stale; then verify_docs records a fingerprint
# of the data each was drawn from, by which make verify tells a stale image.
DOC_FIGURES := fig_closures fig_direction fig3_integral_curves fig4a_regions fig4b_regions \
               fig5_region_c_example fig6a_profiles fig6b_closeup fig7b_kinematic \
               fig7a_tumbler_kinematic fig7b_tumbler_kinematic fig7c_tumbler_kinematic

# The Fig. 7 study's figures come from a benchmark, Fig. 7c/7d at 100 cells from make fig7's run:
# drawn when their data is there (make bench BENCH=bench_fig7_convergence, make fig7), else left as
# they are.
DOC_BENCH_FIGURES := bench_fig7_convergence bench_fig7_work full_fig7c_tumbler full_fig7d_tumbler full_fig7cd_tumbler \
                     bench_drum_shapes

docs-figures: deps
	@$(MAKE) --no-print-directory $(PAR) $(LIB) $(CLI) $(VERIFY_BIN)
	@$(MAKE) --no-print-directory $(PAR) -O $(DOC_FIGURES:%=$(BUILD)/figures/%.png)
	@drawn="$(DOC_FIGURES)"; \
	for f in $(DOC_BENCH_FIGURES); do \
	  first=$$(sed -n 's/^# reads: *\([^ ]*\).*/\1/p' figures/$$f.gp); \
	  if [ -f $(BUILD)/bench-data/$$first ] || [ -f $(RUNS)/$$first ]; then drawn="$$drawn $$f"; \
	  else echo "docs-figures: $$f kept (its benchmark has not run)"; fi; \
	done; \
	for f in $$drawn; do \
	  gnuplot -e "datadir='$(BUILD)/data'; benchdir='$(BUILD)/bench-data'; rundir='$(RUNS)'; outfile='docs/figures/$$f.png.tmp'; small=1" figures/$$f.gp \
	    && mv docs/figures/$$f.png.tmp docs/figures/$$f.png && echo "docs-figures: docs/figures/$$f.png" \
	    || { rm -f docs/figures/$$f.png.tmp; echo "docs-figures: FAILED $$f"; exit 1; }; \
	done; \
	$(BUILD)/verification/verify_docs --fingerprint $$drawn

# Generated tables: a program writes NAME.md into $(BUILD)/data or $(BUILD)/bench-data; this
# copies every fresh one into docs/generated/NAME.md and into the pages' blocks that show it.
docs-refresh: $(BUILD)/verification/verify_docs
	@$(BUILD)/verification/verify_docs --refresh

# ---- scene runs and Fig. 7 at the paper's resolution -------------------------------------------
# One run of a scene file (a long one: the figure scripts that plot it say '# needs: run_SCENE'),
# with progress on stderr; the wall time goes to SCENE.seconds, written only if the run succeeds.
RUNS := $(BUILD)/runs
$(RUNS)/%.seconds: verification/scenes/%.toml $(CLI)
	@mkdir -p $(RUNS)
	@echo "run: $< into $(RUNS)/$* (progress on stderr)"
	@t0=$$(date +%s.%N); \
	$(CLI) run $< --output-dir $(RUNS)/$* > $(RUNS)/$*.log || { cat $(RUNS)/$*.log; exit 1; }; \
	t1=$$(date +%s.%N); awk "BEGIN{printf \"%.0f\n\", $$t1 - $$t0}" > $@

# `make fig7`: the paper's coupled drum (verification/scenes/tumbler.toml, 100 cells per diameter,
# 25 s, default time stepping) run once, then Fig. 7a-d and the animation from it
# (figures/full_fig7*.gp); figures-full reuses the run. Prints the Fig. 7 numbers of the run and
# writes them and the run's cost as tables (verification/fig7_tables.awk: $(RUNS)/fig7_run.md,
# fig7_cost.md, shown by README.md), then the run's and the command's wall time.
FIG7_PNG := $(filter $(BUILD)/figures/full_fig7%,$(FULL_PNG))
fig7: deps
	@start=$$(date +%s); \
	$(MAKE) --no-print-directory $(PAR) $(CLI) && $(MAKE) --no-print-directory $(PAR) $(FIG7_PNG) || exit 1; \
	for png in $(FIG7_PNG); do [ -s $$png ] || { echo "fig7: $$png was not rendered"; exit 1; }; done; \
	run=$$(cat $(RUNS)/tumbler.seconds); \
	if [ $$(stat -c %Y $(RUNS)/tumbler.seconds) -ge $$start ]; then how="this run"; else how="an earlier run, reused"; fi; \
	echo "fig7: Fig. 7a-d and the animation in $(BUILD)/figures/full_fig7*_tumbler.png (+ .gif) from $(RUNS)/tumbler"; \
	awk -v cost=$(RUNS)/fig7_cost.md -f verification/fig7_tables.awk $(RUNS)/tumbler/summary.dat > $(RUNS)/fig7_run.md; \
	sed -n 's/^| \(.*\) | \(.*\) |$$/fig7: \1: \2/p' $(RUNS)/fig7_run.md | tail -n +2; \
	echo "fig7: the drum run took $$run s wall ($$how); make fig7 took $$(( $$(date +%s) - start )) s"

# ---- the two commands --------------------------------------------------------------------------
# Keeps going past a program that fails to build, run or render: the summary counts it as failed.
# One make builds, runs and renders, so that a program runs as soon as it is linked and a figure
# is drawn as soon as its programs have run: the cores stay busy from the first compile to the
# last figure. It also builds the unit tests (make test then only runs them), early: their one
# unit compiles beside the library's instead of alone after the last program.
verify: deps
	@rm -f $(BUILD)/results/*.rc
	@$(MAKE) --no-print-directory -k $(PAR) -O $(CLI) $(TEST_BIN) run-verification figures || echo "verify: some programs did not build, run or render"
	@$(MAKE) --no-print-directory verify-summary

verify-summary:
	@pass=0; fail=0; failed=""; \
	for n in $(VERIFY_NAMES); do \
	  if [ "$$(cat $(BUILD)/results/$$n.rc 2>/dev/null)" = 0 ]; then pass=$$((pass+1)); \
	  else fail=$$((fail+1)); failed="$$failed $$n"; fi; \
	done; \
	for png in $(FIG_PNG); do \
	  if [ -s $$png ]; then pass=$$((pass+1)); else fail=$$((fail+1)); failed="$$failed $$(basename $$png)"; fi; \
	done; \
	echo "verify: $(words $(VERIFY_NAMES)) verification programs and $(words $(FIG_PNG)) figures in $(BUILD)/figures"; \
	[ -z "$$failed" ] || echo "verify: failed:$$failed"; \
	echo "verify: $$pass passed, $$fail failed"; \
	[ $$fail = 0 ]

test: deps
	@$(MAKE) --no-print-directory $(PAR) $(TEST_BIN)
	@$(MAKE) --no-print-directory test-run

test-run:
	@rm -f $(BUILD)/tests/report.xml; \
	$(TEST_BIN) --report_format=XML --report_level=detailed --report_sink=$(BUILD)/tests/report.xml; rc=$$?; \
	pass=$$(grep -o 'test_cases_passed="[0-9]*"' $(BUILD)/tests/report.xml | head -n1 | tr -dc 0-9); \
	fail=$$(grep -o 'test_cases_failed="[0-9]*"' $(BUILD)/tests/report.xml | head -n1 | tr -dc 0-9); \
	abort=$$(grep -o 'test_cases_aborted="[0-9]*"' $(BUILD)/tests/report.xml | head -n1 | tr -dc 0-9); \
	fail=$$(( $${fail:-0} + $${abort:-0} )); \
	if [ $$rc != 0 ] && [ $$fail = 0 ]; then fail=1; fi; \
	echo "test: $${pass:-0} passed, $$fail failed"; \
	exit $$rc

# ---- benchmarks and long studies (not part of verify) ------------------------------------------
# `make bench` runs every benchmark; `make bench BENCH="bench_a bench_b"` only those, and BENCH_ARGS
# go to each one's command line (for one benchmark: e.g. BENCH=bench_fig7_convergence
# BENCH_ARGS="--cells 25,35,50 --explicit-cells 25,35 --t-end 4 --average-from 2", a test in minutes).
BENCH ?= $(notdir $(BENCH_BIN))
BENCH_ARGS ?=
BENCH_RC := $(BENCH:%=$(BUILD)/bench-results/%.rc)
# The figures of the benchmarks run: the bench*.gp whose '# needs:' line names one of them.
BENCH_RUN_PNG = $(foreach gp,$(BENCH_GP),$(if $(filter $(BENCH),$(shell sed -n 's/^# needs://p' $(gp))),$(gp:figures/%.gp=$(BUILD)/figures/%.png)))

$(BUILD)/bench-results/%.rc: $(BUILD)/bench/% $(CLI)
	@mkdir -p $(@D) $(BUILD)/bench-data
	@$< --data $(BUILD)/bench-data $(BENCH_ARGS) 2>&1 | tee $(BUILD)/bench-results/$*.log; echo $${PIPESTATUS[0]} > $@

run-bench: $(BENCH_RC)

# Benchmarks run one after another: timings taken while another benchmark runs are worthless.
bench: deps
	@$(if $(filter-out $(notdir $(BENCH_BIN)),$(BENCH)),echo "bench: BENCH: no benchmark $(filter-out $(notdir $(BENCH_BIN)),$(BENCH)) (allowed: $(notdir $(BENCH_BIN)))"; exit 2,true)
	@$(MAKE) --no-print-directory $(PAR) $(LIB) $(CLI) $(BENCH:%=$(BUILD)/bench/%)
	@rm -f $(BENCH_RC)
	@$(MAKE) --no-print-directory -j1 run-bench
	@rm -f $(BENCH_RUN_PNG)
	@$(MAKE) --no-print-directory $(PAR) $(BENCH_RUN_PNG)

# One job at a time: the full figures may first run the Fig. 7 drum (make fig7) and a benchmark
# that has not run yet (bench_drum_angle), whose timings are worthless if they run side by side;
# rendering the PNGs takes seconds.
FULL_BENCHES = $(sort $(filter bench_%,$(foreach gp,$(FULL_GP),$(shell sed -n 's/^# needs://p' $(gp)))))
figures-full: deps
	@for b in $(FULL_BENCHES); do [ -f $(BUILD)/bench-results/$$b.rc ] || $(MAKE) --no-print-directory bench BENCH=$$b || exit 1; done
	@$(if $(FULL_PNG),$(MAKE) --no-print-directory -j1 $(FULL_PNG),echo "figures-full: no long studies yet (figures/full*.gp)")

# ---- sanitizers --------------------------------------------------------------------------------
# A separate build tree, compiled file by file (UNITY=0: each file compiles on its own); runs the
# unit tests and every verification program (no figures).
# -Wno-maybe-uninitialized: with -fsanitize=address at -O1, GCC 12 warns inside libstdc++'s
# <regex>/<functional> (std::function in the regex NFA, used by tests/test_scene_file.cpp), a
# false positive in a system header; the -O2 build keeps the warning on and has none.
SAN_FLAGS := -O1 -g -fno-omit-frame-pointer -fsanitize=address,undefined -fno-sanitize-recover=undefined \
             -Wno-maybe-uninitialized
sanitize: deps
	@$(MAKE) --no-print-directory $(PAR) BUILD=$(BUILD)/sanitize UNITY=0 OPT="$(SAN_FLAGS)" \
	    EXTRA_LDFLAGS="-fsanitize=address,undefined" $(BUILD)/sanitize/tests/unit_tests \
	    $(patsubst $(BUILD)/%,$(BUILD)/sanitize/%,$(VERIFY_BIN) $(CLI))
	@$(MAKE) --no-print-directory BUILD=$(BUILD)/sanitize test-run
	@rm -f $(BUILD)/sanitize/results/*.rc
	@$(MAKE) --no-print-directory $(PAR) -O BUILD=$(BUILD)/sanitize UNITY=0 OPT="$(SAN_FLAGS)" \
	    EXTRA_LDFLAGS="-fsanitize=address,undefined" GRANSEG_SANITIZE=1 run-verification
	@$(MAKE) --no-print-directory BUILD=$(BUILD)/sanitize FIG_PNG= verify-summary

# The thread sanitizer, over the unit tests and a short coupled drum on two threads
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
tsan: deps
	@$(MAKE) --no-print-directory DEBIAN_PACKAGES="$(TSAN_PACKAGES)" deps
	@$(MAKE) --no-print-directory $(PAR) BUILD=$(BUILD)/tsan UNITY=0 CXX=clang++ OPT="$(TSAN_FLAGS)" \
	    EXTRA_LDFLAGS="-fsanitize=thread" $(BUILD)/tsan/tests/unit_tests $(BUILD)/tsan/granseg
	@$(TSAN_RUN) $(MAKE) --no-print-directory BUILD=$(BUILD)/tsan test-run
	@rm -rf $(BUILD)/tsan/tumbler_threads; \
	$(TSAN_RUN) $(BUILD)/tsan/granseg run verification/scenes/tumbler_threads.toml \
	    --output-dir $(BUILD)/tsan/tumbler_threads > $(BUILD)/tsan/tumbler_threads.log 2>&1; rc=$$?; \
	tail -n 30 $(BUILD)/tsan/tumbler_threads.log; \
	echo "tsan: coupled drum (tumbler_threads.toml) exit $$rc"; exit $$rc

clean:
	rm -rf $(BUILD)

-include $(shell find $(BUILD)/obj -name '*.d' 2>/dev/null)
