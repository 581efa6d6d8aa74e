# SPDX-License-Identifier: MIT
# mk/bench.mk: benchmarks (make bench, make step-cost). They write
# host_tests/bench/ and docs/performance.md, never README.md.
#
# engine step cost against N and against the naive O(N) force sum (one run)
.PHONY: bench step-cost
$(B)/host/bench_engine: host_tests/bench_engine.c host_tests/bench_scene.h $(B)/host/libmdr.a
	$(HOSTCC) -std=c99 -Wall -Wextra -Werror -Ilib/include -O2 $< $(B)/host/libmdr.a -lm -o $@
# instructions per step on the emulated Cortex-M4F and M3 (QEMU -icount
# shift=0; the M3 build runs the step from RAM, as in target-test)
BENCH_CORE_m4 := Cortex-M4F
BENCH_CORE_m3 := Cortex-M3
$(B)/tgt-%/bench_target.elf: host_tests/target/bench_target.c host_tests/bench_scene.h host_tests/bench_matrix.h host_tests/scenes.h $(B)/tgt-%/libmdr.a $(MDR_CM_STARTUP) $(MDR_CM_LDSCRIPT)
	$(TGT_$*) -DMDR_PORT_CYCLES_SYSTICK -DBENCH_CORE='"$(BENCH_CORE_$*)"' $(BENCH_TGT_$*) $(TGT_TEST_CFLAGS) $< \
	  $(MDR_CM_STARTUP) $(B)/tgt-$*/libmdr.a $(MDR_CM_LDFLAGS) -lm -o $@
# the M4F also counts the rows of the benchmark matrix
BENCH_TGT_m4 := -DBENCH_MATRIX
# Instructions per tick of every engine, arithmetic, core and cycle
# (host_tests/target/step_cost.c: QEMU -icount shift=7, exact counts per
# tick), one CSV line each: engine,arith,core,cycle,mean,max,separated,
# pinned,moving; written to $(B)/bench/step_cost.csv and, as a table with
# the goals of issue 20 (mk/step_cost.awk), into docs/performance.md between
# the step-cost markers (make bench runs it first).
STEPCOST_CORE_m4 := m4f
STEPCOST_CORE_m3 := m3
$(B)/tgt-%/step_cost.elf: host_tests/target/step_cost.c host_tests/bench_scene.h $(B)/tgt-%/libmdr.a $(MDR_CM_STARTUP) $(MDR_CM_LDSCRIPT)
	$(TGT_$*) -DMDR_PORT_CYCLES_SYSTICK -DBENCH_CORE='"$(STEPCOST_CORE_$*)"' $(TGT_TEST_CFLAGS) $< \
	  $(MDR_CM_STARTUP) $(B)/tgt-$*/libmdr.a $(MDR_CM_LDFLAGS) -lm -o $@
step-cost: $(B)/tgt-m4/step_cost.elf $(B)/tgt-m3/step_cost.elf
	@mkdir -p $(B)/bench
	@for c in m4 m3; do port/cortex-m/run-qemu -M $$( [ $$c = m4 ] && echo $(QEMU_m4) || echo $(QEMU_m3) ) -shift 7 \
	  -t 600 $(B)/tgt-$$c/step_cost.elf > $(B)/bench/step_cost_$$c.log || { cat $(B)/bench/step_cost_$$c.log; exit 1; }; done
	@{ grep -h '^engine,' $(B)/bench/step_cost_m4.log; grep -hv '^engine,\|^#' $(B)/bench/step_cost_m4.log $(B)/bench/step_cost_m3.log; } \
	  > $(B)/bench/step_cost.csv
	@grep -h '^#' $(B)/bench/step_cost_m4.log $(B)/bench/step_cost_m3.log; cat $(B)/bench/step_cost.csv
	@awk -F, -f mk/step_cost.awk $(B)/bench/step_cost.csv > $(B)/bench/step_cost.md
	@awk -v name=step-cost -f mk/splice.awk $(B)/bench/step_cost.md docs/performance.md > $(B)/bench/performance.md \
	  && cp $(B)/bench/performance.md docs/performance.md
	@echo "step-cost: $(B)/bench/step_cost.csv written; docs/performance.md's step-cost table updated"
