# SPDX-License-Identifier: MIT
# mk/cross.mk: cross builds with their symbol checks (make cross, in make
# test) and the size report (make size).
#
# Per core (flags: port/*/port.mk) the library objects are compiled with
# -ffreestanding -Werror, -fstack-usage and a call graph; per core and
# arithmetic port/link_check.c is linked with -nostdlib -lgcc --gc-sections.
# Checks: no undefined symbol outside the allow-list in lib/ objects, no
# double-precision helper in any link (all are f32 or q31 programs), no
# floating-point helper at all in the q31 step (mdr_q31.o).
.PHONY: cross size
CROSS_WARN := $(MDR_REQUIRED_CFLAGS) -Os $(WARN)
CORE_m0 := $(MDR_CM_PREFIX)gcc $(MDR_CM_FLAGS_m0) -Iport/cortex-m
CORE_m4f := $(MDR_CM_PREFIX)gcc $(MDR_CM_FLAGS_m4f) -Iport/cortex-m
CORE_m7 := $(MDR_CM_PREFIX)gcc $(MDR_CM_FLAGS_m7) -Iport/cortex-m
CORE_rv32imac := $(MDR_RV_PREFIX)gcc $(MDR_RV_FLAGS_rv32imac) -Iport/riscv
CORE_rv32imafc := $(MDR_RV_PREFIX)gcc $(MDR_RV_FLAGS_rv32imafc) -Iport/riscv
CROSS_CORES := m0 m4f m7 rv32imac rv32imafc
# core-arithmetic: Cortex-M0 runs q31, the M7 f32, the M4F and RV32 both
# (m4f-f32nostress: the f32 program without the stress functions)
# (m4f-scene: the minimal scene from the default build, --gc-sections
# only; m4f-full: every public function of f32, q31 and the scenes)
CROSS_CFGS := m0-q31 m4f-f32 m4f-f32nostress m4f-q31 m4f-scene m4f-full m7-f32 rv32imac-f32 rv32imac-q31 rv32imafc-f32 rv32imafc-q31
LC_f32 := -DMDR_LC_F32 -DMDR_LC_STRESS
LC_f32nostress := -DMDR_LC_F32
LC_q31 := -DMDR_LC_Q31
LC_scene := -DMDR_LC_SCENE
LC_full := -DMDR_LC_F32 -DMDR_LC_STRESS -DMDR_LC_Q31 -DMDR_LC_SCENE_ALL
# Programs built with a user configuration (port/configs/<cfg>/mdr_config.h,
# -DMDR_USE_CONFIG), library and program in one link:
#   m4f-scenecfg  the minimal scene with port/configs/minimal-scene
#   m4f-scenelto  the same, compiled and linked with -flto
#   m0-q31min     the minimal q31 scene on the Cortex-M0: a const q31 table
#                 made by the CLI, float init, integer step
#                 (port/configs/minimal-q31)
CROSS_SPECIAL := m4f-scenecfg m4f-scenelto m0-q31min
CFG_minscene := -DMDR_USE_CONFIG -Iport/configs/minimal-scene
CFG_minq31 := -DMDR_USE_CONFIG -Iport/configs/minimal-q31
LC_LINK := -Ilib/include -nostdlib -Wl,--gc-sections -Wl,-e,link_check_entry port/link_check.c
LTO_scenecfg :=
LTO_scenelto := -flto
$(B)/m4f-scenecfg/link_check.elf $(B)/m4f-scenelto/link_check.elf: $(B)/m4f-%/link_check.elf: \
  $(LIB_DEPS) port/link_check.c port/configs/minimal-scene/mdr_config.h
	@mkdir -p $(@D)
	$(CORE_m4f) $(CROSS_WARN) $(LTO_$*) $(CFG_minscene) -DMDR_LC_SCENE $(LC_LINK) lib/src/mdr_f32.c lib/src/mdr_status.c -lgcc -o $@
$(B)/host/min_q31.c: $(B)/host/mdr
	./$(B)/host/mdr table --arith q31 --profile paraboloid --R 2e-3 --springs 64 --a-max 2e-4 --name min_q31 > $@
