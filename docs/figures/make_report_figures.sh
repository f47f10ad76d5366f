#!/usr/bin/env bash
# The drawings and reports of docs/report.md's three scenes (about a minute):
#
#   bash docs/figures/make_report_figures.sh [OGIVE]        # OGIVE defaults to build/ogive
#
# docs/figures/report-NAME-drawing.png: `ogive draw --limit` rendered by rsvg-convert;
# docs/figures/report-NAME.png: `ogive report` rendered by headless Chromium (the page's top).
# Needs librsvg2-bin and chromium-headless-shell: bash .ci/install_deps.sh --charts.
set -euo pipefail
cd "$(dirname "$0")/../.."
ogive=${1:-build/ogive}
[[ -x $ogive ]] || { echo "make_report_figures.sh: no ogive executable at '$ogive' (build first)" >&2; exit 2; }
browser=$(command -v chromium-headless-shell || command -v chromium || true)
[[ -n $browser ]] || { echo "make_report_figures.sh: no chromium (bash .ci/install_deps.sh --charts)" >&2; exit 2; }
command -v rsvg-convert >/dev/null || { echo "make_report_figures.sh: no rsvg-convert" >&2; exit 2; }
out=docs/figures
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

declare -A scenes=(
  [semicircle]="--curve semicircular"
  [engineers-arch]="--span 8 --eccentricity 0.5 --thickness-ratio 0.1 --density 2000 --fill-density 2000 --fill-height-ratio 0.924 --point-load 50000 --point-load-at 0.25"
  [spreading]="--curve semicircular --section no-tension --support-displacement-ratio 0.0001"
)
for name in semicircle engineers-arch spreading; do
  # shellcheck disable=SC2086  # the scene's options, word by word
  "$ogive" draw ${scenes[$name]} --limit --output "$tmp/$name.svg" >/dev/null
  rsvg-convert --width 800 "$tmp/$name.svg" -o "$out/report-$name-drawing.png"
  # shellcheck disable=SC2086
  "$ogive" report ${scenes[$name]} --output "$tmp/$name.html" >/dev/null
  # The page at 800 px wide, long enough for every section (a few hundred KB).
  "$browser" --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size=800,2500 \
    --screenshot="$out/report-$name.png" "file://$tmp/$name.html" 2>/dev/null
done
