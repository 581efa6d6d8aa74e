#!/bin/sh
# SPDX-License-Identifier: MIT
# mk/install_check.sh DIR CC: the program examples/cmake-consumer/main.c
# built against the libmdr installed in DIR/prefix (make install-check)
# with nothing but `pkg-config --cflags --libs mdr`, run with the shared
# library, then linked statically (--static, libmdr.a) and run again.
set -eu
dir=$1
cc=$2
export PKG_CONFIG_PATH="$dir/prefix/lib/pkgconfig"
flags=$(pkg-config --cflags --libs mdr)
$cc -std=c99 -Wall -Wextra -Werror examples/cmake-consumer/main.c $flags -o "$dir/consumer_shared"
LD_LIBRARY_PATH="$dir/prefix/lib" "$dir/consumer_shared" > "$dir/shared.out"
LD_LIBRARY_PATH="$dir/prefix/lib" ldd "$dir/consumer_shared" | grep -q "$dir/prefix/lib/libmdr.so.0" || {
    echo "install-check: consumer_shared is not linked with the installed libmdr.so.0"; exit 1; }
$cc -std=c99 -Wall -Wextra -Werror examples/cmake-consumer/main.c $(pkg-config --cflags mdr) \
    "$dir/prefix/lib/libmdr.a" -o "$dir/consumer_static"
"$dir/consumer_static" > "$dir/static.out"
# the README's host C program, as written, against the installed library
awk '/^```c$/ { c = 1; b = ""; next } /^```$/ { if (c && b ~ /int main\(void\)/) { printf "%s", b; exit } c = 0; next }
     c { b = b $0 "\n" }' README.md > "$dir/readme_host.c"
grep -q 'int main(void)' "$dir/readme_host.c" || { echo "install-check: no C program with main in README.md"; exit 1; }
$cc -std=c99 -Wall -Wextra -Werror "$dir/readme_host.c" $(pkg-config --cflags mdr) "$dir/prefix/lib/libmdr.a" \
    -o "$dir/readme_host"
"$dir/readme_host" > "$dir/readme_host.out"
grep -q 'pull-off -2.204e-09 N' "$dir/readme_host.out" || {
    cat "$dir/readme_host.out"; echo "install-check: the README's C program does not print mdr critical's pull-off"; exit 1; }
# the headers from C++ (firmware written in C++ includes them as they are:
# C linkage through MDR_BEGIN_DECLS; before stop 56 the README's program
# compiled as C++ did not link, helper-24): that program, and a function of
# every public header, compiled by g++ against the installed libmdr.a
g++ -x c++ -std=c++11 -Wall -Wextra -Werror "$dir/readme_host.c" -x none $(pkg-config --cflags mdr) \
    "$dir/prefix/lib/libmdr.a" -o "$dir/readme_host_cpp"
"$dir/readme_host_cpp" | cmp -s - "$dir/readme_host.out" || {
    echo "install-check: the README's C program compiled as C++ prints otherwise"; exit 1; }
cat > "$dir/every_header.cpp" <<'CPP'
#include <mdr.h>
int main()
{
    mdr_contact_f32 c32;
    mdr_contact_f64 c64;
    mdr_scene_f32 s32;
    const float pf[3] = {1e-6f, 0, 0};
    const double pd[3] = {1e-6, 0, 0};
    int bad = mdr_contact_init_f32(&c32, MDR_PROFILE_PARABOLOID, pf, 1e9f, 0.05f) != MDR_OK;
    bad |= mdr_contact_init_f64(&c64, MDR_PROFILE_PARABOLOID, pd, 1e9, 0.05) != MDR_OK;
    bad |= mdr_engine_init_f32(nullptr, nullptr, 1, 0, 0, 0) != MDR_E_NULL;
    bad |= mdr_scene_init_paraboloid_f32(&s32, 1e-6f, 1e9f, 0.05f, 0, 0, MDR_OUT_FORCE, nullptr) != MDR_OK;
    bad |= mdr_engine_init_q31_f32(nullptr, nullptr, 1, 0, 0, 0) != MDR_E_NULL;
    bad |= mdr_scene_init_q31_f32(nullptr, &s32, 1e-6f) != MDR_E_NULL;
    bad |= mdr_tabor_f64(&c64, 1e-9, 1e-8, nullptr, nullptr, nullptr) == MDR_OK;
    return bad || !*mdr_status_str(MDR_OK) || !*mdr_event_str(0) || !*mdr_regime_str(0);
}
CPP
g++ -std=c++11 -Wall -Wextra -Werror "$dir/every_header.cpp" $(pkg-config --cflags mdr) "$dir/prefix/lib/libmdr.a" \
    -o "$dir/every_header_cpp" && "$dir/every_header_cpp" || {
    echo "install-check: a function of every public header from C++ (g++) fails to build or run"; exit 1; }
# the CMake consumer project with find_package(mdr 0.1) on the same prefix
# (the package files make install writes: before stop 56 it wrote none, and
# the README's "find_package(mdr) after installing it" failed; helper-24)
cmake -S examples/cmake-consumer -B "$dir/cmake" -DCMAKE_PREFIX_PATH="$dir/prefix" > "$dir/cmake.log" 2>&1 &&
    cmake --build "$dir/cmake" >> "$dir/cmake.log" 2>&1 || {
    cat "$dir/cmake.log"; echo "install-check: find_package(mdr) on the make install prefix failed"; exit 1; }
"$dir/cmake/consumer" > "$dir/cmake.out"
echo "install-check: make install PREFIX=... ($(cd "$dir/prefix" && find include lib -type f | wc -l) files); built with '$flags':"
echo "  shared: $(cat "$dir/shared.out")"
echo "  static: $(cat "$dir/static.out")"
echo "  README.md host C program: $(cat "$dir/readme_host.out")"
echo "  CMake find_package(mdr 0.1): $(cat "$dir/cmake.out")"
echo "  C++ (g++): the README's program as C++ prints the same; a function of every public header links and runs"