$(B)/m0-q31min/link_check.elf: $(LIB_DEPS) port/link_check.c port/configs/minimal-q31/mdr_config.h $(B)/host/min_q31.c
	@mkdir -p $(@D)
	$(CORE_m0) $(CROSS_WARN) $(CFG_minq31) -DMDR_LC_Q31MIN $(LC_LINK) $(B)/host/min_q31.c \
	  lib/src/mdr_f32.c lib/src/mdr_q31.c lib/src/mdr_status.c -lgcc -o $@
# the tools of a core (binutils prefix)
xtool = $(if $(filter rv%,$(1)),$(MDR_RV_PREFIX),$(MDR_CM_PREFIX))$(2)
# undefined symbols allowed in lib/ objects (besides those another lib/
# object defines: the q31 engine's init, float, calls its landings in
# mdr_q31.o): the two mem* functions GCC may call, and libgcc helpers
# (checked separately for double precision)
ALLOW_RE := ^(memcpy|memset|__aeabi_[a-z0-9]+|__gnu_thumb1_case_[a-z0-9]+|__[a-z]+sf[0-9]|__float(un)?sisf|__fix(uns)?sfsi|__[a-z]+[sd]i[0-9]|__clz[sd]i2)$$
# any floating-point helper (soft float, single or double): none may appear
# in the q31 step (lib/src/mdr_q31.c), which is integer arithmetic only
FLOAT_RE := ^(__aeabi_([fd][a-z0-9]+|[a-z0-9]*2[fd][a-z]*)|__[a-z]+[sd]f[0-9]?|__[a-z]+[sd]f[a-z0-9]*)$$
DOUBLE_RE := ^(__aeabi_(d[a-z0-9]+|[a-z0-9]*2d[a-z]*)|__[a-z]+df[0-9]?|__[a-z]+df[a-z0-9]*)$$
CROSS_OBJS := mdr_f32 mdr_q31 mdr_status

define core_rules
$(B)/$(1)/libmdr.a: $(LIB_DEPS) port/sizes.c
	@mkdir -p $(B)/$(1)
	cd $(B)/$(1) && for o in $(CROSS_OBJS); do \
	  $(CORE_$(1)) $(CROSS_WARN) -fstack-usage -fcallgraph-info=su -I$(CURDIR)/lib/include \
	    $(subst -Iport,-I$(CURDIR)/port,$(filter -Iport%,$(CORE_$(1)))) -c $(CURDIR)/lib/src/$$$$o.c -o $$$$o.o || exit 1; done
	$(CORE_$(1)) $(CROSS_WARN) -Ilib/include -c port/sizes.c -o $(B)/$(1)/sizes.o
	rm -f $$@ && $(call xtool,$(1),ar) rcs $$@ $(addprefix $(B)/$(1)/,$(addsuffix .o,$(CROSS_OBJS)))
endef
define link_rules
$(B)/$(1)/link_check.elf: $(B)/$(word 1,$(subst -, ,$(1)))/libmdr.a port/link_check.c
	@mkdir -p $(B)/$(1)
	$(CORE_$(word 1,$(subst -, ,$(1)))) $(CROSS_WARN) $(LC_$(word 2,$(subst -, ,$(1)))) -Ilib/include \
	  -nostdlib -Wl,--gc-sections -Wl,-e,link_check_entry port/link_check.c $$< -lgcc -o $$@
endef
$(foreach c,$(CROSS_CORES),$(eval $(call core_rules,$(c))))
$(foreach c,$(CROSS_CFGS),$(eval $(call link_rules,$(c))))

