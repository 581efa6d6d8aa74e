# port/riscv/port.mk: compiler flags per RV32 core (riscv64-unknown-elf-gcc,
# multilib rv32). Included by the Makefile; a firmware build takes the line
# of its core. lib/ also needs the flags of lib/Filelists.mk
# (MDR_REQUIRED_CFLAGS) and -I$(MDR_ROOT)/port/riscv.
MDR_RV_PREFIX ?= riscv64-unknown-elf-
MDR_RV_FLAGS_rv32imac := -march=rv32imac -mabi=ilp32
MDR_RV_FLAGS_rv32imafc := -march=rv32imafc -mabi=ilp32f
