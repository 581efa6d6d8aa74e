# libmdr — one Makefile for the library, its tests, the reference and the
# cross builds.
#
#   make            library, CLI and demo for the host (build/host/)
#   make test       everything that proves the library (see `test:` below)
#   make demo       AFM pull-off demo (prints a table, writes CSV/PNG)
#   make ref-check  regenerate the reference vectors with GSL and diff them
#   make size       flash/RAM of the library per cross configuration
#   make cross      cross builds + symbol checks (Cortex-M4F, Cortex-M0, RV32)
#   make tables     regenerate lib/src/mdr_tables.h (quadrature nodes)
#   make deps       install missing Debian packages (as root) or name them
#
# CC, CFLAGS and CROSS_COMPILE given on the command line are respected;
# the flags the library needs are kept apart in MDR_CFLAGS.

ifeq ($(origin CC),default)
CC := gcc
endif
CFLAGS ?= -O2 -g
CROSS_COMPILE ?=
HOSTCC := $(CROSS_COMPILE)$(CC)

B := build
WARN := -Wall -Wextra -Wpedantic -Wconversion -Wdouble-promotion -Wshadow -Wvla -Werror
MDR_CFLAGS := -std=c99 -ffreestanding -fno-math-errno -ffunction-sections -fdata-sections $(WARN) \
              -Ilib/include -Iport/host
TEST_CFLAGS := -std=c99 -D_GNU_SOURCE -Wall -Wextra -Werror -Ilib/include -Iref -Iport/host
GSL_LIBS := -lgsl -lgslcblas -lm

