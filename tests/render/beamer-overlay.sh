#!/bin/sh
# The beamer example of docs/overlays.md compiles with pdflatex against
# the multi-page PDF of an overlay figure and gives one slide per step.
# Skipped (77) without pdflatex, beamer or pdfinfo.
# usage: beamer-overlay.sh CURVEFIG DOCS/overlays.md FIGURES_DIR
set -u
tool=$1 doc=$2 figures=$3
command -v pdflatex >/dev/null && command -v pdfinfo >/dev/null &&
  command -v kpsewhich >/dev/null && kpsewhich beamer.cls >/dev/null ||
  { echo "no pdflatex, beamer or pdfinfo: skipped"; exit 77; }
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$tool" render "$figures/overlay-decasteljau.lua" -o "$out" -f pdf || exit 1
steps=$(pdfinfo "$out/overlay-decasteljau.pdf" | awk '/^Pages:/ { print $2 }')
[ "$steps" = 5 ] || { echo "FAIL the figure's PDF has $steps pages, not 5"; exit 1; }
# every page of the figure the same size
sizes=$(pdfinfo -f 1 -l 5 "$out/overlay-decasteljau.pdf" |
        awk '/^Page +[0-9]+ size:/ { print $4, $6 }' | sort -u | wc -l)
[ "$sizes" = 1 ] || { echo "FAIL the pages differ in size"; exit 1; }
# the first ```latex block of the document
awk '/^```latex$/ { on = 1; next } /^```$/ { if (on) exit } on' "$doc" \
  > "$out/deck.tex"
grep -q includegraphics "$out/deck.tex" || { echo "FAIL no example in $doc"; exit 1; }
(cd "$out" && pdflatex -interaction=nonstopmode -halt-on-error deck.tex \
   > latex-run.txt 2>&1) || { tail -30 "$out/latex-run.txt"; echo "FAIL pdflatex"; exit 1; }
slides=$(pdfinfo "$out/deck.pdf" | awk '/^Pages:/ { print $2 }')
[ "$slides" = 5 ] || { echo "FAIL the deck has $slides slides, not 5"; exit 1; }
echo "ok   5 steps, 5 pages of one size, 5 slides"