# Where one line's instructions go: make step-trace [TRACE=scene,q31,afm]
# [CORE=m3|m4] [CLASS=moving|pinned|separated|all|worst] [DEPTH=1] [TOP=25] [TRACE_TIMEOUT=600].
# step_cost.c runs that line alone (-DSTEP_TRACE), against a copy of the
# core's library with -g (same code), under QEMU's instruction trace
# (-singlestep -d exec,nochain); mk/step_trace.py checks the trace's ticks
# against the counted ones and prints the TOP largest of the class's
# instructions per tick by function (with DEPTH - 1 of its inlining callers)
# and by source line, and what the rest add up to (about two minutes; the
# trace goes through a pipe, nothing large is written). The variables are
# checked before anything is built (one line, make stops).
TRACE ?= scene,q31,afm
CORE ?= m3
CLASS ?= moving
DEPTH ?= 1
TOP ?= 25
# (QEMU's limit in seconds: a busy machine can pass 600 on a q31 grips line)
TRACE_TIMEOUT ?= 600
.PHONY: step-trace
ifneq ($(filter step-trace,$(MAKECMDGOALS)),)
override CORE := $(patsubst m4f,m4,$(CORE))
comma := ,
TRACE_W := $(subst $(comma), ,$(TRACE))
ifneq ($(words $(TRACE_W)) $(filter spring scene,$(word 1,$(TRACE_W))) $(filter f32 q31,$(word 2,$(TRACE_W))) \
      $(filter grips afm,$(word 3,$(TRACE_W))),3 $(TRACE_W))
$(error step-trace: TRACE=$(TRACE) is not a line of make step-cost (engine,arith,cycle: spring|scene,f32|q31,grips|afm))
endif
ifeq ($(filter m3 m4,$(CORE)),)
$(error step-trace: CORE=$(CORE) is not a core it traces (m3, m4 or m4f))
endif
ifeq ($(filter moving pinned separated all worst,$(CLASS)),)
$(error step-trace: CLASS=$(CLASS) is not a tick class (moving, pinned, separated, all or worst))
endif
ifeq ($(shell echo '$(DEPTH) $(TOP)' | grep -Ex '[1-9][0-9]{0,2} [1-9][0-9]{0,3}'),)
$(error step-trace: DEPTH=$(DEPTH) and TOP=$(TOP) must be counts from 1)
endif
ifeq ($(shell echo '$(TRACE_TIMEOUT)' | grep -Ex '[1-9][0-9]{0,4}'),)
$(error step-trace: TRACE_TIMEOUT=$(TRACE_TIMEOUT) must be whole seconds from 1)
endif
endif
TRACE_CC_m3 = $(TGT_m3)
TRACE_CC_m4 = $(TGT_m4) -DMDR_STEP_SECTION='".ramfunc"'
$(B)/trace-%/libmdr.a: $(LIB_DEPS)
	@mkdir -p $(@D)
	for o in $(TGT_LIB_OBJS); do $(TRACE_CC_$*) $(MDR_REQUIRED_CFLAGS) -O2 -g $(WARN) -Ilib/include \
	  -c lib/src/$$o.c -o $(@D)/$$o.o || exit 1; done
	rm -f $@ && $(MDR_CM_PREFIX)ar rcs $@ $(addprefix $(@D)/,$(addsuffix .o,$(TGT_LIB_OBJS)))
