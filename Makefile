# SPDX-License-Identifier: MIT
# libmdr: the library, the CLI and the demo for the host, and the tests.
#
#   make              libmdr.a, the CLI mdr and the demo program (build/host/)
#   make demo         build mdr and the AFM demo and run it: a table on the
#                     terminal, CSV and PNG plots in build/demo/
#   make test         everything that proves the library (the README's test
#                     command; about a quarter of an hour on two cores)
#   make deps         install the Debian packages of mk/packages.txt (apt-get,
#                     through sudo when not root); deps-check only names
#                     the missing ones
#   make install PREFIX=/usr/local   headers, libmdr.a, libmdr.so, mdr.pc
#   make docs         the API reference (Doxygen) in build/docs/html
#   make clean        remove build/
#
# Options: CC (default gcc), CFLAGS (default -O2 -g), CROSS_COMPILE (a
# prefix such as aarch64-linux-gnu-); the flags the library needs are kept
# apart in MDR_CFLAGS. B is the build directory (default build).
#
# Everything else is in mk/, one file per topic, each listing its targets:
#   mk/tests.mk    host and sanitizer suites, matrix, stress, q31-exact, mutate
#   mk/fuzz.mk     fuzz, fuzz-replay          mk/critical.mk  crit-sweep
#   mk/cross.mk    cross, size                mk/target.mk    target-test (QEMU)
#   mk/lint.mk     lint                       mk/bench.mk     bench, step-cost, step-trace
#   mk/ref.mk      ref-check, tables          mk/fit.mk       fit suites, bench-fit
#   mk/python.mk   python, python-test        mk/docs.mk      docs, headers, spdx-check
#   mk/install.mk  install, install-check, cmake-check, errno-check
# A firmware build does not use this Makefile: lib/Filelists.mk (make),
# CMakeLists.txt (CMake) or the four files of lib/src (any IDE).

ifeq ($(origin CC),default)
CC := gcc
endif
CFLAGS ?= -O2 -g
CROSS_COMPILE ?=
HOSTCC := $(CROSS_COMPILE)$(CC)
PYTHON := /usr/bin/python3

B := build
# a phase's own runs, two at a time: -j2, unless make already runs with a
# job server (make -j2 test-phase), whose slots the sub-make then shares
SUB_J2 = $(if $(findstring jobserver,$(MAKEFLAGS)),,-j2)
WARN := -Wall -Wextra -Wpedantic -Wconversion -Wdouble-promotion -Wshadow -Wvla -Werror
MDR_CFLAGS = $(MDR_REQUIRED_CFLAGS) $(WARN) -Ilib/include -Iport/host
TEST_CFLAGS := -std=c99 -D_GNU_SOURCE -Wall -Wextra -Werror -Ilib/include -Iref -Iport/host
GSL_LIBS := -lgsl -lgslcblas -lm

MDR_ROOT := .
include lib/Filelists.mk
include port/cortex-m/port.mk
include port/riscv/port.mk
LIB_SRC := $(MDR_SRC_ALL)
LIB_DEPS := $(MDR_DEPS) $(wildcard lib/src/*.c port/*/mdr_port.h)
REF_SRC := ref/mdr_ref.c

.PHONY: all demo test deps deps-check clean

all: $(B)/host/libmdr.a $(B)/host/mdr $(B)/host/afm_demo

# ---- the library: one object per arithmetic ----------------------------------
$(B)/host/%.o: lib/src/%.c $(LIB_DEPS)
	@mkdir -p $(@D)
	$(HOSTCC) $(MDR_CFLAGS) $(CFLAGS) -c $< -o $@
$(B)/host/libmdr.a: $(B)/host/mdr_f32.o $(B)/host/mdr_f64.o $(B)/host/mdr_q31.o $(B)/host/mdr_status.o
	$(CROSS_COMPILE)ar rcs $@ $^

