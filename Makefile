# granseg: build, verification, figures, tests, benchmarks.
#
# A newcomer runs exactly two commands (README.md):
#   make verify   build, run every verification program, render every figure
#   make test     Boost.Test unit tests
# Both first check the Debian packages below: as root they are installed, otherwise the one
# apt-get line to run is printed and make stops with exit status 2.
#
# Other targets: all (build only), figures, fig7, bench, clean, and those of mk/. Everything
# generated goes to $(BUILD) (default build/). `make UNITY=0` compiles file by file (mk/unity.mk).

SHELL := /bin/bash
BUILD ?= build
# Jobs: the cores themselves (nproc obeys OMP_NUM_THREADS, which would run one program at a time).
JOBS ?= $(shell env -u OMP_NUM_THREADS -u OMP_THREAD_LIMIT nproc 2>/dev/null || echo 2)
# Programs side by side get one OpenMP thread each (docs/flow_solver_choices.md, "Threads").
RUN_THREADS = $(if $(filter 1,$(JOBS)),,OMP_NUM_THREADS=1)

# The one place that lists the Debian packages the project needs.
DEBIAN_PACKAGES := g++ make libgsl-dev libeigen3-dev libboost-test-dev \
                   libboost-program-options-dev gnuplot-nox libtomlplusplus-dev libmuparser-dev clang-format

CXX := g++
OPT ?= -O2
CXXFLAGS := -std=c++17 $(OPT) -Wall -Wextra -Wpedantic -fopenmp $(EXTRA_CXXFLAGS)
CPPFLAGS := -Isrc -Iverification -I$(BUILD)/gen -isystem /usr/include/eigen3 \
            -DTOML_HEADER_ONLY=0 -DTOML_SHARED_LIB=1 -MMD -MP
LDFLAGS := -fopenmp $(EXTRA_LDFLAGS)
LDLIBS := -lgsl -lgslcblas -lmuparser -ltomlplusplus -lboost_program_options

