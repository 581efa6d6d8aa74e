# SPDX-License-Identifier: MIT
# mk/fit.mk: fitting measured force curves (lib/include/mdr_fit.h, the
# `mdr fit` command), included at the end of the Makefile.
#
#   test_fit        cmocka suite (plain, ASan+UBSan, and on the emulated
#                   Cortex-M4F: make test-target)
#   fit-cli         host_tests/test_fit_cli.sh: the `mdr fit` contract and
#                   an engine-to-fit round trip (in make test, via host-tests)
#   make bench-fit  curves/s/core, forward model cost per point, callgrind
#                   instructions per curve -> host_tests/bench/fit.md and
#                   docs/fitting.md (between its bench-fit markers); also
#                   run by make bench
#   make fit-plot   the documentation's plot of a fitted curve over its data
#                   (docs/fit_curve.png, gnuplot)
#   make test-fit-known  the fit's known, open defects (test_fit built with
#                   -DMDR_FIT_KNOWN_DEFECTS: the tests that fail until they
#                   are fixed, named in FIT_KNOWN_DEFECTS below or
#                   TESTS_KNOWN=...; not in make test, and it exits 1 while
#                   one fails; docs/fitting.md lists them). Open: a curved
#                   baseline (stop 40). A tilted one (stop 39) is fixed and
#                   in make test (test_tilt)

TESTS += test_fit
SAN_TESTS += test_fit
TGT_TESTS_m4 += test_fit
# first: a long target run starts while the other lane works through the
# rest (at the end of the list it ran alone last). Left out of make test on
# the M4F (mk/target.mk, TGT_SKIP; TARGET_TEST=full runs them): the noise,
# data-order, unit-scale and reversed-curve sweeps and the closed-form
# sweep (111 of its 173 s of QEMU in soft double), and the noise-free
# piezo-offset sweep (test_pinned_offset_clean, 486 fits); the round trips of every
# profile and arithmetic, the pinned tops and the other refusals run.
TGT_SKIP_m4_test_fit := test_noise,test_fit_sweep,test_reversed,test_order_short_tail,test_order_coarse
TGT_SKIP_m4_test_fit := $(TGT_SKIP_m4_test_fit),test_refuse_units,test_order_baseline_step,test_pinned_offset_clean
TGT_RUNS := $(B)/tgt-m4/test_fit.run $(TGT_RUNS)

# test_fit is built by the suite rules of mk/tests.mk
host-tests: $(B)/host/test_fit fit-cli
san-tests: $(B)/san/test_fit

# the CLI: `mdr fit` lives in examples/mdr_fit_cli.h (threads: -pthread,
# for this program only)
$(B)/host/mdr: examples/mdr_fit_cli.h examples/mdr_fit_cli_t.h
$(B)/host/mdr: private override CFLAGS += -pthread

# the tests of the known, open defects (cmocka's filter: names, * and ?);
# (test_f32_pinned_offset and test_tilt, fixed, are in make test)
FIT_KNOWN_DEFECTS := test_known_*
.PHONY: fit-cli bench-fit fit-plot test-fit-known
test-fit-known: $(B)/host/libmdr.a
ifeq ($(strip $(or $(TESTS_KNOWN),$(FIT_KNOWN_DEFECTS))),)
	@echo "test-fit-known: no known, open defects of the fit (docs/fitting.md); TESTS_KNOWN=... runs named tests"
else
	$(HOSTCC) $(TEST_CFLAGS) $(CFLAGS) -DMDR_FIT_KNOWN_DEFECTS host_tests/test_fit.c $(B)/host/libmdr.a -lcmocka -lm \
	  -o $(B)/host/test_fit_known
	MDR_FIT_TESTS='$(or $(TESTS_KNOWN),$(FIT_KNOWN_DEFECTS))' ./$(B)/host/test_fit_known
endif
fit-cli: $(B)/host/mdr
	@echo "== fit cli"; bash host_tests/test_fit_cli.sh $(B)/host/mdr

# ---- benchmark ----------------------------------------------------------------
$(B)/host/bench_fit: host_tests/bench_fit.c host_tests/noise.h $(B)/host/libmdr.a
	$(HOSTCC) -std=c99 -D_GNU_SOURCE -Wall -Wextra -Werror -Ilib/include -O2 $< $(B)/host/libmdr.a -lm -o $@
# the map figure: curves of the bench's scene through `mdr fit --map`, one
# thread and all cores (wall clock of the same run)
FIT_MAP_CURVES := 512
bench-fit: $(B)/host/bench_fit $(B)/host/mdr
	@mkdir -p $(B)/bench/fitcg $(BENCH_OUT)
	./$(B)/host/bench_fit time --md $(B)/bench/fit_time.md
	@rm -f $(B)/bench/fitcg/cg.out*
	valgrind --tool=callgrind --callgrind-out-file=$(B)/bench/fitcg/cg.out ./$(B)/host/bench_fit callgrind \
	  2> $(B)/bench/fitcg/log || { cat $(B)/bench/fitcg/log; exit 1; }
	@{ cat $(B)/bench/fit_time.md; echo; \
	  echo "| callgrind (instructions, host build $(CFLAGS)) | per curve | per model point |"; \
	  echo "| --- | ---: | ---: |"; \
	  for f in $(B)/bench/fitcg/cg.out.*; do awk -f mk/callgrind_fit.awk $$f; done; \
	} > $(BENCH_OUT)/fit.md
	@bash host_tests/bench_fit_map.sh $(B)/host/mdr $(FIT_MAP_CURVES) >> $(BENCH_OUT)/fit.md
	@cat $(BENCH_OUT)/fit.md
	@awk -v name=bench-fit -f mk/splice.awk $(BENCH_OUT)/fit.md docs/fitting.md > $(B)/bench/fitting.md && \
	  cp $(B)/bench/fitting.md docs/fitting.md
	@echo "bench-fit: $(BENCH_OUT)/fit.md written; docs/fitting.md's table updated"
bench: bench-fit

# ---- the documentation's plot -------------------------------------------------------
fit-plot: $(B)/host/mdr
	@mkdir -p $(B)/fitplot docs
	bash host_tests/fit_plot.sh $(B)/host/mdr $(B)/fitplot docs/fit_curve.png
$(B)/tgt-m4/test_fit.elf: host_tests/noise.h host_tests/test_util.h
