# Targets for the pages and the long studies, beyond the two commands (docs/checked_pages.md).

# make figures-full: the long studies' figures, one job at a time: they may first run the Fig. 7
# drum (make fig7) and a benchmark that has not run yet, whose timings are worthless side by side.
FULL_BENCHES = $(sort $(filter bench_%,$(foreach gp,$(FULL_GP),$(shell sed -n 's/^# needs://p' $(gp)))))
figures-full:
	@for b in $(FULL_BENCHES); do [ -f $(BUILD)/bench-results/$$b.rc ] || $(MAKE) --no-print-directory bench BENCH=$$b || exit 1; done
	@$(if $(FULL_PNG),$(MAKE) --no-print-directory -j1 $(FULL_PNG),echo "figures-full: no long studies yet (figures/full*.gp)")

# make docs-refresh: every fresh generated table (a program writes NAME.md into $(BUILD)/data or
# $(BUILD)/bench-data) copied into docs/generated/NAME.md and into the pages' blocks that show it.
docs-refresh:
	@$(BUILD)/verification/verify_docs --refresh

# make docs-figures: the figures the pages show on a fresh clone, committed under docs/figures/
# (docs/checked_pages.md). Drawn by the same scripts as build/figures/ (with small=1: 800 pixels
# wide) from the data of the verification programs, which run first if their results are stale;
# then verify_docs records a fingerprint of the data each was drawn from, by which make verify
# tells a stale image.
DOC_FIGURES := fig_closures fig_direction fig3_integral_curves fig4a_regions fig4b_regions \
               fig5_region_c_example fig6a_profiles fig6b_closeup fig7b_kinematic \
               fig7a_tumbler_kinematic fig7b_tumbler_kinematic fig7c_tumbler_kinematic \
               fig_tutorial_regions fig_tutorial_drum fig_tutorial_coupled

# The Fig. 7 study's figures come from a benchmark, Fig. 7c/7d at 100 cells from make fig7's run:
# drawn when their data is there (make bench BENCH=bench_fig7_convergence, make fig7), else left as
# they are.
DOC_BENCH_FIGURES := bench_fig7_convergence bench_fig7_work full_fig7c_tumbler full_fig7d_tumbler full_fig7cd_tumbler \
                     bench_drum_shapes

docs-figures:
	@$(MAKE) --no-print-directory -j$(JOBS) $(LIB) $(CLI) $(VERIFY_BIN)
	@$(MAKE) --no-print-directory -j$(JOBS) -O $(DOC_FIGURES:%=$(BUILD)/figures/%.png)
	@drawn="$(DOC_FIGURES)"; \
	for f in $(DOC_BENCH_FIGURES); do \
	  first=$$(sed -n 's/^# reads: *\([^ ]*\).*/\1/p' figures/$$f.gp); \
	  if [ -f $(BUILD)/bench-data/$$first ] || [ -f $(RUNS)/$$first ]; then drawn="$$drawn $$f"; \
	  else echo "docs-figures: $$f kept (its benchmark has not run)"; fi; \
	done; \
	for f in $$drawn; do \
	  gnuplot -e "$(GNUPLOT_DIRS); outfile='docs/figures/$$f.png.tmp'; small=1" figures/$$f.gp \
	    && mv docs/figures/$$f.png.tmp docs/figures/$$f.png && echo "docs-figures: docs/figures/$$f.png" \
	    || { rm -f docs/figures/$$f.png.tmp; echo "docs-figures: FAILED $$f"; exit 1; }; \
	done; \
	$(BUILD)/verification/verify_docs --fingerprint $$drawn

# make exercises: each exercise of docs/tutorial.md applied by its reference solution
# (verification/exercises/NAME.patch) to a scratch copy of the tree, built, and judged by the checks
# the page names; fails when a verdict differs from the page's (tools/exercises.sh). On demand, not
# part of make verify: it rebuilds what each patch touches, minutes on two cores.
exercises: $(LIB) $(CLI) $(VERIFY_BIN)
	@tools/exercises.sh $(BUILD) $(JOBS)

# make commands-cost: what the README's two commands cost on a fresh clone of the commit (several
# minutes: the whole of make verify, then make test), tabled as build/runs/commands_cost.md with its
# provenance record; make docs-refresh copies it into README.md. Run it on a quiet machine.
commands-cost:
	@mkdir -p $(RUNS)
	@tools/commands_cost.sh $(RUNS)/commands_cost.md
