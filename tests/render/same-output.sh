#!/bin/sh
# Every shipped script rendered by two builds, compared byte by byte: for a
# change that must not change any output (a faster path to the same
# numbers).  Run by hand with two builds of the tool:
#   tests/render/same-output.sh OLD_CURVEFIG NEW_CURVEFIG [SOURCE_DIR]
# Each figures/**/*.lua of SOURCE_DIR (default: this checkout) is rendered
# in SVG, PDF, PNG, PS, EPS, PGF and HTML by both tools (HTML needs each
# build's WebAssembly module, render/web/curvefig.wasm), PDF dates from
# SOURCE_DATE_EPOCH; the two trees of files and messages must be the same.
# Exit status 0 when they are, 1 when not (diff -rq names the files).
set -u
abs() { case $1 in /*) echo "$1" ;; */*) echo "$PWD/$1" ;; *) command -v "$1" ;; esac; }
old=$(abs "$1") new=$(abs "$2")
src=${3:-$(cd "$(dirname "$0")/../.." && pwd)}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
export SOURCE_DATE_EPOCH=1700000000
n=0
for s in $(cd "$src" && find figures -name '*.lua' | sort); do
    d=$(echo "$s" | tr / _)
    for t in old new; do
        if [ "$t" = old ]; then tool=$old; else tool=$new; fi
        mkdir -p "$out/$t/$d"
        (cd "$src/figures" && "$tool" render "../$s" -o "$out/$t/$d" \
            -f svg,pdf,png,ps,eps,pgf,html) > "$out/$t/$d.log" 2>&1
        echo "status $?" >> "$out/$t/$d.log"
    done
    n=$((n + 1))
done
files=$(find "$out/new" -type f ! -name '*.log' | wc -l)
if diff -rq "$out/old" "$out/new"; then
    echo "same-output: $n scripts, $files files: the same bytes"
    exit 0
fi
echo "same-output: the two builds differ (above)" >&2
exit 1
