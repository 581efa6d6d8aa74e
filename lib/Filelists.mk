# SPDX-License-Identifier: MIT
# lib/Filelists.mk: what a firmware build takes from libmdr. Include it from
# your Makefile after setting MDR_ROOT (the path of this repository), then
# compile the sources of the arithmetics you use with MDR_REQUIRED_CFLAGS,
# -I$(MDR_INC) and -I$(MDR_ROOT)/port/<your port> (host, cortex-m, riscv,
# or a directory with your own mdr_port.h; hooks: lib/src/mdr_hooks.h).
#
#   MDR_SRC_F32   float: closed forms, stress, critical states, spring
#                 tables and engine, and the q31 table conversion and init
#   MDR_SRC_F64   the same in double (host-side analysis; soft double on
#                 cores without a double FPU)
#   MDR_SRC_Q31   the q31 step (integer only; its init is in MDR_SRC_F32 or
#                 MDR_SRC_F64)
#   MDR_SRC_COMMON  status and event names (always)
#
# Compile-time options (arithmetics, profiles, output groups): one place,
# lib/include/mdr_options.h; your own mdr_config.h with -DMDR_USE_CONFIG
# (template: lib/mdr_config.example.h).
# Linking with --gc-sections (the sources are built with
# -ffunction-sections -fdata-sections) drops every function a program does
# not call. Optional defines: MDR_STEP_SECTION (section of the step path,
# e.g. '".ramfunc"'), MDR_PORT_ASSERT_HOOK (see the port headers).
MDR_ROOT ?= .
MDR_INC := $(MDR_ROOT)/lib/include
MDR_SRC_F32 := $(MDR_ROOT)/lib/src/mdr_f32.c
MDR_SRC_F64 := $(MDR_ROOT)/lib/src/mdr_f64.c
MDR_SRC_Q31 := $(MDR_ROOT)/lib/src/mdr_q31.c
MDR_SRC_COMMON := $(MDR_ROOT)/lib/src/mdr_status.c
MDR_SRC_ALL := $(MDR_SRC_F32) $(MDR_SRC_F64) $(MDR_SRC_Q31) $(MDR_SRC_COMMON)
# the headers and templates the sources include (for dependency rules)
MDR_DEPS := $(wildcard $(MDR_INC)/*.h $(MDR_ROOT)/lib/src/*.h $(MDR_ROOT)/lib/src/*.inc \
              $(MDR_ROOT)/lib/src/*/*.h $(MDR_ROOT)/lib/src/*/*.inc)
# C99, no hosted library, sqrt as an instruction (no errno), one section per
# function and object (for --gc-sections)
MDR_REQUIRED_CFLAGS := -std=c99 -ffreestanding -fno-math-errno -ffunction-sections -fdata-sections
