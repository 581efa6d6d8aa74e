# SPDX-License-Identifier: MIT
# port/riscv/port.mk: compiler flags per RV32 core (riscv64-unknown-elf-gcc,
# multilib rv32). Included by the Makefile; a firmware build takes the line
# of its core, after setting MDR_ROOT (the path of libmdr). lib/ also
# needs the flags of lib/Filelists.mk
# (MDR_REQUIRED_CFLAGS) and -I$(MDR_ROOT)/port/riscv.
MDR_ROOT ?= .
MDR_RV_PREFIX ?= riscv64-unknown-elf-
MDR_RV_FLAGS_rv32imac := -march=rv32imac -mabi=ilp32
MDR_RV_FLAGS_rv32imafc := -march=rv32imafc -mabi=ilp32f
# startup, trap handler, semihosting exit; linker script of QEMU's virt
# board (make target-test)
MDR_RV_STARTUP := $(MDR_ROOT)/port/riscv/startup.c $(MDR_ROOT)/port/riscv/semihost.c $(MDR_ROOT)/port/semihost.c
MDR_RV_LDSCRIPT := $(MDR_ROOT)/port/riscv/virt.ld
# picolibc (Debian: picolibc-riscv64-unknown-elf; the toolchain ships no C
# library) for compiling and linking, with its semihosting console and
# files (libsemihost); our own startup
MDR_RV_LIBC := --specs=picolibc.specs
MDR_RV_LDFLAGS := -T$(MDR_RV_LDSCRIPT) -nostartfiles --oslib=semihost -Wl,--gc-sections
