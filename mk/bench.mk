# make bench: the benchmarks and long studies, one after another (not part of make verify).
# make bench runs every benchmark; make bench BENCH="bench_a bench_b" only those, with BENCH_ARGS on
# each one's command line (e.g. BENCH=bench_fig7_convergence BENCH_ARGS="--cells 25,35,50 --t-end 4").
BENCH ?= $(notdir $(BENCH_BIN))
BENCH_ARGS ?=
BENCH_RC := $(BENCH:%=$(BUILD)/bench-results/%.rc)
# The figures of the benchmarks run: the bench*.gp whose '# needs:' line names one of them.
BENCH_RUN_PNG = $(foreach gp,$(BENCH_GP),$(if $(filter $(BENCH),$(shell sed -n 's/^# needs://p' $(gp))),$(gp:figures/%.gp=$(BUILD)/figures/%.png)))

# One benchmark's run (run-bench: those of BENCH): output also in bench-results/, data in bench-data/.
$(BUILD)/bench-results/%.rc: $(BUILD)/bench/% $(CLI)
	@mkdir -p $(@D) $(BUILD)/bench-data
	@$< --data $(BUILD)/bench-data $(BENCH_ARGS) 2>&1 | tee $(BUILD)/bench-results/$*.log; echo $${PIPESTATUS[0]} > $@
run-bench: $(BENCH_RC)

# Benchmarks run one after another: timings taken while another benchmark runs are worthless.
bench: deps
	@$(if $(filter-out $(notdir $(BENCH_BIN)),$(BENCH)),echo "bench: BENCH: no benchmark $(filter-out $(notdir $(BENCH_BIN)),$(BENCH)) (allowed: $(notdir $(BENCH_BIN)))"; exit 2,true)
	@$(MAKE) --no-print-directory -j$(JOBS) $(LIB) $(CLI) $(BENCH:%=$(BUILD)/bench/%)
	@rm -f $(BENCH_RC)
	@$(MAKE) --no-print-directory -j1 run-bench
	@rm -f $(BENCH_RUN_PNG)
	@$(MAKE) --no-print-directory -j$(JOBS) $(BENCH_RUN_PNG)
