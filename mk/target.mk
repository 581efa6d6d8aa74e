# SPDX-License-Identifier: MIT
# mk/target.mk: the target tests on QEMU (make target-test, in make test).
#
# Built per core with its port (port/cortex-m: startup, board linker
# scripts, semihosting, newlib; port/riscv: the same with picolibc) and run
# by the port's run-qemu:
#   m4        Cortex-M4F, mps2-an386: the unit tests, the library against
#             the committed ref/ vectors (read from ref/vectors through
#             semihosting), the engine tests, the scene tests (whose f32
#             step fuses its multiply-adds here: MDR_PORT_FMA_F32), the q31
#             tests and trace
#   m7        Cortex-M7, mps2-an500: the same but the vector and engine
#             tests (the M4F's f32 and soft double again; TARGET_TEST=full
#             runs them: 44 s and 55 s of QEMU, cut from make test at stop
#             40 for CI time)
#   m3        Cortex-M3 (no FPU), mps2-an385: the q31 tests and trace, the
#             step placed in RAM (MDR_STEP_SECTION=".ramfunc")
#   m0        Cortex-M0, microbit (nRF51, 16 KB RAM): the q31 tests on
#             128-spring tables and the trace with its q31 tables const in
#             flash (`q31_trace --tables`, as a firmware with little RAM
#             does); the program reports the RAM it used (painted stack)
#             and fails where its stack overran the board script's
#             reserve (port/cortex-m/startup.c); linked with newlib-nano
#             (float printf kept), whose stdio and malloc take 2 KB less
#             of the 16 KB than newlib's
#   rv32imac, rv32imafc  RV32, virt: the q31 tests and trace
# q31_trace must print the committed fingerprint ($(Q31_EXPECTED), the
# host's) on every core: the q31 step is bit-exact across cores. Each test
# prints the same cmocka lines as on the host (host_tests/target/cmocka.h).
# TARGET_TEST=full also runs the unit, vector and engine tests on the M3 and
# both RV32 cores, and the vector and engine tests on the M7 (minutes more;
# not in make test). The vector test's f32
# rows must equal the host's bit for bit; on a core without an FPU square
# root (M3, RV32IMAC: lib/'s own routine) those of the host built with
# MDR_PORT_OWN_SQRT, whose CLI also makes that core's generated table for
# the engine test.
.PHONY: target-test
TGT_CORES := m4 m7 m3 m0 rv32imac rv32imafc
TGT_m4 := $(MDR_CM_PREFIX)gcc $(MDR_CM_FLAGS_m4f) -Iport/cortex-m
TGT_m7 := $(MDR_CM_PREFIX)gcc $(MDR_CM_FLAGS_m7) -Iport/cortex-m
TGT_m3 := $(MDR_CM_PREFIX)gcc $(MDR_CM_FLAGS_m3) -Iport/cortex-m -DMDR_STEP_SECTION='".ramfunc"'
TGT_m0 := $(MDR_CM_PREFIX)gcc $(MDR_CM_FLAGS_m0) -Iport/cortex-m
TGT_rv32imac := $(MDR_RV_PREFIX)gcc $(MDR_RV_FLAGS_rv32imac) $(MDR_RV_LIBC) -Iport/riscv
TGT_rv32imafc := $(MDR_RV_PREFIX)gcc $(MDR_RV_FLAGS_rv32imafc) $(MDR_RV_LIBC) -Iport/riscv
QEMU_m4 := mps2-an386
QEMU_m7 := mps2-an500
QEMU_m3 := mps2-an385
QEMU_m0 := microbit
QEMU_rv32imac := virt
QEMU_rv32imafc := virt
TGT_NAME_m4 := Cortex-M4F $(QEMU_m4)
TGT_NAME_m7 := Cortex-M7 $(QEMU_m7)
TGT_NAME_m3 := Cortex-M3 $(QEMU_m3)
TGT_NAME_m0 := Cortex-M0 $(QEMU_m0)
TGT_NAME_rv32imac := RV32IMAC virt
TGT_NAME_rv32imafc := RV32IMAFC virt
# (the longest first: test_engine's lane takes test_vectors while test_fit,
# mk/fit.mk, runs in the other; the short ones fill in after)
TGT_TESTS_m4 := test_engine test_vectors test_unit test_scene test_q31 q31_trace
TGT_TESTS_m7 := test_unit test_scene test_q31 q31_trace
TGT_TESTS_m3 := test_q31 q31_trace
TGT_TESTS_m0 := test_q31 q31_trace
TGT_TESTS_rv32imac := test_q31 q31_trace
TGT_TESTS_rv32imafc := test_q31 q31_trace
ifeq ($(TARGET_TEST),full)
$(foreach t,m3 rv32imac rv32imafc,$(eval TGT_TESTS_$(t) := test_vectors test_engine test_unit $(TGT_TESTS_$(t))))
TGT_TESTS_m7 += test_vectors test_engine
endif
# The tests a core's program leaves out in make test (TGT_SKIP_<core>_<program>,
# comma-separated names; host_tests/target/cmocka.h): sweeps that take most
# of a program's QEMU time in soft double and run whole on the host, under
# the sanitizers and in the mutation gate; every function they call runs on
# the core in the program's other tests (test_unit's: on the M7, below).
# TARGET_TEST=full runs them (stop 76: 216 s of the M4F's QEMU time with
# test_fit's, mk/fit.mk, which with the phase's other runs kept CI above its
# 15 minutes). The M4F's
# test_engine: the sampled-profile rim sweep, the seed's wavy cycle of Fig.
# 4.9 in f64, the coarse tables' first equilibrium and the rims on nodes (75
# of its 183 s).
TGT_SKIP_m4_test_engine := rim_in_spring0_sampled,wavy_seed_fig_4_9,first_equilibrium_coarse_tables,rims_on_nodes
# The M4F's test_unit: the f64 math kernels' sweep and the wavy profile's
# critical states of Fig. 4.9 in f64 (30 of its 34 s), which the M7 runs
# with its double-precision FPU.
TGT_SKIP_m4_test_unit := math_kernels_f64,guduru_wavy_fig_4_9
tgt_skip = $(if $(filter full,$(TARGET_TEST)),,$(TGT_SKIP_$(1)_$(2)))
.PHONY: FORCE
FORCE:
# cores without an FPU square root: the host reference built with lib/'s own
TGT_OWNSQRT := m3 rv32imac
tgt_ref = $(B)/$(if $(filter $(1),$(TGT_OWNSQRT)),ownsqrt/)host
# the test programs' extra flags and inputs per core
TGT_TFLAGS_m0 := -DNSPR=128 -DQ31_TRACE_TABLES -I$(B)/host -DMDR_RAM_REPORT
TGT_TDEPS_m0 := $(B)/host/q31_trace_tables.h
# startup, linker script and libc per port; the runner
TGT_START_cm := $(MDR_CM_STARTUP) $(wildcard port/cortex-m/*.ld) port/target.h
TGT_START_rv := $(MDR_RV_STARTUP) $(MDR_RV_LDSCRIPT) port/target.h
tgt_port = $(if $(filter rv%,$(1)),rv,cm)
TGT_LD_m0 := $(call mdr_cm_ldflags,port/cortex-m/microbit.ld) --specs=nano.specs -u _printf_float
tgt_ld = $(or $(TGT_LD_$(1)),$(if $(filter rv%,$(1)),$(MDR_RV_LDFLAGS),$(MDR_CM_LDFLAGS)))
tgt_run = $(if $(filter rv%,$(1)),port/riscv/run-qemu,port/cortex-m/run-qemu -M $(QEMU_$(1)))
TGT_TEST_CFLAGS := -std=c99 -D_GNU_SOURCE -DMDR_TARGET_TEST -O2 -Wall -Wextra -Werror \
                   -Ihost_tests/target -Ilib/include -Iref
TGT_LIB_OBJS := mdr_f32 mdr_f64 mdr_q31 mdr_status

define target_rules
$(B)/tgt-$(1)/libmdr.a: $(LIB_DEPS)
	@mkdir -p $(B)/tgt-$(1)
	for o in $(TGT_LIB_OBJS); do $(TGT_$(1)) $(MDR_REQUIRED_CFLAGS) -O2 $(WARN) -Ilib/include \
	  -c lib/src/$$$$o.c -o $(B)/tgt-$(1)/$$$$o.o || exit 1; done
	rm -f $$@ && $(call xtool,$(1),ar) rcs $$@ $(addprefix $(B)/tgt-$(1)/,$(addsuffix .o,$(TGT_LIB_OBJS)))
# (the program's skip list in a stamp rewritten only when it changes, so
# that TARGET_TEST=full, or a list's edit, rebuilds it)
$(B)/tgt-$(1)/%.skip: FORCE
	@mkdir -p $$(@D); echo '$$(call tgt_skip,$(1),$$*)' | cmp -s - $$@ || echo '$$(call tgt_skip,$(1),$$*)' > $$@
$(B)/tgt-$(1)/%.elf: host_tests/%.c $(B)/tgt-$(1)/libmdr.a host_tests/target/cmocka.h $(B)/tgt-$(1)/%.skip \
  $(TGT_START_$(call tgt_port,$(1))) $(TGT_TDEPS_$(1))
	$(TGT_$(1)) $(TGT_TEST_CFLAGS) $(TGT_TFLAGS_$(1)) -DMDR_TARGET_SKIP='"$$(call tgt_skip,$(1),$$*)"' $$< $$(if $$(filter test_engine,$$*),$(call tgt_ref,$(1))/gen_tip.c) \
	  $(filter %.c,$(TGT_START_$(call tgt_port,$(1)))) $(B)/tgt-$(1)/libmdr.a $(call tgt_ld,$(1)) -lm -o $$@
$(B)/tgt-$(1)/test_engine.elf: $(call tgt_ref,$(1))/gen_tip.c
$(B)/tgt-$(1)/test_vectors.run: $(call tgt_ref,$(1))/test_vectors
$(B)/tgt-$(1)/q31_trace.run: $(Q31_EXPECTED)
# one QEMU run: its output in .log, a .run stamp when it passed
$(B)/tgt-$(1)/%.run: $(B)/tgt-$(1)/%.elf $(B)/host/q31_trace
	@rm -f $$@; t0=$$$$(date +%s%N); $(call tgt_run,$(1)) -t 600 $$< > $(B)/tgt-$(1)/$$*.log 2>&1 || \
	  { cat $(B)/tgt-$(1)/$$*.log; echo "target $(TGT_NAME_$(1)): $$* failed"; exit 1; }; \
	  d=$$$$((($$$$(date +%s%N) - t0) / 100000000)); echo "(wall $$$$((d / 10)).$$$$((d % 10)) s)" > $(B)/tgt-$(1)/$$*.time
	@if [ $$* = q31_trace ]; then \
	  grep -v '^target RAM ' $(B)/tgt-$(1)/q31_trace.log | cmp -s $(Q31_EXPECTED) - || \
	    { echo "target $(TGT_NAME_$(1)): q31 outputs differ from $(Q31_EXPECTED) (the host's)"; \
	      cat $(Q31_EXPECTED) $(B)/tgt-$(1)/q31_trace.log; exit 1; }; \
	  echo "q31 outputs identical to the host's ($(Q31_EXPECTED))" >> $(B)/tgt-$(1)/q31_trace.log; fi
	@if [ $$* = test_vectors ]; then \
	  ./$(call tgt_ref,$(1))/test_vectors 2>/dev/null | grep ' f32 ' > $(B)/tgt-$(1)/f32.host; \
	  grep ' f32 ' $(B)/tgt-$(1)/test_vectors.log | diff $(B)/tgt-$(1)/f32.host - || \
	    { echo "target $(TGT_NAME_$(1)): f32 errors differ from the host's ($(call tgt_ref,$(1)))"; exit 1; }; \
	  echo "f32 rows identical to the host's$(if $(filter $(1),$(TGT_OWNSQRT)), with lib/'s own sqrt,) (f32 results bit for bit)" \
	    >> $(B)/tgt-$(1)/test_vectors.log; fi
	@touch $$@
endef
$(foreach t,$(TGT_CORES),$(eval $(call target_rules,$(t))))

$(B)/host/q31_trace: host_tests/q31_trace.c $(B)/host/libmdr.a
	$(HOSTCC) -std=c99 $(WARN) -Ilib/include -O2 $< $(B)/host/libmdr.a -o $@
# the trace's q31 tables as const C, for the Cortex-M0
$(B)/host/q31_trace_tables.h: $(B)/host/q31_trace
	./$< --tables > $@
# the host references of the cores without an FPU square root: the host
# rules again, in build/ownsqrt/ with -DMDR_PORT_OWN_SQRT
$(B)/ownsqrt/host/gen_tip.c $(B)/ownsqrt/host/test_vectors: $(LIB_SRC) $(LIB_DEPS) examples/mdr_cli.c \
  examples/mdr_cli_t.h host_tests/test_vectors.c host_tests/fl.h
	$(MAKE) --no-print-directory B=$(B)/ownsqrt CFLAGS='$(CFLAGS) -DMDR_PORT_OWN_SQRT' $@

# keep the programs (intermediate files of the .run rules) for nm and reruns
.PRECIOUS: $(foreach t,$(TGT_CORES),$(B)/tgt-$(t)/%.elf $(B)/tgt-$(t)/%.skip)
TGT_RUNS := $(foreach t,$(TGT_CORES),$(addprefix $(B)/tgt-$(t)/,$(addsuffix .run,$(TGT_TESTS_$(t)))))
target-test:
	@rm -f $(TGT_RUNS)
	@$(MAKE) --no-print-directory $(SUB_J2) $(TGT_RUNS) || { echo "target-test: failed"; exit 1; }
	@$(foreach t,$(TGT_CORES),$(foreach x,$(TGT_TESTS_$(t)),\
	  echo "== target $(TGT_NAME_$(t)): $(x) $$(cat $(B)/tgt-$(t)/$(x).time)"; cat $(B)/tgt-$(t)/$(x).log;))
	@a=$$($(MDR_CM_PREFIX)nm $(B)/tgt-m3/q31_trace.elf | awk '$$3=="mdr_engine_step_d_q31"{print $$1}'); \
	  case $$a in 2*) echo "target mps2-an385: the q31 step ran from RAM (MDR_STEP_SECTION, at 0x$$a)";; \
	  *) echo "target mps2-an385: MDR_STEP_SECTION did not place the step in RAM (0x$$a)"; exit 1;; esac