# ---- the CLI and the demo -------------------------------------------------------
$(B)/host/mdr: examples/mdr_cli.c examples/mdr_cli_t.h examples/mdr_host.h examples/mdr_host_t.h examples/tip_csv.h $(B)/host/libmdr.a
	$(HOSTCC) -std=c99 $(WARN) -Ilib/include $(CFLAGS) $< $(B)/host/libmdr.a -lm -o $@
$(B)/host/afm_demo: examples/afm_demo.c $(B)/host/libmdr.a
	$(HOSTCC) -std=c99 $(WARN) -Ilib/include $(CFLAGS) $< $(B)/host/libmdr.a -lm -o $@
DEMO_DIR = $(B)/demo
demo: $(B)/host/afm_demo $(B)/host/mdr
	./$(B)/host/afm_demo $(DEMO_DIR)
	gnuplot -e "dir='$(DEMO_DIR)'" examples/afm_demo.gp
	@echo "demo: $(DEMO_DIR)/afm_fd.png, $(DEMO_DIR)/afm_cycle.png"

# ---- the tests ------------------------------------------------------------------
# The README's test command (apt-get is make deps' business, not this one's):
# the quick checks of the sources, the docs and the builds a project uses
# (CMake, install, pkg-config), the host suites and the CLI, static
# analysis, the same suites under ASan+UBSan, the option matrix, fuzzing,
# the stress sweep, the q31 bit-exactness across compilers, the mutation
# gate, the cross builds with their symbol checks, the target tests on QEMU
# and the Python package. The phases whose programs are separate targets
# build them and run their suites two at a time (-j2: the machine's two
# cores), each suite's output printed whole, in order (mk/tests.mk,
# mk/target.mk); lint checks two files at a time.
# one phase of make test: its wall time appended to $(B)/phase-times (make
# test prints them at the end: where CI's minutes go)
test_phase = @echo "make $(1)"; t0=$$(date +%s); $(MAKE) --no-print-directory $(1) || exit 1; \
  echo "$(firstword $(filter-out -j2,$(1))) $$(($$(date +%s) - t0))," >> $(B)/phase-times
test: deps-check
	@mkdir -p $(B) && rm -f $(B)/phase-times
	$(call test_phase,spdx-check headers-check docs errno-check)
	$(call test_phase,-j2 host-tests)
	$(call test_phase,-j2 demo-check cmake-check install-check)
	$(call test_phase,-j2 lint)
	$(call test_phase,-j2 san-tests)
	$(call test_phase,-j2 fused-tests)
	$(call test_phase,matrix)
	$(call test_phase,fuzz-replay)
	$(call test_phase,-j2 fuzz)
	$(call test_phase,stress)
	$(call test_phase,q31-exact)
	$(call test_phase,mutate-quick)
	$(call test_phase,-j2 cross)
	$(call test_phase,target-test)
	$(call test_phase,python-test)
	@echo "phase wall times (s): $$(tr '\n' ' ' < $(B)/phase-times)"
	@echo "suites: $(words spdx headers docs errno demo cmake install $(TESTS) cli cli-f32 python lint $(SAN_TESTS) san-cli san-cli-f32 $(FUSED_TESTS) matrix $(addprefix replay-,$(FUZZ_TARGETS)) $(addprefix fuzz-,$(FUZZ_TARGETS)) stress q31-exact mutate-quick $(CROSS_CFGS) $(TGT_RUNS)) passed, 0 failed"

deps:
	@sh mk/deps.sh
deps-check:
	@sh mk/deps.sh --check

clean:
	rm -rf $(B)

include mk/tests.mk
include mk/critical.mk
include mk/fuzz.mk
include mk/bench.mk
include mk/ref.mk
include mk/cross.mk
include mk/target.mk
include mk/lint.mk
include mk/python.mk
include mk/fit.mk
include mk/docs.mk
include mk/install.mk
include mk/demo.mk
