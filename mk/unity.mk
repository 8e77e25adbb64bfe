# Unity build: each folder of sources compiles as one translation unit (the unit tests: one in all).
#
# What it buys: the headers a folder shares (Eigen, Boost.Test, toml++, our own) are parsed, and
# their templates instantiated and optimised, once per folder instead of once per file.
# Measured on clean clones, building what .ci/run builds (the library, granseg, the verification
# programs and the unit tests) with make -j2: about half the CPU time of compiling file by file
# (the measurements, and what was tried besides: docs/history.md, "The two commands in under four
# minutes" and "make verify's CPU time, second pass").
# The computed values are the same (the same flags for every file; inlining across files does not
# change IEEE arithmetic without fast-math or contraction).
#
# What it costs: a folder's unit is compiled again when any of its files changes, and inside a
# folder the names in unnamed namespaces must differ between files. So while you edit a file,
# `make UNITY=0 ...` compiles file by file: every file on its own includes, as the sanitizer
# builds (mk/sanitizers.mk) always do. UNITY=0 is the plain build of the Makefile; this file only
# replaces its object lists.
UNITY ?= 1
ifeq ($(UNITY),1)

# The units of a list of files: one per folder (src/flow/a.cpp and src/flow/b.cpp ->
# $(BUILD)/unity/src-flow.cpp), and their objects (compiled by the Makefile's one compile rule).
unit_src = $(patsubst %,$(BUILD)/unity/%.cpp,$(subst /,-,$(sort $(patsubst %/,%,$(dir $(1))))))
units = $(call obj,$(call unit_src,$(1)))

LIB_OBJ     := $(call units,$(LIB_SRC)) $(call obj,$(EMBED_SRC) $(ID_SRC))
CLI_OBJ     := $(call units,$(CLI_SRC))
HARNESS_OBJ := $(call units,$(HARNESS_SRC))
STUDY_OBJ   := $(call units,$(STUDY_SRC))
FLOW_OBJ    := $(call units,$(FLOW_SRC))
# The unit tests are one unit, whatever their folder: every test file parses the same heavy headers
# (Boost.Test, Eigen, the solvers'), which one unit per test folder parsed once per folder (the
# measurement: docs/history.md). tests/main.cpp defines the test program's entry
# (BOOST_TEST_MODULE before Boost.Test's header): a unit of its own.
UNITY_ALONE := tests/main.cpp
TEST_UNIT   := $(BUILD)/unity/tests.cpp
TEST_OBJ    := $(call obj,$(TEST_UNIT) $(UNITY_ALONE))

# A folder's unit (src-flow: the files of src/flow in name order), written by tools/unity_unit.sh,
# which leaves it untouched while the list of files stays the same.
$(call unit_src,$(LIB_SRC) $(CLI_SRC) $(HARNESS_SRC) $(STUDY_SRC)): $(BUILD)/unity/%.cpp: FORCE
	@tools/unity_unit.sh $@ $(sort $(wildcard $(subst -,/,$*)/*.cpp))
# The tests' unit: every test file but the entry, in name order.
$(TEST_UNIT): FORCE
	@tools/unity_unit.sh $@ $(filter-out $(UNITY_ALONE),$(TEST_SRC))

endif
