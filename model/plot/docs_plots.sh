#!/bin/sh
# docs_plots.sh CONTOUR ROOT [--check]: every plot committed under docs/,
# made by the commands the docs give (docs/paper-b.md "Reproduce with").
#   without --check: writes them into ROOT/docs/ (`make docs-plots`);
#   with --check: writes them into a scratch directory and fails (exit 1),
#   naming the files, when they differ from the committed ones, or when a
#   file is missing on either side (the ctest docs_plots_reproducible).
set -eu
contour=$1 root=$2 mode=${3:-}
if [ "$mode" = --check ]; then
  out=$(mktemp -d "${TMPDIR:-/tmp}/contour-docs-plots.XXXXXX")
  trap 'rm -rf "$out"' EXIT
else
  out=$root/docs
fi
# The plots and the commands that make them (paths relative to docs/).
make_plots() {
  "$contour" gcode "$root/docs/paper-b/fig2-3d-arc.ngc" --svg "$1/paper-b/3d" >/dev/null
  "$contour" gcode "$root/docs/paper-b/circle.ngc" --svg "$1/paper-b/circle" >/dev/null
}
make_plots "$out"
[ "$mode" = --check ] || { echo "docs plots written under $out/paper-b"; exit 0; }
bad=0
made=$(cd "$out" && find . -name '*.svg' | sort)
committed=$(cd "$root/docs" && find . -name '*.svg' | sort)
if [ "$made" != "$committed" ]; then
  echo "the committed plots are not the set the commands make:"
  printf '%s\n' "$made" >"$out/made.txt"
  printf '%s\n' "$committed" >"$out/committed.txt"
  diff "$out/committed.txt" "$out/made.txt" || true
  bad=1
fi
for f in $made; do
  if [ -f "$root/docs/$f" ] && ! cmp -s "$out/$f" "$root/docs/$f"; then
    echo "docs/${f#./} differs from what its command makes (run: make docs-plots)"
    bad=1
  fi
done
[ $bad = 0 ] && echo "every committed plot is what its command makes ($(echo "$made" | wc -l) files)"
exit $bad
