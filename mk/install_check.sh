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
echo "install-check: make install PREFIX=... ($(cd "$dir/prefix" && find include lib -type f | wc -l) files); built with '$flags':"
echo "  shared: $(cat "$dir/shared.out")"
echo "  static: $(cat "$dir/static.out")"
