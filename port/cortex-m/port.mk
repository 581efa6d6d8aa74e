# SPDX-License-Identifier: MIT
# port/cortex-m/port.mk: compiler flags per Cortex-M core (arm-none-eabi-gcc)
# and the files of the bare-metal test harness. Included by the Makefile;
# a firmware build sets MDR_ROOT (the path of libmdr) first and takes the
# line of its core. lib/ also needs the flags of
# lib/Filelists.mk (MDR_REQUIRED_CFLAGS) and -I$(MDR_ROOT)/port/cortex-m.
MDR_ROOT ?= .
MDR_CM_PREFIX ?= arm-none-eabi-
MDR_CM_FLAGS_m0 := -mcpu=cortex-m0 -mthumb -mfloat-abi=soft
MDR_CM_FLAGS_m3 := -mcpu=cortex-m3 -mthumb -mfloat-abi=soft
MDR_CM_FLAGS_m4f := -mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16
MDR_CM_FLAGS_m7 := -mcpu=cortex-m7 -mthumb -mfloat-abi=hard -mfpu=fpv5-sp-d16
# startup, vector table, semihosting exit; linker script of QEMU's MPS2 boards
# (microbit.ld: the micro:bit's; both include sections.ld)
MDR_CM_STARTUP := $(MDR_ROOT)/port/cortex-m/startup.c $(MDR_ROOT)/port/cortex-m/semihost.c $(MDR_ROOT)/port/semihost.c
MDR_CM_LDSCRIPT := $(MDR_ROOT)/port/cortex-m/mps2.ld
# newlib with the semihosting console (librdimon), our own startup; the
# board's script $(1)
mdr_cm_ldflags = -L$(MDR_ROOT)/port/cortex-m -T$(1) -nostartfiles --specs=rdimon.specs -Wl,--gc-sections
MDR_CM_LDFLAGS := $(call mdr_cm_ldflags,$(MDR_CM_LDSCRIPT))
