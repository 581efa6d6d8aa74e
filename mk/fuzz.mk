# SPDX-License-Identifier: MIT
# mk/fuzz.mk: libFuzzer targets (make fuzz) and the replay of the committed
# corpus under ASan+UBSan (make fuzz-replay); both in make test.
#
# Fuzzing (host_tests/fuzz/): libFuzzer targets for the init functions
# (fuzz_init), the tabulated-profile parser and gap tables (fuzz_table) and
# the step functions with arbitrary input sequences (fuzz_step), built with
# clang -fsanitize=fuzzer,address,undefined. make fuzz runs each for
# FUZZ_RUNS inputs from seed 1 and a fresh working corpus (in make test:
# the same seed and count on every machine; libFuzzer's path, coverage and
# time still vary from run to run: docs/accuracy.md), or with FUZZ_TIME=600 for that many
# seconds from a random seed and the working corpus kept in build/fuzz/
# (the long run, on demand), always from the committed corpus too; an
# input that fails is copied into host_tests/fuzz/corpus/<target>/ (commit
# it: from then on it is a regression test) and the run fails.
# make fuzz-replay runs the committed corpus through the same targets built
# with gcc and ASan+UBSan (host_tests/fuzz/replay.c), no libFuzzer needed.
# Both are in make test.
.PHONY: fuzz fuzz-replay
FUZZ_TARGETS := init step table
FUZZ_TIME ?=
FUZZ_RUNS ?= 3000
# libFuzzer's limit per input, seconds: a hang's, not a slow input's. The
# library's longest bounded calls (a wavy critical search at its scan cap,
# MDR_CRIT_SCAN_MAX cells: MDR_E_NOCONV) take about 2 s each under the
# sanitizers on an idle host; stop 75's CI met one input (f64 and f32: 4.4 s
# alone) beyond the 10 s that was the limit, with the host busy
FUZZ_TIMEOUT ?= 60
FUZZ_ARGS = $(if $(FUZZ_TIME),-max_total_time=$(FUZZ_TIME) -seed=0,-runs=$(FUZZ_RUNS) -seed=1)
FUZZ_HDRS := host_tests/fuzz/fuzz.h host_tests/fuzz/fuzz_engine_t.h host_tests/fuzz/fuzz_init_t.h examples/tip_csv.h
FUZZ_CFLAGS := -std=c99 -fno-math-errno -D_GNU_SOURCE -Wall -Wextra -Werror -Ilib/include -Iport/host -Iexamples
# the library instrumented once (-fsanitize=fuzzer-no-link: libFuzzer's
# coverage without its main), linked into each target (each target
# compiling the library itself took three times the 35 s)
FUZZ_SAN := -fsanitize=address,undefined -fno-sanitize-recover=all
$(B)/fuzz/lib/%.o: lib/src/%.c $(LIB_DEPS)
	@mkdir -p $(@D)
	clang -g -O1 -fsanitize=fuzzer-no-link $(FUZZ_SAN) $(FUZZ_CFLAGS) -c $< -o $@
FUZZ_LIB_OBJS := $(addprefix $(B)/fuzz/lib/,$(addsuffix .o,$(basename $(notdir $(LIB_SRC)))))
.SECONDARY: $(FUZZ_LIB_OBJS)
$(B)/fuzz/fuzz_%: host_tests/fuzz/fuzz_%.c $(FUZZ_HDRS) $(FUZZ_LIB_OBJS)
	@mkdir -p $(@D)
	clang -g -O1 -fsanitize=fuzzer $(FUZZ_SAN) $(FUZZ_CFLAGS) $< $(FUZZ_LIB_OBJS) -lm -o $@
$(B)/san/replay_%: host_tests/fuzz/fuzz_%.c host_tests/fuzz/replay.c $(FUZZ_HDRS) $(B)/san/libmdr.a
	$(HOSTCC) $(FUZZ_CFLAGS) -O1 -g $(SAN) $< host_tests/fuzz/replay.c $(B)/san/libmdr.a -lm -o $@
fuzz-replay: $(addprefix $(B)/san/replay_,$(FUZZ_TARGETS))
	@for t in $(FUZZ_TARGETS); do printf '== fuzz corpus %s: ' $$t; \
	  ./$(B)/san/replay_$$t host_tests/fuzz/corpus/$$t || exit 1; done
# one fuzzer's run (its output in $(B)/fuzz/<target>.log, its summary line
# in .sum); make fuzz runs the targets two at a time (-j2) and prints the
# summaries in order; a failing input is copied into the corpus
$(B)/fuzz/%.run: $(B)/fuzz/fuzz_%
	@rm -f $@; t=$*; w=$(B)/fuzz/work_$$t; rm -rf $(B)/fuzz/art_$$t; $(if $(FUZZ_TIME),,rm -rf $$w;) \
	  mkdir -p $$w $(B)/fuzz/art_$$t; \
	  if ./$< $(FUZZ_ARGS) -timeout=$(FUZZ_TIMEOUT) -rss_limit_mb=2048 \
	       -artifact_prefix=$(B)/fuzz/art_$$t/ $$w host_tests/fuzz/corpus/$$t > $(B)/fuzz/$$t.log 2>&1; then \
	    echo "== fuzz $$t: $$(grep -o 'Done [0-9]* runs in [0-9]* second' $(B)/fuzz/$$t.log | tail -1)s, \
	      coverage $$(grep -o 'cov: [0-9]*' $(B)/fuzz/$$t.log | tail -1 | cut -d' ' -f2), no failure" > $(B)/fuzz/$$t.sum; \
	  else \
	    tail -40 $(B)/fuzz/$$t.log; cp $(B)/fuzz/art_$$t/* host_tests/fuzz/corpus/$$t/; \
	    echo "fuzz $$t: failing input copied to host_tests/fuzz/corpus/$$t/ (commit it)"; exit 1; \
	  fi; touch $@
FUZZ_RUNS_ALL := $(addprefix $(B)/fuzz/,$(addsuffix .run,$(FUZZ_TARGETS)))
fuzz: $(addprefix $(B)/fuzz/fuzz_,$(FUZZ_TARGETS))
	@rm -f $(FUZZ_RUNS_ALL)
	@$(MAKE) --no-print-directory $(SUB_J2) $(FUZZ_RUNS_ALL)
	@for t in $(FUZZ_TARGETS); do cat $(B)/fuzz/$$t.sum; done
