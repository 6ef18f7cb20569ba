#!/bin/sh
# Install the build into a scratch root, then build and run examples/ with
# nothing but a C compiler and pkg-config against what was installed, as
# docs/library.md tells a user to: curvefig-core alone for the algorithms
# (the program must not link cairo, pango or Lua), curvefig-render for the
# figure example; and statically when the build made static libraries.
# Usage: install-check.sh BUILD_DIR SOURCE_DIR
set -eu
build=$1 src=$2
root=$(mktemp -d)
trap 'rm -rf "$root"' EXIT
meson install -C "$build" --destdir "$root" --no-rebuild --quiet >/dev/null
pcdir=$(find "$root" -name curvefig-core.pc -printf '%h\n' | head -n 1)
[ -n "$pcdir" ] || { echo "install-check: no curvefig-core.pc installed" >&2; exit 1; }
libdir=$(dirname "$pcdir")
export PKG_CONFIG_PATH="$pcdir" PKG_CONFIG_SYSROOT_DIR="$root"
export LD_LIBRARY_PATH="$libdir"
cc=${CC:-cc}
for e in nurbs-circle knot-insertion interpolation offset surface; do
    # shellcheck disable=SC2046
    $cc -std=c11 -Wall -Wextra -pedantic -Werror -o "$root/$e" "$src/examples/$e.c" \
        $(pkg-config --cflags --libs curvefig-core)
    "$root/$e" >/dev/null
    if ldd "$root/$e" | grep -Eq 'cairo|pango|lua'; then
        echo "install-check: $e (curvefig-core only) links $(ldd "$root/$e" | grep -Eo 'lib(cairo|pango|lua)[^ ]*' | head -n 1)" >&2
        exit 1
    fi
    echo "ok: $e against the installed curvefig-core"
done
if pkg-config --exists curvefig-render; then
    # shellcheck disable=SC2046
    $cc -std=c11 -Wall -Wextra -pedantic -Werror -o "$root/figure" "$src/examples/figure.c" \
        $(pkg-config --cflags --libs curvefig-render)
    (cd "$root" && ./figure out >/dev/null && test -s out.svg && test -s out.pdf)
    echo "ok: figure against the installed curvefig-render"
fi
if [ -f "$libdir/libcurvefig-core.a" ]; then
    # shellcheck disable=SC2046
    $cc -std=c11 -o "$root/static" "$src/examples/knot-insertion.c" \
        $(pkg-config --cflags curvefig-core) -Wl,-Bstatic \
        $(pkg-config --libs-only-L curvefig-core) -lcurvefig-core -Wl,-Bdynamic -lm
    if ldd "$root/static" | grep -q curvefig; then
        echo "install-check: the static program still needs a shared libcurvefig" >&2
        exit 1
    fi
    "$root/static" >/dev/null
    echo "ok: knot-insertion linked statically"
fi
# The installed tool: a render loads neither librsvg nor libmicrohttpd
# (nor what they bring) nor pango; `compare` and `live` run its helpers
# from the libexec directory, found from where the tool is.
tool=$(find "$root" -path '*/bin/curvefig' -type f | head -n 1)
if [ -n "$tool" ]; then
    if ldd "$tool" | grep -Eq 'rsvg|microhttpd|gnutls|icu|stdc\+\+|pango'; then
        echo "install-check: curvefig links $(ldd "$tool" | grep -Eo 'lib(rsvg|microhttpd|gnutls|icu|stdc|pango)[^ ]*' | head -n 1)" >&2
        exit 1
    fi
    printf 'local f = figure{ name = "m", width = "2cm", height = "1cm" }\nf:line({0, 0}, {1, 1})\n' > "$root/m.lua"
    "$tool" render "$root/m.lua" -o "$root" -f png >/dev/null
    "$tool" compare "$root/m.png" "$root/m.png" >/dev/null
    "$tool" help live | grep -q 'curvefig live SCRIPT.lua'
    # a run of live: the installed helper starts its worker (itself again)
    "$tool" live "$root/m.lua" --once | grep -q '"figures"'
    echo "ok: the installed curvefig renders without the checking and live libraries and runs its helpers"
    # copied alone elsewhere, it names the directories it looked in for
    # its WebAssembly module and its helper programs (and only those)
    mkdir "$root/alone"
    cp "$tool" "$root/alone/curvefig"
    status=0
    "$root/alone/curvefig" render "$root/m.lua" -o "$root/alone" -f html 2> "$root/alone/err" || status=$?
    if [ "$status" -eq 0 ] || ! grep -q "curvefig.wasm, which is not installed with this curvefig (looked in $root/alone/../web, " "$root/alone/err"; then
        echo "install-check: the tool alone, -f html: status $status, $(cat "$root/alone/err")" >&2
        exit 1
    fi
    status=0
    "$root/alone/curvefig" live "$root/m.lua" 2> "$root/alone/err" || status=$?
    if [ "$status" -ne 2 ] || ! grep -q "lacks its program curvefig-live (looked in $root/alone, " "$root/alone/err"; then
        echo "install-check: the tool alone, live: status $status, $(cat "$root/alone/err")" >&2
        exit 1
    fi
    echo "ok: the tool copied alone names where it looked for its module and helpers"
fi
# The headers in every C standard from C89 on.
printf '#include <curvefig/curvefig.h>\n#include <curvefig/figure.h>\nint main(void) { return cf_version() == CF_VERSION ? 0 : 1; }\n' > "$root/v.c"
for std in c89 c99 c11 c17; do
    # shellcheck disable=SC2046
    $cc -std=$std -Wall -Wextra -pedantic -Werror -fsyntax-only "$root/v.c" \
        $(pkg-config --cflags curvefig-core) $(pkg-config --exists curvefig-render && pkg-config --cflags curvefig-render)
done
echo "ok: the headers as C89, C99, C11 and C17"
# C++ compilers read the headers too.
if command -v c++ >/dev/null 2>&1; then
    printf '#include <curvefig/curvefig.h>\nint main() { return cf_version() == CF_VERSION ? 0 : 1; }\n' > "$root/v.cc"
    # shellcheck disable=SC2046
    c++ -Wall -Wextra -pedantic -Werror -o "$root/v" "$root/v.cc" $(pkg-config --cflags --libs curvefig-core)
    "$root/v"
    echo "ok: the headers in C++"
fi
