#!/bin/sh
# SPDX-License-Identifier: MIT
# mk/cmake_check.sh DIR: examples/cmake-consumer built with CMake in DIR
# (make cmake-check): add_subdirectory on the host; libmdr built, installed
# and found with find_package on the host; add_subdirectory cross-compiled
# for the Cortex-M4F (cmake/arm-none-eabi.cmake), run on QEMU, its libmdr
# objects free of double-precision helpers. Each program must exit 0.
set -eu
dir=$1
src=$(pwd)
rm -rf "$dir"
mkdir -p "$dir"
log=$dir/log
step() {  # step NAME command...: run quietly, show the log on failure
    name=$1; shift
    "$@" > "$log" 2>&1 || { cat "$log"; echo "cmake-check: $name failed"; exit 1; }
}
step "configure (add_subdirectory)" cmake -S examples/cmake-consumer -B "$dir/sub" -DMDR_SOURCE_DIR="$src" \
    -DCMAKE_EXPORT_COMPILE_COMMANDS=ON
step "build (add_subdirectory)" cmake --build "$dir/sub" -j2
echo "cmake-check host, add_subdirectory: $("$dir/sub/consumer")"
# without a build type the library is optimised all the same (-O2; at -O0
# a firmware's text was 4.6 times larger: helper-56)
grep '"command".*mdr_f32\.c' "$dir/sub/compile_commands.json" | grep -q -- ' -O2 ' ||
    { grep 'mdr_f32' "$dir/sub/compile_commands.json"; echo "cmake-check: libmdr built without -O2 where no build type is set"; exit 1; }

step "configure libmdr" cmake -S . -B "$dir/lib" -DCMAKE_INSTALL_PREFIX="$dir/prefix" -DBUILD_SHARED_LIBS=OFF
step "build libmdr" cmake --build "$dir/lib" -j2
step "install libmdr" cmake --install "$dir/lib"
step "configure (find_package)" cmake -S examples/cmake-consumer -B "$dir/pkg" -DCMAKE_PREFIX_PATH="$dir/prefix"
step "build (find_package)" cmake --build "$dir/pkg" -j2
echo "cmake-check host, find_package: $("$dir/pkg/consumer")"
# the same build installed into another prefix (cmake --install --prefix):
# its mdr.pc points there (pkg-config alone builds and runs the consumer)
step "install libmdr (--prefix)" cmake --install "$dir/lib" --prefix "$dir/moved"
pcdir=$(dirname "$(find "$dir/moved" -name mdr.pc)")
step "pkg-config (--prefix)" env PKG_CONFIG_PATH="$pcdir" pkg-config --cflags --libs mdr
flags=$(cat "$log")
case $(PKG_CONFIG_PATH="$pcdir" pkg-config --variable=libdir mdr) in
"$dir/moved/"*) ;;
*) echo "cmake-check: mdr.pc installed with --prefix $dir/moved points elsewhere: $flags"; exit 1;;
esac
step "build (pkg-config, --prefix)" cc -std=c99 -Wall -Wextra -Werror examples/cmake-consumer/main.c $flags -o "$dir/moved/consumer"
echo "cmake-check host, cmake --install --prefix elsewhere, pkg-config '$flags': $("$dir/moved/consumer")"
# a reduced build's options reach its pkg-config consumers (mdr.pc's
# Cflags; before stop 58 they saw every option on, mdr_options.h's default,
# and a call guarded by #if MDR_CFG_STRESS failed to link: helper-32)
step "configure libmdr (MDR_CFG_STRESS=OFF)" cmake -S . -B "$dir/red" -DCMAKE_INSTALL_PREFIX="$dir/red-prefix" \
    -DBUILD_SHARED_LIBS=OFF -DMDR_CFG_STRESS=OFF
step "build libmdr (reduced)" cmake --build "$dir/red" -j2
step "install libmdr (reduced)" cmake --install "$dir/red"
pcdir=$(dirname "$(find "$dir/red-prefix" -name mdr.pc)")
step "pkg-config (reduced)" env PKG_CONFIG_PATH="$pcdir" pkg-config --cflags --libs mdr
flags=$(cat "$log")
case "$flags" in
*-DMDR_CFG_STRESS=0*) ;;
*) echo "cmake-check: a build with MDR_CFG_STRESS=OFF installed an mdr.pc without it: $flags"; exit 1;;
esac
printf '#include "mdr.h"\nint main(void) { return MDR_CFG_STRESS; }\n' > "$dir/red/opt.c"
step "build (pkg-config, reduced)" cc -std=c99 -Wall -Wextra -Werror "$dir/red/opt.c" $flags -o "$dir/red/opt"
"$dir/red/opt" || { echo "cmake-check: MDR_CFG_STRESS is on in a pkg-config consumer of a build without it"; exit 1; }
echo "cmake-check host, MDR_CFG_STRESS=OFF installed, pkg-config '$flags': the option off in the consumer"

step "configure (Cortex-M4F)" cmake -S examples/cmake-consumer -B "$dir/m4f" -DMDR_SOURCE_DIR="$src" \
    -DCMAKE_TOOLCHAIN_FILE="$src/cmake/arm-none-eabi.cmake" -DCMAKE_BUILD_TYPE=MinSizeRel
step "build (Cortex-M4F)" cmake --build "$dir/m4f" -j2 -v
# (a build type decides: MinSizeRel's -Os, not the default's -O2)
grep 'mdr_f32\.c' "$log" | grep -q -- '-Os' && ! grep 'mdr_f32\.c' "$log" | grep -q -- '-O2' ||
    { cat "$log"; echo "cmake-check: MinSizeRel's libmdr not built with -Os alone"; exit 1; }
dbl=$(arm-none-eabi-nm -u "$dir/m4f/mdr/libmdr.a" | grep '__aeabi_d' || true)
[ -z "$dbl" ] || { echo "cmake-check: double-precision helpers in the Cortex-M4F libmdr.a: $dbl"; exit 1; }
out=$(port/cortex-m/run-qemu -M mps2-an386 -t 60 "$dir/m4f/consumer") || {
    echo "$out"; echo "cmake-check: the Cortex-M4F consumer failed on QEMU"; exit 1; }
echo "cmake-check Cortex-M4F (QEMU mps2-an386), add_subdirectory: $out"