LIB_SRC := lib/src/mdr_f32.c lib/src/mdr_f64.c lib/src/mdr_status.c
LIB_DEPS := $(wildcard lib/include/*.h lib/src/*.h lib/src/*.c port/host/*.h)
REF_SRC := ref/mdr_ref.c

.PHONY: all test demo ref-check size cross tables deps clean host-tests san-tests check-ref

all: $(B)/host/libmdr.a $(B)/host/mdr $(B)/host/afm_demo

# ---- host library: one object per arithmetic --------------------------------
$(B)/host/%.o: lib/src/%.c $(LIB_DEPS)
	@mkdir -p $(@D)
	$(HOSTCC) $(MDR_CFLAGS) $(CFLAGS) -c $< -o $@

$(B)/host/libmdr.a: $(B)/host/mdr_f32.o $(B)/host/mdr_f64.o $(B)/host/mdr_status.o
	$(CROSS_COMPILE)ar rcs $@ $^

$(B)/host/mdr: examples/mdr_cli.c examples/mdr_cli_t.h $(B)/host/libmdr.a
	$(HOSTCC) -std=c99 $(WARN) -Ilib/include $(CFLAGS) $< $(B)/host/libmdr.a -lm -o $@

$(B)/host/afm_demo: examples/afm_demo.c $(B)/host/libmdr.a
	$(HOSTCC) -std=c99 $(WARN) -Ilib/include $(CFLAGS) $< $(B)/host/libmdr.a -lm -o $@

# ---- tests ------------------------------------------------------------------
# Each test binary is built twice: plain, and with address+undefined sanitizers
# on the library and the test (san/).
TESTS := test_unit test_vectors test_ref test_gsl

$(B)/host/test_unit: host_tests/test_unit.c $(B)/host/libmdr.a
	$(HOSTCC) $(TEST_CFLAGS) $(CFLAGS) $< $(B)/host/libmdr.a -lcmocka -lm -o $@
$(B)/host/test_vectors: host_tests/test_vectors.c $(B)/host/libmdr.a
	$(HOSTCC) $(TEST_CFLAGS) $(CFLAGS) $< $(B)/host/libmdr.a -lcmocka -lm -o $@
$(B)/host/test_ref: host_tests/test_ref.c $(REF_SRC) ref/mdr_ref.h
	$(HOSTCC) $(TEST_CFLAGS) $(CFLAGS) $< $(REF_SRC) -lcmocka $(GSL_LIBS) -o $@
$(B)/host/test_gsl: host_tests/test_gsl.c $(REF_SRC) ref/mdr_ref.h $(B)/host/libmdr.a
	$(HOSTCC) $(TEST_CFLAGS) $(CFLAGS) $< $(REF_SRC) $(B)/host/libmdr.a -lcmocka $(GSL_LIBS) -o $@

SAN := -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer
$(B)/san/libmdr.a: $(LIB_SRC) $(LIB_DEPS)
	@mkdir -p $(@D)
	for f in $(LIB_SRC); do $(HOSTCC) $(MDR_CFLAGS) -O1 -g $(SAN) -c $$f -o $(B)/san/$$(basename $$f .c).o || exit 1; done
	ar rcs $@ $(B)/san/mdr_f32.o $(B)/san/mdr_f64.o $(B)/san/mdr_status.o
$(B)/san/test_unit: host_tests/test_unit.c $(B)/san/libmdr.a
	$(HOSTCC) $(TEST_CFLAGS) -O1 -g $(SAN) $< $(B)/san/libmdr.a -lcmocka -lm -o $@
$(B)/san/test_vectors: host_tests/test_vectors.c $(B)/san/libmdr.a
	$(HOSTCC) $(TEST_CFLAGS) -O1 -g $(SAN) $< $(B)/san/libmdr.a -lcmocka -lm -o $@

host-tests: $(addprefix $(B)/host/,$(TESTS)) $(B)/host/mdr
	@for t in $(TESTS); do echo "== $$t"; ./$(B)/host/$$t || exit 1; done
	@echo "== cli"; bash host_tests/test_cli.sh $(B)/host/mdr

SAN_TESTS := test_unit test_vectors
san-tests: $(addprefix $(B)/san/,$(SAN_TESTS))
	@for t in $(SAN_TESTS); do echo "== sanitized $$t"; ./$(B)/san/$$t || exit 1; done

# The README's test command. Installs what is missing (deps), then: host
# tests (unit, lib vs committed ref vectors, ref vs closed forms, lib vs GSL
# directly, CLI), the same under ASan+UBSan, and the cross builds with their
# symbol checks.
test: deps
	$(MAKE) --no-print-directory host-tests
	$(MAKE) --no-print-directory san-tests
	$(MAKE) --no-print-directory cross
	@echo "suites: $(words $(TESTS) cli $(SAN_TESTS) $(CROSS_CFGS)) passed, 0 failed"

demo: $(B)/host/afm_demo
	./$(B)/host/afm_demo $(B)/demo

# ---- reference vectors ------------------------------------------------------
$(B)/host/mdr_refgen: ref/mdr_refgen.c $(REF_SRC) ref/mdr_ref.h
	@mkdir -p $(@D)
	$(HOSTCC) $(TEST_CFLAGS) -O2 $< $(REF_SRC) $(GSL_LIBS) -o $@
$(B)/host/vecdiff: ref/vecdiff.c
	$(HOSTCC) $(TEST_CFLAGS) -O2 $< -lm -o $@

ref-check: $(B)/host/mdr_refgen $(B)/host/vecdiff
	@mkdir -p $(B)/ref
	./$(B)/host/mdr_refgen critical > $(B)/ref/critical.csv & \
	./$(B)/host/mdr_refgen curves > $(B)/ref/curves.csv; wait
	./$(B)/host/vecdiff ref/vectors/critical.csv $(B)/ref/critical.csv
	./$(B)/host/vecdiff ref/vectors/curves.csv $(B)/ref/curves.csv

$(B)/host/gen_tables: ref/gen_tables.c
	@mkdir -p $(@D)
	$(HOSTCC) -O2 $< $(GSL_LIBS) -o $@
tables: $(B)/host/gen_tables
	./$(B)/host/gen_tables > lib/src/mdr_tables.h

# ---- cross builds -------------------------------------------------------------
# Each configuration compiles the f32 library with -ffreestanding, links the
# link-check program with -nostdlib -lgcc and --gc-sections, and fails on an
# undefined symbol outside the allow-list or a double-precision helper.
ARM := arm-none-eabi-
RV := riscv64-unknown-elf-
CROSS_WARN := -std=c99 -ffreestanding -fno-math-errno -ffunction-sections -fdata-sections -Os $(WARN)
CFG_m4f := $(ARM)gcc -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16 -Iport/cortex-m
CFG_m0 := $(ARM)gcc -mcpu=cortex-m0 -mthumb -mfloat-abi=soft -Iport/cortex-m
CFG_rv32imafc := $(RV)gcc -march=rv32imafc -mabi=ilp32f -Iport/riscv
CFG_rv32imac := $(RV)gcc -march=rv32imac -mabi=ilp32 -Iport/riscv
CROSS_CFGS := m4f m0 rv32imafc rv32imac
# undefined symbols allowed in lib/ objects: the two mem* functions GCC may
# call, and libgcc helpers (checked separately for double precision)
ALLOW_RE := ^(memcpy|memset|__aeabi_[a-z0-9]+|__gnu_thumb1_case_[a-z0-9]+|__[a-z]+sf[0-9]|__float(un)?sisf|__fix(uns)?sfsi|__[a-z]+[sd]i[0-9]|__clz[sd]i2)$$
DOUBLE_RE := ^(__aeabi_(d[a-z0-9]+|[a-z0-9]*2d[a-z]*)|__[a-z]+df[0-9]?|__[a-z]+df[a-z0-9]*)$$

define cross_rules
$(B)/$(1)/libmdr.a: $(LIB_DEPS) port/link_check.c
	@mkdir -p $(B)/$(1)
	$(CFG_$(1)) $(CROSS_WARN) -Ilib/include -c lib/src/mdr_f32.c -o $(B)/$(1)/mdr_f32.o
	$(CFG_$(1)) $(CROSS_WARN) -Ilib/include -c lib/src/mdr_status.c -o $(B)/$(1)/mdr_status.o
	rm -f $$@ && $(if $(filter rv%,$(1)),$(RV)ar,$(ARM)ar) rcs $$@ $(B)/$(1)/mdr_f32.o $(B)/$(1)/mdr_status.o
$(B)/$(1)/link_check.elf: $(B)/$(1)/libmdr.a
	$(CFG_$(1)) $(CROSS_WARN) -Ilib/include -nostdlib -Wl,--gc-sections -Wl,-e,link_check_entry \
	  port/link_check.c $(B)/$(1)/libmdr.a -lgcc -o $$@
endef
$(foreach c,$(CROSS_CFGS),$(eval $(call cross_rules,$(c))))

cross: $(foreach c,$(CROSS_CFGS),$(B)/$(c)/link_check.elf)
	@set -e; for c in $(CROSS_CFGS); do \
	  nmtool=$$(case $$c in rv*) echo $(RV)nm;; *) echo $(ARM)nm;; esac); \
	  und=$$($$nmtool -u $(B)/$$c/mdr_f32.o $(B)/$$c/mdr_status.o | awk 'NF==2{print $$2}' | sort -u); \
	  bad=$$(printf '%s\n' $$und | grep -Ev '$(ALLOW_RE)' | grep -v '^$$' || true); \
	  if [ -n "$$bad" ]; then echo "cross $$c: undefined symbols outside the allow-list: $$bad"; exit 1; fi; \
	  dbl=$$($$nmtool $(B)/$$c/link_check.elf | awk '{print $$NF}' | grep -E '$(DOUBLE_RE)' || true); \
	  if [ -n "$$dbl" ]; then echo "cross $$c: double-precision helpers in an f32 build: $$dbl"; exit 1; fi; \
	  echo "cross $$c: ok (undefined in lib: $$(printf '%s ' $$und))"; \
	done

size: cross
	@printf '%-11s %8s %8s %8s   %s\n' config text data bss "(f32 library, all profiles; link_check.elf after --gc-sections)"
	@for c in $(CROSS_CFGS); do \
	  sz=$$(case $$c in rv*) echo $(RV)size;; *) echo $(ARM)size;; esac); \
	  $$sz $(B)/$$c/libmdr.a | awk -v c=$$c 'NR>1{t+=$$1;d+=$$2;b+=$$3} END{printf "%-11s %8d %8d %8d   libmdr.a\n",c,t,d,b}'; \
	  $$sz $(B)/$$c/link_check.elf | awk -v c=$$c 'NR>1{printf "%-11s %8d %8d %8d   link_check.elf\n",c,$$1,$$2,$$3}'; \
	done

# ---- dependencies --------------------------------------------------------------
DEB_PKGS := gcc make libcmocka-dev libgsl-dev gcc-arm-none-eabi libnewlib-arm-none-eabi gcc-riscv64-unknown-elf
deps:
	@missing=""; \
	for p in $(DEB_PKGS); do dpkg -s $$p >/dev/null 2>&1 || missing="$$missing $$p"; done; \
	if [ -n "$$missing" ]; then \
	  if [ "$$(id -u)" = 0 ]; then \
	    echo "installing:$$missing"; \
	    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $$missing >/dev/null; \
	  else echo "missing Debian packages:$$missing (run: sudo apt-get install$$missing)"; exit 1; fi; \
	fi

clean:
	rm -rf $(B)
