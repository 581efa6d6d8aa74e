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
