#!/bin/sh
# SPDX-License-Identifier: MIT
# mk/deps.sh [--check]: the Debian packages of mk/packages.txt.
#   make deps         install the missing ones (apt-get as root, else
#                     through sudo)
#   make deps-check   name the missing ones and fail (no apt-get)
set -eu
cd "$(dirname "$0")/.."
pkgs=$(sed -e 's/#.*//' mk/packages.txt | tr -s ' \t\n' ' ')
missing=""
for p in $pkgs; do
    dpkg -s "$p" > /dev/null 2>&1 || missing="$missing $p"
done
if [ -z "$missing" ]; then
    echo "deps: the $(echo $pkgs | wc -w) Debian packages of mk/packages.txt are installed"
    exit 0
fi
if [ "${1:-}" = --check ]; then
    echo "deps: missing Debian packages:$missing (run: make deps)"
    exit 1
fi
if [ "$(id -u)" = 0 ]; then
    sudo=""
elif command -v sudo > /dev/null; then
    sudo="sudo"
else
    echo "deps: missing Debian packages:$missing; as root: apt-get install$missing"
    exit 1
fi
echo "deps: installing$missing"
$sudo apt-get update -qq
$sudo env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq $missing > /dev/null
