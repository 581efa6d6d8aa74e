# SPDX-License-Identifier: MIT
# mk/lint.mk: cppcheck and clang-tidy (make lint, in make test).
#
# cppcheck and clang-tidy over the code that ships: lib/ (built for the host,
# the Cortex-M4F and RV32IMAC ports), port/, examples/ and ref/. Configuration:
# .clang-tidy (checks and why some are off) and .cppcheck-suppressions (what
# cppcheck is told to ignore, each with its reason); every finding fails.
.PHONY: lint
LINT_LIB := lib/src/mdr_f32.c lib/src/mdr_f64.c lib/src/mdr_q31.c lib/src/mdr_status.c
LINT_HOST := examples/mdr_cli.c examples/afm_demo.c ref/mdr_ref.c ref/mdr_refgen.c ref/vecdiff.c \
             ref/gen_tables.c port/link_check.c port/sizes.c
LINT_CM := port/cortex-m/semihost.c port/cortex-m/startup.c port/semihost.c
LINT_RV := port/riscv/semihost.c port/riscv/startup.c
LINT_LC := -DMDR_LC_F32 -DMDR_LC_STRESS -DMDR_LC_Q31 -DMDR_LC_SCENE -DMDR_LC_SCENE_ALL -DMDR_LC_Q31MIN
LINT_ARM := --target=arm-none-eabi $(MDR_CM_FLAGS_m4f) -isystem /usr/lib/arm-none-eabi/include
# clang-tidy: one stamp per configuration and file (runs under make -j2)
LINT_CFG_host := $(MDR_REQUIRED_CFLAGS) -Ilib/include -Iport/host
LINT_CFG_m4f := $(MDR_REQUIRED_CFLAGS) $(LINT_ARM) -Ilib/include -Iport/cortex-m
LINT_CFG_rv32 := $(MDR_REQUIRED_CFLAGS) --target=riscv32-unknown-elf -march=rv32imac -mabi=ilp32 \
                 -Ilib/include -Iport/riscv
LINT_CFG_app := -std=c99 -D_GNU_SOURCE $(LINT_LC) -Ilib/include -Iport/host -Iref
LINT_CFG_cm := -std=c99 -ffreestanding $(LINT_ARM) -DMDR_RAM_REPORT -Ilib/include -Iport/cortex-m
LINT_CFG_rv := -std=c99 -ffreestanding --target=riscv32-unknown-elf -march=rv32imafc -mabi=ilp32f \
               -isystem /usr/lib/picolibc/riscv64-unknown-elf/include -Ilib/include -Iport/riscv
LINT_UNITS := $(foreach c,host m4f rv32,$(addprefix $(c):,$(LINT_LIB))) \
              $(addprefix app:,$(LINT_HOST)) $(addprefix cm:,$(LINT_CM)) $(addprefix rv:,$(LINT_RV))
lint_stamp = $(B)/lint/$(word 1,$(subst :, ,$(1)))/$(subst /,_,$(word 2,$(subst :, ,$(1)))).tidy
define lint_rule
$(call lint_stamp,$(1)): $(word 2,$(subst :, ,$(1))) .clang-tidy $(LIB_DEPS) $(wildcard examples/*.h ref/*.h)
	@mkdir -p $$(@D)
	@clang-tidy --quiet $$< -- $(LINT_CFG_$(word 1,$(subst :, ,$(1)))) > $$@.log 2>&1 || { cat $$@.log; exit 1; }
	@echo "clang-tidy $(1): clean" && touch $$@
endef
$(foreach u,$(LINT_UNITS),$(eval $(call lint_rule,$(u))))
CPPCHECK := cppcheck --std=c99 --enable=warning,style,performance,portability --inline-suppr \
            --suppressions-list=.cppcheck-suppressions --error-exitcode=1 -q
# cppcheck: one stamp per file group (runs under make -j2 beside clang-tidy).
# The library in the configuration that ships (the -D pins cppcheck to the
# compiler's view: without one it also tried 11 combinations of the
# sources' #ifdef macros per file, such as mdr_f32.c with MDR_ARITH_F64
# defined, 150 of lint's 210 CPU seconds; the option matrix, make matrix,
# compiles every option warning-free; port/configs' minimal builds give
# knownConditionTrueFalse on every disabled output, by design), with
# cppcheck -j2, which also leaves out its whole-program analysis.
CPPCHECK_DEPS := .cppcheck-suppressions $(LIB_DEPS) $(wildcard examples/*.h ref/*.h)
CPPCHECK_lib := -j2 -D__STDC_VERSION__=199901L -Ilib/include -Iport/host
CPPCHECK_host := -D_GNU_SOURCE $(LINT_LC) -Ilib/include -Iport/host -Iref
CPPCHECK_cm := -DMDR_RAM_REPORT -Ilib/include -Iport/cortex-m
CPPCHECK_rv := -Ilib/include -Iport/riscv
CPPCHECK_FILES_lib := $(LINT_LIB)
CPPCHECK_FILES_host := $(LINT_HOST)
CPPCHECK_FILES_cm := $(LINT_CM)
CPPCHECK_FILES_rv := $(LINT_RV)
CPPCHECK_GROUPS := lib host cm rv
define cppcheck_rule
$(B)/lint/cppcheck-$(1).stamp: $(CPPCHECK_FILES_$(1)) $(CPPCHECK_DEPS)
	@mkdir -p $$(@D)
	$(CPPCHECK) $(CPPCHECK_$(1)) $(CPPCHECK_FILES_$(1))
	@touch $$@
endef
$(foreach g,$(CPPCHECK_GROUPS),$(eval $(call cppcheck_rule,$(g))))
$(B)/lint/cppcheck.stamp: $(foreach g,$(CPPCHECK_GROUPS),$(B)/lint/cppcheck-$(g).stamp)
	@echo "cppcheck: clean" && touch $@
lint: $(B)/lint/cppcheck.stamp $(foreach u,$(LINT_UNITS),$(call lint_stamp,$(u)))
	@echo "lint: cppcheck and clang-tidy clean ($(words $(LINT_UNITS)) clang-tidy units)"