step-trace: $(B)/trace-$(CORE)/libmdr.a host_tests/target/step_cost.c mk/step_trace.py
	$(TRACE_CC_$(CORE)) -g -DMDR_PORT_CYCLES_SYSTICK -DBENCH_CORE='"$(STEPCOST_CORE_$(CORE))"' \
	  -DSTEP_TRACE='"$(TRACE)"' $(TGT_TEST_CFLAGS) host_tests/target/step_cost.c \
	  $(MDR_CM_STARTUP) $< $(MDR_CM_LDFLAGS) -lm -o $(B)/trace-$(CORE)/step_trace.elf
	@d=$(B)/trace-$(CORE); f=$$(/usr/bin/python3 mk/step_trace.py $$d/step_trace.elf --dfilter --line $(TRACE) \
	    --class $(CLASS) --depth $(DEPTH) --top $(TOP) --prefix $(MDR_CM_PREFIX)) || exit 2; \
	  rm -f $$d/qemu.fifo && mkfifo $$d/qemu.fifo && \
	  { /usr/bin/python3 mk/step_trace.py $$d/step_trace.elf $$d/qemu.fifo $$d/ticks.log --line $(TRACE) \
	      --class $(CLASS) --depth $(DEPTH) --top $(TOP) --prefix $(MDR_CM_PREFIX) & } && \
	  timeout $(TRACE_TIMEOUT) qemu-system-arm -M $(QEMU_$(CORE)) -nographic -monitor none -serial none \
	    -semihosting-config enable=on,target=native -icount shift=7 -singlestep -d exec,nochain \
	    -dfilter $$f \
	    -D $$d/qemu.fifo -kernel $$d/step_trace.elf > $$d/ticks.log; q=$$?; wait $$!; p=$$?; \
	  rm -f $$d/qemu.fifo; [ $$q -eq 0 ] || { echo "step-trace: QEMU failed"; cat $$d/ticks.log; exit 1; }; exit $$p
# The benchmark matrix (host_tests/bench_matrix.c): time and error on the
# host, instructions from callgrind (one dump per row, divided by the row's
# evaluations) and from the M4F run above; CSV, Markdown and the plot are
# written to host_tests/bench/ (docs/performance.md shows the summary).
BENCH_OUT := host_tests/bench
$(B)/host/bench_matrix: host_tests/bench_matrix.c host_tests/bench_matrix.h host_tests/scenes.h host_tests/naive_sum.h $(REF_SRC) ref/mdr_ref.h $(B)/host/libmdr.a
	$(HOSTCC) $(TEST_CFLAGS) -O2 $< $(REF_SRC) $(B)/host/libmdr.a $(GSL_LIBS) -o $@
bench: step-cost $(B)/host/bench_engine $(B)/host/bench_matrix $(B)/tgt-m4/bench_target.elf $(B)/tgt-m3/bench_target.elf
	@mkdir -p $(B)/bench $(BENCH_OUT)
	./$(B)/host/bench_engine
	port/cortex-m/run-qemu -M $(QEMU_m4) -icount -t 1200 $(B)/tgt-m4/bench_target.elf > $(B)/bench/m4.log || { cat $(B)/bench/m4.log; exit 1; }
	@grep -v '^M4,' $(B)/bench/m4.log; grep '^M4,' $(B)/bench/m4.log | sed 's/^M4,//' > $(B)/bench/m4.csv
	port/cortex-m/run-qemu -M $(QEMU_m3) -icount -t 600 $(B)/tgt-m3/bench_target.elf
	@rm -rf $(B)/bench/cg && mkdir -p $(B)/bench/cg
	valgrind --tool=callgrind --callgrind-out-file=$(B)/bench/cg/cg.out ./$(B)/host/bench_matrix callgrind 2> $(B)/bench/callgrind.log || { cat $(B)/bench/callgrind.log; exit 1; }
	@for f in $(B)/bench/cg/cg.out.*; do awk -f mk/callgrind_rows.awk $$f; done > $(B)/bench/host_instr.csv
	./$(B)/host/bench_matrix time --host-instr $(B)/bench/host_instr.csv --m4 $(B)/bench/m4.csv \
	  --csv $(BENCH_OUT)/bench.csv --md $(BENCH_OUT)/bench.md --plot $(B)/bench/plot.dat
	gnuplot -e "datafile='$(B)/bench/plot.dat'; outfile='$(BENCH_OUT)/bench.png'" host_tests/bench_plot.gp
	@awk -v name=bench -v from='## Summary' -v to='## Every row' -f mk/splice.awk \
	  $(BENCH_OUT)/bench.md docs/performance.md > $(B)/bench/performance.md && cp $(B)/bench/performance.md docs/performance.md
	@echo "bench: $(BENCH_OUT)/bench.csv, bench.md, bench.png written; docs/performance.md's summary updated"
