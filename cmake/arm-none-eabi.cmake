# SPDX-License-Identifier: MIT
# cmake/arm-none-eabi.cmake: toolchain file for a Cortex-M4F (Debian's
# gcc-arm-none-eabi with newlib). Another core: pass -DMDR_CPU_FLAGS=...
# (port/cortex-m/port.mk lists them per core).
#   cmake -S app -B build -DCMAKE_TOOLCHAIN_FILE=path/to/libmdr/cmake/arm-none-eabi.cmake
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_AR arm-none-eabi-ar)
set(CMAKE_RANLIB arm-none-eabi-ranlib)
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)
set(MDR_CPU_FLAGS "-mcpu=cortex-m4 -mthumb -mfloat-abi=hard -mfpu=fpv4-sp-d16" CACHE STRING "core flags")
set(CMAKE_C_FLAGS_INIT "${MDR_CPU_FLAGS}")
set(CMAKE_EXE_LINKER_FLAGS_INIT "${MDR_CPU_FLAGS} -Wl,--gc-sections")
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