cross: $(foreach c,$(CROSS_CFGS) $(CROSS_SPECIAL),$(B)/$(c)/link_check.elf)
	@set -e; $(foreach k,$(CROSS_CORES),k=$(k); nm=$(call xtool,$(k),nm); \
	  def=$$($$nm --defined-only -g $(B)/$$k/mdr_f32.o $(B)/$$k/mdr_q31.o $(B)/$$k/mdr_status.o | awk 'NF==3{print $$3}' | sort -u); \
	  und=$$($$nm -u $(B)/$$k/mdr_f32.o $(B)/$$k/mdr_q31.o $(B)/$$k/mdr_status.o | awk 'NF==2{print $$2}' | sort -u | \
	    { [ -n "$$def" ] && grep -vxF "$$def" || cat; }); \
	  bad=$$(printf '%s\n' $$und | grep -Ev '$(ALLOW_RE)' | grep -v '^$$' || true); \
	  if [ -n "$$bad" ]; then echo "cross $$k: undefined symbols outside the allow-list: $$bad"; exit 1; fi; \
	  qf=$$($$nm -u $(B)/$$k/mdr_q31.o | awk 'NF==2{print $$2}' | grep -E '$(FLOAT_RE)' || true); \
	  if [ -n "$$qf" ]; then echo "cross $$k: float helpers in the q31 step: $$qf"; exit 1; fi; \
	  echo "cross $$k: lib/ ok (undefined: $$(printf '%s ' $$und); q31 step: $$($$nm -u $(B)/$$k/mdr_q31.o | awk 'NF==2{printf "%s ", $$2}'))";) \
	$(foreach c,$(CROSS_CFGS) $(CROSS_SPECIAL),c=$(c); nm=$(call xtool,$(c),nm); \
	  dbl=$$($$nm $(B)/$$c/link_check.elf | awk '{print $$NF}' | grep -E '$(DOUBLE_RE)' || true); \
	  if [ -n "$$dbl" ]; then echo "cross $$c: double-precision helpers: $$dbl"; exit 1; fi; \
	  echo "cross $$c: linked with -nostdlib -lgcc, no double helper";)

# Flash (text + data) of each core-arithmetic program after --gc-sections,
# lib/'s own static RAM (data + bss of its objects), the instance sizes on
# the core, and the worst stack depth of the step functions from the call
# graph (port/stack_depth.awk; libgcc helpers listed, not counted).
SIZE_DESC_f32 := all profiles, closed forms, critical states, stress, tables, engine
SIZE_DESC_f32nostress := the same without the stress functions
SIZE_DESC_q31 := all profiles: table from a profile, q31 conversion, float init, q31 steps
SIZE_DESC_scene := minimal scene (paraboloid, f32, force only, table-free), default build
SIZE_DESC_full := full library: every public function of f32, q31 and the scenes
SIZE_DESC_scenecfg := minimal scene with port/configs/minimal-scene/mdr_config.h
SIZE_DESC_scenelto := the same, -flto
SIZE_DESC_q31min := minimal q31 scene: const 64-spring table (1.3 KB), float init, q31 step; port/configs/minimal-q31
size: cross
	@printf '%-16s %7s %7s   %s\n' config flash "lib RAM" "program (port/link_check.c, --gc-sections)"
	@$(foreach c,$(CROSS_CFGS) $(CROSS_SPECIAL),c=$(c); k=$${c%%-*}; sz=$(call xtool,$(c),size); \
	  ram=$$($$sz $(B)/$$k/libmdr.a | awk 'NR>1{s+=$$2+$$3} END{print s}'); \
	  $$sz $(B)/$$c/link_check.elf | awk -v c=$$c -v r=$$ram -v d='$(SIZE_DESC_$(word 2,$(subst -, ,$(c))))' \
	    'NR>1{printf "%-16s %7d %7d   %s\n",c,$$1+$$2,r,d}';)
	@echo; printf '%-10s %s\n' core "instance sizes in bytes (sizeof on the core)"
	@$(foreach k,$(CROSS_CORES),k=$(k); nm=$(call xtool,$(k),nm); \
	  $$nm -S $(B)/$$k/sizes.o | awk -v k=$$k -f mk/instance_sizes.awk;)
	@echo; echo "worst stack depth of a step function (d, F or z), bytes: call graph of -fstack-usage, libgcc helpers not counted"
	@for k in $(CROSS_CORES); do for a in f32 q31; do \
	  awk -v roots="^mdr_engine_step_[dFz]_$$a\$$" -f port/stack_depth.awk $(B)/$$k/*.ci | sort -k2 -n | tail -1 | \
	    awk -v k=$$k -v a=$$a -f mk/stack_line.awk; \
	 done; done
