# The order in which make verify builds and runs: what it buys is wall time, nothing else.
#
# One make builds, runs and renders (the Makefile's verify), and starts whatever is ready when a
# core frees up; the order of a list alone does not make the longest programs run first. Left to
# itself make linked and ran short programs while the longest waited, and compiled the unit
# tests' large unit last, so that a long program ran alone at the end while the other core waited.
# Measured on clean clones, .ci/run on two cores shared with other work (load average 6 to 12):
# 518 s with these rules, 703 s without them (one run each; without them verify_flow_rotation,
# the longest program, finished last and alone).
# Both rules hold only when make verify runs every program (the goal run-verification): a program
# built on its own waits for nothing.
ifneq ($(filter run-verification,$(MAKECMDGOALS)),)
# The other programs link only after the longest ones (VERIFY_FIRST, in the Makefile)...
VERIFY_FIRST_BIN := $(filter $(VERIFY_FIRST:%=$(BUILD)/verification/%),$(VERIFY_BIN))
$(filter-out $(VERIFY_FIRST_BIN),$(VERIFY_BIN)): | $(VERIFY_FIRST_BIN)
# ...and those link only after the unit tests compiled, when make verify builds them too.
$(VERIFY_FIRST_BIN): | $(if $(filter $(TEST_BIN),$(MAKECMDGOALS)),$(TEST_OBJ))
endif
