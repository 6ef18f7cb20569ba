#!/bin/sh
# Lua 5.4's source for the WebAssembly build (render/web): Debian's
# source package lua5.4, unpacked with its patches into DIR
# (default: third_party/lua5.4 under the top of the checkout).  Enables
# deb-src lines for apt when none are there.  Run as root on Debian 12.
set -eu
top=$(cd "$(dirname "$0")/../.." && pwd)
dir=${1:-$top/third_party/lua5.4}
if [ -f "$dir/src/lua.h" ]; then
    exit 0
fi
if ! grep -rqs '^Types:.*deb-src\|^deb-src ' /etc/apt/sources.list \
        /etc/apt/sources.list.d/; then
    if [ -f /etc/apt/sources.list.d/debian.sources ]; then
        sed -i 's/^Types: deb$/Types: deb deb-src/' \
            /etc/apt/sources.list.d/debian.sources
    else
        sed -n 's/^deb /deb-src /p' /etc/apt/sources.list \
            > /etc/apt/sources.list.d/curvefig-deb-src.list
    fi
    apt-get update
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
(cd "$tmp" && apt-get source lua5.4)
mkdir -p "$(dirname "$dir")"
rm -rf "$dir"
mv "$tmp"/lua5.4-*/ "$dir"