# ---- sources, found by pattern: a new file in one of these folders is built with its folder ----
LIB_SRC     := $(shell find src -name '*.cpp' -not -path 'src/cli/*' | sort)
DATA_FILES  := $(shell find src -name '*.dat' | sort)
CLI_SRC     := $(sort $(wildcard src/cli/*.cpp))
HARNESS_SRC := $(sort $(wildcard verification/harness/*.cpp))
STUDY_SRC   := $(sort $(wildcard verification/study/*.cpp))
VERIFY_SRC  := $(sort $(wildcard verification/verify_*.cpp))
BENCH_SRC   := $(sort $(wildcard verification/bench/bench_*.cpp))
TEST_SRC    := $(shell find tests -name '*.cpp' | sort)
FLOW_SRC    := $(filter src/flow% src/linalg/%,$(LIB_SRC))  # the flow solver (two more flags, below)

# ---- objects: one per source file, under $(BUILD)/obj (mk/unity.mk makes it one per folder) ----
obj = $(patsubst %.cpp,$(BUILD)/obj/%.o,$(1))
EMBED_SRC   := $(BUILD)/gen/embedded_data.cpp
ID_SRC      := $(BUILD)/gen/build_identity.cpp
LIB_OBJ     := $(call obj,$(LIB_SRC) $(EMBED_SRC) $(ID_SRC))
CLI_OBJ     := $(call obj,$(CLI_SRC))
HARNESS_OBJ := $(call obj,$(HARNESS_SRC))
STUDY_OBJ   := $(call obj,$(STUDY_SRC))
TEST_OBJ    := $(call obj,$(TEST_SRC))
VERIFY_OBJ  := $(call obj,$(VERIFY_SRC))
FLOW_OBJ    := $(call obj,$(FLOW_SRC))
include mk/unity.mk

LIB        := $(BUILD)/libgranseg.a
CLI        := $(BUILD)/granseg
VERIFY_BIN := $(patsubst verification/%.cpp,$(BUILD)/verification/%,$(VERIFY_SRC))
BENCH_BIN  := $(patsubst verification/bench/%.cpp,$(BUILD)/bench/%,$(BENCH_SRC))
TEST_BIN   := $(BUILD)/tests/unit_tests
# The longest programs first, longest first (mk/schedule.mk: the last to finish are short ones).
VERIFY_FIRST := verify_tumbler verify_flow_rotation verify_flow_tumbler verify_flow_order verify_tumbler_time_step \
                verify_drum_shapes verify_flow_incline verify_segregation_stress
VERIFY_NAMES := $(filter $(notdir $(VERIFY_BIN)),$(VERIFY_FIRST)) $(filter-out $(VERIFY_FIRST),$(notdir $(VERIFY_BIN)))
FIG_GP       := $(sort $(wildcard figures/fig*.gp))
FIG_PNG      := $(FIG_GP:figures/%.gp=$(BUILD)/figures/%.png)
BENCH_GP     := $(sort $(wildcard figures/bench*.gp))
FULL_GP      := $(sort $(wildcard figures/full*.gp))
FULL_PNG     := $(FULL_GP:figures/%.gp=$(BUILD)/figures/%.png)
RUNS         := $(BUILD)/runs

.PHONY: FORCE all verify test figures fig7 bench figures-full sanitize tsan clean deps \
        run-verification run-bench docs-figures docs-refresh format format-check commands-cost exercises
.DEFAULT_GOAL := all
.DELETE_ON_ERROR:
.SECONDARY:
.SUFFIXES:  # no built-in rules: they would try to remake the compiler's dependency files as programs

# make all: build everything, run nothing.
all: $(LIB) $(CLI) $(VERIFY_BIN) $(TEST_BIN) $(BENCH_BIN)

# ---- Debian packages ---------------------------------------------------------------------------
# make deps (run first by verify, test, bench, ...) always checks; the stamp only orders the first
# compilation after a check when a single file is built directly.
deps $(BUILD)/.deps-ok:
	@tools/check_debian_packages.sh $(DEBIAN_PACKAGES)
	@mkdir -p $(BUILD) && touch $(BUILD)/.deps-ok

# ---- compilation -------------------------------------------------------------------------------
# The one compile rule (generated sources too); -MMD lists each object's headers (read at the end).
$(BUILD)/obj/%.o: %.cpp | $(BUILD)/.deps-ok
	@mkdir -p $(@D)
	$(CXX) $(CPPFLAGS) $(CXXFLAGS) -c $< -o $@

# The flow solver's loops vectorise only with these flags, which change no value (docs/flow_solver.md).
$(FLOW_OBJ): CXXFLAGS += -fno-math-errno -fno-trapping-math

# Generated sources: the data files under src/ (packing tables), so that binaries work from any
# folder, and the build's identity, which checkpoints carry (rewritten only when it changes).
$(EMBED_SRC): $(DATA_FILES) tools/embed_data.sh
	tools/embed_data.sh $@ $(DATA_FILES)
$(ID_SRC): FORCE
	@tools/build_identity.sh $@ $(CXX) $(CXXFLAGS)

# A removed source file leaves the library and the tests: these lists change, and relink.
$(BUILD)/lib-objects.list $(BUILD)/test-objects.list: FORCE
	@mkdir -p $(@D)
	@echo '$(if $(findstring lib-,$@),$(LIB_OBJ),$(TEST_OBJ))' | cmp -s - $@ || \
	  echo '$(if $(findstring lib-,$@),$(LIB_OBJ),$(TEST_OBJ))' > $@
FORCE:

# ---- the library and the programs --------------------------------------------------------------
# The library: everything under src/ but the command line.
$(LIB): $(LIB_OBJ) $(BUILD)/lib-objects.list
	@rm -f $@
	ar rcs $@ $(filter %.o,$^)

# The command line, granseg.
$(CLI): $(CLI_OBJ) $(LIB)
	$(CXX) $(LDFLAGS) $^ $(LDLIBS) -o $@

# A verification program: its one file, the check-table harness and the library. Its own file at
# -O1, as the unit tests: the work is in the library and the harness, which keep $(OPT).
$(VERIFY_OBJ): CXXFLAGS += -O1
$(BUILD)/verification/%: $(BUILD)/obj/verification/%.o $(HARNESS_OBJ) $(LIB)
	@mkdir -p $(@D)
	$(CXX) $(LDFLAGS) $^ $(LDLIBS) -o $@

# A benchmark: its one file, the Fig. 7 study, the harness and the library.
$(BUILD)/bench/%: $(BUILD)/obj/verification/bench/%.o $(STUDY_OBJ) $(HARNESS_OBJ) $(LIB)
	@mkdir -p $(@D)
	$(CXX) $(LDFLAGS) $^ $(LDLIBS) -o $@

# The unit tests: one program of every tests/**/*.cpp (a folder per room of src/), on Boost.Test's shared library.
$(TEST_BIN): $(TEST_OBJ) $(HARNESS_OBJ) $(LIB) $(BUILD)/test-objects.list
	@mkdir -p $(@D)
	$(CXX) $(LDFLAGS) $(filter %.o %.a,$^) $(LDLIBS) -lboost_unit_test_framework -o $@
$(TEST_OBJ): CPPFLAGS += -DBOOST_TEST_DYN_LINK
# The tests' own code at -O1 (after $(OPT), so it wins): their unit compiles in two thirds of the
# time -O2 takes, and the tests run as fast; the library they test keeps $(OPT) (docs/history.md).
$(TEST_OBJ): CXXFLAGS += -O1

# ---- verification ------------------------------------------------------------------------------
# One program's run: its check table printed, its data in $(BUILD)/data, its exit status in
# results/NAME.rc; make goes on, so one failure does not hide the others.
$(BUILD)/results/%.rc: $(BUILD)/verification/% $(CLI)
	@mkdir -p $(@D) $(BUILD)/data
	@t0=$$(date +%s.%N); \
	$(RUN_THREADS) $< --data $(BUILD)/data > $(BUILD)/results/$*.log 2>&1; rc=$$?; \
	t1=$$(date +%s.%N); cat $(BUILD)/results/$*.log; \
	printf "[%s: exit %d, %s s]\n\n" "$*" "$$rc" "$$(awk "BEGIN{printf \"%.1f\", $$t1 - $$t0}")"; \
	echo $$rc > $@

# Every program's result; verify_docs reads what the others wrote (their result logs, the data
# the reference figures were drawn from), so it runs after all of them.
run-verification: $(VERIFY_NAMES:%=$(BUILD)/results/%.rc)
$(BUILD)/results/verify_docs.rc: $(filter-out %/verify_docs.rc,$(VERIFY_NAMES:%=$(BUILD)/results/%.rc))
include mk/schedule.mk

# make verify: keeps going past a program that fails to build, run or render (the summary counts
# it as failed). One make builds, runs and renders, so that a program runs as soon as it is linked
# and a figure is drawn as soon as its programs have run; it also builds the unit tests.
verify: deps
	@rm -f $(BUILD)/results/*.rc
	@$(MAKE) --no-print-directory -k -j$(JOBS) -O $(CLI) $(TEST_BIN) run-verification figures || \
	  echo "verify: some programs did not build, run or render"
	@tools/verify_summary.sh $(BUILD) "$(VERIFY_NAMES)" "$(FIG_PNG)"

# make test: the unit tests, with a count of passed and failed cases (tests/cli/ runs granseg).
test: deps format-check
	@$(MAKE) --no-print-directory -j$(JOBS) $(TEST_BIN) $(CLI)
	@tools/run_unit_tests.sh $(TEST_BIN) $(BUILD)/tests/report.xml

# ---- figures -----------------------------------------------------------------------------------
# Which results each figure is drawn from (its '# needs:' line, tools/figure_deps.sh): a PNG is
# drawn again only when its script or one of those results is newer. A benchmark is none (make
# bench draws the figures of what it ran): a changed program must never rerun an hour of benchmark.
$(BUILD)/figures.mk: $(FIG_GP) $(BENCH_GP) $(FULL_GP) tools/figure_deps.sh
	@mkdir -p $(@D)
	@tools/figure_deps.sh $(BUILD) $(RUNS) $(FIG_GP) $(BENCH_GP) $(FULL_GP) > $@
-include $(BUILD)/figures.mk

# One figure, renamed into place only if gnuplot succeeds: the verify summary counts a missing PNG.
GNUPLOT_DIRS = datadir='$(BUILD)/data'; benchdir='$(BUILD)/bench-data'; rundir='$(RUNS)'
$(BUILD)/figures/%.png: figures/%.gp | $(BUILD)/.deps-ok
	@mkdir -p $(@D)
	@rm -f $@; \
	if gnuplot -e "$(GNUPLOT_DIRS); outfile='$@.tmp.png'" $< > $(BUILD)/figures/$*.log 2>&1 && [ -s $@.tmp.png ]; then \
	  mv $@.tmp.png $@; echo "figure: $@"; \
	else \
	  rm -f $@.tmp.png; echo "figure FAILED: $@ (see $(BUILD)/figures/$*.log)"; cat $(BUILD)/figures/$*.log; \
	fi

# make figures: every figure of the verification programs.
figures: $(FIG_PNG)

# ---- scene runs and Fig. 7 at the paper's resolution -------------------------------------------
# One run of a scene file (a long one: the figure scripts that plot it say '# needs: run_SCENE'),
# with progress on stderr; the wall time goes to SCENE.seconds, written only if the run succeeds.
$(RUNS)/%.seconds: verification/scenes/%.toml $(CLI)
	@mkdir -p $(RUNS)
	@echo "run: $< into $(RUNS)/$* (progress on stderr)"
	@t0=$$(date +%s.%N); \
	$(CLI) run $< --output-dir $(RUNS)/$* > $(RUNS)/$*.log || { cat $(RUNS)/$*.log; exit 1; }; \
	t1=$$(date +%s.%N); awk "BEGIN{printf \"%.0f\n\", $$t1 - $$t0}" > $@

# make fig7: the paper's drum (verification/scenes/tumbler.toml) run once, Fig. 7 and its animation
# drawn; its numbers printed and, with its cost, tabled for README.md (verification/fig7_tables.awk),
# each table with the record of what made it (verify_docs --provenance; docs/checked_pages.md).
FIG7_PNG := $(filter $(BUILD)/figures/full_fig7%,$(FULL_PNG))
FIG7_RECORD = $(BUILD)/verification/verify_docs --provenance "make fig7" \
              "$(CLI) run verification/scenes/tumbler.toml --output-dir $(RUNS)/tumbler" flow drum segregation closures
fig7: deps
	@start=$$(date +%s); \
	$(MAKE) --no-print-directory -j$(JOBS) $(CLI) $(BUILD)/verification/verify_docs && \
	  $(MAKE) --no-print-directory -j$(JOBS) $(FIG7_PNG) || exit 1; \
	for png in $(FIG7_PNG); do [ -s $$png ] || { echo "fig7: $$png was not rendered"; exit 1; }; done; \
	if [ $$(stat -c %Y $(RUNS)/tumbler.seconds) -ge $$start ]; then how="this run"; else how="an earlier run, reused"; fi; \
	echo "fig7: Fig. 7a-d and the animation in $(BUILD)/figures/full_fig7*_tumbler.png (+ .gif) from $(RUNS)/tumbler"; \
	record=$$($(FIG7_RECORD)) || exit 1; \
	awk -v cost=$(RUNS)/fig7_cost.md -f verification/fig7_tables.awk $(RUNS)/tumbler/summary.dat > $(RUNS)/fig7_run.md; \
	for f in $(RUNS)/fig7_run.md $(RUNS)/fig7_cost.md; do echo "$$record" >> $$f; done; \
	sed -n 's/^| \(.*\) | \(.*\) |$$/fig7: \1: \2/p' $(RUNS)/fig7_run.md | tail -n +2; \
	echo "fig7: the drum run took $$(cat $(RUNS)/tumbler.seconds) s wall ($$how); make fig7 took $$(( $$(date +%s) - start )) s"

# ---- benchmarks and long studies (not part of verify) ------------------------------------------
# make bench runs every benchmark; make bench BENCH="bench_a bench_b" only those, with BENCH_ARGS on
# each one's command line. The recipes: mk/bench.mk.
include mk/bench.mk

# ---- beyond the two commands (recipes in mk/) ---------------------------------------------------
# make figures-full: the long studies' figures; make docs-figures: the figures the pages show;
# make docs-refresh: fresh generated tables into the pages (mk/pages.mk, docs/checked_pages.md);
# make commands-cost: make verify and make test timed on a fresh clone; make exercises: the tutorial's.
# make sanitize, make tsan: the address, undefined-behaviour and thread sanitizers (mk/sanitizers.mk).
figures-full docs-figures sanitize tsan commands-cost exercises: deps
docs-refresh: $(BUILD)/verification/verify_docs
include mk/pages.mk mk/sanitizers.mk mk/format.mk

# make clean: everything generated.
clean:
	rm -rf $(BUILD)

# The headers each object included (-MMD): a changed header compiles again what includes it.
-include $(shell find $(BUILD)/obj -name '*.d' 2>/dev/null)
