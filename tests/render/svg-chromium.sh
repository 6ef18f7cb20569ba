#!/bin/sh
# The animated SVG of an overlay figure plays in Chromium: a headless
# screenshot in the middle of each step matches that step's PNG (the
# tool's comparator, anti-aliasing forgiven) and not the next step's.
# The SVG sits inline in a page whose script pauses its SMIL timeline at
# the time of the screenshot (setCurrentTime), so that a loaded machine
# does not shift the time.  Skipped (77) without chromium.
# usage: svg-chromium.sh CURVEFIG SCRIPT.lua NAME STEPS
set -u
tool=$1 script=$2 name=$3 steps=$4
browser=$(command -v chromium || command -v chromium-browser || true)
[ -n "$browser" ] || { echo "no chromium: skipped"; exit 77; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$tool" render "$script" -o "$out" -f svg,png --dpi 96 || exit 1
# the PNG's size in pixels (IHDR), the window of the screenshots
size=$(od -An -tu1 -j16 -N8 "$out/$name-1.png" | awk '{ printf "%d,%d",
    $1 * 16777216 + $2 * 65536 + $3 * 256 + $4,
    $5 * 16777216 + $6 * 65536 + $7 * 256 + $8 }')
fail=0
k=1
while [ "$k" -le "$steps" ]; do
  ms=$(( (k - 1) * 1500 + 750 ))   # the middle of step k (1.5 s a step)
  { printf '<!DOCTYPE html><html><head><style>body { margin: 0 }</style>'
    printf '</head><body>\n'
    sed 1d "$out/$name.svg"   # without the XML declaration
    printf '<script>var s = document.querySelector("svg");\n'
    printf 's.pauseAnimations(); s.setCurrentTime(%d.%03d);</script>\n' \
      $((ms / 1000)) $((ms % 1000))
    printf '</body></html>\n'; } > "$out/step-$k.html"
  timeout 120 "$browser" --headless --no-sandbox --disable-gpu \
    --disable-background-networking --no-first-run --hide-scrollbars \
    --user-data-dir="$out/profile-$k" --window-size="$size" \
    --virtual-time-budget=200 --screenshot="$out/shot-$k.png" \
    "file://$out/step-$k.html" >/dev/null 2>&1
  if [ ! -s "$out/shot-$k.png" ]; then
    echo "FAIL step $k: no screenshot"; fail=1
  elif ! "$tool" compare "$out/shot-$k.png" "$out/$name-$k.png" \
         --max-bad 20 >"$out/cmp" 2>&1; then
    echo "FAIL step $k at $ms ms differs from $name-$k.png:"; cat "$out/cmp"
    fail=1
  else
    next=$(( k % steps + 1 ))
    if "$tool" compare "$out/shot-$k.png" "$out/$name-$next.png" \
         --max-bad 20 >/dev/null 2>&1; then
      echo "FAIL step $k at $ms ms also matches step $next"; fail=1
    else
      echo "ok   step $k at $ms ms"
    fi
  fi
  k=$((k + 1))
done
exit $fail
